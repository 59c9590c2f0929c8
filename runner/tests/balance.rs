//! Balance through case files (issue 24): the `[masses]`, `[balance]` and `[layout]` tables
//! read, run, and their shaking metrics checked against closed forms
//! (`docs/validation/balance.md`) and published worked examples. Mechanisms are named only in
//! the case texts, as a user writes them.

use cardan_case::case::{parse, Case};
use cardan_runner::output::MechanismResult;
use cardan_runner::run_case;
use cardan_testing::within;
use std::f64::consts::PI;
use std::path::Path;

/// 3000 rpm, rad/s.
const SPEED: f64 = 100.0 * PI;

fn case(text: &str) -> Case {
    parse(Path::new("balance-test.toml"), text).unwrap_or_else(|e| panic!("{e}"))
}

fn refused(text: &str) -> String {
    match parse(Path::new("balance-test.toml"), text) {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(e) => e.to_string(),
    }
}

/// A case of `mechanisms` on the thesis geometry at constant speed [`SPEED`] over one
/// revolution (`steps` steps), with the tables `tables` added.
fn text(mechanisms: &str, steps: usize, tables: &str) -> String {
    format!(
        r#"
name = "balance"
machine = "pump"
mechanisms = [{mechanisms}]
[geometry]
crank_length = 0.06
rod_length = 0.14
bore = 0.12
[motion]
start_angle = 90.0
end_angle = 450.0
initial_speed = {SPEED}
angular_acceleration = 0.0
steps = {steps}
{tables}
"#
    )
}

fn results(text: &str) -> Vec<MechanismResult> {
    run_case(&case(text), None).unwrap_or_else(|e| panic!("{e}"))
}

fn metric(results: &[MechanismResult], label: &str, name: &str) -> f64 {
    let r = results.iter().find(|r| r.label == label).expect(label);
    let m = r.summary.metrics.iter().find(|m| m.name == name);
    m.unwrap_or_else(|| panic!("{label}: no {name}")).value
}

/// q_k(λ) of the slider-crank (order 2 only): the root's series summed exactly, as
/// `crates/balance/tests/common/mod.rs` derives it (`docs/validation/balance.md`).
fn q2(lambda: f64) -> f64 {
    let (mut s, mut c, mut n) = (0.0, 1.0, 0usize);
    // c_n = (−1)ⁿ·binom(1/2, n); the cos 2φ coefficient of sin²ⁿφ is −2·4⁻ⁿ·binom(2n, n−1).
    loop {
        if n >= 1 {
            let binomial = (0..n - 1).fold(1.0, |b, i| b * (2 * n - i) as f64 / (i + 1) as f64);
            let term = c * lambda.powi(2 * n as i32) * 2.0 / 4f64.powi(n as i32) * binomial;
            s += term;
            if term.abs() < 1e-20 {
                break;
            }
        }
        c *= -(0.5 - n as f64) / (n + 1) as f64;
        n += 1;
    }
    4.0 * s.abs() / lambda
}

/// The slider-crank's second order is the exact series m_B·r·ω²·(λ + λ³/4 + …) (m_B is the
/// piston plus rod·g/l, the rod's two-mass split) and the cardan gear has no second or fourth order (1e-9
/// of its first: round-off). Tolerance 1e-9: sums of 360 terms of round-off.
#[test]
fn single_cylinders_have_their_closed_form_orders() {
    let r = results(&text(
        r#""slider_crank", "cardan_gear""#,
        360,
        "[masses]\nrod_mass = 1.2\nrod_cg = 0.05\npiston_mass = 0.8",
    ));
    let (crank, rod) = (0.06, 0.14);
    let m_b = 0.8 + 1.2 * 0.05 / rod;
    let expected = m_b * crank * SPEED * SPEED * q2(crank / rod);
    within(
        "slider-crank order 2, N",
        metric(&r, "slider_crank", "shaking_force_order_2"),
        expected,
        1e-9,
    );
    let first = metric(&r, "cardan_gear", "shaking_force_order_1");
    within(
        "cardan order 1, N",
        first,
        2.0 * 2.0 * 0.03 * SPEED * SPEED,
        1e-9,
    );
    for k in [2, 4] {
        let v = metric(&r, "cardan_gear", &format!("shaking_force_order_{k}"));
        assert!(v < 1e-9 * first, "cardan order {k}: {v} N");
    }
}

