//! Bad case files give one clear error each — file, case, field, rule, value — and never stop
//! the other cases of a batch.

use cardan_case::case::parse;
use cardan_testing::mentions;
use std::path::Path;

use cardan_testing::cases::THESIS_PUMP as GOOD;

fn error_of(text: &str) -> String {
    match parse(Path::new("configs/bad.toml"), text) {
        Ok(_) => panic!("accepted a bad case:\n{text}"),
        Err(e) => e.to_string(),
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
            "[\"rhombic_drive\"]",
            &[
                "mechanisms",
                "rhombic_drive",
                "unknown mechanism",
                "cardan_gear",
            ],
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
            &[
                "geometry.pin_offset",
                "0.09",
                "longer than geometry.crank_length",
            ],
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
            "steps = 720\n[masses]\nrules = \"rod\"",
            &[
                "masses.rules",
                "rod",
                "must be \"rod_length\" or \"overall_length\"",
            ],
        ),
        (
            "steps = 720",
            "steps = 720\n[masses.slider_crank]\nrules = \"overall_length\"",
            &["masses.slider_crank.rules", "unknown field"],
        ),
        (
            "steps = 720",
            "steps = 720\n[masses]\nwheel_inertia = 0.001",
            &[
                "masses.wheel_inertia",
                "does not apply to the slider_crank",
                "[masses.cardan_gear]",
            ],
        ),
    ];
    for (from, to, parts) in cases {
        assert!(
            GOOD.contains(from),
            "test set-up: {from:?} not in the good case"
        );
        mentions(&error_of(&GOOD.replacen(from, to, 1)), parts);
    }
}

#[test]
fn syntax_missing_fields_and_unknown_keys_are_located() {
    mentions(
        &error_of(&GOOD.replace("bore = 0.12\n", "")),
        &["configs/bad.toml", "geometry.bore", "(missing)", "required"],
    );
    mentions(
        &error_of(&GOOD.replace("bore = 0.12", "bore = 0.12\nstroke = 0.1")),
        &["configs/bad.toml", "unknown field", "stroke"],
    );
    mentions(
        &error_of(&GOOD.replace("steps = 720", "steps = 72.5")),
        &["configs/bad.toml", "steps"],
    );
    mentions(&error_of("name = "), &["configs/bad.toml", "line 1"]);
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
    let report = cardan_runner::run_paths(&[cases], &out, Default::default());
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

const PUMP_GAS: &str = r#"
[gas]
model = "karhula_pump"
compression_ratio = 12
polytropic_exponent = 1.4
filling = 1.07
ambient_pressure = "1 bar"
"#;

#[test]
fn bad_gas_inputs_name_the_gas_field() {
    let pump = format!("{GOOD}{PUMP_GAS}");
    let case = parse(Path::new("configs/good.toml"), &pump).unwrap();
    assert_eq!(case.gas.unwrap().name(), "karhula_pump");
    let cases: &[(&str, &str, &[&str])] = &[
        (
            "compression_ratio = 12",
            "compression_ratio = 1",
            &["gas.compression_ratio", "1", "greater than 1"],
        ),
        (
            "compression_ratio = 12",
            "compression_ratio = 0.5",
            &["gas.compression_ratio", "0.5", "greater than 1"],
        ),
        (
            "polytropic_exponent = 1.4",
            "polytropic_exponent = 1.0",
            &["gas.polytropic_exponent", "1", "greater than 1"],
        ),
        (
            "polytropic_exponent = 1.4",
            "polytropic_exponent = 0.9",
            &["gas.polytropic_exponent", "0.9", "greater than 1"],
        ),
        (
            "ambient_pressure = \"1 bar\"",
            "ambient_pressure = \"-1 bar\"",
            &["gas.ambient_pressure", "-1 bar", "positive"],
        ),
        (
            "ambient_pressure = \"1 bar\"",
            "ambient_pressure = \"1 furlong\"",
            &["gas.ambient_pressure", "unknown unit", "furlong"],
        ),
        (
            "filling = 1.07",
            "filling = 0",
            &["gas.filling", "0", "positive"],
        ),
        (
            "model = \"karhula_pump\"",
            "model = \"stirling\"",
            &[
                "gas.model",
                "stirling",
                "unknown gas model",
                "karhula_engine",
            ],
        ),
        (
            "model = \"karhula_pump\"",
            "model = \"karhula_engine\"",
            &["gas.model", "engine", "machine = \"engine\""],
        ),
        (
            "filling = 1.07",
            "filling = 1.07\npeak_pressure = \"12 MPa\"",
            &[
                "gas.peak_pressure",
                "not an input of gas.model = \"karhula_pump\"",
            ],
        ),
        (
            "compression_ratio = 12\n",
            "",
            &["gas.compression_ratio", "required"],
        ),
    ];
    for (from, to, parts) in cases {
        assert!(
            pump.contains(from),
            "test set-up: {from:?} not in the pump case"
        );
        mentions(&error_of(&pump.replacen(from, to, 1)), parts);
    }

    let engine = format!(
        "{}{PUMP_GAS}peak_pressure = \"12 MPa\"\ncombustion_delay = 9.5\n",
        GOOD.replace("machine = \"pump\"", "machine = \"engine\"")
    )
    .replace("karhula_pump", "karhula_engine");
    parse(Path::new("configs/good.toml"), &engine).unwrap();
    for (from, to, parts) in [
        (
            "peak_pressure = \"12 MPa\"",
            "peak_pressure = \"50 kPa\"",
            &["gas.peak_pressure", "50 kPa", "exceed ambient_pressure"][..],
        ),
        (
            "combustion_delay = 9.5",
            "combustion_delay = -3",
            &["gas.combustion_delay", "-3", "0 to 180"][..],
        ),
        (
            "combustion_delay = 9.5\n",
            "",
            &["gas.combustion_delay", "required"][..],
        ),
    ] {
        mentions(&error_of(&engine.replacen(from, to, 1)), parts);
    }
}

/// A gas run's CSV carries the pressure, the gas torque and the totals, and its summary the
/// gas and total metrics.
#[test]
fn gas_results_are_written() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("pump.toml");
    std::fs::write(&file, format!("{GOOD}{PUMP_GAS}")).unwrap();
    let out = dir.path().join("out");
    let report = cardan_runner::run_paths(&[file], &out, Default::default());
    assert!(report.failures.is_empty(), "{:#?}", report.failures);
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("good/summary.json")).unwrap())
            .unwrap();
    assert_eq!(summary["gas_model"], "karhula_pump");
    let metrics = &summary["mechanisms"]["cardan_gear"]["metrics"];
    for m in [
        "cylinder_pressure_max",
        "gas_force_max",
        "gas_torque_max",
        "gas_work",
        "gas_torque_mean",
        "gas_power_mean",
        "total_crank_pin_force_max",
        "total_main_bearing_force_max",
        "total_gear_mesh_force_max",
        "total_torque_max",
        "total_work",
        "total_torque_mean",
        "total_power_mean",
    ] {
        assert!(metrics[m].is_number(), "summary lacks {m}");
    }
    assert!(metrics["cylinder_pressure_max"].as_f64().unwrap() > 3e6);
    let csv = std::fs::read_to_string(out.join("good/cardan_gear.csv")).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|c| *c == name).unwrap();
    let (p, gas, total, inertial) = (
        col("cylinder_pressure_pa"),
        col("gas_torque_nm"),
        col("total_torque_nm"),
        col("inertial_torque_nm"),
    );
    for line in lines {
        let cells: Vec<&str> = line.split(',').collect();
        assert_eq!(cells.len(), header.len());
        let x = |k: usize| cells[k].parse::<f64>().unwrap();
        assert!(x(p) >= 1e5 * 0.999);
        assert!((x(total) - x(gas) - x(inertial)).abs() <= 1e-9 * x(total).abs().max(1.0));
    }
}

