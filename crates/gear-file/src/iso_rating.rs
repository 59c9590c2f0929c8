//! The ISO 6336 method B rating of a gear file beside its AGMA 2001 one, and the tooth
//! thickness measurements: computed, written to `gear.json` and `report.md`.

use super::md_table::{cells, num, nums, Table};
use super::rating::GearReport;
use super::validated::*;
use cardan_gears::iso6336::IsoDynamic;
use cardan_gears::tooth_measurement::{
    ideal_pin_diameter, over_pins, span_width, span_width_auto, MeasuredGear, OverPins, Span,
};
use serde_json::{json, Value};
use std::fmt::Write as _;

/// `gear.json`'s `rating.iso6336`.
pub fn iso_json(report: &GearReport) -> Value {
    match &report.iso {
        None => Value::Null,
        Some(Err(e)) => json!({ "error": e }),
        Some(Ok(o)) => {
            let per = |k: usize| {
                json!({
                    "z_bd": o.z_bd[k],
                    "z_nt": o.z_nt[k],
                    "z_x": o.z_x[k],
                    "y_nt": o.y_nt[k],
                    "y_x": o.y_x[k],
                    "contact_stress": o.sigma_h[k],
                    "pitting_stress_limit": o.sigma_hg[k],
                    "contact_safety_factor": o.s_h[k],
                    "form_factor_y_f": o.y_f[k],
                    "stress_correction_y_s": o.y_s[k],
                    "nominal_root_stress": o.sigma_f0[k],
                    "root_stress": o.sigma_f[k],
                    "root_stress_limit": o.sigma_fg[k],
                    "bending_safety_factor": o.s_f[k],
                })
            };
            json!({
                "tangential_load": o.tangential_load,
                "reference_velocity": o.velocity,
                "resonance_ratio": o.resonance_ratio,
                "k_a": o.k_a, "k_v": o.k_v, "k_hbeta": o.k_hbeta, "k_halpha": o.k_halpha,
                "k_fbeta": o.k_fbeta, "k_falpha": o.k_falpha,
                "z_h": o.z_h, "z_e": o.z_e, "z_eps": o.z_eps, "z_beta": o.z_beta,
                "z_l": o.z_lvr[0], "z_v": o.z_lvr[1], "z_r": o.z_lvr[2], "z_w": o.z_w,
                "y_beta": o.y_beta, "y_dt": o.y_dt,
                "nominal_contact_stress": o.sigma_h0,
                "pinion": per(0),
                "gear": per(1),
            })
        }
    }
}

/// `report.md`'s ISO section, with the side-by-side safety factors.
pub fn iso_markdown(report: &GearReport, o: &mut String) {
    let Some(iso) = &report.iso else {
        return;
    };
    let basis = report
        .input
        .rating
        .as_ref()
        .map_or(Basis::Agma2001, |r| r.basis);
    let _ = writeln!(o, "\n## Rating (ISO 6336-2/-3:2019, method B)\n");
    let r = match iso {
        Err(e) => {
            let _ = writeln!(o, "The pair could not be rated by ISO 6336: {e}");
            return;
        }
        Ok(r) => r,
    };
    let dynamic = match report.input.rating.as_ref().and_then(|i| i.iso) {
        Some(i) if matches!(i.dynamic, IsoDynamic::Given(_)) => "given",
        _ => "ISO 6336-1 method B",
    };
    let mut t = Table::quantities(o);
    let ft = r.tangential_load;
    t.value(
        "tangential load at the reference circle F_t",
        ft,
        1.0,
        2,
        "N",
    );
    t.value("application factor K_A", r.k_a, 1.0, 4, "-");
    t.value(
        &format!("dynamic factor K_v ({dynamic})"),
        r.k_v,
        1.0,
        4,
        "-",
    );
    if let Some(n) = r.resonance_ratio {
        t.value("resonance ratio N", n, 1.0, 4, "-");
    }
    let kb = nums(&[r.k_hbeta, r.k_fbeta], 4);
    t.row("face load factors K_Hβ / K_Fβ", &kb, "-");
    let ka = nums(&[r.k_halpha, r.k_falpha], 4);
    t.row("transverse load factors K_Hα / K_Fα", &ka, "-");
    t.value("zone factor Z_H", r.z_h, 1.0, 4, "-");
    t.value("elasticity factor Z_E", r.z_e, 1e3, 2, "√MPa");
    t.value("contact ratio factor Z_ε", r.z_eps, 1.0, 4, "-");
    let z = nums(&[r.z_lvr[0], r.z_lvr[1], r.z_lvr[2], r.z_w], 4);
    t.row("Z_L / Z_v / Z_R / Z_W", &z, "-");
    t.value("nominal contact stress σ_H0", r.sigma_h0, 1e6, 2, "MPa");
    o.push('\n');
    let mut t = Table::members(o, "per member");
    t.pair("Z_B / Z_D", r.z_bd, 1.0, 4, "-");
    t.pair("life factor Z_NT", r.z_nt, 1.0, 4, "-");
    t.pair("size factor Z_X", r.z_x, 1.0, 4, "-");
    t.pair("contact stress σ_H", r.sigma_h, 1e6, 4, "MPa");
    t.pair("pitting stress limit σ_HG", r.sigma_hg, 1e6, 4, "MPa");
    t.pair("life factor Y_NT", r.y_nt, 1.0, 4, "-");
    t.pair("size factor Y_X", r.y_x, 1.0, 4, "-");
    t.pair("root stress σ_F", r.sigma_f, 1e6, 4, "MPa");
    t.pair("root stress limit σ_FG", r.sigma_fg, 1e6, 4, "MPa");
    t.pair("bending safety factor S_F", r.s_f, 1.0, 4, "-");
    t.pair("pitting safety factor S_H", r.s_h, 1.0, 4, "-");
    if let Some(Ok(a)) = &report.rating {
        let _ = writeln!(
            o,
            "\n### AGMA 2001 and ISO 6336 side by side (verdict basis: {})\n\n| safety factor | AGMA pinion | AGMA gear | ISO pinion | ISO gear |\n|---|---:|---:|---:|---:|",
            basis.word()
        );
        let sf = cells(
            &[a.bending_safety[0], a.bending_safety[1], r.s_f[0], r.s_f[1]],
            3,
        );
        let sh = cells(
            &[a.contact_safety[0], a.contact_safety[1], r.s_h[0], r.s_h[1]],
            3,
        );
        let _ = writeln!(o, "| bending (SF / S_F) | {sf} |");
        let _ = writeln!(o, "| pitting (SH / S_H) | {sh} |");
    }
}

