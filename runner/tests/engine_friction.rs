//! An engine's `[friction]` table with the engine components (valve train, accessories,
//! pumping) and the fmep cross-check: a small case runs with them, bad values and engine fields
//! on a pump are clear errors.

use cardan_case::case::parse;
use cardan_dynamics::engine_losses::displacement;
use cardan_dynamics::{engine_metrics, fmep_breakdown, FmepModel, FollowerContact};
use cardan_runner::run_case;
use cardan_testing::mentions;
use std::f64::consts::PI;
use std::path::Path;

/// The Karhula engine (bore = stroke = 120 mm, r_c = 12) at 3000 rpm, one cycle; `FRICTION`
/// is replaced by the `[friction]` fields of a test.
const ENGINE: &str = r#"
name = "engine-friction"
machine = "engine"
mechanisms = ["slider_crank", "cardan_gear"]
[geometry]
crank_length = 0.06
rod_length = 0.14
bore = 0.12
[motion]
start_angle = 90.0
end_angle = 810.0
initial_speed = "3000 rpm"
angular_acceleration = 0.0
steps = 1440
[masses]
piston_mass = 0.026
[gas]
model = "karhula_engine"
compression_ratio = 12
polytropic_exponent = 1.4
filling = 1.07
ambient_pressure = "1 atm"
peak_pressure = "12 MPa"
combustion_delay = "9.5 deg"
[friction]
FRICTION
"#;

fn engine_case(friction: &str) -> String {
    ENGINE.replace("FRICTION", friction)
}

