//! The single-zone closed-cycle engine model of Nunes (2017), §3.4.1, after Blair (1999):
//! a four-stroke spark-ignition cycle integrated from intake closing (IVC) to exhaust opening
//! (EVO) on the explicit finite-difference first law (eq 3.5), with Wiebe heat release
//! (eqs 2.28-2.29), Annand convection and radiation (eqs 2.30-2.40), fuel vaporisation
//! (eqs 2.41-2.42), the combustion efficiency of Blair (eq 2.56) and speed-dependent
//! combustion timing (eqs 3.1-3.2).
//!
//! References: "eq" are the thesis's equations (summarised in docs/validation/nunes-2017.md);
//! "L" lines of the thesis's OCR text; "R…" the labelled readings of that page (its section
//! "Readings of the closed-cycle model").
//!
//! Crank angles are measured from the opening top dead centre (IVO = 0, IVC = π, firing TDC
//! = 2π, EVO = 3π: Table 3.2, L1178-1181), which is [`Chamber::cycle_angle`].
//!
//! Readings (docs/validation/nunes-2017.md R5.1 lists the choices that reproduce the thesis):
//! - Explicit steps of 1° by default: the thesis's peak pressures carry that discretisation
//!   (0.1° steps lower them by 0.1-0.24 %, docs/validation/nunes-2017.md R5.1.1). Heat loss is
//!   evaluated from the state at the start of each step (docs/validation/nunes-2017.md RA).
//! - Trapped mass m_1 = p_1·V(IVC)/(R·T_1) (eq 2.4; V(IVC) = V_d + V_c at the thesis's IVC,
//!   docs/validation/nunes-2017.md R5.1.2); fuel m_f = p_1·V_d/(R·T_1)/AFR (eqs 2.5-2.6: the
//!   swept volume at ambient density, volumetric efficiency 1). There is no residual gas.
//! - Vaporisation (docs/validation/nunes-2017.md R5.1.3) adds dm = m_f·dθ/θ_vap and removes
//!   dm·h_vap over IVC → θ_0. We share the step that contains θ_0 by its overlap, so exactly
//!   m_f is vaporised whatever the step; the thesis's loop (docs/validation/nunes-2017.md RA)
//!   skips that partial step (0.5 % of the fuel vapour at 1°), which changes the pressures by
//!   less than 5·10⁻⁵.
//! - Wiebe χ_b = 0 before θ_0 and capped at χ_b(θ_0 + Δθ) = 1 − e^(−a) after it
//!   (docs/validation/nunes-2017.md R5.1.4): the fraction e^(−a) (0.7 % at a = 5) is never
//!   released.
//! - Annand (docs/validation/nunes-2017.md R5.1.5): S̄_p from one piston's stroke,
//!   [`crate::Cylinder::stroke`] = V_d/(pistons·A) (0.052 m for the thesis, not its 0.104 m
//!   sum); wall area two ends plus the liner ([`crate::Cylinder::wall_area`]); radiation on.
//! - Constant γ and R; U = p·V/(γ − 1), so c_v = R/(γ − 1) (717.6 J/(kg·K) for the thesis's
//!   R and γ, which prints c_v = 718: 0.06 % on the exhaust fraction only).
//! - Open strokes at the ambient pressure (the "ideal Otto" gas exchange, L1153, L1285): no
//!   pumping work. The pressure drops to ambient at EVO (instant blow-down) and the chamber
//!   refills at ambient pressure and temperature.
//! - The piston force is p_abs·A on every piston at every angle (docs/validation/nunes-2017.md
//!   R1: absolute pressure, confirmed by F_max; no crankcase pressure). Inertia belongs to the
//!   mechanism.
//! - Energy fractions of §5.1.1 (docs/validation/nunes-2017.md R5.1.9): the vaporisation heat
//!   counts as heat loss.

use crate::{require, Chamber, Cylinder, GasError, GasMetric, GasModel, PreparedGas};
use std::f64::consts::PI;

/// The coarsest integration step, rad (5°): the Wiebe burn of about 30° must span several
/// steps for the heat release to be resolved at all; a 360° step would integrate nothing.
pub const MAX_STEP: f64 = 5.0 * PI / 180.0;

/// At most this many integration steps from IVC to EVO.
const MAX_STEPS: f64 = 1e7;

