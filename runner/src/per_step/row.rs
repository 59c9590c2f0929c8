//! The per-step row of one crank train, defined once: its documented columns ([`COLUMNS`]),
//! its header for a mechanism and a run ([`RunLayout`]), how a step fills it ([`Row`]), and the
//! check that its numbers are finite.

use super::lane::Lane;
use cardan_dynamics::{radial, tangential, StageColumn, Step};
use cardan_mechanism::{JointKind, Mechanism, PolarComponents};
use std::ops::Range;
use std::sync::Arc;

/// The per-step CSV columns: a name template (units in the name; `{piston}`, `{body}`,
/// `{joint}`, `{extra}`, `{family}` stand for names of the mechanism's topology and the run's
/// load families), and its meaning. The column table of docs/results.md is made from this list.
pub const COLUMNS: &[(&str, &str)] = &[
    ("crank_angle_deg", "crank angle θ from the +x axis (90° is top dead centre of an in-line machine)"),
    ("time_s", "time since the start of the run"),
    ("crank_speed_rad_s", "crank angular velocity ω"),
    ("crank_acceleration_rad_s2", "crank angular acceleration α"),
    ("{piston}_position_m", "piston-pin distance along the cylinder axis from the main bearing axis"),
    ("{piston}_velocity_m_s", "piston velocity along the cylinder, positive away from the crankshaft"),
    ("{piston}_acceleration_m_s2", "piston acceleration along the cylinder"),
    ("{piston}_dx_dtheta_m_rad", "dx/dθ: dV/dθ = −bore area × this"),
    ("{body}_angle_deg", "orientation of the body"),
    ("{body}_angular_velocity_rad_s", "angular velocity of the body"),
    ("{body}_angular_acceleration_rad_s2", "angular acceleration of the body"),
    ("{body}_cg_x_m", "centre of gravity, x"),
    ("{body}_cg_y_m", "centre of gravity, y (along the cylinder)"),
    ("{body}_cg_velocity_m_s", "speed of the centre of gravity"),
    ("{body}_cg_acceleration_m_s2", "acceleration magnitude of the centre of gravity"),
    ("{body}_cg_radial_acceleration_m_s2", "its radial part about the main axis (Karhula 4.1.3)"),
    ("{body}_cg_coriolis_acceleration_m_s2", "its Coriolis part 2·v_r·ω"),
    ("{body}_cg_tangential_acceleration_m_s2", "its tangential part |Z|·α"),
    ("{body}_cg_normal_acceleration_m_s2", "its normal part −|Z|·ω²"),
    ("{joint}_speed_rad_s", "pins: angular velocity of the joint's first body relative to its second"),
    ("{joint}_speed_m_s", "slides: sliding velocity of the first body relative to the second along the slide; meshes: pitch-line velocity relative to the gear carrier"),
    ("{extra}", "a quantity of one mechanism (see its section)"),
    ("cylinder_pressure_pa", "absolute cylinder pressure (empty without a gas model); not always gas_force_n / piston area: the Karhula models put no force on their open strokes (docs/results.md)"),
    ("gas_force_n", "gas force on the piston, towards the crankshaft (empty without a gas model)"),
    ("{family}_{joint}_force_x_n", "force on the joint's first body from its second, x"),
    ("{family}_{joint}_force_y_n", "the same, y"),
    ("{family}_{joint}_force_magnitude_n", "its magnitude"),
    ("{family}_{joint}_moment_nm", "couple a slide carries"),
    ("{family}_{joint}_tangential_n", "gear meshes: the force along the pitch-circle tangent (the tooth load that transmits torque, Karhula A8.1.10)"),
    ("{family}_{joint}_radial_n", "gear meshes: the force towards the first gear's centre"),
    ("{family}_torque_nm", "drive torque on the crankshaft, positive in the direction of rotation"),
    ("{family}_torque_{body}_nm", "the body's share of it by the power balance (Karhula's T_1i10, T_2i10, T_3i10); empty while the crank stands still"),
    ("{joint}_dynamic_tooth_load_n", "with [gear]: Buckingham's dynamic tooth load of the mesh (Karhula A8.1.14), per gear set"),
    ("{joint}_contact_stress_pa", "with [gear]: AGMA contact stress of the mesh"),
    ("{joint}_bending_stress_pa", "with [gear] and known J: AGMA bending stress, the larger member's"),
    ("{joint}_iso_contact_stress_pa", "with [gear] standard = \"iso6336\" or \"both\": ISO 6336-2 method B contact stress σ_H of the mesh, the larger member's"),
    ("{joint}_iso_bending_stress_pa", "with [gear] standard = \"iso6336\" or \"both\": ISO 6336-3 method B tooth root stress σ_F, the larger member's"),
    ("friction_torque_nm", "with [friction]: the drive torque that covers the losses, Σ P / ω"),
    ("power_loss_{component}_w", "with [friction]: one loss component's power (rings, skirt, a slide, a revolute joint's bearings by joint name, a gear mesh by joint name)"),
    // The whole machine (issues 24, 35; the `machine_stage` of cardan-dynamics).
    ("shaking_force_x_n", "with [layout] or [balance]: the machine's shaking force on the frame, x: −Σ m·a of every moving body and rotor (counterweights, balance shafts) of every cylinder"),
    ("shaking_force_y_n", "the same, y"),
    ("shaking_moment_pitch_nm", "with [layout] or [balance]: the machine's free moment about the horizontal axis across the crank axis, at the crank-axis point midway between the outermost cylinders"),
    ("shaking_moment_yaw_nm", "the same, about the vertical axis"),
    ("machine_torque_nm", "the whole crankshaft's drive torque: every cylinder's gas and inertia at its own crank angle, axis and firing phase, plus with [friction] every cylinder's Σ P / ω; one cylinder: its total_torque_nm (+ friction_torque_nm)"),
    ("main_bearing_{k}_force_x_n", "load on the crankshaft at main journal k (from 1, along the crank axis) from the frame, x in the machine frame: one journal for a one-throw machine (its cylinders' main-bearing loads summed), else one each side of every throw, each throw's load split half to each"),
    ("main_bearing_{k}_force_y_n", "the same, y"),
    ("cylinder_{k}_crank_pin_force_x_n", "load on the crankshaft at cylinder k's crank pin from its rod (or wheel), x in the machine frame"),
    ("cylinder_{k}_crank_pin_force_y_n", "the same, y"),
    ("cylinder_{k}_gas_force_n", "with a gas model: the gas force on cylinder k's piston at its own firing phase, towards the crankshaft"),
];