#[test]
fn bad_compressor_inputs_name_the_gas_field() {
    let good = format!(
        "{GOOD}{}",
        r#"
[gas]
model = "compressor"
suction_pressure = "1 bar"
suction_temperature = "20 °C"
delivery_pressure = "8 bar"
clearance_ratio = 0.05
compression_exponent = 1.3
"#
    );
    let case = parse(Path::new("configs/good.toml"), &good).unwrap();
    assert_eq!(case.gas.unwrap().name(), "compressor");
    let cases: &[(&str, &str, &[&str])] = &[
        (
            "delivery_pressure = \"8 bar\"",
            "delivery_pressure = \"0.5 bar\"",
            &["gas.delivery_pressure", "0.5 bar", "above suction_pressure"],
        ),
        (
            "delivery_pressure = \"8 bar\"",
            "delivery_pressure = \"800 bar\"",
            &["gas.delivery_pressure", "800 bar", "delivers nothing"],
        ),
        (
            "suction_pressure = \"1 bar\"",
            "suction_pressure = \"-1 bar\"",
            &["gas.suction_pressure", "-1 bar", "positive"],
        ),
        (
            "suction_temperature = \"20 °C\"",
            "suction_temperature = \"-300 °C\"",
            &["gas.suction_temperature", "-300 °C", "positive"],
        ),
        (
            "clearance_ratio = 0.05",
            "clearance_ratio = -0.05",
            &["gas.clearance_ratio", "-0.05", "negative"],
        ),
        (
            "compression_exponent = 1.3",
            "compression_exponent = 0.8",
            &["gas.compression_exponent", "0.8", "at least 1"],
        ),
        (
            "compression_exponent = 1.3",
            "compression_exponent = 1.3\nexpansion_exponent = 0.5",
            &["gas.expansion_exponent", "0.5", "at least 1"],
        ),
        (
            "compression_exponent = 1.3",
            "compression_exponent = 1.3\ncompression_ratio = 12",
            &[
                "gas.compression_ratio",
                "not an input of gas.model = \"compressor\"",
            ],
        ),
    ];
    for (from, to, parts) in cases {
        assert!(
            good.contains(from),
            "test set-up: {from:?} not in the compressor case"
        );
        mentions(&error_of(&good.replacen(from, to, 1)), parts);
    }
}

