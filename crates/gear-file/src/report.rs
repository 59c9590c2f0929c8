//! `gear.json` and `report.md` of a rated pair.

use super::rating::{check_info, GearReport, JSource, Severity};
use super::validated::*;
use serde_json::{json, Map, Value};
use std::f64::consts::PI;
use std::fmt::Write as _;

/// Text for a Markdown table cell: `|` escaped.
fn cell(s: &str) -> String {
    s.replace('|', "\\|")
}

/// How a J was obtained, with the critical section it was computed at (SI, angles in degrees).
fn j_json(source: &JSource) -> Value {
    let JSource::Computed(b) = source else {
        return Value::Null;
    };
    match (b.agma, b.iso) {
        (Some(a), _) => json!({
            "chord_s_f": a.chord,
            "height_h_f": a.height,
            "fillet_radius_rho_f": a.fillet_radius,
            "load_angle_deg": a.load_angle.to_degrees(),
            "load_radius": a.load_radius,
            "form_factor_y": a.form_factor,
            "stress_correction_kf": a.stress_correction,
        }),
        (None, Some(f)) => json!({
            "chord_s_fn": f.section.chord,
            "moment_arm_h_fe": f.section.moment_arm,
            "fillet_radius_rho_f": f.section.fillet_radius,
            "load_angle_alpha_fen_deg": f.section.load_angle.to_degrees(),
            "load_diameter_d_en": f.section.load_diameter,
            "form_factor_y_f": f.form_factor,
            "stress_correction_y_s": f.stress_correction,
        }),
        _ => Value::Null,
    }
}

fn diameters_json(d: &cardan_gears::Diameters) -> Value {
    json!({
        "reference_diameter": d.reference,
        "base_diameter": d.base,
        "tip_diameter": d.tip,
        "root_diameter": d.root,
        "working_diameter": d.working,
    })
}

impl GearReport {
    /// `gear.json` (see docs/gear-calculator.md): SI numbers (m, N, Pa, W, rad/s),
    /// angles in degrees in fields named `*_deg`.
    pub fn to_json(&self) -> Value {
        let p = &self.pair;
        let s = &p.spec;
        let checks: Vec<Value> = self
            .checks
            .iter()
            .map(|c| {
                let (name, severity, meaning) = check_info(c.kind);
                json!({
                    "check": name,
                    "severity": match severity { Severity::Error => "error", Severity::Warning => "warning" },
                    "passed": c.passed,
                    "margin": c.margin,
                    "rule": meaning,
                    "remedies": c.remedies.iter().map(|r| r.to_string()).collect::<Vec<_>>(),
                })
            })
            .collect();
        let warnings = self.warnings();
        let rating = match &self.rating {
            None => Value::Null,
            Some(Err(e)) => json!({ "error": e }),
            Some(Ok(r)) => {
                let inputs = self.input.rating.as_ref().expect("rated pairs have inputs");
                let member = |k: usize| {
                    let mi = &inputs.members[k];
                    json!({
                        "cycles": r.cycles[k],
                        "j": r.j[k],
                        "j_method": r.j_source[k].word(),
                        "j_section": j_json(&r.j_source[k]),
                        "kb": mi.rim_factor,
                        "ks": r.ks[k],
                        "yn": r.yn[k],
                        "zn": r.zn[k],
                        "ch": r.ch[k],
                        "bending_allowable": mi.bending_allowable,
                        "contact_allowable": mi.contact_allowable,
                        "bending_stress": r.bending_stress[k],
                        "contact_stress": r.contact_stress[k],
                        "bending_safety_factor": r.bending_safety[k],
                        "contact_safety_factor": r.contact_safety[k],
                    })
                };
                json!({
                    "power": r.power,
                    "pinion_torque": r.pinion_torque,
                    "pinion_speed": inputs.pinion_speed,
                    "pitch_line_velocity": r.pitch_line_velocity,
                    "tangential_load": r.tangential_load,
                    "face_width": self.input.face_width,
                    "kv": r.kv,
                    "kv_velocity_limit": r.kv_velocity_limit,
                    "ko": inputs.overload,
                    "km": r.km,
                    "i": r.i,
                    "cp": inputs.elastic_coefficient,
                    "kt": inputs.temperature_factor,
                    "kr": inputs.reliability_factor,
                    "cf": inputs.surface_condition,
                    "required_safety_factor": inputs.required_safety_factor,
                    "basis": inputs.basis.word(),
                    "iso6336": super::iso_rating::iso_json(self),
                    "pinion": member(0),
                    "gear": member(1),
                    "warnings": r.warnings,
                })
            }
        };
        let mut inputs = Map::new();
        for (k, v) in &self.input.given {
            inputs.insert(k.clone(), json!(v));
        }
        json!({
            "schema_version": SCHEMA_VERSION,
            "name": self.input.name,
            "file": self.input.file.display().to_string(),
            "pair": if p.internal { "internal" } else { "external" },
            "passed": self.failures().is_empty(),
            "failures": self.failures(),
            "warnings": warnings,
            "inputs": inputs,
            "module": s.module,
            "cardan_crank_length": self.input.cardan_crank_length,
            "pressure_angle_deg": s.pressure_angle.to_degrees(),
            "teeth": [s.pinion.teeth, s.gear.teeth],
            "profile_shift": [s.pinion.shift, s.gear.shift],
            "ratio": p.ratio,
            "working_pressure_angle_deg": p.working_pressure_angle.to_degrees(),
            "operating_pressure_angle_deg": p.operating_pressure_angle.to_degrees(),
            "working_center_distance": p.working_centre_distance,
            "center_distance": p.centre_distance,
            "base_pitch": p.base_pitch,
            "path_of_contact": p.path_of_contact,
            "contact_ratio": p.contact_ratio,
            "backlash_circumferential": p.backlash_circumferential,
            "backlash_normal": p.backlash_normal,
            "gear_addendum": p.gear_addendum(),
            "max_gear_addendum_without_interference": p.max_gear_addendum_without_interference(),
            "trochoid_ratio": if p.internal { json!(p.trochoid_ratio()) } else { Value::Null },
            "pinion": diameters_json(&p.pinion),
            "gear": diameters_json(&p.gear),
            "face_width": self.input.face_width,
            "checks": checks,
            "rating": rating,
            "measurement": super::iso_rating::measurement_json(&self.input),
        })
    }

