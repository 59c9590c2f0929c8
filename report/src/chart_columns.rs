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

/// The key of the locus of `y` against `x`: `locus:x:y` (no column name starts with `locus:`).
pub(crate) fn locus_key(x: &str, y: &str) -> String {
    format!("locus:{x}:{y}")
}

/// The loci of the header `h`: (key, x column, y column) of each of [`LOCI`] whose columns it
/// has.
pub(crate) fn loci(h: &[String]) -> Vec<(String, String, String)> {
    let has = |c: &str| h.iter().any(|x| x == c);
    LOCI.iter()
        .filter(|(_, x, y)| has(x) && has(y))
        .map(|(_, x, y)| (locus_key(x, y), x.to_string(), y.to_string()))
        .collect()
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
/// every wanted column but the crank angle (the x of them all) on its own, keyed by its name,
/// and the sum of the power-loss columns ([`sum_key`]). Summing per row before thinning keeps
/// the total's own peaks, which the sum of the thinned parts would not.
pub(crate) fn traces(h: &[String], joints: &[String]) -> Vec<(String, Vec<String>)> {
    let mut out: Vec<(String, Vec<String>)> = wanted_columns(h, joints)
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

/// The CSV columns the charts use, of the header `h` (the mechanism's `joints`): crank angle,
/// piston motion, pressure, drive torques, the joint forces of the last load family (the
/// total), friction.
pub(crate) fn wanted_columns(h: &[String], joints: &[String]) -> Vec<String> {
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
