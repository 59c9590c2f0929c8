//! A machine's balance as a case asks for it: its layout, the firing delays of its cylinders,
//! and the balancing devices ([`MachineBalance`]); prepared for one mechanism
//! ([`PreparedBalance`]): the rotors sized from that mechanism's masses, the shaking force and
//! free moments at any step, and the orders at constant speed.
//!
//! Every device is sized from what the mechanism's own shaking force shows at constant speed
//! (its first and second orders, [`FirstOrderMasses::from_first_order`]), never assumed. At a
//! constant speed ω (α = 0) every force is the same function of θ times ω², so the rotors are
//! sized at ω = 1 rad/s and hold at every speed; with the crank accelerating they shake with
//! the tangential terms of [`Rotor::force`], as real counterweights do.

use crate::counterweight::{
    crank_counterweight, lanchester_shafts, CardanCounterweights, CardanMasses, FirstOrderMasses,
    Rotor,
};
use crate::device_error::{Device, DeviceError};
use crate::layout::{Layout, MachineOrders, MachineShaking, OrdersScratch};
use crate::shaking::{shaking_lane, Shaking};
use cardan_mechanism::{Column, CrankState, Mechanism, State, StateBlock, C};
use std::sync::{Arc, Mutex, TryLockError};

/// Steps of the revolution over which the orders are taken. N samples give order k exactly but
/// for the orders N − k, N + k, … folded onto it (aliasing); orders up to 6 are asked for, and
/// a slider-crank's order j is of the size of (λ/(1 + √(1 − λ²)))ʲ of its first, below 1e-40
/// at j = 114 for a rod only 1.7 times its crank (λ = 0.6), so 120 steps give the orders to
/// round-off (test: `crates/balance/tests/closed_forms.rs`, against 960 steps for every
/// registered mechanism) at a third of the cost of 360 (each step a state of every cylinder).
pub const ORDER_STEPS: usize = 120;

/// The highest order a summary reports (`shaking_force_order_4`): the orders are taken up to
/// it and no further (each order is its own sum over the revolution, the same bits whatever
/// the highest; the tests take higher ones through [`Layout::orders`]).
pub const MAX_ORDER: usize = 4;

/// What a case says about its machine's balance (issue 24's `[layout]` and `[balance]`).
#[derive(Debug, Clone, PartialEq)]
pub struct MachineBalance {
    /// The layout's kind as case files name it (`[layout] kind`: "inline", "vee", "boxer",
    /// "radial", "custom"), for the outputs to say what machine they are of; "inline" for one
    /// cylinder without a `[layout]`.
    pub kind: &'static str,
    /// The cylinders on the crankshaft.
    pub layout: Layout,
    /// Each cylinder's firing delay after cylinder 1, rad of crank angle (0 for cylinder 1): the
    /// gas cycle of cylinder i is cylinder 1's, `firing_delay[i]` later.
    pub firing_delay: Vec<f64>,
    /// The crank counterweight of every cylinder: all its rotating mass and this fraction of
    /// its reciprocating mass (`None`: no counterweight, today's balanced crankshaft).
    pub counterweight: Option<f64>,
    /// Two Lanchester shafts at twice the crank speed cancelling the machine's second order
    /// force.
    pub lanchester: bool,
    /// The counterweight pair on crank and wheel of every cylinder ([`CardanCounterweights`]).
    pub cardan_counterweights: bool,
    /// Whether the case asks for the machine's shaking step by step (it has `[layout]` or
    /// `[balance]`): the shaking force and free moments at every step and their peaks. Its
    /// orders, taken over one revolution, are every run's whatever this says.
    pub shaking_per_step: bool,
}

impl Default for MachineBalance {
    /// One cylinder, no balancing device: a case without `[layout]` or `[balance]`.
    fn default() -> Self {
        Self {
            kind: "inline",
            layout: Layout::single(),
            firing_delay: vec![0.0],
            counterweight: None,
            lanchester: false,
            cardan_counterweights: false,
            shaking_per_step: false,
        }
    }
}

