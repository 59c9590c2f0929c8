//! Engine-level losses: valve train (cam and follower), Bishop (1964) accessory and pumping
//! correlations, and the empirical whole-engine fmep of Patton, Nitschke & Heywood (1989) with
//! the Sandoval & Heywood (2003) update.
//!
//! Mean effective pressures are returned in Pa; [`mep_power`] turns an mep into a power.

use crate::RotaryLoss;
use std::f64::consts::PI;

/// Power of a mean effective pressure: P = mep · V_d · n / (2π n_R), with `displacement` V_d the
/// total swept volume (m³), `crank_speed` ω (rad/s) and `revolutions_per_cycle` n_R (2 for a
/// four-stroke engine, 1 for a two-stroke engine or a pump). Thai thesis eqs 2.5.e.3.2 and
/// 2.5.f.6 (P = mep · V_d · N/(60·2) for N in rev/min, four-stroke).
pub fn mep_power(mep: f64, displacement: f64, crank_speed: f64, revolutions_per_cycle: f64) -> f64 {
    mep * displacement * crank_speed.abs() / (2.0 * PI * revolutions_per_cycle)
}

fn rpm(crank_speed: f64) -> f64 {
    crank_speed.abs() * 60.0 / (2.0 * PI)
}

// ---------------------------------------------------------------------------------------------
// Valve train
// ---------------------------------------------------------------------------------------------

/// Cam force on a translating follower: W = F_pl + k S + m A (Thai thesis eqs 2.5.d.14–15;
/// sleeve friction neglected), N. `preload` F_pl (N), `spring_rate` k (N/m), `lift` S (m),
/// `equivalent_mass` m (kg, follower + valve + ⅓ spring reduced to the follower) and
/// `acceleration` A (m/s², positive in the lift direction). Negative values mean the follower
/// leaves the cam (valve float); they are returned as computed.
pub fn follower_load(
    preload: f64,
    spring_rate: f64,
    lift: f64,
    equivalent_mass: f64,
    acceleration: f64,
) -> f64 {
    preload + spring_rate * lift + equivalent_mass * acceleration
}

/// Coulomb friction at a flat-faced follower: T_f = μ W (R + S) on the cam (Thai thesis eq.
/// 2.5.d.18 without its mm→m factors), P = T_f |ω_cam| = μ W × sliding speed, since the cam
/// surface slides past the flat face at ω (R + S).
///
/// `friction_coefficient` μ, `load` W (N), `base_radius` R and `lift` S (m), `cam_speed`
/// (rad/s).
pub fn flat_follower_friction(
    friction_coefficient: f64,
    load: f64,
    base_radius: f64,
    lift: f64,
    cam_speed: f64,
) -> RotaryLoss {
    let t = friction_coefficient * load.abs() * (base_radius + lift);
    RotaryLoss {
        friction_torque: t,
        power: t * cam_speed.abs(),
    }
}

/// Torque needed to drive a cam with a flat follower:
/// T = W (μ (R + S) + dS/dθ) (Thai thesis eqs 2.5.d.20–21), N·m. `lift_slope` dS/dθ in m/rad.
/// Over a cam revolution the geometric part W dS/dθ integrates to the spring/inertia work
/// (≈ 0), leaving the friction part.
pub fn cam_drive_torque(
    friction_coefficient: f64,
    load: f64,
    base_radius: f64,
    lift: f64,
    lift_slope: f64,
) -> f64 {
    load * (friction_coefficient * (base_radius + lift) + lift_slope)
}

/// Friction of a roller follower: rolling resistance at the cam/roller contact plus the roller's
/// pin (needle or plain) bearing, P = W v_r (c_rr + μ_pin r_pin / r_roller), W. `load` W (N),
/// `rolling_speed` v_r = the contact's surface speed on the roller (m/s),
/// `rolling_resistance` c_rr (rolling-friction arm over roller radius; ≈ 0.001–0.005, an
/// engineering value \[M\], not from the seeds), `pin_friction` μ_pin, `pin_radius` and
/// `roller_radius` (m). Returns the equivalent tangential force W (c_rr + μ_pin r_pin/r_roller)
/// and the power.
pub fn roller_follower_friction(
    load: f64,
    rolling_speed: f64,
    rolling_resistance: f64,
    pin_friction: f64,
    pin_radius: f64,
    roller_radius: f64,
) -> crate::SlidingLoss {
    let f = load.abs() * (rolling_resistance + pin_friction * pin_radius / roller_radius);
    crate::SlidingLoss {
        friction_force: f,
        power: f * rolling_speed.abs(),
    }
}

