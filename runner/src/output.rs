//! Result files: `summary.json` and, per mechanism, a CSV streamed one row per step. A case's
//! files are written into a fresh temporary folder that then replaces the case's folder as a
//! whole, so no file of an earlier run survives beside the new ones.

use crate::case::{Case, OutputOptions};
use crate::run::MechanismResult;
use anyhow::Context;
use cardan_dynamics::{radial, tangential, GearRatings, Sink, Step};
use cardan_mechanism::{JointKind, Mechanism, PolarComponents};
use serde_json::{json, Map, Value};
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// Version of the layout of `summary.json`; raised when a name or the shape changes.
pub const SCHEMA_VERSION: u32 = 2;

/// The summary of a case as JSON (see README.md, "Results").
pub fn summary_json(case: &Case, results: &[MechanismResult]) -> Value {
    let mut mechanisms = Map::new();
    for r in results {
        let m = r.mechanism.as_ref();
        let mut metrics = Map::new();
        let mut units = Map::new();
        for metric in &r.summary.metrics {
            metrics.insert(metric.name.clone(), json!(metric.value));
            units.insert(metric.name.clone(), json!(metric.unit));
        }
        let masses = m.masses();
        let mut mass_properties: Map<String, Value> = masses
            .fields()
            .iter()
            .map(|(name, value, _)| (name.to_string(), json!(value)))
            .collect();
        mass_properties.insert("rod_material".into(), json!(masses.rod_material.name()));
        let t = m.topology();
        let bodies: Map<String, Value> = t
            .bodies
            .iter()
            .map(|b| {
                (
                    b.name.to_string(),
                    json!({"mass_kg": b.mass, "inertia_kg_m2": b.inertia}),
                )
            })
            .collect();
        let joints: Map<String, Value> = t
            .joints
            .iter()
            .map(|j| {
                let between = json!([
                    t.bodies[j.body].name,
                    j.other.map_or("frame", |o| t.bodies[o].name)
                ]);
                let v = match j.kind {
                    JointKind::Revolute(b) => {
                        json!({"kind": "revolute", "bodies": between, "journal_radius_m": b.radius,
                            "bearings": b.count, "static_load_rating_N": b.static_load_rating})
                    }
                    JointKind::Prismatic => json!({"kind": "prismatic", "bodies": between}),
                    JointKind::GearMesh {
                        ratio,
                        pitch_radius,
                        internal,
                        pressure_angle,
                        ..
                    } => json!({
                        "kind": "gear_mesh",
                        "bodies": between,
                        "ratio": ratio,
                        "pitch_radius_m": pitch_radius,
                        "internal": internal,
                        "pressure_angle_deg": pressure_angle.to_degrees()
                    }),
                };
                (j.name.to_string(), v)
            })
            .collect();
        mechanisms.insert(
            r.label.clone(),
            json!({
                "metrics": metrics,
                "units": units,
                "mass_properties": mass_properties,
                "bodies": bodies,
                "joints": joints,
            }),
        );
    }
    json!({
        "schema_version": SCHEMA_VERSION,
        "case": case.name,
        "machine": case.machine.name(),
        "gas_model": case.gas.as_ref().map(|g| g.name()),
        "mechanisms": mechanisms,
    })
}

/// The per-step CSV columns: a name template (units in the name; `{piston}`, `{body}`,
/// `{joint}`, `{extra}`, `{family}` stand for names of the mechanism's topology and the run's
/// load families), and its meaning. The README's column table is made from this list.
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
    ("cylinder_pressure_pa", "absolute cylinder pressure (empty without a gas model)"),
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
    ("friction_torque_nm", "with [friction]: the drive torque that covers the losses, Σ P / ω"),
    ("power_loss_{component}_w", "with [friction]: one loss component's power (rings, skirt, a slide, a revolute joint's bearings by joint name, a gear mesh by joint name)"),
];

