//! The loss budget: friction models of `cardan-friction` and the gear-mesh loss of
//! `cardan-gears` attached to a mechanism's pistons and joints by kind, with no mechanism code.
//! At every step each component's power loss follows from the joint's total (lossless) load and
//! relative speed, or from the piston's speed, as Karhula (2008) App. 9.1 computes them: the
//! losses are charged to the drive afterwards (A9.1.56-75) and do not change the loads.
//!
//! The components, in this order:
//! - `rings`: the piston rings of every piston in a cylinder (A9.1.2-4, A9.1.8), or each ring
//!   on its oil film (Reynolds with squeeze film and asperity contact, [`cardan_friction::RingFilm`]);
//! - per prismatic joint: `skirt` for the slide of a piston on the frame (its side force,
//!   A9.1.5; the viscous skirt of the Thai thesis 2.5.c.1-3 in the other reading), the joint's
//!   own name for any other slide (a Scotch-yoke slot: Coulomb friction on its force);
//! - per revolute joint, by its name: its rolling bearings (A9.1.10-35; Palmgren; SKF) or a
//!   plain journal bearing (Petroff; short bearing with the eccentricity from the load);
//! - per gear mesh, by its name: Anderson & Loewenthal's sliding, rolling and windage loss
//!   (A9.1.36-55) in the thesis's or the corrected reading;
//! - of an engine ([`Friction::engine`]) with a cylinder, each if switched on: `valve_train`,
//!   `accessories`, `pumping` ([`crate::engine_losses`]), at the step's crank speed.

pub mod models;

use crate::engine_losses::{displacement, EngineLosses, ValveTrainLoss};
use crate::loss::{BindInput, LaneFailure, Loss, LossLanes, Oil, ParameterValues};
use crate::loss_models::{default_model, Attachment, LossModel};
use crate::mesh::GearSpec;
use crate::setup_error::{failed, SetupError, SetupInput};
use crate::MachineKind;
use cardan_friction::KARHULA_SKIRT_MU;
use cardan_mechanism::{
    Bearings, Column, JointKind, Loads, LoadsBlock, Mechanism, State, StateBlock, Topology, LANES,
};

/// Catalogue values of a joint's bearings; `None` keeps the declared value.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BearingSize {
    /// Pitch (mean) diameter d_m of one bearing, m (the journal diameter of a plain bearing).
    pub pitch_diameter: Option<f64>,
    /// Basic static load rating C0 of one bearing, N.
    pub static_load_rating: Option<f64>,
    /// Bearings side by side sharing the joint's load.
    pub count: Option<u32>,
}

impl BearingSize {
    /// `declared` with these values put in.
    pub fn apply(&self, declared: Bearings) -> Bearings {
        Bearings {
            radius: self.pitch_diameter.map_or(declared.radius, |d| d / 2.0),
            count: self.count.unwrap_or(declared.count),
            static_load_rating: self
                .static_load_rating
                .unwrap_or(declared.static_load_rating),
        }
    }
}

/// Every loss model of a case, SI: the registry's model at each attachment
/// ([`crate::LOSS_MODELS`]; `None`: no loss there) and the parameters they are bound with.
#[derive(Debug, Clone, PartialEq)]
pub struct Friction {
    pub oil: Oil,
    /// The models' parameters the case sets (the others take their defaults).
    pub parameters: ParameterValues,
    /// Model of the rings of every piston in a cylinder.
    pub rings: Option<&'static LossModel>,
    /// Model of a piston's slide on the frame.
    pub skirt: Option<&'static LossModel>,
    /// Coulomb friction coefficient of the other slides (a Scotch-yoke slot).
    pub slide_friction_coefficient: f64,
    /// Model of every revolute joint.
    pub bearings: Option<&'static LossModel>,
    /// Models of named revolute joints (`None`: no loss), overriding [`Friction::bearings`].
    pub joint_bearings: Vec<(String, Option<&'static LossModel>)>,
    /// Catalogue values of named revolute joints' bearings, overriding the sizing rules the
    /// mechanism declared (Karhula A9.1.10-13).
    pub joint_sizes: Vec<(String, BearingSize)>,
    /// Model of every gear mesh.
    pub gear_mesh: Option<&'static LossModel>,
    /// The pair the mesh loss is computed on (the case's `[gear]`; Karhula's 20-tooth wheel
    /// with a 0.8-module ring addendum and b = d1/3 by default, A9.1.36-46).
    pub pair: GearSpec,
    /// The engine components (valve train, accessories, pumping) and the fmep cross-check of a
    /// four-stroke engine; `None` for a machine that is not an engine. The runner sets it for
    /// `machine = "engine"`, with every component off unless the case switches it on.
    pub engine: Option<EngineLosses>,
}

impl Friction {
    /// Karhula's (2008) App. 9.1 models and values ([`crate::LossParameter::default`],
    /// [`default_model`]): ring pack with μ = 0.07, Coulomb skirt (and other slides) with
    /// μ = 0.09, rolling bearings in his reading with f0 = 2, mesh loss as printed with z1 = 20,
    /// oil of 5 mm²/s and 900 kg/m³; no engine components (the thesis has none).
    pub fn karhula() -> Self {
        Self {
            oil: Oil {
                kinematic_viscosity: 5e-6,
                density: 900.0,
            },
            parameters: ParameterValues::default(),
            rings: default_model(Attachment::Rings),
            skirt: default_model(Attachment::Skirt),
            slide_friction_coefficient: KARHULA_SKIRT_MU,
            bearings: default_model(Attachment::Bearing),
            joint_bearings: Vec::new(),
            joint_sizes: Vec::new(),
            gear_mesh: default_model(Attachment::GearMesh),
            pair: GearSpec::default(),
            engine: None,
        }
    }