/// Where the groups of a row's columns are that a row for the charts alone may leave unfilled
/// ([`Row::skip_unread`]).
#[derive(Clone)]
struct Groups {
    /// The body columns (orientation, centre-of-gravity motion and its polar parts).
    bodies: Range<usize>,
    /// The joints' speeds and the extras.
    speeds: Range<usize>,
    /// Per force block (each family, then their total): its joints' load columns, and its
    /// torque shares.
    loads: Vec<(Range<usize>, Range<usize>)>,
}

/// Which of a row's [`Groups`] it fills.
#[derive(Clone)]
struct Fill {
    bodies: bool,
    speeds: bool,
    loads: Vec<(bool, bool)>,
}

/// The CSV header of `mechanism` run with the load families `families` (the run's, then
/// `total` when there are several), and where its groups of columns are; [`Row::fill`] fills
/// a row in this order.
fn header(
    mechanism: &dyn Mechanism,
    families: &[&str],
    gas: bool,
    stages: &[Vec<StageColumn>],
) -> (Vec<String>, Groups) {
    let t = mechanism.topology();
    let mut h: Vec<String> = [
        "crank_angle_deg",
        "time_s",
        "crank_speed_rad_s",
        "crank_acceleration_rad_s2",
    ]
    .map(String::from)
    .to_vec();
    for p in &t.pistons {
        for s in [
            "position_m",
            "velocity_m_s",
            "acceleration_m_s2",
            "dx_dtheta_m_rad",
        ] {
            h.push(format!("{}_{s}", p.name));
        }
    }
    let bodies_start = h.len();
    for b in &t.bodies {
        for s in [
            "angle_deg",
            "angular_velocity_rad_s",
            "angular_acceleration_rad_s2",
            "cg_x_m",
            "cg_y_m",
            "cg_velocity_m_s",
            "cg_acceleration_m_s2",
            "cg_radial_acceleration_m_s2",
            "cg_coriolis_acceleration_m_s2",
            "cg_tangential_acceleration_m_s2",
            "cg_normal_acceleration_m_s2",
        ] {
            h.push(format!("{}_{s}", b.name));
        }
    }
    let bodies = bodies_start..h.len();
    for j in &t.joints {
        let unit = match j.kind {
            JointKind::Revolute(_) => "rad_s",
            JointKind::Prismatic | JointKind::GearMesh { .. } => "m_s",
        };
        h.push(format!("{}_speed_{unit}", j.name));
    }
    h.extend(t.extras.iter().map(|e| e.name.to_string()));
    let speeds = bodies.end..h.len();
    let mut loads = Vec::new();
    if gas {
        h.push("cylinder_pressure_pa".into());
        h.push("gas_force_n".into());
    }
    for f in families {
        let joints_start = h.len();
        for j in &t.joints {
            for s in ["force_x_n", "force_y_n", "force_magnitude_n"] {
                h.push(format!("{f}_{}_{s}", j.name));
            }
            match j.kind {
                JointKind::Prismatic => h.push(format!("{f}_{}_moment_nm", j.name)),
                JointKind::GearMesh { .. } => {
                    h.push(format!("{f}_{}_tangential_n", j.name));
                    h.push(format!("{f}_{}_radial_n", j.name));
                }
                JointKind::Revolute(_) => {}
            }
        }
        let joints = joints_start..h.len();
        h.push(format!("{f}_torque_nm"));
        let shares_start = h.len();
        for b in &t.bodies {
            h.push(format!("{f}_torque_{}_nm", b.name));
        }
        loads.push((joints, shares_start..h.len()));
    }
    h.extend(stages.iter().flatten().map(|c| c.name.clone()));
    let groups = Groups {
        bodies,
        speeds,
        loads,
    };
    (h, groups)
}