#[test]
fn bad_closed_cycle_inputs_name_the_gas_field() {
    let good = format!(
        "{}{}",
        GOOD.replace("machine = \"pump\"", "machine = \"engine\""),
        r#"
[gas]
model = "closed_cycle"
compression_ratio = 10
lambda = 1.0
combustion_start_per_speed = "-0.0004 deg/rpm"
"#
    );
    let case = parse(Path::new("configs/good.toml"), &good).unwrap();
    assert_eq!(case.gas.unwrap().name(), "closed_cycle");
    let cases: &[(&str, &str, &[&str])] = &[
        (
            "compression_ratio = 10",
            "compression_ratio = 0.9",
            &["gas.compression_ratio", "0.9", "greater than 1"],
        ),
        ("lambda = 1.0", "lambda = 0", &["gas.lambda", "0"]),
        (
            "lambda = 1.0",
            "ambient_pressure = \"-1 bar\"",
            &["gas.ambient_pressure", "-1 bar"],
        ),
        (
            "lambda = 1.0",
            "wall_temperature = \"-10 K\"",
            &["gas.wall_temperature", "-10 K"],
        ),
        ("lambda = 1.0", "gamma = 1.0", &["gas.gamma", "1"]),
        (
            "lambda = 1.0",
            "exhaust_opening = \"90 deg\"",
            &["gas.exhaust_opening", "90 deg"],
        ),
        (
            "combustion_start_per_speed = \"-0.0004 deg/rpm\"",
            "combustion_start_per_speed = \"-0.0004 rpm\"",
            &["gas.combustion_start_per_speed", "unknown unit", "deg/rpm"],
        ),
        (
            "lambda = 1.0",
            "filling = 1.0",
            &[
                "gas.filling",
                "not an input of gas.model = \"closed_cycle\"",
            ],
        ),
    ];
    for (from, to, parts) in cases {
        assert!(
            good.contains(from),
            "test set-up: {from:?} not in the closed-cycle case"
        );
        mentions(&error_of(&good.replacen(from, to, 1)), parts);
    }
}

/// Gas models need a cylinder volume: a mechanism whose pistons turn (the hypotrochoid's piston
/// links) cannot take a `[gas]` table.
#[test]
fn gas_needs_pistons_in_cylinders() {
    // 721 steps: at 720 a step lands on a fold of the hypotrochoid's chain, refused first.
    let text = format!("{GOOD}{PUMP_GAS}")
        .replace(
            "mechanisms = [\"slider_crank\", \"cardan_gear\"]",
            "mechanisms = [\"slider_crank\", \"hypotrochoid\"]",
        )
        .replace("steps = 720", "steps = 721");
    mentions(
        &error_of(&text),
        &["gas", "hypotrochoid", "cylinder", "without [gas]"],
    );
}

/// Issue 22's r15: a case written in millimetres and rpm without units (crank 60, rod 140,
/// bore 120, speed 3000) used to run a 60 m crank at 3000 rad/s. Each implausible bare number
/// is refused, naming the field and the unit it was likely meant in; the same numbers with
/// their units run.
#[test]
fn numbers_meant_in_other_units_are_refused_with_the_likely_unit() {
    for (from, to, expected) in [
        ("crank_length = 0.06", "crank_length = 60", "\"60 mm\""),
        ("rod_length = 0.14", "rod_length = 140", "\"140 mm\""),
        ("bore = 0.12", "bore = 120", "\"120 mm\""),
        (
            "initial_speed = 628.3185307",
            "initial_speed = 3000",
            "\"3000 rpm\"",
        ),
    ] {
        assert!(GOOD.contains(from), "{from}");
        let e = error_of(&GOOD.replace(from, to));
        let field = to.split(' ').next().unwrap();
        assert!(e.contains(field) && e.contains(expected), "{to}: {e}");
    }
    let with_units = GOOD
        .replace("crank_length = 0.06", "crank_length = \"60 mm\"")
        .replace("rod_length = 0.14", "rod_length = \"140 mm\"")
        .replace("bore = 0.12", "bore = \"120 mm\"")
        .replace(
            "initial_speed = 628.3185307",
            "initial_speed = \"6000 RPM\"",
        );
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("case.toml");
    std::fs::write(&file, with_units).unwrap();
    assert!(cardan_case::case::load(&file).is_ok());
}

/// Issue 22's r10: the default hypotrochoid at 720 steps was "valid" for `cardan check` and
/// failed its run at a fold of its parallelogram chain (a step on sin((m+1)θ) = 0). The case is
/// refused on reading, naming the step and the remedy; with 721 steps it runs.
#[test]
fn a_grid_on_the_hypotrochoid_fold_is_refused_before_the_run() {
    let text = GOOD.replace(
        "mechanisms = [\"slider_crank\", \"cardan_gear\"]",
        "mechanisms = [\"hypotrochoid\"]",
    );
    let e = error_of(&text);
    assert!(
        e.contains("motion.steps") && e.contains("fold") && e.contains("steps = 721"),
        "{e}"
    );
    let text = text.replace("steps = 720", "steps = 721");
    let case = parse(Path::new("configs/good.toml"), &text).unwrap();
    cardan_runner::run_case(&case, None).unwrap();
}

/// Issue 22 item 9: what `cardan check` passed and the run then failed on. A gear face over
/// 40 in (the range of AGMA's empirical Cpf) failed at the first step's rating, and a
/// 250-character name when its folder was written: both are refused on reading.
#[test]
fn what_the_run_would_refuse_is_refused_on_reading() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs");
    let pump = std::fs::read_to_string(dir.join("karhula-pump-r60-l140-a0-w30pi.toml")).unwrap();
    let e = error_of(&format!("{pump}\n[gear]\nface_width = \"1.2 m\"\n"));
    assert!(e.contains("gear.face_width") && e.contains("40 in"), "{e}");
    let long = GOOD.replace(
        "name = \"good\"",
        &format!("name = \"{}\"", "a".repeat(250)),
    );
    let e = error_of(&long);
    assert!(e.contains("name") && e.contains("at most 200"), "{e}");
}

