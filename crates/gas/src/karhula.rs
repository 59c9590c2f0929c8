//! The polytropic pump and the approximate four-stroke engine of Karhula (2008), appendix 6.1.1
//! and chapter 6.2.
//!
//! Strokes are counted from the top dead centre at θ = 90° (cylinder on the +y axis), over a
//! 720° cycle (ch. 6.2): pump: intake 90-270°, compression 270-450°, intake 450-630°,
//! compression 630-810°; engine: intake 90-270°, compression 270-450°, power 450-630°,
//! exhaust 630-810°.
//!
//! Readings (the thesis is terse):
//! - Pressures are absolute and the piston force is p·A_pis on the closed strokes and zero on
//!   the open ones (A6.2.1.1-2, A6.2.1.13-14): there is no crankcase back pressure. With this
//!   reading the thesis's peak compression torques (684 / 576 N·m) are reproduced to 0.6 %;
//!   a gauge-pressure force would give 4 % less.
//! - The pump's valves stay closed on the compression strokes (zero delivery, the thesis's
//!   worst case); the polytropic starts from the filled cylinder, p_atm·(C_fill·V_unc)^n (A6.1.1.11).
//! - Engine: the compression stroke carries the polytropic pressure, the power stroke the
//!   combustion pressure p_comb(θ) = p_comb,max/p_pol,max · p_pol(θ − δ) (A6.1.1.13). Integrating
//!   this gives 2524 J per cycle for the thesis's slider-crank (δ = 10°), not the thesis's
//!   combustion work (about 1460 J; 1267 J for the cardan gear). The thesis's work columns
//!   follow instead if the scaled, shifted pressure acts on both the compression and the power
//!   strokes: with δ = 9.5° that gives 1470 J and 1274 J (−13.3 %, thesis −13 %) while keeping
//!   its peak torques within 2 %. That cannot be a physical cycle (combustion pressure during
//!   compression), so [`EngineReading::Direct`] is the default and [`EngineReading::Thesis`]
//!   reproduces the thesis's work, output torque and efficiency columns.

use crate::{require, Chamber, Cylinder, GasError, GasMetric, GasModel, PistonVolume, PreparedGas};
use cardan_mechanism::{vectorised, LANES};
use cardan_numeric::{powf_lane, powf_lanes};
use std::f64::consts::PI;

/// Which half-turn of the 720° cycle θ falls in: 0 = the stroke after the opening TDC.
#[inline(always)]
fn stroke(chamber: &Chamber, theta: f64) -> usize {
    (chamber.cycle_angle(theta) / PI) as usize % 4
}

/// The polytropic compression of A6.1.1.11: p(V) = p_atm·(C_fill·V_unc)^n / V^n.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Polytropic {
    /// Polytropic exponent n (1.3-1.4 for air, ch. 10).
    pub exponent: f64,
    /// Filling factor C_fill: the intake charge as a fraction of V_unc at ambient pressure (1.0-1.1).
    pub filling: f64,
    /// Ambient (intake) pressure p_atm, Pa.
    pub ambient_pressure: f64,
}

impl Polytropic {
    pub fn new(exponent: f64, filling: f64, ambient_pressure: f64) -> Result<Self, GasError> {
        require(
            "polytropic_exponent",
            exponent,
            exponent > 1.0,
            "must be greater than 1 (1 is isothermal, below is not a compression)",
        )?;
        require("filling", filling, filling > 0.0, "must be positive")?;
        require(
            "ambient_pressure",
            ambient_pressure,
            ambient_pressure > 0.0,
            "must be positive",
        )?;
        Ok(Self {
            exponent,
            filling,
            ambient_pressure,
        })
    }

    /// Absolute pressure at volume `v`, Pa (A6.1.1.11). The power is
    /// [`cardan_numeric::powf_lane`] (within one ulp of `powf`): the bits of a lane of the
    /// pump's block path ([`KarhulaPump`]), which takes its powers all at once.
    pub fn pressure(&self, cylinder: &Cylinder, v: f64) -> f64 {
        self.ambient_pressure * powf_lane(self.filling * cylinder.max_volume() / v, self.exponent)
    }

    /// Maximum polytropic pressure, at the clearance volume (A6.1.1.6), Pa.
    pub fn max_pressure(&self, cylinder: &Cylinder) -> f64 {
        self.pressure(cylinder, cylinder.clearance_volume)
    }

    /// Maximum isothermal pressure p_atm·V_unc/V_comp (A6.1.1.4), Pa.
    pub fn isothermal_max_pressure(&self, cylinder: &Cylinder) -> f64 {
        self.ambient_pressure * cylinder.compression_ratio()
    }
}

