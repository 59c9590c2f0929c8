//! What validation builds for each mechanism's run, kept in the [`crate::Case`] so that the run
//! takes it instead of building it again: the whole machine (`[layout]`, `[balance]`), its loss
//! budget (with `[friction]`) and the per-step stages of the registry
//! ([`crate::stage_registry::STAGES`]), each built with the case's friction, as the run uses
//! them. Building them is the check that they can be built: a case `cardan check` passes has
//! its setup, and the run cannot fail setting it up.

use crate::error::{CaseError, Invalid};
use crate::stage_registry::{StageEntry, StageInputs, STAGES};
use cardan_dynamics::{Friction, GearSpec, LossBudget, Machine, Stage};
use cardan_gears::BendingJMemo;
use cardan_mechanism::Mechanism;
use std::sync::Arc;

/// A mechanism's machine and per-step stages, as validation built them.
#[derive(Debug, Clone)]
pub struct Setup {
    /// The whole machine of it, built once at validation: every cylinder, the crank's
    /// masses, the balancing devices.
    pub machine: Arc<Machine>,
    /// Its loss budget (`None` without `[friction]`): the stages' and the solved motion's.
    pub losses: Option<LossBudget>,
    /// The stages its runs take, each with its registry entry, in the registry's order.
    pub stages: Vec<(&'static StageEntry, Box<dyn Stage>)>,
    /// What of the case does not apply to this mechanism and is ignored for it, one sentence
    /// each (`[balance] cardan_counterweights` on a mechanism without a cardan wheel): the
    /// run's warnings in `summary.json`.
    pub notes: Vec<String>,
}

impl Setup {
    /// The setup of the machine `machine.0`'s mechanism in a cylinder of `bore` (m) under the
    /// case's `friction` and `gear`, the machine's orders taken at the speed `machine.1`
    /// (rad/s), `gas`: whether the case has a gas model, the gear pairs' bending geometry
    /// factors taken from `bending_j` where it holds them; a stage that cannot be set up is the
    /// case field at fault, for this mechanism.
    pub fn build(
        machine: (&Arc<Machine>, f64),
        bore: f64,
        (friction, gear, gas): (Option<&Friction>, Option<&GearSpec>, bool),
        bending_j: &BendingJMemo,
        invalid: &Invalid,
    ) -> Result<Self, CaseError> {
        let mechanism = machine.0.mechanism().as_ref();
        let failed = |e: cardan_dynamics::SetupError| {
            invalid(
                &crate::input_field::setup_field(e.field),
                &format!("(for the {})", mechanism.name()),
                &e.rule,
            )
        };
        let losses = match friction {
            Some(f) => Some(LossBudget::new(f, mechanism, bore).map_err(failed)?),
            None => None,
        };
        let inputs = StageInputs {
            machine: machine.0,
            friction,
            losses: losses.as_ref(),
            gear,
            gas,
            order_speed: machine.1,
            bending_j,
        };
        let mut stages = Vec::with_capacity(STAGES.len());
        for entry in STAGES {
            if let Some(stage) = (entry.build)(&inputs).map_err(failed)? {
                stages.push((entry, stage));
            }
        }
        Ok(Self {
            losses,
            stages,
            notes: machine.0.notes.clone(),
            machine: Arc::clone(machine.0),
        })
    }

    /// The stages of a run (a crank train's own copies, their history unset), in the run's
    /// order.
    pub fn stages(&self) -> Vec<Box<dyn Stage>> {
        self.stages.iter().map(|(_, s)| s.fork()).collect()
    }

    /// Whether its runs take the stage of the registry entry `name`.
    pub fn has_stage(&self, name: &str) -> bool {
        self.stages.iter().any(|(e, _)| e.name == name)
    }
}

/// Refuses a machine a mechanism cannot form: several cylinders of opposed pistons or of a
/// mechanism whose pistons move in no cylinder, a balancing device the mechanism has no body
/// for; returns each mechanism's [`cardan_dynamics::Machine`], built here once
/// ([`cardan_balance::MachineBalance::prepare`]), with the mechanism equipped with what the
/// machine puts on its bodies (the cardan pair's wheel counterweight,
/// [`cardan_balance::MachineBalance::equip`]), which the runs take.
pub(crate) fn check_machine(
    machine: &cardan_balance::MachineBalance,
    mechanisms: Vec<Arc<dyn Mechanism>>,
    (pistons, kind): (u32, crate::error::Machine),
    invalid: &Invalid,
) -> Result<Vec<Arc<cardan_dynamics::Machine>>, CaseError> {
    let n = machine.layout.cylinders.len();
    if n > 1 && pistons == 2 {
        return Err(invalid(
            "layout.cylinders",
            &n,
            "a machine of several opposed-piston cylinders is not modelled: run one cylinder",
        ));
    }
    let kind = match kind {
        crate::error::Machine::Pump => cardan_dynamics::MachineKind::Pump,
        crate::error::Machine::Engine => cardan_dynamics::MachineKind::Engine,
    };
    if machine.cardan_counterweights
        && !mechanisms
            .iter()
            .any(|m| machine.cardan_pair_applies(m.as_ref()))
    {
        let names: Vec<&str> = mechanisms.iter().map(|m| m.name()).collect();
        return Err(invalid(
            "balance.cardan_counterweights",
            &"true",
            &format!(
                "applies to a mechanism with a cardan wheel (a body turning against the crank at its speed), and the case has none ({})",
                names.join(", ")
            ),
        ));
    }
    let mut machines = Vec::with_capacity(mechanisms.len());
    for m in mechanisms {
        if n > 1 && !m.has_cylinder() {
            return Err(invalid(
                "layout.cylinders",
                &n,
                &format!(
                    "the {}'s pistons move in no cylinder: it cannot form a machine of several cylinders",
                    m.name()
                ),
            ));
        }
        match cardan_dynamics::Machine::build(machine, Arc::clone(&m), kind) {
            Ok(built) => machines.push(Arc::new(built)),
            Err(e) => {
                let field = crate::input_field::device_field(e.device);
                return Err(invalid(field, &format!("(for the {})", m.name()), &e.rule));
            }
        }
    }
    Ok(machines)
}

/// Each machine's setup ([`Setup::build`]), built with the case's `friction`, `gear` and gas
/// (`tables`), its orders at `speed` (rad/s), the bending geometry factors through
/// `bending_j`; `[gear]` is refused if no mechanism has a gear mesh to rate.
pub(crate) fn setups(
    machines: &[Arc<cardan_dynamics::Machine>],
    bore: f64,
    tables: (Option<&Friction>, Option<&GearSpec>, bool),
    (speed, bending_j): (f64, &BendingJMemo),
    invalid: &Invalid,
) -> Result<Vec<Setup>, CaseError> {
    let setups = machines
        .iter()
        .map(|m| Setup::build((m, speed), bore, tables, bending_j, invalid))
        .collect::<Result<Vec<_>, _>>()?;
    if tables.1.is_some() && !setups.iter().any(|s| s.has_stage("gear_rating")) {
        return Err(invalid(
            "gear",
            &"a [gear] table",
            "no mechanism of the case has a gear mesh to rate",
        ));
    }
    Ok(setups)
}