/// Bad ISO 6336 inputs of `[gear]` are refused on reading (so `cardan check` refuses them as the
/// run would), naming the field, the value as written, the rule and the fix: an ISO rating
/// without its accuracy grade, values out of range, an ISO field no rating reads (an
/// accuracy grade whose K_v and K_Hα are both given, an override without an ISO rating), and a
/// hardness ISO 6336-5's through-hardened line does not cover (its 190-342 HB, narrower than
/// AGMA's 140-400).
#[test]
fn bad_iso_gear_inputs_name_the_gear_field() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs");
    let pump = std::fs::read_to_string(dir.join("karhula-pump-r60-l140-a0-w30pi.toml")).unwrap();
    let cases: &[(&str, &[&str])] = &[
        (
            "standard = \"iso6336\"",
            &[
                "gear.accuracy_grade",
                "(missing)",
                "ISO 1328-1",
                "accuracy_grade = 7",
            ],
        ),
        (
            "standard = \"both\"\naccuracy_grade = 13",
            &["gear.accuracy_grade = 13", "from 1 to 12"],
        ),
        (
            "standard = \"both\"\naccuracy_grade = 7\napplication_factor = 0.8",
            &["gear.application_factor = 0.8", "from 1 to 4", "Table B.1"],
        ),
        (
            "accuracy_grade = 7",
            &[
                "gear.accuracy_grade = 7",
                "read only by an ISO 6336 rating",
                "standard = \"both\"",
            ],
        ),
        (
            "iso_quality = \"me\"",
            &[
                "gear.iso_quality = \"me\"",
                "read only by an ISO 6336 rating",
            ],
        ),
        (
            "standard = \"iso\"",
            &["gear.standard", "unknown word \"iso\""],
        ),
        (
            "standard = \"both\"\naccuracy_grade = 7\niso_dynamic_factor = 0.9",
            &["gear.iso_dynamic_factor = 0.9", "from 1 to 4", "at least 1"],
        ),
        (
            "standard = \"both\"\naccuracy_grade = 7\niso_dynamic_factor = 1.1\ntransverse_load_factor = 1.05",
            &[
                "gear.accuracy_grade = 7",
                "read by nothing",
                "iso_dynamic_factor and transverse_load_factor",
            ],
        ),
        (
            "face_load_factor = 1.3",
            &[
                "gear.face_load_factor = 1.3",
                "read only by an ISO 6336 rating",
            ],
        ),
        (
            "sigma_hlim = \"1200 MPa\"",
            &["gear.sigma_hlim", "1200 MPa", "read only by an ISO 6336 rating"],
        ),
        (
            "standard = \"both\"\naccuracy_grade = 7\nsigma_flim = [\"400 MPa\", \"-3 MPa\"]",
            &["gear.sigma_flim", "-3 MPa"],
        ),
        (
            "standard = \"both\"\naccuracy_grade = 7\nhardness = [300, 150]",
            &[
                "gear.hardness",
                "190-342 HB",
                "the gear's 150 HB",
                "standard = \"agma2001\"",
            ],
        ),
    ];
    for (gear, parts) in cases {
        let e = error_of(&format!("{pump}\n[gear]\n{gear}\n"));
        for p in *parts {
            assert!(e.contains(p), "{gear}: {p} not in {e}");
        }
    }
}

/// What the gas model would refuse when the run prepares it is refused on reading, naming the
/// field the user wrote, in the unit written (issue 36.11): a bore, crank or rod far out of
/// scale (the run blamed `gas.swept_volume`, no case field), a combustion start outside its
/// window (refused only at run time, in radians), a compression ratio that overheats the gas
/// by itself (blamed on the default `fuel_heating_value`).
#[test]
fn what_the_gas_model_would_refuse_is_refused_on_reading() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs");
    let engine = std::fs::read_to_string(dir.join("nunes-op-r26-l90-2000rpm.toml")).unwrap();
    let cases: &[(&str, &str, &[&str])] = &[
        (
            "bore = \"60 mm\"",
            "bore = \"1e-9 m\"",
            &["geometry.bore", "\"1e-9 m\"", "0.1 mm to 10 m"],
        ),
        (
            "bore = \"60 mm\"",
            "bore = \"1e300 m\"",
            &["geometry.bore", "\"1e300 m\"", "0.1 mm to 10 m"],
        ),
        (
            "bore = \"60 mm\"",
            "bore = \"0.05 mm\"",
            &["geometry.bore", "\"0.05 mm\"", "0.1 mm to 10 m"],
        ),
        (
            "crank_length = \"26 mm\"",
            "crank_length = \"1e-12 m\"",
            &["geometry.crank_length", "\"1e-12 m\"", "0.1 mm to 10 m"],
        ),
        (
            "rod_length = \"90 mm\"",
            "rod_length = \"1e300 m\"",
            &["geometry.rod_length", "\"1e300 m\"", "0.1 mm to 10 m"],
        ),
        (
            "combustion_start = \"350.93 deg\"",
            "combustion_start = \"700 deg\"",
            &[
                "gas.combustion_start",
                "\"700 deg\"",
                "between intake_closing and exhaust_opening",
            ],
        ),
        (
            "compression_ratio = 10 ",
            "compression_ratio = 1e6 ",
            // Refused by its plausible range (issue 36.5) before the model's own rule (a
            // compression that overheats the gas by itself): either way in its own field.
            &["gas.compression_ratio", "1000000", "at most 50"],
        ),
    ];
    for (from, to, parts) in cases {
        assert!(engine.contains(from), "{from}");
        let e = error_of(&engine.replace(from, to));
        mentions(&e, parts);
        assert!(
            !e.contains("swept_volume") && !e.contains("fuel_heating_value"),
            "{e}"
        );
    }
    // The same case as shipped reads and its gas is prepared.
    parse(Path::new("configs/good.toml"), &engine).unwrap();
}

