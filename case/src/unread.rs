//! Inputs a case gives that nothing of it would read, and inputs its run would refuse before
//! stepping, refused on reading (issue 36: check ≡ run): the crank, rod and bore's scale, the
//! gas prepared for every crank train, a mechanism's table for a mechanism not listed, a pin
//! offset no mechanism has, a dynamic motion's unread fields, a two-stroke layout of a
//! four-stroke engine model.

use crate::balance::{Cycle, LayoutTable};
use crate::error::{CaseError, Invalid, Machine};
use crate::gas::GasCase;
use crate::quantity::{AngularAcceleration, AngularSpeed, Length, Positive, Quantity};
use cardan_mechanism::Mechanism;
use std::path::Path;
use std::sync::Arc;

/// The smallest crank, rod and bore a case may give: 0.1 mm, m.
pub const MIN_DIMENSION: f64 = 1e-4;
/// The largest crank, rod and bore a case may give: 10 m, m.
pub const MAX_DIMENSION: f64 = 10.0;

/// Refuses a crank, rod or bore outside [`MIN_DIMENSION`]..=[`MAX_DIMENSION`], in the unit it was
/// written in. The reasons: the largest reciprocating machines built (two-stroke marine diesels,
/// about 1 m bore and 3.5 m stroke) are well inside 10 m; below 0.1 mm a crank train is a
/// micro-mechanism whose pistons' gas seals, films and heat transfer (the models' correlations:
/// Annand's, the ring packs') were never fitted, and the cylinder's swept volume (π/4·bore²·stroke)
/// falls towards the floating-point noise of the chamber's volume. A value outside is a unit
/// mistake or a typing error far more often than a machine.
/// `lengths`: `[geometry]`'s crank_length, rod_length and bore.
pub(crate) fn geometry_size(
    lengths: [&Positive<Length>; 3],
    invalid: &Invalid,
) -> Result<(), CaseError> {
    for (field, q) in ["crank_length", "rod_length", "bore"]
        .into_iter()
        .zip(lengths)
    {
        if !(MIN_DIMENSION..=MAX_DIMENSION).contains(&q.si) {
            return Err(invalid(
                &format!("geometry.{field}"),
                &q.written,
                "must lie from 0.1 mm to 10 m: the largest reciprocating machines built (marine two-strokes, about 1 m bore and 3.5 m stroke) fit well inside, and below 0.1 mm the gas, friction and heat-transfer correlations were never fitted (a unit mistake?)",
            ));
        }
    }
    Ok(())
}

/// Refuses a mechanism's own table (`[cardan_gear]`) or mass table (`[masses.cardan_gear]`) for
/// a mechanism the case does not list: it would be read by nothing (as `[gear]` without a mesh
/// is refused).
/// `listed`: the case's `mechanisms`; `own`: its mechanisms' own tables and mass tables.
pub(crate) fn tables(
    listed: &[String],
    own: [&toml::Table; 2],
    invalid: &Invalid,
) -> Result<(), CaseError> {
    for (tables, prefix) in own.into_iter().zip(["", "masses."]) {
        if let Some(name) = tables.keys().find(|k| !listed.contains(k)) {
            return Err(invalid(
                &format!("{prefix}{name}"),
                &format!("a [{prefix}{name}] table"),
                &format!(
                    "the {name} is not among the case's mechanisms ({}), so nothing would read it: list it in mechanisms or remove the table",
                    listed.join(", ")
                ),
            ));
        }
    }
    Ok(())
}

/// Refuses a `geometry.pin_offset` other than 0 that no mechanism of the case reads (a mixed
/// case's slider-crank takes it, its cardan gear has no pin to offset).
/// `offset`: the offset in m and as written, if given.
pub(crate) fn pin_offset(
    offset: Option<(f64, &str)>,
    mechanisms: &[Arc<dyn Mechanism>],
    invalid: &Invalid,
) -> Result<(), CaseError> {
    if let Some((_, written)) = offset.filter(|p| p.0 != 0.0) {
        let readers: Vec<&str> = cardan_mechanism::MECHANISMS
            .iter()
            .filter(|e| e.pin_offset)
            .map(|e| e.name)
            .collect();
        if !mechanisms.iter().any(|m| readers.contains(&m.name())) {
            return Err(invalid(
                "geometry.pin_offset",
                &written,
                &format!(
                    "no mechanism of the case has a piston pin to offset (only the {} does): remove it, or add a mechanism that reads it",
                    readers.join(", the ")
                ),
            ));
        }
    }
    Ok(())
}