    /// `model` bound at the site of `mechanism` in a cylinder of `bore` (m): joint `joint`, a
    /// revolute joint's `bearings`.
    fn bind(
        &self,
        model: &LossModel,
        mechanism: &dyn Mechanism,
        bore: f64,
        joint: usize,
        bearings: Option<Bearings>,
    ) -> Result<Box<dyn Loss>, SetupError> {
        let site = BindInput {
            parameters: &self.parameters,
            declared: &[],
            oil: &self.oil,
            pair: &self.pair,
            mechanism,
            bore,
            joint,
            bearings,
        };
        model.bind_at(&site).unwrap_or_else(|| {
            Err(failed(
                SetupInput::Model(model.attachment),
                &"is bound by the engine, not at a joint",
            ))
        })
    }
}

/// The loss models of one mechanism, ready to evaluate step by step.
#[derive(Debug, Clone)]
pub struct LossBudget {
    names: Vec<String>,
    parts: Vec<Box<dyn Loss>>,
    /// Pump, or engine ([`Friction::engine`] set): its need or output and efficiency are the
    /// kind's, whatever the sign of a run's work (issue 36).
    kind: MachineKind,
}

impl LossBudget {
    /// Pump or engine (the loss stage's totals in `cardan-dynamics`: the need or output).
    pub fn kind(&self) -> MachineKind {
        self.kind
    }

    /// The budget of `mechanism` in a cylinder of `bore` (m) under `friction`.
    pub fn new(
        friction: &Friction,
        mechanism: &dyn Mechanism,
        bore: f64,
    ) -> Result<Self, SetupError> {
        let t = mechanism.topology();
        let f = friction;
        let mut names = Vec::new();
        let mut parts = Vec::new();
        if mechanism.has_cylinder() {
            if let Some(rings) = friction.rings {
                names.push("rings".to_string());
                parts.push(f.bind(rings, mechanism, bore, 0, None)?);
            }
        }
        for (k, j) in t.joints.iter().enumerate() {
            match j.kind {
                JointKind::Prismatic => {
                    let skirt = j.other.is_none() && t.pistons.iter().any(|p| p.body == j.body);
                    let part = match (skirt, friction.skirt) {
                        (true, None) => continue,
                        (true, Some(model)) => f.bind(model, mechanism, bore, k, None)?,
                        (false, _) => models::coulomb(k, friction.slide_friction_coefficient),
                    };
                    names.push(if skirt { "skirt" } else { j.name }.to_string());
                    parts.push(part);
                }
                JointKind::Revolute(b) => {
                    let model = friction
                        .joint_bearings
                        .iter()
                        .find(|(name, _)| name == j.name)
                        .map_or(friction.bearings, |(_, m)| *m);
                    let Some(model) = model else { continue };
                    let b = friction
                        .joint_sizes
                        .iter()
                        .find(|(name, _)| name == j.name)
                        .map_or(b, |(_, size)| size.apply(b));
                    parts.push(f.bind(model, mechanism, bore, k, Some(b))?);
                    names.push(j.name.to_string());
                }
                JointKind::GearMesh { .. } => {
                    let Some(model) = friction.gear_mesh else {
                        continue;
                    };
                    parts.push(f.bind(model, mechanism, bore, k, None)?);
                    names.push(j.name.to_string());
                }
            }
        }
        if let (Some(engine), true) = (&friction.engine, mechanism.has_cylinder()) {
            engine
                .check()
                .map_err(|(field, rule)| failed(SetupInput::Engine(field), &rule))?;
            let volume = displacement(bore, mechanism.stroke());
            if let Some(train) = &engine.valve_train {
                let part = ValveTrainLoss::new(train, bore, mechanism.top_dead_centre())
                    .map_err(|e| failed(SetupInput::Model(Attachment::ValveTrain), &e))?;
                names.push("valve_train".to_string());
                parts.push(Box::new(part));
            }
            if engine.accessories {
                names.push("accessories".to_string());
                parts.push(Box::new(models::Accessories {
                    displacement: volume,
                }));
            }
            if engine.pumping {
                names.push("pumping".to_string());
                parts.push(Box::new(models::Pumping {
                    displacement: volume,
                    engine: *engine,
                }));
            }
        }
        Ok(Self {
            names,
            parts,
            kind: match f.engine {
                Some(_) => MachineKind::Engine,
                None => MachineKind::Pump,
            },
        })
    }

