//! `model = "karhula_pump"` and `model = "karhula_engine"`: Karhula's air pump (ch. 6.2) and
//! four-stroke engine (ch. 6.3), the polytropic compression of A6.1.1.11 on the closed
//! strokes.

use super::model::{entry, Clearance, Context, GasEntry, ModelTable, ReadModel};
use crate::error::{CaseError, Machine};
use crate::plausible::{CompressionRatio, Filling, PolytropicExponent};
use crate::quantity::{Angle, Positive, Pressure, Quantity, Ranged};
use cardan_gas::{EngineReading, KarhulaEngine, KarhulaPump, Polytropic};
use schemars::JsonSchema;
use serde::Deserialize;
use std::sync::Arc;

/// The registry line of the pump.
pub const PUMP: GasEntry = entry::<KarhulaPumpTable>("karhula_pump", Some(Machine::Pump));
/// The registry line of the engine.
pub const ENGINE: GasEntry =
    entry::<KarhulaEngineTable>("karhula_engine", Some(Machine::Engine)).four_stroke();

/// The filling factor C_fill when not given: the intake charge is the uncompressed volume at
/// ambient pressure (Karhula A6.1.1.11 with C_fill = 1; the thesis's range is 1.0-1.1).
pub const DEFAULT_FILLING: f64 = 1.0;
/// The ambient pressure when not given: the standard atmosphere, 101 325 Pa (ISO 2533).
pub const DEFAULT_AMBIENT_PRESSURE: f64 = 101_325.0;

/// `[gas]` of `model = "karhula_pump"`: Karhula's air pump (ch. 6.2), the valves closed on the
/// compression strokes (zero delivery, the thesis's worst case).
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct KarhulaPumpTable {
    /// Compression ratio ε = (V_stroke + V_comp)/V_comp, greater than 1; required.
    pub compression_ratio: Ranged<CompressionRatio>,
    /// Polytropic exponent n of the compression (A6.1.1.11), greater than 1 (1.3-1.4 for air,
    /// Karhula ch. 10); required.
    pub polytropic_exponent: Ranged<PolytropicExponent>,
    /// Filling factor C_fill: the intake charge as a fraction of the uncompressed volume at
    /// ambient pressure (A6.1.1.11; 1.0-1.1). Default 1.
    pub filling: Option<Ranged<Filling>>,
    /// Ambient (intake) pressure p_atm, absolute; Pa. Default 101 325 Pa (the standard
    /// atmosphere, ISO 2533).
    pub ambient_pressure: Option<Positive<Pressure>>,
}

/// `[gas]` of `model = "karhula_engine"`: Karhula's approximate four-stroke engine (ch. 6.3),
/// the combustion pressure a scaled, shifted polytropic (A6.1.1.13).
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct KarhulaEngineTable {
    /// Compression ratio ε = (V_stroke + V_comp)/V_comp, greater than 1; required.
    pub compression_ratio: Ranged<CompressionRatio>,
    /// Polytropic exponent n of the compression (A6.1.1.11), greater than 1 (1.3-1.4 for air,
    /// Karhula ch. 10); required.
    pub polytropic_exponent: Ranged<PolytropicExponent>,
    /// Filling factor C_fill: the intake charge as a fraction of the uncompressed volume at
    /// ambient pressure (A6.1.1.11; 1.0-1.1). Default 1.
    pub filling: Option<Ranged<Filling>>,
    /// Ambient (intake) pressure p_atm, absolute; Pa. Default 101 325 Pa (the standard
    /// atmosphere, ISO 2533).
    pub ambient_pressure: Option<Positive<Pressure>>,
    /// Peak combustion pressure p_comb,max, absolute, above `ambient_pressure`; Pa (7-17 MPa,
    /// Karhula ch. 10); required.
    pub peak_pressure: Quantity<Pressure>,
    /// Crank angle of the pressure peak after top dead centre δ, from 0 to 180; degrees (8-10°,
    /// A6.1.1.13); required.
    pub combustion_delay: Quantity<Angle>,
    /// Which pressure the compression stroke carries. Default "direct".
    #[serde(default)]
    pub reading: KarhulaEngineReading,
}

/// The engine's reading of the thesis (docs/case-file.md, "Gas").
#[derive(Debug, Clone, Copy, Default, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum KarhulaEngineReading {
    /// The polytropic compression pressure on the compression stroke: the physical cycle.
    #[default]
    Direct,
    /// The combustion pressure on the compression stroke too, as Karhula's work columns imply.
    Thesis,
}

fn polytropic(
    exponent: &Ranged<PolytropicExponent>,
    filling: &Option<Ranged<Filling>>,
    ambient: &Option<Positive<Pressure>>,
    cx: &Context,
) -> Result<Polytropic, CaseError> {
    Polytropic::new(
        exponent.si,
        filling.as_ref().map_or(DEFAULT_FILLING, |f| f.si),
        ambient.as_ref().map_or(DEFAULT_AMBIENT_PRESSURE, |p| p.si),
    )
    .map_err(|e| cx.broken(e))
}

impl ModelTable for KarhulaPumpTable {
    fn build(self, cx: &Context) -> Result<ReadModel, CaseError> {
        let gas = polytropic(
            &self.polytropic_exponent,
            &self.filling,
            &self.ambient_pressure,
            cx,
        )?;
        let clearance = Clearance::CompressionRatio(self.compression_ratio.si);
        Ok((Arc::new(KarhulaPump { gas }), clearance))
    }
}

impl ModelTable for KarhulaEngineTable {
    fn build(self, cx: &Context) -> Result<ReadModel, CaseError> {
        let gas = polytropic(
            &self.polytropic_exponent,
            &self.filling,
            &self.ambient_pressure,
            cx,
        )?;
        let mut engine = KarhulaEngine::new(gas, self.peak_pressure.si, self.combustion_delay.si)
            .map_err(|e| cx.broken(e))?;
        engine.reading = match self.reading {
            KarhulaEngineReading::Direct => EngineReading::Direct,
            KarhulaEngineReading::Thesis => EngineReading::Thesis,
        };
        let clearance = Clearance::CompressionRatio(self.compression_ratio.si);
        Ok((Arc::new(engine), clearance))
    }
}