/// Inputs that nothing of the case would read are refused, naming the field and why, as
/// `[gear]` without a mesh is (issue 36.14): a mechanism's own or mass table for a mechanism not
/// in the case, `angular_acceleration` in a dynamic motion, `steady_tolerance` with one cycle,
/// `pin_offset` where no mechanism has a pin to offset, a two-stroke layout with a four-stroke
/// engine model. Where a mixed case has a mechanism that reads it, it is accepted.
#[test]
fn inputs_nothing_would_read_are_refused() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs");
    let shipped = |n: &str| std::fs::read_to_string(dir.join(format!("{n}.toml"))).unwrap();
    let slider_only = GOOD.replace(
        "mechanisms = [\"slider_crank\", \"cardan_gear\"]",
        "mechanisms = [\"slider_crank\"]",
    );
    let cardan_only = GOOD.replace(
        "mechanisms = [\"slider_crank\", \"cardan_gear\"]",
        "mechanisms = [\"cardan_gear\"]",
    );
    let dynamic = shipped("karhula-pump-motor-dynamic");
    let four_stroke = shipped("balance-inline3");
    let cases: Vec<(String, &[&str])> = vec![
        (
            format!("{slider_only}[cardan_gear]\npressure_angle = \"25 deg\"\n"),
            &[
                "configs/bad.toml",
                "\"good\"",
                "cardan_gear = a [cardan_gear] table",
                "not among the case's mechanisms (slider_crank)",
            ],
        ),
        (
            format!("{slider_only}[hypotrochoid]\nangular_modulus = 3\n"),
            &[
                "hypotrochoid = a [hypotrochoid] table",
                "not among the case's mechanisms",
            ],
        ),
        (
            format!("{slider_only}[masses.scotch_yoke]\npiston_mass = 1.0\n"),
            &[
                "masses.scotch_yoke = a [masses.scotch_yoke] table",
                "not among the case's mechanisms",
            ],
        ),
        (
            dynamic.replace(
                "angular_acceleration = 0.0",
                "angular_acceleration = \"50 rad/s^2\"",
            ),
            &[
                "motion.angular_acceleration = \"50 rad/s^2\"",
                "not read by a dynamic motion",
            ],
        ),
        (
            dynamic.replace("cycles = 5", "steady_tolerance = 0.001"),
            &["motion.steady_tolerance = 0.001", "single cycle"],
        ),
        (
            dynamic.replace("cycles = 5", "cycles = 1\nsteady_tolerance = 0.001"),
            &["motion.steady_tolerance = 0.001", "single cycle"],
        ),
        (
            // Issue 36.12: a case file's gear meshes held to the gear file's pitch-line rule
            // (the cardan pair of r = 26 mm: v = ω·r, 500 m/s at 19 000 rad/s).
            shipped("nunes-op-r26-l90-2000rpm-lead10").replace(
                "initial_speed = \"2000 rpm\"",
                "initial_speed = \"200000 rpm\"",
            ),
            &[
                "motion.initial_speed = \"200000 rpm\"",
                "gear mesh",
                "m/s at the pitch line",
                "at most 500 m/s",
            ],
        ),
        (
            // The thesis pump's cardan pair (v = 2ω·e, e = 30 mm) run up to 35 000 rad/s.
            cardan_testing::cases::loaded_thesis_pump("bad").replace(
                "angular_acceleration = 0.0\n",
                "angular_acceleration = \"1e8 rad/s^2\"\n",
            ),
            &[
                "motion.angular_acceleration = \"1e8 rad/s^2\"",
                "at most 500 m/s",
            ],
        ),
        (
            // Issue 36.3: the solved speed of 1e15 kg·m² does not move in double precision.
            dynamic.replace("inertia = \"0.2 kg*m^2\"", "inertia = \"1e15 kg*m^2\""),
            &["flywheel.inertia = \"1e15 kg*m^2\"", "at most 1e6 kg*m^2"],
        ),
        (
            // Issue 36.10: 100 000 cycles took about 13 hours.
            dynamic.replace("cycles = 5", "cycles = 100000"),
            &[
                "motion.cycles = 100000",
                "integration steps, more than 20000000",
                "steady_tolerance",
            ],
        ),
        (
            cardan_only.replace("bore = 0.12", "bore = 0.12\npin_offset = \"5 mm\""),
            &[
                "geometry.pin_offset = \"5 mm\"",
                "no mechanism of the case has a piston pin to offset",
                "slider_crank",
            ],
        ),
        (
            four_stroke.replace("cylinders = 3", "cylinders = 3\ncycle = \"two_stroke\""),
            &[
                "layout.cycle = \"two_stroke\"",
                "gas.model = \"karhula_engine\" is a four-stroke cycle",
            ],
        ),
    ];
    for (text, parts) in &cases {
        mentions(&error_of(text), parts);
    }
    // Read by some mechanism of the case, or as shipped: accepted.
    let accepted = [
        GOOD.replace("bore = 0.12", "bore = 0.12\npin_offset = \"5 mm\""),
        format!("{GOOD}[cardan_gear]\npressure_angle = \"25 deg\"\n"),
        dynamic.replace("cycles = 5", "cycles = 5\nsteady_tolerance = 0.001"),
        dynamic,
        four_stroke,
        shipped("karhula-pump-inline3-motor-dynamic"),
    ];
    for text in &accepted {
        parse(Path::new("configs/good.toml"), text).unwrap_or_else(|e| panic!("{e}\n{text}"));
    }
}