/// One member's measurements: its span (none for a ring) and the pin dimension.
pub type Measured = (Option<Span>, OverPins);

/// The measurements of `[measurement]`: for each member, the span (external gears) and the
/// dimension over / between pins.
pub fn measurements(input: &GearFile) -> Option<Result<[Measured; 2], String>> {
    let m = input.measurement?;
    let s = &input.spec;
    Some((|| {
        let one = |k: usize| -> Result<Measured, String> {
            let g = [&s.pinion, &s.gear][k];
            let gear = MeasuredGear {
                module: s.module,
                pressure_angle: s.pressure_angle,
                teeth: g.teeth.unsigned_abs(),
                shift: g.shift,
                thinning: g.thickness_allowance,
                internal: g.teeth < 0,
            };
            let span = if gear.internal {
                None
            } else {
                Some(
                    match m.span_teeth {
                        Some(kk) => span_width(&gear, kk[k]),
                        None => span_width_auto(&gear),
                    }
                    .map_err(|e| e.to_string())?,
                )
            };
            let pin = match m.pin_diameter {
                Some(p) => p[k],
                None => ideal_pin_diameter(&gear).map_err(|e| e.to_string())?,
            };
            Ok((span, over_pins(&gear, pin).map_err(|e| e.to_string())?))
        };
        Ok([one(0)?, one(1)?])
    })())
}

/// `gear.json`'s `measurement`.
pub fn measurement_json(input: &GearFile) -> Value {
    match measurements(input) {
        None => Value::Null,
        Some(Err(e)) => json!({ "error": e }),
        Some(Ok(ms)) => {
            let one = |(span, pins): &Measured| {
                json!({
                    "span_teeth": span.map(|s| s.teeth),
                    "span_width": span.map(|s| s.width),
                    "span_contact_diameter": span.map(|s| s.contact_diameter),
                    "pin_diameter": pins.pin_diameter,
                    "dimension_over_pins": pins.dimension,
                    "pin_centre_diameter": pins.centre_diameter,
                })
            };
            json!({ "pinion": one(&ms[0]), "gear": one(&ms[1]) })
        }
    }
}

/// `report.md`'s measurement section.
pub fn measurement_markdown(input: &GearFile, o: &mut String) {
    let Some(ms) = measurements(input) else {
        return;
    };
    let _ = writeln!(
        o,
        "\n## Tooth thickness measurements (ISO 21771 §6.3, §6.4)\n"
    );
    let ms = match ms {
        Err(e) => {
            let _ = writeln!(o, "Not computed: {e}");
            return;
        }
        Ok(ms) => ms,
    };
    let _ = writeln!(
        o,
        "With the thinning of `thickness_allowance`. A ring's dimension is between the pins.\n"
    );
    let mut t = Table::members(o, "quantity");
    let span = |k: usize, f: fn(&Span) -> String| ms[k].0.as_ref().map_or("-".to_string(), f);
    let k = [0, 1].map(|k| span(k, |s| s.teeth.to_string()));
    t.pair_text("teeth spanned k", [&k[0], &k[1]], "-");
    let w = [0, 1].map(|k| span(k, |s| num(s.width * 1e3, 4)));
    t.pair_text("span width W_k", [&w[0], &w[1]], "mm");
    let pins = [ms[0].1.pin_diameter, ms[1].1.pin_diameter];
    t.pair("pin / ball diameter D_M", pins, 1e-3, 4, "mm");
    let dims = [ms[0].1.dimension, ms[1].1.dimension];
    t.pair("dimension over (between) pins M_d", dims, 1e-3, 4, "mm");
}