fn error_of(text: &str) -> String {
    match parse(Path::new("configs/bad.toml"), text) {
        Ok(_) => panic!("accepted a bad case:\n{text}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn an_engine_case_runs_with_every_engine_component() {
    let text = engine_case(
        r#"valve_train = "flat"
accessories = true
pumping = true
intake_pressure = "60 kPa"
fmep_model = "pnh""#,
    );
    let case = parse(Path::new("configs/engine-friction.toml"), &text).unwrap();
    let friction = case.friction.as_ref().unwrap();
    let engine = friction.engine.unwrap();
    assert_eq!(
        engine.valve_train.map(|v| v.follower),
        Some(FollowerContact::FLAT)
    );
    assert!(engine.accessories && engine.pumping);
    assert_eq!(engine.intake_pressure, 60e3);
    assert_eq!(engine.fmep_model, FmepModel::Pnh1989);
    // The PNH gas-loading term takes the gas model's compression ratio.
    assert_eq!(engine.compression_ratio, 12.0);
    let w = 100.0 * PI;
    let vd = displacement(0.12, 0.12);
    for r in run_case(&case, None).unwrap() {
        let s = &r.summary;
        let name = r.mechanism.name();
        for c in ["valve_train", "accessories", "pumping"] {
            let p = s.get(&format!("power_loss_mean_{c}")).unwrap();
            assert!(p > 0.0, "{name}: {c} = {p}");
        }
        // Constant speed: Bishop's accessories mep (2.69 kPa at 1000 rpm, growing as N^1.5;
        // docs/validation/thai-thesis.md) at 3000 rpm is 2.69·3^1.5 = 13.977 kPa (±0.005·5.2
        // from the printed 2.69); the mep is the mean power over V_d·N/120.
        let got = s.get("power_loss_mean_accessories").unwrap() / (vd * 25.0);
        assert!(
            (got - 13.977e3).abs() <= 0.005e3 * 3f64.powf(1.5),
            "{name}: {got} against 13.977 kPa"
        );
        // The fmep metrics the runner adds after the run.
        let m = engine_metrics(
            friction,
            r.mechanism.as_ref(),
            case.geometry.bore,
            &case.motion,
            case.end_angle,
            s,
        );
        let get = |n: &str| m.iter().find(|(k, _)| *k == n).map(|(_, v)| *v).unwrap();
        let lost = s.get("loss_work").unwrap();
        assert!((get("fmep") * vd / lost - 1.0).abs() < 1e-12);
        assert!(get("fmep_mechanical") < get("fmep"));
        let pnh = fmep_breakdown(&engine, &friction.oil, 0.12, 0.12, w).total();
        assert!((get("fmep_pnh") / pnh - 1.0).abs() < 1e-12, "{name}");
    }
}

#[test]
fn engine_components_are_off_by_default() {
    // An empty [friction] table on an engine is the thesis's set: no engine component, the
    // cross-check's settings at their defaults.
    let case = parse(Path::new("configs/engine.toml"), &engine_case("")).unwrap();
    let engine = case.friction.as_ref().unwrap().engine.unwrap();
    assert!(engine.valve_train.is_none() && !engine.accessories && !engine.pumping);
    assert_eq!(engine.intake_pressure, 101_325.0);
    assert_eq!(engine.fmep_model, FmepModel::SandovalHeywood2003);
    for r in run_case(&case, None).unwrap() {
        for c in ["valve_train", "accessories", "pumping"] {
            assert!(r.summary.get(&format!("power_loss_mean_{c}")).is_none());
        }
    }
    // A roller follower; without a gas model the PNH compression ratio is 10.
    let text = engine_case(r#"valve_train = "roller""#)
        .replace("[gas]\nmodel = \"karhula_engine\"\ncompression_ratio = 12\npolytropic_exponent = 1.4\nfilling = 1.07\nambient_pressure = \"1 atm\"\npeak_pressure = \"12 MPa\"\ncombustion_delay = \"9.5 deg\"\n", "");
    assert!(!text.contains("[gas]"));
    let case = parse(Path::new("configs/engine.toml"), &text).unwrap();
    let engine = case.friction.as_ref().unwrap().engine.unwrap();
    assert_eq!(engine.compression_ratio, 10.0);
    assert_eq!(
        engine.valve_train.map(|v| v.follower),
        Some(FollowerContact::ROLLER)
    );
    // A pump's [friction] has no engine part.
    let pump = engine_case("")
        .replace("machine = \"engine\"", "machine = \"pump\"")
        .replace("model = \"karhula_engine\"", "model = \"karhula_pump\"")
        .replace(
            "peak_pressure = \"12 MPa\"\ncombustion_delay = \"9.5 deg\"\n",
            "",
        );
    let case = parse(Path::new("configs/pump.toml"), &pump).unwrap();
    assert!(case.friction.as_ref().unwrap().engine.is_none());
}

#[test]
fn bad_engine_fields_are_clear_errors() {
    let cases: &[(&str, &[&str])] = &[
        (
            r#"valve_train = "hydraulic""#,
            &[
                "configs/bad.toml",
                "\"engine-friction\"",
                "friction.valve_train",
                "hydraulic",
                r#"unknown word "hydraulic""#,
                "must be \"flat\", \"roller\" or \"none\"",
            ],
        ),
        (
            r#"accessories = "yes""#,
            &["friction.accessories", "yes", "must be true or false"],
        ),
        (
            "pumping = 1",
            &["friction.pumping = 1", "must be true or false"],
        ),
        (
            r#"pumping = true
intake_pressure = "2 bar""#,
            &[
                "friction.intake_pressure",
                "2 bar",
                "at most ambient",
                "not boosted",
            ],
        ),
        (
            r#"intake_pressure = "5 kPa""#,
            &["friction.intake_pressure", "5 kPa", "above 0.1 × ambient"],
        ),
        (
            r#"intake_pressure = "-5 kPa""#,
            &["friction.intake_pressure", "must be positive"],
        ),
        (
            r#"valve_train = "roller"
cam_friction_coefficient = 0.1"#,
            &[
                "friction.cam_friction_coefficient",
                "0.1",
                r#"only with valve_train = "flat""#,
            ],
        ),
        (
            r#"valve_spring_speed = "7000 rpm""#,
            &[
                "friction.valve_spring_speed",
                "7000 rpm",
                "the valve train is off",
            ],
        ),
        (
            r#"valve_train = "flat"
valve_spring_speed = 0"#,
            &["friction.valve_spring_speed", "must be positive"],
        ),
        (
            r#"valve_train = "flat"
cam_friction_coefficient = -0.1"#,
            &["friction.cam_friction_coefficient", "must not be negative"],
        ),
        (
            r#"fmep_model = "chen_flynn""#,
            &[
                "friction.fmep_model",
                r#"unknown word "chen_flynn""#,
                "must be \"sandoval_heywood\" or \"pnh\"",
            ],
        ),
        (
            r#"valve_trains = "flat""#,
            &["friction.valve_trains", "unknown field", "valve_train"],
        ),
    ];
    for (friction, parts) in cases {
        mentions(&error_of(&engine_case(friction)), parts);
    }
}

#[test]
fn engine_fields_on_a_pump_are_refused() {
    let pump = |friction: &str| {
        engine_case(friction)
            .replace("machine = \"engine\"", "machine = \"pump\"")
            .replace("model = \"karhula_engine\"", "model = \"karhula_pump\"")
            .replace(
                "peak_pressure = \"12 MPa\"\ncombustion_delay = \"9.5 deg\"\n",
                "",
            )
    };
    for (field, value) in [
        ("valve_train", r#""flat""#),
        ("accessories", "true"),
        ("pumping", "false"),
        ("intake_pressure", r#""80 kPa""#),
        ("fmep_model", r#""pnh""#),
    ] {
        let e = error_of(&pump(&format!("{field} = {value}")));
        mentions(
            &e,
            &[
                &format!("friction.{field}"),
                "only an engine has a valve train, accessories and pumping losses",
                "machine = \"pump\"",
            ],
        );
    }
}