/// Common mistakes of form (a table written as an array of tables, a whole number written with
/// a decimal point, a string for a number or a number for a string, a field left out) read as
/// a person would say them: the field's path, what it must be and the value written, not the
/// TOML reader's Rust types ("expected i64", "struct RawGeometry with 6 elements").
#[test]
fn mistakes_of_form_name_the_field_and_what_it_must_be() {
    let cases: &[(&str, &str, &[&str])] = &[
        (
            "[geometry]",
            "[[geometry]]",
            &[
                "configs/bad.toml",
                "\"good\"",
                "geometry",
                "must be a table ([geometry]), not an array of tables ([[geometry]])",
            ],
        ),
        (
            "[motion]",
            "[[motion]]",
            &[
                "motion",
                "must be a table ([motion]), not an array of tables ([[motion]])",
            ],
        ),
        (
            "steps = 720",
            "steps = 720.0",
            &[
                "\"good\"",
                "motion.steps",
                "720.0",
                "must be a whole number (720, not 720.0)",
            ],
        ),
        (
            "steps = 720",
            "steps = 72.5",
            &["motion.steps", "72.5", "must be a whole number"],
        ),
        (
            "steps = 720",
            "steps = \"720\"",
            &["motion.steps", "\"720\"", "whole number", "without quotes"],
        ),
        (
            "machine = \"pump\"",
            "machine = 1",
            &[
                "machine",
                "= 1",
                "must be a string in quotes",
                "\"pump\" or \"engine\"",
            ],
        ),
        (
            "name = \"good\"",
            "name = 3",
            &["name", "= 3", "must be a string in quotes"],
        ),
        (
            "[\"slider_crank\", \"cardan_gear\"]",
            "\"slider_crank\"",
            &[
                "mechanisms",
                "\"slider_crank\"",
                "must be a list",
                "[\"slider_crank\"]",
            ],
        ),
        (
            "[\"slider_crank\", \"cardan_gear\"]",
            "[1, 2]",
            &[
                "mechanisms[0] = 1",
                "must be a string in quotes",
                "e.g. [\"slider_crank\"]",
            ],
        ),
        (
            "bore = 0.12",
            "bore = 0.12\nopposed_pistons = \"yes\"",
            &[
                "geometry.opposed_pistons",
                "\"yes\"",
                "must be true or false",
            ],
        ),
        (
            "steps = 720",
            "steps = 720\n[output]\ncsv = \"yes\"",
            &["output.csv", "\"yes\"", "must be true or false"],
        ),
        (
            "steps = 720",
            "steps = 720\n[output]\ndecimation = 2.0",
            &[
                "output.decimation",
                "2.0",
                "must be a whole number (2, not 2.0)",
            ],
        ),
        (
            "steps = 720",
            "steps = 720\n[[output]]\ncsv = true",
            &[
                "output",
                "must be a table ([output]), not an array of tables ([[output]])",
            ],
        ),
        (
            "steps = 720",
            "steps = 720\n[masses]\nrod_mass = true",
            &["masses.rod_mass", "true", "expected a number in kg"],
        ),
        (
            "bore = 0.12",
            "bore = [0.12]",
            &["geometry.bore", "[0.12]", "expected a number in m"],
        ),
        (
            "steps = 720\n",
            "",
            &[
                "\"good\"",
                "motion.steps",
                "(missing)",
                "required",
                "whole number",
            ],
        ),
        (
            "bore = 0.12\n",
            "",
            &[
                "geometry.bore",
                "(missing)",
                "required",
                "m or a string with a unit",
            ],
        ),
        (
            "machine = \"pump\"\n",
            "",
            &["machine", "(missing)", "required", "\"pump\" or \"engine\""],
        ),
        (
            "name = \"good\"\n",
            "",
            &["configs/bad.toml", "name", "(missing)", "required"],
        ),
        (
            "[motion]",
            "[motions]",
            &["motions", "unknown field", "did you mean \"motion\"?"],
        ),
    ];
    for (from, to, parts) in cases {
        assert!(
            GOOD.contains(from),
            "test set-up: {from:?} not in the good case"
        );
        let message = error_of(&GOOD.replacen(from, to, 1));
        mentions(&message, parts);
        for rust in [
            "i64",
            "RawGeometry",
            "RawMotion",
            "struct",
            "invalid type",
            "invalid length",
        ] {
            assert!(
                !message.contains(rust),
                "{to:?}: the message speaks the reader's types ({rust}): {message}"
            );
        }
    }
}

/// The good case on radians, with the crank's deceleration `a` (rad/s²) from 2 rad/s over
/// 0 to `end` rad.
fn decelerating(a: f64, end: f64) -> String {
    GOOD.replace("start_angle = 90.0", "start_angle = \"0 rad\"")
        .replace("end_angle = 810.0", &format!("end_angle = \"{end:?} rad\""))
        .replace("initial_speed = 628.3185307", "initial_speed = \"2 rad/s\"")
        .replace(
            "angular_acceleration = 0.0",
            &format!("angular_acceleration = \"{a:?} rad/s^2\""),
        )
}

