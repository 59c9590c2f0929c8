//! The columns of a crank train's per-step rows that the case charts draw, told by their
//! names (`cardan_runner::per_step::COLUMNS`): the crank angle, piston motion, pressure, the
//! drive torque of each load family, the joint forces of the last family, friction; and the
//! series made of them ([`traces`]: each column, and the sum of the power losses).

use crate::data::family_rank;

/// The load family `f` of a drive-torque column `f_torque_nm` (`per_step::COLUMNS`), `None`
/// for any other column, the friction torque `friction_torque_nm` (a `[friction]` case's, not a
/// load family: it has no joint forces, and its own chart) and the machine's summed torque
/// `machine_torque_nm` (a `[layout]` case's) among them.
pub(crate) fn load_family(column: &str) -> Option<&str> {
    column
        .strip_suffix("_torque_nm")
        .filter(|f| !f.is_empty() && !f.contains("_torque_") && *f != "friction" && *f != "machine")
}

/// The machine's balance columns the charts draw (issue 24): the shaking force's components,
/// the free moment's, the machine's summed torque.
pub(crate) const BALANCE_COLUMNS: [&str; 5] = [
    "shaking_force_x_n",
    "shaking_force_y_n",
    "shaking_moment_pitch_nm",
    "shaking_moment_yaw_nm",
    "machine_torque_nm",
];

/// The loci the charts draw (`locus.rs`): per chart its file name, the x column and the y
/// column (the shaking force's F_y against F_x, issue 24's polar plot).
pub(crate) const LOCI: [(&str, &str, &str); 1] = [(
    "shaking_force_locus",
    "shaking_force_x_n",
    "shaking_force_y_n",
)];

/// The frame a locus is drawn in: the machine's (the columns as they are), or the crank's
/// (turned by the row's crank angle: `bearing_polar.rs`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Frame {
    Machine,
    Crank,
}

/// The key of the locus of `y` against `x`: `locus:x:y` in the machine's frame, `crank:x:y`
/// in the crank's (no column name starts with either).
pub(crate) fn locus_key(x: &str, y: &str) -> String {
    format!("locus:{x}:{y}")
}

/// The key of the locus of (`x`, `y`) in the crank's frame.
pub(crate) fn crank_key(x: &str, y: &str) -> String {
    format!("crank:{x}:{y}")
}

/// The machine's bearing loads of the header `h` (issue 38's polar diagrams): per main
/// journal `main_bearing_<k>` and per crank pin `cylinder_<k>_crank_pin`, the prefix of its
/// `_force_x_n` and `_force_y_n` columns, journals first, each by its number.
pub(crate) fn bearing_loads(h: &[String]) -> Vec<String> {
    let has = |c: &str| h.iter().any(|x| x == c);
    let mut out: Vec<(usize, usize, String)> = h
        .iter()
        .filter_map(|c| c.strip_suffix("_force_x_n"))
        .filter_map(|p| {
            let journal = p.strip_prefix("main_bearing_").map(|k| (0, k));
            let pin = p
                .strip_prefix("cylinder_")
                .and_then(|k| k.strip_suffix("_crank_pin"))
                .map(|k| (1, k));
            let (kind, k) = journal.or(pin)?;
            Some((kind, k.parse().ok()?, p.to_string()))
        })
        .filter(|(_, _, p)| has(&format!("{p}_force_y_n")))
        .collect();
    out.sort();
    out.into_iter().map(|(_, _, p)| p).collect()
}

/// The loci of the header `h`: (key, x column, y column, frame) of each of [`LOCI`] whose
/// columns it has; of the bearing loads ([`bearing_loads`]) the journals' in both frames and
/// the crank pins' in the crank's; the crank speed over time; and each piston's position
/// against the cylinder pressure (the indicator diagram's, `indicator.rs`).
pub(crate) fn loci(h: &[String]) -> Vec<(String, String, String, Frame)> {
    let has = |c: &str| h.iter().any(|x| x == c);
    let mut out: Vec<(String, String, String, Frame)> = LOCI
        .iter()
        .filter(|(_, x, y)| has(x) && has(y))
        .map(|(_, x, y)| {
            (
                locus_key(x, y),
                x.to_string(),
                y.to_string(),
                Frame::Machine,
            )
        })
        .collect();
    for p in bearing_loads(h) {
        let (x, y) = (format!("{p}_force_x_n"), format!("{p}_force_y_n"));
        if p.starts_with("main_bearing_") {
            out.push((locus_key(&x, &y), x.clone(), y.clone(), Frame::Machine));
        }
        out.push((crank_key(&x, &y), x, y, Frame::Crank));
    }
    // The crank speed over time (`crank_speed.rs`'s `crank_speed_time.svg`).
    if has("time_s") && has("crank_speed_rad_s") {
        let key = locus_key("time_s", "crank_speed_rad_s");
        out.push((
            key,
            "time_s".into(),
            "crank_speed_rad_s".into(),
            Frame::Machine,
        ));
    }
    if has("cylinder_pressure_pa") {
        for p in h.iter().filter_map(|c| c.strip_suffix("_dx_dtheta_m_rad")) {
            let x = format!("{p}_position_m");
            if has(&x) {
                let key = locus_key(&x, "cylinder_pressure_pa");
                out.push((key, x, "cylinder_pressure_pa".into(), Frame::Machine));
            }
        }
    }
    out
}

