//! Gear files against published examples (Shigley Example 14-4, the KHK internal-gear example of
//! `docs/validation/gears.md` §1.2), the interfering 20/40 internal pair, the shipped examples in
//! `configs-gears/`, bad files and the output folder.

use cardan_case::units::{to_si, Dimension};
use cardan_gear_file::{evaluate, load, parse, run, GearReport};
use cardan_gears::units::{INCH, LBF, PSI};
use cardan_testing::mentions;
use serde_json::Value;
use std::path::{Path, PathBuf};

fn shipped(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../configs-gears")
        .join(name)
}

fn report_of(text: &str) -> GearReport {
    evaluate(&parse(Path::new("gears/test.toml"), text).unwrap()).unwrap()
}

fn error_of(text: &str) -> String {
    match parse(Path::new("gears/bad.toml"), text) {
        Ok(_) => panic!("accepted a bad gear file:\n{text}"),
        Err(e) => e.to_string(),
    }
}

/// The tolerance of `crates/gears/tests/agma.rs`: half a unit of the last printed digit plus
/// 0.1 % for Shigley's rounding of intermediate factors to 3–4 figures.
fn close(value: f64, printed: f64, half_unit: f64) -> bool {
    (value - printed).abs() <= half_unit + 1e-3 * printed.abs()
}

fn check<'a>(json: &'a Value, name: &str) -> &'a Value {
    json["checks"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["check"] == name)
        .unwrap_or_else(|| panic!("no check {name}"))
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

#[test]
fn shigley_example_14_4_through_the_shipped_gear_file() {
    // docs/validation/gears.md §2.1: Budynas & Nisbett, Shigley's MED, Example 14-4, with its KR =
    // 0.85 (AGMA table at R = 0.90) and Cp = 2300 √psi pinned as the example does.
    let dir = tempfile::tempdir().unwrap();
    let written = run(&shipped("shigley-14-4.toml"), dir.path()).unwrap();
    assert!(written.report.failures().is_empty());
    let text = std::fs::read_to_string(dir.path().join("shigley-14-4/gear.json")).unwrap();
    let j: Value = serde_json::from_str(&text).unwrap();
    let r = &j["rating"];
    // Factors printed by Shigley.
    assert!(close(num(&r["tangential_load"]) / LBF, 164.8, 0.05));
    assert!(close(num(&r["kv"]), 1.377, 0.0005));
    assert!(close(num(&r["i"]), 0.121, 0.0005));
    assert!(close(num(&r["km"]), 1.22, 0.005));
    assert!(close(num(&r["kr"]), 0.85, 0.0));
    assert!(close(num(&r["pinion"]["ks"]), 1.043, 0.0005));
    assert!(close(num(&r["gear"]["ks"]), 1.052, 0.0005));
    // Outputs: bending 6417 / 4854 psi, contact 70 360 / 70 660 psi, SF 5.62 / 6.82,
    // SH 1.69 / 1.52.
    let psi = |v: &Value| num(v) / PSI;
    for (member, bending, contact, sf, sh) in [
        ("pinion", 6417.0, 70_360.0, 5.62, 1.69),
        ("gear", 4854.0, 70_660.0, 6.82, 1.52),
    ] {
        let m = &r[member];
        let s = psi(&m["bending_stress"]);
        assert!(close(s, bending, 0.5), "{member} bending {s}");
        let sc = psi(&m["contact_stress"]);
        assert!(close(sc, contact, 5.0), "{member} contact {sc}");
        let f = num(&m["bending_safety_factor"]);
        assert!(close(f, sf, 0.005), "{member} SF {f}");
        let h = num(&m["contact_safety_factor"]);
        assert!(close(h, sh, 0.005), "{member} SH {h}");
    }
    // Geometry: dP = 1.7 in, standard centre distance (17 + 52)/20 in = 3.45 in, exact.
    assert!((num(&j["pinion"]["working_diameter"]) / INCH - 1.7).abs() < 1e-12);
    assert!((num(&j["center_distance"]) / INCH - 3.45).abs() < 1e-12);
    assert!((num(&j["working_pressure_angle_deg"]) - 20.0).abs() < 1e-12);
    assert_eq!(j["passed"], true);
    // A 17-tooth 20° pinion without shift is just below the rack-generation undercut limit:
    // a warning, not a failure.
    assert_eq!(check(&j, "pinion_undercut")["severity"], "warning");
    assert_eq!(check(&j, "pinion_undercut")["passed"], false);
    let md = std::fs::read_to_string(dir.path().join("shigley-14-4/report.md")).unwrap();
    mentions(
        &md,
        &[
            "bending stress σ",
            "pitting safety factor SH",
            "| bending safety factor SF | 5.615 | 6.827 | - |",
            "`\"4 hp\"`",
        ],
    );
}

