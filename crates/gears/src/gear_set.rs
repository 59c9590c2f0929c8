//! One call per crank-angle step: a gear set (geometry, face width, materials, accuracy,
//! lubricant) evaluated for the tangential tooth load and the speeds of that step.

use crate::agma::factors::{dynamic_factor, DynamicFactor, Quality};
use crate::agma::{GearSetRating, Rating};
use crate::buckingham::{BuckinghamPair, DynamicLoad};
use crate::error::{positive, require, GearError};
use crate::geometry::GearPair;
use crate::mesh_loss::{mesh_loss, Lubricant, MeshGeometry, MeshLoss, MeshSpeeds, Reading};

/// A gear set ready for per-step evaluation.
#[derive(Debug, Clone, PartialEq)]
pub struct GearSet {
    /// Validated pair geometry.
    pub pair: GearPair,
    /// Face width `b` \[m\].
    pub face_width: f64,
    /// Accuracy grade for the AGMA dynamic factor.
    pub quality: Quality,
    /// AGMA rating data (materials, factors, I, J).
    pub rating: GearSetRating,
    /// Buckingham data (radii, error, moduli, tooth form).
    pub buckingham: BuckinghamPair,
    /// Lubricant for the mesh loss.
    pub lubricant: Lubricant,
    /// Mesh-loss reading; `None`: no mesh loss computed (a caller that computes it itself).
    pub loss_reading: Option<Reading>,
}

/// Inputs of one step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshStep {
    /// Tangential tooth load `Ft` \[N\] (sign = direction; magnitudes are rated).
    pub tangential_load: f64,
    /// Pitch-line velocity of the mesh \[m/s\] (cardan gear: `2 ω e`, Karhula A8.1.7).
    pub pitch_line_velocity: f64,
    /// Angular speeds of pinion and carrier.
    pub speeds: MeshSpeeds,
}

/// Results of one step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepResult {
    /// Buckingham dynamic tooth load chain (Karhula A8.1.1–14).
    pub dynamic: DynamicLoad,
    /// AGMA dynamic factor at this pitch-line velocity.
    pub kv: DynamicFactor,
    /// AGMA stresses and safety factors at `|Ft|` (infinite safety factors at zero load).
    pub rating: Rating,
    /// Anderson & Loewenthal mesh loss (`None` without a loss reading).
    pub loss: Option<MeshLoss>,
}

impl GearSet {
    /// Evaluates one step. The AGMA rating uses `Wt = |Ft|` with `Kv`; the Buckingham load is
    /// an independent estimate of the dynamic tooth load (the two are alternatives, not
    /// factors of each other).
    pub fn evaluate(&self, step: &MeshStep) -> Result<StepResult, GearError> {
        let kv = self.dynamic_factor(step)?;
        let v = step.pitch_line_velocity.abs();
        let wt = step.tangential_load.abs();
        let dynamic = self.buckingham.dynamic_load(wt, v)?;
        let rating = self.rating.rate(wt, kv.kv, self.face_width)?;
        let loss = match self.loss_reading {
            Some(reading) => Some(mesh_loss(
                &MeshGeometry::from_pair(&self.pair, self.face_width)?,
                &self.lubricant,
                &step.speeds,
                step.tangential_load,
                reading,
            )?),
            None => None,
        };
        Ok(StepResult {
            dynamic,
            kv,
            rating,
            loss,
        })
    }

    /// The AGMA dynamic factor of [`GearSet::evaluate`] at `step`, with its checks of the
    /// step, alone: for a caller that rates another load than the step's tangential load.
    pub fn dynamic_factor(&self, step: &MeshStep) -> Result<DynamicFactor, GearError> {
        self.check_step(step)?;
        dynamic_factor(self.quality, step.pitch_line_velocity.abs())
    }

    /// Whether [`GearSet::check_step`] passes a step of tangential load `tangential_load`
    /// \[N\] at the pitch-line velocity `pitch_line_velocity` \[m/s\]: its conditions as one
    /// test, for a caller that checks a block of steps at once.
    #[inline(always)]
    pub fn takes_step(&self, tangential_load: f64, pitch_line_velocity: f64) -> bool {
        let v = pitch_line_velocity.abs();
        (self.face_width.is_finite() && self.face_width > 0.0)
            && (v.is_finite() && (0.0..=crate::MAX_PITCH_LINE_VELOCITY).contains(&v))
            && tangential_load.is_finite()
    }

    /// The checks of [`GearSet::evaluate`] before the dynamic factor: the face width and the
    /// step's load.
    pub fn check_step(&self, step: &MeshStep) -> Result<(), GearError> {
        positive("face_width", self.face_width)?;
        // A solved motion's speed is known only at its steps (case files check a prescribed
        // one's at validation: one rule with the gear file's).
        crate::check_pitch_line_velocity(step.pitch_line_velocity.abs())?;
        require(
            step.tangential_load.is_finite(),
            "tangential_load",
            "must be finite",
            step.tangential_load,
        )
    }
}