    /// `report.md`: inputs with units, geometry, checks with margins and remedies, rating.
    pub fn to_markdown(&self) -> String {
        let mut o = String::new();
        self.verdict_markdown(&mut o);
        self.geometry_markdown(&mut o);
        self.checks_markdown(&mut o);
        self.rating_markdown(&mut o);
        super::iso_rating::iso_markdown(self, &mut o);
        super::iso_rating::measurement_markdown(&self.input, &mut o);
        o
    }

    /// The title, the pair in a sentence, and the verdict with its failures and warnings.
    fn verdict_markdown(&self, o: &mut String) {
        let p = &self.pair;
        let s = &p.spec;
        let _ = writeln!(o, "# Gear pair `{}`\n", self.input.name);
        let _ = writeln!(
            o,
            "{} spur pair {}/{} from `{}`.\n",
            if p.internal { "Internal" } else { "External" },
            s.pinion.teeth,
            s.gear.teeth,
            self.input.file.display()
        );
        let failures = self.failures();
        if failures.is_empty() {
            let rated = match &self.input.rating {
                Some(r) => format!(
                    ", every safety factor at least required_safety_factor {}",
                    r.required_safety_factor
                ),
                None => ", geometry only".to_string(),
            };
            let _ = writeln!(
                o,
                "**Verdict: the pair works** (every blocking check passed{rated}).\n"
            );
        } else {
            let _ = writeln!(o, "**Verdict: the pair cannot work as given.**\n");
            for f in &failures {
                let _ = writeln!(o, "- {f}");
            }
            o.push('\n');
        }
        let warnings = self.warnings();
        if !warnings.is_empty() {
            let _ = writeln!(
                o,
                "Warnings (rules of thumb and the rating's caveats; they do not fail the pair):\n"
            );
            for w in &warnings {
                let _ = writeln!(o, "- {w}");
            }
            o.push('\n');
        }
    }