#[test]
fn torque_and_power_give_the_same_rating() {
    // 4 hp at 1800 rpm = 15.8245 N·m on the pinion: the same stresses to rounding.
    let text = std::fs::read_to_string(shipped("shigley-14-4.toml")).unwrap();
    let a = report_of(&text);
    let t = 4.0 * cardan_gears::units::HORSEPOWER / (1800.0 * std::f64::consts::PI / 30.0);
    let b = report_of(&text.replace("power = \"4 hp\"", &format!("torque = \"{t} N*m\"")));
    let (ra, rb) = (a.rating.unwrap().unwrap(), b.rating.unwrap().unwrap());
    for k in 0..2 {
        assert!((ra.bending_stress[k] / rb.bending_stress[k] - 1.0).abs() < 1e-12);
        assert!((ra.contact_safety[k] / rb.contact_safety[k] - 1.0).abs() < 1e-12);
    }
}

const KHK: &str = r#"
name = "khk-internal"
module = "3 mm"
pressure_angle = 20
teeth = [16, -24]
profile_shift = [0.0, -0.516]   # KHK x2 = +0.516 is ISO x2 = -0.516
"#;

#[test]
fn khk_internal_gear_example() {
    // docs/validation/gears.md §1.2 (KHK Gear Technical Reference, m = 3, α = 20°, 16/24, x2 =
    // 0.516): values printed to 4–6 significant figures, tolerance half a unit of the last digit,
    // as in crates/gears/tests/geometry.rs.
    let j = report_of(KHK).to_json();
    let mm = |v: &Value| num(v) * 1e3;
    assert_eq!(j["pair"], "internal");
    assert!((num(&j["working_pressure_angle_deg"]) - 31.3209).abs() < 5e-5);
    assert!((mm(&j["center_distance"]) - 13.2000).abs() < 5e-5);
    assert!((mm(&j["pinion"]["reference_diameter"]) - 48.0).abs() < 1e-9);
    assert!((mm(&j["gear"]["reference_diameter"]) - 72.0).abs() < 1e-9);
    assert!((mm(&j["pinion"]["base_diameter"]) - 45.1052).abs() < 5e-5);
    assert!((mm(&j["gear"]["base_diameter"]) - 67.6579).abs() < 5e-5);
    assert!((mm(&j["pinion"]["working_diameter"]) - 52.7998).abs() < 5e-5);
    assert!((mm(&j["gear"]["working_diameter"]) - 79.1997).abs() < 5e-5);
    assert!((mm(&j["pinion"]["tip_diameter"]) - 54.000).abs() < 5e-4);
    assert!((mm(&j["gear"]["tip_diameter"]) - 69.096).abs() < 5e-4);
    assert!((num(&j["contact_ratio"]) - 1.6592).abs() < 5e-5);
    // Path of contact = εα · π m cos α (its definition), so it carries the same check.
    let pb = std::f64::consts::PI * 3.0 * 20f64.to_radians().cos();
    assert!((mm(&j["path_of_contact"]) / pb - 1.6592).abs() < 5e-5);
    // Involute interference OK: z1/z2 = 0.6667 >= KHK limit 0.6594 (margin = z1/z2 − limit).
    let inv = check(&j, "involute_interference_pinion");
    assert_eq!(inv["passed"], true);
    assert!((16.0 / 24.0 - num(&inv["margin"]) - 0.6594).abs() < 5e-5);
    // Trochoid OK: 0.6667 >= θ2/θ1 = 0.6314.
    assert!((num(&j["trochoid_ratio"]) - 0.6314).abs() < 5e-5);
    assert_eq!(check(&j, "trochoid_interference")["passed"], true);
    // KHK's pair breaks only the rules of thumb (teeth difference 8 < 10, 16-tooth pinion
    // without shift): warnings, so the pair passes.
    assert_eq!(j["passed"], true);
    assert_eq!(j["warnings"].as_array().unwrap().len(), 2);
    assert_eq!(check(&j, "teeth_difference")["severity"], "warning");

    // The same pair unshifted: the ring tip (66 mm) lies inside its base circle.
    let q = report_of(&KHK.replace("profile_shift = [0.0, -0.516]", ""));
    let f = q.failures();
    assert!(
        f.iter()
            .any(|m| m.contains("ring_tip_inside_base_circle")
                && m.contains("shorter ring addendum")),
        "{f:?}"
    );
}

const INTERFERING: &str = r#"
name = "internal-20-40-full"
module = "3 mm"
pressure_angle = "20 deg"
teeth = [20, -40]
"#;

