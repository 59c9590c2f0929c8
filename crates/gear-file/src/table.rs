//! The gear file's typed schema: one struct per table, `deny_unknown_fields`, each value a
//! [`Quantity`] in its dimension (units from the one table of `cardan_case::units`), words as
//! enums. Rules that join fields, and the physics' own ranges, are checked after reading
//! (`input.rs`). The doc comments are the JSON Schema's descriptions ([`gear_file_schema`]).

use cardan_case::quantity::{
    broken, Angle, AngularSpeed, Length, NonNegative, Number, Positive, Power, Pressure, Quantity,
    RootStress, Torque,
};
use schemars::{json_schema, JsonSchema, Schema, SchemaGenerator};
use serde::{de::DeserializeOwned, de::Error as _, Deserialize, Deserializer};
use std::borrow::Cow;

/// A gear pair's file: `name`, the geometry at the top level, `[rating]` for the AGMA rating.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct GearFileTable {
    /// The output folder's name (`DIR/<name>`): letters, digits, '-', '_' and '.', at most
    /// 200, not starting with '.'; required.
    pub name: String,
    /// Module m; m (a bare number above 0.1 is refused as meant in mm: ISO 54 modules run to
    /// 100 mm). Give it or `cardan_crank_length`.
    pub module: Option<Positive<Length>>,
    /// The cardan crank length e the module follows from, m = 2e/z1 (Karhula A9.1.37); m.
    /// Give it or `module`.
    pub cardan_crank_length: Option<Positive<Length>>,
    /// Reference (generating) pressure angle α, in (0°, 45°); degrees; required.
    pub pressure_angle: Quantity<Angle>,
    /// Teeth [z1, z2], whole numbers, |z| ≤ 100 000; z2 < 0 is an internal gear (ISO 21771),
    /// |z2| > z1; required.
    pub teeth: Pair<Teeth>,
    /// Profile shift coefficients [x1, x2], ISO 21771 signs (KHK's internal x2 = −ISO x2).
    /// Default [0, 0].
    pub profile_shift: Option<Pair<Quantity<Number>>>,
    /// Operating centre distance; m. Default the zero-backlash working centre distance.
    pub center_distance: Option<Positive<Length>>,
    /// Tip diameters [da1, da2] (a ring's: its inner circle); m. Give it or
    /// `addendum_coefficient`.
    pub tip_diameter: Option<Pair<Positive<Length>>>,
    /// Addendum coefficients [ha1, ha2], in modules. Default [1, 1] (ISO 53).
    pub addendum_coefficient: Option<Pair<Quantity<Number>>>,
    /// Dedendum coefficients [hf1, hf2], in modules. Default [1.25, 1.25] (ISO 53).
    pub dedendum_coefficient: Option<Pair<Quantity<Number>>>,
    /// Tip radius of the generating rack (a ring's: of the pinion-type cutter) [ρ1, ρ2], in
    /// modules, for the computed bending geometry factor J. Default [0.25, 0.25] (ISO 53
    /// profile C, the smallest ISO 53 tip radius).
    pub rack_tip_radius_coefficient: Option<Pair<Quantity<Number>>>,
    /// Tooth thinning [j1, j2] at the reference circle; m. Default [0, 0].
    pub thickness_allowance: Option<Pair<Quantity<Length>>>,
    /// Face width; m. Needed with `[rating]`.
    pub face_width: Option<Positive<Length>>,
    /// The smallest |z2| − z1 of an internal pair, a whole number from 0 to 1000. Default 10
    /// (AGMA 917-B97 as quoted by Nunes 2017, `cardan_gears::PairSpec::standard`).
    pub min_teeth_difference: Option<TeethDifference>,
    /// The AGMA 2001-D04 rating (and the ISO 6336 one beside it); without it, the geometry
    /// only.
    pub rating: Option<RatingTable>,
    /// Tooth thickness measurements (ISO 21771 §6.3, §6.4): span width over k teeth and the
    /// dimension over (between, for a ring) two pins or balls, with the thinning of
    /// `thickness_allowance`; without it, none.
    pub measurement: Option<MeasurementTable>,
}