/// The single-zone closed-cycle spark-ignition engine of Nunes (2017), §3.4.1. Every field is
/// SI; angles are from the opening top dead centre.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClosedCycle {
    /// Ambient and intake pressure p_1, Pa: the pressure at IVC and on the open strokes
    /// (Table 3.2: 101 325 Pa; pressure ratio 1, L1151).
    pub ambient_pressure: f64,
    /// Ambient and intake temperature T_1, K: the charge temperature at IVC (Table 3.2: 288.15 K).
    pub ambient_temperature: f64,
    /// Cylinder wall temperature T_wall, K (Table 3.2 / L1153: 350 K after Stone 1999).
    pub wall_temperature: f64,
    /// Gas constant R, J/(kg·K) (Table 3.2: 287.04).
    pub gas_constant: f64,
    /// Ratio of specific heats γ, constant (Table 3.2: 1.4; G_6 = (γ + 1)/(γ − 1), eq 3.7).
    pub gamma: f64,
    /// Relative air-fuel ratio λ = AFR/AFR_stoich (eq 2.55; Table 3.2: 1, stoichiometric).
    pub lambda: f64,
    /// Stoichiometric air-fuel ratio AFR_stoich, by mass (Table 3.2: 15.06).
    pub stoichiometric_air_fuel_ratio: f64,
    /// Lower heating value of the fuel QHV, J/kg (Table 3.2 "fuel heat power": 43.5 MJ/kg).
    /// Zero gives a motored engine (the fuel-energy metrics are then left out).
    pub fuel_heating_value: f64,
    /// Heat of vaporisation of the fuel h_vap, J/kg (Table 3.2: 400 kJ/kg, eq 2.42).
    pub vaporisation_heat: f64,
    /// η_cmax of Blair's combustion efficiency η_c = η_cmax·(−1.6082 + 4.6509·λ − 2.0764·λ²)
    /// (eq 2.56; 0.9, L815-827). The correlation is stated for 0.75 ≤ λ ≤ 1.2.
    pub max_combustion_efficiency: f64,
    /// Start of combustion at zero speed θ_0(0), rad from the opening TDC: θ_0 = 350.93°
    /// − 0.0004°·N (eq 3.1, N in rpm), so 350.93° = 6.12488 rad.
    pub combustion_start: f64,
    /// dθ_0/dω, s (rad per rad/s): eq 3.1's −0.0004°/rpm = −0.0004/6 s = −6.6667e-5 s, a
    /// constant ignition advance in time.
    pub combustion_start_per_speed: f64,
    /// Combustion duration at zero speed Δθ(0), rad: Δθ = 30.663° + 0.0027°·N (eq 3.2).
    pub combustion_duration: f64,
    /// dΔθ/dω, s (rad per rad/s): eq 3.2's 0.0027°/rpm = 0.0027/6 s = 4.5e-4 s.
    pub combustion_duration_per_speed: f64,
    /// Wiebe efficiency parameter a (eq 2.28; 5, L640).
    pub wiebe_a: f64,
    /// Wiebe form factor m, exponent m + 1 (eq 2.28; 2, L640).
    pub wiebe_m: f64,
    /// Annand's Nusselt coefficient a_Nu in Nu = a_Nu·Re^0.7 (eq 2.30; 0.49 for four-stroke
    /// engines, L660). Zero turns convection off.
    pub annand_a: f64,
    /// Radiation constant of C_r = c·(T⁴ − T_wall⁴)/(T − T_wall), W/(m²·K⁴) (eq 2.37;
    /// 4.25e-9). Zero turns radiation off.
    pub radiation_coefficient: f64,
    /// Intake valve closing IVC, rad from the opening TDC: the start of the closed cycle
    /// (Table 3.2: 180° = π).
    pub intake_closing: f64,
    /// Exhaust valve opening EVO, rad from the opening TDC: the end of the closed cycle
    /// (Table 3.2: 540° = 3π).
    pub exhaust_opening: f64,
    /// Integration step, rad (the thesis's 1°, docs/validation/nunes-2017.md R5.1.1). It is
    /// shortened, if needed, to fit a whole number of steps between IVC and EVO (at most
    /// 10 000 000).
    pub step: f64,
}

impl Default for ClosedCycle {
    fn default() -> Self {
        Self::nunes_2017()
    }
}

/// The closed cycle at each integration point, IVC to EVO; heat and work are cumulative
/// from IVC.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ClosedCycleTrace {
    /// Crank angle from the opening TDC, rad.
    pub angle: Vec<f64>,
    /// Chamber volume V, m³.
    pub volume: Vec<f64>,
    /// Absolute pressure p, Pa.
    pub pressure: Vec<f64>,
    /// Mean gas temperature T = p·V/(m·R) (eq 3.6), K.
    pub temperature: Vec<f64>,
    /// Gas mass m (eq 3.8), kg.
    pub mass: Vec<f64>,
    /// Mass fraction burned χ_b (eq 2.28, capped).
    pub burned_fraction: Vec<f64>,
    /// Σ δQ_R, heat released by combustion (eq 3.14), J.
    pub heat_released: Vec<f64>,
    /// Σ δQ_L, heat lost to the walls (eq 2.39), J.
    pub heat_loss: Vec<f64>,
    /// Σ δQ_vap, heat taken by the fuel vaporisation (eq 3.10), J.
    pub vaporisation_heat: Vec<f64>,
    /// Σ (p_1 + p_2)/2·(V_2 − V_1), the work of the gas (eqs 2.48, 3.4), J.
    pub work: Vec<f64>,
    /// Totals of the cycle.
    pub balance: EnergyBalance,
}

