//! Single-stage reciprocating air compressor with clearance and ideal valves.
//!
//! Sources (equation numbers differ between editions, so formulas are cited by section):
//! - \[EM\] Eastop & McConkey, *Applied Thermodynamics for Engineering Technologists*, 5th ed.,
//!   ch. 9 "Positive displacement machines": the indicator diagram with clearance, volumetric
//!   efficiency, indicated work and power.
//! - \[RM\] Rogers & Mayhew, *Engineering Thermodynamics: Work and Heat Transfer*, 4th ed.,
//!   ch. 16 (reciprocating compressors): the same cycle and the re-expansion of the clearance gas.
//! - \[CB\] Çengel & Boles, *Thermodynamics: An Engineering Approach*: ch. 4 (polytropic boundary
//!   work), ch. 5 (unsteady flow: charging a volume), ch. 7 "Minimizing the compressor work"
//!   (polytropic and isothermal compression work).
//!
//! The cycle, numbered as in \[EM\] and \[RM\]: 1 bottom dead centre, start of compression (V_1 =
//! V_max, p_s); 2 the discharge valve opens (p_d); 3 top dead centre, end of discharge (V_3 =
//! V_c); 4 the suction valve opens after the clearance gas re-expanded (p_s). The valves are
//! ideal: lossless, instantaneous, opening at exactly p_s and p_d. The crankcase is at suction
//! pressure, so each piston feels F = (p − p_s)·A_pis, positive towards the crankshaft.

use crate::{require, Chamber, Cylinder, GasError, GasMetric, GasModel, PreparedGas, Volume};
use std::f64::consts::PI;

/// Specific gas constant of dry air, J/(kg·K): R̄/M = 8.314 46/0.028 964 (ISO 2533 standard
/// atmosphere, 287.052 87).
pub const AIR_GAS_CONSTANT: f64 = 287.05;

/// The periodic steady state is reached when a cycle's mass balance (delivered − inducted)
/// is below this fraction of the inducted mass. The residual mass then contracts by V_c/V_2
/// per cycle, so its remaining error is the balance times V_c/(V_2 − V_c).
pub const STEADY_TOLERANCE: f64 = 1e-12;

/// Most cycles iterated before giving up (only reached when the delivery is nearly zero).
pub const MAX_CYCLES: usize = 1_000_000;

/// Crank-angle steps of the numerical ∮ p dV over one revolution (midpoint rule).
pub const WORK_STEPS: usize = 36_000;

/// A reciprocating compressor: suction and delivery states and the polytropic exponents.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Compressor {
    /// Suction (inlet, and crankcase) pressure p_s, Pa absolute.
    pub suction_pressure: f64,
    /// Suction temperature T_s, K.
    pub suction_temperature: f64,
    /// Delivery (receiver) pressure p_d, Pa absolute; above `suction_pressure`.
    pub delivery_pressure: f64,
    /// Polytropic exponent n_c of the compression 1-2 (1 isothermal, 1.4 isentropic air).
    pub compression_exponent: f64,
    /// Polytropic exponent n_e of the re-expansion 3-4 of the clearance gas.
    pub expansion_exponent: f64,
    /// Specific gas constant R, J/(kg·K) ([`AIR_GAS_CONSTANT`] for air).
    pub gas_constant: f64,
}

/// One state of the indicator diagram.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StatePoint {
    /// Chamber volume, m³.
    pub volume: f64,
    /// Absolute pressure, Pa.
    pub pressure: f64,
    /// Gas temperature, K.
    pub temperature: f64,
    /// Gas mass in the chamber, kg.
    pub mass: f64,
}

/// One cycle from top dead centre to top dead centre: re-expansion 3-4 of the residual left by
/// the previous cycle, suction 4-1, compression 1-2, discharge 2-3.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IndicatorDiagram {
    /// Points 1, 2, 3, 4 (index 0-3). Point 4 holds the incoming residual; point 3 the residual
    /// this cycle leaves for the next.
    pub points: [StatePoint; 4],
    /// Mass drawn in through the suction valve, kg.
    pub inducted_mass: f64,
    /// Mass pushed out through the discharge valve, m_2 − m_3, kg.
    pub delivered_mass: f64,
}

