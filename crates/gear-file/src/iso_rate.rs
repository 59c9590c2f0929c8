//! The ISO 6336 method B rating of a gear file's pair (what `rating.rs` computes beside the
//! AGMA rating; `iso_rating.rs` writes it).

use super::validated::*;
use cardan_gears::iso6336::{rate, IsoInputs, IsoMember, IsoRating};
use cardan_gears::tooth_root::{iso6336_method_b, GeneratedMember, PairMember};
use cardan_gears::GearPair;

/// The ISO rating of the pair, when its inputs are given; an error names what could not be
/// computed or is not finite.
pub fn rate_iso(
    pair: &GearPair,
    r: &RatingInputs,
    face_width: f64,
    rack_tip_radius: [Option<f64>; 2],
) -> Option<Result<IsoRating, String>> {
    let iso = r.iso?;
    Some((|| {
        let d1 = pair.pinion.working;
        let torque = match r.load {
            Load::Power(p) => p / r.pinion_speed,
            Load::Torque(t) => t,
        };
        let k_hb = match iso.face_load_factor {
            Some(k) => k,
            None => {
                r.load_distribution
                    .factor(face_width, d1)
                    .map_err(|e| format!("ISO K_Hβ from AGMA Km: {e}"))?
                    .km
            }
        };
        let cycles = [r.pinion_cycles, r.pinion_cycles / pair.ratio];
        let member = |k: usize| -> Result<IsoMember, String> {
            let m = r.members[k].iso.ok_or("ISO member inputs missing")?;
            let (form_factor, stress_correction_factor) =
                match (m.form_factor, m.stress_correction_factor) {
                    (Some(y_f), Some(y_s)) => (y_f, y_s),
                    _ => {
                        let which = if k == 0 {
                            PairMember::Pinion
                        } else {
                            PairMember::Gear
                        };
                        let member = GeneratedMember {
                            which,
                            rack_tip_radius: rack_tip_radius[k],
                        };
                        let root = iso6336_method_b(pair, member)
                            .map_err(|e| format!("ISO 6336-3 Y_F, Y_S from the tooth form: {e}"))?;
                        (root.form_factor, root.stress_correction)
                    }
                };
            Ok(IsoMember {
                sigma_hlim: m.sigma_hlim,
                sigma_flim: m.sigma_flim,
                life_curve: m.life_curve,
                form_factor,
                stress_correction_factor,
                rim_factor: 1.0,
                notch_sensitivity: 1.0,
                surface_factor: 1.0,
                cycles: cycles[k],
            })
        };
        let out = rate(
            pair,
            &IsoInputs {
                pinion_torque: torque,
                pinion_speed: r.pinion_speed,
                face_width,
                application_factor: iso.application_factor,
                dynamic: iso.dynamic,
                accuracy_grade: iso.accuracy_grade,
                face_load_factor: k_hb,
                transverse_load_factor: iso.transverse_load_factor,
                elasticity_factor: r.elastic_coefficient,
                lubrication: iso.lubrication,
                members: [member(0)?, member(1)?],
            },
        )
        .map_err(|e| format!("ISO 6336: {e}"))?;
        let figures = [
            ("ISO contact stress of the pinion", out.sigma_h[0]),
            ("ISO contact stress of the gear", out.sigma_h[1]),
            ("ISO root stress of the pinion", out.sigma_f[0]),
            ("ISO root stress of the gear", out.sigma_f[1]),
            ("ISO S_H of the pinion", out.s_h[0]),
            ("ISO S_H of the gear", out.s_h[1]),
            ("ISO S_F of the pinion", out.s_f[0]),
            ("ISO S_F of the gear", out.s_f[1]),
            ("ISO K_v", out.k_v),
        ];
        if let Some((q, v)) = figures.iter().find(|(_, v)| !v.is_finite()) {
            return Err(format!(
                "{q} = {v} is not a finite number: check rating.power or rating.torque, rating.pinion_speed and the ISO factors"
            ));
        }
        Ok(out)
    })())
}
