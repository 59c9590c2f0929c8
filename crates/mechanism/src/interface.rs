//! What every mechanism implements and is built from: the [`Mechanism`] trait, the machine's
//! shared geometry, a mechanism's options and its registry entry's shape, the checks the
//! mechanisms share; and the filling of a [`StateBlock`] by a mechanism. Below the mechanisms'
//! modules and above the block, model and motion ones (the registry, naming every mechanism,
//! is the crate root's).

use crate::input::Input;
use crate::mass::{MassInputs, MassProperties};
use crate::model::{Bearings, Loads, State, Topology};
use crate::motion::{MotionError, MotionSource};
use crate::{Column, CrankState, LoadsBlock, StateBlock, C, LANES};
use std::collections::BTreeMap;

/// A physically impossible or ill-posed machine: the input at fault, its value, the rule (the
/// case maps the input to its field).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{field:?} = {value}: {rule}")]
pub struct MechanismError {
    /// The input at fault, e.g. [`Input::RodLength`], the cardan gear's option
    /// `pressure_angle`.
    pub field: Input,
    pub value: String,
    pub rule: String,
}

impl MechanismError {
    pub fn new(field: Input, value: impl std::fmt::Display, rule: impl Into<String>) -> Self {
        Self {
            field,
            value: value.to_string(),
            rule: rule.into(),
        }
    }
}

/// Any mechanism: its parts, and its motion as a pure function of the crank state.
pub trait Mechanism: Send + Sync + std::fmt::Debug {
    /// The name used in case files and outputs.
    fn name(&self) -> &'static str;

    /// Bodies, joints, pistons.
    fn topology(&self) -> &Topology;

    /// The resolved mass fields (for the summary).
    fn masses(&self) -> &MassProperties;

    /// Fills the lanes `0..block.len` of `block` (made by [`StateBlock::for_topology`]) at the
    /// crank states its crank columns hold, all but the extras. Callers go through
    /// [`StateBlock::fill`] or [`StateBlock::fill_next`]. A mechanism may leave alone the columns
    /// that are zero at every step (a block starts zeroed and is filled by mechanisms of one
    /// kind: which columns it writes must not depend on its parameters, as a sweep's points
    /// share blocks, `cardan_pipeline::RunRooms`).
    fn fill_block(&self, block: &mut StateBlock);

    /// Fills the [`Topology::extras`] of a `state` that [`Mechanism::fill_block`] filled (only
    /// done when an output wants them).
    fn fill_extras(&self, _state: &mut State) {}

    /// The first piston's position x (m) and dx/dθ (m/rad) at crank angle `angle` (rad): what
    /// the cylinder volume V(θ) and dV/dθ need, without the rest of the state.
    fn piston_position(&self, angle: f64) -> (f64, f64);

    /// First piston's position at top dead centre, m.
    fn piston_top(&self) -> f64;

    /// First piston's position at bottom dead centre, m.
    fn piston_bottom(&self) -> f64;

    /// Crank angle of top dead centre, where the piston reaches [`Mechanism::piston_top`], rad.
    /// In-line mechanisms have it at π/2 (the cylinder lies along +y).
    fn top_dead_centre(&self) -> f64 {
        std::f64::consts::FRAC_PI_2
    }

    /// Stroke, m.
    fn stroke(&self) -> f64 {
        self.piston_top() - self.piston_bottom()
    }

    /// Whether the first piston reciprocates along a cylinder between dead centres, so that a
    /// gas model can take the chamber volume from its position. The hypotrochoid's piston links
    /// turn about the main axis instead.
    fn has_cylinder(&self) -> bool {
        true
    }

    /// Checks the crank angles of a run, `first + i·step` for i = 0..=`steps` (rad), before it
    /// runs: an error names the first angle where the mechanism's loads are singular (a chain
    /// that folds), so that `cardan check` refuses what the run would fail on. None by
    /// default.
    fn check_angles(&self, _first: f64, _step: f64, _steps: usize) -> Result<(), MechanismError> {
        Ok(())
    }

