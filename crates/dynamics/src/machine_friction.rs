//! The friction torque on the crank of a solved machine motion: every loss of the case's loss
//! budget ([`LossBudget`], the models of `[friction]`) evaluated at a state of the motion, as a
//! run evaluates it (the state filled at its crank angle, speed and acceleration, loaded by the
//! run's families, their total made as the stepper makes it), and charged to the crank as the
//! torque that covers it: T_f = Σ P_loss / ω (Karhula 2008 A9.1.56-59: the losses are charged
//! to the drive, P = T·ω; docs/validation/machine-motion.md).
//!
//! **At vanishing speed.** A loss is a power, and ω = 0 (a run-up from rest) leaves P/ω as
//! 0/0. The models are evaluated at the speed max(ω, ω_ε), ω_ε = [`VANISHING_SPEED`], and
//! their torque is P(ω_ε)/ω_ε: the limit ω → 0 of each kind of loss to within ω_ε's effect on
//! the loads. A Coulomb loss (rings, Coulomb skirt and slides, the bearings' load terms) is
//! P = μ·|F|·|v| with v ∝ ω, so P/ω = μ·|F|·|v/ω| does not depend on the speed but through the
//! loads' ω² terms, which ω_ε² = 1e-12 rad²/s² leaves unchanged to far below the solve's
//! tolerance; a viscous loss (P ∝ ω², a journal bearing, the viscous skirt) or a speed power
//! above one (rolling bearings' (ν·n)^(2/3) term) tends to 0 and is ω_ε-small there. The
//! machine then starts from rest only if its drive exceeds the friction's breakaway torque
//! (`machine_motion::SolveError::CannotStart` otherwise), as a Coulomb contact does.
//!
//! The friction depends on the crank's acceleration through the inertial loads, so the machine
//! equation is implicit in α: [`crate::machine_motion`] solves it by fixed-point iteration
//! (its contraction factor is ∂T_f/∂α / J, a friction coefficient times a bearing radius over
//! the crank radius: small).

use crate::family::LoadFamily;
use crate::losses::LossBudget;
use crate::stage::GasAt;
use crate::stepper::Loading;
use crate::LossLanes;
use cardan_mechanism::{Column, CrankState, LoadsBlock, Mechanism, StateBlock, LANES, ZERO};

/// The speed at which the losses are evaluated below it, rad/s (module doc: the limit of a
/// Coulomb loss's torque at vanishing speed).
pub const VANISHING_SPEED: f64 = 1e-6;

/// The friction of a solved motion: the loss budget validation built for the mechanism
/// (`cardan_case::setup::Setup`), and the load families of the run, whose total loads the
/// losses are computed from. A budget whose losses carry a history from step to step (the
/// ring films' squeeze term) has no value at the Runge-Kutta stages' states: the case refuses
/// it with a solved motion.
#[derive(Clone, Copy)]
pub struct MotionFriction<'a> {
    pub budget: &'a LossBudget,
    pub families: &'a [&'a dyn LoadFamily],
}

/// The friction torque of [`MotionFriction`] at any state, with its scratch space.
pub(crate) struct FrictionAt<'a> {
    mechanism: &'a dyn Mechanism,
    gas: Option<GasAt<'a>>,
    budget: LossBudget,
    loading: Loading<'a>,
    states: StateBlock,
    loads: Vec<LoadsBlock>,
    total: LoadsBlock,
    /// The loss components at the state, W (lane 0).
    losses: Vec<Column>,
}

impl<'a> FrictionAt<'a> {
    /// The friction of `friction` on `mechanism`, its pistons pushed by `gas` if given.
    pub(crate) fn new(
        mechanism: &'a dyn Mechanism,
        gas: Option<GasAt<'a>>,
        friction: MotionFriction<'a>,
    ) -> Self {
        let t = mechanism.topology();
        Self {
            mechanism,
            gas,
            budget: friction.budget.clone(),
            loading: Loading::new(friction.families, t),
            states: StateBlock::for_topology(t),
            loads: vec![LoadsBlock::for_topology(t); friction.families.len()],
            total: LoadsBlock::for_topology(t),
            losses: vec![ZERO; friction.budget.names().len()],
        }
    }

    /// The torque the losses take from the crank at crank angle `angle` (rad) with the gas of
    /// crank angle `gas_angle` (a cylinder of a machine: its own crank angle and its gas phase,
    /// `machine_motion::MachineTorques::cylinders`), speed `speed` (rad/s, at least
    /// [`VANISHING_SPEED`] is used) and acceleration `acceleration` (rad/s²): Σ P_loss / ω, N·m,
    /// not negative; `Err`: why a loss cannot be computed there.
    pub(crate) fn torque(
        &mut self,
        (angle, gas_angle): (f64, f64),
        speed: f64,
        acceleration: f64,
    ) -> Result<f64, String> {
        let speed = speed.max(VANISHING_SPEED);
        // The time is read by no loss the solved motion takes (the ring films', which carry
        // the time of the step before, are refused with it).
        let crank = CrankState::new(angle, speed, acceleration, 0.0);
        self.states
            .fill(self.mechanism, std::slice::from_ref(&crank));
        let (mut force, mut pressure): (Column, Option<f64>) = ([0.0; LANES], None);
        if let Some(g) = self.gas {
            let (p, f) = g.at(gas_angle);
            (force[0], pressure) = (f, Some(p));
        }
        let applied = self.gas.map(|_| &force);
        self.loading.loads(
            self.mechanism,
            &self.states,
            applied,
            &mut self.loads,
            &mut self.total,
        );
        let total = if self.loading.several {
            &self.total
        } else {
            &self.loads[0]
        };
        let pressure = pressure.map(|p| [p; LANES]);
        let at = LossLanes {
            lanes: 0..1,
            states: &self.states,
            total,
            pressure: pressure.as_ref(),
            rated_meshes: &[],
        };
        self.budget
            .evaluate(&at, &mut self.losses)
            .map_err(|f| f.why)?;
        let power: f64 = self.losses.iter().map(|c| c[0]).sum();
        Ok(power / speed)
    }
}