    /// The inputs as given, and the ISO 21771 geometry.
    fn geometry_markdown(&self, o: &mut String) {
        let p = &self.pair;
        let s = &p.spec;
        let mm = |x: f64| format!("{:.4}", x * 1e3);
        let _ = writeln!(o, "## Inputs\n\n| field | value as given |\n|---|---|");
        for (k, v) in &self.input.given {
            let _ = writeln!(o, "| `{k}` | `{}` |", cell(v));
        }
        let _ = writeln!(
            o,
            "\nBare numbers are SI (lengths m, speeds rad/s, power W, torque N·m, stress Pa), except angles (degrees).\n"
        );

        let _ = writeln!(o, "## Geometry (ISO 21771)\n");
        let _ = writeln!(o, "| quantity | value | unit |\n|---|---:|---|");
        let mut row = |q: &str, v: String, u: &str| {
            let _ = writeln!(o, "| {} | {v} | {u} |", cell(q));
        };
        row("module m", mm(s.module), "mm");
        if let Some(e) = self.input.cardan_crank_length {
            row("cardan crank length e (m = 2e/z1, A9.1.37)", mm(e), "mm");
        }
        row(
            "reference pressure angle α",
            format!("{:.4}", s.pressure_angle.to_degrees()),
            "deg",
        );
        row(
            "teeth z1 / z2",
            format!("{} / {}", s.pinion.teeth, s.gear.teeth),
            "-",
        );
        row(
            "profile shift x1 / x2 (ISO)",
            format!("{:.4} / {:.4}", s.pinion.shift, s.gear.shift),
            "-",
        );
        row("ratio u = |z2|/z1", format!("{:.4}", p.ratio), "-");
        row(
            "working pressure angle αw",
            format!("{:.4}", p.working_pressure_angle.to_degrees()),
            "deg",
        );
        row(
            "operating pressure angle",
            format!("{:.4}", p.operating_pressure_angle.to_degrees()),
            "deg",
        );
        row(
            "zero-backlash centre distance aw",
            mm(p.working_centre_distance),
            "mm",
        );
        row("centre distance a", mm(p.centre_distance), "mm");
        row("base pitch pb", mm(p.base_pitch), "mm");
        row("path of contact gα", mm(p.path_of_contact), "mm");
        row("contact ratio εα", format!("{:.4}", p.contact_ratio), "-");
        row(
            "backlash jt / jn",
            format!(
                "{} / {}",
                mm(p.backlash_circumferential),
                mm(p.backlash_normal)
            ),
            "mm",
        );
        row("gear addendum", mm(p.gear_addendum()), "mm");
        row(
            "largest gear addendum without involute interference",
            mm(p.max_gear_addendum_without_interference()),
            "mm",
        );
        if let Some(b) = self.input.face_width {
            row("face width b", mm(b), "mm");
        }
        let _ = writeln!(o, "\n| diameter [mm] | pinion | gear |\n|---|---:|---:|");
        for (name, f) in [
            (
                "reference d",
                (|d: &cardan_gears::Diameters| d.reference) as fn(&cardan_gears::Diameters) -> f64,
            ),
            ("base db", |d| d.base),
            ("tip da", |d| d.tip),
            ("root df", |d| d.root),
            ("working dw", |d| d.working),
        ] {
            let _ = writeln!(o, "| {name} | {} | {} |", mm(f(&p.pinion)), mm(f(&p.gear)));
        }
    }

    /// Every check with its margin, rule and remedies.
    fn checks_markdown(&self, o: &mut String) {
        let _ = writeln!(
            o,
            "\n## Checks\n\n| check | kind | margin | result | rule | remedy |\n|---|---|---:|---|---|---|"
        );
        for c in &self.checks {
            let (name, severity, meaning) = check_info(c.kind);
            let _ = writeln!(
                o,
                "| {name} | {} | {} | {} | {} | {} |",
                match severity {
                    Severity::Error => "blocking",
                    Severity::Warning => "rule of thumb",
                },
                c.margin_text(),
                if c.passed { "ok" } else { "**FAILED**" },
                cell(meaning),
                cell(
                    &c.remedies
                        .iter()
                        .map(|r| r.to_string())
                        .collect::<Vec<_>>()
                        .join("; or ")
                )
            );
        }
    }

