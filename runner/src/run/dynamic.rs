//! A crank train whose motion is solved from its torques (`[motion] mode = "dynamic"`):
//! its flywheel sized if a coefficient of fluctuation is asked, its cycles before the reported
//! one integrated, and the metrics of the reported cycle with Petrescu's (2015) first
//! approximation beside them (`cardan_dynamics::machine_motion`).

use cardan_case::machine_motion::Dynamics;
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
            let (j, _) = size_flywheel(torques, &run, target)?;
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