/// The CSV header of `mechanism` run with the load families `families`.
fn header(
    mechanism: &dyn Mechanism,
    families: &[&str],
    gas: bool,
    losses: &[String],
    gears: Option<&GearRatings>,
) -> Vec<String> {
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
    for j in &t.joints {
        let unit = match j.kind {
            JointKind::Revolute(_) => "rad_s",
            JointKind::Prismatic | JointKind::GearMesh { .. } => "m_s",
        };
        h.push(format!("{}_speed_{unit}", j.name));
    }
    h.extend(t.extras.iter().map(|e| e.name.to_string()));
    if gas {
        h.push("cylinder_pressure_pa".into());
        h.push("gas_force_n".into());
    }
    for f in families {
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
        h.push(format!("{f}_torque_nm"));
        for b in &t.bodies {
            h.push(format!("{f}_torque_{}_nm", b.name));
        }
    }
    if let Some(g) = gears {
        for (name, bending) in g.names().into_iter().zip(g.bending()) {
            h.push(format!("{name}_dynamic_tooth_load_n"));
            h.push(format!("{name}_contact_stress_pa"));
            if bending {
                h.push(format!("{name}_bending_stress_pa"));
            }
        }
    }
    if !losses.is_empty() {
        h.push("friction_torque_nm".into());
        h.extend(losses.iter().map(|c| format!("power_loss_{c}_w")));
    }
    h
}

/// What a run's steps hold besides the mechanism's own state: the load families (in the run's
/// order), a gas model, the loss components, the rated gear meshes.
pub struct RunLayout<'b> {
    pub families: &'b [&'b str],
    pub gas: bool,
    pub losses: &'b [String],
    pub gears: Option<&'b GearRatings>,
}

/// A sink writing one CSV row per step (every `decimation`-th step and the last).
pub struct CsvSink<'a> {
    mechanism: &'a dyn Mechanism,
    writer: csv::Writer<BufWriter<File>>,
    options: OutputOptions,
    last_step: usize,
    /// Families with a total (the names of the header's force blocks).
    with_total: bool,
    row: Vec<f64>,
    text: String,
    total_shares: Vec<f64>,
}

impl<'a> CsvSink<'a> {
    /// A CSV at `path` for `mechanism` run with `run`'s families and stages over
    /// `last_step + 1` steps.
    pub fn create(
        path: &Path,
        mechanism: &'a dyn Mechanism,
        run: &RunLayout,
        options: OutputOptions,
        last_step: usize,
    ) -> anyhow::Result<Self> {
        let file = File::create(path).with_context(|| format!("create {}", path.display()))?;
        let mut writer =
            csv::WriterBuilder::new().from_writer(BufWriter::with_capacity(1 << 16, file));
        let mut names: Vec<&str> = run.families.to_vec();
        let with_total = run.families.len() > 1;
        if with_total {
            names.push("total");
        }
        writer.write_record(header(mechanism, &names, run.gas, run.losses, run.gears))?;
        Ok(Self {
            mechanism,
            writer,
            options,
            last_step,
            with_total,
            row: Vec::new(),
            text: String::new(),
            total_shares: vec![0.0; mechanism.topology().bodies.len()],
        })
    }

    /// Writes out what is buffered.
    pub fn finish(mut self) -> anyhow::Result<()> {
        self.writer.flush()?;
        Ok(())
    }