// ---------------------------------------------------------------------------------------------
// Bishop (1964) accessories and pumping, as used by the Thai thesis §2.5.e.3 and §2.5.f
// ---------------------------------------------------------------------------------------------

/// Water pump, oil pump and miscellaneous accessories: mep = 2.69 kPa · (N/1000)^1.5 (Bishop
/// 1964, 0.39 psi; Thai thesis eq. 2.5.e.3.1), returned in Pa. `crank_speed` in rad/s.
pub fn bishop_pumps_misc_mep(crank_speed: f64) -> f64 {
    2.69e3 * (rpm(crank_speed) / 1000.0).powf(1.5)
}

/// Bishop's throttling loss, Pa (Thai thesis eqs 2.5.f.1–2, converted from psi/inHg):
/// mep = (p_a − p_i) + p′_e [(imep_s/3904 kPa)(N/1000)]², where p_i is the absolute
/// intake-manifold pressure, imep_s = 12.87 (p_i − 0.1 p_a) the "standard" imep of that manifold
/// pressure (kPa), and p′_e the exhaust gauge pressure at full load and 4000 rev/min
/// (Bishop: 10 inHg = 33.86 kPa). Inputs in Pa and rad/s.
///
/// Confidence: structure high, the constants 12.87 and 3904 medium (OCR; see
/// `docs/validation/thai-thesis.md` §5.6).
pub fn bishop_throttling_mep(
    ambient_pressure: f64,
    intake_pressure: f64,
    exhaust_full_load_gauge: f64,
    crank_speed: f64,
) -> f64 {
    let pa = ambient_pressure / 1e3;
    let pi = intake_pressure / 1e3;
    let imep_s = 12.87 * (pi - 0.1 * pa);
    let pe = exhaust_full_load_gauge / 1e3;
    let n = rpm(crank_speed) / 1000.0;
    ((pa - pi) + pe * (imep_s / 3904.0 * n).powi(2)) * 1e3
}

/// Bishop's exhaust gauge pressure at full load and 4000 rev/min, 10 inHg, Pa.
pub const BISHOP_EXHAUST_FULL_LOAD: f64 = 33.86e3;

// ---------------------------------------------------------------------------------------------
// Patton, Nitschke & Heywood (1989) / Sandoval & Heywood (2003)
// ---------------------------------------------------------------------------------------------

/// A set of identical shaft bearings.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ShaftBearings {
    /// Number of bearings.
    pub count: u32,
    /// Journal diameter, m.
    pub diameter: f64,
    /// Bearing length, m.
    pub length: f64,
}

/// Valve-train layout of PNH (constants of Sandoval 2002 Table 4.2).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Valvetrain {
    /// Single overhead cam, finger follower.
    SohcFinger,
    /// Single overhead cam, rocker arm.
    SohcRocker,
    /// Single overhead cam, direct acting.
    SohcDirect,
    /// Double overhead cam, finger follower.
    DohcFinger,
    /// Double overhead cam, direct acting.
    DohcDirect,
    /// Cam in block, pushrod (no roller constant: the table's "0.5" is a misprint).
    Ohv,
}

impl Valvetrain {
    /// (C_ff kPa·mm, C_rf kPa·mm·min, C_oh, C_om kPa) of Sandoval (2002) Table 4.2, as quoted in
    /// `docs/validation/engine-friction.md`. C_rf of OHV is NaN.
    pub fn constants(self) -> (f64, f64, f64, f64) {
        match self {
            Valvetrain::SohcFinger => (600.0, 0.0227, 0.2, 42.8),
            Valvetrain::SohcRocker => (400.0, 0.0151, 0.5, 21.4),
            Valvetrain::SohcDirect => (200.0, 0.0076, 0.5, 10.7),
            Valvetrain::DohcFinger => (600.0, 0.0227, 0.2, 25.8),
            Valvetrain::DohcDirect => (133.0, 0.005, 0.5, 10.7),
            Valvetrain::Ohv => (400.0, f64::NAN, 0.5, 32.1),
        }
    }
}