/// The cardan counterweight pair, sized from the masses the case gives (the wheel's 0.4 kg,
/// the crank's 0.01 kg·m), leaves no shaking force at any step, at constant speed and
/// accelerating (1e-12 of the unbalanced peak: round-off); its joint loads carry the pair, so
/// its results have no warning about them, and at constant speed its drive needs no inertial
/// torque.
#[test]
fn the_cardan_counterweight_pair_leaves_no_shaking_force() {
    let masses = "[masses.cardan_gear]\nwheel_mass = 0.4\ncrank_unbalance = 0.01";
    for acceleration in [0.0, 2000.0] {
        let with = |balance: &str| {
            let t = text(r#""cardan_gear""#, 720, &format!("{masses}\n{balance}")).replace(
                "angular_acceleration = 0.0",
                &format!("angular_acceleration = {acceleration}"),
            );
            let r = results(&t);
            (metric(&r, "cardan_gear", "shaking_force_max"), r)
        };
        let (bare, r) = with("[balance]");
        assert!(r[0].warnings.is_empty(), "{:?}", r[0].warnings);
        let bare_torque = metric(&r, "cardan_gear", "inertial_torque_max");
        let (balanced, r) = with("[balance]\ncardan_counterweights = true");
        assert!(r[0].warnings.is_empty(), "{:?}", r[0].warnings);
        if acceleration == 0.0 {
            // The pair's wheel counterweight (m₂ = m at ρ = r_c) moves across the cylinder
            // as the rod moves along it: m·(2r_c·ω)²·(cos²θ + sin²θ)/2, a constant kinetic
            // energy (docs/validation/balance.md), so at constant speed the inertial drive
            // torque vanishes (round-off of the unbalanced machine's).
            let torque = metric(&r, "cardan_gear", "inertial_torque_max");
            assert!(bare_torque > 1.0, "unbalanced {bare_torque} N·m");
            assert!(torque < 1e-9 * bare_torque, "{torque} N·m of {bare_torque}");
        }
        assert!(bare > 1000.0, "unbalanced {bare} N");
        assert!(
            balanced < 1e-12 * bare,
            "α = {acceleration}: {balanced} N left of {bare} N"
        );
    }
}