#[test]
fn interfering_internal_pair_is_written_and_fails_naming_the_remedy() {
    // docs/validation/gears.md §1.3/§1.4: 20/40, 20°, full ring addendum interferes (KHK limit
    // 0.592 > z1/z2 = 0.5); largest ring addendum 0.8975 m (4 decimals, ±5e-5 m).
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("pair.toml");
    std::fs::write(&file, INTERFERING).unwrap();
    let written = run(&file, &dir.path().join("out")).unwrap();
    let f = written.report.failures();
    assert_eq!(f.len(), 1, "{f:?}");
    mentions(
        &f[0],
        &[
            "involute_interference_pinion",
            "FAILED",
            "shorter ring addendum (at most 2.692",
            "profile shift",
            "larger pressure angle",
        ],
    );
    // Geometry is still written, with the check, its margin and remedies.
    let j: Value =
        serde_json::from_str(&std::fs::read_to_string(written.dir.join("gear.json")).unwrap())
            .unwrap();
    assert_eq!(j["passed"], false);
    let c = check(&j, "involute_interference_pinion");
    assert_eq!(c["passed"], false);
    assert!((0.5 - num(&c["margin"]) - 0.592).abs() < 5e-4);
    assert!(c["remedies"][0]
        .as_str()
        .unwrap()
        .starts_with("shorter ring addendum"));
    assert!((num(&j["max_gear_addendum_without_interference"]) / 3e-3 - 0.8975).abs() < 5e-5);
    assert!((num(&j["contact_ratio"]) - 2.1500).abs() < 5e-5);
    assert!(written.dir.join("report.md").is_file());
    let md = std::fs::read_to_string(written.dir.join("report.md")).unwrap();
    mentions(&md, &["cannot work", "**FAILED**", "shorter ring addendum"]);
}

#[test]
fn karhula_cardan_pair_example() {
    // Karhula 2008 A9.1.37: m = 2e/z1 = 2·30 mm/20 = 3 mm; ring addendum 0.8 m gives εα 1.7649
    // (docs/validation/gears.md §1.3, 4 decimals) and no interference.
    let input = load(&shipped("karhula-cardan-20-40.toml")).unwrap();
    let report = evaluate(&input).unwrap();
    assert!(report.failures().is_empty(), "{:?}", report.failures());
    let j = report.to_json();
    assert!((num(&j["module"]) - 3e-3).abs() < 1e-15);
    assert!((num(&j["center_distance"]) - 0.03).abs() < 1e-15);
    assert!((num(&j["contact_ratio"]) - 1.7649).abs() < 5e-5);
    assert!((num(&j["gear"]["tip_diameter"]) - 0.1152).abs() < 1e-12);
    assert_eq!(j["warnings"].as_array().unwrap().len(), 0);
    assert!(j["rating"].is_null());
}

#[test]
fn bad_files_name_file_pair_field_and_rule() {
    let cases: &[(&str, &str, &[&str])] = &[
        (
            "teeth = [20, -40]",
            "teeth = [20, -15]",
            &["teeth", "[20, -15]", "more teeth than the pinion"],
        ),
        (
            "teeth = [20, -40]",
            "teeth = [20]",
            &["teeth", "two values"],
        ),
        (
            "teeth = [20, -40]",
            "teeth = [20.5, -40]",
            &["teeth", "whole numbers"],
        ),
        (
            "module = \"3 mm\"",
            "module = \"3 furlongs\"",
            &["module", "furlongs", "accepted: m, mm, cm, um, µm, in"],
        ),
        ("module = \"3 mm\"", "module = -3", &["module", "positive"]),
        ("module = \"3 mm\"", "", &["module", "cardan_crank_length"]),
        (
            "pressure_angle = \"20 deg\"",
            "pressure_angle = \"50 deg\"",
            &["pressure_angle", "45"],
        ),
        (
            "teeth = [20, -40]",
            "teeth = [20, -40]\ncenter_distance = \"1 mm\"",
            &["center_distance", "1 mm"],
        ),
        (
            "teeth = [20, -40]",
            "teeth = [20, -40]\ntip_diameter = [\"66 mm\", \"130 mm\"]",
            &["tip_diameter", "root circle"],
        ),
        (
            "teeth = [20, -40]",
            "teeth = [20, -40]\nmodul = 3",
            &["unknown field", "modul"],
        ),
        (
            "name = \"internal-20-40-full\"",
            "name = \"../x\"",
            &["name", "folder name"],
        ),
    ];
    for (from, to, parts) in cases {
        let text = INTERFERING.replace(from, to);
        let e = error_of(&text);
        mentions(&e, &["gears/bad.toml"]);
        mentions(&e, parts);
    }
    // Rating inputs.
    let shigley = std::fs::read_to_string(shipped("shigley-14-4.toml")).unwrap();
    let rating: &[(&str, &str, &[&str])] = &[
        (
            "power = \"4 hp\"",
            "power = \"4 horses\"",
            &["rating.power", "horses", "hp"],
        ),
        ("power = \"4 hp\"", "", &["rating.power", "torque"]),
        (
            "quality = 6 ",
            "quality = 3 ",
            &["rating.quality", "[5, 12]"],
        ),
        (
            "reliability = 0.90",
            "reliability = 1.5",
            &["rating.reliability", "0.9999"],
        ),
        (
            "hardness = 240",
            "hardness = 500",
            &["rating.pinion.hardness", "[140, 400]"],
        ),
        ("face_width = \"1.5 in\"", "", &["face_width", "[rating]"]),
        (
            "lewis_y = 0.412",
            "",
            &["rating.gear.lewis_y", "both members"],
        ),
        (
            "elastic_coefficient = \"2300 sqrt(psi)\"",
            "",
            &["rating.elastic_coefficient", "youngs_modulus"],
        ),
        (
            "enclosure = \"commercial\"",
            "enclosure = \"closed\"",
            &["rating.enclosure", "unknown word \"closed\"", "precision"],
        ),
        (
            "pinion_speed = \"1800 rpm\"",
            "pinion_speed = \"0 rpm\"",
            &["rating.pinion_speed", "positive"],
        ),
    ];
    for (from, to, parts) in rating {
        assert!(shigley.contains(from), "{from}");
        let e = error_of(&shigley.replace(from, to));
        mentions(&e, &["gears/bad.toml", "shigley-14-4"]);
        mentions(&e, parts);
    }
    // Syntax: the TOML reader's message with the file.
    mentions(&error_of("name = "), &["gears/bad.toml"]);
}

