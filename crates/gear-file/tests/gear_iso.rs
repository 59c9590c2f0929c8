//! Gear files with named materials, the ISO 6336 rating beside AGMA's (and as the verdict's
//! basis), and the `[measurement]` table.

use cardan_gear_file::{evaluate, parse, GearReport};
use cardan_gears::units::PSI;
use serde_json::Value;
use std::path::Path;

fn shipped(name: &str) -> String {
    std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../configs-gears")
            .join(name),
    )
    .unwrap()
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

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

const ISO: &str = "iso-6336-spur-example.toml";

#[test]
fn agma_files_keep_their_figures_and_have_no_iso_rating() {
    let j = report_of(&shipped("shigley-14-4.toml")).to_json();
    assert_eq!(j["rating"]["basis"], "agma2001");
    assert!(j["rating"]["iso6336"].is_null());
    assert!(j["measurement"].is_null());
}

#[test]
fn a_named_material_gives_the_agma_allowables_of_the_charts() {
    // Shigley Ex. 14-4's 240 / 200 HB grade 1 through-hardened steel, named: St 31 350 /
    // 28 260 psi, Sc 106 400 / 93 500 psi as printed (±5 psi, ±50 psi).
    let text = shigley_with_material();
    let j = report_of(&text).to_json();
    let r = &j["rating"];
    let psi = |v: &Value| num(v) / PSI;
    assert!((psi(&r["pinion"]["bending_allowable"]) - 31_350.0).abs() <= 5.0);
    assert!((psi(&r["gear"]["bending_allowable"]) - 28_260.0).abs() <= 5.0);
    assert!((psi(&r["pinion"]["contact_allowable"]) - 106_400.0).abs() <= 50.0);
    assert!((psi(&r["gear"]["contact_allowable"]) - 93_500.0).abs() <= 50.0);
}

fn shigley_with_material() -> String {
    shipped("shigley-14-4.toml").replace(
        "hardness = 240",
        "material = \"steel-through-hardened\"\nhardness = 240",
    )
}

#[test]
fn a_steel_pair_needs_no_elastic_coefficient() {
    // Both members named: Z_E = Cp from E = 206 GPa, ν = 0.3, 189.8 √MPa (ISO 6336-2 §7).
    let text = shipped(ISO);
    assert!(!text.contains("elastic_coefficient"));
    let j = report_of(&text).to_json();
    assert!((num(&j["rating"]["cp"]) / 1e3 - 189.8).abs() < 0.05);
    assert!((num(&j["rating"]["iso6336"]["z_e"]) / 1e3 - 189.8).abs() < 0.05);
}

#[test]
fn the_iso_example_rates_both_ways_and_decides_by_iso() {
    let report = report_of(&shipped(ISO));
    assert!(report.failures().is_empty(), "{:?}", report.failures());
    let j = report.to_json();
    let iso = &j["rating"]["iso6336"];
    assert_eq!(j["rating"]["basis"], "iso6336");
    for member in ["pinion", "gear"] {
        assert!(num(&iso[member]["contact_safety_factor"]) > 1.0);
        assert!(num(&iso[member]["bending_safety_factor"]) > 1.0);
    }
    // ISO 6336-1 §6.5.4: below resonance K_v = N K + 1 > 1.
    assert!(num(&iso["k_v"]) > 1.0 && num(&iso["resonance_ratio"]) < 0.85);
    let md = report.to_markdown();
    assert!(md.contains("side by side (verdict basis: iso6336)"), "{md}");
}

#[test]
fn iso_safety_factors_scale_with_the_load_through_the_file() {
    // With K_v and K_Hα given, S_F ∝ 1/F_t and S_H ∝ 1/√F_t (ISO 6336-3 eq. (1), 6336-2
    // eq. (3)): four times the power halves S_H and quarters S_F.
    let base = shipped(ISO).replace(
        "accuracy_grade = 6",
        "accuracy_grade = 6\niso_dynamic_factor = 1.1\ntransverse_load_factor = 1.0",
    );
    let a = report_of(&base).to_json();
    let b = report_of(&base.replace("power = \"15 kW\"", "power = \"60 kW\"")).to_json();
    for m in ["pinion", "gear"] {
        let s = |j: &Value, k: &str| num(&j["rating"]["iso6336"][m][k]);
        assert!(
            (s(&a, "contact_safety_factor") / s(&b, "contact_safety_factor") - 2.0).abs() < 1e-9
        );
        assert!(
            (s(&a, "bending_safety_factor") / s(&b, "bending_safety_factor") - 4.0).abs() < 1e-9
        );
    }
}

