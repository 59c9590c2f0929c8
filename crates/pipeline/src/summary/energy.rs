//! The summary's ends: the crank angle, time and kinetic energy of the run's first and last
//! steps, which give its span and duration and the energy check (drive work = ΔKE, Karhula
//! 2008 A5.2.1.37 against the bodies' kinetic energy).

use crate::step::StepBlock;
use cardan_loads::energy::kinetic_energy;
use cardan_mechanism::{State, Topology};
use cardan_metrics::Summary;
use std::ops::Range;

/// Largest energy-check error a run may have, relative to the energy the drive moves
/// (∫|T| dθ): the trapezoidal work of a smooth torque on a grid fine enough to describe it is
/// far closer than this (1e-9 on the shipped cases); a coarser grid fails the case.
pub(crate) const ENERGY_TOLERANCE: f64 = 1e-3;

/// The least energy the check is measured against, as a fraction of the run's kinetic energy:
/// a run whose reduced inertia is constant (the cardan gear with its counterweight pair, at
/// constant speed) moves no energy through the drive, and its work and kinetic energy change
/// are round-off (some 1e-16 of the kinetic energy a step) that no grid improves.
const ROUND_OFF_ENERGY: f64 = 1e-12;

/// (crank angle, time, kinetic energy) of a step.
type End = (f64, f64, f64);

/// The first and last steps' angle, time and kinetic energy.
#[derive(Debug, Clone)]
pub(crate) struct Ends {
    first: Option<End>,
    last: End,
    /// Index of the run's last step (where the kinetic energy is taken again).
    last_step: usize,
    /// A lane of a block as a state (where the kinetic energy is taken).
    scratch: State,
}

impl Ends {
    /// The ends of a run of `points` steps of a mechanism of `topology`.
    pub(crate) fn new(topology: &Topology, points: usize) -> Self {
        Self {
            first: None,
            last: (0.0, 0.0, 0.0),
            last_step: points.saturating_sub(1),
            scratch: State::for_topology(topology),
        }
    }

    /// Takes the lanes `lanes` of `block`: the kinetic energy is wanted at the first and last
    /// steps only.
    #[inline(always)]
    pub(crate) fn push(&mut self, block: &StepBlock, lanes: Range<usize>, topology: &Topology) {
        let Some(last) = lanes.end.checked_sub(1) else {
            return;
        };
        let c = &block.state.crank;
        for i in [lanes.start, last] {
            if self.first.is_none() || block.first + i == self.last_step {
                block.state.gather(i, &mut self.scratch);
                let now = (
                    c.angle[i],
                    c.time[i],
                    kinetic_energy(topology, &self.scratch),
                );
                self.first.get_or_insert(now);
                self.last = now;
            }
        }
    }

    /// Whether a step was taken.
    pub(crate) fn started(&self) -> bool {
        self.first.is_some()
    }

    /// Continues with `later`, which took the steps from the last one this took on.
    pub(crate) fn merge(&mut self, later: &Self) {
        if later.first.is_some() {
            self.first = self.first.or(later.first);
            self.last = later.last;
        }
    }

    /// The crank-angle span (rad) and the duration (s) of the run (`None` without steps).
    pub(crate) fn span(&self) -> Option<(f64, f64)> {
        let first = self.first?;
        Some((self.last.0 - first.0, self.last.1 - first.1))
    }

    /// The kinetic energy change, and the energy check's error of the `inertial` family's
    /// (work, ∫|T| dθ) if the run has it, relative to ∫|T| dθ, or to [`ROUND_OFF_ENERGY`] of the
    /// kinetic energy where the drive moves less; fails past [`ENERGY_TOLERANCE`] if `enforce`.
    pub(crate) fn finish(
        &self,
        inertial: Option<(f64, f64)>,
        enforce: bool,
        m: &mut Summary,
    ) -> Result<(), String> {
        let first = self.first.ok_or("the run has no steps")?;
        let change = self.last.2 - first.2;
        m.push("kinetic_energy_change", change);
        if let Some((work, abs_work)) = inertial {
            let error = (work - change).abs();
            let floor = ROUND_OFF_ENERGY * first.2.abs().max(self.last.2.abs());
            let relative = if error == 0.0 {
                0.0
            } else {
                error / abs_work.max(floor)
            };
            m.push("energy_balance_error", relative);
            if relative > ENERGY_TOLERANCE && enforce {
                return Err(format!(
                    "the energy check fails: inertial work {} J against a kinetic energy change of {} J, \
                     {relative:.2e} of the {} J the drive moves (tolerance {ENERGY_TOLERANCE:e}): \
                     the crank-angle grid is too coarse for this motion; raise motion.steps",
                    work, change, abs_work
                ));
            }
        }
        Ok(())
    }
}