/// A cylinder of a machine at the machine's crank angle θ (the reference throw's, module note
/// of `layout`): the mechanism at its own crank angle θ + `lead`, its gas the gas model's at
/// θ − `firing_delay` (the gas model being a function of a cylinder's own crank angle).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Phase {
    /// Its own crank angle ψ_i ahead of the machine's, φ_i − β_i, rad
    /// ([`Layout::cylinder_crank`]).
    pub lead: f64,
    /// Its gas cycle behind the machine's crank angle, rad: its firing delay after cylinder 1
    /// ([`MachineBalance::firing_delay`]) less cylinder 1's lead, so that cylinder 1's gas is
    /// the gas model's at its own angle ψ_1.
    pub firing_delay: f64,
}

impl Phase {
    /// The one cylinder of a machine in its own frame (or cylinder 1 of an inline machine).
    pub const FIRST: Phase = Phase {
        lead: 0.0,
        firing_delay: 0.0,
    };
}

impl MachineBalance {
    /// Every cylinder's [`Phase`], cylinder 1's first (lead and delay 0 where its throw and
    /// axis are the reference's: every layout but a vee, whose banks lie at ± half the bank
    /// angle).
    pub fn phases(&self) -> Vec<Phase> {
        let own = |c: &crate::layout::Cylinder| c.throw - c.axis_angle;
        let first = own(&self.layout.cylinders[0]);
        self.layout
            .cylinders
            .iter()
            .zip(&self.firing_delay)
            .map(|(c, &delay)| Phase {
                lead: own(c),
                firing_delay: delay - first,
            })
            .collect()
    }

    /// Whether the machine is one cylinder in the mechanism's own frame.
    pub fn is_single(&self) -> bool {
        self.layout.cylinders.len() == 1 && is_own_frame(&self.layout, 0)
    }

    /// Whether the cardan counterweight pair applies to `mechanism`: asked for
    /// (`cardan_counterweights`) and the mechanism has a body turning against the crank at its
    /// speed (a cardan wheel) to carry it. A mechanism without one ignores the pair (a case
    /// comparing the slider-crank with the cardan gear equips the cardan gear only, as
    /// `[masses.cardan_gear]` applies to it only).
    pub fn cardan_pair_applies(&self, mechanism: &dyn Mechanism) -> bool {
        self.cardan_counterweights && backward_body(mechanism).is_some()
    }

    /// `mechanism` carrying what the machine puts on its bodies besides the crankshaft: with
    /// `cardan_counterweights` and a cardan wheel ([`MachineBalance::cardan_pair_applies`]),
    /// the pair's wheel counterweight, on the body that turns against
    /// the crank at its speed ([`Mechanism::with_added_mass`]), so that the joint loads, the
    /// drive torque and the kinetic energy have it. Without, or where the mechanism already
    /// carries it (no backward first order left), `mechanism` itself: equipping twice is
    /// equipping once. A run takes the equipped mechanism (`cardan_case`'s validation).
    ///
    /// The counterweight (sized by [`CardanCounterweights::for_masses`] from the first order,
    /// module note of `counterweight`): a point mass m₂ = |B₁|/(ω²·r_c²) at ρ = r_c from the
    /// body's reference point (the cardan wheel's centre S), placed in the body's frame where its
    /// backward rotor m₂·o₀·d cancels B₁/ω² (o₀ the body's orientation at θ = 0: a point
    /// z + o₀·e^{−iθ}·d of a body turning at −ω is a backward rotor of m·o₀·d): opposite the
    /// wheel pin T for the cardan gear.
    pub fn equip(&self, mechanism: Arc<dyn Mechanism>) -> Result<Arc<dyn Mechanism>, DeviceError> {
        if !self.cardan_counterweights {
            return Ok(mechanism);
        }
        let m = mechanism.as_ref();
        let Some(body) = backward_body(m) else {
            // No cardan wheel: the mechanism ignores the pair.
            return Ok(mechanism);
        };
        let first = Layout::single().orders(m, &[], 1.0, ORDER_STEPS, 1).force[1];
        let backward = first.backward;
        if backward.norm() <= PAIR_DONE * first.forward.norm().max(backward.norm()) {
            return Ok(mechanism);
        }
        let crank = m.crank_radius();
        let masses = CardanMasses {
            crank,
            reciprocating: backward.norm() / crank,
            wheel: 0.0,
            crank_unbalance: 0.0,
        };
        let pair = CardanCounterweights::for_masses(&masses, crank);
        let o0 = m.state(&CrankState::new(0.0, 1.0, 0.0, 0.0)).bodies[body].orientation;
        let offset = -backward / (pair.wheel_mass * o0);
        m.with_added_mass(body, pair.wheel_mass, offset, 0.0)
            .map(Arc::from)
            .ok_or_else(|| DeviceError {
                device: Device::CardanCounterweights,
                rule: format!(
                    "the {} cannot carry a counterweight on its body turning against the crank",
                    m.name()
                ),
            })
    }

