//! Bad case files give one clear error each — file, case, field, rule, value — and never stop
//! the other cases of a batch.

use cardan_runner::case::parse;
use std::path::Path;

const GOOD: &str = r#"
name = "good"
machine = "pump"
mechanisms = ["slider_crank", "cardan_gear"]
[geometry]
crank_length = 0.06
rod_length = 0.14
bore = 0.12
[motion]
start_angle = 90.0
end_angle = 810.0
initial_speed = 628.3185307
angular_acceleration = 0.0
steps = 720
"#;

fn error_of(text: &str) -> String {
    match parse(Path::new("configs/bad.toml"), text) {
        Ok(_) => panic!("accepted a bad case:\n{text}"),
        Err(e) => e.to_string(),
    }
}

fn assert_mentions(message: &str, parts: &[&str]) {
    for p in parts {
        assert!(
            message.contains(p),
            "error message {message:?} does not mention {p:?}"
        );
    }
}

#[test]
fn the_good_case_is_accepted() {
    let case = parse(Path::new("configs/good.toml"), GOOD).unwrap();
    assert_eq!(case.steps, 720);
    assert_eq!(case.mechanisms.len(), 2);
}

#[test]
fn each_rule_names_file_case_field_rule_and_value() {
    let cases: &[(&str, &str, &[&str])] = &[
        (
            "rod_length = 0.14",
            "rod_length = 0.05",
            &[
                "configs/bad.toml",
                "\"good\"",
                "geometry.rod_length",
                "0.05",
                "longer than geometry.crank_length",
            ],
        ),
        (
            "rod_length = 0.14",
            "rod_length = 0.06",
            &["geometry.rod_length", "longer than"],
        ),
        (
            "bore = 0.12",
            "bore = -0.12",
            &["geometry.bore", "-0.12", "must be positive"],
        ),
        (
            "crank_length = 0.06",
            "crank_length = 0.0",
            &["geometry.crank_length", "must be positive"],
        ),
        (
            "bore = 0.12",
            "bore = nan",
            &["geometry.bore", "nan", "finite"],
        ),
        ("steps = 720", "steps = 4", &["motion.steps", "4", "from 8"]),
        (
            "end_angle = 810.0",
            "end_angle = 45.0",
            &["motion.end_angle", "45", "greater than motion.start_angle"],
        ),
        (
            "initial_speed = 628.3185307",
            "initial_speed = -1.0",
            &["motion.initial_speed", "-1", "forwards"],
        ),
        (
            "angular_acceleration = 0.0",
            "angular_acceleration = -20000.0",
            &["motion.initial_speed", "stops"],
        ),
        (
            "bore = 0.12",
            "bore = \"12 furlongs\"",
            &["geometry.bore", "unknown unit", "furlongs"],
        ),
        (
            "machine = \"pump\"",
            "machine = \"boat\"",
            &["machine", "boat", "\"pump\" or \"engine\""],
        ),
        (
            "[\"slider_crank\", \"cardan_gear\"]",
            "[\"scotch_yoke\"]",
            &["mechanisms", "scotch_yoke", "unknown mechanism"],
        ),
        (
            "[\"slider_crank\", \"cardan_gear\"]",
            "[\"cardan_gear\", \"cardan_gear\"]",
            &["mechanisms", "twice"],
        ),
        (
            "name = \"good\"",
            "name = \"../escape\"",
            &["name", "folder name"],
        ),
        (
            "bore = 0.12",
            "bore = 0.12\npin_offset = 0.09",
            &["geometry.pin_offset", "0.09", "longer than crank_length"],
        ),
        (
            "steps = 720",
            "steps = 720\n[masses]\npiston_mass = -1.0",
            &["masses.piston_mass", "-1", "negative"],
        ),
        (
            "steps = 720",
            "steps = 720\n[masses.cardan_gear]\nrod_cg = 0.5",
            &["masses.cardan_gear.rod_cg", "0.5", "on the rod"],
        ),
        (
            "steps = 720",
            "steps = 720\n[masses]\nrod_material = \"cheese\"",
            &["masses.rod_material", "cheese", "\"steel\" or \"titanium\""],
        ),
        (
            "steps = 720",
            "steps = 720\n[masses]\nwheel_inertia = 0.001",
            &["masses.wheel_inertia", "cardan gear only"],
        ),
    ];
    for (from, to, parts) in cases {
        assert!(
            GOOD.contains(from),
            "test set-up: {from:?} not in the good case"
        );
        assert_mentions(&error_of(&GOOD.replacen(from, to, 1)), parts);
    }
}

