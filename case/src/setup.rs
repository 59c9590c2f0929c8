//! What validation builds for each mechanism's run, kept in the [`crate::Case`] so that the run
//! takes it instead of building it again: the per-step stages, the gear ratings (with `[gear]`)
//! and the loss budget (with `[friction]`), each built with the case's friction, as the run
//! uses them, and the machine's balance (`[layout]`, `[balance]`). Building them is the check that they can be built: a case `cardan check` passes
//! has its setup, and the run cannot fail setting it up.

use crate::error::{CaseError, Invalid};
use cardan_dynamics::{Friction, GearRatings, GearSpec, LossBudget, Machine, MachineStage, Stage};
use std::sync::Arc;

/// A mechanism's per-step stages, as validation built them.
#[derive(Debug, Clone)]
pub struct Setup {
    /// The gear ratings of its meshes (`None` without `[gear]`, or without a gear mesh).
    pub gear_ratings: Option<GearRatings>,
    /// Its loss budget (`None` without `[friction]`).
    pub losses: Option<LossBudget>,
    /// The whole machine of it, built once at validation: every cylinder, the crank's
    /// masses, the balancing devices.
    pub machine: Arc<Machine>,
    /// The machine's stage: every cylinder's loads, the machine's torque, journal and pin
    /// loads, its shaking forces and moments.
    pub balance: MachineStage,
    /// What of the case does not apply to this mechanism and is ignored for it, one sentence
    /// each (`[balance] cardan_counterweights` on a mechanism without a cardan wheel): the
    /// run's warnings in `summary.json`.
    pub notes: Vec<String>,
}

impl Setup {
    /// The setup of the machine `machine.0`'s mechanism in a cylinder of `bore` (m) under the
    /// case's `friction` and `gear`, the machine's orders taken at the speed `machine.1`
    /// (rad/s), `gas`: whether the case has a gas model; a stage that cannot be set up is the
    /// case field at fault, for this mechanism.
    pub fn build(
        machine: (&Arc<Machine>, f64),
        bore: f64,
        (friction, gear, gas): (Option<&Friction>, Option<&GearSpec>, bool),
        invalid: &Invalid,
    ) -> Result<Self, CaseError> {
        let mechanism = machine.0.mechanism().as_ref();
        let failed = |e: cardan_dynamics::SetupError| {
            invalid(
                &e.field,
                &format!("(for the {})", mechanism.name()),
                &e.rule,
            )
        };
        let gear_ratings = match gear {
            Some(spec) => {
                let ratings = GearRatings::new(spec, mechanism, friction).map_err(failed)?;
                (!ratings.names().is_empty()).then_some(ratings)
            }
            None => None,
        };
        let losses = match friction {
            Some(f) => Some(LossBudget::new(f, mechanism, bore).map_err(failed)?),
            None => None,
        };
        let balance = MachineStage::new(Arc::clone(machine.0), machine.1, gas, losses.as_ref());
        Ok(Self {
            gear_ratings,
            losses,
            notes: machine.0.notes.clone(),
            machine: Arc::clone(machine.0),
            balance,
        })
    }

    /// The stages of a run (a crank train's own copies, their history unset), in the run's
    /// order: the gear ratings, then the loss budget (which takes their mesh losses), then the
    /// machine's balance.
    pub fn stages(&self) -> Vec<Box<dyn Stage>> {
        let gears = self.gear_ratings.iter().map(|g| g.fork());
        gears
            .chain(self.losses.iter().map(|l| l.fork()))
            .chain([self.balance.fork()])
            .collect()
    }
}
