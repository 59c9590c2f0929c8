//! A general planar kinetostatic solve: the Newton-Euler equations of every link, with every
//! joint reaction unknown, assembled into one linear system per step and solved by least
//! squares (faer's QR). It knows nothing of slider-cranks or cardan gears: the mechanisms are
//! described by [`slider_crank_model`] and [`cardan_gear_model`], and its answers are compared
//! with the closed forms of Karhula (2008) in the tests.
//!
//! For each body: Σ F = m·a_g and Σ M_g = J·α (d'Alembert: Beer & Johnston, as cited in Karhula
//! ch. 5). A least-squares solve accepts the identically satisfied equations of point-like links
//! (whose moment row is empty) and reports the residual, so that a statically inconsistent
//! model shows itself instead of passing silently.

use crate::kinetostatics::cross;
use crate::{Loads, MassProperties};
use cardan_mechanism::{KinematicState, MechanismKind, PointMotion, C};
use faer::linalg::solvers::SolveLstsq;
use faer::Mat;

/// A rigid link moving in the plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Body {
    /// kg.
    pub mass: f64,
    /// About the centre of gravity, kg·m².
    pub inertia: f64,
    /// Centre of gravity, m.
    pub cg: C,
    /// m/s².
    pub cg_acceleration: C,
    /// rad/s².
    pub angular_acceleration: f64,
    /// External force through the centre of gravity (the gas on the piston), N.
    pub applied_force: C,
}

/// A joint; `other: None` is the frame. Each joint's unknown is the reaction on `body` from
/// `other`; `other` receives its opposite.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Joint {
    /// Revolute joint at `at`: two unknown force components.
    Pin {
        body: usize,
        other: Option<usize>,
        at: C,
    },
    /// A contact that only transmits force along the unit vector `direction`: one unknown.
    Contact {
        body: usize,
        other: Option<usize>,
        at: C,
        direction: C,
    },
    /// The drive torque on `body` from the frame: one unknown.
    Drive { body: usize },
}

/// An extra linear relation: the magnitude of `contact` (a [`Joint::Contact`]) equals `factor`
/// times the component along `direction` of the force of `pin` (a [`Joint::Pin`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tie {
    pub contact: usize,
    pub pin: usize,
    pub direction: C,
    pub factor: f64,
}

/// A mechanism at one instant, as the solver sees it.
#[derive(Debug, Clone, PartialEq)]
pub struct Model {
    pub bodies: Vec<Body>,
    pub joints: Vec<Joint>,
    pub ties: Vec<Tie>,
}

/// The reaction of each joint, in the order of [`Model::joints`]: the force on `body` (zero
/// for a drive) and the torque (zero but for a drive).
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    pub forces: Vec<C>,
    pub torques: Vec<f64>,
    /// Euclidean norm of the equation residual, in the units of the equations (N and N·m).
    pub residual: f64,
}

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PlanarError {
    #[error("the model has {equations} equations for {unknowns} unknowns: it is statically indeterminate")]
    Indeterminate { equations: usize, unknowns: usize },
}