    fn fill_row(&mut self, s: &Step) {
        let t = self.mechanism.topology();
        let st = s.state;
        let r = &mut self.row;
        r.clear();
        r.extend([
            st.crank.angle.to_degrees(),
            st.crank.time,
            st.crank.speed,
            st.crank.acceleration,
        ]);
        for p in &st.pistons {
            r.extend([p.position, p.velocity, p.acceleration, p.dx_dtheta]);
        }
        for b in &st.bodies {
            let polar = PolarComponents::of(&b.cg);
            r.extend([
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
        r.extend(st.joints.iter().map(|j| j.relative_speed));
        r.extend(&st.extras);
        if let Some(p) = s.pressure {
            r.push(p);
            r.push(s.piston_forces.first().copied().unwrap_or(0.0));
        }
        if self.with_total {
            for (k, total) in self.total_shares.iter_mut().enumerate() {
                *total = s.shares.iter().map(|sh| sh[k]).sum();
            }
        }
        let total = self
            .with_total
            .then_some((s.total, self.total_shares.as_slice()));
        let families = s.families.iter().zip(s.shares.iter().map(Vec::as_slice));
        for (loads, shares) in families.chain(total) {
            for ((j, l), m) in t.joints.iter().zip(&loads.joints).zip(&st.joints) {
                r.extend([l.force.re, l.force.im, l.force.norm()]);
                match j.kind {
                    JointKind::Prismatic => r.push(l.moment),
                    JointKind::GearMesh { .. } => {
                        r.extend([tangential(l.force, m), radial(l.force, m)]);
                    }
                    JointKind::Revolute(_) => {}
                }
            }
            r.push(loads.crank_torque);
            r.extend(shares);
        }
        for g in s.gears {
            r.extend([g.dynamic_load, g.contact_stress]);
            if !g.bending_stress.is_nan() {
                r.push(g.bending_stress);
            }
        }
        if !s.losses.is_empty() {
            r.push(s.friction_torque);
            r.extend(s.losses);
        }
    }
}

impl Sink for CsvSink<'_> {
    fn wants_details(&self) -> bool {
        true
    }

    fn push(&mut self, s: &Step) -> Result<(), String> {
        if s.index % self.options.decimation != 0 && s.index != self.last_step {
            return Ok(());
        }
        self.fill_row(s);
        let mut buffer = ryu::Buffer::new();
        for &v in &self.row {
            // A quantity undefined at this step (NaN) is an empty cell.
            let cell: &str = if v.is_nan() {
                ""
            } else if let Some(d) = self.options.significant_digits {
                use std::fmt::Write as _;
                self.text.clear();
                let _ = write!(self.text, "{:.*e}", d - 1, v);
                &self.text
            } else {
                buffer.format(v)
            };
            self.writer.write_field(cell).map_err(|e| e.to_string())?;
        }
        self.writer
            .write_record(None::<&[u8]>)
            .map_err(|e| e.to_string())
    }
}

/// Writes `contents` to `path`. No fsync: a case folder appears whole by a rename, and waiting
/// for the disk would cost more than the computation of a small case (10 000 pump cases of
/// 720 steps: 13.4 s with one fsync per case, 6.7 s without); durability across a power cut is not promised.
pub fn write_file(path: &Path, contents: &[u8]) -> anyhow::Result<()> {
    let mut f = File::create(path).with_context(|| format!("create {}", path.display()))?;
    f.write_all(contents)?;
    Ok(())
}

/// A fresh, empty temporary folder beside `dir`, to be moved onto it by [`replace_dir`].
pub fn temporary_dir(dir: &Path) -> anyhow::Result<PathBuf> {
    let parent = dir.parent().context("no parent folder")?;
    std::fs::create_dir_all(parent).with_context(|| format!("create {}", parent.display()))?;
    let name = dir.file_name().context("no folder name")?.to_string_lossy();
    let tmp = parent.join(format!(".{name}.tmp-{}", std::process::id()));
    if tmp.exists() {
        std::fs::remove_dir_all(&tmp)?;
    }
    std::fs::create_dir(&tmp).with_context(|| format!("create {}", tmp.display()))?;
    Ok(tmp)
}

/// Moves the finished folder `tmp` onto `dir`, replacing whatever was there as a whole.
pub fn replace_dir(tmp: &Path, dir: &Path) -> anyhow::Result<()> {
    if dir.exists() {
        let name = dir.file_name().context("no folder name")?.to_string_lossy();
        let old = dir.with_file_name(format!(".{name}.old-{}", std::process::id()));
        if old.exists() {
            std::fs::remove_dir_all(&old)?;
        }
        std::fs::rename(dir, &old).with_context(|| format!("move {} aside", dir.display()))?;
        std::fs::rename(tmp, dir).with_context(|| format!("rename to {}", dir.display()))?;
        std::fs::remove_dir_all(&old).with_context(|| format!("remove {}", old.display()))?;
    } else {
        std::fs::rename(tmp, dir).with_context(|| format!("rename to {}", dir.display()))?;
    }
    Ok(())
}
