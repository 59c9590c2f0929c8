//! What validation builds for each mechanism's run, kept in the [`crate::Case`] so that the run
//! takes it instead of building it again: the per-step stages, the gear ratings (with `[gear]`)
//! and the loss budget (with `[friction]`), each built with the case's friction, as the run
//! uses them, and the machine's balance (`[layout]`, `[balance]`). Building them is the check that they can be built: a case `cardan check` passes
//! has its setup, and the run cannot fail setting it up.

use crate::error::{CaseError, Invalid};
use cardan_dynamics::{
    Friction, GearRatings, GearSpec, GearStage, LossBudget, LossStage, Machine, MachineStage, Stage,
};
use cardan_mechanism::Mechanism;
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
        let t = self.machine.mechanism().topology();
        let gears = (self.gear_ratings.iter())
            .map(|g| Box::new(GearStage::new(g.clone(), t)) as Box<dyn Stage>);
        let losses =
            (self.losses.iter()).map(|l| Box::new(LossStage::new(l.clone(), t)) as Box<dyn Stage>);
        gears.chain(losses).chain([self.balance.fork()]).collect()
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
                let (field, rule) = e.split_once(": ").unwrap_or(("balance", &e));
                return Err(invalid(field, &format!("(for the {})", m.name()), rule));
            }
        }
    }
    Ok(machines)
}

/// Each machine's setup ([`Setup::build`]), built with the case's `friction`, `gear` and gas
/// (`tables`), its orders at `speed` (rad/s); `[gear]` is refused if no mechanism has a gear
/// mesh to rate.
pub(crate) fn setups(
    machines: &[Arc<cardan_dynamics::Machine>],
    bore: f64,
    tables: (Option<&Friction>, Option<&GearSpec>, bool),
    speed: f64,
    invalid: &Invalid,
) -> Result<Vec<Setup>, CaseError> {
    let setups = machines
        .iter()
        .map(|m| Setup::build((m, speed), bore, tables, invalid))
        .collect::<Result<Vec<_>, _>>()?;
    if tables.1.is_some() && setups.iter().all(|s| s.gear_ratings.is_none()) {
        return Err(invalid(
            "gear",
            &"a [gear] table",
            "no mechanism of the case has a gear mesh to rate",
        ));
    }
    Ok(setups)
}
