//! A general planar kinetostatic solve: the Newton-Euler equations of every body, with every
//! joint reaction unknown, assembled from a mechanism's declared [`Topology`] into one linear
//! system per step and solved by least squares (faer's QR). It knows no mechanism: the tests
//! compare it with each mechanism's closed forms.
//!
//! For each body: Σ F = m·a_g and Σ M_g = J·α (d'Alembert: Beer & Johnston, as cited in Karhula
//! ch. 5). Unknowns: two force components at a pin; the force across a slide and its couple;
//! the tangential force of an involute mesh (its radial part |F_t|·tan α follows the sign of
//! F_t: the system is solved for one flank, and again for the other if F_t comes out with the
//! wrong sign); the force of a tied mesh (one extra equation ties it to its joint); the drive
//! torque on the crankshaft. A body lumped with the crankshaft (`Body::lumped`: Karhula's
//! cardan wheel) has no moment equation of its own: its moments about its joint with the
//! crankshaft, times its speed ratio, join the crankshaft's (virtual power). A least-squares solve accepts the identically satisfied equations
//! of point-like bodies (whose moment row is empty) and reports the residual, so that a
//! statically inconsistent model shows itself instead of passing silently.

use cardan_mechanism::{cross, JointKind, JointLoad, Loads, MeshForce, State, Topology, C};
use faer::linalg::solvers::SolveLstsq;
use faer::Mat;

/// How one joint's unknowns make its force: (force per unit of the first unknown, per unit of
/// the second, couple per unit of the second).
#[derive(Debug, Clone, Copy)]
enum Unknowns {
    /// Fx, Fy.
    Pin,
    /// Force along `n`, couple.
    Slide { n: C },
    /// Force along `d`.
    Along { d: C },
}

impl Unknowns {
    fn count(self) -> usize {
        match self {
            Unknowns::Pin | Unknowns::Slide { .. } => 2,
            Unknowns::Along { .. } => 1,
        }
    }
}

/// The loads of one step by the general solve, written to `out`; returns the residual norm of
/// the equations (N and N·m).
pub fn loads(
    topology: &Topology,
    state: &State,
    inertia: bool,
    piston_forces: &[f64],
    out: &mut Loads,
) -> f64 {
    // An involute mesh's radial force follows the sign of F_t: try the positive flank, then
    // the negative one if F_t came out negative.
    let mut flank = 1.0;
    for attempt in 0..2 {
        let (residual, involute_ft) = solve(topology, state, inertia, piston_forces, flank, out);
        match involute_ft {
            Some(ft) if ft * flank < 0.0 && attempt == 0 => flank = -flank,
            _ => return residual,
        }
    }
    unreachable!("the loop returns on its second pass")
}

/// The unknowns of the solve: each joint's kind of unknowns and its first column, the drive
/// torque's column, the tied meshes (mesh joint, tied joint, direction, factor) and the first
/// involute mesh.
struct Columns {
    kinds: Vec<Unknowns>,
    first: Vec<usize>,
    drive: usize,
    ties: Vec<(usize, usize, C, f64)>,
    involute: Option<usize>,
}

impl Columns {
    /// The columns of `topology`'s joints in `state`, the involute meshes' flank sign `flank`.
    fn of(topology: &Topology, state: &State, flank: f64) -> Self {
        let joints = &topology.joints;
        let mut kinds = Vec::with_capacity(joints.len());
        let mut first = Vec::with_capacity(joints.len());
        let mut unknowns = 0;
        let mut ties = Vec::new();
        let mut involute = None;
        for (j, joint) in joints.iter().enumerate() {
            let m = &state.joints[j];
            let u = match joint.kind {
                JointKind::Revolute(_) => Unknowns::Pin,
                JointKind::Prismatic => Unknowns::Slide {
                    n: C::i() * m.direction,
                },
                JointKind::GearMesh {
                    pressure_angle,
                    force,
                    ..
                } => match force {
                    MeshForce::Involute => {
                        involute.get_or_insert(j);
                        // Tangent t = i·d; radial part |F_t|·tan α along d, towards the centre
                        // of the gear on `body`.
                        Unknowns::Along {
                            d: C::i() * m.direction + flank * pressure_angle.tan() * m.direction,
                        }
                    }
                    MeshForce::Tied {
                        direction,
                        joint: tied,
                        factor,
                    } => {
                        ties.push((j, tied, direction, factor));
                        Unknowns::Along { d: direction }
                    }
                },
            };
            kinds.push(u);
            first.push(unknowns);
            unknowns += u.count();
        }
        Self {
            kinds,
            first,
            drive: unknowns,
            ties,
            involute,
        }
    }