/// Physical check of the pair in the joint loads, through a case file's per-step CSV: with the
/// pair, no gas, at constant speed, the machine shakes the frame with no force, so the frame's
/// two reactions, the main bearing's and the ring gear's (the cardan gear has no cylinder
/// wall force: the gears guide the rod), cancel at every step (1e-9 of the crank pin's peak,
/// which carries kilonewtons). In the thesis's reading the ring takes the rod's force
/// (A5.2.1.48-51), kilonewtons, and the main bearing its opposite. In the involute reading the
/// ring takes nothing at all: the rod's inertia force at T and the wheel counterweight's at Q
/// (mirror points about S, equal masses) have no moment about S at constant speed, since
/// T − Q = 2·(T − S) turns at −ω and its acceleration is −ω² times itself; the main bearing
/// then takes nothing either, the crank pin alone holding the wheel to the crank. Without the
/// pair the two do not cancel (their sum is the shaking force).
#[test]
fn with_the_cardan_pair_the_main_bearing_and_the_ring_cancel() {
    let masses = "[masses.cardan_gear]\nwheel_mass = 0.4\ncrank_unbalance = 0.01";
    for reading in ["karhula", "involute"] {
        let frame_sum = |balance: &str| {
            let t = text(
                r#""cardan_gear""#,
                360,
                &format!(
                    "{masses}\n[cardan_gear]\ngear_mesh_model = \"{reading}\"\n{balance}\n[output]\ncsv = true"
                ),
            );
            let dir = std::env::temp_dir().join(format!("balance-pair-{reading}"));
            let _ = std::fs::remove_dir_all(&dir);
            std::fs::create_dir_all(&dir).unwrap();
            run_case(&case(&t), Some(&dir)).unwrap();
            let csv = std::fs::read_to_string(dir.join("cardan_gear.csv")).unwrap();
            let _ = std::fs::remove_dir_all(&dir);
            let mut lines = csv.lines();
            let header: Vec<&str> = lines.next().unwrap().split(',').collect();
            let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
            let (mut peak, mut worst, mut pin) = (0.0f64, 0.0f64, 0.0f64);
            for line in lines {
                let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
                let force = |joint: &str| {
                    let x = v[col(&format!("inertial_{joint}_force_x_n"))];
                    let y = v[col(&format!("inertial_{joint}_force_y_n"))];
                    (x, y)
                };
                let (main, ring) = (force("main_bearing"), force("gear_mesh"));
                let crank_pin = force("crank_pin");
                pin = pin.max(crank_pin.0.hypot(crank_pin.1));
                peak = peak.max(main.0.hypot(main.1)).max(ring.0.hypot(ring.1));
                worst = worst.max((main.0 + ring.0).hypot(main.1 + ring.1));
            }
            (peak, worst, pin)
        };
        let (peak, worst, pin) = frame_sum("[balance]\ncardan_counterweights = true");
        assert!(pin > 1000.0, "{reading}: the crank pin carries {pin} N");
        assert!(worst <= 1e-9 * pin, "{reading}: {worst} N left of {peak} N");
        if reading == "karhula" {
            assert!(
                peak > 1000.0,
                "{reading}: the frame's joints carry {peak} N"
            );
        } else {
            assert!(
                peak <= 1e-9 * pin,
                "{reading}: the frame's joints carry {peak} N"
            );
        }
        let (peak, worst, _) = frame_sum("");
        assert!(
            worst > 0.1 * peak,
            "{reading}: unbalanced, {worst} N of {peak} N"
        );
    }
}

/// Half the reciprocating mass balanced on a Scotch yoke (a pure first order): the force left
/// turns backwards at constant magnitude m·r·ω²/2, so its largest value over the run is its
/// first order's, which is that.
#[test]
fn a_half_counterweight_leaves_a_first_order_of_constant_magnitude() {
    let r = results(&text(
        r#""scotch_yoke""#,
        360,
        "[masses]\nrod_mass = 2.0\npiston_mass = 0.5\ncrank_unbalance = 0.02\n[balance]\ncounterweight = 0.5",
    ));
    let expected = 2.5 * 0.06 * SPEED * SPEED / 2.0;
    within(
        "peak, N",
        metric(&r, "scotch_yoke", "shaking_force_max"),
        expected,
        1e-9,
    );
    within(
        "order 1, N",
        metric(&r, "scotch_yoke", "shaking_force_order_1"),
        expected,
        1e-9,
    );
}