impl IndicatorDiagram {
    /// Delivered minus inducted mass, kg: zero in the periodic steady state.
    pub fn mass_balance(&self) -> f64 {
        self.delivered_mass - self.inducted_mass
    }

    /// η_v = (V_1 − V_4)/(V_1 − V_3) = 1 − (V_c/V_s)·[(p_d/p_s)^(1/n_e) − 1] (\[EM\] ch. 9,
    /// volumetric efficiency; \[RM\] ch. 16): the induced volume at suction state per swept volume.
    pub fn volumetric_efficiency(&self) -> f64 {
        let v = self.points.map(|p| p.volume);
        (v[0] - v[3]) / (v[0] - v[2])
    }
}

/// n/(n − 1)·[r^((n−1)/n) − 1], and its isothermal limit ln r at n = 1 (\[CB\] ch. 7): written
/// as ln r·(e^x − 1)/x with x = (n − 1)/n·ln r, so n → 1 loses no digits and n = 1 divides by
/// nothing.
fn polytropic_factor(n: f64, r: f64) -> f64 {
    let x = (n - 1.0) / n * r.ln();
    if x == 0.0 {
        r.ln()
    } else {
        r.ln() * x.exp_m1() / x
    }
}

impl Compressor {
    /// A compressor with checked inputs: pressures, temperature and gas constant positive and
    /// finite, delivery above suction, exponents at least 1.
    pub fn new(
        suction_pressure: f64,
        suction_temperature: f64,
        delivery_pressure: f64,
        compression_exponent: f64,
        expansion_exponent: f64,
        gas_constant: f64,
    ) -> Result<Self, GasError> {
        let c = Self {
            suction_pressure,
            suction_temperature,
            delivery_pressure,
            compression_exponent,
            expansion_exponent,
            gas_constant,
        };
        c.check()?;
        Ok(c)
    }

    /// Air ([`AIR_GAS_CONSTANT`]) with one exponent n for compression and re-expansion.
    pub fn air(
        suction_pressure: f64,
        suction_temperature: f64,
        delivery_pressure: f64,
        exponent: f64,
    ) -> Result<Self, GasError> {
        Self::new(
            suction_pressure,
            suction_temperature,
            delivery_pressure,
            exponent,
            exponent,
            AIR_GAS_CONSTANT,
        )
    }

    /// The rules of [`Compressor::new`], checked again by every computation (the fields are
    /// public).
    fn check(&self) -> Result<(), GasError> {
        let positive = |field, v: f64| require(field, v, v > 0.0, "must be positive and finite");
        positive("suction_pressure", self.suction_pressure)?;
        positive("suction_temperature", self.suction_temperature)?;
        positive("delivery_pressure", self.delivery_pressure)?;
        positive("gas_constant", self.gas_constant)?;
        require(
            "delivery_pressure",
            self.delivery_pressure,
            self.delivery_pressure > self.suction_pressure,
            "must be above suction_pressure (delivery below suction: nothing to compress)",
        )?;
        let exponent =
            |field, n: f64| require(field, n, n >= 1.0, "must be at least 1 (1 is isothermal)");
        exponent("compression_exponent", self.compression_exponent)?;
        exponent("expansion_exponent", self.expansion_exponent)?;
        Ok(())
    }

    /// Pressure ratio r = p_d/p_s.
    pub fn pressure_ratio(&self) -> f64 {
        self.delivery_pressure / self.suction_pressure
    }

