//! A case's results: each crank train's [`MechanismResult`] (made by [`crate::run`]), and the
//! result file `summary.json` made of them (the per-step files are [`crate::per_step`]'s). A case's
//! files are written into a fresh temporary folder that then replaces the case's folder as a
//! whole ([`cardan_report::files`]), so no file of an earlier run survives beside the new ones.

use cardan_case::case::Case;
use cardan_dynamics::Summary;
use cardan_mechanism::{JointKind, Mechanism};
use serde_json::{json, Map, Value};
use std::sync::Arc;

/// The result of one crank train of a case: one per mechanism, two per mechanism in an
/// opposed-piston case with a crank phase offset.
#[derive(Debug, Clone)]
pub struct MechanismResult {
    pub mechanism: Arc<dyn Mechanism>,
    /// Its name in the outputs (the key in `summary.json`, the CSV's name): the mechanism's
    /// name, with `_crank2` for the second crank train of a phased opposed-piston case.
    pub label: String,
    pub summary: Summary,
    /// What the case should know about these results (a grid too coarse for its peaks), said
    /// on stderr and in summary.json and the report.
    pub warnings: Vec<String>,
    /// A solved motion's (time s, crank speed rad/s) at the start of every cycle it ran, the
    /// reported one's last (`summary.json`'s `cycle_starts`: the run-up before the reported
    /// cycle, drawn by the report's `crank_speed_time.svg`); empty for a prescribed motion.
    pub cycle_starts: Vec<(f64, f64)>,
    /// A solved motion's (time s, crank speed rad/s) through every cycle before the reported
    /// one, each cycle's start and its steps' extremes, thinned to at most
    /// [`cardan_dynamics::runup::MAX_RUNUP_POINTS`] (`summary.json`'s `runup`, drawn by
    /// `crank_speed_time.svg`), from the run's start to the reported cycle's; empty for a
    /// prescribed motion.
    pub runup: Vec<(f64, f64)>,
}

/// Version of the layout of `summary.json`; raised when a name or the shape changes.
pub const SCHEMA_VERSION: u32 = 2;

/// The machine the balance metrics are of (`[layout]`, `[balance]`; docs/results.md): its
/// layout's kind and number of cylinders, and the balancing devices, named as in case files
/// (`counterweight`: the fraction of the reciprocating mass balanced, `null` without a
/// counterweight).
fn layout_json(case: &Case) -> Value {
    let machine = &case.balance;
    json!({
        "kind": machine.kind,
        "cylinders": machine.layout.cylinders.len(),
        "counterweight": machine.counterweight,
        "balance_shafts": if machine.lanchester { "lanchester" } else { "none" },
        "cardan_counterweights": machine.cardan_counterweights,
    })
}

/// The gas chamber `mechanism` works on, for the report's indicator diagram (`pv_diagram.svg`):
/// the first piston's column, its top-dead-centre position, the piston area of all the pistons
/// on the chamber and the clearance volume, so that V = V_comp + n·A_pis·(x_TDC − x) (Karhula
/// 2008, A6.1.1.7, [`cardan_gas::Cylinder::volume_curve`]) follows from each row's piston
/// position. `None` without a gas model, a cylinder (the hypotrochoid's chambers are angles),
/// or where the volume is not one piston's (an opposed pair with a crank phase: the other
/// train's piston is in the other rows).
fn chamber_json(case: &Case, mechanism: &dyn Mechanism) -> Option<Value> {
    let gas = case.gas.as_ref()?;
    if !mechanism.has_cylinder() || case.crank_phase != 0.0 {
        return None;
    }
    let piston = mechanism.topology().pistons.first()?.name;
    let c = gas
        .cylinder(case.geometry.bore, mechanism.stroke(), case.pistons)
        .ok()?;
    Some(json!({
        "piston": piston,
        "piston_top_m": mechanism.piston_top(),
        "piston_area_m2": f64::from(c.pistons) * c.area,
        "swept_volume_m3": c.swept_volume,
        "clearance_volume_m3": c.clearance_volume,
    }))
}