impl Model {
    /// Solves for all joint reactions.
    pub fn solve(&self) -> Result<Solution, PlanarError> {
        let mut columns = Vec::with_capacity(self.joints.len());
        let mut unknowns = 0;
        for j in &self.joints {
            columns.push(unknowns);
            unknowns += match j {
                Joint::Pin { .. } => 2,
                Joint::Contact { .. } | Joint::Drive { .. } => 1,
            };
        }
        let equations = 3 * self.bodies.len() + self.ties.len();
        if equations < unknowns {
            return Err(PlanarError::Indeterminate {
                equations,
                unknowns,
            });
        }
        let mut a = Mat::<f64>::zeros(equations, unknowns);
        let mut b = Mat::<f64>::zeros(equations, 1);
        for (k, body) in self.bodies.iter().enumerate() {
            let rhs = body.mass * body.cg_acceleration - body.applied_force;
            b[(3 * k, 0)] = rhs.re;
            b[(3 * k + 1, 0)] = rhs.im;
            b[(3 * k + 2, 0)] = body.inertia * body.angular_acceleration;
        }
        for (j, joint) in self.joints.iter().enumerate() {
            let col = columns[j];
            match *joint {
                Joint::Pin { body, other, at } => {
                    for (target, sign) in [(Some(body), 1.0), (other, -1.0)] {
                        let Some(k) = target else { continue };
                        let arm = at - self.bodies[k].cg;
                        a[(3 * k, col)] += sign;
                        a[(3 * k + 1, col + 1)] += sign;
                        // arm × (Fx, Fy) = arm.re·Fy − arm.im·Fx
                        a[(3 * k + 2, col)] -= sign * arm.im;
                        a[(3 * k + 2, col + 1)] += sign * arm.re;
                    }
                }
                Joint::Contact {
                    body,
                    other,
                    at,
                    direction,
                } => {
                    for (target, sign) in [(Some(body), 1.0), (other, -1.0)] {
                        let Some(k) = target else { continue };
                        a[(3 * k, col)] += sign * direction.re;
                        a[(3 * k + 1, col)] += sign * direction.im;
                        a[(3 * k + 2, col)] += sign * cross(at - self.bodies[k].cg, direction);
                    }
                }
                Joint::Drive { body } => a[(3 * body + 2, col)] += 1.0,
            }
        }
        for (t, tie) in self.ties.iter().enumerate() {
            let row = 3 * self.bodies.len() + t;
            a[(row, columns[tie.contact])] = 1.0;
            a[(row, columns[tie.pin])] = -tie.factor * tie.direction.re;
            a[(row, columns[tie.pin] + 1)] = -tie.factor * tie.direction.im;
        }
        let x = a.qr().solve_lstsq(&b);
        let residual = (&a * &x - &b).norm_l2();
        let mut forces = Vec::with_capacity(self.joints.len());
        let mut torques = Vec::with_capacity(self.joints.len());
        for (j, joint) in self.joints.iter().enumerate() {
            let col = columns[j];
            let (f, t) = match *joint {
                Joint::Pin { .. } => (C::new(x[(col, 0)], x[(col + 1, 0)]), 0.0),
                Joint::Contact { direction, .. } => (x[(col, 0)] * direction, 0.0),
                Joint::Drive { .. } => (C::new(0.0, 0.0), x[(col, 0)]),
            };
            forces.push(f);
            torques.push(t);
        }
        Ok(Solution {
            forces,
            torques,
            residual,
        })
    }
}

const CRANKSHAFT: usize = 0;
const ROD_OR_WHEEL: usize = 1;
const RECIPROCATING: usize = 2;

impl Body {
    /// A crankshaft assembly turning about the main axis, its centre of gravity on the axis.
    fn crankshaft(inertia: f64, angular_acceleration: f64) -> Self {
        let zero = C::new(0.0, 0.0);
        Body {
            mass: 0.0,
            inertia,
            cg: zero,
            cg_acceleration: zero,
            angular_acceleration,
            applied_force: zero,
        }
    }

    /// A translating mass on the cylinder axis at `point`, pushed by the gas.
    fn reciprocating(mass: f64, point: &PointMotion, piston_force: f64) -> Self {
        Body {
            mass,
            inertia: 0.0,
            cg: point.position,
            cg_acceleration: point.acceleration,
            angular_acceleration: 0.0,
            applied_force: C::new(0.0, -piston_force),
        }
    }
}

/// Crankshaft, a middle link and a reciprocating link: main bearing, crank pin, the pin
/// between the middle and reciprocating links at `upper_pin`, one more contact, the drive.
fn crank_train(
    state: &KinematicState,
    crankshaft_inertia: f64,
    middle: Body,
    reciprocating: Body,
    upper_pin: C,
    contact: Joint,
    ties: Vec<Tie>,
) -> Model {
    Model {
        bodies: vec![
            Body::crankshaft(crankshaft_inertia, state.crank.acceleration),
            middle,
            reciprocating,
        ],
        joints: vec![
            Joint::Pin {
                body: CRANKSHAFT,
                other: None,
                at: C::new(0.0, 0.0),
            },
            Joint::Pin {
                body: CRANKSHAFT,
                other: Some(ROD_OR_WHEEL),
                at: state.crank_pin.position,
            },
            Joint::Pin {
                body: RECIPROCATING,
                other: Some(ROD_OR_WHEEL),
                at: upper_pin,
            },
            contact,
            Joint::Drive { body: CRANKSHAFT },
        ],
        ties,
    }
}