    /// V_1..V_4, m³: V_1 = V_max, V_2 = V_1·r^(−1/n_c), V_3 = V_c, V_4 = V_c·r^(1/n_e)
    /// (p·V^n = const, \[CB\] ch. 4; \[EM\] ch. 9).
    fn volumes(&self, cylinder: &Cylinder) -> [f64; 4] {
        let r = self.pressure_ratio();
        let (v1, vc) = (cylinder.max_volume(), cylinder.clearance_volume);
        let v2 = v1 * r.powf(-1.0 / self.compression_exponent);
        [v1, v2, vc, vc * r.powf(1.0 / self.expansion_exponent)]
    }

    /// V_1..V_4 of a compressor that delivers: V_4 < V_1 and V_2 > V_3.
    fn checked_volumes(&self, cylinder: &Cylinder) -> Result<[f64; 4], GasError> {
        self.check()?;
        let (vs, vc) = (cylinder.swept_volume, cylinder.clearance_volume);
        require("swept_volume", vs, vs > 0.0, "must be positive")?;
        require("clearance_volume", vc, vc >= 0.0, "must not be negative")?;
        let v = self.volumes(cylinder);
        require(
            "delivery_pressure",
            self.delivery_pressure,
            v[3] < v[0] && v[1] > v[2],
            "is too high for this clearance: the compressor delivers nothing",
        )?;
        Ok(v)
    }

    /// Pressure on the ideal-valve indicator diagram (\[EM\] ch. 9), Pa. Compression branch
    /// (dV/dθ < 0): p = min(p_s·(V_1/V)^n_c, p_d); expansion branch (dV/dθ ≥ 0): p =
    /// max(p_d·(V_c/V)^n_e, p_s), which is p_s without clearance. Volumes outside [V_c, V_1]
    /// (round-off) stay within [p_s, p_d].
    pub fn pressure(&self, cylinder: &Cylinder, at: Volume) -> f64 {
        self.pressure_on(&self.volumes(cylinder), at)
    }

    /// [`Compressor::pressure`] with the diagram's volumes V_1..V_4 already known.
    fn pressure_on(&self, volumes: &[f64; 4], at: Volume) -> f64 {
        let (ps, pd) = (self.suction_pressure, self.delivery_pressure);
        let [v1, v2, vc, v4] = *volumes;
        let v = at.volume;
        let p = if at.rate < 0.0 {
            if v <= v2 {
                pd
            } else {
                ps * (v1 / v).powf(self.compression_exponent)
            }
        } else if v >= v4 {
            ps
        } else {
            pd * (vc / v).powf(self.expansion_exponent)
        };
        p.min(pd).max(ps)
    }

    /// One cycle that starts from a residual at temperature `t_res` filling V_c at p_d.
    ///
    /// Suction 4-1 at constant p_s through an adiabatic valve (first law for a control volume,
    /// \[CB\] ch. 5): dU = h_s·dm − p_s·dV with U = c_v·p_s·V/R and h_s = c_p·T_s gives
    /// c_p·T_s·dm = (c_v/R + 1)·p_s·dV, so dm = p_s·dV/(R·T_s), whatever the residual's
    /// temperature: m_in = p_s·(V_1 − V_4)/(R·T_s). The mixture then has T_1 from
    /// p_s·V_1 = (m_res + m_in)·R·T_1; the polytropic 1-2 gives T_2 = T_1·r^((n_c−1)/n_c)
    /// (\[CB\] ch. 7), the discharge temperature T_d; the residual left in V_c at p_d, T_d is
    /// m_3 = p_d·V_c/(R·T_d), and it re-expands to T_4 = T_d·r^(−(n_e−1)/n_e).
    fn one_cycle(&self, v: &[f64; 4], t_res: f64) -> IndicatorDiagram {
        let (ps, pd, r_gas) = (
            self.suction_pressure,
            self.delivery_pressure,
            self.gas_constant,
        );
        let r = self.pressure_ratio();
        let m_res = pd * v[2] / (r_gas * t_res);
        let m_in = ps * (v[0] - v[3]) / (r_gas * self.suction_temperature);
        let t1 = ps * v[0] / (r_gas * (m_res + m_in));
        let t2 = t1 * r.powf((self.compression_exponent - 1.0) / self.compression_exponent);
        let m3 = pd * v[2] / (r_gas * t2);
        let t4 = t_res * r.powf(-(self.expansion_exponent - 1.0) / self.expansion_exponent);
        let point = |volume, pressure, temperature, mass| StatePoint {
            volume,
            pressure,
            temperature,
            mass,
        };
        IndicatorDiagram {
            points: [
                point(v[0], ps, t1, m_res + m_in),
                point(v[1], pd, t2, m_res + m_in),
                point(v[2], pd, t2, m3),
                point(v[3], ps, t4, m_res),
            ],
            inducted_mass: m_in,
            delivered_mass: m_res + m_in - m3,
        }
    }

