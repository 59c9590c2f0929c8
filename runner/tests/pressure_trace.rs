//! The `pressure_trace` gas model against the engine its shipped trace was sampled from.

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