    /// This mechanism with a rigid mass added to body `body` (a balancing counterweight,
    /// `cardan_balance::MachineBalance::equip`): `mass` (kg) whose centre of gravity is at
    /// `offset` (m, complex) from the body's reference point in the body's own frame (the point
    /// its centre of gravity is filled at without the added mass, the frame turning with its
    /// orientation: at position reference + orientation·offset), with the polar moment
    /// `inertia` (kg·m²) about its own centre of gravity. The joint loads, drive torque,
    /// shaking force and kinetic energy of the result include it. `None` where the mechanism
    /// cannot take one on that body (the default).
    fn with_added_mass(
        &self,
        _body: usize,
        _mass: f64,
        _offset: C,
        _inertia: f64,
    ) -> Option<Box<dyn Mechanism>> {
        None
    }

    /// Radius at which the crank delivers its force, m: the crank-pin radius, the radius of
    /// Vidinsky's (2021) output force F_out in his mechanical advantage MA = F_out/F_in (L225).
    /// By default half the stroke (the slider-crank's and the Scotch yoke's crank).
    fn crank_radius(&self) -> f64 {
        self.stroke() / 2.0
    }

    /// The closed-form kinetostatics over a block, if the mechanism has them: the joint loads
    /// and drive torque caused by the bodies' inertia (if `inertia`) and by the force
    /// `piston_force` on every piston (N along the cylinder axis towards the crankshaft; none
    /// without one), at the block's steps, written to `out` (made by
    /// [`LoadsBlock::for_topology`] and only ever written by this method: the columns that
    /// are zero at every step, a pin's couple say, may be left as they are). Returns false
    /// (and leaves `out` alone) where the general planar solve must serve.
    fn closed_form_block(
        &self,
        _block: &StateBlock,
        _inertia: bool,
        _piston_force: Option<&Column>,
        _out: &mut LoadsBlock,
    ) -> bool {
        false
    }

    /// [`Mechanism::closed_form_block`] at one state (allocates a block: for tests and single
    /// states), with `piston_forces` the force on each piston (the first serves all).
    fn closed_form_loads(
        &self,
        state: &State,
        inertia: bool,
        piston_forces: &[f64],
        out: &mut Loads,
    ) -> bool {
        let block = StateBlock::of_state(self.topology(), state);
        let force = piston_forces.first().map(|&f| [f; LANES]);
        let mut loads = LoadsBlock::for_topology(self.topology());
        if !self.closed_form_block(&block, inertia, force.as_ref(), &mut loads) {
            return false;
        }
        loads.gather(0, out);
        true
    }

    /// A new state at `crank`, with its extras (allocates a block: for single states; many
    /// states go through [`Mechanism::each_state`], steppers fill blocks).
    fn state(&self, crank: &CrankState) -> State {
        let mut out = None;
        self.each_state(std::slice::from_ref(crank), &mut |s| out = Some(s.clone()));
        out.expect("one state per crank state")
    }

    /// Calls `visit` with the state at each of `cranks` in turn, with its extras, filled a
    /// block of [`LANES`] at a time into one block and one state (a block is some 30 kB of
    /// columns to zero: made once for all).
    fn each_state(&self, cranks: &[CrankState], visit: &mut dyn FnMut(&State)) {
        let t = self.topology();
        let mut block = StateBlock::for_topology(t);
        let mut s = State::for_topology(t);
        for chunk in cranks.chunks(LANES) {
            block.fill(self, chunk);
            for i in 0..chunk.len() {
                block.gather(i, &mut s);
                self.fill_extras(&mut s);
                visit(&s);
            }
        }
    }
}

/// What every mechanism of a case shares, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MachineGeometry {
    /// Half the stroke, m: the slider-crank's and Scotch yoke's crank; twice the cardan crank.
    pub crank_length: f64,
    /// Rod length, m: centre distance of the slider-crank rod; the cardan rod from wheel pin
    /// to piston pin; the Scotch yoke's from the slot centre line to the piston pin.
    pub rod_length: f64,
    /// Bore, m.
    pub bore: f64,
    /// Piston-pin offset from the cylinder axis, m (slider-crank only).
    pub pin_offset: f64,
}