    /// The number of unknowns: the joints' and the drive torque.
    fn count(&self) -> usize {
        self.drive + 1
    }
}

/// One least-squares solve with the involute flank sign `flank`; returns the residual and the
/// tangential force of the (first) involute mesh, if any.
fn solve(
    topology: &Topology,
    state: &State,
    inertia: bool,
    piston_forces: &[f64],
    flank: f64,
    out: &mut Loads,
) -> (f64, Option<f64>) {
    let columns = Columns::of(topology, state, flank);
    let bodies = &topology.bodies;
    let equations = 3 * bodies.len() + columns.ties.len();
    let mut a = Mat::<f64>::zeros(equations, columns.count());
    let mut b = Mat::<f64>::zeros(equations, 1);
    let moments: Vec<Moment> = (0..bodies.len())
        .map(|k| Moment::of(topology, state, k))
        .collect();
    if inertia {
        inertia_rows(topology, state, &moments, &mut b);
    }
    gas_rows(topology, state, piston_forces, &moments, &mut b);
    joint_rows(topology, state, &columns, &moments, &mut a);
    a[(3 * topology.crankshaft + 2, columns.drive)] += 1.0;
    tie_rows(bodies.len(), &columns, &mut a);
    let x = a.qr().solve_lstsq(&b);
    let residual = (&a * &x - &b).norm_l2();
    for (j, load) in out.joints.iter_mut().enumerate() {
        let c = columns.first[j];
        *load = match columns.kinds[j] {
            Unknowns::Pin => JointLoad {
                force: C::new(x[(c, 0)], x[(c + 1, 0)]),
                moment: 0.0,
            },
            Unknowns::Slide { n } => JointLoad {
                force: x[(c, 0)] * n,
                moment: x[(c + 1, 0)],
            },
            Unknowns::Along { d } => JointLoad {
                force: x[(c, 0)] * d,
                moment: 0.0,
            },
        };
    }
    out.crank_torque = x[(columns.drive, 0)];
    let involute = columns.involute;
    (residual, involute.map(|j| x[(columns.first[j], 0)]))
}

/// The gas in the right-hand side `b`: it pushes each piston along its axis towards the
/// crankshaft, at the piston pin, with the force `piston_forces` of its piston.
fn gas_rows(
    topology: &Topology,
    state: &State,
    piston_forces: &[f64],
    moments: &[Moment],
    b: &mut Mat<f64>,
) {
    for ((piston, motion), &force) in topology
        .pistons
        .iter()
        .zip(&state.pistons)
        .zip(piston_forces)
    {
        let k = piston.body;
        let f = -force * piston.axis;
        let at = piston.origin + motion.position * piston.axis;
        let Moment { row, scale, about } = moments[k];
        b[(3 * k, 0)] -= f.re;
        b[(3 * k + 1, 0)] -= f.im;
        b[(row, 0)] -= scale * cross(at - about, f);
    }
}