    /// The cycles from a cold start (the clearance gas at p_d and the suction temperature),
    /// each starting from the residual of the one before; endless.
    pub fn cycles(
        &self,
        cylinder: &Cylinder,
    ) -> Result<impl Iterator<Item = IndicatorDiagram> + '_, GasError> {
        let v = self.checked_volumes(cylinder)?;
        let first = self.one_cycle(&v, self.suction_temperature);
        Ok(std::iter::successors(Some(first), move |d| {
            Some(self.one_cycle(&v, d.points[2].temperature))
        }))
    }

    /// The first cycle whose mass balance is within [`STEADY_TOLERANCE`] of the inducted mass,
    /// and how many cycles it took (1 without clearance).
    pub fn steady_state(&self, cylinder: &Cylinder) -> Result<(IndicatorDiagram, usize), GasError> {
        self.cycles(cylinder)?
            .take(MAX_CYCLES)
            .enumerate()
            .find(|(_, d)| d.mass_balance().abs() <= STEADY_TOLERANCE * d.inducted_mass)
            .map(|(k, d)| (d, k + 1))
            .ok_or(GasError {
                field: "delivery_pressure",
                value: self.delivery_pressure,
                rule: "is too close to the no-delivery limit: the cycle does not settle",
            })
    }

    /// Indicated work per cycle in closed form, J (\[EM\] ch. 9; \[RM\] ch. 16):
    /// W = n_c/(n_c−1)·p_s·V_1·[r^((n_c−1)/n_c) − 1] − n_e/(n_e−1)·p_s·V_4·[r^((n_e−1)/n_e) − 1],
    /// the ∮ V dp of the diagram (the two constant-pressure lines add nothing). At n_c = n_e = 1
    /// it is p_s·(V_1 − V_4)·ln r (\[CB\] ch. 7, isothermal compression).
    pub fn closed_form_work(&self, cylinder: &Cylinder) -> Result<f64, GasError> {
        let v = self.checked_volumes(cylinder)?;
        let (ps, r) = (self.suction_pressure, self.pressure_ratio());
        Ok(ps * v[0] * polytropic_factor(self.compression_exponent, r)
            - ps * v[3] * polytropic_factor(self.expansion_exponent, r))
    }

    /// Indicated work per revolution W = −∮ p dV on the chamber's own volume curve, from its
    /// top dead centre over 2π, by the midpoint rule in crank angle with [`WORK_STEPS`] steps, J.
    pub fn indicated_work(&self, chamber: &Chamber) -> Result<f64, GasError> {
        self.checked_volumes(&chamber.cylinder)?;
        let (c, h) = (&chamber.cylinder, 2.0 * PI / WORK_STEPS as f64);
        let at = |k: f64| (chamber.volume)(chamber.tdc_angle + h * k);
        let mut work = 0.0;
        let mut v_a = at(0.0).volume;
        for k in 0..WORK_STEPS {
            let v_b = at(k as f64 + 1.0).volume;
            work -= self.pressure(c, at(k as f64 + 0.5)) * (v_b - v_a);
            v_a = v_b;
        }
        Ok(work)
    }
}