#[test]
fn material_constants_give_the_elastic_coefficient() {
    // Cp from E = 30 Mpsi, ν = 0.3 on both members is 2290.6 √psi (formula; Shigley's table
    // rounds it to 2300), so SH rises by 2300/2290.6.
    let text = std::fs::read_to_string(shipped("shigley-14-4.toml")).unwrap();
    let table = report_of(&text).rating.unwrap().unwrap();
    let with_materials = text
        .replace("elastic_coefficient = \"2300 sqrt(psi)\"", "")
        .replace(
            "grade = 1",
            "grade = 1\nyoungs_modulus = \"30 Mpsi\"\npoisson_ratio = 0.3",
        );
    let r = report_of(&with_materials).rating.unwrap().unwrap();
    let cp = (1.0 / (std::f64::consts::PI * 2.0 * (1.0 - 0.09) / (30e6 * PSI))).sqrt();
    let ratio = 2300.0 * PSI.sqrt() / cp;
    assert!((r.contact_safety[0] / table.contact_safety[0] - ratio).abs() < 1e-12);
}

#[test]
fn local_units() {
    let s = |x: &str| toml::Value::String(x.into());
    let hp = cardan_gears::units::HORSEPOWER;
    assert!((to_si(&s("4 hp"), Dimension::Power).unwrap() - 4.0 * hp).abs() < 1e-9);
    assert_eq!(to_si(&s("3 kW"), Dimension::Power).unwrap(), 3000.0);
    assert_eq!(
        to_si(&toml::Value::Float(5.0), Dimension::Power).unwrap(),
        5.0
    );
    assert_eq!(to_si(&s("20 N*m"), Dimension::Torque).unwrap(), 20.0);
    assert!((to_si(&s("1 lbf*in"), Dimension::Torque).unwrap() - LBF * INCH).abs() < 1e-15);
    assert_eq!(to_si(&s("12 MPa"), Dimension::Pressure).unwrap(), 12e6);
    assert!((to_si(&s("1 psi"), Dimension::Pressure).unwrap() - PSI).abs() < 1e-12);
    assert!(
        (to_si(&s("2300 sqrt(psi)"), Dimension::RootStress).unwrap() - 2300.0 * PSI.sqrt()).abs()
            < 1e-9
    );
    assert_eq!(to_si(&s("190 √MPa"), Dimension::RootStress).unwrap(), 190e3);
    assert!(to_si(&s("4 N*m"), Dimension::Power)
        .unwrap_err()
        .contains("accepted: W, kW, MW, hp"));
    assert!(to_si(&toml::Value::Boolean(true), Dimension::Pressure).is_err());
    assert!(to_si(&s("nan MPa"), Dimension::Pressure).is_err());
}

#[test]
fn output_folder_is_replaced_as_a_whole() {
    let dir = tempfile::tempdir().unwrap();
    let file = shipped("karhula-cardan-20-40.toml");
    let first = run(&file, dir.path()).unwrap();
    std::fs::write(first.dir.join("stale.txt"), "old").unwrap();
    let second = run(&file, dir.path()).unwrap();
    assert_eq!(first.dir, second.dir);
    assert!(!second.dir.join("stale.txt").exists());
    assert!(second.dir.join("gear.json").is_file() && second.dir.join("report.md").is_file());
    // Nothing but the pair's folder is left beside it (no temporary folders).
    let names: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(
        names,
        vec![std::ffi::OsString::from("karhula-cardan-20-40")]
    );
}