    /// The machine of `mechanism` ([`MachineBalance::equip`]ped first, which it may already
    /// be): its rotors sized (module note), or why a device cannot be formed with it.
    pub fn prepare(&self, mechanism: Arc<dyn Mechanism>) -> Result<PreparedBalance, DeviceError> {
        let mechanism = self.equip(mechanism)?;
        let m = mechanism.as_ref();
        // One room for the orders that size the devices and the run's own (the same mechanism).
        let mut scratch = OrdersScratch::default();
        let (own, carried) = self.cylinder_rotors(m, &mut scratch)?;
        let mut rotors: Vec<Rotor> = (0..self.layout.cylinders.len())
            .flat_map(|i| own.iter().map(move |r| (i, r)))
            .map(|(i, r)| self.layout.place(i, r))
            .collect();
        if self.lanchester {
            let second = (self.layout)
                .orders_in(m, &rotors, 1.0, ORDER_STEPS, 2, &mut scratch)
                .force[2];
            rotors.extend(lanchester_shafts(&second, 1.0, self.layout.reference()));
        }
        Ok(PreparedBalance {
            mechanism,
            axes: self.layout.axes(),
            reference: self.layout.reference(),
            layout: self.layout.clone(),
            rotors,
            carried,
            scratch: KeptScratch(Mutex::new(scratch)),
        })
    }

    /// One cylinder's rotors in its own frame: the crank's own unbalance, then its
    /// counterweight or the cardan pair's crank counterweight (the wheel's is the equipped
    /// mechanism's own mass, [`MachineBalance::equip`]); and the Σ m·ρ of those the crankshaft
    /// carries alone ([`PreparedBalance::crank_masses`]).
    fn cylinder_rotors(
        &self,
        m: &dyn Mechanism,
        scratch: &mut OrdersScratch,
    ) -> Result<(Vec<Rotor>, C), DeviceError> {
        let unbalance = m.masses().crank_unbalance;
        let mut own = Vec::new();
        if unbalance != 0.0 {
            own.push(Rotor::crank_unbalance(unbalance));
        }
        let mut carried = C::new(unbalance, 0.0);
        let single = Layout::single();
        let mut first =
            |own: &[Rotor]| (single.orders_in(m, own, 1.0, ORDER_STEPS, 1, scratch)).force[1];
        if let Some(fraction) = self.counterweight {
            if self.cardan_counterweights {
                return Err(DeviceError {
                    device: Device::Counterweight,
                    rule: "cannot be combined with cardan_counterweights = true (the pair already cancels the whole first order)".into(),
                });
            }
            let masses = FirstOrderMasses::from_first_order(&first(&own), 1.0);
            let counterweight = crank_counterweight(&masses, fraction, 0.0);
            carried += counterweight.mass_radius;
            own.push(counterweight);
        }
        if self.cardan_pair_applies(m) {
            // The equipped mechanism has no backward first order left (its wheel carries the
            // counterweight): what is left turns with the crank, (m + m_w + m₂)·r_c + m·e
            // towards S, and the pair's crank counterweight opposite S cancels it.
            let counterweight = -first(&own).forward;
            carried += counterweight;
            own.push(Rotor::on_crank(counterweight, 0.0));
        }
        Ok((own, carried))
    }
}

/// Whether cylinder `i` of `layout` runs at the machine's own crank angle in the machine's
/// frame (no throw, no turn of its axis): its state is the step's.
fn is_own_frame(layout: &Layout, i: usize) -> bool {
    let c = &layout.cylinders[i];
    c.throw == 0.0 && c.axis_angle == 0.0
}

/// Below this fraction of the first order, a mechanism's backward first order is round-off: it
/// carries the cardan pair's wheel counterweight already ([`MachineBalance::equip`]).
const PAIR_DONE: f64 = 1e-9;

