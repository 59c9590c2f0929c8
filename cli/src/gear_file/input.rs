//! Reading a gear file: the TOML tables, each value in SI and validated once.

use super::*;
use cardan_case::units::{is_folder_name, to_si, Dimension};
use cardan_gears::agma::factors::{
    bending_allowable_through_hardened, contact_allowable_through_hardened, Grade,
};
use cardan_gears::{
    cardan_module, dynamic_factor, elastic_coefficient, pitting_cycle_factor,
    reliability_factor_fit, reliability_factor_table, BendingHighCycle, BendingLowCycle, Enclosure,
    GearError, GearPair, GearSpec, IForm, LoadDistribution, PairSpec, Quality, Tip,
};
use serde::Deserialize;
use std::path::Path;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawGearFile {
    name: String,
    module: Option<toml::Value>,
    cardan_crank_length: Option<toml::Value>,
    pressure_angle: toml::Value,
    teeth: toml::Value,
    profile_shift: Option<toml::Value>,
    center_distance: Option<toml::Value>,
    tip_diameter: Option<toml::Value>,
    addendum_coefficient: Option<toml::Value>,
    dedendum_coefficient: Option<toml::Value>,
    thickness_allowance: Option<toml::Value>,
    face_width: Option<toml::Value>,
    min_teeth_difference: Option<toml::Value>,
    rating: Option<RawRating>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawRating {
    power: Option<toml::Value>,
    torque: Option<toml::Value>,
    pinion_speed: toml::Value,
    quality: Option<toml::Value>,
    accuracy_level: Option<toml::Value>,
    dynamic_factor: Option<toml::Value>,
    overload_factor: Option<toml::Value>,
    reliability: Option<toml::Value>,
    reliability_factor: Option<toml::Value>,
    temperature_factor: Option<toml::Value>,
    surface_condition_factor: Option<toml::Value>,
    pinion_cycles: Option<toml::Value>,
    bending_cycle_low: Option<String>,
    bending_cycle_high: Option<String>,
    pitting_nitrided: Option<bool>,
    geometry_factor_i: Option<toml::Value>,
    elastic_coefficient: Option<toml::Value>,
    hardness_ratio_factor: Option<toml::Value>,
    enclosure: Option<String>,
    crowned: Option<bool>,
    offset_ratio: Option<toml::Value>,
    adjusted_at_assembly: Option<bool>,
    required_safety_factor: Option<toml::Value>,
    pinion: RawMember,
    gear: RawMember,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawMember {
    j: toml::Value,
    rim_factor: Option<toml::Value>,
    lewis_y: Option<toml::Value>,
    size_factor: Option<toml::Value>,
    hardness: Option<toml::Value>,
    grade: Option<toml::Value>,
    bending_allowable: Option<toml::Value>,
    contact_allowable: Option<toml::Value>,
    youngs_modulus: Option<toml::Value>,
    poisson_ratio: Option<toml::Value>,
}

type Invalid<'a> = dyn Fn(&str, &dyn std::fmt::Display, &str) -> GearFileError + 'a;

/// Validates the text of a gear file; `file` is only for the messages.
pub fn parse(file: &Path, text: &str) -> Result<GearFile, GearFileError> {
    let raw: RawGearFile = toml::from_str(text).map_err(|e| GearFileError::Syntax {
        file: file.into(),
        message: e.to_string().trim_end().to_string(),
    })?;
    let name = raw.name.clone();
    let invalid = |field: &str, value: &dyn std::fmt::Display, rule: &str| GearFileError::Invalid {
        file: file.into(),
        name: name.clone(),
        field: field.to_string(),
        value: value.to_string(),
        rule: rule.to_string(),
    };
    if !is_folder_name(&raw.name) {
        return Err(invalid(
            "name",
            &format!("\"{}\"", raw.name),
            "must be a non-empty folder name of at most 200 letters, digits, '-', '_' and '.', not starting with '.'",
        ));
    }
    let given = given_fields(text);
    let length = |field: &str, v: &toml::Value| {
        to_si(v, Dimension::Length).map_err(|r| invalid(field, v, &r))
    };
    let positive_length = |field: &str, v: &toml::Value| {
        let x = length(field, v)?;
        if x > 0.0 {
            Ok(x)
        } else {
            Err(invalid(field, v, "must be positive"))
        }
    };
    let number = |field: &str, v: &toml::Value| {
        to_si(v, Dimension::Number).map_err(|r| invalid(field, v, &r))
    };

    // Teeth.
    let teeth = pair_of(&raw.teeth, "teeth", &invalid)?;
    let mut z = [0i32; 2];
    for k in 0..2 {
        z[k] = match teeth[k].as_integer() {
            Some(i) if (-100_000..=100_000).contains(&i) => i as i32,
            _ => {
                return Err(invalid(
                    "teeth",
                    &raw.teeth,
                    "must be two whole numbers [z1, z2] (z2 negative for an internal gear), |z| <= 100000",
                ))
            }
        };
    }

    // Module, or the cardan crank length it follows from.
    let (module, crank) = match (&raw.module, &raw.cardan_crank_length) {
        (Some(m), None) => {
            // A module is millimetres (ISO 54: 0.05…100 mm): a bare number above 0.1 m was
            // meant in mm, as a bare crank of 60 is refused in case files.
            let module = positive_length("module", m)?;
            if module > 0.1 && !m.is_str() {
                return Err(invalid(
                    "module",
                    m,
                    &format!("a bare number is in m: a module of {} m is implausible (ISO 54 modules run to 100 mm); write \"{} mm\" if you meant millimetres, or give the unit explicitly", cardan_case::units::short(module), cardan_case::units::short(module)),
                ));
            }
            (module, None)
        }
        (None, Some(e)) => {
            let e_si = positive_length("cardan_crank_length", e)?;
            let m = cardan_module(e_si, z[0].max(0) as u32).map_err(|err| {
                invalid(
                    "cardan_crank_length",
                    e,
                    &format!("gives no module m = 2e/z1: {err}"),
                )
            })?;
            (m, Some(e_si))
        }
        (Some(m), Some(_)) => {
            return Err(invalid(
                "module",
                m,
                "give module or cardan_crank_length (m = 2e/z1, Karhula A9.1.37), not both",
            ))
        }
        (None, None) => {
            return Err(invalid(
                "module",
                &"(missing)",
                "give module (a length, e.g. \"3 mm\") or cardan_crank_length",
            ))
        }
    };
    let pressure_angle = to_si(&raw.pressure_angle, Dimension::Angle)
        .map_err(|r| invalid("pressure_angle", &raw.pressure_angle, &r))?;

    let mut spec = PairSpec {
        module,
        pressure_angle,
        pinion: GearSpec::standard(z[0], 0.0),
        gear: GearSpec::standard(z[1], 0.0),
        centre_distance: None,
        min_teeth_difference: 10,
    };
    if let Some(v) = &raw.profile_shift {
        let x = pair_of(v, "profile_shift", &invalid)?;
        spec.pinion.shift = number("profile_shift", &x[0])?;
        spec.gear.shift = number("profile_shift", &x[1])?;
    }
    if let Some(v) = &raw.addendum_coefficient {
        let h = pair_of(v, "addendum_coefficient", &invalid)?;
        spec.pinion.tip = Tip::Coefficient(number("addendum_coefficient", &h[0])?);
        spec.gear.tip = Tip::Coefficient(number("addendum_coefficient", &h[1])?);
    }
    if let Some(v) = &raw.tip_diameter {
        if raw.addendum_coefficient.is_some() {
            return Err(invalid(
                "tip_diameter",
                v,
                "give tip_diameter or addendum_coefficient, not both",
            ));
        }
        let d = pair_of(v, "tip_diameter", &invalid)?;
        spec.pinion.tip = Tip::Diameter(positive_length("tip_diameter", &d[0])?);
        spec.gear.tip = Tip::Diameter(positive_length("tip_diameter", &d[1])?);
    }
    if let Some(v) = &raw.dedendum_coefficient {
        let h = pair_of(v, "dedendum_coefficient", &invalid)?;
        spec.pinion.dedendum_coefficient = number("dedendum_coefficient", &h[0])?;
        spec.gear.dedendum_coefficient = number("dedendum_coefficient", &h[1])?;
    }
    if let Some(v) = &raw.thickness_allowance {
        let t = pair_of(v, "thickness_allowance", &invalid)?;
        spec.pinion.thickness_allowance = length("thickness_allowance", &t[0])?;
        spec.gear.thickness_allowance = length("thickness_allowance", &t[1])?;
    }
    if let Some(v) = &raw.center_distance {
        spec.centre_distance = Some(positive_length("center_distance", v)?);
    }
    if let Some(v) = &raw.min_teeth_difference {
        spec.min_teeth_difference = match v.as_integer() {
            Some(i) if (0..=1000).contains(&i) => i as u32,
            _ => {
                return Err(invalid(
                    "min_teeth_difference",
                    v,
                    "must be a whole number from 0 to 1000",
                ))
            }
        };
    }
    // The geometry is validated here, so that a bad pair is an input error of this file.
    GearPair::new(spec).map_err(|e| geometry_error(e, &raw, &invalid))?;

    let face_width = raw
        .face_width
        .as_ref()
        .map(|v| positive_length("face_width", v))
        .transpose()?;
    let rating = match &raw.rating {
        None => None,
        Some(r) => {
            if face_width.is_none() {
                return Err(invalid(
                    "face_width",
                    &"(missing)",
                    "a pair with a [rating] table needs its face width",
                ));
            }
            Some(parse_rating(r, &invalid)?)
        }
    };
    Ok(GearFile {
        file: file.into(),
        name: raw.name,
        spec,
        cardan_crank_length: crank,
        face_width,
        rating,
        given,
    })
}

/// `[a, b]` of a two-entry array field.
fn pair_of(
    v: &toml::Value,
    field: &str,
    invalid: &Invalid,
) -> Result<[toml::Value; 2], GearFileError> {
    match v.as_array() {
        Some(a) if a.len() == 2 => Ok([a[0].clone(), a[1].clone()]),
        _ => Err(invalid(
            field,
            v,
            "must be a list of two values [pinion, gear]",
        )),
    }
}

/// Names the file's field behind an input error of the geometry.
fn geometry_error(e: GearError, raw: &RawGearFile, invalid: &Invalid) -> GearFileError {
    let GearError::InvalidInput { field, rule, value } = e else {
        return invalid("teeth", &raw.teeth, &e.to_string());
    };
    let tip_field = if raw.tip_diameter.is_some() {
        "tip_diameter"
    } else {
        "addendum_coefficient"
    };
    let name = match field {
        "module" if raw.module.is_none() => "cardan_crank_length",
        "module" => "module",
        "pressure_angle" => "pressure_angle",
        "pinion.teeth" | "gear.teeth" => "teeth",
        "pinion.shift" | "gear.shift" | "shift" => "profile_shift",
        "pinion.dedendum_coefficient" | "gear.dedendum_coefficient" => "dedendum_coefficient",
        "pinion.thickness_allowance" | "gear.thickness_allowance" => "thickness_allowance",
        "centre_distance" => "center_distance",
        "tip diameter" => "tip_diameter",
        _ => tip_field,
    };
    let given = match name {
        "cardan_crank_length" => raw.cardan_crank_length.clone(),
        "module" => raw.module.clone(),
        "pressure_angle" => Some(raw.pressure_angle.clone()),
        "teeth" => Some(raw.teeth.clone()),
        "profile_shift" => raw.profile_shift.clone(),
        "dedendum_coefficient" => raw.dedendum_coefficient.clone(),
        "thickness_allowance" => raw.thickness_allowance.clone(),
        "center_distance" => raw.center_distance.clone(),
        "tip_diameter" => raw.tip_diameter.clone(),
        _ => raw.addendum_coefficient.clone(),
    };
    let detail = format!("{rule} (as computed: {field} = {value})");
    match given {
        Some(v) => invalid(name, &v, &detail),
        None => invalid(name, &"(default)", &detail),
    }
}

fn parse_rating(r: &RawRating, invalid: &Invalid) -> Result<RatingInputs, GearFileError> {
    let quantity = |field: &str, v: &toml::Value, q: Dimension| {
        to_si(v, q).map_err(|rule| invalid(field, v, &rule))
    };
    let number = |field: &str, v: &toml::Value| {
        to_si(v, Dimension::Number).map_err(|rule| invalid(field, v, &rule))
    };
    let positive_number = |field: &str, v: &toml::Value| {
        let x = number(field, v)?;
        if x > 0.0 {
            Ok(x)
        } else {
            Err(invalid(field, v, "must be positive"))
        }
    };
    let factor = |field: &str, v: &Option<toml::Value>| match v {
        Some(v) => positive_number(field, v),
        None => Ok(1.0),
    };
    let gear_err =
        |field: &str, v: &dyn std::fmt::Display, e: GearError| invalid(field, v, &e.to_string());

    let load = match (&r.power, &r.torque) {
        (Some(p), None) => Load::Power(quantity("rating.power", p, Dimension::Power)?),
        (None, Some(t)) => Load::Torque(quantity("rating.torque", t, Dimension::Torque)?),
        (Some(p), Some(_)) => {
            return Err(invalid(
                "rating.power",
                p,
                "give power or the pinion torque, not both",
            ))
        }
        (None, None) => {
            return Err(invalid(
                "rating.power",
                &"(missing)",
                "give power (e.g. \"4 hp\", \"3 kW\") or the pinion torque (\"20 N*m\")",
            ))
        }
    };
    let (load_field, load_value) = match load {
        Load::Power(p) => ("rating.power", p),
        Load::Torque(t) => ("rating.torque", t),
    };
    if load_value <= 0.0 {
        let v = r
            .power
            .as_ref()
            .or(r.torque.as_ref())
            .unwrap_or(&r.pinion_speed);
        return Err(invalid(
            load_field,
            v,
            "must be positive (a pair without load has no rating: leave out [rating] for the geometry only)",
        ));
    }
    let pinion_speed = to_si(&r.pinion_speed, Dimension::AngularSpeed)
        .map_err(|rule| invalid("rating.pinion_speed", &r.pinion_speed, &rule))?;
    if pinion_speed <= 0.0 {
        return Err(invalid(
            "rating.pinion_speed",
            &r.pinion_speed,
            "must be positive",
        ));
    }

    let kv = match (&r.quality, &r.accuracy_level, &r.dynamic_factor) {
        (Some(q), None, None) => {
            let qv = number("rating.quality", q)?;
            dynamic_factor(Quality::Qv(qv), 0.0).map_err(|e| gear_err("rating.quality", q, e))?;
            KvInput::Quality(Quality::Qv(qv))
        }
        (None, Some(a), None) => {
            let av = number("rating.accuracy_level", a)?;
            dynamic_factor(Quality::Av(av), 0.0)
                .map_err(|e| gear_err("rating.accuracy_level", a, e))?;
            KvInput::Quality(Quality::Av(av))
        }
        (None, None, Some(k)) => {
            let kv = number("rating.dynamic_factor", k)?;
            if kv < 1.0 {
                return Err(invalid("rating.dynamic_factor", k, "must be >= 1"));
            }
            KvInput::Given(kv)
        }
        _ => {
            return Err(invalid(
                "rating.quality",
                &r.quality.clone().unwrap_or(toml::Value::String("(missing)".into())),
                "give exactly one of quality (AGMA 2001 Qv, 5-12), accuracy_level (AGMA 2101 Av, 6-12) or dynamic_factor (Kv)",
            ))
        }
    };

    let reliability_factor = match (&r.reliability, &r.reliability_factor) {
        (Some(v), None) => {
            let rel = number("rating.reliability", v)?;
            reliability_factor_table(rel)
                .or_else(|_| reliability_factor_fit(rel))
                .map_err(|e| gear_err("rating.reliability", v, e))?
        }
        (None, Some(v)) => positive_number("rating.reliability_factor", v)?,
        (Some(v), Some(_)) => {
            return Err(invalid(
                "rating.reliability",
                v,
                "give reliability or reliability_factor (KR), not both",
            ))
        }
        (None, None) => 1.0,
    };
    let pinion_cycles = match &r.pinion_cycles {
        Some(v) => {
            let n = number("rating.pinion_cycles", v)?;
            pitting_cycle_factor(n, false).map_err(|e| gear_err("rating.pinion_cycles", v, e))?;
            n
        }
        None => 1e7,
    };
    let bending_low =
        match r.bending_cycle_low.as_deref().unwrap_or("hb250") {
            "hb400" => BendingLowCycle::Hb400,
            "case-carburized" => BendingLowCycle::CaseCarburized,
            "hb250" => BendingLowCycle::Hb250,
            "nitrided" => BendingLowCycle::Nitrided,
            "hb160" => BendingLowCycle::Hb160,
            other => return Err(invalid(
                "rating.bending_cycle_low",
                &format!("\"{other}\""),
                "must be one of \"hb400\", \"case-carburized\", \"hb250\", \"nitrided\", \"hb160\"",
            )),
        };
    let bending_high = match r.bending_cycle_high.as_deref().unwrap_or("upper") {
        "upper" => BendingHighCycle::Upper,
        "lower" => BendingHighCycle::Lower,
        other => {
            return Err(invalid(
                "rating.bending_cycle_high",
                &format!("\"{other}\""),
                "must be \"upper\" (general) or \"lower\" (critical service)",
            ))
        }
    };
    let i = match &r.geometry_factor_i {
        None => IInput::Form(IForm::Lpstc),
        Some(toml::Value::String(s)) if s == "lpstc" => IInput::Form(IForm::Lpstc),
        Some(toml::Value::String(s)) if s == "pitch-point" => IInput::Form(IForm::PitchPoint),
        Some(v @ (toml::Value::Float(_) | toml::Value::Integer(_))) => {
            IInput::Given(positive_number("rating.geometry_factor_i", v)?)
        }
        Some(v) => {
            return Err(invalid(
                "rating.geometry_factor_i",
                v,
                "must be \"lpstc\" (AGMA 908), \"pitch-point\" (Shigley eq. 14-23) or a number",
            ))
        }
    };
    let enclosure = match r.enclosure.as_deref().unwrap_or("commercial") {
        "open" => Enclosure::Open,
        "commercial" => Enclosure::CommercialEnclosed,
        "precision" => Enclosure::PrecisionEnclosed,
        "extra-precision" => Enclosure::ExtraPrecisionEnclosed,
        other => {
            return Err(invalid(
                "rating.enclosure",
                &format!("\"{other}\""),
                "must be one of \"open\", \"commercial\", \"precision\", \"extra-precision\"",
            ))
        }
    };
    let offset_ratio = match &r.offset_ratio {
        Some(v) => {
            let x = number("rating.offset_ratio", v)?;
            if x < 0.0 {
                return Err(invalid("rating.offset_ratio", v, "must not be negative"));
            }
            x
        }
        None => 0.0,
    };

    let member = |which: &str, m: &RawMember| -> Result<MemberInputs, GearFileError> {
        let f = |k: &str| format!("rating.{which}.{k}");
        let j = positive_number(&f("j"), &m.j)?;
        let rim_factor = factor(&f("rim_factor"), &m.rim_factor)?;
        let lewis_y = m
            .lewis_y
            .as_ref()
            .map(|v| positive_number(&f("lewis_y"), v))
            .transpose()?;
        let size_factor = m
            .size_factor
            .as_ref()
            .map(|v| positive_number(&f("size_factor"), v))
            .transpose()?;
        if let (Some(v), Some(_)) = (&m.lewis_y, &m.size_factor) {
            return Err(invalid(
                &f("lewis_y"),
                v,
                "give lewis_y (Ks from Shigley eq. 14-10) or size_factor (Ks), not both",
            ));
        }
        let hardness = m
            .hardness
            .as_ref()
            .map(|v| positive_number(&f("hardness"), v))
            .transpose()?;
        let grade = match &m.grade {
            None => Grade::One,
            Some(v) => match v.as_integer() {
                Some(1) => Grade::One,
                Some(2) => Grade::Two,
                _ => return Err(invalid(&f("grade"), v, "must be 1 or 2 (AGMA 2001 grade)")),
            },
        };
        let allowable = |key: &str,
                         given: &Option<toml::Value>,
                         chart: fn(f64, Grade) -> Result<f64, GearError>|
         -> Result<f64, GearFileError> {
            match (given, hardness) {
                (Some(v), _) => {
                    let s = quantity(&f(key), v, Dimension::Pressure)?;
                    if s > 0.0 {
                        Ok(s)
                    } else {
                        Err(invalid(&f(key), v, "must be positive"))
                    }
                }
                (None, Some(hb)) => chart(hb, grade).map_err(|e| {
                    gear_err(&f("hardness"), m.hardness.as_ref().unwrap_or(&m.j), e)
                }),
                (None, None) => Err(invalid(
                    &f(key),
                    &"(missing)",
                    "give it (a stress, e.g. \"31350 psi\") or the Brinell hardness of a through-hardened steel (AGMA 2001 charts)",
                )),
            }
        };
        Ok(MemberInputs {
            j,
            rim_factor,
            lewis_y,
            size_factor,
            hardness,
            bending_allowable: allowable(
                "bending_allowable",
                &m.bending_allowable,
                bending_allowable_through_hardened,
            )?,
            contact_allowable: allowable(
                "contact_allowable",
                &m.contact_allowable,
                contact_allowable_through_hardened,
            )?,
        })
    };
    let members = [member("pinion", &r.pinion)?, member("gear", &r.gear)?];
    if members[0].lewis_y.is_some() != members[1].lewis_y.is_some() {
        return Err(invalid(
            "rating.gear.lewis_y",
            &r.gear
                .lewis_y
                .clone()
                .unwrap_or(toml::Value::String("(missing)".into())),
            "give lewis_y for both members or for neither",
        ));
    }

    let elastic = match &r.elastic_coefficient {
        Some(v) => {
            let cp = quantity("rating.elastic_coefficient", v, Dimension::RootStress)?;
            if cp <= 0.0 {
                return Err(invalid("rating.elastic_coefficient", v, "must be positive"));
            }
            cp
        }
        None => {
            let mut en = [(0.0, 0.0); 2];
            for (k, (which, m)) in [("pinion", &r.pinion), ("gear", &r.gear)]
                .iter()
                .enumerate()
            {
                let (Some(e), Some(nu)) = (&m.youngs_modulus, &m.poisson_ratio) else {
                    return Err(invalid(
                        "rating.elastic_coefficient",
                        &"(missing)",
                        &format!("give it (e.g. \"2300 sqrt(psi)\", \"190 sqrt(MPa)\") or youngs_modulus and poisson_ratio in [rating.{which}]"),
                    ));
                };
                en[k] = (
                    quantity(
                        &format!("rating.{which}.youngs_modulus"),
                        e,
                        Dimension::Pressure,
                    )?,
                    number(&format!("rating.{which}.poisson_ratio"), nu)?,
                );
            }
            elastic_coefficient(en[0].0, en[0].1, en[1].0, en[1].1).map_err(|e| {
                gear_err(
                    "rating.pinion.youngs_modulus",
                    r.pinion.youngs_modulus.as_ref().unwrap_or(&r.pinion.j),
                    e,
                )
            })?
        }
    };
    let required_safety_factor = match &r.required_safety_factor {
        None => 1.0,
        Some(v) => {
            let n = number("rating.required_safety_factor", v)?;
            if !n.is_finite() {
                return Err(invalid(
                    "rating.required_safety_factor",
                    v,
                    "must be a finite number",
                ));
            }
            if n < 1.0 {
                return Err(invalid(
                    "rating.required_safety_factor",
                    v,
                    "must be >= 1 (below 1 the pair is expected to break)",
                ));
            }
            n
        }
    };
    let hardness_ratio_factor = r
        .hardness_ratio_factor
        .as_ref()
        .map(|v| positive_number("rating.hardness_ratio_factor", v))
        .transpose()?;

    Ok(RatingInputs {
        load,
        pinion_speed,
        kv,
        overload: factor("rating.overload_factor", &r.overload_factor)?,
        reliability_factor,
        temperature_factor: factor("rating.temperature_factor", &r.temperature_factor)?,
        surface_condition: factor(
            "rating.surface_condition_factor",
            &r.surface_condition_factor,
        )?,
        pinion_cycles,
        bending_low,
        bending_high,
        nitrided: r.pitting_nitrided.unwrap_or(false),
        i,
        elastic_coefficient: elastic,
        hardness_ratio_factor,
        load_distribution: LoadDistribution {
            crowned: r.crowned.unwrap_or(false),
            offset_ratio,
            enclosure,
            adjusted_at_assembly: r.adjusted_at_assembly.unwrap_or(false),
        },
        members,
        required_safety_factor,
    })
}

/// The top-level and `[rating]` entries of the file as written, for the report.
fn given_fields(text: &str) -> Vec<(String, String)> {
    let Ok(table) = text.parse::<toml::Table>() else {
        return Vec::new();
    };
    let mut out = Vec::new();
    fn walk(prefix: &str, t: &toml::Table, out: &mut Vec<(String, String)>) {
        for (k, v) in t {
            let key = if prefix.is_empty() {
                k.clone()
            } else {
                format!("{prefix}.{k}")
            };
            match v {
                toml::Value::Table(sub) => walk(&key, sub, out),
                _ => out.push((key, v.to_string())),
            }
        }
    }
    walk("", &table, &mut out);
    out
}