/// Issue 22, reproducer r07: 200 kW through a 3 mm, 20/40, 30 mm-wide pair, SF ≈ 0.1 by hand
/// (the computation is in the file; one copy, beside the command's reproducers that
/// `cli/tests/gear.rs` runs through `cardan gear`).
const OVERLOADED: &str = include_str!("../../../cli/tests/reproducers/r07-gear-overloaded.toml");

#[test]
fn overloaded_pair_fails_its_verdict_naming_the_safety_factors_and_the_remedy() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("overloaded.toml");
    std::fs::write(&file, OVERLOADED).unwrap();
    let written = run(&file, &dir.path().join("out")).unwrap();
    let f = written.report.failures();
    let all = f.join("\n");
    mentions(
        &all,
        &[
            "bending safety factor SF of the pinion",
            "pitting safety factor SH of the pinion",
            "required_safety_factor 1",
            "rating.power at most",
            "face width",
        ],
    );
    let j: Value =
        serde_json::from_str(&std::fs::read_to_string(written.dir.join("gear.json")).unwrap())
            .unwrap();
    assert_eq!(j["passed"], false);
    assert_eq!(j["rating"]["required_safety_factor"], 1.0);
    let md = std::fs::read_to_string(written.dir.join("report.md")).unwrap();
    mentions(
        &md,
        &["cannot work", "bending safety factor SF of the pinion"],
    );
    assert!(!md.contains("the pair works"), "{md}");
}

/// The power the remedy names (the stresses are linear in Wt for bending and go with √Wt for
/// pitting at a fixed speed: AGMA 2001-D04 eqs. 1 and 15) is enough: at it the pair passes.
#[test]
fn the_load_remedy_of_an_overloaded_pair_makes_it_pass() {
    let f = report_of(OVERLOADED).failures();
    let line = f
        .iter()
        .find(|m| m.contains("rating.power at most"))
        .unwrap_or_else(|| panic!("{f:?}"));
    let after = line.split("rating.power at most ").nth(1).unwrap();
    let kw: f64 = after.split(" kW").next().unwrap().parse().unwrap();
    assert!(kw > 0.0 && kw < 200.0, "{line}");
    let at = report_of(&OVERLOADED.replace("\"200 kW\"", &format!("\"{kw} kW\"")));
    assert!(at.failures().is_empty(), "{:?}", at.failures());
    let above = report_of(&OVERLOADED.replace("\"200 kW\"", &format!("\"{} kW\"", kw * 1.01)));
    assert!(!above.failures().is_empty());
}

/// The face width the remedy names is enough; 200 kW would need more than 40 in (SH ≈ 0.19
/// asks for about 28 times the face, `σc ∝ 1/√b`), 30 kW does not.
#[test]
fn the_face_width_remedy_makes_the_pair_pass() {
    let text = OVERLOADED.replace("\"200 kW\"", "\"30 kW\"");
    let f = report_of(&text).failures();
    let line = f
        .iter()
        .find(|m| m.contains("face_width at least"))
        .unwrap_or_else(|| panic!("{f:?}"));
    let after = line.split("face_width at least ").nth(1).unwrap();
    let mm: f64 = after.split(" mm").next().unwrap().parse().unwrap();
    assert!(mm > 30.0, "{line}");
    let wide = text.replace("\"30 mm\"", &format!("\"{mm} mm\""));
    assert!(
        report_of(&wide).failures().is_empty(),
        "{:?}",
        report_of(&wide).failures()
    );
    let narrower = text.replace("\"30 mm\"", &format!("\"{} mm\"", mm * 0.99));
    assert!(!report_of(&narrower).failures().is_empty());
}

#[test]
fn required_safety_factor_sets_the_minimum() {
    // Shigley Example 14-4 prints SF 5.62 / 6.82 and SH 1.69 / 1.52: a required 1.5 passes,
    // 1.6 fails on the gear's pitting factor only.
    let text = std::fs::read_to_string(shipped("shigley-14-4.toml")).unwrap();
    let with = |n: &str| {
        text.replace(
            "[rating]\n",
            &format!("[rating]\nrequired_safety_factor = {n}\n"),
        )
    };
    assert!(report_of(&with("1.5")).failures().is_empty());
    let f = report_of(&with("1.6")).failures();
    assert_eq!(f.len(), 1, "{f:?}");
    mentions(
        &f[0],
        &[
            "pitting safety factor SH of the gear",
            "required_safety_factor 1.6",
        ],
    );
    for (bad, rule) in [
        ("0.5", ">= 1"),
        ("-2", ">= 1"),
        ("\"x\"", "required_safety_factor"),
        ("inf", "finite"),
        ("nan", "finite"),
    ] {
        let e = error_of(&with(bad));
        mentions(
            &e,
            &["gears/bad.toml", "rating.required_safety_factor", rule],
        );
    }
}