    /// The AGMA 2001 rating, or why there is none.
    fn rating_markdown(&self, o: &mut String) {
        match &self.rating {
            None => {
                let _ = writeln!(o, "\n## Rating\n\nNo `[rating]` table: geometry only.");
            }
            Some(Err(e)) => {
                let _ = writeln!(o, "\n## Rating\n\nThe pair could not be rated: {e}");
            }
            Some(Ok(r)) => {
                let inputs = self.input.rating.as_ref().expect("rated pairs have inputs");
                let _ = writeln!(o, "\n## Rating (AGMA 2001-D04)\n");
                let _ = writeln!(o, "| quantity | value | unit |\n|---|---:|---|");
                let mut row = |q: &str, v: String, u: &str| {
                    let _ = writeln!(o, "| {q} | {v} | {u} |");
                };
                row("power", format!("{:.1}", r.power), "W");
                row("pinion torque", format!("{:.3}", r.pinion_torque), "N·m");
                row(
                    "pinion speed",
                    format!("{:.2}", inputs.pinion_speed * 30.0 / PI),
                    "rpm",
                );
                row(
                    "pitch-line velocity",
                    format!("{:.4}", r.pitch_line_velocity),
                    "m/s",
                );
                row(
                    "tangential load Wt",
                    format!("{:.2}", r.tangential_load),
                    "N",
                );
                row("dynamic factor Kv", format!("{:.4}", r.kv), "-");
                row("overload factor Ko", format!("{:.4}", inputs.overload), "-");
                row("load distribution factor Km", format!("{:.4}", r.km), "-");
                row("pitting geometry factor I", format!("{:.4}", r.i), "-");
                row(
                    "elastic coefficient Cp",
                    format!("{:.2}", inputs.elastic_coefficient / 1e3),
                    "√MPa",
                );
                row(
                    "temperature factor KT",
                    format!("{:.4}", inputs.temperature_factor),
                    "-",
                );
                row(
                    "reliability factor KR",
                    format!("{:.4}", inputs.reliability_factor),
                    "-",
                );
                let _ = writeln!(
                    o,
                    "\n| per member | pinion | gear | unit |\n|---|---:|---:|---|"
                );
                let mi = &inputs.members;
                let mut pair_row = |q: &str, a: [f64; 2], fmt: &dyn Fn(f64) -> String, u: &str| {
                    let _ = writeln!(o, "| {q} | {} | {} | {u} |", fmt(a[0]), fmt(a[1]));
                };
                let f4 = |x: f64| format!("{x:.4}");
                let f3 = |x: f64| format!("{x:.3}");
                let mpa = |x: f64| format!("{:.2}", x / 1e6);
                let cyc = |x: f64| format!("{x:.4e}");
                pair_row("load cycles", r.cycles, &cyc, "-");
                pair_row("bending geometry factor J", r.j, &f4, "-");
                let words = [r.j_source[0].word(), r.j_source[1].word()];
                let _ = writeln!(o, "| J obtained by | {} | {} | - |", words[0], words[1]);
                let mut pair_row = |q: &str, a: [f64; 2], fmt: &dyn Fn(f64) -> String, u: &str| {
                    let _ = writeln!(o, "| {q} | {} | {} | {u} |", fmt(a[0]), fmt(a[1]));
                };
                pair_row(
                    "rim thickness factor KB",
                    [mi[0].rim_factor, mi[1].rim_factor],
                    &f4,
                    "-",
                );
                pair_row("size factor Ks", r.ks, &f4, "-");
                pair_row("stress-cycle factor YN", r.yn, &f4, "-");
                pair_row("stress-cycle factor ZN", r.zn, &f4, "-");
                pair_row("hardness-ratio factor CH", r.ch, &f4, "-");
                pair_row(
                    "allowable bending stress St",
                    [mi[0].bending_allowable, mi[1].bending_allowable],
                    &mpa,
                    "MPa",
                );
                pair_row(
                    "allowable contact stress Sc",
                    [mi[0].contact_allowable, mi[1].contact_allowable],
                    &mpa,
                    "MPa",
                );
                pair_row("bending stress σ", r.bending_stress, &mpa, "MPa");
                pair_row("contact stress σc", r.contact_stress, &mpa, "MPa");
                pair_row("bending safety factor SF", r.bending_safety, &f3, "-");
                pair_row(
                    "pitting safety factor SH (stress ratio; compare SH² with SF)",
                    r.contact_safety,
                    &f3,
                    "-",
                );
                let _ = writeln!(
                    o,
                    "\nRequired safety factor (`required_safety_factor`, both SF and SH): {}",
                    inputs.required_safety_factor
                );
                for (k, member) in ["pinion", "gear"].into_iter().enumerate() {
                    if let JSource::Computed(b) = &r.j_source[k] {
                        let _ = writeln!(
                            o,
                            "\nJ of the {member} computed from the tooth form by {} (docs/gear-calculator.md).",
                            b.method.name()
                        );
                    }
                }
            }
        }
    }
}
