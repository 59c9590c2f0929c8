//! The `[gear]` table of a case: the gear pair of every gear mesh and its rating data, in SI,
//! validated once here. With it, each mechanism's meshes are rated at every step
//! ([`cardan_dynamics::GearRatings`]); the mesh loss of `[friction]` uses the same pair.
//!
//! The table is [`GearTable`]; its defaults are [`GearSpec::default`]'s (the dynamics crate),
//! written there once. [`Ranged`] and [`PerGear`] are the number with a range and the value
//! given once or per member, also used by the gear file of `cardan gear`.

use crate::error::{CaseError, Invalid};
pub use crate::plausible::{
    AccuracyGrade, ApplicationFactor, GeometryFactorJ, Hardness, IsoLoadFactor, ProfileShift,
    QualityNumber, RingAddendum, Teeth,
};
use crate::quantity::{broken, Dim, Length, NonNegative, Positive, Pressure};
pub use crate::quantity::{Range, Ranged};
use cardan_dynamics::mesh::{GearStandard, IsoOverrides, IsoQuality};
use cardan_dynamics::{GearMaterial, GearSpec, ToothLoad};
use schemars::{json_schema, JsonSchema, Schema, SchemaGenerator};
use serde::{de::Error as _, Deserialize, Deserializer};
use std::borrow::Cow;

/// A value given once for both members of a pair, or per member as `[pinion, gear]`.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct PerGear<T>(pub [T; 2]);

impl<R: Range, D: Dim> PerGear<Ranged<R, D>> {
    /// [pinion, gear] in SI.
    pub fn si(&self) -> [f64; 2] {
        [self.0[0].si, self.0[1].si]
    }
}

impl<'de, T: serde::de::DeserializeOwned + Clone> Deserialize<'de> for PerGear<T> {
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        let value = toml::Value::deserialize(deserializer)?;
        let one =
            |v: &toml::Value| T::deserialize(v.clone()).map_err(|e| De::Error::custom(e.message()));
        match &value {
            toml::Value::Array(a) if a.len() == 2 => Ok(Self([one(&a[0])?, one(&a[1])?])),
            toml::Value::Array(_) => Err(De::Error::custom(broken(
                &value,
                "must be one value or two [pinion, gear]",
            ))),
            v => {
                let x = one(v)?;
                Ok(Self([x.clone(), x]))
            }
        }
    }
}

impl<T: JsonSchema> JsonSchema for PerGear<T> {
    fn schema_name() -> Cow<'static, str> {
        format!("PerGear_{}", T::schema_name()).into()
    }

    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        let one = generator.subschema_for::<T>();
        json_schema!({
            "description": "One value for both members, or [pinion, gear].",
            "anyOf": [one, { "type": "array", "items": one, "minItems": 2, "maxItems": 2 }]
        })
    }
}

/// The gears' steel and its treatment, for the allowable stresses.
#[derive(Debug, Clone, Copy, Deserialize, JsonSchema, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum GearMaterialWord {
    /// Through-hardened steel: allowables from the hardness (AGMA 2001-D04 Figs. 3 and 8).
    ThroughHardened,
    /// Carburized and hardened, grade 2.
    Carburized,
}

/// Which load is rated.
#[derive(Debug, Clone, Copy, Deserialize, JsonSchema, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ToothLoadWord {
    /// The mesh force along the pitch-circle tangent (Karhula A8.1.10).
    Tangential,
    /// The mesh force's magnitude.
    RingForce,
    /// Karhula's reading that reproduces his published dynamic tooth loads.
    Thesis,
}

/// Which standard rates the stresses: the gear file's `basis` words, or both.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, JsonSchema, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum StandardWord {
    /// AGMA 2001-D04 (the default; the rating of every run before).
    Agma2001,
    /// ISO 6336-2/-3:2019 method B, in place of AGMA's stresses and safety factors.
    Iso6336,
    /// Both side by side.
    Both,
}

/// ISO 6336-5 material quality grade (the gear file's words).
#[derive(Debug, Clone, Copy, Deserialize, JsonSchema, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum IsoQualityWord {
    /// ML: modest demands.
    Ml,
    /// MQ: the usual industrial quality.
    Mq,
    /// ME: high reliability.
    Me,
}