impl Polytropic {
    /// The polytropic needs a clearance volume.
    fn check(&self, chamber: &Chamber) -> Result<(), GasError> {
        let cylinder = &chamber.cylinder;
        require(
            "compression_ratio",
            cylinder.compression_ratio(),
            cylinder.clearance_volume > 0.0,
            "must be finite: the polytropic pressure needs a clearance volume",
        )?;
        Ok(())
    }
}

/// A Karhula model on its chamber: `closed(stroke, θ)` gives the pressure on the closed
/// strokes, where the force is p·A_pis (A6.2.1.1, A6.2.1.13); the open strokes are at ambient
/// pressure and carry no force. So the pressure it reports is not force / A_pis on the open
/// strokes: a pressure trace fed the reported pressure adds p_amb·A_pis there (docs/results.md).
struct ClosedStrokes<'a, F> {
    chamber: Chamber<'a>,
    ambient: f64,
    closed: F,
}

impl<F: Fn(&Chamber, usize, f64) -> Option<f64> + Sync> PreparedGas for ClosedStrokes<'_, F> {
    fn at(&self, theta: f64) -> (f64, f64) {
        match (self.closed)(&self.chamber, stroke(&self.chamber, theta), theta) {
            Some(p) => (p, p * self.chamber.cylinder.area),
            None => (self.ambient, 0.0),
        }
    }

    fn metrics(&self) -> Vec<GasMetric> {
        Vec::new()
    }
}

/// Air pump with the valves closed on the compression strokes (Karhula ch. 6.2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KarhulaPump {
    pub gas: Polytropic,
}

impl KarhulaPump {
    /// Whether the valves are closed on `stroke` (the compression strokes).
    #[inline(always)]
    fn closed(stroke: usize) -> bool {
        matches!(stroke, 1 | 3)
    }
}

impl GasModel for KarhulaPump {
    fn prepare<'a>(
        &'a self,
        chamber: Chamber<'a>,
        _speed: f64,
    ) -> Result<Box<dyn PreparedGas + 'a>, GasError> {
        self.gas.check(&chamber)?;
        Ok(Box::new(PreparedPump {
            chamber,
            gas: self.gas,
        }))
    }
}

/// The pump on its chamber: the polytropic pressure (A6.1.1.11) on the compression strokes,
/// where the force is p·A_pis (A6.2.1.1); ambient pressure and no force on the intake strokes
/// (as [`ClosedStrokes`]). A function of the chamber volume and the stroke alone, so that a
/// block's steps take the volume from their piston positions ([`PreparedGas::lanes`]).
struct PreparedPump<'a> {
    chamber: Chamber<'a>,
    gas: Polytropic,
}

impl PreparedGas for PreparedPump<'_> {
    fn at(&self, theta: f64) -> (f64, f64) {
        if KarhulaPump::closed(stroke(&self.chamber, theta)) {
            let p =
                (self.gas).pressure(&self.chamber.cylinder, (self.chamber.volume)(theta).volume);
            (p, p * self.chamber.cylinder.area)
        } else {
            (self.gas.ambient_pressure, 0.0)
        }
    }

    fn lanes(
        &self,
        angle: &[f64],
        position: &[f64],
        pressure: &mut [f64],
        force: &mut [f64],
    ) -> bool {
        let Some(piston) = self.chamber.piston else {
            return false;
        };
        for (((a, x), p), f) in angle
            .chunks(LANES)
            .zip(position.chunks(LANES))
            .zip(pressure.chunks_mut(LANES))
            .zip(force.chunks_mut(LANES))
        {
            pump_lanes(self, &piston, a, x, p, f);
        }
        true
    }

    fn metrics(&self) -> Vec<GasMetric> {
        Vec::new()
    }
}

vectorised! {
    /// [`PreparedPump::at`] over at most [`LANES`] lanes, the volume from the piston's position
    /// (`piston`), the powers of the closed strokes' lanes all at once
    /// ([`cardan_numeric::powf_lanes`], lane by lane the bits of [`Polytropic::pressure`]'s
    /// `powf_lane`): the pressure of A6.1.1.11 and the force p·A_pis of A6.2.1.1.
    fn pump_lanes(
        pump: &PreparedPump,
        piston: &PistonVolume,
        angle: &[f64],
        position: &[f64],
        pressure: &mut [f64],
        force: &mut [f64],
    ) {
        let n = angle.len().min(position.len()).min(pressure.len()).min(force.len()).min(LANES);
        let (gas, cylinder) = (&pump.gas, &pump.chamber.cylinder);
        let mut closed = [false; LANES];
        // The closed lanes lie between `first` and `end` (a block spans one or two strokes:
        // the intake strokes' lanes outside take no power).
        let (mut first, mut end) = (n, 0);
        for (i, (c, &theta)) in closed.iter_mut().zip(&angle[..n]).enumerate() {
            *c = KarhulaPump::closed(stroke(&pump.chamber, theta));
            if *c {
                first = first.min(i);
                end = i + 1;
            }
        }
        let mut base = [0.0; LANES];
        let mut power = [0.0; LANES];
        if first < end {
            let charge = gas.filling * cylinder.max_volume();
            for (b, &x) in base[first..end].iter_mut().zip(&position[first..end]) {
                *b = charge / piston.volume(x);
            }
            powf_lanes(&base[first..end], gas.exponent, &mut power[first..end]);
        }
        let (ambient, area) = (gas.ambient_pressure, cylinder.area);
        for i in 0..n {
            let p = ambient * power[i];
            (pressure[i], force[i]) = if closed[i] { (p, p * area) } else { (ambient, 0.0) };
        }
    }
}

