//! The pitch-line velocity a case's gear meshes reach, checked at validation as `cardan gear`
//! checks a gear file's (issue 36.12: one rule, [`cardan_gears::check_pitch_line_velocity`]):
//! a pair no gear can run at is refused by `cardan check`, in the case's own speed field,
//! instead of being rated. A prescribed motion's fastest crank speed is known before stepping;
//! a solved motion's is not, and the gear stage refuses a step beyond the limit.

use crate::error::{CaseError, Invalid};
use cardan_mechanism::{CrankMotion, CrankState, JointKind, Mechanism, StateBlock};
use std::sync::Arc;

/// Crank angles a turn is sampled at for the meshes' fastest pitch-line velocity: one block of
/// states (a sweep validates every point). A mesh's relative speed is constant for the cardan
/// pair and varies with the first few orders of the crank angle for the others, whose peaks 64
/// points a turn (5.6° apart) find within a fraction of a per cent: far inside a rule set at a
/// rim's bursting speed.
const SAMPLES: usize = cardan_mechanism::LANES;

/// Refuses `mechanisms` whose gear meshes, at the crank speed `speed` (rad/s, the run's fastest,
/// given as the field `field` = `written`), run faster at the pitch line than a gear can.
pub(crate) fn check(
    mechanisms: &[Arc<dyn Mechanism>],
    speed: f64,
    (field, written): (&str, &str),
    invalid: &Invalid,
) -> Result<(), CaseError> {
    for m in mechanisms {
        let meshes: Vec<(usize, &str)> = m
            .topology()
            .joints
            .iter()
            .enumerate()
            .filter(|(_, j)| matches!(j.kind, JointKind::GearMesh { .. }))
            .map(|(k, j)| (k, j.name))
            .collect();
        if meshes.is_empty() {
            continue;
        }
        // A turn's states filled as one block, the meshes' speeds read from its columns (no
        // state gathered: the extras are not wanted).
        let cranks: Vec<CrankState> = (0..SAMPLES)
            .map(|s| {
                let angle = std::f64::consts::TAU * s as f64 / SAMPLES as f64;
                CrankState::new(angle, speed, 0.0, 0.0)
            })
            .collect();
        let mut block = StateBlock::for_topology(m.topology());
        block.fill(m.as_ref(), &cranks);
        let mut fastest: (f64, &str) = (0.0, meshes[0].1);
        for i in 0..block.len {
            for &(k, name) in &meshes {
                let v = block.joints[k].relative_speed[i].abs();
                // Not `max`: a NaN speed is kept, for the rule to refuse.
                if !fastest.0.is_nan() && (v.is_nan() || v > fastest.0) {
                    fastest = (v, name);
                }
            }
        }
        let (v, name) = fastest;
        if let Err(e) = cardan_gears::check_pitch_line_velocity(v) {
            let rule = match e {
                cardan_gears::GearError::InvalidInput { rule, .. } => rule.to_string(),
                e => e.to_string(),
            };
            return Err(invalid(
                field,
                &written,
                &format!(
                    "the {}'s gear mesh {name} then runs at {} m/s at the pitch line, which {rule}",
                    m.name(),
                    crate::units::short(v)
                ),
            ));
        }
    }
    Ok(())
}

/// Refuses `mechanisms` whose meshes run too fast at the run's fastest crank speed (`run`: the
/// prescribed motion, its end angle rad, and whether the motion is solved instead), blamed on
/// the field that sets it (`written`: `motion.angular_acceleration` and
/// `motion.initial_speed` as written).
pub(crate) fn check_run(
    mechanisms: &[Arc<dyn Mechanism>],
    (motion, end_angle, solved): (&CrankMotion, f64, bool),
    [acceleration, initial_speed]: [&str; 2],
    invalid: &Invalid,
) -> Result<(), CaseError> {
    // The run's fastest crank speed: an end of a prescribed ramp (ω² is linear in the
    // angle), a solved motion's start (its later speeds are checked at each step).
    let end = motion.at_angle(end_angle).ok().filter(|_| !solved);
    let blame = match end.filter(|e| e.speed.abs() > motion.initial_speed.abs()) {
        Some(e) => (e.speed, ("motion.angular_acceleration", acceleration)),
        None => (
            motion.initial_speed,
            ("motion.initial_speed", initial_speed),
        ),
    };
    check(mechanisms, blame.0.abs(), blame.1, invalid)
}