/// The power-loss columns of a header (`power_loss_<component>_w`): each one's chart, and
/// their sum's (the total loss).
pub(crate) fn loss_columns(h: &[String]) -> Vec<String> {
    h.iter()
        .filter(|c| c.starts_with("power_loss_") && c.ends_with("_w"))
        .cloned()
        .collect()
}

/// The key of the series that sums `columns`: their names joined by `+` (as its charts'
/// `data-source` names it) after `sum:`, which no column name starts with, so that the sum of
/// one column stays apart from the column itself (the sum counts a gap as 0).
pub(crate) fn sum_key(columns: &[String]) -> String {
    format!("sum:{}", columns.join("+"))
}

/// The series the charts can draw from rows with the header `h` (the mechanism's `joints`):
/// every column drawn over crank angle but the crank angle (the x of them all) on its own,
/// keyed by its name, and the sum of the power-loss columns ([`sum_key`]). Summing per row
/// before thinning keeps the total's own peaks, which the sum of the thinned parts would not.
/// (The loci are [`loci`].)
pub(crate) fn traces(h: &[String], joints: &[String]) -> Vec<(String, Vec<String>)> {
    let mut out: Vec<(String, Vec<String>)> = trace_columns(h, joints)
        .into_iter()
        .filter(|c| c != "crank_angle_deg")
        .map(|c| (c.clone(), vec![c]))
        .collect();
    let losses = loss_columns(h);
    if !losses.is_empty() {
        out.push((sum_key(&losses), losses));
    }
    out
}

/// The CSV columns the charts use, of the header `h` (the mechanism's `joints`): those drawn
/// over crank angle ([`trace_columns`]) and those of the loci ([`loci`]), in the header's
/// order.
pub(crate) fn wanted_columns(h: &[String], joints: &[String]) -> Vec<String> {
    let traced = trace_columns(h, joints);
    let loci = loci(h);
    h.iter()
        .filter(|c| traced.contains(c) || loci.iter().any(|(_, x, y, _)| x == *c || y == *c))
        .cloned()
        .collect()
}

/// The columns drawn over crank angle, of the header `h` (the mechanism's `joints`): crank
/// angle and speed, piston motion, pressure, drive torques, the joint forces of the last load
/// family (the total), friction, the balance columns.
fn trace_columns(h: &[String], joints: &[String]) -> Vec<String> {
    let pistons: Vec<&str> = h
        .iter()
        .filter_map(|x| x.strip_suffix("_dx_dtheta_m_rad"))
        .collect();
    let mut families: Vec<&str> = h.iter().filter_map(|x| load_family(x)).collect();
    families.sort_by_key(|x| family_rank(x));
    let forces: Vec<String> = families
        .last()
        .map(|f| {
            joints
                .iter()
                .map(|j| format!("{f}_{j}_force_magnitude_n"))
                .collect()
        })
        .unwrap_or_default();
    h.iter()
        .filter(|c| {
            c.as_str() == "crank_angle_deg"
                || c.as_str() == "crank_speed_rad_s"
                || c.as_str() == "cylinder_pressure_pa"
                || c.as_str() == "friction_torque_nm"
                || BALANCE_COLUMNS.contains(&c.as_str())
                || (c.starts_with("power_loss_") && c.ends_with("_w"))
                || ["_position_m", "_velocity_m_s", "_acceleration_m_s2"]
                    .iter()
                    .any(|s| c.strip_suffix(s).is_some_and(|p| pistons.contains(&p)))
                || load_family(c).is_some_and(|f| families.contains(&f))
                || forces.contains(c)
        })
        .cloned()
        .collect()
}