    /// The components' names, in the order of [`LossBudget::evaluate`]'s output.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// Whether a step's losses depend on the steps before it (the ring films' squeeze term
    /// carries each film's thickness from step to step): then the steps must be taken in
    /// order, by one thread.
    pub fn carries_history(&self) -> bool {
        self.parts.iter().any(|p| p.carries_history())
    }

    /// The power loss of each component at one step, W, into `out` (one per name): `state` of
    /// a mechanism of `topology` under the `total` loads, with the absolute cylinder pressure
    /// `pressure` (Pa) if a gas model runs. The budget at a block of one lane
    /// ([`LossBudget::evaluate`]).
    pub fn at_state(
        &mut self,
        topology: &Topology,
        (state, total): (&State, &Loads),
        pressure: Option<f64>,
        out: &mut [f64],
    ) -> Result<(), String> {
        let states = StateBlock::of_state(topology, state);
        let totals = LoadsBlock::of_loads(topology, total);
        let pressure = pressure.map(|p| [p; LANES]);
        let at = LossLanes {
            pressure: pressure.as_ref(),
            ..LossLanes::one(&states, &totals)
        };
        let mut columns = vec![[0.0; LANES]; out.len()];
        self.evaluate(&at, &mut columns).map_err(|f| f.why)?;
        for (out, c) in out.iter_mut().zip(&columns) {
            *out = c[0];
        }
        Ok(())
    }

    /// The power loss of each component at the lanes `at.lanes`, W, into the same lanes of
    /// `out` (a column per name); `Err`: the first lane a component cannot be computed at and
    /// why (the first component's failure where several fail there), as if the lanes were
    /// taken one at a time: every lane before it is complete.
    pub fn evaluate(&mut self, at: &LossLanes, out: &mut [Column]) -> Result<(), LaneFailure> {
        let mut first: Option<LaneFailure> = None;
        for (part, out) in self.parts.iter_mut().zip(out.iter_mut()) {
            if let Err(f) = part.power(at, out) {
                if first.as_ref().is_none_or(|e| f.lane < e.lane) {
                    first = Some(f);
                }
            }
        }
        first.map_or(Ok(()), Err)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A model giving its lane's index as its loss, failing at `fails` (if set).
    #[derive(Debug, Clone)]
    struct FailsAt(Option<usize>, &'static str);

    impl Loss for FailsAt {
        fn power(&mut self, at: &LossLanes, out: &mut Column) -> Result<(), LaneFailure> {
            for i in at.lanes.clone() {
                if Some(i) == self.0 {
                    let why = self.1.to_string();
                    return Err(LaneFailure { lane: i, why });
                }
                out[i] = i as f64;
            }
            Ok(())
        }
    }

    fn budget(parts: &[FailsAt]) -> LossBudget {
        LossBudget {
            names: (0..parts.len()).map(|k| k.to_string()).collect(),
            parts: parts
                .iter()
                .map(|p| Box::new(p.clone()) as Box<dyn Loss>)
                .collect(),
            kind: MachineKind::Pump,
        }
    }

    /// The budget over a block fails where taking its lanes one at a time would: at the first
    /// lane any component fails at, naming the first component failing there.
    #[test]
    fn a_block_fails_at_its_first_failing_lane_and_component() {
        let t = cardan_mechanism::Topology {
            bodies: Vec::new(),
            joints: Vec::new(),
            pistons: Vec::new(),
            crankshaft: 0,
            extras: Vec::new(),
        };
        let (states, total) = (StateBlock::for_topology(&t), LoadsBlock::for_topology(&t));
        let at = LossLanes {
            lanes: 0..LANES,
            ..LossLanes::one(&states, &total)
        };
        type Failure = Option<(usize, &'static str)>;
        let cases: [(&[FailsAt], Failure); 4] = [
            (&[FailsAt(None, "a"), FailsAt(None, "b")], None),
            (
                &[FailsAt(Some(20), "a"), FailsAt(Some(9), "b")],
                Some((9, "b")),
            ),
            (
                &[FailsAt(Some(9), "a"), FailsAt(Some(20), "b")],
                Some((9, "a")),
            ),
            (
                &[FailsAt(Some(9), "a"), FailsAt(Some(9), "b")],
                Some((9, "a")),
            ),
        ];
        for (parts, want) in cases {
            let mut out = vec![[f64::NAN; LANES]; parts.len()];
            let got = budget(parts).evaluate(&at, &mut out);
            let complete = match (got, want) {
                (Ok(()), None) => LANES,
                (Err(f), Some((lane, why))) => {
                    assert_eq!((f.lane, f.why.as_str()), (lane, why));
                    lane
                }
                (got, want) => panic!("{got:?}, want {want:?}"),
            };
            for c in &out {
                assert!((0..complete).all(|i| c[i] == i as f64));
            }
        }
    }
}