/// `[measurement]`: what to measure the teeth with.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MeasurementTable {
    /// Teeth spanned [k1, k2] (external gears; a ring's entry is ignored), whole numbers
    /// from 1 to z - 1. Default: the span touching the flanks nearest d + 2xm.
    pub span_teeth: Option<Pair<SpanTeeth>>,
    /// Pin or ball diameters [D1, D2]; m. Default: the pin touching the flanks on d + 2xm.
    pub pin_diameter: Option<Pair<Positive<Length>>>,
}

/// Which standard the verdict's safety factors come from.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize, JsonSchema)]
#[serde(rename_all = "kebab-case")]
pub enum Basis {
    /// AGMA 2001-D04 SF and SH (the default).
    #[default]
    Agma2001,
    /// ISO 6336-2/-3:2019 method B S_F and S_H.
    Iso6336,
}

/// ISO 6336-5 material quality grade.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize, JsonSchema)]
#[serde(rename_all = "kebab-case")]
pub enum QualityWord {
    /// ML: modest demands.
    Ml,
    /// MQ: the usual industrial quality (default).
    #[default]
    Mq,
    /// ME: high reliability.
    Me,
}

/// `[rating]`: the load, the speed and the AGMA factors of the pair.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RatingTable {
    /// Transmitted power, positive; W. Give it or `torque`.
    pub power: Option<Quantity<Power>>,
    /// Pinion torque, positive; N·m. Give it or `power`.
    pub torque: Option<Quantity<Torque>>,
    /// Pinion speed relative to the gear's frame (a cardan gear's carrier); rad/s; required.
    pub pinion_speed: Positive<AngularSpeed>,
    /// AGMA 2001 quality number Qv (5-12), for Kv. Give one of `quality`, `accuracy_level`,
    /// `dynamic_factor`.
    pub quality: Option<Quantity<Number>>,
    /// AGMA 2101 accuracy level Av (6-12), for Kv.
    pub accuracy_level: Option<Quantity<Number>>,
    /// The dynamic factor Kv itself, at least 1.
    pub dynamic_factor: Option<Quantity<Number>>,
    /// Overload factor Ko. Default 1.
    pub overload_factor: Option<Positive<Number>>,
    /// Reliability R (AGMA table at 0.5, 0.9, 0.99, 0.999, 0.9999, else Shigley's fit). Give
    /// it or `reliability_factor`; default KR = 1.
    pub reliability: Option<Quantity<Number>>,
    /// Reliability factor KR. Default 1.
    pub reliability_factor: Option<Positive<Number>>,
    /// Temperature factor KT. Default 1.
    pub temperature_factor: Option<Positive<Number>>,
    /// Surface condition factor Cf. Default 1.
    pub surface_condition_factor: Option<Positive<Number>>,
    /// Load cycles of the pinion (the gear's: divided by the ratio). Default 1e7 (the cycles
    /// the AGMA 2001 charts are drawn for).
    pub pinion_cycles: Option<Quantity<Number>>,
    /// Low-cycle curve of the bending stress-cycle factor YN (AGMA 2001-D04 Fig. 18). Default
    /// "hb250".
    #[serde(default)]
    pub bending_cycle_low: BendingLow,
    /// High-cycle curve of YN. Default "upper".
    #[serde(default)]
    pub bending_cycle_high: BendingHigh,
    /// The nitrided curve of the pitting stress-cycle factor ZN. Default false.
    pub pitting_nitrided: Option<bool>,
    /// Pitting geometry factor I: "lpstc" (AGMA 908, the lowest point of single tooth
    /// contact), "pitch-point" (Shigley eq. 14-23) or a positive number. Default "lpstc".
    pub geometry_factor_i: Option<GeometryFactorI>,
    /// Elastic coefficient Cp; √Pa. Give it, or `youngs_modulus` and `poisson_ratio` in both
    /// member tables.
    pub elastic_coefficient: Option<Positive<RootStress>>,
    /// Hardness ratio factor CH of the gear. Default from the hardnesses (through-hardened).
    pub hardness_ratio_factor: Option<Positive<Number>>,
    /// Load distribution Km: the gearing's enclosure. Default "commercial".
    #[serde(default)]
    pub enclosure: EnclosureWord,
    /// Load distribution Km: crowned teeth. Default false.
    pub crowned: Option<bool>,
    /// Load distribution Km: the pinion's offset ratio S1/S. Default 0.
    pub offset_ratio: Option<NonNegative<Number>>,
    /// Load distribution Km: the mesh adjusted at assembly. Default false.
    pub adjusted_at_assembly: Option<bool>,
    /// The smallest bending SF and pitting SH each member must reach, at least 1. Default 1.
    pub required_safety_factor: Option<Quantity<Number>>,
    /// Which standard's safety factors decide the verdict: "agma2001" (default) or
    /// "iso6336" (ISO 6336-2/-3 method B; each member's Y_F and Y_S computed from the tooth
    /// form unless it gives `form_factor` and `stress_correction_factor`). The ISO rating is
    /// also computed, beside AGMA's, whenever a member gives `form_factor`.
    #[serde(default)]
    pub basis: Basis,
    /// ISO: application factor K_A. Default `overload_factor` (the same factor).
    pub application_factor: Option<Positive<Number>>,
    /// ISO: ISO 1328-1 accuracy grade (1-12) of both gears, for K_v and K_Hα by ISO 6336-1
    /// method B.
    pub accuracy_grade: Option<Quantity<Number>>,
    /// ISO: the dynamic factor K_v itself, at least 1 (instead of method B).
    pub iso_dynamic_factor: Option<Quantity<Number>>,
    /// ISO: face load factor K_Hβ, at least 1. Default AGMA 2001's empirical Km for the face
    /// width.
    pub face_load_factor: Option<Quantity<Number>>,
    /// ISO: transverse load factor K_Hα = K_Fα, at least 1. Default ISO 6336-1 method B.
    pub transverse_load_factor: Option<Quantity<Number>>,
    /// ISO: density of the gear blanks, for K_v method B; kg/m³ as a bare number. Default
    /// 7830 (steel).
    pub density: Option<Positive<Number>>,
    /// ISO: oil kinematic viscosity at 40 °C in mm²/s (a bare number), for Z_L, Z_v;
    /// with `flank_roughness`. Default: Z_L Z_v Z_R = 1.
    pub oil_viscosity: Option<Positive<Number>>,
    /// ISO: mean flank roughness Rz of the pair, for Z_R; m.
    pub flank_roughness: Option<Positive<Length>>,
    /// `[rating.pinion]`.
    pub pinion: MemberTable,
    /// `[rating.gear]`.
    pub gear: MemberTable,
}

