//! `model = "compressor"`: a reciprocating compressor with its suction and delivery valves,
//! in its periodic steady state (`cardan_gas::compressor`).

use super::model::{entry, Clearance, Context, GasEntry, ModelTable, ReadModel};
use crate::error::{CaseError, Machine};
use crate::plausible::{ClearanceRatio, CompressorExponent};
use crate::quantity::{GasConstant, Positive, Pressure, Ranged, Temperature};
use cardan_gas::compressor::{Compressor, AIR_GAS_CONSTANT};
use schemars::JsonSchema;
use serde::Deserialize;
use std::sync::Arc;

/// The registry line.
pub const ENTRY: GasEntry = entry::<CompressorTable>("compressor", Some(Machine::Pump));

/// `[gas]` of `model = "compressor"`: suction and delivery states and the polytropic
/// exponents of a reciprocating compressor.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct CompressorTable {
    /// Suction (inlet, and crankcase) pressure p_s, absolute; Pa; required.
    pub suction_pressure: Positive<Pressure>,
    /// Suction temperature T_s; K; required.
    pub suction_temperature: Positive<Temperature>,
    /// Delivery (receiver) pressure p_d, absolute, above `suction_pressure` and low enough
    /// that the compressor delivers; Pa; required.
    pub delivery_pressure: Positive<Pressure>,
    /// Clearance ratio c = V_comp/V_stroke (zero: no clearance); required.
    pub clearance_ratio: Ranged<ClearanceRatio>,
    /// Polytropic exponent n_c of the compression, at least 1 (1 isothermal, 1.4 isentropic
    /// air); required.
    pub compression_exponent: Ranged<CompressorExponent>,
    /// Polytropic exponent n_e of the re-expansion of the clearance gas, at least 1. Default:
    /// `compression_exponent`.
    pub expansion_exponent: Option<Ranged<CompressorExponent>>,
    /// Specific gas constant R; J/(kg·K). Default 287.05, air (`cardan_gas::compressor::AIR_GAS_CONSTANT`).
    pub gas_constant: Option<Positive<GasConstant>>,
}

impl ModelTable for CompressorTable {
    fn build(self, cx: &Context) -> Result<ReadModel, CaseError> {
        let n_c = self.compression_exponent.si;
        let compressor = Compressor::new(
            self.suction_pressure.si,
            self.suction_temperature.si,
            self.delivery_pressure.si,
            n_c,
            self.expansion_exponent.map_or(n_c, |n| n.si),
            self.gas_constant.map_or(AIR_GAS_CONSTANT, |r| r.si),
        )
        .map_err(|e| cx.broken(e))?;
        let clearance = Clearance::ClearanceRatio(self.clearance_ratio.si);
        // A compressor must deliver, whatever its size.
        let cylinder = clearance.cylinder(1.0, 1.0, 1).map_err(|e| cx.broken(e))?;
        compressor
            .steady_state(&cylinder)
            .map_err(|e| cx.broken(e))?;
        Ok((Arc::new(compressor), clearance))
    }
}