#[test]
fn an_overloaded_pair_fails_by_its_iso_factors() {
    let text = shipped(ISO).replace("power = \"15 kW\"", "power = \"150 kW\"");
    let report = report_of(&text);
    let failures = report.failures().join("\n");
    assert!(
        failures.contains("ISO pitting safety factor S_H of the pinion"),
        "{failures}"
    );
    assert!(
        failures.contains("remedy: rating.power at most about"),
        "{failures}"
    );
    // The same pair judged by AGMA names AGMA's factors instead.
    let agma = report_of(&text.replace("basis = \"iso6336\"", "basis = \"agma2001\""));
    let failures = agma.failures().join("\n");
    assert!(
        failures.contains("(Shigley eq. 14-42)") && !failures.contains("ISO"),
        "{failures}"
    );
}

#[test]
fn iso_basis_computes_the_tooth_form_factors_unless_given() {
    use cardan_gears::tooth_root::{iso6336_method_b, GeneratedMember, PairMember};
    // The shipped example gives neither Y_F nor Y_S: ISO 6336-3 method B from the tooth form.
    let file = parse(Path::new("gears/test.toml"), &shipped(ISO)).unwrap();
    let pair = cardan_gears::GearPair::new(file.spec).unwrap();
    let iso = &report_of(&shipped(ISO)).to_json()["rating"]["iso6336"];
    for (k, which) in [PairMember::Pinion, PairMember::Gear]
        .into_iter()
        .enumerate()
    {
        let member = GeneratedMember {
            which,
            rack_tip_radius: None,
        };
        let root = iso6336_method_b(&pair, member).unwrap();
        let y_f = num(&iso[["pinion", "gear"][k]]["form_factor_y_f"]);
        assert_eq!(y_f, root.form_factor, "member {k}");
        // ISO 6336-3 method B's Y_F (load at the outer point of single contact) for 20 and 40
        // teeth of a standard rack lies between 1.2 and 2.5, its Y_S between 1.5 and 2.5 (the standard's charts).
        assert!((1.2..2.5).contains(&y_f), "Y_F {y_f}");
        let y_s = num(&iso[["pinion", "gear"][k]]["stress_correction_y_s"]);
        assert_eq!(y_s, root.stress_correction, "member {k}");
        assert!((1.5..2.5).contains(&y_s), "Y_S {y_s}");
    }
    // Given, they override the tooth form; given alone, Y_S is refused.
    let given = shipped(ISO).replace(
        "iso_quality = \"mq\"\n",
        "iso_quality = \"mq\"\nform_factor = 2.55\nstress_correction_factor = 1.70\n",
    );
    let iso = &report_of(&given).to_json()["rating"]["iso6336"];
    assert_eq!(num(&iso["pinion"]["form_factor_y_f"]), 2.55);
    let alone = shipped(ISO).replacen(
        "iso_quality = \"mq\"\n",
        "iso_quality = \"mq\"\nstress_correction_factor = 1.70\n",
        1,
    );
    let e = error_of(&alone);
    assert!(
        e.contains("rating.pinion.stress_correction_factor") && e.contains("form_factor"),
        "{e}"
    );
    let e = error_of(&shipped(ISO).replace("accuracy_grade = 6", ""));
    assert!(e.contains("rating.accuracy_grade"), "{e}");
}

#[test]
fn an_unknown_material_lists_the_table() {
    let e = error_of(&shipped(ISO).replacen("steel-case-carburized", "unobtainium", 1));
    assert!(
        e.contains("rating.pinion.material") && e.contains("steel-through-hardened"),
        "{e}"
    );
    // Grade 3 without carburized steel, and bronze without ISO limits, are refused.
    let e = error_of(&shigley_with_material().replacen("grade = 1", "grade = 3", 1));
    assert!(e.contains("grade"), "{e}");
    let e = error_of(&shipped(ISO).replace("steel-case-carburized", "tin-bronze"));
    assert!(e.contains("bronze"), "{e}");
}

#[test]
fn span_width_through_the_gear_file_matches_the_published_example() {
    // MachineCalcs' worked example (m = 2 mm, z = 20, α = 20°, x = 0): k = 3, W = 15.321 mm;
    // a thinning j takes j cos α off W_k.
    let text = "name = \"w\"\nmodule = \"2 mm\"\npressure_angle = \"20 deg\"\nteeth = [20, 40]\n[measurement]\n";
    let j = report_of(text).to_json();
    let p = &j["measurement"]["pinion"];
    assert_eq!(p["span_teeth"], 3);
    assert!((num(&p["span_width"]) * 1e3 - 15.321).abs() < 5e-4);
    let thin = text.replace(
        "[measurement]",
        "thickness_allowance = [\"0.1 mm\", \"0 mm\"]\n[measurement]",
    );
    let t = report_of(&thin).to_json();
    let dw = num(&p["span_width"]) - num(&t["measurement"]["pinion"]["span_width"]);
    assert!((dw - 0.1e-3 * 20f64.to_radians().cos()).abs() < 1e-12);
    // A ring has no span, only the dimension between pins.
    let ring = report_of(&text.replace("[20, 40]", "[20, -40]")).to_json();
    assert!(ring["measurement"]["gear"]["span_width"].is_null());
    assert!(num(&ring["measurement"]["gear"]["dimension_over_pins"]) > 0.0);
}