/// Four-stroke engine with the combustion pressure of A6.1.1.13.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KarhulaEngine {
    pub gas: Polytropic,
    pub reading: EngineReading,
    /// Peak combustion pressure p_comb,max, Pa (7-17 MPa, ch. 10).
    pub peak_pressure: f64,
    /// Crank angle of the pressure peak after top dead centre, rad (8-10°, A6.1.1.13).
    pub combustion_delay: f64,
}

/// Which pressure the engine's compression stroke carries (module documentation).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum EngineReading {
    /// The polytropic compression pressure: the physical cycle.
    #[default]
    Direct,
    /// The scaled, shifted combustion pressure, as the thesis's work columns imply.
    Thesis,
}

impl KarhulaEngine {
    /// The engine in the direct reading ([`EngineReading::Direct`]).
    pub fn new(
        gas: Polytropic,
        peak_pressure: f64,
        combustion_delay: f64,
    ) -> Result<Self, GasError> {
        require(
            "peak_pressure",
            peak_pressure,
            peak_pressure > gas.ambient_pressure,
            "must exceed ambient_pressure",
        )?;
        require(
            "combustion_delay",
            combustion_delay,
            (0.0..PI).contains(&combustion_delay),
            "must be from 0 to 180 degrees",
        )?;
        Ok(Self {
            gas,
            reading: EngineReading::Direct,
            peak_pressure,
            combustion_delay,
        })
    }

    /// p_comb(θ) = p_comb,max/p_pol,max · p_pol(V(θ − δ)) (A6.1.1.13-14), Pa.
    pub fn combustion_pressure(&self, chamber: &Chamber, theta: f64) -> f64 {
        let c = &chamber.cylinder;
        let scale = self.peak_pressure / self.gas.max_pressure(c);
        scale
            * self
                .gas
                .pressure(c, (chamber.volume)(theta - self.combustion_delay).volume)
    }
}

impl GasModel for KarhulaEngine {
    fn prepare<'a>(
        &'a self,
        chamber: Chamber<'a>,
        _speed: f64,
    ) -> Result<Box<dyn PreparedGas + 'a>, GasError> {
        self.gas.check(&chamber)?;
        Ok(Box::new(ClosedStrokes {
            chamber,
            ambient: self.gas.ambient_pressure,
            closed: move |ch: &Chamber, stroke, theta| match (stroke, self.reading) {
                (1, EngineReading::Direct) => {
                    Some(self.gas.pressure(&ch.cylinder, (ch.volume)(theta).volume))
                }
                (1, EngineReading::Thesis) | (2, _) => Some(self.combustion_pressure(ch, theta)),
                _ => None,
            },
        }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strokes_start_at_top_dead_centre() {
        let volume = |_: f64| crate::Volume {
            volume: 1.0,
            rate: 0.0,
        };
        let chamber = Chamber {
            cylinder: Cylinder::with_compression_ratio(0.1, 1e-3, 10.0).unwrap(),
            tdc_angle: std::f64::consts::FRAC_PI_2,
            volume: &volume,
            piston: None,
        };
        let stroke = |d: f64| stroke(&chamber, d.to_radians());
        assert_eq!(stroke(90.0), 0);
        assert_eq!(stroke(269.9), 0);
        assert_eq!(stroke(270.1), 1);
        assert_eq!(stroke(450.1), 2);
        assert_eq!(stroke(630.1), 3);
        assert_eq!(stroke(809.9), 3);
        assert_eq!(stroke(810.1), 0);
        assert_eq!(stroke(-89.9), 3);
    }

    #[test]
    fn bad_gas_inputs_are_refused() {
        assert!(Cylinder::with_compression_ratio(0.1, 1e-3, 1.0).is_err());
        assert!(Polytropic::new(1.0, 1.0, 1e5).is_err());
        assert!(Polytropic::new(1.4, 1.0, -1e5).is_err());
        assert!(Polytropic::new(f64::NAN, 1.0, 1e5).is_err());
        let gas = Polytropic::new(1.4, 1.07, 101_325.0).unwrap();
        assert!(KarhulaEngine::new(gas, 5e4, 0.17).is_err());
        assert!(KarhulaEngine::new(gas, 12e6, -0.1).is_err());
    }
}