/// Energy and mass totals of one closed cycle, J or kg.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct EnergyBalance {
    /// Start of combustion θ_0 at this speed, rad from the opening TDC (eq 3.1).
    pub combustion_start: f64,
    /// Combustion duration Δθ at this speed, rad (eq 3.2).
    pub combustion_duration: f64,
    /// Combustion efficiency η_c (eq 2.56).
    pub combustion_efficiency: f64,
    /// Gas trapped at IVC m_1 (eq 2.4), kg.
    pub trapped_mass: f64,
    /// Fuel per cycle m_f (eqs 2.5-2.6), kg.
    pub fuel_mass: f64,
    /// Fuel energy m_f·QHV, J.
    pub fuel_energy: f64,
    /// Σ δQ_R, J.
    pub heat_released: f64,
    /// Σ δQ_L, J.
    pub heat_loss: f64,
    /// Σ δQ_vap, J.
    pub vaporisation_heat: f64,
    /// Gross indicated work W = ∮ p dV from IVC to EVO (eq 2.48), J.
    pub work: f64,
    /// U_EVO − U_IVC, with U = p·V/(γ − 1), J.
    pub internal_energy_change: f64,
    /// The thesis's exhaust energy m_EVO·c_v·(T_EVO − T_1) (docs/validation/nunes-2017.md
    /// R5.1.9), J.
    pub exhaust_energy: f64,
    /// Highest pressure of the trace (on the integration grid), Pa.
    pub peak_pressure: f64,
    /// Crank angle of the highest pressure, rad from the opening TDC.
    pub peak_pressure_angle: f64,
}

impl EnergyBalance {
    /// First law over the cycle, Q_R − Q_L − Q_vap − W − ΔU: zero to round-off, because the
    /// step (eq 3.4) is solved exactly (eq 3.5) and its terms telescope.
    pub fn residual(&self) -> f64 {
        self.heat_released
            - self.heat_loss
            - self.vaporisation_heat
            - self.work
            - self.internal_energy_change
    }
}

impl ClosedCycle {
    /// The inputs of Nunes (2017), Table 3.2 (L1155-1185) and docs/validation/nunes-2017.md
    /// R5.1: WOT, sea-level ISA, stoichiometric aviation gasoline, 1° steps (the two opposed
    /// pistons are the chamber's).
    pub fn nunes_2017() -> Self {
        Self {
            ambient_pressure: 101_325.0,
            ambient_temperature: 288.15,
            wall_temperature: 350.0,
            gas_constant: 287.04,
            gamma: 1.4,
            lambda: 1.0,
            stoichiometric_air_fuel_ratio: 15.06,
            fuel_heating_value: 43.5e6,
            vaporisation_heat: 400e3,
            max_combustion_efficiency: 0.9,
            combustion_start: 350.93_f64.to_radians(),
            combustion_start_per_speed: -0.0004 / 6.0,
            combustion_duration: 30.663_f64.to_radians(),
            combustion_duration_per_speed: 0.0027 / 6.0,
            wiebe_a: 5.0,
            wiebe_m: 2.0,
            annand_a: 0.49,
            radiation_coefficient: 4.25e-9,
            intake_closing: PI,
            exhaust_opening: 3.0 * PI,
            step: 1.0_f64.to_radians(),
        }
    }