/// Issue 22, reproducer r12: a pinion speed of 1e-300 rad/s makes the torque, and every stress,
/// infinite; the pair must fail naming the quantity, not "work".
#[test]
fn a_tiny_pinion_speed_fails_naming_the_infinite_quantity() {
    let tiny = OVERLOADED
        .replace("\"200 kW\"", "\"4 hp\"")
        .replace("\"1800 rpm\"", "1e-300");
    let r = report_of(&tiny);
    let f = r.failures();
    assert!(!f.is_empty());
    mentions(
        &f.join("\n"),
        &[
            "pinion torque",
            "not a finite number",
            "rating.pinion_speed",
        ],
    );
    assert_eq!(r.to_json()["passed"], false);
    assert!(!r.to_markdown().contains("the pair works"));
}

#[test]
fn zero_load_is_an_input_error() {
    let e = error_of(&OVERLOADED.replace("\"200 kW\"", "0"));
    mentions(&e, &["rating.power", "positive"]);
}

#[test]
fn warnings_appear_in_the_report() {
    // Shigley's 17-tooth unshifted pinion is just below the undercut limit: a warning listed
    // under the verdict, the pair still works.
    let r = report_of(&std::fs::read_to_string(shipped("shigley-14-4.toml")).unwrap());
    assert!(r.failures().is_empty());
    let w = r.warnings();
    assert!(w.iter().any(|m| m.contains("pinion_undercut")), "{w:?}");
    let md = r.to_markdown();
    let verdict = md.split("## Inputs").next().unwrap();
    mentions(verdict, &["the pair works", "Warnings", "pinion_undercut"]);
}

/// Issue 22 item 11: `module = 3` (meant in mm) was a 3 m module; it is refused with the
/// likely unit, and "3 mm" is taken as written.
#[test]
fn a_bare_module_meant_in_millimetres_is_refused() {
    let text = std::fs::read_to_string(shipped("karhula-cardan-20-40.toml")).unwrap();
    let line = text
        .lines()
        .find(|l| l.starts_with("module") || l.starts_with("cardan_crank_length"))
        .unwrap()
        .to_string();
    let bare = text.replace(&line, "module = 3");
    let e = parse(std::path::Path::new("g.toml"), &bare)
        .unwrap_err()
        .to_string();
    assert!(e.contains("module") && e.contains("\"3 mm\""), "{e}");
    let with_unit = text.replace(&line, "module = \"3 mm\"");
    assert!(parse(std::path::Path::new("g.toml"), &with_unit).is_ok());
}

/// Every shipped gear file reads (and the test files written by the tests above are built on
/// them).
#[test]
fn every_shipped_gear_file_reads() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../configs-gears");
    let mut read = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let file = entry.unwrap().path();
        if file.extension().is_some_and(|e| e == "toml") {
            load(&file).unwrap_or_else(|e| panic!("{e}"));
            read += 1;
        }
    }
    assert!(read >= 2, "{read} shipped gear files");
}

/// A misspelled field, at the top level, in `[rating]` or in a member's table, names its path
/// and the nearest valid name; a misspelled word the nearest word.
#[test]
fn a_misspelled_field_names_its_path_and_the_nearest_name() {
    let shigley = std::fs::read_to_string(shipped("shigley-14-4.toml")).unwrap();
    for (from, to, parts) in [
        (
            "face_width = ",
            "face_widht = ",
            &[
                "face_widht: unknown field \"face_widht\"",
                "did you mean \"face_width\"?",
            ][..],
        ),
        (
            "pinion_speed = ",
            "pinion_sped = ",
            &[
                "rating.pinion_sped: unknown field",
                "did you mean \"pinion_speed\"?",
            ][..],
        ),
        (
            "lewis_y = 0.412",
            "lewis_why = 0.412",
            &[
                "rating.gear.lewis_why: unknown field",
                "did you mean \"lewis_y\"?",
            ][..],
        ),
        (
            "enclosure = \"commercial\"",
            "enclosure = \"comercial\"",
            &[
                "rating.enclosure: unknown word \"comercial\"",
                "did you mean \"commercial\"?",
            ][..],
        ),
    ] {
        assert!(shigley.contains(from), "{from}");
        let e = error_of(&shigley.replacen(from, to, 1));
        mentions(&e, &["gears/bad.toml", "shigley-14-4"]);
        mentions(&e, parts);
    }
}

/// The gear file's JSON Schema names every table and says which fields are required.
#[test]
fn the_gear_file_schema_lists_the_fields() {
    let schema = cardan_gear_file::gear_file_schema();
    let required = schema["required"].as_array().unwrap();
    for field in ["name", "pressure_angle", "teeth"] {
        assert!(required.iter().any(|r| r == field), "{field}: {schema}");
    }
    assert_eq!(schema["additionalProperties"], false);
    let text = schema.to_string();
    for field in [
        "pinion_speed",
        "bending_allowable",
        "lewis_y",
        "extra-precision",
    ] {
        assert!(text.contains(field), "{field}");
    }
}