/// `[gear]`: the gear pair of every gear mesh of the case and its rating data. Every field is
/// optional; the defaults are docs/case-file.md's ("Gear rating in runs").
#[derive(Debug, Deserialize, JsonSchema, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct GearTable {
    /// Teeth of the mesh's first gear (the cardan wheel), a whole number from 5 to 1000.
    /// Default 20 (Karhula A9.1.36).
    pub teeth: Option<Ranged<Teeth>>,
    /// Face width; m. Default a third of the pinion's pitch diameter (Karhula A8.1.9, A9.1.46).
    pub face_width: Option<Positive<Length>>,
    /// Addendum of an internal (ring) gear in modules, from 0 to 1.5. Default 0.8, the contact
    /// ratio of about 1.8 of Karhula's text (a full 1.0 interferes on 20/40 at 20°).
    pub ring_addendum: Option<Ranged<RingAddendum>>,
    /// Profile shift coefficients, from −1 to 1 (ISO 21771 signs); one for both, or
    /// [pinion, gear]. Default 0.
    pub profile_shift: Option<PerGear<Ranged<ProfileShift>>>,
    /// AGMA 2000 quality number Qv for the dynamic factor, from 5 to 12. Default 8 (this
    /// project's).
    pub quality: Option<Ranged<QualityNumber>>,
    /// The gears' steel and treatment. Default "through_hardened".
    pub material: Option<GearMaterialWord>,
    /// Brinell hardness of through-hardened steel, from 140 to 400 HB; one for both, or
    /// [pinion, gear]. Default 300 HB (this project's).
    pub hardness: Option<PerGear<Ranged<Hardness>>>,
    /// AGMA bending geometry factors J, between 0 and 1; one for both, or [pinion, gear]: given,
    /// they replace the computed ones. Default computed from the tooth form (AGMA 908-B89 for an
    /// external member, ISO 6336-3 method B for an internal ring; docs/gear-calculator.md).
    pub j: Option<PerGear<Ranged<GeometryFactorJ>>>,
    /// Buckingham's effective profile error (backlash); m. Default 0.005 in = 0.127 mm
    /// (Karhula).
    pub backlash: Option<NonNegative<Length>>,
    /// Young's modulus of both gears; Pa. Default 210 GPa (Karhula).
    pub youngs_modulus: Option<Positive<Pressure>>,
    /// Two identical gear sets side by side share the load (Nunes 2017's twin set). Default
    /// false.
    pub twin: Option<bool>,
    /// Which load is rated. Default "tangential".
    pub tooth_load: Option<ToothLoadWord>,
    /// Which standard rates the stresses and safety factors: "agma2001" (AGMA 2001-D04),
    /// "iso6336" (ISO 6336-2/-3:2019 method B in its place) or "both" side by side; the
    /// words of the gear file's `basis`. Default "agma2001".
    pub standard: Option<StandardWord>,
    /// ISO 1328-1 accuracy grade of both gears, from 1 to 12, for ISO 6336-1 method B's K_v
    /// and K_Hα; required by an ISO rating (no default).
    pub accuracy_grade: Option<Ranged<AccuracyGrade>>,
    /// ISO 6336-1 application factor K_A, from 1 to 4, for an ISO rating. Default 1 (the
    /// rated load is the run's computed load, as AGMA's K_o = 1; ISO 6336-1 Annex B: 1.00 for
    /// uniform driver and driven machine).
    pub application_factor: Option<Ranged<ApplicationFactor>>,
    /// ISO 6336-5 material quality "ml", "mq" or "me", for σ_Hlim and σ_Flim of an ISO rating.
    /// Default "mq".
    pub iso_quality: Option<IsoQualityWord>,
    /// ISO 6336-1 dynamic factor K_v, from 1 to 4, in place of method B's from the accuracy
    /// grade (ISO 6336-1:2019 §4.1.6: a measured or established value takes precedence).
    /// Default computed.
    pub iso_dynamic_factor: Option<Ranged<IsoLoadFactor>>,
    /// ISO 6336-1 transverse load factor K_Hα (= K_Fα), from 1 to 4, in place of method B's.
    /// With `iso_dynamic_factor` too, no `accuracy_grade` is needed. Default computed.
    pub transverse_load_factor: Option<Ranged<IsoLoadFactor>>,
    /// ISO 6336-1 face load factor K_Hβ, from 1 to 4 (K_Fβ follows from it). Default the AGMA
    /// rating's K_m for the face width.
    pub face_load_factor: Option<Ranged<IsoLoadFactor>>,
    /// ISO 6336-5 allowable contact stress number σ_Hlim; Pa; one for both, or [pinion, gear].
    /// Default from `material`, `hardness` and `iso_quality`.
    pub sigma_hlim: Option<PerGear<Positive<Pressure>>>,
    /// ISO 6336-5 nominal bending stress number σ_Flim; Pa; one for both, or [pinion, gear].
    /// Default from `material`, `hardness` and `iso_quality`.
    pub sigma_flim: Option<PerGear<Positive<Pressure>>>,
}

