//! The whole machine a run is of ([`Machine`]): every cylinder's equipped mechanism on one
//! crankshaft, at its own crank angle, axis and gas phase, the masses the crankshaft carries,
//! the balancing devices, which crank pin each cylinder's rod is on and which main journals
//! carry each throw; built once per mechanism and case (`cardan_case`'s validation), read by
//! the load families (the crank's masses), the machine's stage ([`crate::MachineStage`]), the
//! solved motion (the cylinders' phases) and the outputs.
//!
//! # Main journals
//!
//! The cylinders are grouped into throw planes by their axial position (a vee's pair, a
//! radial's star, share one). One plane: one main journal carries the whole machine (a
//! one-throw crankshaft, as the one-cylinder mechanism's main bearing). Several planes: a main
//! journal on each side of every throw (a fully supported crankshaft), midway between
//! neighbouring planes and half a pitch beyond the outermost ones; each throw's main-bearing
//! load is shared between its two neighbouring journals by the statically determinate split,
//! the throw taken as a beam simply supported on them (Khurmi & Gupta, *A Textbook of Machine
//! Design*, ch. 32, the centre crankshaft: reactions F·b₂/b and F·b₁/b): half to each, the
//! journals being midway. The usual first approximation of engine-dynamics texts; a
//! continuous beam on elastic journals shares the loads otherwise (`docs/results.md`).

use crate::family::{main_bearing, Gas, Inertial, Solver};
use cardan_balance::{MachineBalance, Phase, PreparedBalance};
use cardan_mechanism::{JointKind, Mechanism, Topology, C};
use std::sync::Arc;

pub use cardan_losses::MachineKind;

/// A machine of one mechanism, built once (module note).
#[derive(Debug, Clone)]
pub struct Machine {
    /// Pump or engine.
    pub kind: MachineKind,
    /// What of the machine does not apply to this mechanism and is ignored for it, one
    /// sentence each (`[balance] cardan_counterweights` on a mechanism without a cardan
    /// wheel): the run's warnings in `summary.json`.
    pub notes: Vec<String>,
    /// Whether the case asks for the machine's shaking step by step
    /// ([`MachineBalance::shaking_per_step`]).
    pub shaking_per_step: bool,
    /// The layout and devices prepared for the mechanism ([`MachineBalance::prepare`], called
    /// here only): the equipped mechanism, the rotors, the crank's carried masses.
    balance: PreparedBalance,
    /// Each cylinder's crank angle and gas phase at the machine's crank angle.
    phases: Vec<Phase>,
    /// Each cylinder's axis direction e^{iβ} in the machine frame.
    axes: Vec<C>,
    /// Each cylinder's crank pin (index from 0, the pins in the cylinders' order of first use).
    pin_of: Vec<usize>,
    /// Each cylinder's throw plane (index from 0, by axial position).
    plane_of: Vec<usize>,
    /// The number of throw planes.
    planes: usize,
    /// The mechanism's main bearing (the crankshaft's pin on the frame) and crank pin (the
    /// crankshaft's first pin on another body), by joint index.
    main_bearing: Option<usize>,
    crank_pin: Option<usize>,
}

/// Two angles closer than this (rad) are one: a shared crank pin.
const SAME_ANGLE: f64 = 1e-9;

/// Two axial positions closer than this (m) are one throw plane.
const SAME_PLANE: f64 = 1e-9;

