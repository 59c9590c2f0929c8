//! The `pressure_trace` gas model against the engine its shipped trace was sampled from.

use std::f64::consts::PI;

/// The shipped example's trace is the Karhula engine's pressure at 0.5° steps, so the
/// example reproduces that engine's slider-crank gas loads: its gas work within 1e-4 and its
/// peak gas torque within 1e-5 (a linear interpolation's error between 0.5° samples), its
/// peak pressure exactly (a sample).
#[test]
fn the_example_reproduces_the_engine_its_trace_came_from() {
    let configs = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs");
    let run = |name: &str| {
        let case = cardan_case::case::load(&configs.join(name)).unwrap();
        // The first mechanism of both cases, whose pressure the trace is.
        let results = cardan_runner::run_case(&case, None).unwrap();
        results.into_iter().next().unwrap().summary
    };
    let trace = run("example-pressure-trace.toml");
    let engine = run("karhula-engine-r60-l140-a0-w200pi-titanium.toml");
    for (metric, tolerance) in [
        ("gas_work", 1e-4),
        ("gas_torque_max", 1e-5),
        ("cylinder_pressure_max", 1e-12),
    ] {
        let (a, b) = (trace.get(metric).unwrap(), engine.get(metric).unwrap());
        assert!(
            (a / b - 1.0).abs() <= tolerance,
            "{metric}: {a} against {b}"
        );
    }
}

/// The thesis pump at 30π rad/s over one revolution (90° → 450°) on `steps` steps, with the
/// gas table `gas` and per-step CSV.
fn pump(steps: usize, gas: &str) -> String {
    format!(
        r#"
name = "pump-trace"
machine = "pump"
mechanisms = ["slider_crank"]
[geometry]
crank_length = 0.06
rod_length = 0.14
bore = 0.12
[motion]
start_angle = 90.0
end_angle = 450.0
initial_speed = 94.24777960769379
angular_acceleration = 0.0
steps = {steps}
[masses.slider_crank]
rod_inertia = 0.0167
[output]
csv = true
[gas]
{gas}
"#
    )
}

/// A CSV file's column `name`.
fn column(csv: &str, name: &str) -> Vec<String> {
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let k = header.iter().position(|h| *h == name).unwrap();
    lines
        .map(|l| l.split(',').nth(k).unwrap().to_string())
        .collect()
}

/// A run's own per-step CSV fed back as a `pressure_trace` (issue 35 §4), closed form (its
/// rows from 90° to 450°, the last the first a cycle on), on the same grid: the thesis pump at
/// 30π rad/s, slider-crank, one revolution of 3600 steps.
///
/// - The trace of `gas_force_n / A_pis` (the pressure whose p·A is the force the run applied)
///   reproduces the run's `gas_work` to 1e-9: the trace's rows are the run's rows, so its linear
///   interpolation is evaluated at its own nodes; only the round-off of degrees ↔ radians and of
///   F/A·A remains (1e-15 per row, even across the top dead centre's jump of 3 MPa over 0.1°).
/// - The trace of `cylinder_pressure_pa` (the absolute gas pressure) does not: the Karhula
///   models put no force on their open strokes, where that column reads the ambient pressure,
///   and the trace puts p·A on every stroke. A pump's cycle has one open stroke (90° → 270°, the
///   intake), so its `gas_work` is short by the ambient's work there, p_amb·A_pis·stroke
///   (137.5 J of 701.7 J), to 1e-5: the run's trapezoids take half a row of the jump at each
///   dead centre, (1 + λ)·r·Δθ²/2 = 1.3e-7 m of the stroke's 0.12 m.
#[test]
fn a_runs_own_pressure_column_fed_back_as_a_trace() {
    let dir = tempfile::tempdir().unwrap();
    let steps = 3600;
    let karhula = "model = \"karhula_pump\"\ncompression_ratio = 12\npolytropic_exponent = 1.4\n\
                   filling = 1.07\nambient_pressure = \"101325 Pa\"";
    let write = |name: &str, text: &str| {
        let path = dir.path().join(name);
        std::fs::write(&path, text).unwrap();
        path
    };
    let run = |path: &std::path::Path, out: &str| {
        let case = cardan_case::case::load(path).unwrap_or_else(|e| panic!("{e}"));
        let out = dir.path().join(out);
        std::fs::create_dir_all(&out).unwrap();
        let r = cardan_runner::run_case(&case, Some(&out)).unwrap_or_else(|e| panic!("{e}"));
        r.into_iter()
            .next()
            .unwrap()
            .summary
            .get("gas_work")
            .unwrap()
    };
    let model = run(&write("model.toml", &pump(steps, karhula)), "model");
    let csv = std::fs::read_to_string(dir.path().join("model/slider_crank.csv")).unwrap();
    let angles = column(&csv, "crank_angle_deg");
    let area = 0.25 * PI * 0.12 * 0.12;
    let traced = |name: &str, pressure: &dyn Fn(&str) -> f64| {
        let rows: String = angles
            .iter()
            .zip(column(&csv, name))
            .map(|(a, x)| format!("{a},{}\n", pressure(&x)))
            .collect();
        let file = format!("{name}.csv");
        write(&file, &format!("crank_angle_deg,pressure_pa\n{rows}"));
        let gas = format!("model = \"pressure_trace\"\nfile = \"{file}\"");
        run(&write(&format!("{name}.toml"), &pump(steps, &gas)), name)
    };
    let number = |x: &str| x.parse::<f64>().unwrap();
    let from_force = traced("gas_force_n", &|x| number(x) / area);
    let from_pressure = traced("cylinder_pressure_pa", &|x| number(x));
    let ambient = 101325.0 * area * 0.12;
    println!("gas_work {model} J; traces: of the force {from_force} J, of the pressure {from_pressure} J (+ ambient's {ambient} J)");
    assert!(
        (from_force - model).abs() <= 1e-9 * model,
        "the force's trace: {from_force} J against {model} J"
    );
    assert!(
        (from_pressure + ambient - model).abs() <= 1e-5 * ambient,
        "the pressure's trace: {from_pressure} J + {ambient} J against {model} J"
    );
}
