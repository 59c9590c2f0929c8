//! `model = "closed_cycle"`: the single-zone closed-cycle spark-ignition engine of Nunes
//! (2017), §3.4.1. Every input but the compression ratio is optional; the defaults are
//! Nunes's ([`ClosedCycle::nunes_2017`], Table 3.2), written once, in the gas crate.

use super::model::{entry, Clearance, Context, GasEntry, ModelTable, ReadModel};
use crate::error::{CaseError, Machine};
use crate::plausible::{
    AirFuelRatio, AnnandA, CompressionRatio, Efficiency, HeatCapacityRatio, Lambda,
    RadiationCoefficient, WiebeA, WiebeM,
};
use crate::quantity::{
    Angle, AnglePerSpeed, GasConstant, NonNegative, Positive, Pressure, Quantity, Ranged,
    SpecificEnergy, Temperature,
};
use cardan_gas::closed_cycle::ClosedCycle;
use schemars::JsonSchema;
use serde::Deserialize;
use std::sync::Arc;

/// The registry line.
pub const ENTRY: GasEntry =
    entry::<ClosedCycleTable>("closed_cycle", Some(Machine::Engine)).four_stroke();

/// `[gas]` of `model = "closed_cycle"`: the closed cycle of Nunes (2017). Angles are from the
/// opening top dead centre; the defaults are Nunes (2017) Table 3.2 (`ClosedCycle::nunes_2017`).
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ClosedCycleTable {
    /// Compression ratio ε = (V_stroke + V_comp)/V_comp, greater than 1; required.
    pub compression_ratio: Ranged<CompressionRatio>,
    /// Ambient and intake pressure p_1, absolute; Pa. Default 101 325 Pa (Table 3.2).
    pub ambient_pressure: Option<Positive<Pressure>>,
    /// Ambient and intake temperature T_1; K. Default 288.15 K (Table 3.2).
    pub ambient_temperature: Option<Positive<Temperature>>,
    /// Cylinder wall temperature T_wall; K. Default 350 K (Table 3.2, after Stone 1999).
    pub wall_temperature: Option<Positive<Temperature>>,
    /// Gas constant R; J/(kg·K). Default 287.04 (Table 3.2).
    pub gas_constant: Option<Positive<GasConstant>>,
    /// Ratio of specific heats γ, constant, greater than 1. Default 1.4 (Table 3.2).
    pub gamma: Option<Ranged<HeatCapacityRatio>>,
    /// Relative air-fuel ratio λ = AFR/AFR_stoich (eq 2.55), about 0.43 to 1.81 (the
    /// combustion efficiency correlation is stated for 0.75 to 1.2). Default 1 (Table 3.2).
    pub lambda: Option<Ranged<Lambda>>,
    /// Stoichiometric air-fuel ratio AFR_stoich, by mass. Default 15.06 (Table 3.2).
    pub stoichiometric_air_fuel_ratio: Option<Ranged<AirFuelRatio>>,
    /// Lower heating value of the fuel QHV; J/kg. Default 43.5 MJ/kg (Table 3.2). Zero gives a
    /// motored engine.
    pub fuel_heating_value: Option<NonNegative<SpecificEnergy>>,
    /// Heat of vaporisation of the fuel h_vap; J/kg. Default 400 kJ/kg (Table 3.2, eq 2.42).
    pub vaporisation_heat: Option<NonNegative<SpecificEnergy>>,
    /// η_cmax of Blair's combustion efficiency (eq 2.56), in (0, 1]. Default 0.9.
    pub max_combustion_efficiency: Option<Ranged<Efficiency>>,
    /// Start of combustion at zero speed θ_0(0); degrees. Default 350.93° (eq 3.1).
    pub combustion_start: Option<Quantity<Angle>>,
    /// dθ_0/dω, the start's change with speed; s (rad per rad/s), or deg/rpm. Default
    /// −0.0004 deg/rpm (eq 3.1).
    pub combustion_start_per_speed: Option<Quantity<AnglePerSpeed>>,
    /// Combustion duration at zero speed Δθ(0); degrees. Default 30.663° (eq 3.2).
    pub combustion_duration: Option<Quantity<Angle>>,
    /// dΔθ/dω, the duration's change with speed; s (rad per rad/s), or deg/rpm. Default
    /// 0.0027 deg/rpm (eq 3.2).
    pub combustion_duration_per_speed: Option<Quantity<AnglePerSpeed>>,
    /// Wiebe efficiency parameter a (eq 2.28). Default 5.
    pub wiebe_a: Option<Ranged<WiebeA>>,
    /// Wiebe form factor m, exponent m + 1 (eq 2.28), greater than −1. Default 2.
    pub wiebe_m: Option<Ranged<WiebeM>>,
    /// Annand's Nusselt coefficient a_Nu in Nu = a_Nu·Re^0.7 (eq 2.30); zero turns convection
    /// off. Default 0.49 (four-stroke engines).
    pub annand_a: Option<Ranged<AnnandA>>,
    /// Radiation constant c of C_r = c·(T⁴ − T_wall⁴)/(T − T_wall) (eq 2.37); W/(m²·K⁴); zero
    /// turns radiation off. Default 4.25e-9.
    pub radiation_coefficient: Option<Ranged<RadiationCoefficient>>,
    /// Intake valve closing IVC, the start of the closed cycle, from 0 to 720; degrees.
    /// Default 180° (Table 3.2).
    pub intake_closing: Option<Quantity<Angle>>,
    /// Exhaust valve opening EVO, the end of the closed cycle, after IVC and at most 720;
    /// degrees. Default 540° (Table 3.2).
    pub exhaust_opening: Option<Quantity<Angle>>,
    /// Integration step, at most 5; degrees. Default 1° (Nunes's step).
    pub step: Option<Quantity<Angle>>,
}

/// Each given field replaces Nunes's value.
macro_rules! given {
    ($table:ident, $cycle:ident: $($field:ident),* $(,)?) => {
        $(if let Some(q) = &$table.$field {
            $cycle.$field = q.si;
        })*
    };
}

impl ModelTable for ClosedCycleTable {
    fn build(self, cx: &Context) -> Result<ReadModel, CaseError> {
        let mut c = ClosedCycle::nunes_2017();
        let t = &self;
        given!(t, c: ambient_pressure, ambient_temperature, wall_temperature, gas_constant,
            gamma, lambda, stoichiometric_air_fuel_ratio, fuel_heating_value, vaporisation_heat,
            max_combustion_efficiency, combustion_start, combustion_start_per_speed,
            combustion_duration, combustion_duration_per_speed, wiebe_a, wiebe_m, annand_a,
            radiation_coefficient, intake_closing, exhaust_opening, step);
        c.validate().map_err(|e| cx.broken(e))?;
        let clearance = Clearance::CompressionRatio(self.compression_ratio.si);
        Ok((Arc::new(c), clearance))
    }
}