/// `[rating.pinion]`, `[rating.gear]`: one member's factors and material.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MemberTable {
    /// AGMA bending geometry factor J, between 0 and 1 (the case file's `[gear] j`, read by
    /// the same type), given: it replaces the computed one. Default computed from the tooth
    /// form: AGMA 908-B89 for an external member, ISO 6336-3 method B for an internal ring
    /// (docs/gear-calculator.md).
    pub j: Option<cardan_case::gear::Ranged<cardan_case::gear::GeometryFactorJ>>,
    /// Rim thickness factor KB. Default 1.
    pub rim_factor: Option<Positive<Number>>,
    /// Lewis form factor Y, for the size factor Ks (Shigley eq. 14-10); both members or
    /// neither. Give it or `size_factor`; default Ks = 1.
    pub lewis_y: Option<Positive<Number>>,
    /// Size factor Ks.
    pub size_factor: Option<Positive<Number>>,
    /// Brinell hardness (core hardness of a nitrided steel): St and Sc from the AGMA charts
    /// (140-400 HB through-hardened steel when no `material` is named), and σ_Hlim, σ_Flim
    /// of a through-hardened steel or grey iron.
    pub hardness: Option<Positive<Number>>,
    /// AGMA 2001 grade, 1 or 2 (3 for case-carburized steel). Default 1.
    pub grade: Option<GradeNumber>,
    /// Allowable bending stress number St; Pa. Default from `hardness`.
    pub bending_allowable: Option<Positive<Pressure>>,
    /// Allowable contact stress number Sc; Pa. Default from `hardness`.
    pub contact_allowable: Option<Positive<Pressure>>,
    /// Young's modulus, for Cp; Pa.
    pub youngs_modulus: Option<Quantity<Pressure>>,
    /// Poisson's ratio, for Cp.
    pub poisson_ratio: Option<Quantity<Number>>,
    /// A material of the table (`cardan_gears::materials`): "steel-through-hardened",
    /// "steel-case-carburized", "steel-nitrided", "nitriding-steel", "grey-cast-iron",
    /// "tin-bronze", "aluminium-bronze". Gives E and ν (so Cp / Z_E), the AGMA allowables by
    /// `grade` and `hardness` and the ISO 6336-5 limits by `iso_quality`; stresses given here
    /// override it.
    pub material: Option<String>,
    /// ISO 6336-5 material quality "ml", "mq" (default) or "me".
    #[serde(default)]
    pub iso_quality: QualityWord,
    /// ISO 6336-3 tooth form factor Y_F (method B, load at the outer point of single tooth
    /// contact), positive; needed for the ISO rating.
    pub form_factor: Option<Positive<Number>>,
    /// ISO 6336-3 stress correction factor Y_S, positive; needed for the ISO rating.
    pub stress_correction_factor: Option<Positive<Number>>,
    /// ISO 6336-5 allowable stress number (contact) σ_Hlim; Pa. Default from `material`.
    pub sigma_hlim: Option<Positive<Pressure>>,
    /// ISO 6336-5 nominal stress number (bending) σ_Flim; Pa. Default from `material`.
    pub sigma_flim: Option<Positive<Pressure>>,
}