impl GearTable {
    /// The gear data of the case ([`GearTable::spec`]), its ISO fields checked against
    /// `standard`: an ISO rating needs `accuracy_grade`, and an ISO field without one would be
    /// read by nothing.
    pub(crate) fn build(&self, invalid: &Invalid) -> Result<GearSpec, CaseError> {
        let spec = self.spec();
        let both_factors =
            self.iso_dynamic_factor.is_some() && self.transverse_load_factor.is_some();
        if spec.standard.iso() && self.accuracy_grade.is_none() && !both_factors {
            return Err(invalid(
                "gear.accuracy_grade",
                &"(missing)",
                "an ISO 6336 rating (standard = \"iso6336\" or \"both\") needs the ISO 1328-1 accuracy grade of both gears, 1 to 12, for K_v and K_Hα by ISO 6336-1 method B: add e.g. accuracy_grade = 7 (or give both iso_dynamic_factor and transverse_load_factor)",
            ));
        }
        if let (Some(grade), true) = (&self.accuracy_grade, both_factors) {
            return Err(invalid(
                "gear.accuracy_grade",
                &grade.written,
                "is read by nothing: iso_dynamic_factor and transverse_load_factor replace the K_v and K_Hα it gives; remove it, or one of them",
            ));
        }
        if !spec.standard.iso() {
            let written = |r: &Option<Ranged<IsoLoadFactor>>| r.as_ref().map(|a| a.written.clone());
            let stress = |p: &Option<PerGear<Positive<Pressure>>>| {
                p.as_ref().map(|p| p.0[0].written.clone())
            };
            let given = [
                (
                    "accuracy_grade",
                    self.accuracy_grade.as_ref().map(|a| a.written.to_string()),
                ),
                (
                    "application_factor",
                    self.application_factor
                        .as_ref()
                        .map(|a| a.written.to_string()),
                ),
                (
                    "iso_quality",
                    self.iso_quality
                        .map(|q| format!("\"{q:?}\"").to_lowercase()),
                ),
                ("iso_dynamic_factor", written(&self.iso_dynamic_factor)),
                (
                    "transverse_load_factor",
                    written(&self.transverse_load_factor),
                ),
                ("face_load_factor", written(&self.face_load_factor)),
                ("sigma_hlim", stress(&self.sigma_hlim)),
                ("sigma_flim", stress(&self.sigma_flim)),
            ];
            if let Some((field, Some(value))) = given.into_iter().find(|(_, v)| v.is_some()) {
                return Err(invalid(
                    &format!("gear.{field}"),
                    &value,
                    "is read only by an ISO 6336 rating, which the case does not ask for: add standard = \"both\" (ISO beside AGMA) or \"iso6336\", or remove it",
                ));
            }
        }
        Ok(spec)
    }

