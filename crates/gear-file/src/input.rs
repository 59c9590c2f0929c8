//! Reading a gear file: the typed tables of `table.rs`, read by `cardan_case::schema::read`
//! (a misspelled field or word is named with its path and the nearest valid name), then the
//! rules that join fields and the physics' own ranges, each value in SI and validated once.

use super::iso_input;
use super::table::{
    BendingHigh, BendingLow, EnclosureWord, GearFileTable, GeometryFactorI, MemberTable,
    RatingTable,
};
use super::validated::*;
use cardan_case::quantity::{Number, Positive, Pressure};
use cardan_case::units::{is_folder_name, short};
use cardan_gears::agma::factors::{
    bending_allowable_through_hardened, contact_allowable_through_hardened, Grade,
};
use cardan_gears::{
    cardan_module, check_pitch_line_velocity, dynamic_factor, elastic_coefficient,
    pitting_cycle_factor, reliability_factor_fit, reliability_factor_table, BendingHighCycle,
    BendingLowCycle, Enclosure, GearError, GearPair, IForm, LoadDistribution, PairSpec, Quality,
    Tip,
};
use std::path::Path;

/// Pinion load cycles when not given: the 10⁷ cycles the AGMA 2001-D04 stress-cycle factors
/// are 1 at (Figs. 18 and 19).
pub const DEFAULT_PINION_CYCLES: f64 = 1e7;

type Invalid<'a> = dyn Fn(&str, &dyn std::fmt::Display, &str) -> GearFileError + 'a;

/// Validates the text of a gear file; `file` is only for the messages.
pub fn parse(file: &Path, text: &str) -> Result<GearFile, GearFileError> {
    let table: toml::Table = toml::from_str(text).map_err(|e| GearFileError::Syntax {
        file: file.into(),
        message: e.to_string().trim_end().to_string(),
    })?;
    let name = match table.get("name") {
        Some(toml::Value::String(s)) => s.clone(),
        _ => "(unnamed)".to_string(),
    };
    let invalid = |field: &str, value: &dyn std::fmt::Display, rule: &str| GearFileError::Invalid {
        file: file.into(),
        name: name.clone(),
        field: field.to_string(),
        value: value.to_string(),
        rule: rule.to_string(),
    };
    let raw: GearFileTable = cardan_case::schema::read(toml::Value::Table(table.clone()), "")
        .map_err(|error| {
            match error
                .message
                .strip_prefix("= ")
                .and_then(|m| m.split_once(": "))
            {
                Some((value, rule)) => invalid(&error.field, &value, rule),
                None => GearFileError::Field {
                    file: file.into(),
                    name: name.clone(),
                    error,
                },
            }
        })?;
    if !is_folder_name(&raw.name) {
        return Err(invalid(
            "name",
            &format!("\"{}\"", raw.name),
            "must be a non-empty folder name of at most 200 letters, digits, '-', '_' and '.', not starting with '.'",
        ));
    }
    let given = given_fields(text);
    let z = raw.teeth.0.map(|t| t.0);

    let (module, crank) = module_of(&raw, z, &invalid)?;
    let spec = pair_spec(&raw, &table, module, z, &invalid)?;
    // The geometry is validated here, so that a bad pair is an input error of this file.
    let pair = GearPair::new(spec).map_err(|e| geometry_error(e, &table, &invalid))?;

    let rack_tip_radius = rack_tip_radius(&raw, &table, module, &invalid)?;
    let face_width = raw.face_width.as_ref().map(|w| w.si);
    let rating = rating_of(&raw, face_width, &pair, &invalid)?;
    if let Some(r) = &rating {
        computable_j(r, &pair, rack_tip_radius, &table, &invalid)?;
    }
    let measurement = iso_input::measurement(&raw.measurement, z, &invalid)?;
    Ok(GearFile {
        file: file.into(),
        name: raw.name,
        spec,
        cardan_crank_length: crank,
        face_width,
        rack_tip_radius,
        rating,
        measurement,
        given,
    })
}

