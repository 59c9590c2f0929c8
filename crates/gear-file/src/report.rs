//! `gear.json` and `report.md` of a rated pair.

use super::md_table::{cell, num, nums, Table};
use super::rating::{check_info, GearReport, JSource, Severity};
use super::validated::*;
use serde_json::{json, Map, Value};
use std::f64::consts::PI;
use std::fmt::Write as _;

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
        let checks = self.checks_json();
        let warnings = self.warnings();
        let rating = self.rating_json();
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

    /// `gear.json`'s `checks`: each check's name, severity, outcome, margin, rule and remedies.
    fn checks_json(&self) -> Vec<Value> {
        self.checks
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
            .collect()
    }

    /// `gear.json`'s `rating`: `null` without a `[rating]` table, its error, or the AGMA
    /// rating's factors, each member's stresses and safety factors, and the ISO 6336 rating.
    fn rating_json(&self) -> Value {
        match &self.rating {
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
        }
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
        let _ = writeln!(o, "## Inputs\n\n| field | value as given |\n|---|---|");
        for (k, v) in &self.input.given {
            let _ = writeln!(o, "| `{k}` | `{}` |", cell(v));
        }
        let _ = writeln!(
            o,
            "\nBare numbers are SI (lengths m, speeds rad/s, power W, torque N·m, stress Pa), except angles (degrees).\n"
        );

        let _ = writeln!(o, "## Geometry (ISO 21771)\n");
        let mut t = Table::quantities(o);
        t.value("module m", s.module, 1e-3, 4, "mm");
        if let Some(e) = self.input.cardan_crank_length {
            t.value(
                "cardan crank length e (m = 2e/z1, A9.1.37)",
                e,
                1e-3,
                4,
                "mm",
            );
        }
        let deg = |x: f64| num(x.to_degrees(), 4);
        t.row("reference pressure angle α", &deg(s.pressure_angle), "deg");
        let teeth = format!("{} / {}", s.pinion.teeth, s.gear.teeth);
        t.row("teeth z1 / z2", &teeth, "-");
        let shifts = nums(&[s.pinion.shift, s.gear.shift], 4);
        t.row("profile shift x1 / x2 (ISO)", &shifts, "-");
        t.value("ratio u = |z2|/z1", p.ratio, 1.0, 4, "-");
        let aw = deg(p.working_pressure_angle);
        t.row("working pressure angle αw", &aw, "deg");
        let a_op = deg(p.operating_pressure_angle);
        t.row("operating pressure angle", &a_op, "deg");
        for (q, x) in [
            (
                "zero-backlash centre distance aw",
                p.working_centre_distance,
            ),
            ("centre distance a", p.centre_distance),
            ("base pitch pb", p.base_pitch),
            ("path of contact gα", p.path_of_contact),
        ] {
            t.value(q, x, 1e-3, 4, "mm");
        }
        t.value("contact ratio εα", p.contact_ratio, 1.0, 4, "-");
        let backlash = nums(
            &[p.backlash_circumferential * 1e3, p.backlash_normal * 1e3],
            4,
        );
        t.row("backlash jt / jn", &backlash, "mm");
        t.value("gear addendum", p.gear_addendum(), 1e-3, 4, "mm");
        t.value(
            "largest gear addendum without involute interference",
            p.max_gear_addendum_without_interference(),
            1e-3,
            4,
            "mm",
        );
        if let Some(b) = self.input.face_width {
            t.value("face width b", b, 1e-3, 4, "mm");
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
            let (a, b) = (f(&p.pinion) * 1e3, f(&p.gear) * 1e3);
            let _ = writeln!(o, "| {name} | {} | {} |", num(a, 4), num(b, 4));
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
                let mut t = Table::quantities(o);
                t.value("power", r.power, 1.0, 1, "W");
                t.value("pinion torque", r.pinion_torque, 1.0, 3, "N·m");
                t.value("pinion speed", inputs.pinion_speed, PI / 30.0, 2, "rpm");
                t.value("pitch-line velocity", r.pitch_line_velocity, 1.0, 4, "m/s");
                t.value("tangential load Wt", r.tangential_load, 1.0, 2, "N");
                t.value("dynamic factor Kv", r.kv, 1.0, 4, "-");
                t.value("overload factor Ko", inputs.overload, 1.0, 4, "-");
                t.value("load distribution factor Km", r.km, 1.0, 4, "-");
                t.value("pitting geometry factor I", r.i, 1.0, 4, "-");
                let cp = inputs.elastic_coefficient;
                t.value("elastic coefficient Cp", cp, 1e3, 2, "√MPa");
                t.value(
                    "temperature factor KT",
                    inputs.temperature_factor,
                    1.0,
                    4,
                    "-",
                );
                t.value(
                    "reliability factor KR",
                    inputs.reliability_factor,
                    1.0,
                    4,
                    "-",
                );
                o.push('\n');
                let mi = &inputs.members;
                let mut t = Table::members(o, "per member");
                let cycles = r.cycles.map(|c| format!("{c:.4e}"));
                t.pair_text("load cycles", [&cycles[0], &cycles[1]], "-");
                t.pair("bending geometry factor J", r.j, 1.0, 4, "-");
                let words = [r.j_source[0].word(), r.j_source[1].word()];
                t.pair_text("J obtained by", words, "-");
                let rim = [mi[0].rim_factor, mi[1].rim_factor];
                t.pair("rim thickness factor KB", rim, 1.0, 4, "-");
                t.pair("size factor Ks", r.ks, 1.0, 4, "-");
                t.pair("stress-cycle factor YN", r.yn, 1.0, 4, "-");
                t.pair("stress-cycle factor ZN", r.zn, 1.0, 4, "-");
                t.pair("hardness-ratio factor CH", r.ch, 1.0, 4, "-");
                let st = [mi[0].bending_allowable, mi[1].bending_allowable];
                t.pair("allowable bending stress St", st, 1e6, 2, "MPa");
                let sc = [mi[0].contact_allowable, mi[1].contact_allowable];
                t.pair("allowable contact stress Sc", sc, 1e6, 2, "MPa");
                t.pair("bending stress σ", r.bending_stress, 1e6, 2, "MPa");
                t.pair("contact stress σc", r.contact_stress, 1e6, 2, "MPa");
                t.pair("bending safety factor SF", r.bending_safety, 1.0, 3, "-");
                t.pair(
                    "pitting safety factor SH (stress ratio; compare SH² with SF)",
                    r.contact_safety,
                    1.0,
                    3,
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