/// Cam follower type.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Follower {
    /// Flat (sliding) follower: mixed lubrication term C_ff (1 + N₀/N).
    Flat,
    /// Roller follower: C_rf N.
    Roller,
}

/// Engine description for the PNH correlation (SI inputs).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PnhEngine {
    /// Bore B, m.
    pub bore: f64,
    /// Stroke S, m.
    pub stroke: f64,
    /// Number of cylinders n_c.
    pub cylinders: u32,
    /// Compression ratio r_c.
    pub compression_ratio: f64,
    /// Main bearings.
    pub main_bearings: ShaftBearings,
    /// Connecting-rod (big-end) bearings.
    pub rod_bearings: ShaftBearings,
    /// Number of camshaft bearings.
    pub cam_bearings: u32,
    /// Total number of valves n_v.
    pub valves: u32,
    /// Maximum valve lift L_v, m.
    pub max_valve_lift: f64,
    /// Valve-train layout.
    pub valvetrain: Valvetrain,
    /// Follower type.
    pub follower: Follower,
}

/// Which form of the PNH correlation.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum PnhVariant {
    /// Patton, Nitschke & Heywood (1989), SAE 890836: boundary factor 1 + 1000/N, no viscosity
    /// scaling.
    Pnh1989,
    /// Sandoval & Heywood (2003), SAE 2003-01-0725: every hydrodynamic term (main and rod
    /// bearings, skirt, the 0.088 r_c gas-loading term, cam bearings, oscillating hydrodynamic)
    /// × √(ν/ν₀) with ν₀ = 10.6 cSt (10W-30 at 90 °C), boundary factor 1 + 500/N (rings, flat
    /// follower, oscillating mixed). Sandoval's ring-tension/roughness factors and doubled K in
    /// the gas-loading exponent are not applied (engine-specific calibrations; `docs/validation/engine-friction.md`).
    SandovalHeywood2003 {
        /// Kinematic viscosity of the oil at operating temperature over ν₀ = 10.6 cSt.
        viscosity_ratio: f64,
    },
}

/// PNH friction mean effective pressures by component, Pa.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct FmepBreakdown {
    /// Crankshaft seals (boundary): 1.22e5 D_b/(B² S n_c).
    pub crank_seals: f64,
    /// Main bearings (hydrodynamic): 3.03e-4 N D_b³ L_b n_b/(B² S n_c).
    pub main_bearings: f64,
    /// Turbulent dissipation: 1.35e-10 D_b² N² n_b/n_c.
    pub turbulent_dissipation: f64,
    /// Piston skirt (hydrodynamic): 2.94e2 S̄p/B.
    pub skirt: f64,
    /// Rings without gas loading: 4.06e4 (1 + N₀/N)/B².
    pub rings: f64,
    /// Rod bearings: 3.03e-4 N D_r³ L_r n_r/(B² S n_c).
    pub rod_bearings: f64,
    /// Gas-pressure loading: 6.89 (p_i/p_a)[0.088 r_c + 0.182 r_c^(1.33 − 2.38e-2 S̄p)].
    pub gas_loading: f64,
    /// Cam bearings incl. the 4.12 kPa constant: 244 N n_cb/(B² S n_c) + 4.12.
    pub cam_bearings: f64,
    /// Follower: C_ff (1 + N₀/N) n_v/(S n_c) or C_rf N n_v/(S n_c).
    pub follower: f64,
    /// Oscillating hydrodynamic: C_oh L_v^1.5 N^0.5 n_v/(B S n_c).
    pub oscillating_hydrodynamic: f64,
    /// Oscillating mixed: C_om (1 + N₀/N) L_v n_v/(S n_c).
    pub oscillating_mixed: f64,
    /// Auxiliaries (oil and water pumps, non-charging alternator): 6.23 + 5.22e-3 N − 1.79e-7 N².
    pub auxiliaries: f64,
}

