//! The ISO 6336 method B rating of a mesh's pair, prepared once for the gear rating of every
//! step (ISO 6336-1/-2/-3:2019, [`cardan_gears::iso6336`]).

use cardan_gears::iso6336::{IsoDynamic, IsoInputs, IsoMember, PreparedIso, STEEL_DENSITY};
use cardan_gears::materials::material;
use cardan_gears::{GearSet, GeneratedMember, PairMember};

use crate::mesh::{GearMaterial, GearSpec};
use crate::stage::SetupError;
use crate::{failed, GearInput, SetupInput};

/// The load cycles of the pinion the ISO life factors `Z_NT`, `Y_NT` are taken at (the gear's:
/// divided by the ratio): 1e7, the life the AGMA rating of a run is taken at (its `Y_N` = `Z_N`
/// = 1, AGMA 2001-D04 Figs. 18 and 19 are drawn through 1 at 1e7 cycles), and the gear file's
/// default `pinion_cycles`.
pub const ISO_PINION_CYCLES: f64 = 1e7;

/// The ISO 6336 method B rating of `set`'s pair (ISO 6336-1/-2/-3:2019,
/// [`cardan_gears::iso6336`]) under `spec`, prepared once: `σ_Hlim`, `σ_Flim` and the life
/// curves of the gear file's material table (`cardan_gears::materials`: "through_hardened" is
/// its "steel-through-hardened" at each member's hardness, "carburized" its
/// "steel-case-carburized") at `spec.iso_quality`; `Y_F`, `Y_S` from the tooth form by
/// ISO 6336-3 method B with the default generating rack (as the computed J,
/// [`cardan_gears::iso6336_method_b`]); `K_Hβ` the AGMA rating's `Km` for the face width (as the
/// gear file's default: ISO 6336-1 methods B and C need shaft and bearing data); `Z_E` the
/// AGMA rating's elastic coefficient (the same expression); `K_v` and `K_Hα` by method B
/// from `spec.accuracy_grade` (steel blanks, 7830 kg/m³); `Z_L Z_v Z_R` = 1, `Y_B` = `Y_δrelT`
/// = `Y_RrelT` = 1; [`ISO_PINION_CYCLES`]. Each of `K_v`, `K_Hα`, `K_Hβ`, `σ_Hlim`, `σ_Flim`
/// given in `spec.iso_overrides` replaces its computed value (ISO 6336-1:2019 §4.1.6: a
/// factor established by method A or from experience takes precedence); with `K_v` and `K_Hα`
/// both given no accuracy grade is needed.
pub(super) fn iso_rating(spec: &GearSpec, set: &GearSet) -> Result<PreparedIso, SetupError> {
    let pair = &set.pair;
    let given = spec.iso_overrides;
    let grade = spec.accuracy_grade;
    if grade.is_none() && (given.dynamic_factor.is_none() || given.transverse_load_factor.is_none())
    {
        return Err(failed(
            SetupInput::Gear(GearInput::AccuracyGrade),
            &"an ISO 6336 rating needs the ISO 1328-1 accuracy grade of both gears (1-12) for \
              K_v and K_Hα by ISO 6336-1 method B: give [gear] accuracy_grade",
        ));
    }
    let table = match spec.material {
        GearMaterial::ThroughHardened => "steel-through-hardened",
        GearMaterial::Carburized => "steel-case-carburized",
    };
    let table = material(table).expect("the materials table has both steels");
    let km = match given.face_load_factor {
        Some(k) => k,
        None => {
            (set.rating.load_distribution)
                .factor(set.face_width, pair.pinion.working)
                .map_err(|e| failed(SetupInput::Gear(GearInput::FaceWidth), &e))?
                .km
        }
    };
    let cycles = [ISO_PINION_CYCLES, ISO_PINION_CYCLES / pair.ratio];
    let member = |k: usize| -> Result<IsoMember, SetupError> {
        let (which, name) = [(PairMember::Pinion, "pinion"), (PairMember::Gear, "gear")][k];
        let hardness = (spec.material == GearMaterial::ThroughHardened).then_some(spec.hardness[k]);
        let limits = table.iso_limits(hardness, spec.iso_quality).map_err(|e| {
            failed(
                SetupInput::Gear(GearInput::Hardness),
                &format!(
                    "{e} (the {name}'s {} HB): give a hardness within it, or rate by AGMA alone \
                     (standard = \"agma2001\")",
                    spec.hardness[k]
                ),
            )
        })?;
        let root = cardan_gears::iso6336_method_b(pair, GeneratedMember::new(which)).map_err(|e| {
            failed(
                SetupInput::Gear(GearInput::Pair),
                &format!("the {name}'s ISO 6336-3 Y_F and Y_S cannot be computed from the tooth form ({e})"),
            )
        })?;
        Ok(IsoMember {
            sigma_hlim: given.sigma_hlim.map_or(limits.contact, |s| s[k]),
            sigma_flim: given.sigma_flim.map_or(limits.bending, |s| s[k]),
            life_curve: table.life_curve(),
            form_factor: root.form_factor,
            stress_correction_factor: root.stress_correction,
            rim_factor: 1.0,
            notch_sensitivity: 1.0,
            surface_factor: 1.0,
            cycles: cycles[k],
        })
    };
    let inputs = IsoInputs {
        // Not read by the preparation: each step's load and speed are.
        pinion_torque: 1.0,
        pinion_speed: 1.0,
        face_width: set.face_width,
        application_factor: spec.application_factor,
        dynamic: match given.dynamic_factor {
            Some(k) => IsoDynamic::Given(k),
            None => IsoDynamic::MethodB {
                density: STEEL_DENSITY,
            },
        },
        accuracy_grade: grade,
        face_load_factor: km,
        transverse_load_factor: given.transverse_load_factor,
        elasticity_factor: set.rating.elastic_coefficient,
        lubrication: None,
        members: [member(0)?, member(1)?],
    };
    PreparedIso::new(pair, &inputs)
        .map_err(|e| failed(SetupInput::Gear(GearInput::Pair), &format!("ISO 6336: {e}")))
}