/// What a run's steps hold besides the mechanism's own state: the load families (in the run's
/// order), a gas model, the columns of each of the run's stages (in the run's order).
pub struct RunLayout<'b> {
    pub families: &'b [&'b str],
    pub gas: bool,
    pub stages: &'b [Vec<StageColumn>],
}

/// The per-step row of one crank train: its column names and how a [`Step`] fills it. The
/// files and the charts both take their rows from here, so that a column's name and its value
/// are defined in one place.
#[derive(Clone)]
pub struct Row<'a> {
    mechanism: &'a dyn Mechanism,
    /// Shared by the copies a shared run makes.
    header: Arc<[String]>,
    /// Where its groups of columns are, and which it fills; the others are NaN. The bodies' arc
    /// tangents and hypotenuses are most of a row's cost, and no chart draws them: a row for
    /// the charts alone skips them, and the groups it does not read.
    groups: Groups,
    fill: Fill,
    /// Families with a total (the names of the header's force blocks).
    with_total: bool,
    total_shares: Vec<f64>,
    /// Which of each stage's values its columns hold.
    stages: Arc<[Vec<usize>]>,
}

impl<'a> Row<'a> {
    /// The row of `mechanism` run with `run`'s families and stages.
    pub fn new(mechanism: &'a dyn Mechanism, run: &RunLayout) -> Self {
        let mut names: Vec<&str> = run.families.to_vec();
        let with_total = run.families.len() > 1;
        if with_total {
            names.push("total");
        }
        let (header, groups) = header(mechanism, &names, run.gas, run.stages);
        Self {
            mechanism,
            header: header.into(),
            fill: Fill {
                bodies: true,
                speeds: true,
                loads: vec![(true, true); groups.loads.len()],
            },
            groups,
            with_total,
            total_shares: vec![0.0; mechanism.topology().bodies.len()],
            stages: run
                .stages
                .iter()
                .map(|s| s.iter().map(|c| c.value).collect())
                .collect(),
        }
    }

    /// The column names.
    pub fn header(&self) -> &[String] {
        &self.header
    }