/// A crank that really stops before the end angle is refused, saying where it stops (2 rad/s
/// at −1 rad/s² stops after ω0²/(2|α|) = 2 rad = 114.592°) and that ω² is below 0 by more
/// than round-off.
#[test]
fn a_crank_that_stops_before_the_end_is_refused_saying_where() {
    let message = error_of(&decelerating(-1.0, 3.0));
    mentions(
        &message,
        &[
            "motion.initial_speed",
            "stops at 114.592°",
            "before the end angle 171.887°",
            "more than round-off",
        ],
    );
}

/// A crank decelerated to rest exactly at the end angle: ω0² + 2·α·Δθ there is 0 up to
/// round-off, and may come out a few ulp below 0 (or exactly 0). That is a crank that just
/// reaches the end, not one that stops before it: the case is read and runs, at rest at the
/// end.
#[test]
fn a_crank_that_just_reaches_the_end_angle_at_rest_runs() {
    let (w0, end) = (2.0_f64, 3.0_f64);
    let exact = -(w0 * w0) / (2.0 * end);
    // The accelerations around the exact one whose ω² at the end rounds to below 0 or to 0.
    let mut found = Vec::new();
    for ulps in -4_i64..=4 {
        let a = f64::from_bits((exact.to_bits() as i64 + ulps) as u64);
        let w2 = w0 * w0 + 2.0 * a * end;
        if w2 <= 0.0 && w2 > -1e-12 {
            found.push((a, w2));
        }
    }
    assert!(
        found.iter().any(|(_, w2)| *w2 < 0.0),
        "test set-up: no acceleration with ω² a round-off below 0: {found:?}"
    );
    for (a, _) in found {
        let case = parse(Path::new("configs/rest.toml"), &decelerating(a, end))
            .unwrap_or_else(|e| panic!("α = {a:?}: {e}"));
        cardan_runner::run_case(&case, None).unwrap_or_else(|e| panic!("α = {a:?}: {e}"));
    }
}

/// A misspelled field, table, option or word anywhere in a case names its dotted path and the
/// nearest valid name (issue 23), as README.md shows.
#[test]
fn a_misspelling_anywhere_names_its_path_and_the_nearest_valid_name() {
    let readme =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../README.md"))
            .unwrap();
    let shown = "geometry.crank_lenght: unknown field \"crank_lenght\": did you mean \"crank_length\"? (the fields here: crank_length, rod_length, bore, pin_offset, opposed_pistons, crank_phase)";
    assert!(readme.contains(shown), "README.md no longer shows: {shown}");
    let e = error_of(&GOOD.replace("crank_length", "crank_lenght"));
    assert!(e.ends_with(shown), "{e}");
    let cases: &[(&str, &str, &[&str])] = &[
        (
            "steps = 720",
            "stpes = 720",
            &["motion.stpes", "did you mean \"steps\"?"],
        ),
        (
            "steps = 720",
            "steps = 720\n[masses]\nrod_mas = \"1 kg\"",
            &["masses.rod_mas", "did you mean \"rod_mass\"?"],
        ),
        (
            "steps = 720",
            "steps = 720\n[masses.cardan_gear]\npiston_mas = \"1 kg\"",
            &[
                "masses.cardan_gear.piston_mas",
                "did you mean \"piston_mass\"?",
            ],
        ),
        (
            "steps = 720",
            "steps = 720\n[cardan_gaer]\ngear_mesh_model = \"involute\"",
            &["cardan_gaer", "did you mean \"cardan_gear\"?"],
        ),
        (
            "steps = 720",
            "steps = 720\n[cardan_gear]\ngear_mesh_modle = \"involute\"",
            &[
                "cardan_gear.gear_mesh_modle",
                "did you mean \"gear_mesh_model\"?",
            ],
        ),
        (
            "steps = 720",
            "steps = 720\n[cardan_gear]\ngear_mesh_model = \"involut\"",
            &["cardan_gear.gear_mesh_model", "did you mean \"involute\"?"],
        ),
        (
            "steps = 720",
            "steps = 720\n[output]\ncvs = false",
            &["output.cvs", "did you mean \"csv\"?"],
        ),
        (
            "machine = \"pump\"",
            "machine = \"pmup\"",
            &["machine", "did you mean \"pump\"?"],
        ),
        (
            "\"cardan_gear\"]",
            "\"cardan_gaer\"]",
            &["mechanisms", "did you mean \"cardan_gear\"?"],
        ),
        (
            "[motion]",
            "[motoin]",
            &["motoin", "did you mean \"motion\"?"],
        ),
    ];
    for (from, to, parts) in cases {
        assert!(GOOD.contains(from), "test set-up: {from:?}");
        mentions(&error_of(&GOOD.replacen(from, to, 1)), parts);
    }
}