    /// Every impossible input is an error naming its field.
    pub fn validate(&self) -> Result<(), GasError> {
        let positive = [
            ("ambient_pressure", self.ambient_pressure),
            ("ambient_temperature", self.ambient_temperature),
            ("wall_temperature", self.wall_temperature),
            ("gas_constant", self.gas_constant),
            ("lambda", self.lambda),
            (
                "stoichiometric_air_fuel_ratio",
                self.stoichiometric_air_fuel_ratio,
            ),
            ("wiebe_a", self.wiebe_a),
        ];
        for (field, v) in positive {
            require(field, v, v > 0.0, "must be positive")?;
        }
        let non_negative = [
            ("fuel_heating_value", self.fuel_heating_value),
            ("vaporisation_heat", self.vaporisation_heat),
            ("annand_a", self.annand_a),
            ("radiation_coefficient", self.radiation_coefficient),
        ];
        for (field, v) in non_negative {
            require(field, v, v >= 0.0, "must not be negative")?;
        }
        let finite = [
            ("combustion_start", self.combustion_start),
            (
                "combustion_start_per_speed",
                self.combustion_start_per_speed,
            ),
            ("combustion_duration", self.combustion_duration),
            (
                "combustion_duration_per_speed",
                self.combustion_duration_per_speed,
            ),
        ];
        for (field, v) in finite {
            require(field, v, true, "must be finite")?;
        }
        require(
            "gamma",
            self.gamma,
            self.gamma > 1.0,
            "must be greater than 1",
        )?;
        let g = self.max_combustion_efficiency;
        require(
            "max_combustion_efficiency",
            g,
            g > 0.0 && g <= 1.0,
            "must be in (0, 1]",
        )?;
        require(
            "lambda",
            self.lambda,
            self.combustion_efficiency() > 0.0 && self.combustion_efficiency() <= 1.0,
            "gives a combustion efficiency (eq 2.56) outside (0, 1]: λ must lie between about \
             0.43 and 1.81 (the correlation is stated for 0.75 to 1.2)",
        )?;
        require(
            "wiebe_m",
            self.wiebe_m,
            self.wiebe_m > -1.0,
            "must be greater than -1 (the Wiebe exponent m + 1 must be positive)",
        )?;
        let (ivc, evo) = (self.intake_closing, self.exhaust_opening);
        require(
            "intake_closing",
            ivc,
            (0.0..4.0 * PI).contains(&ivc),
            "must be from 0 to 720 degrees after the opening top dead centre",
        )?;
        require(
            "exhaust_opening",
            evo,
            evo > ivc && evo <= 4.0 * PI,
            "must be after intake_closing and at most 720 degrees after the opening top dead centre",
        )?;
        require(
            "step",
            self.step,
            self.step > 0.0 && self.step <= MAX_STEP && (evo - ivc) / self.step <= MAX_STEPS,
            "must be positive, at most 5° (so that the combustion, about 30°, spans several \
             steps) and give at most 10 000 000 steps from intake_closing to exhaust_opening",
        )?;
        Ok(())
    }

    /// Combustion efficiency η_c = η_cmax·(−1.6082 + 4.6509·λ − 2.0764·λ²) (eq 2.56, Blair):
    /// 0.86967 at λ = 1.
    pub fn combustion_efficiency(&self) -> f64 {
        let l = self.lambda;
        self.max_combustion_efficiency * (-1.6082 + 4.6509 * l - 2.0764 * l * l)
    }

    /// Start θ_0 (rad from the opening TDC) and duration Δθ (rad) of combustion at the mean
    /// crank speed `speed` (rad/s) (eqs 3.1-3.2).
    pub fn combustion_timing(&self, speed: f64) -> (f64, f64) {
        (
            self.combustion_start + self.combustion_start_per_speed * speed,
            self.combustion_duration + self.combustion_duration_per_speed * speed,
        )
    }

    /// Wiebe mass fraction burned χ_b = 1 − exp(−a·((θ − θ_0)/Δθ)^(m+1)) (eq 2.28), zero
    /// before θ_0 and held at its value at θ_0 + Δθ after it (docs/validation/nunes-2017.md
    /// R5.1.4).
    pub fn burned_fraction(&self, theta: f64, start: f64, duration: f64) -> f64 {
        if theta <= start {
            return 0.0;
        }
        let x = ((theta - start) / duration).min(1.0);
        1.0 - (-self.wiebe_a * x.powf(self.wiebe_m + 1.0)).exp()
    }

    /// Heat-transfer coefficient C_h + C_r, W/(m²·K), at gas pressure `p` (Pa) and temperature
    /// `t` (K), with mean piston speed `sp` (m/s) (eqs 2.30-2.37).
    fn heat_transfer_coefficient(&self, bore: f64, p: f64, t: f64, sp: f64) -> Option<f64> {
        let mu = 7.457e-6 + 4.1547e-8 * t - 7.4793e-12 * t * t; // (2.34), kg/(m·s)
        let k = 6.1944e-3 + 7.3814e-5 * t - 1.2491e-8 * t * t; // (2.36), W/(m·K)
        if !(mu > 0.0 && k > 0.0) {
            return None; // the fits end near 5700 K and 6400 K
        }
        // (2.31)-(2.32), then (2.30) and (2.35).
        let re = p / (self.gas_constant * t) * sp * bore / mu;
        let ch = k * self.annand_a * re.powf(0.7) / bore;
        // (2.37), with (T⁴ − T_w⁴)/(T − T_w) = (T + T_w)·(T² + T_w²), regular at T = T_w.
        let tw = self.wall_temperature;
        let cr = self.radiation_coefficient * (t + tw) * (t * t + tw * tw);
        Some(ch + cr)
    }