/// Refuses a dynamic motion's unread inputs: an `angular_acceleration` other than 0 (the
/// acceleration is solved), a `steady_tolerance` with a single cycle (nothing to stop early).
/// Refuses a dynamic motion's negative initial speed (the crank turns forwards). `(dynamic,
/// acceleration, speed)`: whether the motion is solved, `motion.angular_acceleration` and
/// `motion.initial_speed`;
/// `steady_tolerance` and `cycles`: `[motion]`'s.
pub(crate) fn dynamic_inputs(
    (dynamic, acceleration, speed): (
        bool,
        &Quantity<AngularAcceleration>,
        &Quantity<AngularSpeed>,
    ),
    steady_tolerance: Option<f64>,
    cycles: Option<i64>,
    invalid: &Invalid,
) -> Result<(), CaseError> {
    if dynamic && (speed.si.is_nan() || speed.si < 0.0) {
        return Err(invalid(
            "motion.initial_speed",
            &speed.written,
            "must not be negative: the crank turns forwards",
        ));
    }
    if dynamic && acceleration.si != 0.0 {
        return Err(invalid(
            "motion.angular_acceleration",
            &acceleration.written,
            "is not read by a dynamic motion (motion.mode = \"dynamic\": the crank's acceleration is solved from its torques): write 0",
        ));
    }
    if let Some(tolerance) = steady_tolerance {
        if cycles.is_none_or(|c| c <= 1) {
            return Err(invalid(
                "motion.steady_tolerance",
                &tolerance,
                "stops the cycles of a dynamic motion early, and this one runs a single cycle: set motion.cycles above 1 or remove it",
            ));
        }
    }
    Ok(())
}

/// The case's mechanisms, the cylinder (bore, m; pistons; the trains' lead, rad) and the mean
/// crank speed (rad/s) the gas is prepared for.
pub(crate) type Trains<'a> = (&'a [Arc<dyn Mechanism>], (f64, u32, f64), f64);

/// The gas made ready for every crank train as the run makes it ([`crate::gas::check_ready`],
/// at the mean crank speed `speed`), an error about the cylinder's size said in the geometry's
/// fields as written (`bore`, `crank`, `speed_written`: `geometry.bore`, `geometry.crank_length`
/// and `motion.initial_speed` as written); and a two-stroke `[layout]` refused
/// with a four-stroke engine model.
pub(crate) fn gas_ready(
    gas: &GasCase,
    table: &toml::Table,
    at: (&Path, &str, Machine),
    (mechanisms, cylinder, speed): Trains,
    (layout, [bore, crank, speed_written]): (Option<&LayoutTable>, [&str; 3]),
    invalid: &Invalid,
) -> Result<(), CaseError> {
    let two_stroke = layout.is_some_and(|l| l.cycle == Cycle::TwoStroke);
    if two_stroke && gas.four_stroke() {
        return Err(invalid(
            "layout.cycle",
            &"\"two_stroke\"",
            &format!(
                "gas.model = \"{}\" is a four-stroke cycle (720° per cylinder): its cylinders fire 720°/N apart, not 360°/N; use cycle = \"four_stroke\"",
                gas.name()
            ),
        ));
    }
    crate::gas::check_ready(gas, table, at, mechanisms, cylinder, speed).map_err(|e| match e {
        Ok(e) if e.field == "speed" => invalid(
            "motion.initial_speed",
            &speed_written,
            &format!(
                "gives a mean crank speed of {} rad/s, which the gas model refuses: {}",
                crate::units::show(&e.value.to_string()),
                e.rule
            ),
        ),
        Ok(e) => invalid(
            "geometry.bore",
            &bore,
            &format!(
                "with geometry.crank_length = {} the cylinder's {} is {} ({}): {}",
                crank,
                e.field.replace('_', " "),
                crate::units::show(&e.value.to_string()),
                if e.field == "bore" { "m" } else { "m³" },
                e.rule
            ),
        ),
        Err(e) => e,
    })?;
    Ok(())
}

/// Refuses a `[gas]` table with a mechanism whose pistons move in no cylinder: the gas models
/// need a cylinder volume.
pub(crate) fn gas_cylinders(
    mechanisms: &[Arc<dyn Mechanism>],
    invalid: &Invalid,
) -> Result<(), CaseError> {
    match mechanisms.iter().find(|m| !m.has_cylinder()) {
        Some(m) => Err(invalid(
            "gas",
            &format!("a [gas] table with the {}", m.name()),
            &format!(
                "the {}'s pistons do not move in a cylinder, and the gas models need a cylinder volume: run it without [gas]",
                m.name()
            ),
        )),
        None => Ok(()),
    }
}
