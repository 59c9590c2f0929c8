//! Cylinder gas: pressure and piston force over the crank angle, on the volume curve of any
//! mechanism.
//!
//! A model sees the machine only through its [`Chamber`]: the cylinder's size and V(θ), dV/dθ
//! as a function of crank angle. It never needs to know which mechanism moves the piston, nor
//! how many pistons share the chamber (the opposed-piston layout of Nunes 2017 has two and no
//! head). Pressures are absolute, in Pa; the force on each piston is along the cylinder axis,
//! positive towards the crankshaft, in N.

pub mod closed_cycle;
pub mod compressor;
pub mod cylinder;
pub mod karhula;

pub use closed_cycle::ClosedCycle;
pub use compressor::Compressor;
pub use cylinder::{Chamber, Cylinder, PistonVolume, Volume};
pub use karhula::{EngineReading, KarhulaEngine, KarhulaPump, Polytropic};

/// The gas over one run of crank angles.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct GasCycle {
    /// Absolute cylinder pressure at each requested crank angle, Pa.
    pub pressure: Vec<f64>,
    /// Gas force on each piston along the cylinder axis, towards the crankshaft, at each
    /// requested crank angle, N.
    pub piston_force: Vec<f64>,
    /// Results of the model per cycle (e.g. `imep` in Pa, `volumetric_efficiency` as a
    /// fraction).
    pub metrics: Vec<GasMetric>,
}

impl GasCycle {
    /// The value of the metric `name`, if the model gave it.
    pub fn metric(&self, name: &str) -> Option<f64> {
        self.metrics
            .iter()
            .find(|m| m.name == name)
            .map(|m| m.value)
    }
}

/// One result of a gas model per cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GasMetric {
    /// Name, as written to summary.json.
    pub name: &'static str,
    /// SI unit ("1" for fractions).
    pub unit: &'static str,
    pub value: f64,
}

/// A gas model: what the gas does to the pistons over the crank angle.
pub trait GasModel: Sync {
    /// The model made ready for `chamber` when the crank turns at the mean speed `speed`
    /// (rad/s, used by speed-dependent models: heat transfer, timing, mass flow): the work done
    /// once per cycle (the closed cycle's integration, the compressor's periodic steady state)
    /// is done here, so that the gas at any crank angle is then a cheap look-up.
    fn prepare<'a>(
        &'a self,
        chamber: Chamber<'a>,
        speed: f64,
    ) -> Result<Box<dyn PreparedGas + 'a>, GasError>;

    /// The gas at the crank angles `angles` (rad, increasing, any span).
    fn cycle(&self, chamber: &Chamber, speed: f64, angles: &[f64]) -> Result<GasCycle, GasError> {
        let gas = self.prepare(*chamber, speed)?;
        let mut cycle = GasCycle {
            metrics: gas.metrics(),
            ..GasCycle::default()
        };
        for &theta in angles {
            let (p, f) = gas.at(theta);
            cycle.pressure.push(p);
            cycle.piston_force.push(f);
        }
        Ok(cycle)
    }
}

/// A gas model ready for one chamber and speed.
pub trait PreparedGas: Sync {
    /// Absolute cylinder pressure (Pa) and the gas force on each piston along the cylinder
    /// axis, towards the crankshaft (N), at crank angle `theta` (rad).
    fn at(&self, theta: f64) -> (f64, f64);

    /// [`PreparedGas::at`] over the lanes of a block of steps at once: the crank angles
    /// `angle` (rad) and the first piston's position `position` there (m, as the mechanism
    /// filled the block) in, the pressure (Pa) and the force on each piston (N) out, for the
    /// lanes of the shortest slice. A model whose gas at a step is a function of the step's
    /// chamber volume and angle alone takes the volume from the position
    /// ([`Chamber::piston`]): lane by lane the bits of [`PreparedGas::at`] at a position with
    /// the bits of [`cardan_mechanism::Mechanism::piston_position`]'s. Returns false, writing
    /// nothing, where it does not (the model needs the volume at other angles, or the chamber
    /// is not a function of one piston's position): then `at` serves each lane.
    fn lanes(
        &self,
        _angle: &[f64],
        _position: &[f64],
        _pressure: &mut [f64],
        _force: &mut [f64],
    ) -> bool {
        false
    }

    /// The model's results per cycle.
    fn metrics(&self) -> Vec<GasMetric>;
}

/// An impossible gas input: the field, its value and the rule it breaks.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{field} = {value}: {rule}")]
pub struct GasError {
    pub field: &'static str,
    pub value: f64,
    pub rule: &'static str,
}

pub(crate) fn require(
    field: &'static str,
    value: f64,
    ok: bool,
    rule: &'static str,
) -> Result<f64, GasError> {
    if ok && value.is_finite() {
        Ok(value)
    } else {
        Err(GasError { field, value, rule })
    }
}