/// The module, m, and the cardan crank length it follows from, if the file gives that instead
/// (`module` or `cardan_crank_length`, exactly one).
fn module_of(
    raw: &GearFileTable,
    z: [i32; 2],
    invalid: &Invalid,
) -> Result<(f64, Option<f64>), GearFileError> {
    Ok(match (&raw.module, &raw.cardan_crank_length) {
        (Some(m), None) => {
            // A module is millimetres (ISO 54: 0.05…100 mm): a bare number above 0.1 m was
            // meant in mm, as a bare crank of 60 is refused in case files.
            if m.si > 0.1 && !m.written.starts_with('"') {
                let x = short(m.si);
                return Err(invalid(
                    "module",
                    &m.written,
                    &format!("a bare number is in m: a module of {x} m is implausible (ISO 54 modules run to 100 mm); write \"{x} mm\" if you meant millimetres, or give the unit explicitly"),
                ));
            }
            (m.si, None)
        }
        (None, Some(e)) => {
            let m = cardan_module(e.si, z[0].max(0) as u32).map_err(|err| {
                invalid(
                    "cardan_crank_length",
                    &e.written,
                    &format!("gives no module m = 2e/z1: {err}"),
                )
            })?;
            (m, Some(e.si))
        }
        (Some(m), Some(_)) => {
            return Err(invalid(
                "module",
                &m.written,
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
    })
}

/// The pair's specification from the module and the file's teeth, pressure angle, profile
/// shifts, tips, dedenda, thickness allowances, centre distance and teeth difference.
fn pair_spec(
    raw: &GearFileTable,
    table: &toml::Table,
    module: f64,
    z: [i32; 2],
    invalid: &Invalid,
) -> Result<PairSpec, GearFileError> {
    let mut spec = PairSpec::standard(module, z[0], z[1], raw.pressure_angle.si, 0.0, 0.0);
    if let Some(x) = &raw.profile_shift {
        [spec.pinion.shift, spec.gear.shift] = x.si();
    }
    if let Some(h) = &raw.addendum_coefficient {
        let h = h.si();
        spec.pinion.tip = Tip::Coefficient(h[0]);
        spec.gear.tip = Tip::Coefficient(h[1]);
    }
    if let Some(d) = &raw.tip_diameter {
        if raw.addendum_coefficient.is_some() {
            return Err(invalid(
                "tip_diameter",
                &table["tip_diameter"],
                "give tip_diameter or addendum_coefficient, not both",
            ));
        }
        let d = d.si();
        spec.pinion.tip = Tip::Diameter(d[0]);
        spec.gear.tip = Tip::Diameter(d[1]);
    }
    if let Some(h) = &raw.dedendum_coefficient {
        [
            spec.pinion.dedendum_coefficient,
            spec.gear.dedendum_coefficient,
        ] = h.si();
    }
    if let Some(t) = &raw.thickness_allowance {
        [
            spec.pinion.thickness_allowance,
            spec.gear.thickness_allowance,
        ] = t.si();
    }
    spec.centre_distance = raw.center_distance.as_ref().map(|c| c.si);
    if let Some(d) = raw.min_teeth_difference {
        spec.min_teeth_difference = d.0;
    }
    Ok(spec)
}

/// A J not given must be computable from the tooth form (`super::rating::member_j`): else
/// the file is refused here, so that `cardan check` refuses what `cardan gear` cannot rate.
fn computable_j(
    r: &RatingInputs,
    pair: &GearPair,
    tips: [Option<f64>; 2],
    table: &toml::Table,
    invalid: &Invalid,
) -> Result<(), GearFileError> {
    for (k, which) in ["pinion", "gear"].into_iter().enumerate() {
        if r.members[k].j.is_some() {
            continue;
        }
        if let Err(e) = super::rating::member_j(pair, k, tips[k]) {
            let (field, shown) = match table.get("rack_tip_radius_coefficient") {
                Some(v) => ("rack_tip_radius_coefficient".to_string(), v.to_string()),
                None => (format!("rating.{which}.j"), "(missing)".to_string()),
            };
            return Err(invalid(
                &field,
                &shown,
                &format!("the {which}'s bending geometry factor J cannot be computed from the tooth form: {e}; give rating.{which}.j, or a smaller rack_tip_radius_coefficient"),
            ));
        }
    }
    Ok(())
}

/// The generating rack's tip radii in m from `rack_tip_radius_coefficient` (modules); whether
/// they fit the rack tooth is checked where J is computed ([`computable_j`]).
fn rack_tip_radius(
    raw: &GearFileTable,
    table: &toml::Table,
    module: f64,
    invalid: &Invalid,
) -> Result<[Option<f64>; 2], GearFileError> {
    let Some(c) = &raw.rack_tip_radius_coefficient else {
        return Ok([None, None]);
    };
    let c = c.si();
    for (k, v) in c.iter().enumerate() {
        if !(v.is_finite() && *v > 0.0) {
            return Err(invalid(
                "rack_tip_radius_coefficient",
                &table["rack_tip_radius_coefficient"],
                &format!(
                    "the {} value must be a positive number of modules (ISO 53: 0.25 to 0.38)",
                    ["pinion", "gear"][k]
                ),
            ));
        }
    }
    Ok([Some(c[0] * module), Some(c[1] * module)])
}

/// The `[rating]` table's inputs, checked against the pair (its pitch-line velocity), if the
/// file has one.
fn rating_of(
    raw: &GearFileTable,
    face_width: Option<f64>,
    pair: &GearPair,
    invalid: &Invalid,
) -> Result<Option<RatingInputs>, GearFileError> {
    match &raw.rating {
        None => Ok(None),
        Some(r) => {
            if face_width.is_none() {
                return Err(invalid(
                    "face_width",
                    &"(missing)",
                    "a pair with a [rating] table needs its face width",
                ));
            }
            let inputs = parse_rating(r, invalid)?;
            // The pitch-line velocity the rating takes (rate_figures: ω1 · dw1/2).
            let v = inputs.pinion_speed * pair.pinion.working / 2.0;
            check_pitch_line_velocity(v).map_err(|e| {
                let rule = match e {
                    GearError::InvalidInput { rule, .. } => rule.to_string(),
                    e => e.to_string(),
                };
                invalid(
                    "rating.pinion_speed",
                    &r.pinion_speed.written,
                    &format!("the pitch-line velocity it gives, {} m/s, {rule}", short(v)),
                )
            })?;
            Ok(Some(inputs))
        }
    }
}

/// Names the file's field behind an input error of the geometry.
fn geometry_error(e: GearError, table: &toml::Table, invalid: &Invalid) -> GearFileError {
    let GearError::InvalidInput { field, rule, value } = e else {
        return invalid("teeth", &table["teeth"], &e.to_string());
    };
    let tip_field = if table.contains_key("tip_diameter") {
        "tip_diameter"
    } else {
        "addendum_coefficient"
    };
    let name = match field {
        "module" if !table.contains_key("module") => "cardan_crank_length",
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
    let detail = format!("{rule} (as computed: {field} = {value})");
    match table.get(name) {
        Some(v) => invalid(name, v, &detail),
        None => invalid(name, &"(default)", &detail),
    }
}

/// The `[rating]` table's inputs, each checked and in SI, in the order a file's errors are
/// reported.
fn parse_rating(r: &RatingTable, invalid: &Invalid) -> Result<RatingInputs, GearFileError> {
    let factor = |f: &Option<Positive<Number>>| f.as_ref().map_or(1.0, |q| q.si);

    let load = load(r, invalid)?;
    let kv = kv_input(r, invalid)?;
    let reliability_factor = reliability_factor(r, invalid)?;
    let pinion_cycles = pinion_cycles(r, invalid)?;
    let i = match r
        .geometry_factor_i
        .clone()
        .unwrap_or(GeometryFactorI::Lpstc)
    {
        GeometryFactorI::Lpstc => IInput::Form(IForm::Lpstc),
        GeometryFactorI::PitchPoint => IInput::Form(IForm::PitchPoint),
        GeometryFactorI::Given(x) => IInput::Given(x),
    };

    let basis = iso_input::basis(r);
    let members = [
        member("pinion", &r.pinion, iso_input::iso_asked(r), invalid)?,
        member("gear", &r.gear, iso_input::iso_asked(r), invalid)?,
    ];
    if members[0].lewis_y.is_some() != members[1].lewis_y.is_some() {
        let y = r.gear.lewis_y.as_ref().map_or("(missing)", |y| &y.written);
        return Err(invalid(
            "rating.gear.lewis_y",
            &y,
            "give lewis_y for both members or for neither",
        ));
    }

    let elastic = elastic(r, &members, invalid)?;
    let iso = iso_input::iso_rating(r, &members, invalid)?;
    let required_safety_factor = required_safety_factor(r, invalid)?;

    Ok(RatingInputs {
        load,
        pinion_speed: r.pinion_speed.si,
        kv,
        overload: factor(&r.overload_factor),
        reliability_factor,
        temperature_factor: factor(&r.temperature_factor),
        surface_condition: factor(&r.surface_condition_factor),
        pinion_cycles,
        bending_low: match r.bending_cycle_low {
            BendingLow::Hb400 => BendingLowCycle::Hb400,
            BendingLow::CaseCarburized => BendingLowCycle::CaseCarburized,
            BendingLow::Hb250 => BendingLowCycle::Hb250,
            BendingLow::Nitrided => BendingLowCycle::Nitrided,
            BendingLow::Hb160 => BendingLowCycle::Hb160,
        },
        bending_high: match r.bending_cycle_high {
            BendingHigh::Upper => BendingHighCycle::Upper,
            BendingHigh::Lower => BendingHighCycle::Lower,
        },
        nitrided: r.pitting_nitrided.unwrap_or(false),
        i,
        elastic_coefficient: elastic,
        hardness_ratio_factor: r.hardness_ratio_factor.as_ref().map(|c| c.si),
        load_distribution: LoadDistribution {
            crowned: r.crowned.unwrap_or(false),
            offset_ratio: r.offset_ratio.as_ref().map_or(0.0, |x| x.si),
            enclosure: match r.enclosure {
                EnclosureWord::Open => Enclosure::Open,
                EnclosureWord::Commercial => Enclosure::CommercialEnclosed,
                EnclosureWord::Precision => Enclosure::PrecisionEnclosed,
                EnclosureWord::ExtraPrecision => Enclosure::ExtraPrecisionEnclosed,
            },
            adjusted_at_assembly: r.adjusted_at_assembly.unwrap_or(false),
        },
        members,
        required_safety_factor,
        basis,
        iso,
    })
}

/// The load to rate the pair at: `power` or the pinion's `torque`, exactly one, positive.
fn load(r: &RatingTable, invalid: &Invalid) -> Result<Load, GearFileError> {
    let (load, load_field, written) = match (&r.power, &r.torque) {
        (Some(p), None) => (Load::Power(p.si), "rating.power", &p.written),
        (None, Some(t)) => (Load::Torque(t.si), "rating.torque", &t.written),
        (Some(p), Some(_)) => {
            return Err(invalid(
                "rating.power",
                &p.written,
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
    let (Load::Power(load_value) | Load::Torque(load_value)) = load;
    if load_value <= 0.0 {
        return Err(invalid(
            load_field,
            written,
            "must be positive (a pair without load has no rating: leave out [rating] for the geometry only)",
        ));
    }
    Ok(load)
}

/// The reliability factor K_R: from `reliability` (AGMA 2001-D04 Table 11, else Shigley eq.
/// 14-38's fit), or given, or 1.
fn reliability_factor(r: &RatingTable, invalid: &Invalid) -> Result<f64, GearFileError> {
    Ok(match (&r.reliability, &r.reliability_factor) {
        (Some(v), None) => reliability_factor_table(v.si)
            .or_else(|_| reliability_factor_fit(v.si))
            .map_err(|e| invalid("rating.reliability", &v.written, &e.to_string()))?,
        (None, Some(k)) => k.si,
        (Some(v), Some(_)) => {
            return Err(invalid(
                "rating.reliability",
                &v.written,
                "give reliability or reliability_factor (KR), not both",
            ))
        }
        (None, None) => 1.0,
    })
}

/// The pinion's load cycles, checked against the pitting cycle factor's range; else
/// [`DEFAULT_PINION_CYCLES`].
fn pinion_cycles(r: &RatingTable, invalid: &Invalid) -> Result<f64, GearFileError> {
    Ok(match &r.pinion_cycles {
        Some(n) => {
            pitting_cycle_factor(n.si, false)
                .map_err(|e| invalid("rating.pinion_cycles", &n.written, &e.to_string()))?;
            n.si
        }
        None => DEFAULT_PINION_CYCLES,
    })
}

/// The safety factor the rating requires: finite and at least 1; 1 when not given.
fn required_safety_factor(r: &RatingTable, invalid: &Invalid) -> Result<f64, GearFileError> {
    Ok(match &r.required_safety_factor {
        None => 1.0,
        Some(n) if !n.si.is_finite() => {
            return Err(invalid(
                "rating.required_safety_factor",
                &n.written,
                "must be a finite number",
            ))
        }
        Some(n) if n.si < 1.0 => {
            return Err(invalid(
                "rating.required_safety_factor",
                &n.written,
                "must be >= 1 (below 1 the pair is expected to break)",
            ))
        }
        Some(n) => n.si,
    })
}

/// How Kv is obtained: exactly one of `quality`, `accuracy_level`, `dynamic_factor`.
fn kv_input(r: &RatingTable, invalid: &Invalid) -> Result<KvInput, GearFileError> {
    let gear_err =
        |field: &str, v: &dyn std::fmt::Display, e: GearError| invalid(field, v, &e.to_string());
    Ok(match (&r.quality, &r.accuracy_level, &r.dynamic_factor) {
        (Some(q), None, None) => {
            dynamic_factor(Quality::Qv(q.si), 0.0)
                .map_err(|e| gear_err("rating.quality", &q.written, e))?;
            KvInput::Quality(Quality::Qv(q.si))
        }
        (None, Some(a), None) => {
            dynamic_factor(Quality::Av(a.si), 0.0)
                .map_err(|e| gear_err("rating.accuracy_level", &a.written, e))?;
            KvInput::Quality(Quality::Av(a.si))
        }
        (None, None, Some(k)) => {
            if k.si < 1.0 {
                return Err(invalid("rating.dynamic_factor", &k.written, "must be >= 1"));
            }
            KvInput::Given(k.si)
        }
        _ => {
            let q = r.quality.as_ref().map_or("(missing)", |q| &q.written);
            return Err(invalid(
                "rating.quality",
                &q,
                "give exactly one of quality (AGMA 2001 Qv, 5-12), accuracy_level (AGMA 2101 Av, 6-12) or dynamic_factor (Kv)",
            ));
        }
    })
}

/// The elastic coefficient Cp, given or from both members' Young's modulus and Poisson's
/// ratio.
fn elastic(
    r: &RatingTable,
    members: &[MemberInputs; 2],
    invalid: &Invalid,
) -> Result<f64, GearFileError> {
    Ok(match &r.elastic_coefficient {
        Some(cp) => cp.si,
        None => {
            let mut en = [(0.0, 0.0); 2];
            for (k, (which, m)) in [("pinion", &r.pinion), ("gear", &r.gear)]
                .iter()
                .enumerate()
            {
                en[k] = match (&m.youngs_modulus, &m.poisson_ratio, members[k].material) {
                    (Some(e), Some(nu), _) => (e.si, nu.si),
                    (None, None, Some(mat)) => (mat.youngs_modulus, mat.poisson_ratio),
                    _ => {
                        return Err(invalid(
                            "rating.elastic_coefficient",
                            &"(missing)",
                            &format!("give it (e.g. \"2300 sqrt(psi)\", \"190 sqrt(MPa)\"), or youngs_modulus and poisson_ratio, or a material, in [rating.{which}]"),
                        ))
                    }
                };
            }
            elastic_coefficient(en[0].0, en[0].1, en[1].0, en[1].1).map_err(|e| {
                let shown = r
                    .pinion
                    .youngs_modulus
                    .as_ref()
                    .map_or("(missing)", |y| y.written.as_str());
                invalid("rating.pinion.youngs_modulus", &shown, &e.to_string())
            })?
        }
    })
}

/// One member's rating inputs, `[rating.<which>]`.
fn member(
    which: &str,
    m: &MemberTable,
    iso_asked: bool,
    invalid: &Invalid,
) -> Result<MemberInputs, GearFileError> {
    let mat = iso_input::member_material(which, m, invalid)?;
    let f = |k: &str| format!("rating.{which}.{k}");
    if let (Some(y), Some(_)) = (&m.lewis_y, &m.size_factor) {
        return Err(invalid(
            &f("lewis_y"),
            &y.written,
            "give lewis_y (Ks from Shigley eq. 14-10) or size_factor (Ks), not both",
        ));
    }
    let grade_number = m.grade.map_or(1, |g| g.0);
    if mat.is_none() && grade_number == 3 {
        return Err(invalid(
            &f("grade"),
            &3,
            "grade 3 exists only for case-carburized steel: name material = \"steel-case-carburized\"",
        ));
    }
    let grade = match grade_number {
        2 => Grade::Two,
        _ => Grade::One,
    };
    let from_material = match mat {
        Some(mat) if m.bending_allowable.is_none() || m.contact_allowable.is_none() => Some(
            mat.agma_allowables(m.hardness.as_ref().map(|h| h.si), grade_number)
                .map_err(|e| {
                    let shown = m
                        .hardness
                        .as_ref()
                        .map_or("(missing)".to_string(), |h| h.written.clone());
                    invalid(&f("hardness"), &shown, &format!("{} ({e})", mat.name))
                })?,
        ),
        _ => None,
    };
    let allowable = |key: &str,
                     given: &Option<Positive<Pressure>>,
                     chart: fn(f64, Grade) -> Result<f64, GearError>|
     -> Result<f64, GearFileError> {
        match (given, &m.hardness) {
            (Some(s), _) => Ok(s.si),
            (None, _) if from_material.is_some() => Ok(if key == "bending_allowable" {
                from_material.map_or(0.0, |a| a.bending)
            } else {
                from_material.map_or(0.0, |a| a.contact)
            }),
            (None, Some(hb)) => chart(hb.si, grade)
                .map_err(|e| invalid(&f("hardness"), &hb.written, &e.to_string())),
            (None, None) => Err(invalid(
                &f(key),
                &"(missing)",
                "give it (a stress, e.g. \"31350 psi\") or the Brinell hardness of a through-hardened steel (AGMA 2001 charts)",
            )),
        }
    };
    Ok(MemberInputs {
        j: m.j.as_ref().map(|j| j.si),
        rim_factor: m.rim_factor.as_ref().map_or(1.0, |k| k.si),
        lewis_y: m.lewis_y.as_ref().map(|y| y.si),
        size_factor: m.size_factor.as_ref().map(|k| k.si),
        hardness: m.hardness.as_ref().map(|h| h.si),
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
        material: mat,
        iso: iso_input::iso_member(which, m, mat, iso_asked, invalid)?,
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
