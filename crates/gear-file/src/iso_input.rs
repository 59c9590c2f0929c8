//! Reading the gear file's materials, ISO 6336 inputs and `[measurement]` table: each value
//! in SI and validated once, errors naming the field, its value and the rule.

use super::table::{Basis as BasisWord, MeasurementTable, MemberTable, QualityWord, RatingTable};
use super::validated::*;
use cardan_gears::iso6336::{IsoDynamic, Lubrication, STEEL_DENSITY};
use cardan_gears::materials::{material, material_names, IsoQuality, LifeCurve, Material};

type Invalid<'a> = dyn Fn(&str, &dyn std::fmt::Display, &str) -> GearFileError + 'a;

/// The named material of `[rating.<which>]`, if any.
pub fn member_material(
    which: &str,
    m: &MemberTable,
    invalid: &Invalid,
) -> Result<Option<&'static Material>, GearFileError> {
    let Some(name) = &m.material else {
        return Ok(None);
    };
    match material(name) {
        Some(mat) => Ok(Some(mat)),
        None => Err(invalid(
            &format!("rating.{which}.material"),
            &format!("\"{name}\""),
            &format!(
                "is not in the materials table; use one of {}",
                material_names().join(", ")
            ),
        )),
    }
}

/// The member's ISO inputs when it gives `form_factor` (then `stress_correction_factor` and
/// the limits, given or from its material, are required), else `None`; `required` (the file
/// asks for the ISO rating, [`iso_asked`]) makes the ISO inputs required, Y_F and Y_S then
/// computed from the tooth form where not given.
pub fn iso_member(
    which: &str,
    m: &MemberTable,
    mat: Option<&'static Material>,
    required: bool,
    invalid: &Invalid,
) -> Result<Option<IsoMemberInputs>, GearFileError> {
    let f = |k: &str| format!("rating.{which}.{k}");
    let (y_f, y_s) = match (&m.form_factor, &m.stress_correction_factor) {
        (Some(yf), Some(ys)) => (Some(yf.si), Some(ys.si)),
        (None, None) if !required => return Ok(None),
        // Computed from the tooth form at rating (ISO 6336-3 method B).
        (None, None) => (None, None),
        (None, Some(ys)) => {
            return Err(invalid(
                &f("stress_correction_factor"),
                &ys.written,
                "give it with form_factor (ISO 6336-3 §6 Y_F), or neither: both are then computed from the tooth form",
            ))
        }
        (Some(_), None) => {
            return Err(invalid(
                &f("stress_correction_factor"),
                &"(missing)",
                "give it with form_factor (ISO 6336-3 §7 Y_S, e.g. 1.9)",
            ))
        }
    };
    let quality = match m.iso_quality {
        QualityWord::Ml => IsoQuality::Ml,
        QualityWord::Mq => IsoQuality::Mq,
        QualityWord::Me => IsoQuality::Me,
    };
    let hb = m.hardness.as_ref().map(|h| h.si);
    let limits = match mat {
        Some(mat) if m.sigma_hlim.is_none() || m.sigma_flim.is_none() => Some(
            mat.iso_limits(hb, quality)
                .map_err(|e| invalid(&f("material"), &mat.name, &e.to_string()))?,
        ),
        _ => None,
    };
    let limit = |key: &str, given: Option<f64>, table: Option<f64>| match given.or(table) {
        Some(x) => Ok(x),
        None => Err(invalid(
            &f(key),
            &"(missing)",
            "the ISO 6336 rating needs it (a stress, e.g. \"1500 MPa\"), or name a material",
        )),
    };
    Ok(Some(IsoMemberInputs {
        form_factor: y_f,
        stress_correction_factor: y_s,
        sigma_hlim: limit(
            "sigma_hlim",
            m.sigma_hlim.as_ref().map(|s| s.si),
            limits.map(|l| l.contact),
        )?,
        sigma_flim: limit(
            "sigma_flim",
            m.sigma_flim.as_ref().map(|s| s.si),
            limits.map(|l| l.bending),
        )?,
        life_curve: mat.map_or(LifeCurve::ThroughHardened, |m| m.life_curve()),
    }))
}

/// Whether the file asks for the ISO 6336 rating: its verdict's basis is ISO, or it gives a
/// field only the ISO rating reads (`accuracy_grade`, `iso_dynamic_factor`,
/// `transverse_load_factor`, `face_load_factor`, `application_factor`, `density`,
/// `oil_viscosity`, `flank_roughness`, a member's `sigma_hlim` or `sigma_flim`). Then the ISO
/// rating is computed beside AGMA's, `Y_F` and `Y_S` from the tooth form where not given: a
/// value the user wrote is never left unread.
pub fn iso_asked(r: &RatingTable) -> bool {
    let member = |m: &MemberTable| m.sigma_hlim.is_some() || m.sigma_flim.is_some();
    r.basis == BasisWord::Iso6336
        || r.accuracy_grade.is_some()
        || r.iso_dynamic_factor.is_some()
        || r.transverse_load_factor.is_some()
        || r.face_load_factor.is_some()
        || r.application_factor.is_some()
        || r.density.is_some()
        || r.oil_viscosity.is_some()
        || r.flank_roughness.is_some()
        || member(&r.pinion)
        || member(&r.gear)
}

