//! Result files: `summary.json` and one CSV per mechanism, each written atomically (to a
//! temporary file in the same folder, then renamed over the target).

use crate::case::Case;
use crate::run::MechanismRun;
use anyhow::Context;
use cardan_dynamics::Step;
use cardan_mechanism::PolarComponents;
use serde_json::{json, Map, Value};
use std::io::Write;
use std::path::Path;

/// The summary of a case as JSON:
/// `{"case", "machine", "mechanisms": {<name>: {"metrics": {...}, "mass_properties": {...}}}}`.
pub fn summary_json(case: &Case, runs: &[MechanismRun]) -> Value {
    let mut mechanisms = Map::new();
    for run in runs {
        let metrics: Map<String, Value> = run
            .summary
            .metrics
            .iter()
            .map(|m| (m.name.to_string(), json!(m.value)))
            .collect();
        let m = &run.case.masses;
        mechanisms.insert(
            run.case.kind.name().to_string(),
            json!({
                "metrics": metrics,
                "mass_properties": {
                    "rod_material": run.case.rod_material.name(),
                    "crankshaft_inertia": m.crankshaft_inertia,
                    "wheel_inertia": m.wheel_inertia,
                    "rod_mass": m.rod_mass,
                    "rod_inertia": m.rod_inertia,
                    "rod_cg": m.rod_cg,
                    "piston_mass": m.piston_mass,
                    "reciprocating_mass": m.reciprocating_mass(run.case.kind),
                },
            }),
        );
    }
    json!({
        "case": case.name,
        "machine": case.machine.name(),
        "gas_model": case.gas.as_ref().map(|g| g.name()),
        "mechanisms": mechanisms,
    })
}

/// CSV columns, with their units in the names. One row per crank-angle step.
pub const CSV_COLUMNS: &[&str] = &[
    "crank_angle_deg",
    "time_s",
    "crank_speed_rad_s",
    "piston_position_m",
    "piston_velocity_m_s",
    "piston_acceleration_m_s2",
    "piston_dx_dtheta_m_rad",
    "rod_angle_deg",
    "rod_angular_velocity_rad_s",
    "rod_angular_acceleration_rad_s2",
    "rod_cg_x_m",
    "rod_cg_y_m",
    "rod_cg_velocity_m_s",
    "rod_cg_acceleration_m_s2",
    "rod_cg_radial_acceleration_m_s2",
    "rod_cg_coriolis_acceleration_m_s2",
    "rod_cg_tangential_acceleration_m_s2",
    "rod_cg_normal_acceleration_m_s2",
    "main_bearing_speed_rad_s",
    "crank_pin_speed_rad_s",
    "piston_pin_speed_rad_s",
    "inertial_main_bearing_force_x_n",
    "inertial_main_bearing_force_y_n",
    "inertial_crank_pin_force_x_n",
    "inertial_crank_pin_force_y_n",
    "inertial_piston_pin_force_x_n",
    "inertial_piston_pin_force_y_n",
    "inertial_piston_side_force_n",
    "inertial_gear_mesh_force_x_n",
    "inertial_gear_mesh_force_y_n",
    "inertial_torque_nm",
    "inertial_torque_crankshaft_nm",
    "inertial_torque_rod_or_wheel_nm",
    "inertial_torque_piston_nm",
    "rod_percussion_centre_m",
    "cylinder_pressure_pa",
    "gas_force_n",
    "gas_torque_nm",
    "total_main_bearing_force_x_n",
    "total_main_bearing_force_y_n",
    "total_crank_pin_force_x_n",
    "total_crank_pin_force_y_n",
    "total_piston_pin_force_x_n",
    "total_piston_pin_force_y_n",
    "total_piston_side_force_n",
    "total_gear_mesh_force_x_n",
    "total_gear_mesh_force_y_n",
    "total_torque_nm",
];

/// Writes `v,`; `None` (a quantity the run does not define) is an empty cell.
fn cell(out: &mut String, v: Option<f64>) {
    use std::fmt::Write as _;
    if let Some(v) = v {
        let _ = write!(out, "{v}");
    }
    out.push(',');
}