impl FmepBreakdown {
    /// Crankshaft group (seals + mains + turbulent dissipation), Pa.
    pub fn crankshaft(&self) -> f64 {
        self.crank_seals + self.main_bearings + self.turbulent_dissipation
    }
    /// Reciprocating group (skirt + rings + rod bearings + gas loading), Pa.
    pub fn reciprocating(&self) -> f64 {
        self.skirt + self.rings + self.rod_bearings + self.gas_loading
    }
    /// Valve-train group, Pa.
    pub fn valvetrain(&self) -> f64 {
        self.cam_bearings + self.follower + self.oscillating_hydrodynamic + self.oscillating_mixed
    }
    /// Total mechanical fmep (no pumping), Pa.
    pub fn total(&self) -> f64 {
        self.crankshaft() + self.reciprocating() + self.valvetrain() + self.auxiliaries
    }
}

/// Patton–Nitschke–Heywood (1989) friction mean effective pressure by component, Pa.
///
/// Equations and constants as reproduced by Sandoval (2002, MIT BSc thesis, eqs 7.a–11, Table
/// 4.2), quoted in `docs/validation/engine-friction.md`. Inside, as published: fmep in kPa,
/// B, S, D, L, L_v in mm, N in rev/min, S̄p = 2 S N/60 in m/s. `crank_speed` in rad/s (> 0),
/// `intake_pressure` p_i and `ambient_pressure` p_a in Pa (any consistent unit: only the ratio
/// enters). Roller followers of the OHV layout have no constant and give NaN.
pub fn pnh_fmep(
    engine: &PnhEngine,
    variant: PnhVariant,
    crank_speed: f64,
    intake_pressure: f64,
    ambient_pressure: f64,
) -> FmepBreakdown {
    let (vr, n0) = match variant {
        PnhVariant::Pnh1989 => (1.0, 1000.0),
        PnhVariant::SandovalHeywood2003 { viscosity_ratio } => (viscosity_ratio.sqrt(), 500.0),
    };
    let b = engine.bore * 1e3;
    let s = engine.stroke * 1e3;
    let nc = f64::from(engine.cylinders);
    let n = rpm(crank_speed);
    let sp = 2.0 * engine.stroke * n / 60.0;
    let bnd = 1.0 + n0 / n;
    let b2s = b * b * s * nc;
    let (db, lb, nb) = (
        engine.main_bearings.diameter * 1e3,
        engine.main_bearings.length * 1e3,
        f64::from(engine.main_bearings.count),
    );
    let (dr, lr, nr) = (
        engine.rod_bearings.diameter * 1e3,
        engine.rod_bearings.length * 1e3,
        f64::from(engine.rod_bearings.count),
    );
    let rc = engine.compression_ratio;
    let (cff, crf, coh, com) = engine.valvetrain.constants();
    let nv = f64::from(engine.valves);
    let lv = engine.max_valve_lift * 1e3;
    let kpa = 1e3;
    FmepBreakdown {
        crank_seals: 1.22e5 * db / b2s * kpa,
        main_bearings: 3.03e-4 * vr * n * db.powi(3) * lb * nb / b2s * kpa,
        turbulent_dissipation: 1.35e-10 * db * db * n * n * nb / nc * kpa,
        skirt: 2.94e2 * vr * sp / b * kpa,
        rings: 4.06e4 * bnd / (b * b) * kpa,
        rod_bearings: 3.03e-4 * vr * n * dr.powi(3) * lr * nr / b2s * kpa,
        gas_loading: 6.89
            * (intake_pressure / ambient_pressure)
            * (0.088 * vr * rc + 0.182 * rc.powf(1.33 - 2.38e-2 * sp))
            * kpa,
        cam_bearings: (244.0 * vr * n * f64::from(engine.cam_bearings) / b2s + 4.12) * kpa,
        follower: match engine.follower {
            Follower::Flat => cff * bnd * nv / (s * nc),
            Follower::Roller => crf * n * nv / (s * nc),
        } * kpa,
        oscillating_hydrodynamic: coh * vr * lv.powf(1.5) * n.sqrt() * nv / (b * s * nc) * kpa,
        oscillating_mixed: com * bnd * lv * nv / (s * nc) * kpa,
        auxiliaries: (6.23 + 5.22e-3 * n - 1.79e-7 * n * n) * kpa,
    }
}