    /// The inputs of [`ClosedCycle::trace`] checked (the model's own, a clearance volume, a
    /// positive speed), and the combustion's start and duration at `speed` (eqs 3.1-3.2), rad,
    /// checked to lie within the closed cycle.
    fn checked_timing(&self, chamber: &Chamber, speed: f64) -> Result<(f64, f64), GasError> {
        self.validate()?;
        let cyl = chamber.cylinder;
        require(
            "clearance_volume",
            cyl.clearance_volume,
            cyl.clearance_volume > 0.0,
            "must be positive: the closed cycle needs a clearance volume",
        )?;
        require("speed", speed, speed > 0.0, "must be positive")?;
        let (ivc, evo) = (self.intake_closing, self.exhaust_opening);
        let (start, duration) = self.combustion_timing(speed);
        require(
            "combustion_start",
            start,
            start > ivc && start < evo,
            "must lie between intake_closing and exhaust_opening at the mean crank speed \
             (eq 3.1: combustion_start + combustion_start_per_speed × speed)",
        )?;
        require(
            "combustion_duration",
            duration,
            duration > 0.0,
            "must be positive at the mean crank speed (eq 3.2: combustion_duration + \
             combustion_duration_per_speed × speed)",
        )?;
        Ok((start, duration))
    }

    /// The heat-transfer coefficient at the state `s` at the start of a step (eq 2.39's h),
    /// W/(m²·K); beyond the range of the Annand fits, the input at fault: the compression where
    /// the isentropic compression from IVC alone (T·V^(γ−1) constant), at `compressed` K,
    /// would already be too hot, else the fuel.
    fn step_heat_transfer(
        &self,
        cyl: &Cylinder,
        s: &Point,
        compressed: f64,
        sp: f64,
    ) -> Result<f64, GasError> {
        self.heat_transfer_coefficient(cyl.bore, s.p, s.t, sp)
            .ok_or_else(
                || match self.heat_transfer_coefficient(cyl.bore, s.p, compressed, sp) {
                    Some(_) => GasError {
                        field: "fuel_heating_value",
                        value: self.fuel_heating_value,
                        rule: "heats the gas beyond the range of the Annand property fits \
                               (eqs 2.34, 2.36)",
                    },
                    None => GasError {
                        field: "compression_ratio",
                        value: (cyl.swept_volume + cyl.clearance_volume) / cyl.clearance_volume,
                        rule: "compresses the gas beyond the range of the Annand property fits \
                               (eqs 2.34, 2.36) by itself, whatever the fuel's heat",
                    },
                },
            )
    }

    /// The energy balance's totals at the last point `s` of a cycle that started with the
    /// internal energy `u0`, J: heat released, lost and taken by vaporisation, work, the change
    /// of internal energy and the exhaust's energy above ambient (eqs 3.4-3.8's sums).
    fn closing_balance(&self, s: &Point, u0: f64) -> EnergyBalance {
        let (r, g, t1) = (self.gas_constant, self.gamma, self.ambient_temperature);
        EnergyBalance {
            heat_released: s.q_r,
            heat_loss: s.q_l,
            vaporisation_heat: s.q_v,
            work: s.w,
            internal_energy_change: s.p * s.v / (g - 1.0) - u0,
            exhaust_energy: s.m * r / (g - 1.0) * (s.t - t1),
            ..EnergyBalance::default()
        }
    }