/// A textbook problem with its printed answer (`docs/validation/balance.md`: 250 rpm, stroke
/// 180 mm, reciprocating 120 kg, revolving 70 kg at the crank, two thirds balanced): the force
/// left 30° from the dead centre is 3.264 kN (4 printed figures: 3e-4). Run as a case: the
/// Scotch yoke (the texts neglect obliquity), its yoke the reciprocating mass, the revolving
/// mass the crank's own unbalance; the run's step at 30° past top dead centre. The same force
/// loads the main bearing.
#[test]
fn a_textbook_single_cylinder_with_two_thirds_balanced() {
    let t = format!(
        r#"
name = "textbook"
machine = "pump"
mechanisms = ["scotch_yoke"]
[geometry]
crank_length = 0.09
rod_length = 0.3
bore = 0.1
[motion]
start_angle = 120.0
end_angle = 480.0
initial_speed = "250 rpm"
angular_acceleration = 0.0
steps = 360
[masses]
rod_mass = "120 kg"
piston_mass = 0.0
crank_unbalance = {}
[balance]
counterweight = {}
[output]
csv = true
"#,
        70.0 * 0.09,
        2.0 / 3.0
    );
    let dir = std::env::temp_dir().join("balance-textbook");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    run_case(&case(&t), Some(&dir)).unwrap();
    let csv = std::fs::read_to_string(dir.join("scotch_yoke.csv")).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let first: Vec<f64> = lines
        .next()
        .unwrap()
        .split(',')
        .map(|x| x.parse().unwrap())
        .collect();
    within(
        "crank angle, deg",
        first[col("crank_angle_deg")],
        120.0,
        1e-12,
    );
    let force = first[col("shaking_force_x_n")].hypot(first[col("shaking_force_y_n")]);
    within("residual force at 30°, N", force, 3264.0, 3e-4);
    // The frame takes that force at the main bearing alone (the yoke's slide carries nothing
    // across the axis at constant speed without gas): the crankshaft's unbalance and its
    // counterweight turn with it and load the main bearing (docs/case-file.md, [balance]).
    let main = first[col("inertial_main_bearing_force_x_n")]
        .hypot(first[col("inertial_main_bearing_force_y_n")]);
    within("main bearing load at 30°, N", main, 3264.0, 3e-4);
    let _ = std::fs::remove_dir_all(&dir);
}

/// Layouts of the slider-crank: an inline six has no first or second order force or moment
/// (1e-9 of one cylinder's first order); a flat inline four's second order force is four
/// cylinders' m·r·ω²·q₂ (≈ 4·m·r·ω²·λ); a boxer four has only a second order couple; a
/// three-cylinder radial's first order is (3/2)·m·r·ω²,
/// turning with the crank. One cylinder's first order: m·r·ω², m the reciprocating mass.
#[test]
fn layouts_cancel_what_the_closed_forms_say() {
    let masses = "[masses]\nrod_mass = 0.0\nrod_inertia = 0.0\npiston_mass = 1.0";
    let run = |layout: &str| {
        results(&text(
            r#""slider_crank""#,
            360,
            &format!("{masses}\n{layout}"),
        ))
    };
    let p1 = 0.06 * SPEED * SPEED;
    let six = run("[layout]\nkind = \"inline\"\ncylinders = 6\ncylinder_spacing = 0.1");
    for name in [
        "shaking_force_order_1",
        "shaking_force_order_2",
        "shaking_moment_order_1",
        "shaking_moment_order_2",
    ] {
        let v = metric(&six, "slider_crank", name);
        assert!(v < 1e-9 * p1, "inline six {name}: {v}");
    }
    let four = run("[layout]\ncylinders = 4");
    let lambda = 0.06 / 0.14;
    within(
        "flat four order 2, N",
        metric(&four, "slider_crank", "shaking_force_order_2"),
        4.0 * p1 * q2(lambda),
        1e-9,
    );
    let approx = 4.0 * p1 * lambda;
    let f2 = metric(&four, "slider_crank", "shaking_force_order_2");
    assert!(
        (f2 / approx - 1.0).abs() < lambda * lambda / 4.0 * 1.1,
        "4·m·r·ω²·λ to O(λ²)"
    );
    // The boxer four (throws 0°, 180°, 180°, 0°, opposed pairs): no first or second order
    // force, no first order couple; a second order couple of 2·a·m·r·ω²·q₂ (a = 0.1 m).
    let boxer = run("[layout]\nkind = \"boxer\"\ncylinders = 4\ncylinder_spacing = 0.1");
    for name in [
        "shaking_force_order_1",
        "shaking_force_order_2",
        "shaking_moment_order_1",
    ] {
        let v = metric(&boxer, "slider_crank", name);
        assert!(v < 1e-9 * p1, "boxer four {name}: {v}");
    }
    within(
        "boxer four second order couple, N·m",
        metric(&boxer, "slider_crank", "shaking_moment_order_2"),
        2.0 * 0.1 * p1 * q2(lambda),
        1e-9,
    );
    let radial = run("[layout]\nkind = \"radial\"\ncylinders = 3");
    within(
        "radial order 1, N",
        metric(&radial, "slider_crank", "shaking_force_order_1"),
        1.5 * p1,
        1e-9,
    );
}