#[test]
fn no_number_in_the_report_prints_a_negative_zero() {
    // Issue 39 item 5: a value that rounds to zero printed "-0.0000". A profile shift of
    // −0.00001 is written to 4 decimals in the geometry table.
    let text = shipped(ISO).replace(
        "teeth = [20, 40]",
        "teeth = [20, 40]\nprofile_shift = [-0.00001, 0.00001]",
    );
    let md = report_of(&text).to_markdown();
    assert!(
        md.contains("| profile shift x1 / x2 (ISO) | 0.0000 / 0.0000 | - |"),
        "{md}"
    );
    // No number anywhere is a minus sign before zeros only (the inputs echo "-0.00001").
    let negative_zero = md.match_indices('-').any(|(i, _)| {
        let digits: String = md[i + 1..]
            .chars()
            .take_while(|c| c.is_ascii_digit() || *c == '.')
            .collect();
        digits.starts_with('0')
            && digits.contains('.')
            && digits.chars().all(|c| c == '0' || c == '.')
    });
    assert!(!negative_zero, "{md}");
}

#[test]
fn an_iso_field_asks_for_the_iso_rating_and_the_overrides_are_taken() {
    // Judged by AGMA, no Y_F given: an ISO field (here accuracy_grade) still asks for the ISO
    // rating beside AGMA's, Y_F and Y_S from the tooth form (it was left unread before).
    let agma = shipped(ISO).replace("basis = \"iso6336\"", "basis = \"agma2001\"");
    let j = report_of(&agma).to_json();
    assert_eq!(j["rating"]["basis"], "agma2001");
    assert!(j["rating"]["iso6336"].is_object(), "{}", j["rating"]);
    // Without any ISO field, no ISO rating, as before.
    let bare = agma.replace("accuracy_grade = 6 ", "# ");
    assert!(report_of(&bare).to_json()["rating"]["iso6336"].is_null());
    // The user's K_v, K_Hα, K_Hβ, σ_Hlim, σ_Flim and cycles replace the computed ones.
    let text = agma
        .replace(
            "accuracy_grade = 6 ",
            "iso_dynamic_factor = 1.2\ntransverse_load_factor = 1.1\nface_load_factor = 1.3\n# ",
        )
        .replace("pinion_cycles = 1e9", "pinion_cycles = 3e6")
        .replace(
            "[rating.pinion]\n",
            "[rating.pinion]\nsigma_hlim = \"1400 MPa\"\nsigma_flim = \"400 MPa\"\n",
        );
    let iso = &report_of(&text).to_json()["rating"]["iso6336"];
    assert_eq!(num(&iso["k_v"]), 1.2);
    assert_eq!((num(&iso["k_halpha"]), num(&iso["k_falpha"])), (1.1, 1.1));
    assert_eq!(num(&iso["k_hbeta"]), 1.3);
    // 3e6 cycles: ISO 6336-3 Table 3's knee, Y_NT = 1; σ_FG = σ_Flim Y_ST (Y_X = 1 at 3 mm).
    assert!((num(&iso["pinion"]["y_nt"]) - 1.0).abs() < 1e-12);
    assert!((num(&iso["pinion"]["root_stress_limit"]) / 800e6 - 1.0).abs() < 1e-12);
    let z_nt = num(&iso["pinion"]["z_nt"]);
    let limit = num(&iso["pinion"]["pitting_stress_limit"]);
    assert!((limit / (1400e6 * z_nt) - 1.0).abs() < 1e-12);
}

#[test]
fn a_bad_iso_override_names_its_field_and_value() {
    let text = shipped(ISO).replace("accuracy_grade = 6 ", "iso_dynamic_factor = 0.9\n# ");
    let e = error_of(&text);
    assert!(
        e.contains("rating.iso_dynamic_factor") && e.contains("0.9"),
        "{e}"
    );
    let text = shipped(ISO).replace(
        "[rating.gear]\n",
        "[rating.gear]\nsigma_hlim = \"-5 MPa\"\n",
    );
    let e = error_of(&text);
    assert!(e.contains("sigma_hlim") && e.contains("-5 MPa"), "{e}");
}