    /// The closed cycle from IVC to EVO at the mean crank speed `speed` (rad/s), on Blair's
    /// finite-difference first law (eqs 3.4-3.8) with the phases of eqs 3.9-3.17.
    pub fn trace(&self, chamber: &Chamber, speed: f64) -> Result<ClosedCycleTrace, GasError> {
        let cyl = chamber.cylinder;
        let (start, duration) = self.checked_timing(chamber, speed)?;
        let (ivc, evo) = (self.intake_closing, self.exhaust_opening);
        let (r, g, p1, t1) = (
            self.gas_constant,
            self.gamma,
            self.ambient_pressure,
            self.ambient_temperature,
        );
        let volume = |theta: f64| {
            let v = (chamber.volume)(theta + chamber.tdc_angle).volume;
            require("volume", v, v > 0.0, "chamber volume must be positive")
        };
        let n = ((evo - ivc) / self.step - 1e-9).ceil().max(1.0) as usize;
        let h = (evo - ivc) / n as f64;
        let dt = h / speed; // (2.38), with N/60 = ω/(2π)
        let g6 = (g + 1.0) / (g - 1.0); // (3.7)
        let eta_c = self.combustion_efficiency();
        let afr = self.lambda * self.stoichiometric_air_fuel_ratio; // (2.55)
        let fuel = p1 * cyl.swept_volume / (r * t1) / afr; // (2.5)-(2.6)
        let stroke = cyl.stroke();
        let sp = 2.0 * stroke * speed / (2.0 * PI); // (2.33)
        let vap_span = start - ivc; // θ_vap (2.41), rad

        let v = volume(ivc)?;
        let mut s = Point {
            angle: ivc,
            v,
            p: p1,
            t: t1,
            m: p1 * v / (r * t1), // (2.4)
            ..Point::default()
        };
        let u0 = s.p * s.v / (g - 1.0);
        let mut tr = ClosedCycleTrace::default();
        tr.push(&s);
        for i in 1..=n {
            let a2 = ivc + h * i as f64;
            let v2 = volume(a2)?;
            // Vaporisation over IVC → θ_0 (2.41-2.42, 3.9-3.10), shared by overlap.
            let dm = fuel * ((a2.min(start) - s.angle) / vap_span).max(0.0);
            let dq_vap = dm * self.vaporisation_heat;
            // Heat release (2.29 = 3.14).
            let xb2 = self.burned_fraction(a2, start, duration);
            let dq_r = eta_c * (xb2 - s.xb) * fuel * self.fuel_heating_value;
            // Heat loss (2.39) from the state at the start of the step.
            let hc = self.step_heat_transfer(&cyl, &s, t1 * (v / s.v).powf(g - 1.0), sp)?;
            let dq_l = hc * (s.t - self.wall_temperature) * cyl.wall_area(s.v) * dt;
            // (3.5)
            let p2 = (2.0 * (dq_r - dq_l - dq_vap) + s.p * (g6 * s.v - v2)) / (g6 * v2 - s.v);
            require(
                "step",
                self.step,
                p2 > 0.0,
                "too coarse for the explicit heat loss at this speed: the pressure becomes \
                 negative (use a smaller step or a higher speed)",
            )?;
            let m2 = s.m + dm; // (3.8)
            s = Point {
                angle: a2,
                v: v2,
                p: p2,
                t: p2 * v2 / (m2 * r), // (3.6)
                m: m2,
                xb: xb2,
                q_r: s.q_r + dq_r,
                q_l: s.q_l + dq_l,
                q_v: s.q_v + dq_vap,
                w: s.w + 0.5 * (s.p + p2) * (v2 - s.v),
            };
            tr.push(&s);
        }
        let (peak_pressure, peak_pressure_angle) = tr.peak_pressure(p1);
        tr.balance = EnergyBalance {
            combustion_start: start,
            combustion_duration: duration,
            combustion_efficiency: eta_c,
            trapped_mass: tr.mass[0],
            fuel_mass: fuel,
            fuel_energy: fuel * self.fuel_heating_value,
            peak_pressure,
            peak_pressure_angle,
            ..self.closing_balance(&s, u0)
        };
        Ok(tr)
    }
}

/// One integration point: state and cumulative heat and work.
#[derive(Debug, Clone, Copy, Default)]
struct Point {
    angle: f64,
    v: f64,
    p: f64,
    t: f64,
    m: f64,
    xb: f64,
    q_r: f64,
    q_l: f64,
    q_v: f64,
    w: f64,
}

impl ClosedCycleTrace {
    fn push(&mut self, s: &Point) {
        self.angle.push(s.angle);
        self.volume.push(s.v);
        self.pressure.push(s.p);
        self.temperature.push(s.t);
        self.mass.push(s.m);
        self.burned_fraction.push(s.xb);
        self.heat_released.push(s.q_r);
        self.heat_loss.push(s.q_l);
        self.vaporisation_heat.push(s.q_v);
        self.work.push(s.w);
    }

    /// The highest pressure of the trace, Pa, and its angle, rad (`otherwise` at the first
    /// point if no pressure compares highest).
    fn peak_pressure(&self, otherwise: f64) -> (f64, f64) {
        let (ip, &pmax) = self
            .pressure
            .iter()
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(b.1))
            .unwrap_or((0, &otherwise));
        (pmax, self.angle[ip])
    }
}

/// Linear interpolation of the trace at `angle` (rad from the opening TDC, within it).
fn interpolate(tr: &ClosedCycleTrace, angle: f64) -> f64 {
    let n = tr.angle.len() - 1;
    let (a0, an) = (tr.angle[0], tr.angle[n]);
    let s = (angle - a0) / (an - a0) * n as f64;
    let i = (s.floor().max(0.0) as usize).min(n.saturating_sub(1));
    let f = s - i as f64;
    let (p0, p1) = (tr.pressure[i], tr.pressure[(i + 1).min(n)]);
    p0 + f * (p1 - p0)
}

