//! The plausible ranges of the case file's bare numbers (issue 36.5): every dimensionless input
//! (ratios, exponents, factors, fractions, coefficients given in the SI unit their field
//! names) is a [`Ranged`](crate::quantity::Ranged) of one line of this table, with its range
//! and the reason or source of it. A value outside is refused when the file is read (so
//! `cardan check` refuses it, naming the field, the value as written and this rule), and the
//! JSON Schema carries the bounds. The ranges are far wider than any machine this project
//! models: they stop nonsense (a compression ratio of 1e308), not unusual designs; a model's
//! own, narrower rules are checked after reading. docs/case-file.md ("Plausible ranges") lists
//! them; `case/tests/plausible_ranges.rs` checks that every number of the schema without a
//! unit has one, and that values outside are refused.
//!
//! Whole numbers counted by the case (steps, cycles, cylinders, digits, points) are
//! [`Whole`](crate::quantity::Whole)s, their range at their field.

use crate::quantity::Range;

macro_rules! ranges {
    ($($(#[$doc:meta])* $name:ident ($schema:literal): $min:expr, $max:expr, $($flag:ident)* => $rule:literal;)*) => {
        $(
            $(#[$doc])*
            #[derive(Debug, Clone, PartialEq)]
            pub struct $name;
            impl Range for $name {
                const NAME: &'static str = $schema;
                const MIN: f64 = $min;
                const MAX: f64 = $max;
                $(const $flag: bool = true;)*
                const RULE: &'static str = $rule;
            }
        )*
        /// Every range of the table: (JSON Schema name, minimum, maximum, rule).
        pub const TABLE: &[(&str, f64, f64, &str)] = &[$(($schema, $min, $max, $rule)),*];
    };
}

ranges! {
    // [gas]
    /// A compression ratio ε = (V_stroke + V_comp)/V_comp.
    CompressionRatio("CompressionRatio"): 1.0, 50.0, MIN_OPEN => "must be greater than 1 and at most 50: ε = (V_stroke + V_comp)/V_comp > 1 needs a clearance volume; engines run 8 to about 25 (Karhula's 12, Nunes's 10), and 50 leaves a clearance of 2 % of the swept volume";
    /// A compressor's clearance ratio c = V_comp/V_stroke.
    ClearanceRatio("ClearanceRatio"): 0.0, 1.0, => "must not be negative and at most 1: c = V_comp/V_stroke, 0 for no clearance; a clearance larger than the swept volume leaves a compressor that hardly delivers (this project's example: 0.05)";
    /// A polytropic exponent of Karhula's pump and engine.
    PolytropicExponent("PolytropicExponent"): 1.0, 1.7, MIN_OPEN => "must be greater than 1 and at most 1.7: Karhula's compression (A6.1.1.11) needs n > 1 (1.3 to 1.4 for air, Karhula ch. 10); 5/3, a monatomic gas's ratio of specific heats, is the largest of an ideal gas";
    /// A compressor's polytropic exponent.
    CompressorExponent("CompressorExponent"): 1.0, 1.7, => "must be at least 1 (isothermal) and at most 1.7: 1.4 is air's isentropic exponent, and 5/3, a monatomic gas's, the largest ratio of specific heats of an ideal gas";
    /// A ratio of specific heats γ.
    HeatCapacityRatio("HeatCapacityRatio"): 1.0, 1.7, MIN_OPEN => "must be greater than 1 and at most 1.7: γ = c_p/c_v > 1 for any gas, 1.4 for air (Nunes Table 3.2), 5/3 for a monatomic gas, the largest of an ideal gas";
    /// Karhula's filling factor C_fill.
    Filling("Filling"): 0.0, 4.0, MIN_OPEN => "must be positive and at most 4: the intake charge as a fraction of the uncompressed volume at ambient pressure, 1.0 to 1.1 in Karhula (A6.1.1.11); above 1 a charge pressed in, and a boost pressure ratio of 4 is beyond supercharged engines";
    /// The relative air-fuel ratio λ.
    Lambda("Lambda"): 0.0, 3.0, MIN_OPEN => "must be positive and at most 3: λ = AFR/AFR_stoich; the combustion efficiency correlation (Nunes eq 2.56) holds only from about 0.43 to 1.81, which is checked next";
    /// A stoichiometric air-fuel ratio by mass.
    AirFuelRatio("AirFuelRatio"): 1.0, 40.0, => "must be from 1 to 40: fuels' stoichiometric air-fuel ratios by mass run from 1.7 (nitromethane) and 6.4 (methanol) to 14.7 (gasoline) and 34.3 (hydrogen); Nunes Table 3.2: 15.06";
    /// A fraction in (0, 1], an efficiency.
    Efficiency("Efficiency"): 0.0, 1.0, MIN_OPEN => "must be positive and at most 1: an efficiency (Blair's η_cmax, Nunes eq 2.56: 0.9)";
    /// Wiebe's efficiency parameter a.
    WiebeA("WiebeA"): 0.0, 50.0, MIN_OPEN => "must be positive and at most 50: a = −ln(1 − x_b) at the end of combustion (Nunes eq 2.28): 4.6 burns 99 %, 6.9 burns 99.9 % (Nunes: 5), and 50 leaves e^-50 unburned";
    /// Wiebe's form factor m.
    WiebeM("WiebeM"): -1.0, 20.0, MIN_OPEN => "must be greater than -1 and at most 20: the Wiebe exponent m + 1 must be positive (Nunes eq 2.28; Nunes: 2); at m = 20 the whole burn falls into the last fifth of its duration";
    /// Annand's Nusselt coefficient.
    AnnandA("AnnandA"): 0.0, 2.0, => "must be from 0 to 2: Annand's a in Nu = a·Re^0.7 is 0.35 to 0.8, rising with the charge's motion (0.49 for four-strokes, Nunes eq 2.30); 0 turns convection off";
    /// A radiation constant, W/(m²·K⁴).
    RadiationCoefficient("RadiationCoefficient"): 0.0, 5.670_374_419e-8, => "must be from 0 to 5.670374419e-8 W/(m²·K⁴): radiation is at most a black body's, the Stefan–Boltzmann constant σ (Nunes eq 2.37: 4.25e-9); 0 turns radiation off";
    // [friction]
    /// A Coulomb friction coefficient μ.
    FrictionCoefficient("FrictionCoefficient"): 0.0, 1.0, => "must not be negative and at most 1: a Coulomb friction coefficient; lubricated metal pairs run 0.001 to 0.1 (Karhula's ring 0.07, skirt 0.09, A9.1.4-5) and even dry steel on steel stays below 1";
    /// Palmgren's lubrication factor f0.
    LubricationFactor("LubricationFactor"): 0.0, 20.0, MIN_OPEN => "must be positive and at most 20: Palmgren's f0 runs from about 1 to 12 over rolling bearings' types and lubrication (Karhula: 2, docs/validation/rolling-bearings.md)";
    /// The constant of Karhula's bearing load term.
    BearingLoadConstant("BearingLoadConstant"): 0.0, 0.1, MIN_OPEN => "must be positive and at most 0.1: 0.0009 reproduces Karhula's tables and 0.009 is printed in A9.1.26-27; 0.1 is ten times the larger";
    /// A journal's length over its diameter L/D.
    JournalLengthRatio("JournalLengthRatio"): 0.0, 4.0, MIN_OPEN => "must be positive and at most 4: L/D of engine journals is about 0.3 to 0.6 (default 0.5), and the short-bearing solution holds up to about 1; 4 is a long sleeve";
    /// A journal's radial clearance over its radius c/R.
    JournalClearanceRatio("JournalClearanceRatio"): 0.0, 0.05, MIN_OPEN => "must be positive and at most 0.05: c/R of journal bearings is about 0.001 (the rule of a clearance of a thousandth of the radius, the default); 0.05 is a loose fit no film carries";
    // [load], [flywheel], [motion]
    /// k of a load's term k·ω, N·m·s/rad.
    TorquePerSpeed("TorquePerSpeed"): -1e6, 1e6, => "must be from -1e6 to 1e6 N·m·s/rad: at 1 rad/s that is a meganewton-metre, beyond a ship's diesel (this project's motor: -1.19 to -3.56)";
    /// k of a load's term k·ω², N·m·s²/rad².
    TorquePerSpeedSquared("TorquePerSpeedSquared"): -1e6, 1e6, => "must be from -1e6 to 1e6 N·m·s²/rad²: at 1 rad/s that is a meganewton-metre, beyond a ship's diesel";
    /// A coefficient of fluctuation of speed.
    FluctuationCoefficient("FluctuationCoefficient"): 1e-4, 1.0, MAX_OPEN => "must be from 1e-4 to 1 (exclusive): Cs = (ω_max − ω_min)/ω_mean; machines are designed for about 0.002 (electric generators) to 0.2 (crushers), and a ripple as large as the mean speed cannot be met";
    /// A fraction of a cycle's start speed.
    /// An optimisation's last step, a fraction of each variable's range.
    OptimizeTolerance("OptimizeTolerance"): 1e-6, 0.01, => "must lie from 1e-6 to 0.01: the search's last step as a fraction of each variable's range (default 1e-4); below 1e-6 the objective's own round-off, above 1 % a coarse optimum";
    SteadyTolerance("SteadyTolerance"): 0.0, 1.0, MIN_OPEN MAX_OPEN => "must be between 0 and 1 (exclusive): a fraction of the cycle's start speed (this project's cases: 1e-5)";
    // [gear]
    /// The teeth of the cardan wheel.
    Teeth("GearTeeth"): 5.0, 1000.0, WHOLE => "must be a whole number from 5 to 1000 (the teeth of the mesh's first gear: the cardan wheel)";
    /// A ring gear's addendum in modules.
    RingAddendum("GearRingAddendum"): 0.0, 1.5, => "must be from 0 to 1.5 modules (1 is a full addendum)";
    /// A profile shift coefficient.
    ProfileShift("GearProfileShift"): -1.0, 1.0, => "profile shift coefficients must be from -1 to 1";
    /// An AGMA quality number.
    QualityNumber("GearQualityNumber"): 5.0, 12.0, => "must be an AGMA quality number Qv from 5 to 12";
    /// Brinell hardness of through-hardened steel.
    Hardness("GearHardness"): 140.0, 400.0, => "must be from 140 to 400 HB (through-hardened steel, AGMA 2001-D04 Figs. 3 and 8)";
    /// An ISO 1328-1 accuracy grade.
    AccuracyGrade("GearAccuracyGrade"): 1.0, 12.0, => "must be an ISO 1328-1 accuracy grade from 1 to 12 (the gear file's range; ISO 6336-1 method B's K_v and K_Hα read the deviations of the grade)";
    /// An ISO 6336-1 application factor K_A.
    ApplicationFactor("GearApplicationFactor"): 1.0, 4.0, => "must be from 1 to 4: ISO 6336-1:2019 Annex B Table B.1 runs from 1.00 (uniform driver and driven machine) to 2.25 (heavy shocks on both), and 4 is well beyond it";
    /// An ISO 6336-1 load factor K_v, K_Hα or K_Hβ given in place of its computed value.
    IsoLoadFactor("GearIsoLoadFactor"): 1.0, 4.0, => "must be from 1 to 4: ISO 6336-1's K_v, K_Hα and K_Hβ multiply the nominal load and are at least 1 (K_v of a gear run near its resonance, K_Hβ of a load on one end of the face, stay well below 4; ISO 6336-1:2019 §§6-8)";
    /// An AGMA bending geometry factor.
    GeometryFactorJ("GearGeometryFactorJ"): 0.0, 1.0, MIN_OPEN MAX_OPEN => "bending geometry factors J must be between 0 and 1";
}
