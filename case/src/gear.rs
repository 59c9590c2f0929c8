//! The `[gear]` table of a case: the gear pair of every gear mesh and its rating data, in SI,
//! validated once here. With it, each mechanism's meshes are rated at every step
//! ([`cardan_dynamics::GearRatings`]); the mesh loss of `[friction]` uses the same pair.

use crate::case::{CaseError, Invalid};
use crate::units::{to_si, Dimension};
use cardan_dynamics::{GearMaterial, GearSpec, ToothLoad};

/// The fields of `[gear]`, with their dimensions.
const FIELDS: [(&str, Dimension); 12] = [
    ("teeth", Dimension::Number),
    ("face_width", Dimension::Length),
    ("ring_addendum", Dimension::Number),
    ("profile_shift", Dimension::Number),
    ("quality", Dimension::Number),
    ("material", Dimension::Number),
    ("hardness", Dimension::Number),
    ("j", Dimension::Number),
    ("backlash", Dimension::Length),
    ("youngs_modulus", Dimension::Pressure),
    ("twin", Dimension::Number),
    ("tooth_load", Dimension::Number),
];

/// Reads `[gear]`.
pub fn parse(table: &toml::Table, invalid: &Invalid) -> Result<GearSpec, CaseError> {
    let mut g = GearSpec::default();
    for (key, value) in table {
        let path = format!("gear.{key}");
        let Some((_, dim)) = FIELDS.iter().find(|(f, _)| f == key) else {
            return Err(invalid(
                &path,
                value,
                &format!(
                    "unknown field: [gear] has {}",
                    FIELDS.map(|(f, _)| f).join(", ")
                ),
            ));
        };
        let number = |v: &toml::Value| to_si(v, *dim).map_err(|rule| invalid(&path, v, &rule));
        // One number, or a pair [pinion, gear] (one number applies to both).
        let pair = |v: &toml::Value| -> Result<[f64; 2], CaseError> {
            match v.as_array() {
                Some(a) if a.len() == 2 => Ok([number(&a[0])?, number(&a[1])?]),
                Some(_) => Err(invalid(&path, v, "must be one value or two [pinion, gear]")),
                None => {
                    let x = number(v)?;
                    Ok([x, x])
                }
            }
        };
        let check = |ok: bool, rule: &str| {
            if ok {
                Ok(())
            } else {
                Err(invalid(&path, value, rule))
            }
        };
        match key.as_str() {
            "teeth" => {
                let x = number(value)?;
                check(
                    x.fract() == 0.0 && (5.0..=1000.0).contains(&x),
                    "must be a whole number from 5 to 1000 (the teeth of the mesh's first gear: the cardan wheel)",
                )?;
                g.teeth = x as u32;
            }
            "face_width" => {
                let x = number(value)?;
                check(x > 0.0, "must be positive")?;
                g.face_width = Some(x);
            }
            "ring_addendum" => {
                let x = number(value)?;
                check(
                    (0.0..=1.5).contains(&x),
                    "must be from 0 to 1.5 modules (1 is a full addendum)",
                )?;
                g.ring_addendum = x;
            }
            "profile_shift" => {
                let x = pair(value)?;
                check(
                    x.iter().all(|s| (-1.0..=1.0).contains(s)),
                    "profile shift coefficients must be from -1 to 1",
                )?;
                g.profile_shift = x;
            }
            "quality" => {
                let x = number(value)?;
                check(
                    (5.0..=12.0).contains(&x),
                    "must be an AGMA quality number Qv from 5 to 12",
                )?;
                g.quality = x;
            }
            "hardness" => {
                let x = pair(value)?;
                check(
                    x.iter().all(|h| (140.0..=400.0).contains(h)),
                    "must be from 140 to 400 HB (through-hardened steel, AGMA 2001-D04 Figs. 3 and 8)",
                )?;
                g.hardness = x;
            }
            "j" => {
                let x = pair(value)?;
                check(
                    x.iter().all(|j| *j > 0.0 && *j < 1.0),
                    "bending geometry factors J must be between 0 and 1",
                )?;
                g.j = Some(x);
            }
            "backlash" => {
                let x = number(value)?;
                check(x >= 0.0, "must not be negative")?;
                g.error = x;
            }
            "youngs_modulus" => {
                let x = number(value)?;
                check(x > 0.0, "must be positive")?;
                g.youngs_modulus = x;
            }
            "material" => {
                g.material = match value.as_str() {
                    Some("through_hardened") => GearMaterial::ThroughHardened,
                    Some("carburized") => GearMaterial::Carburized,
                    _ => {
                        return Err(invalid(
                            &path,
                            value,
                            "must be \"through_hardened\" (allowables from the hardness) or \"carburized\" (carburized and hardened, grade 2)",
                        ))
                    }
                };
            }
            "twin" => {
                g.twin = value.as_bool().ok_or_else(|| {
                    invalid(
                        &path,
                        value,
                        "must be true (two gear sets share the load) or false",
                    )
                })?;
            }
            _ => {
                g.tooth_load = match value.as_str() {
                    Some("tangential") => ToothLoad::Tangential,
                    Some("ring_force") => ToothLoad::RingForce,
                    Some("thesis") => ToothLoad::Thesis,
                    _ => {
                        return Err(invalid(
                            &path,
                            value,
                            "must be \"tangential\" (the mesh force along the pitch-circle tangent, A8.1.10) or \"ring_force\" (its magnitude) or \"thesis\" (Karhula's reading that reproduces his published dynamic tooth loads)",
                        ))
                    }
                };
            }
        }
    }
    Ok(g)
}
