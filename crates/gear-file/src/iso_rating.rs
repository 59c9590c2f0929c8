//! The ISO 6336 method B rating of a gear file beside its AGMA 2001 one, and the tooth
//! thickness measurements: computed, written to `gear.json` and `report.md`.

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
    let _ = writeln!(o, "| quantity | value | unit |\n|---|---:|---|");
    let mut row = |q: &str, v: String, u: &str| {
        let _ = writeln!(o, "| {q} | {v} | {u} |");
    };
    row(
        "tangential load at the reference circle F_t",
        format!("{:.2}", r.tangential_load),
        "N",
    );
    row("application factor K_A", format!("{:.4}", r.k_a), "-");
    row(
        &format!("dynamic factor K_v ({dynamic})"),
        format!("{:.4}", r.k_v),
        "-",
    );
    if let Some(n) = r.resonance_ratio {
        row("resonance ratio N", format!("{n:.4}"), "-");
    }
    row(
        "face load factors K_Hβ / K_Fβ",
        format!("{:.4} / {:.4}", r.k_hbeta, r.k_fbeta),
        "-",
    );
    row(
        "transverse load factors K_Hα / K_Fα",
        format!("{:.4} / {:.4}", r.k_halpha, r.k_falpha),
        "-",
    );
    row("zone factor Z_H", format!("{:.4}", r.z_h), "-");
    row(
        "elasticity factor Z_E",
        format!("{:.2}", r.z_e / 1e3),
        "√MPa",
    );
    row("contact ratio factor Z_ε", format!("{:.4}", r.z_eps), "-");
    row(
        "Z_L / Z_v / Z_R / Z_W",
        format!(
            "{:.4} / {:.4} / {:.4} / {:.4}",
            r.z_lvr[0], r.z_lvr[1], r.z_lvr[2], r.z_w
        ),
        "-",
    );
    row(
        "nominal contact stress σ_H0",
        format!("{:.2}", r.sigma_h0 / 1e6),
        "MPa",
    );
    let _ = writeln!(
        o,
        "\n| per member | pinion | gear | unit |\n|---|---:|---:|---|"
    );
    let mut pair_row = |q: &str, a: [f64; 2], scale: f64, u: &str| {
        let _ = writeln!(
            o,
            "| {q} | {:.4} | {:.4} | {u} |",
            a[0] / scale,
            a[1] / scale
        );
    };
    pair_row("Z_B / Z_D", r.z_bd, 1.0, "-");
    pair_row("life factor Z_NT", r.z_nt, 1.0, "-");
    pair_row("size factor Z_X", r.z_x, 1.0, "-");
    pair_row("contact stress σ_H", r.sigma_h, 1e6, "MPa");
    pair_row("pitting stress limit σ_HG", r.sigma_hg, 1e6, "MPa");
    pair_row("life factor Y_NT", r.y_nt, 1.0, "-");
    pair_row("size factor Y_X", r.y_x, 1.0, "-");
    pair_row("root stress σ_F", r.sigma_f, 1e6, "MPa");
    pair_row("root stress limit σ_FG", r.sigma_fg, 1e6, "MPa");
    pair_row("bending safety factor S_F", r.s_f, 1.0, "-");
    pair_row("pitting safety factor S_H", r.s_h, 1.0, "-");
    if let Some(Ok(a)) = &report.rating {
        let _ = writeln!(
            o,
            "\n### AGMA 2001 and ISO 6336 side by side (verdict basis: {})\n\n| safety factor | AGMA pinion | AGMA gear | ISO pinion | ISO gear |\n|---|---:|---:|---:|---:|",
            basis.word()
        );
        let _ = writeln!(
            o,
            "| bending (SF / S_F) | {:.3} | {:.3} | {:.3} | {:.3} |",
            a.bending_safety[0], a.bending_safety[1], r.s_f[0], r.s_f[1]
        );
        let _ = writeln!(
            o,
            "| pitting (SH / S_H) | {:.3} | {:.3} | {:.3} | {:.3} |",
            a.contact_safety[0], a.contact_safety[1], r.s_h[0], r.s_h[1]
        );
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
    let _ = writeln!(o, "With the thinning of `thickness_allowance`. A ring's dimension is between the pins.\n\n| quantity | pinion | gear | unit |\n|---|---:|---:|---|");
    let span = |s: &Option<Span>, f: fn(&Span) -> String| s.as_ref().map_or("-".to_string(), f);
    let _ = writeln!(
        o,
        "| teeth spanned k | {} | {} | - |",
        span(&ms[0].0, |s| s.teeth.to_string()),
        span(&ms[1].0, |s| s.teeth.to_string())
    );
    let _ = writeln!(
        o,
        "| span width W_k | {} | {} | mm |",
        span(&ms[0].0, |s| format!("{:.4}", s.width * 1e3)),
        span(&ms[1].0, |s| format!("{:.4}", s.width * 1e3))
    );
    let _ = writeln!(
        o,
        "| pin / ball diameter D_M | {:.4} | {:.4} | mm |",
        ms[0].1.pin_diameter * 1e3,
        ms[1].1.pin_diameter * 1e3
    );
    let _ = writeln!(
        o,
        "| dimension over (between) pins M_d | {:.4} | {:.4} | mm |",
        ms[0].1.dimension * 1e3,
        ms[1].1.dimension * 1e3
    );
}