#[test]
fn syntax_missing_fields_and_unknown_keys_are_located() {
    assert_mentions(
        &error_of(&GOOD.replace("bore = 0.12\n", "")),
        &["configs/bad.toml", "missing field", "bore"],
    );
    assert_mentions(
        &error_of(&GOOD.replace("bore = 0.12", "bore = 0.12\nstroke = 0.1")),
        &["configs/bad.toml", "unknown field", "stroke"],
    );
    assert_mentions(
        &error_of(&GOOD.replace("steps = 720", "steps = 72.5")),
        &["configs/bad.toml", "steps"],
    );
    assert_mentions(&error_of("name = "), &["configs/bad.toml", "line 1"]);
}

/// One bad file and one duplicate name among good cases: the good cases are written, the
/// failures listed.
#[test]
fn one_failing_case_does_not_stop_the_batch() {
    let dir = tempfile::tempdir().unwrap();
    let cases = dir.path().join("cases");
    std::fs::create_dir_all(cases.join("sub")).unwrap();
    std::fs::write(cases.join("a.toml"), GOOD.replace("\"good\"", "\"a\"")).unwrap();
    std::fs::write(cases.join("sub/b.toml"), GOOD.replace("\"good\"", "\"b\"")).unwrap();
    std::fs::write(
        cases.join("bad.toml"),
        GOOD.replace("rod_length = 0.14", "rod_length = 0.01"),
    )
    .unwrap();
    std::fs::write(cases.join("dup.toml"), GOOD.replace("\"good\"", "\"a\"")).unwrap();
    std::fs::write(cases.join("notes.txt"), "not a case").unwrap();
    let out = dir.path().join("out");
    let report = cardan_runner::run_paths(&[cases], &out).unwrap();
    let mut written: Vec<_> = report.written.iter().map(|w| w.0.as_str()).collect();
    written.sort();
    assert_eq!(written, ["a", "b"]);
    assert_eq!(report.failures.len(), 2, "{:#?}", report.failures);
    assert!(report
        .failures
        .iter()
        .any(|f| f.contains("bad.toml") && f.contains("geometry.rod_length")));
    assert!(report
        .failures
        .iter()
        .any(|f| f.contains("dup.toml") && f.contains("already the name")));
    for name in ["a", "b"] {
        let dir = out.join(name);
        let summary: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap())
                .unwrap();
        assert_eq!(summary["case"], name);
        for mech in ["slider_crank", "cardan_gear"] {
            assert!(
                summary["mechanisms"][mech]["metrics"]["inertial_torque_max"]
                    .as_f64()
                    .unwrap()
                    > 0.0
            );
            let csv = std::fs::read_to_string(dir.join(format!("{mech}.csv"))).unwrap();
            let header = csv.lines().next().unwrap();
            for col in [
                "crank_angle_deg",
                "time_s",
                "piston_position_m",
                "piston_velocity_m_s",
                "piston_acceleration_m_s2",
            ] {
                assert!(
                    header.split(',').any(|c| c == col),
                    "{mech}.csv lacks {col}"
                );
            }
            assert_eq!(csv.lines().count(), 1 + 721);
        }
        // No temporary files are left behind.
        assert!(std::fs::read_dir(&dir).unwrap().all(|e| !e
            .unwrap()
            .file_name()
            .to_string_lossy()
            .starts_with('.')));
    }
}