/// A four-stroke inline four with gas: the machine's torque is the sum of the four cylinders'
/// each on its own throw and firing phase, so over a cycle its mean is four times one
/// cylinder's (the work of four cylinders), and it is far more even than one cylinder's.
#[test]
fn a_machine_torque_is_the_sum_of_its_cylinders() {
    let engine = |layout: &str| {
        let t = format!(
            r#"
name = "engine"
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
[gas]
model = "karhula_engine"
compression_ratio = 12
polytropic_exponent = 1.4
filling = 1.07
ambient_pressure = "1 atm"
peak_pressure = "8 MPa"
combustion_delay = "9.5 deg"
{layout}
"#
        );
        results(&t)
    };
    let one = engine("");
    let four = engine("[layout]\ncylinders = 4");
    for m in ["slider_crank", "cardan_gear"] {
        let single = metric(&one, m, "torque_nonuniformity");
        let machine = metric(&four, m, "torque_nonuniformity");
        assert!(
            machine < single / 2.0,
            "{m}: {machine} vs one cylinder's {single}"
        );
    }
}

/// Bad `[layout]` and `[balance]` input: a clear error naming the field.
#[test]
fn bad_layouts_and_balance_are_refused_naming_the_field() {
    let with = |tables: &str| refused(&text(r#""slider_crank", "cardan_gear""#, 360, tables));
    let cases = [
        (
            "[layout]\ncylinders = 4\ncrank_angles = [0, 180, 180]",
            "layout.crank_angles",
        ),
        (
            "[layout]\ncylinders = 4\nfiring_order = [1, 3, 3, 2]",
            "layout.firing_order",
        ),
        (
            "[layout]\nkind = \"vee\"\ncylinders = 2\nbank_angle = 190",
            "layout.bank_angle",
        ),
        (
            "[layout]\nkind = \"vee\"\ncylinders = 2\nbank_angle = 0",
            "layout.bank_angle",
        ),
        (
            "[layout]\ncylinders = 2\nbank_angle = 90",
            "layout.bank_angle",
        ),
        (
            "[layout]\ncylinders = 2\ncylinder_axes = [0, 90]",
            "layout.cylinder_axes",
        ),
        (
            "[layout]\ncylinders = 2\naxial_positions = [0, 0.1]",
            "layout.axial_positions",
        ),
        (
            "[layout]\nkind = \"custom\"\ncylinders = 2\naxial_positions = [0]",
            "layout.axial_positions",
        ),
        (
            "[layout]\nkind = \"radial\"\ncylinders = 3\ncylinder_spacing = 0.1",
            "layout.cylinder_spacing",
        ),
        (
            "[layout]\nkind = \"boxer\"\ncylinders = 3",
            "layout.cylinders",
        ),
        (
            "[layout]\ncylinders = 2\nfiring_ordr = [1, 2]",
            "layout.firing_ordr",
        ),
        ("[balance]\ncounterweight = 1.5", "balance.counterweight"),
        ("[balance]\ncounterweight = -0.5", "balance.counterweight"),
        (
            "[balance]\nbalance_shafts = \"lanchaster\"",
            "balance.balance_shafts",
        ),
        (
            "[masses]\ncrank_unbalance = -0.01",
            "masses.crank_unbalance",
        ),
        (
            "[masses.cardan_gear]\nwheel_mass = -1",
            "masses.cardan_gear.wheel_mass",
        ),
        ("[masses]\nwheel_mass = 1", "masses.wheel_mass"),
    ];
    for (tables, field) in cases {
        let e = with(tables);
        assert!(e.contains(field), "{tables}: {e}");
    }
    // The pair in a case of no mechanism with a cardan wheel says which mechanisms it has.
    let e = refused(&text(
        "\"slider_crank\"",
        360,
        "[balance]\ncardan_counterweights = true",
    ));
    assert!(
        e.contains("balance.cardan_counterweights") && e.contains("slider_crank"),
        "{e}"
    );
}

/// `[balance] cardan_counterweights = true` in a case comparing the slider-crank with the
/// cardan gear (issue 35 §4) applies to the mechanism with a cardan wheel, as
/// `[masses.cardan_gear]` does: the cardan gear's results are bit for bit those of a case of
/// the cardan gear alone with the pair (its first order cancelled: 1e-12 of the unbalanced
/// one's, round-off), the slider-crank's those of the case without `[balance]`, with a
/// warning in `summary.json` saying the pair is ignored for it.
#[test]
fn the_cardan_pair_applies_to_the_mechanisms_with_a_cardan_wheel() {
    let masses = "[masses.cardan_gear]\nwheel_mass = 0.4\ncrank_unbalance = 0.01";
    let pair = format!("{masses}\n[balance]\ncardan_counterweights = true");
    let both = case(&text("\"slider_crank\", \"cardan_gear\"", 360, &pair));
    let compared = run_case(&both, None).unwrap_or_else(|e| panic!("{e}"));
    let bits = |r: &[MechanismResult], label: &str| -> Vec<(String, u64)> {
        let r = r.iter().find(|r| r.label == label).expect(label);
        r.summary
            .metrics
            .iter()
            .map(|m| (m.name.clone(), m.value.to_bits()))
            .collect()
    };
    let cardan = results(&text("\"cardan_gear\"", 360, &pair));
    // The slider-crank alone without the cardan gear's table (nothing would read it: refused).
    let slider = results(&text("\"slider_crank\"", 360, "[balance]"));
    assert_eq!(bits(&compared, "cardan_gear"), bits(&cardan, "cardan_gear"));
    assert_eq!(
        bits(&compared, "slider_crank"),
        bits(&slider, "slider_crank")
    );
    let bare = results(&text("\"cardan_gear\"", 360, masses));
    let first = |r: &[MechanismResult]| metric(r, "cardan_gear", "shaking_force_order_1");
    assert!(
        first(&cardan) < 1e-12 * first(&bare),
        "{} of {}",
        first(&cardan),
        first(&bare)
    );
    let summary = cardan_runner::output::summary_json(&both, &compared);
    let warnings = summary["warnings"].as_array().expect("warnings");
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    let w = warnings[0].as_str().unwrap();
    for part in ["slider_crank", "cardan_counterweights", "ignored"] {
        assert!(w.contains(part), "{part}: {w}");
    }
}

/// `summary.json` names the machine its balance metrics are of: the layout's kind, cylinders
/// and devices as the case file gives them (a case without `[layout]`: one inline cylinder, no
/// device, `counterweight` null).
#[test]
fn the_summary_names_the_machine_the_balance_metrics_are_of() {
    let layout = |tables: &str| {
        let c = case(&text("\"slider_crank\"", 36, tables));
        let results = run_case(&c, None).unwrap_or_else(|e| panic!("{e}"));
        cardan_runner::output::summary_json(&c, &results)["layout"].clone()
    };
    assert_eq!(
        layout(""),
        serde_json::json!({"kind": "inline", "cylinders": 1, "counterweight": null,
            "balance_shafts": "none", "cardan_counterweights": false})
    );
    assert_eq!(
        layout(
            "[layout]\nkind = \"vee\"\ncylinders = 4\nbank_angle = \"60 deg\"\n\
             [balance]\ncounterweight = 0.5\nbalance_shafts = \"lanchester\""
        ),
        serde_json::json!({"kind": "vee", "cylinders": 4, "counterweight": 0.5,
            "balance_shafts": "lanchester", "cardan_counterweights": false})
    );
    assert_eq!(
        layout("[layout]\nkind = \"radial\"\ncylinders = 5")["kind"],
        "radial"
    );
}

/// Each cylinder's throw and firing delay, degrees (rounded to 1e-6°).
fn throws_and_delays(c: &Case) -> (Vec<f64>, Vec<f64>) {
    let deg = |x: f64| (x.to_degrees() * 1e6).round() / 1e6;
    let b = &c.balance;
    (
        b.layout.cylinders.iter().map(|c| deg(c.throw)).collect(),
        b.firing_delay.iter().map(|&d| deg(d)).collect(),
    )
}

/// A two-stroke layout without a firing order (issue 35 §1) gets a two-stroke's crank: an inline
/// machine's throws 360°/N apart in the usual firing order (a twin's 0° and 180°, not the
/// four-stroke twin's 0° and 0°; a four's 0°, 90°, 270°, 180° of 1-3-4-2, not 0°, 180°, 180°,
/// 0°), each cylinder firing at its own top dead centre (a two-stroke fires every revolution:
/// delay = −throw mod 360°); a vee's pins those of an inline of half as many cylinders (a 90°
/// vee four fires every 90°, not two cylinders at once). The twin is bit for bit the twin
/// with `firing_order = [1, 2]` written out.
#[test]
fn a_two_stroke_layout_defaults_to_a_two_stroke_crank() {
    let layout = |tables: &str| case(&text("\"slider_crank\", \"cardan_gear\"", 360, tables));
    let twin = "[layout]\ncylinders = 2\ncycle = \"two_stroke\"";
    assert_eq!(
        throws_and_delays(&layout(twin)),
        (vec![0.0, 180.0], vec![0.0, 180.0])
    );
    assert_eq!(
        throws_and_delays(&layout("[layout]\ncylinders = 4\ncycle = \"two_stroke\"")),
        (vec![0.0, 90.0, 270.0, 180.0], vec![0.0, 270.0, 90.0, 180.0])
    );
    assert_eq!(
        throws_and_delays(&layout(
            "[layout]\nkind = \"vee\"\ncylinders = 4\ncycle = \"two_stroke\""
        )),
        (vec![0.0, 0.0, 180.0, 180.0], vec![0.0, 90.0, 180.0, 270.0])
    );
    // The same twin with its firing order written out: the same machine, the same results.
    let explicit = format!("{twin}\nfiring_order = [1, 2]");
    assert_eq!(layout(twin).balance, layout(&explicit).balance);
    let summary = |tables: &str| {
        let c = layout(tables);
        let r = run_case(&c, None).unwrap_or_else(|e| panic!("{e}"));
        cardan_runner::output::summary_json(&c, &r)
    };
    let (default, written) = (summary(twin), summary(&explicit));
    assert_eq!(default.to_string(), written.to_string());
    // Throws 180° apart: the twin's first-order shaking force of the slider-crank's
    // reciprocating masses cancels (with the four-stroke twin's throws it doubles).
    let one = results(&text("\"slider_crank\"", 360, ""));
    let two = results(&text("\"slider_crank\"", 360, twin));
    let first = |r: &[MechanismResult]| metric(r, "slider_crank", "shaking_force_order_1");
    assert!(
        first(&two) < 1e-9 * first(&one),
        "{} vs {}",
        first(&two),
        first(&one)
    );
}

/// The shaking is taken at every step only where a case asks for it (`[layout]` or
/// `[balance]`, an empty `[balance]` will do; CHANGELOG): without, the run writes neither
/// `shaking_force_max` nor `shaking_moment_max` nor the per-step shaking columns, and every
/// other metric and column has the bits of the run that asks (the orders among them); with
/// gas and friction, every registered mechanism that forms a machine.
#[test]
fn the_shaking_at_every_step_only_where_asked() {
    let mechanisms = r#""slider_crank", "cardan_gear", "scotch_yoke""#;
    let tables = |balance: &str| {
        format!(
            "[gas]\nmodel = \"karhula_pump\"\ncompression_ratio = 12\npolytropic_exponent = 1.4\nfilling = 1.07\nambient_pressure = \"1 bar\"\n[friction]\n{balance}\n[output]\ncsv = true\n"
        )
    };
    let run = |balance: &str, folder: &str| {
        let dir = std::env::temp_dir().join(folder);
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let results = run_case(&case(&text(mechanisms, 720, &tables(balance))), Some(&dir))
            .unwrap_or_else(|e| panic!("{e}"));
        (results, dir)
    };
    let (plain, plain_dir) = run("", "balance-not-asked");
    let (asked, asked_dir) = run("[balance]", "balance-asked");
    let peaks = ["shaking_force_max", "shaking_moment_max"];
    let shaking_columns = [
        "shaking_force_x_n",
        "shaking_force_y_n",
        "shaking_moment_pitch_nm",
        "shaking_moment_yaw_nm",
    ];
    for (p, a) in plain.iter().zip(&asked) {
        let names = |r: &MechanismResult| -> Vec<String> {
            r.summary
                .metrics
                .iter()
                .map(|m| m.name.to_string())
                .collect()
        };
        let expected: Vec<String> = names(a)
            .into_iter()
            .filter(|n| !peaks.contains(&n.as_str()))
            .collect();
        assert_eq!(names(p), expected, "{}: the metrics", p.label);
        assert!(
            names(a).iter().any(|n| n == "shaking_force_max"),
            "{}",
            a.label
        );
        assert!(
            expected.iter().any(|n| n == "shaking_force_order_1"),
            "{}",
            p.label
        );
        for m in &p.summary.metrics {
            let v = metric(&asked, &a.label, &m.name);
            assert_eq!(m.value.to_bits(), v.to_bits(), "{}: {}", p.label, m.name);
        }
        let csv =
            |dir: &Path| std::fs::read_to_string(dir.join(format!("{}.csv", p.label))).unwrap();
        let (p_csv, a_csv) = (csv(&plain_dir), csv(&asked_dir));
        let header = |text: &str| -> Vec<String> {
            text.lines()
                .next()
                .unwrap()
                .split(',')
                .map(String::from)
                .collect()
        };
        let (p_head, a_head) = (header(&p_csv), header(&a_csv));
        let kept: Vec<usize> = (0..a_head.len())
            .filter(|&k| !shaking_columns.contains(&a_head[k].as_str()))
            .collect();
        assert_eq!(kept.len() + 4, a_head.len(), "{}: {a_head:?}", a.label);
        let kept_names: Vec<&String> = kept.iter().map(|&k| &a_head[k]).collect();
        assert_eq!(p_head.iter().collect::<Vec<_>>(), kept_names, "{}", p.label);
        for (p_row, a_row) in p_csv.lines().zip(a_csv.lines()).skip(1) {
            let a_cells: Vec<&str> = a_row.split(',').collect();
            let a_kept: Vec<&str> = kept.iter().map(|&k| a_cells[k]).collect();
            assert_eq!(p_row.split(',').collect::<Vec<_>>(), a_kept, "{}", p.label);
        }
    }
    let _ = std::fs::remove_dir_all(&plain_dir);
    let _ = std::fs::remove_dir_all(&asked_dir);
    // A table of peaks no point would have is refused, naming the fix; with [balance] taken.
    let listed = "[output]\nmetrics = [\"shaking_moment_max\"]\n";
    let e = refused(&text(mechanisms, 36, listed));
    assert!(
        e.contains("output.metrics") && e.contains("[layout] or [balance]"),
        "{e}"
    );
    case(&text(mechanisms, 36, &format!("[balance]\n{listed}")));
}