fn csv_row(s: &Step, pressure: Option<f64>, out: &mut String) {
    let k = &s.kinematics;
    let l = &s.inertial;
    let t = s.total();
    let p = PolarComponents::of(&k.rod.point);
    let values = [
        k.crank.angle.to_degrees(),
        k.crank.time,
        k.crank.speed,
        k.piston.position,
        k.piston.velocity,
        k.piston.acceleration,
        k.piston.dx_dtheta,
        k.rod.direction.arg().to_degrees(),
        k.rod.angular_velocity,
        k.rod.angular_acceleration,
        k.rod.point.position.re,
        k.rod.point.position.im,
        k.rod.point.velocity.norm(),
        k.rod.point.acceleration.norm(),
        p.radial_acceleration,
        p.coriolis_acceleration,
        p.tangential_acceleration,
        p.normal_acceleration,
        k.joint_speeds.main_bearing,
        k.joint_speeds.crank_pin,
        k.joint_speeds.piston_pin,
        l.main_bearing.re,
        l.main_bearing.im,
        l.crank_pin.re,
        l.crank_pin.im,
        l.piston_pin.re,
        l.piston_pin.im,
        l.piston_side,
        l.gear_mesh.re,
        l.gear_mesh.im,
        l.crank_torque,
        l.torque_by_link[0],
        l.torque_by_link[1],
        l.torque_by_link[2],
    ];
    for v in values {
        cell(out, Some(v));
    }
    // An undefined centre of percussion, and the gas of a run without one, are empty cells.
    cell(out, l.rod_percussion_centre);
    cell(out, pressure);
    cell(out, s.gas.map(|(force, _)| force));
    cell(out, s.gas.map(|(_, gas)| gas.crank_torque));
    for v in [
        t.main_bearing.re,
        t.main_bearing.im,
        t.crank_pin.re,
        t.crank_pin.im,
        t.piston_pin.re,
        t.piston_pin.im,
        t.piston_side,
        t.gear_mesh.re,
        t.gear_mesh.im,
        t.crank_torque,
    ] {
        cell(out, Some(v));
    }
    out.pop();
    out.push('\n');
}

/// The CSV text of one mechanism run.
pub fn csv(run: &MechanismRun) -> String {
    let mut out = String::with_capacity(400 * (run.steps.len() + 1));
    out.push_str(&CSV_COLUMNS.join(","));
    out.push('\n');
    for (k, s) in run.steps.iter().enumerate() {
        csv_row(s, run.gas.as_ref().map(|g| g.pressure[k]), &mut out);
    }
    out
}

/// Writes `contents` to `path` atomically.
pub fn write_atomic(path: &Path, contents: &[u8]) -> anyhow::Result<()> {
    let dir = path.parent().context("no parent folder")?;
    let name = path.file_name().context("no file name")?.to_string_lossy();
    let tmp = dir.join(format!(".{name}.tmp-{}", std::process::id()));
    let result = (|| {
        let mut f =
            std::fs::File::create(&tmp).with_context(|| format!("create {}", tmp.display()))?;
        f.write_all(contents)?;
        f.sync_all()?;
        std::fs::rename(&tmp, path).with_context(|| format!("rename to {}", path.display()))
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

/// Writes `summary.json` and `<mechanism>.csv` of a case into `dir`.
pub fn write_case(dir: &Path, case: &Case, runs: &[MechanismRun]) -> anyhow::Result<()> {
    std::fs::create_dir_all(dir).with_context(|| format!("create {}", dir.display()))?;
    for run in runs {
        write_atomic(
            &dir.join(format!("{}.csv", run.case.kind.name())),
            csv(run).as_bytes(),
        )?;
    }
    let mut summary = serde_json::to_string_pretty(&summary_json(case, runs))?;
    summary.push('\n');
    write_atomic(&dir.join("summary.json"), summary.as_bytes())
}