/// A shipped case with a gear mesh (the cardan gear, 20/40 teeth of 3 mm: a 4.7 mm tooth),
/// its `[gear]` table `gear`; the error of reading it as a case file, if any.
fn case_error_of(gear: &str) -> Option<String> {
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../configs/karhula-r60-l140-a0-w3pi.toml"),
    )
    .unwrap();
    let text = format!("{text}\n[gear]\nteeth = 20\n{gear}\n");
    cardan_case::case::parse(Path::new("cases/gear.toml"), &text)
        .err()
        .map(|e| e.to_string())
}

/// Shigley's shipped pair (17/52 teeth, module 2.54 mm: a 3.99 mm tooth) with `from` replaced
/// by `to`.
fn shigley_with(from: &str, to: &str) -> String {
    let text = std::fs::read_to_string(shipped("shigley-14-4.toml")).unwrap();
    assert!(text.contains(from), "{from}");
    text.replace(from, to)
}

/// Issue 36.12: J = 100 is refused by gear files as by case files, by the same reader (the
/// case's `Ranged<GeometryFactorJ>`) with the same rule.
#[test]
fn a_geometry_factor_j_above_1_is_refused_by_gear_and_case_files() {
    let rule = "bending geometry factors J must be between 0 and 1";
    let e = error_of(&shigley_with("j = 0.30", "j = 100"));
    mentions(&e, &["gears/bad.toml", "rating.pinion.j", "100", rule]);
    let e = case_error_of("j = 100").expect("a case with J = 100 was accepted");
    mentions(&e, &["cases/gear.toml", "gear.j", "100", rule]);
}

/// Issue 36.12: a tip inside the mate's root circle (a dedendum of 0 in a gear file; a ring
/// addendum of 1.4 modules over the pinion's 1.25-module dedendum in a case file) is refused
/// by the one check of `GearPair::new`.
#[test]
fn a_tip_inside_the_mates_root_circle_is_refused_by_gear_and_case_files() {
    let rule = "the gear's tip circle reaches into the pinion's root circle";
    let e = error_of(&shigley_with(
        "face_width = \"1.5 in\"",
        "face_width = \"1.5 in\"\ndedendum_coefficient = [0, 1.25]",
    ));
    mentions(&e, &["dedendum_coefficient", "[0, 1.25]", rule]);
    // The pinion's tip against a gear dedendum of 0.
    let e = error_of(&shigley_with(
        "face_width = \"1.5 in\"",
        "face_width = \"1.5 in\"\ndedendum_coefficient = [1.25, 0]",
    ));
    mentions(
        &e,
        &[
            "dedendum_coefficient",
            "the pinion's tip circle reaches into the gear's root circle",
        ],
    );
    // A case file has no dedendum: its ring's tip (0.15 module past the pinion's root).
    let e = case_error_of("ring_addendum = 1.4").expect("a ring tip in the pinion's root");
    mentions(&e, &["cases/gear.toml", "gear", rule]);
    // Without: the shipped pair reads (its clearance 0.25 module).
    assert_eq!(case_error_of("ring_addendum = 0.8"), None);
    assert!(parse(Path::new("x.toml"), &shigley_with("", "")).is_ok());
}

/// Issue 36.12: thinning a tooth by more than its thickness (5 mm on Shigley's 3.99 mm tooth,
/// a backlash beyond the pitch) is refused; a case file has no thinning field (refused by
/// name, the nearest fields listed).
#[test]
fn a_tooth_thinned_away_is_refused_by_gear_files_and_a_case_file_has_no_such_field() {
    let e = error_of(&shigley_with(
        "face_width = \"1.5 in\"",
        "face_width = \"1.5 in\"\nthickness_allowance = [\"5 mm\", \"0 mm\"]",
    ));
    mentions(
        &e,
        &[
            "thickness_allowance",
            "5 mm",
            "less than the tooth's thickness at the reference circle",
        ],
    );
    // Just under the tooth's thickness, π m / 2 = 3.99 mm: a pair (whose backlash check fails).
    assert!(parse(
        Path::new("x.toml"),
        &shigley_with(
            "face_width = \"1.5 in\"",
            "face_width = \"1.5 in\"\nthickness_allowance = [\"3.9 mm\", \"0 mm\"]",
        )
    )
    .is_ok());
    let e = case_error_of("thickness_allowance = \"5 mm\"").expect("an unknown field");
    mentions(&e, &["gear.thickness_allowance", "unknown field"]);
}

