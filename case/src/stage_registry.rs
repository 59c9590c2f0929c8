//! The registry of per-step stages ([`STAGES`]), as `cardan_mechanism::MECHANISMS` is of
//! mechanisms: each entry names the case-file table that asks for its stage, its part of the
//! metric registry and the report's charts its per-step columns feed, and builds the stage for
//! one machine of a case. A case's runs take the stages its entries build, in the registry's
//! order, which is the order a run evaluates them (an entry reads what earlier ones pass on:
//! the loss budget takes the gear ratings' mesh losses, the machine the train's loss). Adding
//! a stage is a module in `cardan-dynamics` (its `Stage` and `StageTotals`) and an entry here
//! (ARCHITECTURE.md, "Adding a stage").

use cardan_dynamics::metrics::{self, MetricDef};
use cardan_dynamics::{
    Friction, GearRatings, GearSpec, GearStage, LossBudget, LossStage, Machine, MachineStage,
    SetupError, Stage,
};
use std::sync::Arc;

/// What a stage is built from: one machine of a case and the case's tables.
#[derive(Debug, Clone, Copy)]
pub struct StageInputs<'a> {
    pub machine: &'a Arc<Machine>,
    /// The case's friction (`[friction]`).
    pub friction: Option<&'a Friction>,
    /// The loss budget of the machine's mechanism under `friction`, built once for every
    /// stage that charges losses.
    pub losses: Option<&'a LossBudget>,
    /// The case's gear pair (`[gear]`).
    pub gear: Option<&'a GearSpec>,
    /// Whether the case has a gas model.
    pub gas: bool,
    /// Speed the machine's orders are taken at, rad/s.
    pub order_speed: f64,
    /// The bending geometry factors computed so far (shared by a sweep's points).
    pub bending_j: &'a cardan_gears::BendingJMemo,
}

/// A stage built for one machine, `None` where it has nothing to do; or the case field at
/// fault.
pub type Built = Result<Option<Box<dyn Stage>>, SetupError>;

/// One per-step stage a case may run.
#[derive(Debug)]
pub struct StageEntry {
    /// Its name (the docs' and the tests').
    pub name: &'static str,
    /// The case-file table that asks for it (`None`: every run has it).
    pub table: Option<&'static str>,
    /// Its part of the metric registry (`Stage::metrics` of what it builds).
    pub metrics: &'static [MetricDef],
    /// The report's charts drawn from its per-step columns (files of `plots/`), where the run
    /// has what they need (a machine of several cylinders for the machine's torque, a main
    /// bearing for its polar diagram).
    pub charts: &'static [&'static str],
    /// The stage for one machine of a case, `None` where there is nothing for it to do (the
    /// table is absent, the mechanism has no gear mesh to rate); a stage that cannot be set up
    /// is the case field at fault.
    pub build: fn(&StageInputs) -> Built,
}

/// Every per-step stage, in the order a run evaluates them.
pub const STAGES: &[StageEntry] = &[
    StageEntry {
        name: "gear_rating",
        table: Some("gear"),
        metrics: metrics::GEAR_RATING,
        charts: &[],
        build: gear_rating,
    },
    StageEntry {
        name: "losses",
        table: Some("friction"),
        metrics: metrics::LOSSES,
        charts: &["friction_torque.svg", "power_loss.svg"],
        build: losses,
    },
    StageEntry {
        name: "machine",
        table: None,
        metrics: metrics::MACHINE,
        charts: &[
            "shaking_force.svg",
            "shaking_moment.svg",
            "torque_machine.svg",
            "main_bearing_polar.svg",
            "main_bearing_polar_crank.svg",
            "crank_pin_polar.svg",
        ],
        build: machine,
    },
];

/// The entry named `name`.
pub fn find(name: &str) -> Option<&'static StageEntry> {
    STAGES.iter().find(|e| e.name == name)
}

/// The gear ratings of every gear mesh of the mechanism (`[gear]`; none without a mesh).
fn gear_rating(x: &StageInputs) -> Built {
    let Some(spec) = x.gear else {
        return Ok(None);
    };
    let m = x.machine.mechanism();
    let ratings = GearRatings::with_memo(spec, m.as_ref(), x.friction, x.bending_j)?;
    if ratings.names().is_empty() {
        return Ok(None);
    }
    Ok(Some(Box::new(GearStage::new(ratings))))
}

/// The train's loss budget (`[friction]`).
fn losses(x: &StageInputs) -> Built {
    let Some(budget) = x.losses else {
        return Ok(None);
    };
    Ok(Some(Box::new(LossStage::new(budget.clone()))))
}

/// The whole machine: every cylinder's loads, the machine's torque, journal and pin loads,
/// its shaking forces and moments.
fn machine(x: &StageInputs) -> Built {
    let machine = Arc::clone(x.machine);
    let stage = MachineStage::new(machine, x.order_speed, x.gas, x.losses);
    Ok(Some(Box::new(stage)))
}