/// YN's low-cycle curve.
#[derive(Debug, Clone, Copy, Default, Deserialize, JsonSchema)]
#[serde(rename_all = "kebab-case")]
pub enum BendingLow {
    /// 400 HB.
    Hb400,
    /// Case carburized.
    CaseCarburized,
    /// 250 HB.
    #[default]
    Hb250,
    /// Nitrided.
    Nitrided,
    /// 160 HB.
    Hb160,
}

/// YN's high-cycle curve.
#[derive(Debug, Clone, Copy, Default, Deserialize, JsonSchema)]
#[serde(rename_all = "kebab-case")]
pub enum BendingHigh {
    /// General applications.
    #[default]
    Upper,
    /// Critical service.
    Lower,
}

/// The gearing's enclosure, for Km (AGMA 2001-D04, Shigley Table 14-9).
#[derive(Debug, Clone, Copy, Default, Deserialize, JsonSchema)]
#[serde(rename_all = "kebab-case")]
pub enum EnclosureWord {
    /// Open gearing.
    Open,
    /// Commercial enclosed units.
    #[default]
    Commercial,
    /// Precision enclosed units.
    Precision,
    /// Extra-precision enclosed units.
    ExtraPrecision,
}

/// The pitting geometry factor I: how it is computed, or its value.
#[derive(Debug, Clone, PartialEq)]
pub enum GeometryFactorI {
    /// AGMA 908, at the lowest point of single tooth contact.
    Lpstc,
    /// Shigley eq. 14-23, at the pitch point.
    PitchPoint,
    /// Given.
    Given(f64),
}

impl<'de> Deserialize<'de> for GeometryFactorI {
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        let v = toml::Value::deserialize(deserializer)?;
        match &v {
            toml::Value::String(s) if s == "lpstc" => Ok(Self::Lpstc),
            toml::Value::String(s) if s == "pitch-point" => Ok(Self::PitchPoint),
            toml::Value::Float(_) | toml::Value::Integer(_) => Positive::<Number>::from_value(&v)
                .map(|q| Self::Given(q.si))
                .map_err(|rule| De::Error::custom(broken(&v, &rule))),
            _ => Err(De::Error::custom(broken(
                &v,
                "must be \"lpstc\" (AGMA 908), \"pitch-point\" (Shigley eq. 14-23) or a number",
            ))),
        }
    }
}

impl JsonSchema for GeometryFactorI {
    fn schema_name() -> Cow<'static, str> {
        "GeometryFactorI".into()
    }

    fn json_schema(_: &mut SchemaGenerator) -> Schema {
        json_schema!({
            "anyOf": [
                { "enum": ["lpstc", "pitch-point"] },
                { "type": "number", "exclusiveMinimum": 0 }
            ]
        })
    }
}