/// Issue 36.15: a mass a hypotrochoid does not have is refused naming the tables it may go in,
/// not always `[masses.cardan_gear]`; in the hypotrochoid's own table, that it has no such body.
#[test]
fn a_mass_a_mechanism_lacks_names_the_tables_it_applies_to() {
    let case = "name = \"h\"\nmachine = \"pump\"\nmechanisms = [\"hypotrochoid\"]\n[geometry]\ncrank_length = \"75 mm\"\nrod_length = \"340 mm\"\nbore = \"100 mm\"\n[motion]\nstart_angle = 90\nend_angle = 810\ninitial_speed = \"1 rad/s\"\nangular_acceleration = 0\nsteps = 7206\n";
    let own = error_of(&format!("{case}[masses.hypotrochoid]\npiston_mass = 0.4\n"));
    mentions(
        &own,
        &[
            "masses.hypotrochoid.piston_mass",
            "does not apply to the hypotrochoid (it has no such body)",
            "[masses.slider_crank], [masses.cardan_gear], [masses.scotch_yoke]",
        ],
    );
    let common = error_of(&format!("{case}[masses]\nwheel_mass = 0.3\n"));
    mentions(
        &common,
        &["masses.wheel_mass", "does not apply to the hypotrochoid"],
    );
    assert!(
        !common.contains("[masses.slider_crank]") && common.contains("[masses.cardan_gear]"),
        "{common}"
    );
}

/// Issue 36.15: a bare whole `initial_speed` of rpm's size passes, and summary.json's
/// `warnings` says how it was taken.
#[test]
fn a_bare_speed_that_reads_like_rpm_is_a_warning_of_the_summary() {
    let text = GOOD.replacen("initial_speed = ", "initial_speed = 980 # ", 1);
    let case = parse(Path::new("configs/speed.toml"), &text).unwrap();
    let summary = cardan_runner::output::summary_json(&case, &[]);
    let warnings = summary["warnings"].to_string();
    mentions(
        &warnings,
        &["motion.initial_speed = 980", "980 rad/s", "9358 rpm"],
    );
    let quiet = parse(Path::new("configs/speed.toml"), GOOD).unwrap();
    assert!(cardan_runner::output::summary_json(&quiet, &[])
        .get("warnings")
        .is_none());
}

/// An `[optimize]` naming a summary metric that no mechanism of the case reports (issue 40):
/// a name the metric registry's templates accept but no mechanism's joint or body has, the
/// objective of a mechanism whose summary lacks it, a gear metric without `[gear]`. `cardan
/// check` (the batch's reading, `load_batch`) and `cardan run` (`run_paths`) refuse it with
/// one message naming the file, the field, the metric and the likely fix, and run nothing.
#[test]
fn an_optimisation_of_a_metric_no_mechanism_reports_is_refused_by_check_and_run() {
    use cardan_testing::cases::kinematic_optimization;
    let good_constraint = "rod_angular_velocity_max >= 20 rad/s";
    let cases: Vec<(String, &[&str])> = vec![
        (
            // `crankpin` for the slider-crank's joint `crank_pin`: the registry's template
            // `{family}_{joint}_force_max` reads it, no summary has it.
            kinematic_optimization("", "inertial_crankpin_force_max <= 5 kN"),
            &[
                "opt.toml",
                "case \"kinematic\"",
                "optimize.constraints = \"inertial_crankpin_force_max <= 5 kN\"",
                "no mechanism of the case reports the metric \"inertial_crankpin_force_max\"",
                "the slider_crank's summary has no such metric",
                "did you mean \"inertial_crank_pin_force_max\"",
                "constrain a metric one of them reports",
            ],
        ),
        (
            // The cardan gear's rod is guided by the gears: it has no piston side force.
            kinematic_optimization("", good_constraint)
                .replace("\"slider_crank\"", "\"cardan_gear\"")
                .replace(
                    "objective = \"piston_acceleration_max\"",
                    "objective = \"inertial_piston_side_force_max\"",
                ),
            &[
                "opt.toml",
                "optimize.objective = \"inertial_piston_side_force_max\"",
                "the cardan_gear's summary has no metric \"inertial_piston_side_force_max\"",
                "optimise a metric every mechanism of the case reports",
            ],
        ),
        (
            kinematic_optimization("", "bending_safety_factor >= 1.2"),
            &[
                "opt.toml",
                "optimize.constraints = \"bending_safety_factor >= 1.2\"",
                "needs a [gear] table",
            ],
        ),
    ];
    let dir = tempfile::tempdir().unwrap();
    for (k, (text, words)) in cases.iter().enumerate() {
        let file = dir.path().join(format!("{k}")).join("opt.toml");
        std::fs::create_dir_all(file.parent().unwrap()).unwrap();
        std::fs::write(&file, text).unwrap();
        let (batch, checked) = cardan_runner::run::load_batch(std::slice::from_ref(&file));
        assert!(batch.optimizations.is_empty(), "case {k} accepted");
        assert_eq!(checked.len(), 1, "{checked:?}");
        for w in *words {
            assert!(
                checked[0].contains(w),
                "case {k}: {w:?} not in {}",
                checked[0]
            );
        }
        let out = dir.path().join(format!("out{k}"));
        let options = cardan_runner::RunOptions {
            jobs: Some(1),
            ..Default::default()
        };
        let report = cardan_runner::run_paths(std::slice::from_ref(&file), &out, options);
        assert_eq!(report.failures, checked, "case {k}: check and run disagree");
        assert!(report.written.is_empty() && !out.join("kinematic").exists());
    }
    // A constraint on a metric one mechanism reports binds that one: accepted.
    let both = kinematic_optimization("", "inertial_piston_side_force_max <= 5 kN")
        .replace("[\"slider_crank\"]", "[\"slider_crank\", \"cardan_gear\"]");
    let file = dir.path().join("both.toml");
    std::fs::write(&file, both).unwrap();
    let (batch, failures) = cardan_runner::run::load_batch(&[file]);
    assert!(failures.is_empty(), "{failures:?}");
    assert_eq!(batch.optimizations.len(), 1);
}