/// The first body of `m` that turns at minus the crank speed (read from a state at
/// ω = 1 rad/s).
fn backward_body(m: &dyn Mechanism) -> Option<usize> {
    let state = m.state(&CrankState::new(0.3, 1.0, 0.0, 0.0));
    state
        .bodies
        .iter()
        .position(|b| (b.angular_velocity + 1.0).abs() < 1e-12)
}

/// A machine's balance prepared for one mechanism.
#[derive(Debug, Clone)]
pub struct PreparedBalance {
    mechanism: Arc<dyn Mechanism>,
    layout: Layout,
    /// Every rotor of the machine, in the machine frame.
    rotors: Vec<Rotor>,
    /// [`PreparedBalance::crank_masses`].
    carried: C,
    /// The cylinders' axis directions ([`Layout::axes`]), made once.
    axes: Vec<C>,
    /// The plane the moments are taken about ([`Layout::reference`]), m, found once.
    reference: f64,
    /// Room for [`PreparedBalance::orders`], kept from the sizing of the devices.
    scratch: KeptScratch,
}

/// An [`OrdersScratch`] behind a lock, so that [`PreparedBalance::orders`] takes `&self` and
/// the prepared machine stays shareable between threads; a clone starts with a room of its own.
#[derive(Default)]
struct KeptScratch(Mutex<OrdersScratch>);

impl std::fmt::Debug for KeptScratch {
    /// Its name only: what a room holds depends on the calls made, not on the machine.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("KeptScratch")
    }
}

impl Clone for KeptScratch {
    fn clone(&self) -> Self {
        Self::default()
    }
}

impl PreparedBalance {
    /// The layout.
    pub fn layout(&self) -> &Layout {
        &self.layout
    }

    /// The rotors, in the machine frame.
    pub fn rotors(&self) -> &[Rotor] {
        &self.rotors
    }

    /// Σ m·ρ (kg·m, complex: towards where the masses are at θ = 0, in a cylinder's own frame)
    /// of the masses each cylinder's crankshaft carries besides the mechanism's bodies and
    /// alone: the crank's own unbalance and its counterweight (`[balance] counterweight`), or
    /// the cardan pair's crank counterweight. They turn with the crank about the main axis, so
    /// only the main bearing holds them: its reaction gains their m·a
    /// (`cardan_dynamics::Inertial`). The pair's wheel counterweight is not among them: it is
    /// part of the wheel of the equipped mechanism ([`PreparedBalance::mechanism`]), whose
    /// kinetostatics share it out to the crank pin, the mesh and the main bearing. Lanchester
    /// shafts run in bearings of their own, not the mechanism's.
    pub fn crank_masses(&self) -> C {
        self.carried
    }

    /// The mechanism the machine is made of, equipped ([`MachineBalance::equip`]).
    pub fn mechanism(&self) -> &Arc<dyn Mechanism> {
        &self.mechanism
    }

    /// The machine's shaking at `crank`, cylinder 1's own shaking being `first` where its
    /// state is the step's (the stepper's columns; computed here otherwise, each cylinder's
    /// state filled into `scratch`'s block of one lane: no block made per step).
    pub fn at(
        &self,
        crank: &CrankState,
        first: Option<Shaking>,
        scratch: &mut CylinderScratch,
    ) -> MachineShaking {
        let m = self.mechanism.as_ref();
        let t = m.topology();
        let per_cylinder = (0..self.layout.cylinders.len()).map(|i| match first {
            Some(s) if i == 0 && is_own_frame(&self.layout, 0) => s,
            _ => {
                let block = scratch.block(t);
                block.fill(m, &[self.layout.cylinder_crank(i, crank)]);
                shaking_lane(t, block, 0)
            }
        });
        let (axes, z0) = (&self.axes, self.reference);
        (self.layout).sum_about(z0, |i| axes[i], per_cylinder, &self.rotors, crank)
    }

    /// The machine's shaking at `crank` from each cylinder's own (`per_cylinder[i]`, in its
    /// frame at its own angle) and the rotors' ([`Layout::sum`]).
    pub fn sum(
        &self,
        per_cylinder: impl ExactSizeIterator<Item = Shaking>,
        crank: &CrankState,
    ) -> MachineShaking {
        let (axes, z0) = (&self.axes, self.reference);
        (self.layout).sum_about(z0, |i| axes[i], per_cylinder, &self.rotors, crank)
    }