/// The verdict's basis.
pub fn basis(r: &RatingTable) -> Basis {
    match r.basis {
        BasisWord::Agma2001 => Basis::Agma2001,
        BasisWord::Iso6336 => Basis::Iso6336,
    }
}

/// The pair's ISO inputs, when its members have theirs.
pub fn iso_rating(
    r: &RatingTable,
    members: &[MemberInputs; 2],
    invalid: &Invalid,
) -> Result<Option<IsoRatingInputs>, GearFileError> {
    if members.iter().any(|m| m.iso.is_none()) {
        if let Some(k) = members.iter().position(|m| m.iso.is_some()) {
            let other = ["gear", "pinion"][k];
            return Err(invalid(
                &format!("rating.{other}.form_factor"),
                &"(missing)",
                "give form_factor and stress_correction_factor for both members or for neither",
            ));
        }
        return Ok(None);
    }
    let at_least_one = |field: &str,
                        q: &Option<
        cardan_case::quantity::Quantity<cardan_case::quantity::Number>,
    >| match q {
        Some(k) if !(k.si.is_finite() && k.si >= 1.0) => Err(invalid(
            &format!("rating.{field}"),
            &k.written,
            "must be a number >= 1",
        )),
        Some(k) => Ok(Some(k.si)),
        None => Ok(None),
    };
    let accuracy_grade = match &r.accuracy_grade {
        Some(q) if !(q.si.is_finite() && (1.0..=12.0).contains(&q.si)) => {
            return Err(invalid(
                "rating.accuracy_grade",
                &q.written,
                "must lie in [1, 12] (ISO 1328-1 accuracy grade)",
            ))
        }
        q => q.as_ref().map(|q| q.si),
    };
    let kv = at_least_one("iso_dynamic_factor", &r.iso_dynamic_factor)?;
    let transverse = at_least_one("transverse_load_factor", &r.transverse_load_factor)?;
    if accuracy_grade.is_none() && (kv.is_none() || transverse.is_none()) {
        return Err(invalid(
            "rating.accuracy_grade",
            &"(missing)",
            "the ISO rating needs the ISO 1328-1 accuracy grade (1-12) for K_v and K_Hα by ISO 6336-1 method B, or give iso_dynamic_factor and transverse_load_factor",
        ));
    }
    let lubrication = match (&r.oil_viscosity, &r.flank_roughness) {
        (Some(nu), Some(rz)) => Some(Lubrication {
            viscosity_40: nu.si,
            flank_roughness: rz.si,
        }),
        (None, None) => None,
        (Some(nu), None) => {
            return Err(invalid(
                "rating.flank_roughness",
                &"(missing)",
                &format!(
                    "give it with oil_viscosity = {} (Z_L, Z_v and Z_R go together)",
                    nu.written
                ),
            ))
        }
        (None, Some(rz)) => {
            return Err(invalid(
                "rating.oil_viscosity",
                &"(missing)",
                &format!(
                    "give it with flank_roughness = {} (mm²/s at 40 °C, a bare number)",
                    rz.written
                ),
            ))
        }
    };
    Ok(Some(IsoRatingInputs {
        application_factor: r
            .application_factor
            .as_ref()
            .or(r.overload_factor.as_ref())
            .map_or(1.0, |k| k.si),
        accuracy_grade,
        dynamic: match kv {
            Some(k) => IsoDynamic::Given(k),
            None => IsoDynamic::MethodB {
                density: r.density.as_ref().map_or(STEEL_DENSITY, |d| d.si),
            },
        },
        face_load_factor: at_least_one("face_load_factor", &r.face_load_factor)?,
        transverse_load_factor: transverse,
        lubrication,
    }))
}

/// `[measurement]`.
pub fn measurement(
    t: &Option<MeasurementTable>,
    z: [i32; 2],
    invalid: &Invalid,
) -> Result<Option<MeasurementInputs>, GearFileError> {
    let Some(t) = t else {
        return Ok(None);
    };
    let span_teeth = t.span_teeth.as_ref().map(|p| [p.0[0].0, p.0[1].0]);
    if let Some(k) = span_teeth {
        for (i, (&k, &z)) in k.iter().zip(&z).enumerate() {
            if z > 0 && k >= z as u32 {
                return Err(invalid(
                    "measurement.span_teeth",
                    &format!("{k:?}"),
                    &format!(
                        "the {} has {z} teeth: span at most z - 1",
                        ["pinion", "gear"][i]
                    ),
                ));
            }
        }
    }
    Ok(Some(MeasurementInputs {
        span_teeth,
        pin_diameter: t.pin_diameter.as_ref().map(|p| p.si()),
    }))
}