    /// Leaves each group of columns (the bodies', the joints' speeds and the extras, each force
    /// block's joint loads, its torque shares) NaN unless `reads` says one of its columns is
    /// read (by its index).
    pub fn skip_unread(&mut self, reads: impl Fn(usize) -> bool) {
        let any = |r: &Range<usize>| r.clone().any(&reads);
        let g = &self.groups;
        self.fill = Fill {
            bodies: any(&g.bodies),
            speeds: any(&g.speeds),
            loads: g.loads.iter().map(|(j, s)| (any(j), any(s))).collect(),
        };
    }

    /// Appends the step's row to `r` (NaN for a quantity undefined at the step, and in the
    /// groups [skipped](Row::skip_unread)).
    pub fn fill(&mut self, s: &Step, r: &mut Vec<f64>) {
        let start = r.len();
        self.fill_into(s, r);
        debug_assert_eq!(
            r.len() - start,
            self.header.len(),
            "a row must match the header"
        );
    }

    /// Writes the row of the step `s` into `r`, a row's room (NaN for a quantity undefined at
    /// the step): every column, but the groups [skipped](Row::skip_unread) left as they are.
    pub(super) fn fill_slice(&mut self, s: &impl Lane, r: &mut [f64]) {
        assert_eq!(
            r.len(),
            self.header.len(),
            "a row's room must match the header"
        );
        let mut cursor = Cursor { out: r, at: 0 };
        self.fill_into(s, &mut cursor);
        debug_assert_eq!(cursor.at, self.header.len(), "a row must match the header");
    }

    /// The row of the step `s`, column by column into `r`: the row's one definition.
    fn fill_into(&mut self, s: &impl Lane, r: &mut impl Columns) {
        let t = self.mechanism.topology();
        let crank = s.crank();
        r.put([
            crank.angle.to_degrees(),
            crank.time,
            crank.speed,
            crank.acceleration,
        ]);
        for p in 0..t.pistons.len() {
            let p = s.piston(p);
            r.put([p.position, p.velocity, p.acceleration, p.dx_dtheta]);
        }
        if self.fill.bodies {
            for b in 0..t.bodies.len() {
                let b = s.body(b);
                let polar = PolarComponents::of(&b.cg);
                r.put([
                    b.orientation.arg().to_degrees(),
                    b.angular_velocity,
                    b.angular_acceleration,
                    b.cg.position.re,
                    b.cg.position.im,
                    b.cg.velocity.norm(),
                    b.cg.acceleration.norm(),
                    polar.radial_acceleration,
                    polar.coriolis_acceleration,
                    polar.tangential_acceleration,
                    polar.normal_acceleration,
                ]);
            }
        } else {
            r.skip(self.groups.bodies.len());
        }
        if self.fill.speeds {
            r.put_each((0..t.joints.len()).map(|j| s.joint(j).relative_speed));
            r.put_each((0..t.extras.len()).map(|e| s.extra(e)));
        } else {
            r.skip(self.groups.speeds.len());
        }
        if let Some((pressure, force)) = s.gas() {
            r.put([pressure, force]);
        }
        let families = s.families();
        if self.with_total && self.fill.loads[families].1 {
            for (k, total) in self.total_shares.iter_mut().enumerate() {
                *total = (0..families).map(|f| s.share(f, k)).sum();
            }
        }
        // The families, then their total if there are several.
        for f in 0..families + usize::from(self.with_total) {
            let (joints, shares) = self.fill.loads[f];
            if joints {
                for (j, joint) in t.joints.iter().enumerate() {
                    let l = s.load(f, j);
                    r.put([l.force.re, l.force.im, l.force.norm()]);
                    match joint.kind {
                        JointKind::Prismatic => r.put([l.moment]),
                        JointKind::GearMesh { .. } => {
                            let m = s.joint(j);
                            r.put([tangential(l.force, &m), radial(l.force, &m)]);
                        }
                        JointKind::Revolute(_) => {}
                    }
                }
            } else {
                r.skip(self.groups.loads[f].0.len());
            }
            r.put([s.crank_torque(f)]);
            if !shares {
                r.skip(self.groups.loads[f].1.len());
            } else if f < families {
                r.put_each((0..self.total_shares.len()).map(|b| s.share(f, b)));
            } else {
                r.put_slice(&self.total_shares);
            }
        }
        for (k, columns) in self.stages.iter().enumerate().take(s.stages()) {
            r.put_each(columns.iter().map(|&value| s.stage(k, value)));
        }
    }
}

