//! A crank train whose motion is solved from its torques (`[motion] mode = "dynamic"`):
//! its flywheel sized if a coefficient of fluctuation is asked, its cycles before the reported
//! one integrated, and the metrics of the reported cycle with Petrescu's (2015) first
//! approximation beside them (`cardan_dynamics::machine_motion`).

use cardan_case::machine_motion::Dynamics;
use cardan_dynamics::flywheel_sizing::SizingError;
use cardan_dynamics::machine_motion::{
    size_flywheel, solve_cycles, Cycles, MachineTorques, SolvedRun,
};

/// A solved train ready to step: its flywheel, its run, the cycles before the reported one,
/// and the metrics of the reported cycle.
pub(super) struct Solved {
    pub flywheel: f64,
    pub run: SolvedRun,
    pub cycles: Cycles,
    pub metrics: Vec<(&'static str, f64)>,
}

/// Solves the cycles of `torques` (its flywheel the case's, or the one `dynamics` asks to size)
/// over `run`.
pub(super) fn solve(
    dynamics: &Dynamics,
    torques: &MachineTorques,
    run: SolvedRun,
) -> Result<Solved, String> {
    let mut metrics = Vec::new();
    let flywheel = match dynamics.fluctuation_target {
        None => dynamics.flywheel,
        Some(target) => {
            let (j, _) = size_flywheel(torques, &run, target).map_err(|e| match e {
                SizingError::Solve(why) => why,
                e => format!("flywheel.fluctuation_coefficient: {e}"),
            })?;
            metrics.push(("flywheel_inertia_required", j));
            j
        }
    };
    let t = MachineTorques {
        flywheel,
        ..*torques
    };
    let cycles = solve_cycles(&t, &run).map_err(|e| e.to_string())?;
    let mean = cycles.speed_mean(&run);
    let (lo, hi) = (cycles.speed_min, cycles.speed_max);
    resolved(hi - lo, mean, run.steps, flywheel)?;
    let (jlo, jhi) = (cycles.inertia_min, cycles.inertia_max);
    // Petrescu eq. (1)-(2): ω = ω_m·sqrt(J*_m/J*), J*_m = (J*_max + J*_min)/2.
    let jm = 0.5 * (jlo + jhi);
    let (plo, phi) = (mean * (jm / jhi).sqrt(), mean * (jm / jlo).sqrt());
    // The textbooks' linearisation Cs ≈ ΔE/(J·ω_m²) (validation-cases.md §9.1), J the
    // machine's mean reduced inertia J*_m.
    let de = cycles.energy_max - cycles.energy_min;
    metrics.extend([
        ("speed_mean", mean),
        ("speed_min", lo),
        ("speed_max", hi),
        ("speed_fluctuation_coefficient", (hi - lo) / mean),
        ("kinetic_energy_fluctuation", de),
        ("fluctuation_coefficient_linear", de / (jm * mean * mean)),
        ("flywheel_inertia", flywheel),
    ]);
    if let Some(t) = cycles.runup_time() {
        metrics.push(("runup_time", t));
    }
    metrics.extend([
        ("reduced_inertia_min", jlo),
        ("reduced_inertia_max", jhi),
        ("petrescu_speed_min", plo),
        ("petrescu_speed_max", phi),
        ("petrescu_fluctuation_coefficient", (phi - plo) / mean),
        ("dynamic_coefficient_min", lo / mean),
        ("dynamic_coefficient_max", hi / mean),
    ]);
    // The registry's order (flywheel_inertia_required after flywheel_inertia).
    let order = |name: &str| {
        cardan_dynamics::metrics::MACHINE_MOTION
            .iter()
            .position(|d| d.name == name)
    };
    metrics.sort_by_key(|(name, _)| order(name));
    Ok(Solved {
        flywheel,
        run,
        cycles,
        metrics,
    })
}

/// The smallest speed fluctuation (ω_max − ω_min)/ω_mean a solved cycle resolves: a thousand
/// times the relative rounding its `steps` speed updates may accumulate (steps · ε), so that
/// the fluctuation and ΔE = ½·J·(ω_max² − ω_min²) carry three significant digits at least.
pub(super) fn speed_resolution(steps: usize) -> f64 {
    1e3 * steps as f64 * f64::EPSILON
}

/// Fails where the solved speed's fluctuation `spread` about `mean` is below what its `steps`
/// resolve (issue 36.3: a flywheel of 1e15 kg·m² reported a fluctuation and a ΔE of 0, which are
/// lost in the rounding, not zero); a speed that does not change at all (no torque varies) is
/// resolved.
fn resolved(spread: f64, mean: f64, steps: usize, flywheel: f64) -> Result<(), String> {
    let limit = speed_resolution(steps);
    let fluctuation = spread / mean;
    if spread > 0.0 && fluctuation < limit {
        return Err(format!(
            "the solved speed fluctuates by {fluctuation:.3e} of its mean, below the {limit:.1e} \
             that double precision resolves over a cycle of {steps} steps (the fluctuation and \
             the kinetic energy's cannot be resolved): the flywheel of {flywheel:.4e} kg*m^2 is \
             far larger than the machine's energy fluctuation needs; give a smaller one or the \
             coefficient it is sized for (flywheel.fluctuation_coefficient)"
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fluctuation_below_the_rounding_of_its_steps_fails() {
        let limit = speed_resolution(1440);
        assert!((limit - 1440.0 * 1e3 * f64::EPSILON).abs() < 1e-25);
        assert!(resolved(0.5 * limit * 600.0, 600.0, 1440, 1e15).is_err());
        assert!(resolved(2.0 * limit * 600.0, 600.0, 1440, 1e5).is_ok());
        // A speed that does not move at all is resolved exactly.
        assert!(resolved(0.0, 600.0, 1440, 1.0).is_ok());
    }
}