impl MachineGeometry {
    /// The rolling bearings of the piston pin, crank pin and main axis by the rules of Karhula
    /// (2008) App. 9.1: pitch diameters d_m = d_pis/4 at the piston pin (A9.1.10), 1.5 times
    /// that at the crank pin and main bearings (A9.1.11); static load ratings C0 = d_m\[mm\]·10³ N
    /// at the piston pin (A9.1.12), twice that at the crank pin and main bearings (A9.1.13); two
    /// main bearings sharing the load (A9.1.24-25), one bearing elsewhere (a mechanism with two
    /// side by side says so itself).
    pub fn bearings(&self) -> [Bearings; 3] {
        let dm_pin = self.bore / 4.0;
        let c0_pin = dm_pin * 1e3 * 1e3;
        let pin = Bearings {
            radius: dm_pin / 2.0,
            count: 1,
            static_load_rating: c0_pin,
        };
        let crank = Bearings {
            radius: 0.75 * dm_pin,
            count: 1,
            static_load_rating: 2.0 * c0_pin,
        };
        [pin, crank, Bearings { count: 2, ..crank }]
    }
}

/// The kind of value a mechanism option takes (its unit at the case-file edge).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum OptionKind {
    Angle,
    Length,
    /// A pure number from `min` to `max` (only whole numbers if `whole`): every bare number of
    /// a case file has a plausible range, checked on reading and written in its JSON Schema.
    Number {
        min: f64,
        max: f64,
        whole: bool,
    },
    /// One of these words.
    Choice(&'static [&'static str]),
}

/// An option of a mechanism, set in the case file's table named after it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OptionSpec {
    pub name: &'static str,
    pub kind: OptionKind,
    pub meaning: &'static str,
}

/// A mechanism option's value: a number in SI, or a word.
#[derive(Debug, Clone, PartialEq)]
pub enum OptionValue {
    Number(f64),
    Word(String),
}

/// Option values by name.
pub type Options = BTreeMap<String, OptionValue>;

/// Builds a mechanism from the case's geometry, mass fields and its own options.
pub type Build =
    fn(&MachineGeometry, &MassInputs, &Options) -> Result<Box<dyn Mechanism>, MechanismError>;

/// One line of the registry.
#[derive(Debug, Clone, Copy)]
pub struct Entry {
    /// The name case files use.
    pub name: &'static str,
    pub summary: &'static str,
    /// Its own options, all optional.
    pub options: &'static [OptionSpec],
    /// Mass fields it has no use for (an error if a case sets them for it).
    pub unused_masses: &'static [&'static str],
    /// Whether it reads `geometry.pin_offset` (a case giving one that none of its mechanisms
    /// reads is refused).
    pub pin_offset: bool,
    pub build: Build,
}

pub(crate) fn check_length(field: Input, value: f64) -> Result<f64, MechanismError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(MechanismError::new(
            field,
            value,
            "must be a finite positive length",
        ))
    }
}

/// Checks that the rod's centre of gravity lies on the rod.
pub(crate) fn check_rod_cg(rod_cg: f64, rod: f64) -> Result<(), MechanismError> {
    if (0.0..=rod).contains(&rod_cg) {
        Ok(())
    } else {
        Err(MechanismError::new(
            Input::RodCg,
            rod_cg,
            format!("the rod's centre of gravity must lie on the rod, between 0 and geometry.rod_length ({rod} m)"),
        ))
    }
}

/// The word option `name` of `options`, or `default`.
pub(crate) fn word<'a>(options: &'a Options, name: &str, default: &'a str) -> &'a str {
    match options.get(name) {
        Some(OptionValue::Word(w)) => w,
        _ => default,
    }
}

/// The number option `name` of `options`, or `default`.
pub(crate) fn number(options: &Options, name: &str, default: f64) -> f64 {
    match options.get(name) {
        Some(OptionValue::Number(x)) => *x,
        _ => default,
    }
}

impl StateBlock {
    /// Fills the block with `mechanism` at `cranks` (at most [`LANES`] of them).
    pub fn fill<M: Mechanism + ?Sized>(&mut self, mechanism: &M, cranks: &[CrankState]) {
        assert!(cranks.len() <= LANES, "a block holds at most {LANES} steps");
        for (i, c) in cranks.iter().enumerate() {
            self.crank.set(i, c);
        }
        self.len = cranks.len();
        mechanism.fill_block(self);
    }

    /// Fills the block with the next states of the prescribed `motion`
    /// ([`MotionSource::next_block`]) and `mechanism` at them; the motion's error if it stopped
    /// short of a block.
    pub fn fill_next(
        &mut self,
        mechanism: &dyn Mechanism,
        motion: &mut dyn MotionSource,
    ) -> Option<MotionError> {
        let (n, error) = motion.next_block(&mut self.crank);
        self.len = n;
        mechanism.fill_block(self);
        error
    }
}