/// Where [`Row::fill_into`] puts a row's columns, in the header's order: appended to a
/// block of rows ([`Row::fill`]), or written into a row's room ([`Cursor`]).
trait Columns {
    /// The next `N` columns.
    fn put<const N: usize>(&mut self, values: [f64; N]);
    fn put_slice(&mut self, values: &[f64]);
    fn put_each(&mut self, values: impl ExactSizeIterator<Item = f64>);
    /// Passes the next `n` columns, unfilled (NaN in a block of rows).
    fn skip(&mut self, n: usize);
}

impl Columns for Vec<f64> {
    #[inline(always)]
    fn put<const N: usize>(&mut self, values: [f64; N]) {
        self.extend(values);
    }

    #[inline(always)]
    fn put_slice(&mut self, values: &[f64]) {
        self.extend_from_slice(values);
    }

    #[inline(always)]
    fn put_each(&mut self, values: impl ExactSizeIterator<Item = f64>) {
        // One at a time: fewer instructions than extend's here (measured).
        for v in values {
            self.push(v);
        }
    }

    #[inline(always)]
    fn skip(&mut self, n: usize) {
        self.resize(self.len() + n, f64::NAN);
    }
}

/// A row's room and the next column's index ([`Row::fill_slice`]).
struct Cursor<'r> {
    out: &'r mut [f64],
    at: usize,
}

impl Columns for Cursor<'_> {
    #[inline(always)]
    fn put<const N: usize>(&mut self, values: [f64; N]) {
        self.put_slice(&values);
    }

    #[inline(always)]
    fn put_slice(&mut self, values: &[f64]) {
        self.out[self.at..self.at + values.len()].copy_from_slice(values);
        self.at += values.len();
    }

    #[inline(always)]
    fn put_each(&mut self, values: impl ExactSizeIterator<Item = f64>) {
        let n = values.len();
        for (out, v) in self.out[self.at..self.at + n].iter_mut().zip(values) {
            *out = v;
        }
        self.at += n;
    }

    #[inline(always)]
    fn skip(&mut self, n: usize) {
        self.at += n;
    }
}

/// Fails the step `s` if a number of its row `row` among `columns` is infinite, naming the
/// column (the CSV's name) and the crank angle: the stepper checks what the loads are made of
/// (NaN included), but a derived column (a magnitude, a torque share, a power) can still
/// overflow. A NaN here is a documented empty cell (a torque share while the crank stands
/// still, an extra where it is undefined).
pub(super) fn finite_row(
    header: &[String],
    row: &[f64],
    columns: impl IntoIterator<Item = usize>,
    s: &impl Lane,
) -> Result<(), String> {
    match columns.into_iter().find(|&k| row[k].is_infinite()) {
        None => Ok(()),
        Some(k) => Err(format!(
            "crank angle {:.4}°: {} is not finite ({})",
            s.crank().angle.to_degrees(),
            header[k],
            row[k]
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cardan_mechanism::{MachineGeometry, MassInputs, Options, MECHANISMS};

    /// A per-step file's columns are found by name (pandas, the NPY files): no two of a row may
    /// share one, for any registered mechanism with every family, the gas and the balance stage.
    #[test]
    fn every_column_name_is_unique() {
        let geometry = MachineGeometry {
            crank_length: 0.06,
            rod_length: 0.14,
            bore: 0.12,
            pin_offset: 0.0,
        };
        let machine = cardan_dynamics::machine_stage::SHAKING_COLUMNS;
        let balance: Vec<StageColumn> = (machine.iter())
            .chain([&cardan_dynamics::machine_stage::TORQUE_COLUMN])
            .enumerate()
            .map(|(value, name)| StageColumn {
                name: name.to_string(),
                value,
            })
            .collect();
        let stages = [balance];
        for entry in MECHANISMS {
            let m = (entry.build)(&geometry, &MassInputs::default(), &Options::new()).unwrap();
            let run = RunLayout {
                families: &["inertial", "gas"],
                gas: true,
                stages: &stages,
            };
            let row = Row::new(m.as_ref(), &run);
            let mut seen = std::collections::BTreeSet::new();
            for name in row.header() {
                assert!(seen.insert(name), "{}: column {name} twice", entry.name);
            }
        }
    }
}
