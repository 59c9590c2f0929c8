//! What validation builds for each mechanism's run, kept in the [`crate::Case`] so that the run
//! takes it instead of building it again: the per-step stages, the gear ratings (with `[gear]`)
//! and the loss budget (with `[friction]`), each built with the case's friction, as the run
//! uses them, and the machine's balance (`[layout]`, `[balance]`). Building them is the check that they can be built: a case `cardan check` passes
//! has its setup, and the run cannot fail setting it up.

use crate::error::{CaseError, Invalid};
use cardan_balance::MachineBalance;
use cardan_dynamics::{Friction, GearRatings, GearSpec, LossBudget, MachineStage, Stage};
use cardan_mechanism::Mechanism;
use std::sync::Arc;

/// A mechanism's per-step stages, as validation built them.
#[derive(Debug, Clone)]
pub struct Setup {
    /// The gear ratings of its meshes (`None` without `[gear]`, or without a gear mesh).
    pub gear_ratings: Option<GearRatings>,
    /// Its loss budget (`None` without `[friction]`).
    pub losses: Option<LossBudget>,
    /// The machine's balance of it: shaking forces and moments, and the machine's torque.
    pub balance: MachineStage,
    /// What of the case does not apply to this mechanism and is ignored for it, one sentence
    /// each (`[balance] cardan_counterweights` on a mechanism without a cardan wheel): the
    /// run's warnings in `summary.json`.
    pub notes: Vec<String>,
}

impl Setup {
    /// The setup of `mechanism` in a cylinder of `bore` (m) under the case's `friction` and
    /// `gear`, in the machine `machine.0` whose orders are taken at the speed `machine.1`
    /// (rad/s); a stage that cannot be set up is the case field at fault, for this mechanism.
    pub fn build(
        shared: &Arc<dyn Mechanism>,
        bore: f64,
        friction: Option<&Friction>,
        gear: Option<&GearSpec>,
        machine: (&MachineBalance, f64),
        invalid: &Invalid,
    ) -> Result<Self, CaseError> {
        let mechanism = shared.as_ref();
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
        let balance = MachineStage::new(machine.0, Arc::clone(shared), machine.1)
            .map_err(|e| invalid("layout", &format!("(for the {})", mechanism.name()), &e))?;
        let mut notes = Vec::new();
        if machine.0.cardan_counterweights && !machine.0.cardan_pair_applies(mechanism) {
            notes.push(format!(
                "balance.cardan_counterweights = true is ignored: the {} has no cardan wheel (a body turning against the crank) to carry the pair",
                mechanism.name()
            ));
        }
        Ok(Self {
            gear_ratings,
            losses,
            balance,
            notes,
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