/// The summary of a case as JSON (see docs/results.md).
pub fn summary_json(case: &Case, results: &[MechanismResult]) -> Value {
    let mut mechanisms = Map::new();
    for r in results {
        mechanisms.insert(r.label.clone(), mechanism_json(case, r));
    }
    let mut summary = json!({
        "schema_version": SCHEMA_VERSION,
        "case": case.name,
        "machine": case.machine.name(),
        "gas_model": case.gas.as_ref().map(|g| g.name()),
        "layout": layout_json(case),
    });
    summary["mechanisms"] = Value::Object(mechanisms);
    // The case's notes (inputs likely meant otherwise), then each crank train's warnings.
    let warnings: Vec<String> = (case.notes.iter().cloned())
        .chain(
            results
                .iter()
                .flat_map(|r| r.warnings.iter().map(move |w| format!("{}: {w}", r.label))),
        )
        .collect();
    if !warnings.is_empty() {
        summary["warnings"] = json!(warnings);
    }
    summary
}

/// A crank train's entry of `summary.json`: its metrics with their units, its mass properties,
/// bodies and joints, and its chamber, cycle starts and run-up where it has them.
fn mechanism_json(case: &Case, r: &MechanismResult) -> Value {
    let m = r.mechanism.as_ref();
    let mut metrics = Map::new();
    let mut units = Map::new();
    for metric in &r.summary.metrics {
        metrics.insert(metric.name.clone(), json!(metric.value));
        units.insert(metric.name.clone(), json!(metric.unit));
    }
    let mass_properties = mass_properties_json(m);
    let bodies = bodies_json(m);
    let joints = joints_json(m);
    // The maps moved in: `json!` would serialise each into a copy.
    let mechanism: Map<String, Value> = [
        ("metrics", metrics),
        ("units", units),
        ("mass_properties", mass_properties),
        ("bodies", bodies),
        ("joints", joints),
    ]
    .into_iter()
    .map(|(k, v)| (k.to_string(), Value::Object(v)))
    .collect();
    let mut mechanism = Value::Object(mechanism);
    if let Some(chamber) = chamber_json(case, m) {
        mechanism["chamber"] = chamber;
    }
    if !r.cycle_starts.is_empty() {
        let (time, speed): (Vec<f64>, Vec<f64>) = r.cycle_starts.iter().copied().unzip();
        mechanism["cycle_starts"] = json!({"time_s": time, "crank_speed_rad_s": speed});
    }
    if !r.runup.is_empty() {
        let (time, speed): (Vec<f64>, Vec<f64>) = r.runup.iter().copied().unzip();
        mechanism["runup"] = json!({"time_s": time, "crank_speed_rad_s": speed});
    }
    mechanism
}

/// A mechanism's mass properties in `summary.json`, by field, with its rod's material.
fn mass_properties_json(m: &dyn Mechanism) -> Map<String, Value> {
    let masses = m.masses();
    let mut mass_properties: Map<String, Value> = masses
        .fields()
        .iter()
        .map(|(name, value, _)| (name.to_string(), json!(value)))
        .collect();
    mass_properties.insert("rod_material".into(), json!(masses.rod_material.name()));
    mass_properties
}

/// A mechanism's bodies in `summary.json`: each one's mass and moment of inertia.
fn bodies_json(m: &dyn Mechanism) -> Map<String, Value> {
    m.topology()
        .bodies
        .iter()
        .map(|b| {
            (
                b.name.to_string(),
                json!({"mass_kg": b.mass, "inertia_kg_m2": b.inertia}),
            )
        })
        .collect()
}

/// A mechanism's joints in `summary.json`: each one's kind, the bodies it joins and its
/// kind's dimensions.
fn joints_json(m: &dyn Mechanism) -> Map<String, Value> {
    let t = m.topology();
    t.joints
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
        .collect()
}