impl Machine {
    /// The machine `machine` of `mechanism` (equipped with what the machine puts on its
    /// bodies), or why a device cannot be formed with it.
    pub fn build(
        machine: &MachineBalance,
        mechanism: Arc<dyn Mechanism>,
        kind: MachineKind,
    ) -> Result<Self, cardan_balance::DeviceError> {
        let mut notes = Vec::new();
        if machine.cardan_counterweights && !machine.cardan_pair_applies(mechanism.as_ref()) {
            notes.push(format!(
                "balance.cardan_counterweights = true is ignored: the {} has no cardan wheel (a body turning against the crank) to carry the pair",
                mechanism.name()
            ));
        }
        let balance = machine.prepare(mechanism)?;
        let layout = balance.layout();
        let cylinders = &layout.cylinders;
        let mut planes: Vec<f64> = Vec::new();
        for c in cylinders {
            if !planes
                .iter()
                .any(|&z| (z - c.axial_position).abs() <= SAME_PLANE)
            {
                planes.push(c.axial_position);
            }
        }
        planes.sort_by(f64::total_cmp);
        let plane_of = cylinders
            .iter()
            .map(|c| {
                let near = |&z: &f64| (z - c.axial_position).abs() <= SAME_PLANE;
                planes.iter().position(near).expect("its plane")
            })
            .collect();
        let mut pins: Vec<(f64, f64)> = Vec::new();
        let mut pin_of = Vec::with_capacity(cylinders.len());
        for c in cylinders {
            let same = |&(z, phi): &(f64, f64)| {
                (z - c.axial_position).abs() <= SAME_PLANE && angle_gap(phi, c.throw) <= SAME_ANGLE
            };
            let k = pins.iter().position(same).unwrap_or_else(|| {
                pins.push((c.axial_position, c.throw));
                pins.len() - 1
            });
            pin_of.push(k);
        }
        let t = balance.mechanism().topology();
        Ok(Self {
            kind,
            notes,
            shaking_per_step: machine.shaking_per_step,
            phases: machine.phases(),
            axes: layout.axes(),
            pin_of,
            plane_of,
            planes: planes.len(),
            main_bearing: main_bearing(t),
            crank_pin: crank_pin(t),
            balance,
        })
    }

    /// The mechanism every cylinder runs, equipped ([`MachineBalance::equip`]).
    pub fn mechanism(&self) -> &Arc<dyn Mechanism> {
        self.balance.mechanism()
    }

    /// The layout and devices prepared for the mechanism.
    pub fn balance(&self) -> &PreparedBalance {
        &self.balance
    }

    /// Σ m·ρ of the masses each cylinder's crankshaft carries besides the mechanism's bodies
    /// ([`PreparedBalance::crank_masses`]), kg·m.
    pub fn crank_masses(&self) -> C {
        self.balance.crank_masses()
    }

    /// A cylinder's load families as every run of the machine takes them: the bodies' inertia
    /// with the crank's carried masses, and the gas where the case has one (`gas`), both by the
    /// mechanism's closed forms. The run's train and the machine's stage take the same.
    pub fn load_families(&self, gas: bool) -> (Inertial, Option<Gas>) {
        let inertial = Inertial::new(Solver::ClosedForm).carrying(self.crank_masses());
        (inertial, gas.then_some(Gas(Solver::ClosedForm)))
    }

    /// Every cylinder's crank angle and gas phase at the machine's crank angle.
    pub fn phases(&self) -> &[Phase] {
        &self.phases
    }

    /// The number of cylinders.
    pub fn cylinders(&self) -> usize {
        self.phases.len()
    }

    /// Whether cylinder 1 is the mechanism at the machine's crank angle in its own frame (a
    /// run's train is then cylinder 1).
    pub fn train_is_first(&self) -> bool {
        self.balance.first_in_own_frame()
    }

    /// Cylinder `i`'s axis direction e^{iβ_i}.
    pub fn axis(&self, i: usize) -> C {
        self.axes[i]
    }

    /// The number of main journals (module note).
    pub fn journals(&self) -> usize {
        if self.planes == 1 {
            1
        } else {
            self.planes + 1
        }
    }

    /// The journals that carry cylinder `i`'s main-bearing load, each with its share.
    pub fn journals_of(&self, i: usize) -> [(usize, f64); 2] {
        let p = self.plane_of[i];
        if self.planes == 1 {
            [(0, 1.0), (0, 0.0)]
        } else {
            [(p, 0.5), (p + 1, 0.5)]
        }
    }

    /// The crank pin cylinder `i`'s rod is on.
    pub fn pin_of(&self, i: usize) -> usize {
        self.pin_of[i]
    }

    /// The number of crank pins.
    pub fn pins(&self) -> usize {
        self.pin_of.iter().max().map_or(0, |&k| k + 1)
    }

    /// The mechanism's main bearing joint, if it has one.
    pub fn main_bearing(&self) -> Option<usize> {
        self.main_bearing
    }

    /// The mechanism's crank pin joint, if it has one.
    pub fn crank_pin(&self) -> Option<usize> {
        self.crank_pin
    }
}

/// |a − b| modulo a turn, rad.
fn angle_gap(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(std::f64::consts::TAU);
    d.min(std::f64::consts::TAU - d)
}

/// The crankshaft's first pin on another body: the crank pin.
fn crank_pin(t: &Topology) -> Option<usize> {
    t.joints.iter().position(|j| {
        j.body == t.crankshaft && j.other.is_some() && matches!(j.kind, JointKind::Revolute(_))
    })
}