impl GasModel for Compressor {
    /// Pressure and piston force at any crank angle; metrics of the periodic steady state,
    /// with `speed` (rad/s) scaling the mass flow and power (one cycle per revolution).
    fn prepare<'a>(
        &'a self,
        chamber: Chamber<'a>,
        speed: f64,
    ) -> Result<Box<dyn PreparedGas + 'a>, GasError> {
        let c = &chamber.cylinder;
        let (steady, _) = self.steady_state(c)?;
        // The diagram is a function of V alone, so on any volume curve that rises and falls
        // once per revolution its work is the closed form (the tests check it against
        // `indicated_work` on both mechanisms).
        let work = self.closed_form_work(c)?;
        Ok(Box::new(PreparedCompressor {
            model: self,
            volumes: self.volumes(c),
            chamber,
            steady,
            work,
            speed,
        }))
    }
}

/// The compressor at its periodic steady state on one chamber.
struct PreparedCompressor<'a> {
    model: &'a Compressor,
    chamber: Chamber<'a>,
    volumes: [f64; 4],
    steady: IndicatorDiagram,
    work: f64,
    speed: f64,
}

impl PreparedGas for PreparedCompressor<'_> {
    fn at(&self, theta: f64) -> (f64, f64) {
        let p = self
            .model
            .pressure_on(&self.volumes, (self.chamber.volume)(theta));
        (
            p,
            (p - self.model.suction_pressure) * self.chamber.cylinder.area,
        )
    }

    fn metrics(&self) -> Vec<GasMetric> {
        let cycles_per_second = self.speed / (2.0 * PI);
        let metric = |name, unit, value| GasMetric { name, unit, value };
        let steady = &self.steady;
        vec![
            metric(
                "delivered_mass_flow",
                "kg/s",
                steady.delivered_mass * cycles_per_second,
            ),
            metric("volumetric_efficiency", "1", steady.volumetric_efficiency()),
            metric("specific_energy", "J/kg", self.work / steady.delivered_mass),
            metric("indicated_power", "W", self.work * cycles_per_second),
            metric("discharge_temperature", "K", steady.points[1].temperature),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polytropic_factor_is_smooth_through_the_isothermal_limit() {
        let r: f64 = 8.0;
        assert_eq!(polytropic_factor(1.0, r), r.ln());
        // The naive n/(n−1)·(r^((n−1)/n) − 1) keeps only about 6 digits at n − 1 = 1e-10.
        let n = 1.0 + 1e-10;
        let series = r.ln() * (1.0 + 0.5 * (n - 1.0) / n * r.ln());
        assert!((polytropic_factor(n, r) / series - 1.0).abs() < 1e-15);
        let n = 1.4;
        let direct = n / (n - 1.0) * (r.powf((n - 1.0) / n) - 1.0);
        assert!((polytropic_factor(n, r) / direct - 1.0).abs() < 1e-14);
    }

    #[test]
    fn pressure_follows_the_four_lines_and_is_continuous_at_the_valve_events() {
        let c = Compressor::air(1e5, 293.15, 8e5, 1.3).unwrap();
        let cyl = Cylinder::with_clearance(0.1, 1e-3, 5e-5).unwrap();
        let [v1, v2, vc, v4] = c.volumes(&cyl);
        let p = |volume, rate| c.pressure(&cyl, Volume { volume, rate });
        assert_eq!(p(v1, -1.0), 1e5);
        assert!((p(v2 * (1.0 + 1e-12), -1.0) / 8e5 - 1.0).abs() < 1e-11);
        assert_eq!(p(0.5 * (v2 + vc), -1.0), 8e5);
        assert_eq!(p(vc, 1.0), 8e5);
        assert!((p(v4 * (1.0 - 1e-12), 1.0) / 1e5 - 1.0).abs() < 1e-11);
        assert_eq!(p(0.5 * (v4 + v1), 1.0), 1e5);
        // Round-off outside [V_c, V_1] stays within [p_s, p_d].
        assert_eq!(p(v1 * (1.0 + 1e-15), -1.0), 1e5);
        assert_eq!(p(-1e-20, -1.0), 8e5);
    }
}