    /// [`PreparedBalance::at`] the state `state` of cylinder 1 (a whole step).
    pub fn at_state(&self, state: &State, scratch: &mut CylinderScratch) -> MachineShaking {
        let own = crate::shaking::shaking(self.mechanism.topology(), state);
        self.at(&state.crank, Some(own), scratch)
    }

    /// Whether cylinder 1 runs at the machine's own crank angle in the machine's frame (no
    /// throw, no turn of its axis): its state is the mechanism's at the machine's angle.
    pub fn first_in_own_frame(&self) -> bool {
        is_own_frame(&self.layout, 0)
    }

    /// Whether [`PreparedBalance::at_block`] takes the machine: one cylinder.
    pub fn by_block(&self) -> bool {
        self.layout.cylinders.len() == 1
    }

    /// [`PreparedBalance::at_state`] at every lane of `states` (cylinder 1's states), read from
    /// the block's columns, into `out`'s first four columns: the shaking force's x and y, the
    /// free moment's pitch and yaw. The same operations in the same order as at each step
    /// (the same bits). A machine of one cylinder only ([`PreparedBalance::by_block`]); one not
    /// in its own frame has its states filled into `scratch`'s block.
    ///
    /// # Panics
    /// With several cylinders, or fewer than four columns.
    pub fn at_block(&self, states: &StateBlock, scratch: &mut CylinderScratch, out: &mut [Column]) {
        assert!(self.by_block(), "a block of a machine of one cylinder");
        let m = self.mechanism.as_ref();
        let t = m.topology();
        let n = states.len;
        let own: &StateBlock = if is_own_frame(&self.layout, 0) {
            states
        } else {
            scratch.cranks.clear();
            let own = (0..n).map(|i| self.layout.cylinder_crank(0, &states.crank.at(i)));
            scratch.cranks.extend(own);
            let block = scratch
                .block
                .get_or_insert_with(|| Box::new(StateBlock::for_topology(t)));
            block.fill(m, &scratch.cranks);
            block
        };
        let [fx, fy, pitch, yaw, ..] = out else {
            panic!("four columns: the force's x and y, the moment's pitch and yaw");
        };
        for i in 0..n {
            let s = shaking_lane(t, own, i);
            let crank = states.crank.at(i);
            let machine = self
                .layout
                .sum_on(&self.axes, std::iter::once(s), &self.rotors, &crank);
            fx[i] = machine.force.re;
            fy[i] = machine.force.im;
            pitch[i] = machine.pitch();
            yaw[i] = machine.yaw();
        }
    }

    /// The orders 0..=[`MAX_ORDER`] of the shaking force and free moment over one revolution
    /// at the constant speed `speed` (rad/s).
    ///
    /// Taken in the kept room ([`OrdersScratch`]; a room of its own where another thread holds
    /// it): the bits of [`Layout::orders`].
    pub fn orders(&self, speed: f64) -> MachineOrders {
        let m = self.mechanism.as_ref();
        let orders = |scratch: &mut OrdersScratch| {
            (self.layout).orders_in(m, &self.rotors, speed, ORDER_STEPS, MAX_ORDER, scratch)
        };
        match self.scratch.0.try_lock() {
            Ok(mut kept) => orders(&mut kept),
            // A call that panicked left it: every call writes what it reads.
            Err(TryLockError::Poisoned(kept)) => orders(&mut kept.into_inner()),
            Err(TryLockError::WouldBlock) => orders(&mut OrdersScratch::default()),
        }
    }
}

/// Room for the states of the cylinders [`PreparedBalance::at`] and
/// [`PreparedBalance::at_block`] evaluate apart from the step's: a block (some 30 kB, made at
/// its first use and kept) and its crank states.
#[derive(Debug, Clone, Default)]
pub struct CylinderScratch {
    block: Option<Box<StateBlock>>,
    cranks: Vec<CrankState>,
}

impl CylinderScratch {
    /// The kept block, made for `topology` at its first use.
    fn block(&mut self, topology: &cardan_mechanism::Topology) -> &mut StateBlock {
        self.block
            .get_or_insert_with(|| Box::new(StateBlock::for_topology(topology)))
    }
}