impl GasModel for ClosedCycle {
    /// Pressure at each crank angle: the trace, linearly interpolated, from IVC to EVO
    /// and the ambient pressure elsewhere; the force on each piston p·A_pis
    /// (docs/validation/nunes-2017.md R1). Metrics per cycle of the chamber
    /// (docs/validation/nunes-2017.md R5.1.8-R5.1.9):
    /// - `imep` W/V_d, Pa (eq 2.50); `indicated_work` W, J (eq 2.48);
    /// - `indicated_torque_mean` W/(4π), N·m: the whole chamber's mean torque (the thesis's
    ///   "average torque", docs/validation/nunes-2017.md R1); `indicated_power` W·ω/(4π), W
    ///   (eqs 2.46, 2.49);
    /// - `peak_pressure`, Pa, on the integration grid, and `peak_pressure_angle_deg`, degrees
    ///   from the opening TDC;
    /// - `combustion_efficiency` η_c (eq 2.56);
    /// - with fuel energy E_f = m_f·QHV > 0 (not motored): `isfc` m_f/W, kg/J (eq 2.52; the
    ///   gross indicated value), `indicated_efficiency` W/E_f (eq 2.53, the
    ///   thesis's "thermal efficiency" and its work fraction), and the other fractions of E_f:
    ///   `heat_loss_fraction` (Q_L + Q_vap)/E_f, `exhaust_fraction` m_EVO·c_v·(T_EVO − T_1)/E_f
    ///   and `unreleased_fraction` 1 − Q_R/E_f (incomplete combustion and the Wiebe cut-off).
    ///   The four sum to 1 less (m_EVO − m_1)·c_v·T_1/E_f (0.5 % for the thesis): the fuel
    ///   vapour enters the scheme without internal energy.
    fn prepare<'a>(
        &'a self,
        chamber: Chamber<'a>,
        speed: f64,
    ) -> Result<Box<dyn PreparedGas + 'a>, GasError> {
        let trace = self.trace(&chamber, speed)?;
        Ok(Box::new(PreparedClosedCycle {
            model: self,
            chamber,
            speed,
            trace,
        }))
    }
}

/// The closed cycle integrated once for its chamber and speed.
struct PreparedClosedCycle<'a> {
    model: &'a ClosedCycle,
    chamber: Chamber<'a>,
    speed: f64,
    trace: ClosedCycleTrace,
}