/// Each joint's unknowns in the equations of the two bodies it joins (with opposite signs):
/// a unit force f at the joint adds f to a body's force rows and arm × f to its moment row.
fn joint_rows(
    topology: &Topology,
    state: &State,
    columns: &Columns,
    moments: &[Moment],
    a: &mut Mat<f64>,
) {
    for (j, joint) in topology.joints.iter().enumerate() {
        let col = columns.first[j];
        let at = state.joints[j].position;
        for (target, sign) in [(Some(joint.body), 1.0), (joint.other, -1.0)] {
            let Some(k) = target else { continue };
            let Moment { row, scale, about } = moments[k];
            let arm = at - about;
            let mut put = |c: usize, f: C, couple: f64| {
                a[(3 * k, c)] += sign * f.re;
                a[(3 * k + 1, c)] += sign * f.im;
                a[(row, c)] += sign * scale * (cross(arm, f) + couple);
            };
            match columns.kinds[j] {
                Unknowns::Pin => {
                    put(col, C::new(1.0, 0.0), 0.0);
                    put(col + 1, C::new(0.0, 1.0), 0.0);
                }
                Unknowns::Slide { n } => {
                    put(col, n, 0.0);
                    put(col + 1, C::new(0.0, 0.0), 1.0);
                }
                Unknowns::Along { d } => put(col, d, 0.0),
            }
        }
    }
}

/// A tied mesh's equation each, after the `bodies`' 3 rows each: its force equals `factor`
/// times the tied joint's force component along `direction`.
fn tie_rows(bodies: usize, columns: &Columns, a: &mut Mat<f64>) {
    for (t, &(mesh, tied, direction, factor)) in columns.ties.iter().enumerate() {
        let row = 3 * bodies + t;
        a[(row, columns.first[mesh])] = 1.0;
        let c = columns.first[tied];
        match columns.kinds[tied] {
            Unknowns::Pin => {
                a[(row, c)] -= factor * direction.re;
                a[(row, c + 1)] -= factor * direction.im;
            }
            Unknowns::Slide { n } => a[(row, c)] -= factor * dot(n, direction),
            Unknowns::Along { d } => a[(row, c)] -= factor * dot(d, direction),
        }
    }
}

/// The bodies' inertia in the right-hand side `b`: m·a in each body's force rows, J·α in its own
/// moment row; a lumped body's moment about its joint, J·α + (g − joint) × m·a, added to the row
/// it joins (after that row's own terms are set).
fn inertia_rows(topology: &Topology, state: &State, moments: &[Moment], b: &mut Mat<f64>) {
    let bodies = &topology.bodies;
    for (k, (body, m)) in bodies.iter().zip(&state.bodies).enumerate() {
        let rhs = body.mass * m.cg.acceleration;
        b[(3 * k, 0)] = rhs.re;
        b[(3 * k + 1, 0)] = rhs.im;
        if moments[k].row == 3 * k + 2 {
            b[(3 * k + 2, 0)] = body.inertia * m.angular_acceleration;
        }
    }
    for (k, (body, m)) in bodies.iter().zip(&state.bodies).enumerate() {
        let Moment { row, scale, about } = moments[k];
        if row != 3 * k + 2 {
            let rhs = body.mass * m.cg.acceleration;
            b[(row, 0)] +=
                scale * (body.inertia * m.angular_acceleration + cross(m.cg.position - about, rhs));
        }
    }
}

/// Where a body's moment equation goes: its own row, about its centre of gravity; or, for a
/// body lumped with the crankshaft ([`cardan_mechanism::Body::lumped`]), the crankshaft's row,
/// taken about the joint between them and times the body's speed ratio (virtual power).
#[derive(Debug, Clone, Copy)]
struct Moment {
    row: usize,
    scale: f64,
    about: C,
}

impl Moment {
    fn of(topology: &Topology, state: &State, k: usize) -> Self {
        let own = Self {
            row: 3 * k + 2,
            scale: 1.0,
            about: state.bodies[k].cg.position,
        };
        let c = topology.crankshaft;
        let Some(ratio) = topology.bodies[k].lumped else {
            return own;
        };
        let pair = |j: &cardan_mechanism::Joint| {
            (j.body == k && j.other == Some(c)) || (j.body == c && j.other == Some(k))
        };
        match topology.joints.iter().position(pair) {
            Some(j) if k != c => Self {
                row: 3 * c + 2,
                scale: ratio,
                about: state.joints[j].position,
            },
            // Not carried by the crankshaft: its own joints hold it after all.
            _ => own,
        }
    }
}

fn dot(a: C, b: C) -> f64 {
    a.re * b.re + a.im * b.im
}