/// Slider-crank: crankshaft (centre of gravity on the main axis), rod, piston (a point mass at
/// the piston pin). Joints: main bearing, crank pin, piston pin, cylinder wall, drive.
pub fn slider_crank_model(
    state: &KinematicState,
    masses: &MassProperties,
    piston_force: f64,
) -> Model {
    let pin_b = state.piston_pin.position;
    let rod = Body {
        mass: masses.rod_mass,
        inertia: masses.rod_inertia,
        cg: state.rod.point.position,
        cg_acceleration: state.rod.point.acceleration,
        angular_acceleration: state.rod.angular_acceleration,
        applied_force: C::new(0.0, 0.0),
    };
    let piston = Body::reciprocating(masses.piston_mass, &state.piston_pin, piston_force);
    let wall = Joint::Contact {
        body: RECIPROCATING,
        other: None,
        at: pin_b,
        direction: C::new(1.0, 0.0),
    };
    crank_train(
        state,
        masses.crankshaft_inertia,
        rod,
        piston,
        pin_b,
        wall,
        vec![],
    )
}

/// Cardan gear: crankshaft assembly (carrying the wheel's inertia, Karhula ch. 11.2), cardan
/// wheel, reciprocating assembly (piston, pin and rod on the cylinder axis). Joints: main
/// bearing, crank pin S, wheel pin T, gear mesh at the pitch point (a contact along the
/// cylinder axis whose force the thesis ties to the rod force, A5.2.1.48-51), drive. There is
/// no cylinder-wall joint: the rod's straight line comes from the gears.
pub fn cardan_gear_model(
    state: &KinematicState,
    masses: &MassProperties,
    piston_force: f64,
) -> Model {
    let axis = C::new(0.0, 1.0);
    let wheel_motion = state.wheel.expect("a cardan gear state has a wheel");
    let pin_t = state.rod.lower_pin;
    let wheel = Body {
        mass: 0.0,
        inertia: 0.0,
        cg: state.crank_pin.position,
        cg_acceleration: state.crank_pin.acceleration,
        angular_acceleration: wheel_motion.angular_acceleration,
        applied_force: C::new(0.0, 0.0),
    };
    let assembly = Body::reciprocating(
        masses.reciprocating_mass(MechanismKind::CardanGear),
        &pin_t,
        piston_force,
    );
    let mesh = Joint::Contact {
        body: ROD_OR_WHEEL,
        other: None,
        at: wheel_motion.mesh_point,
        direction: axis,
    };
    // Mesh force on the wheel = the rod's force on the wheel = −(force on the rod from the wheel).
    let tie = Tie {
        contact: 3,
        pin: 2,
        direction: axis,
        factor: -1.0,
    };
    crank_train(
        state,
        masses.crankshaft_inertia + masses.wheel_inertia,
        wheel,
        assembly,
        pin_t.position,
        mesh,
        vec![tie],
    )
}

/// The loads of one step by the general solve, in the conventions of [`Loads`], with the
/// residual of the solve.
pub fn loads(
    kind: MechanismKind,
    state: &KinematicState,
    masses: &MassProperties,
    piston_force: f64,
) -> (Loads, f64) {
    let model = match kind {
        MechanismKind::SliderCrank => slider_crank_model(state, masses, piston_force),
        MechanismKind::CardanGear => cardan_gear_model(state, masses, piston_force),
    };
    let s = model
        .solve()
        .expect("both mechanism models are determinate");
    let f = &s.forces;
    let loads = Loads {
        main_bearing: f[0],
        crank_pin: f[1],
        piston_pin: f[2],
        piston_side: match kind {
            MechanismKind::SliderCrank => f[3].re,
            MechanismKind::CardanGear => 0.0,
        },
        gear_mesh: match kind {
            MechanismKind::SliderCrank => C::new(0.0, 0.0),
            MechanismKind::CardanGear => f[3],
        },
        crank_torque: s.torques[4],
        torque_by_link: [0.0; 3],
        rod_percussion_centre: None,
    };
    (loads, s.residual)
}