/// Issue 36.12: a pinion speed of 1e300 rad/s (a pitch-line velocity of 2e298 m/s) is refused
/// by the one speed check, `cardan_gears::check_pitch_line_velocity`; 1800 rpm reads.
#[test]
fn a_pinion_speed_no_gear_can_run_at_is_refused() {
    let e = error_of(&shigley_with(
        "pinion_speed = \"1800 rpm\"",
        "pinion_speed = \"1e300 rad/s\"",
    ));
    mentions(
        &e,
        &[
            "rating.pinion_speed",
            "1e300 rad/s",
            "must be at most 500 m/s",
        ],
    );
    // 500 m/s on Shigley's 43.18 mm pinion: 23 158 rad/s; just under it reads, just over not.
    let under = shigley_with(
        "pinion_speed = \"1800 rpm\"",
        "pinion_speed = \"23000 rad/s\"",
    );
    assert!(parse(Path::new("x.toml"), &under).is_ok());
    let over = shigley_with(
        "pinion_speed = \"1800 rpm\"",
        "pinion_speed = \"23300 rad/s\"",
    );
    mentions(&error_of(&over), &["rating.pinion_speed", "500 m/s"]);
}

/// Issue 39.1: without `j`, the gear file computes J from the tooth form (AGMA 908-B89 for
/// the external Shigley pair; the ISO 6336-3 rack of the ring of an internal pair) and says so;
/// a J given stays an override. The computed J of Shigley's 17/52 pair with the default rack
/// (dedendum 1.25 m, tip radius 0.25 m) lies within 0.03 of the 0.30 / 0.40 Shigley read from
/// his Fig. 14-6 (crates/gears/tests/tooth_root.rs: the rack the chart was drawn for is not
/// stated; across the AGMA full-depth racks J spans ±0.02).
#[test]
fn j_is_computed_when_not_given_and_the_report_says_how() {
    let text = shigley_with("j = 0.30\n", "").replace("j = 0.40\n", "");
    let input = parse(Path::new("gears/test.toml"), &text).unwrap();
    assert!(input.rating.as_ref().unwrap().members[0].j.is_none());
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("computed.toml");
    std::fs::write(&file, &text).unwrap();
    let written = run(&file, dir.path()).unwrap();
    let json: Value =
        serde_json::from_str(&std::fs::read_to_string(written.dir.join("gear.json")).unwrap())
            .unwrap();
    let r = &json["rating"];
    for (member, read) in [("pinion", 0.30), ("gear", 0.40)] {
        assert_eq!(r[member]["j_method"], "AGMA 908-B89", "{member}");
        let j = num(&r[member]["j"]);
        assert!((j - read).abs() < 0.03, "{member}: {j}");
        assert!(num(&r[member]["j_section"]["stress_correction_kf"]) > 1.0);
    }
    let md = std::fs::read_to_string(written.dir.join("report.md")).unwrap();
    mentions(
        &md,
        &[
            "| J obtained by | AGMA 908-B89 | AGMA 908-B89 | - |",
            "J of the pinion computed from the tooth form by AGMA 908-B89",
        ],
    );
    // Bending stress ∝ 1/J: the computed J rates the pair by the same AGMA equation.
    let given = report_of(&std::fs::read_to_string(shipped("shigley-14-4.toml")).unwrap());
    let computed = report_of(&text);
    let (g, c) = (
        given.rating.unwrap().unwrap(),
        computed.rating.unwrap().unwrap(),
    );
    assert_eq!(g.j, [0.30, 0.40]);
    assert!(matches!(g.j_source[0], cardan_gear_file::JSource::Given));
    for k in 0..2 {
        let ratio = c.bending_stress[k] / g.bending_stress[k];
        assert!((ratio - g.j[k] / c.j[k]).abs() < 1e-12, "{ratio}");
    }

    // An internal pair: the ring's J by ISO 6336-3 method B, the pinion's by AGMA 908.
    let internal = shigley_with("teeth = [17, 52]", "teeth = [17, -52]")
        .replace("j = 0.30\n", "")
        .replace("j = 0.40\n", "");
    let r = report_of(&internal).rating.unwrap().unwrap();
    assert_eq!(r.j_source[0].word(), "AGMA 908-B89");
    assert_eq!(r.j_source[1].word(), "ISO 6336-3 method B");
    assert!(r.j[1] > 0.2 && r.j[1] < 0.6, "{}", r.j[1]);
}

/// Issue 39.1: a rack tip radius that does not fit the rack tooth (0.38 m at 25°) is refused
/// when J has to be computed, naming the field and the remedy; with J given it is not needed.
#[test]
fn a_rack_tip_radius_that_does_not_fit_is_refused_when_j_is_computed() {
    let text = shigley_with("j = 0.30\n", "")
        .replace("pressure_angle = \"20 deg\"", "pressure_angle = \"25 deg\"")
        .replace(
            "face_width = \"1.5 in\"",
            "face_width = \"1.5 in\"\nrack_tip_radius_coefficient = [0.38, 0.38]",
        );
    let e = error_of(&text);
    mentions(
        &e,
        &[
            "rack_tip_radius_coefficient",
            "[0.38, 0.38]",
            "J cannot be computed",
            "does not fit",
            "give rating.pinion.j",
        ],
    );
}