    /// The gear data of the case: each given field replaces [`GearSpec::default`]'s.
    pub fn spec(&self) -> GearSpec {
        let mut g = GearSpec::default();
        if let Some(t) = &self.teeth {
            g.teeth = t.si as u32;
        }
        if let Some(w) = &self.face_width {
            g.face_width = Some(w.si);
        }
        if let Some(a) = &self.ring_addendum {
            g.ring_addendum = a.si;
        }
        if let Some(x) = &self.profile_shift {
            g.profile_shift = x.si();
        }
        if let Some(q) = &self.quality {
            g.quality = q.si;
        }
        if let Some(m) = self.material {
            g.material = match m {
                GearMaterialWord::ThroughHardened => GearMaterial::ThroughHardened,
                GearMaterialWord::Carburized => GearMaterial::Carburized,
            };
        }
        if let Some(h) = &self.hardness {
            g.hardness = h.si();
        }
        if let Some(j) = &self.j {
            g.j = Some(j.si());
        }
        if let Some(b) = &self.backlash {
            g.error = b.si;
        }
        if let Some(e) = &self.youngs_modulus {
            g.youngs_modulus = e.si;
        }
        if let Some(t) = self.twin {
            g.twin = t;
        }
        if let Some(w) = self.standard {
            g.standard = match w {
                StandardWord::Agma2001 => GearStandard::Agma2001,
                StandardWord::Iso6336 => GearStandard::Iso6336,
                StandardWord::Both => GearStandard::Both,
            };
        }
        g.accuracy_grade = self.accuracy_grade.as_ref().map(|a| a.si);
        if let Some(k) = &self.application_factor {
            g.application_factor = k.si;
        }
        let stress =
            |p: &Option<PerGear<Positive<Pressure>>>| p.as_ref().map(|p| [p.0[0].si, p.0[1].si]);
        g.iso_overrides = IsoOverrides {
            dynamic_factor: self.iso_dynamic_factor.as_ref().map(|k| k.si),
            transverse_load_factor: self.transverse_load_factor.as_ref().map(|k| k.si),
            face_load_factor: self.face_load_factor.as_ref().map(|k| k.si),
            sigma_hlim: stress(&self.sigma_hlim),
            sigma_flim: stress(&self.sigma_flim),
        };
        if let Some(q) = self.iso_quality {
            g.iso_quality = match q {
                IsoQualityWord::Ml => IsoQuality::Ml,
                IsoQualityWord::Mq => IsoQuality::Mq,
                IsoQualityWord::Me => IsoQuality::Me,
            };
        }
        if let Some(t) = self.tooth_load {
            g.tooth_load = match t {
                ToothLoadWord::Tangential => ToothLoad::Tangential,
                ToothLoadWord::RingForce => ToothLoad::RingForce,
                ToothLoadWord::Thesis => ToothLoad::Thesis,
            };
        }
        g
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(text: &str) -> Result<GearSpec, String> {
        let table: toml::Table = toml::from_str(text).unwrap();
        crate::schema::read::<GearTable>(toml::Value::Table(table), "gear")
            .map(|t| t.spec())
            .map_err(|e| e.to_string())
    }

    #[test]
    fn a_misspelled_field_or_word_names_the_nearest_name() {
        let e = read("ring_adendum = 0.8").unwrap_err();
        assert!(
            e.contains("gear.ring_adendum: unknown field \"ring_adendum\": did you mean \"ring_addendum\"?"),
            "{e}"
        );
        let e = read("tooth_load = \"ring_forse\"").unwrap_err();
        assert!(
            e.contains(
                "gear.tooth_load: unknown word \"ring_forse\": did you mean \"ring_force\"?"
            ),
            "{e}"
        );
    }

    #[test]
    fn ranges_and_pairs_are_checked_with_the_value_written() {
        let e = read("hardness = [300, 500]").unwrap_err();
        assert!(
            e.contains("gear.hardness = 500: must be from 140 to 400 HB"),
            "{e}"
        );
        let e = read("j = [0.3, 0.4, 0.5]").unwrap_err();
        assert!(
            e.contains("gear.j = [0.3, 0.4, 0.5]: must be one value or two"),
            "{e}"
        );
        let e = read("teeth = 20.5").unwrap_err();
        assert!(
            e.contains("gear.teeth = 20.5: must be a whole number"),
            "{e}"
        );
        let g = read("teeth = 24.0\nprofile_shift = 0.1\nj = [0.3, 0.4]\nbacklash = \"0.1 mm\"")
            .unwrap();
        assert_eq!(g.teeth, 24);
        assert_eq!(g.profile_shift, [0.1, 0.1]);
        assert_eq!(g.j, Some([0.3, 0.4]));
        assert!((g.error - 1e-4).abs() < 1e-15);
        assert_eq!(read("").unwrap(), GearSpec::default());
    }

    #[test]
    fn the_schema_has_every_field_with_its_range() {
        let schema = schemars::schema_for!(GearTable).to_value();
        assert_eq!(schema["additionalProperties"], false);
        let text = schema.to_string();
        for part in [
            "ring_addendum",
            "tooth_load",
            "ring_force",
            "\"maximum\":400.0",
        ] {
            assert!(text.contains(part), "{part}: {text}");
        }
    }
}