impl PreparedGas for PreparedClosedCycle<'_> {
    fn at(&self, theta: f64) -> (f64, f64) {
        let m = self.model;
        let a = self.chamber.cycle_angle(theta);
        let p = if (m.intake_closing..=m.exhaust_opening).contains(&a) {
            interpolate(&self.trace, a)
        } else {
            m.ambient_pressure
        };
        (p, p * self.chamber.cylinder.area)
    }

    fn metrics(&self) -> Vec<GasMetric> {
        let b = &self.trace.balance;
        let w = b.work;
        let ef = b.fuel_energy;
        let metrics = [
            ("imep", "Pa", w / self.chamber.cylinder.swept_volume),
            ("indicated_work", "J", w),
            ("indicated_torque_mean", "N*m", w / (4.0 * PI)),
            ("indicated_power", "W", w * self.speed / (4.0 * PI)),
            ("peak_pressure", "Pa", b.peak_pressure),
            (
                "peak_pressure_angle_deg",
                "deg",
                b.peak_pressure_angle.to_degrees(),
            ),
            ("combustion_efficiency", "1", b.combustion_efficiency),
            ("isfc", "kg/J", b.fuel_mass / w),
            ("indicated_efficiency", "1", w / ef),
            (
                "heat_loss_fraction",
                "1",
                (b.heat_loss + b.vaporisation_heat) / ef,
            ),
            ("exhaust_fraction", "1", b.exhaust_energy / ef),
            ("unreleased_fraction", "1", 1.0 - b.heat_released / ef),
        ];
        // Without fuel energy (a motored engine) the last five are undefined: left out.
        let keep = if ef > 0.0 { metrics.len() } else { 7 };
        metrics[..keep]
            .iter()
            .map(|&(name, unit, value)| GasMetric { name, unit, value })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Cylinder, Volume};

    fn cylinder() -> Cylinder {
        Cylinder::with_compression_ratio(0.06, PI / 4.0 * 0.06 * 0.06 * 0.104, 10.0).unwrap()
    }

    #[test]
    fn thesis_correlations() {
        let e = ClosedCycle::nunes_2017();
        assert!((e.combustion_efficiency() - 0.869_67).abs() < 5e-6);
        // docs/validation/nunes-2017.md R2.9: at 8000 rpm θ_0 = 347.73°, Δθ = 52.263°; at
        // 2000 rpm 350.13°, 36.063°.
        for (rpm, start, dur) in [(8000.0, 347.73, 52.263), (2000.0, 350.13, 36.063)] {
            let (s, d) = e.combustion_timing(rpm * PI / 30.0);
            assert!((s.to_degrees() - start).abs() < 1e-9, "{}", s.to_degrees());
            assert!((d.to_degrees() - dur).abs() < 1e-9, "{}", d.to_degrees());
        }
        // Wiebe: zero before the start, 1 − e^(−5) at and after the end (capped).
        assert_eq!(e.burned_fraction(1.0, 2.0, 0.5), 0.0);
        let end = 1.0 - (-5.0_f64).exp();
        assert!((e.burned_fraction(2.5, 2.0, 0.5) - end).abs() < 1e-15);
        assert_eq!(
            e.burned_fraction(3.0, 2.0, 0.5),
            e.burned_fraction(2.5, 2.0, 0.5)
        );
        assert!((e.burned_fraction(2.25, 2.0, 0.5) - (1.0 - (-5.0 / 8.0_f64).exp())).abs() < 1e-15);
    }

    #[test]
    fn bad_inputs_are_refused_by_name() {
        let base = ClosedCycle::nunes_2017();
        assert_eq!(base.validate(), Ok(()));
        type Break = fn(&mut ClosedCycle);
        let cases: [(&str, Break); 15] = [
            ("ambient_pressure", |e| e.ambient_pressure = -1.0),
            ("ambient_temperature", |e| e.ambient_temperature = 0.0),
            ("wall_temperature", |e| e.wall_temperature = f64::NAN),
            ("gas_constant", |e| e.gas_constant = f64::INFINITY),
            ("gamma", |e| e.gamma = 1.0),
            ("lambda", |e| e.lambda = 0.0),
            ("lambda", |e| e.lambda = 2.0),
            ("fuel_heating_value", |e| e.fuel_heating_value = -1.0),
            ("max_combustion_efficiency", |e| {
                e.max_combustion_efficiency = 1.2
            }),
            ("wiebe_m", |e| e.wiebe_m = -1.0),
            ("exhaust_opening", |e| e.exhaust_opening = e.intake_closing),
            ("intake_closing", |e| e.intake_closing = -0.1),
            ("step", |e| e.step = 0.0),
            ("step", |e| e.step = 1e-12),
            ("combustion_start", |e| e.combustion_start = f64::NAN),
        ];
        for (field, break_it) in cases {
            let mut e = base;
            break_it(&mut e);
            assert_eq!(e.validate().map_err(|err| err.field), Err(field));
        }
    }

    #[test]
    fn bad_chambers_and_speeds_are_refused() {
        let e = ClosedCycle::nunes_2017();
        let c = cylinder();
        let good = move |th: f64| Volume {
            volume: c.clearance_volume + c.swept_volume * 0.5 * (1.0 - th.cos()),
            rate: c.swept_volume * 0.5 * th.sin(),
        };
        let ch = Chamber {
            cylinder: c,
            tdc_angle: 0.0,
            volume: &good,
            piston: None,
        };
        assert!(e.cycle(&ch, 100.0, &[0.0, 1.0]).is_ok());
        for speed in [0.0, -1.0, f64::NAN] {
            assert_eq!(e.trace(&ch, speed).unwrap_err().field, "speed");
        }
        // Ignition after EVO at this speed.
        let mut late = e;
        late.combustion_start_per_speed = 1.0;
        assert_eq!(
            late.trace(&ch, 100.0).unwrap_err().field,
            "combustion_start"
        );
        let no_clearance = Chamber {
            cylinder: Cylinder::with_clearance(0.06, c.swept_volume, 0.0).unwrap(),
            ..ch
        };
        assert_eq!(
            e.trace(&no_clearance, 100.0).unwrap_err().field,
            "clearance_volume"
        );
        let negative = |_: f64| Volume {
            volume: -1.0,
            rate: 0.0,
        };
        let bad = Chamber {
            volume: &negative,
            ..ch
        };
        assert_eq!(e.trace(&bad, 100.0).unwrap_err().field, "volume");
        // Absurd fuel energy: out of the property fits, an error and not a panic.
        let mut hot = e;
        hot.fuel_heating_value = 1e10;
        assert!(hot.trace(&ch, 100.0).is_err());
        // A crawl with a coarse step: the explicit heat loss overshoots; an error.
        let mut coarse = e;
        coarse.step = MAX_STEP;
        let err = coarse.trace(&ch, 1e-3).unwrap_err();
        assert!(err.rule.contains("explicit heat loss"), "{err}");
        // A step that cannot resolve the combustion is refused outright (issue 7: a 360° step).
        coarse.step = 2.0 * PI;
        assert_eq!(coarse.validate().unwrap_err().field, "step");
        coarse.step = MAX_STEP * (1.0 + 1e-12);
        assert_eq!(coarse.validate().unwrap_err().field, "step");
    }
}