/// A whole number read from a TOML integer, in `[MIN, MAX]`, or the rule it breaks.
fn whole<'de, De: Deserializer<'de>>(
    deserializer: De,
    range: std::ops::RangeInclusive<i64>,
    rule: &str,
) -> Result<i64, De::Error> {
    let v = toml::Value::deserialize(deserializer)?;
    match v.as_integer() {
        Some(i) if range.contains(&i) => Ok(i),
        _ => Err(De::Error::custom(broken(&v, rule))),
    }
}

/// A number of teeth, z2 negative for an internal gear.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Teeth(pub i32);

impl<'de> Deserialize<'de> for Teeth {
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        let rule =
            "must be two whole numbers [z1, z2] (z2 negative for an internal gear), |z| <= 100000";
        whole(deserializer, -100_000..=100_000, rule).map(|i| Teeth(i as i32))
    }
}

/// The smallest teeth difference of an internal pair.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TeethDifference(pub u32);

impl<'de> Deserialize<'de> for TeethDifference {
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        whole(
            deserializer,
            0..=1000,
            "must be a whole number from 0 to 1000",
        )
        .map(|i| TeethDifference(i as u32))
    }
}

/// Teeth spanned by a span measurement.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpanTeeth(pub u32);

impl<'de> Deserialize<'de> for SpanTeeth {
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        whole(
            deserializer,
            1..=100_000,
            "must be a whole number of teeth, at least 1",
        )
        .map(|i| SpanTeeth(i as u32))
    }
}

/// An AGMA 2001 grade, 1, 2 or 3 (3: case-carburized only).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GradeNumber(pub u8);

impl<'de> Deserialize<'de> for GradeNumber {
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        whole(deserializer, 1..=3, "must be 1, 2 or 3 (AGMA 2001 grade)")
            .map(|i| GradeNumber(i as u8))
    }
}

macro_rules! whole_schema {
    ($($name:ident: $min:expr, $max:expr;)*) => {$(
        impl JsonSchema for $name {
            fn schema_name() -> Cow<'static, str> {
                stringify!($name).into()
            }

            fn json_schema(_: &mut SchemaGenerator) -> Schema {
                json_schema!({ "type": "integer", "minimum": $min, "maximum": $max })
            }
        }
    )*};
}

whole_schema! {
    Teeth: -100_000, 100_000;
    TeethDifference: 0, 1000;
    GradeNumber: 1, 3;
    SpanTeeth: 1, 100_000;
}

/// Two values, [pinion, gear].
#[derive(Debug, Clone, PartialEq)]
pub struct Pair<T>(pub [T; 2]);

impl<D, const RULE: u8> Pair<Quantity<D, RULE>> {
    /// [pinion, gear] in SI.
    pub fn si(&self) -> [f64; 2] {
        [self.0[0].si, self.0[1].si]
    }
}

impl<'de, T: DeserializeOwned> Deserialize<'de> for Pair<T> {
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        let value = toml::Value::deserialize(deserializer)?;
        let one =
            |v: &toml::Value| T::deserialize(v.clone()).map_err(|e| De::Error::custom(e.message()));
        match value.as_array() {
            Some(a) if a.len() == 2 => Ok(Pair([one(&a[0])?, one(&a[1])?])),
            _ => Err(De::Error::custom(broken(
                &value,
                "must be a list of two values [pinion, gear]",
            ))),
        }
    }
}

impl<T: JsonSchema> JsonSchema for Pair<T> {
    fn schema_name() -> Cow<'static, str> {
        format!("Pair_{}", T::schema_name()).into()
    }

    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        let one = generator.subschema_for::<T>();
        json_schema!({
            "description": "[pinion, gear]",
            "type": "array", "items": one, "minItems": 2, "maxItems": 2
        })
    }
}

/// The JSON Schema of a gear file, for `cargo xtask schema` and editors.
pub fn gear_file_schema() -> serde_json::Value {
    schemars::schema_for!(GearFileTable).to_value()
}
