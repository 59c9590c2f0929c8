//! The solved machine motion through case files (issue 25; docs/validation/machine-motion.md):
//! the textbook flywheel problem of validation-cases.md §9.1 reproduced through `[load]
//! torque_table` and `[flywheel]`, and the friction of `[friction]` among the solved torques
//! (its work closes the energy balance of the summary). Mechanisms are named only in the case
//! texts, as a user writes them.

use cardan_case::case::{parse, Case};
use cardan_runner::output::MechanismResult;
use cardan_runner::run_case;
use std::f64::consts::TAU;
use std::path::Path;

fn case(text: &str) -> Case {
    parse(Path::new("machine-motion-test.toml"), text).unwrap_or_else(|e| panic!("{e}"))
}

fn results(text: &str) -> Vec<MechanismResult> {
    run_case(&case(text), None).unwrap_or_else(|e| panic!("{e}"))
}

fn metric(r: &MechanismResult, name: &str) -> f64 {
    let m = r.summary.metrics.iter().find(|m| m.name == name);
    m.unwrap_or_else(|| panic!("{}: no {name}", r.label)).value
}

/// The flywheel problem (validation-cases.md §9.1): T = 25 − 7.5·sin 3θ kN·m against
/// T_r = 25 + 3.6·sin θ kN·m, as the net torque −7.5·sin 3θ − 3.6·sin θ kN·m in a 1° table
/// (`[load] torque_table`, 361 points), on a slider-crank of no mass (it adds no inertia and no
/// torque) and a flywheel table `flywheel`; from ω_max = ω_m + ΔE/(2·I·ω_m) = 47.4836 rad/s at
/// θ = 0 (where the excess energy is largest), so that (ω_max + ω_min)/2 is the book's 450 rpm.
fn flywheel_problem(flywheel: &str) -> String {
    let table: Vec<String> = (0..=360)
        .map(|k| {
            let x = (k as f64).to_radians();
            let t = -7.5 * (3.0 * x).sin() - 3.6 * x.sin();
            format!("[{k}, \"{t:.9} kN*m\"]")
        })
        .collect();
    format!(
        r#"
name = "flywheel-problem"
machine = "pump"
mechanisms = ["slider_crank"]
[geometry]
crank_length = 0.06
rod_length = 0.14
bore = 0.12
[motion]
mode = "dynamic"
start_angle = 0.0
end_angle = 360.0
initial_speed = "47.4836 rad/s"
angular_acceleration = 0.0
steps = 720
[masses]
crankshaft_inertia = 0.0
rod_mass = 0.0
rod_inertia = 0.0
piston_mass = 0.0
crank_unbalance = 0.0
[load]
torque_table = [{}]
[flywheel]
{flywheel}
"#,
        table.join(", ")
    )
}

/// The fluctuation of energy, kJ (validation-cases.md §9.1: 2.5·cos 3θ + 3.6·cos θ between
/// θ = 0 and π), the mean speed of 450 rpm (rad/s), and the book's linearised coefficient
/// ΔE/(I·ω_m²) at I = 360 kg·m².
const DELTA_E: f64 = 12.2e3;
const MEAN_SPEED: f64 = 450.0 * TAU / 60.0;
const INERTIA: f64 = 360.0;

/// Through the case file: ΔE = 12.2 kJ (the summary's kinetic_energy_fluctuation, and
/// ½·I·(ω_max² − ω_min²) from its speeds) to 1e-3 (the 1° table's linear interpolation of
/// sin 3θ: (3h)²/12 ≈ 2.3e-4 of the energy); the linear coefficient ΔE/(I·ω_m²) = 0.01526 the
/// summary reports beside the solved one, each to 1e-3 of the book's (the table, and the solved
/// one's exact (ω_max − ω_min)/ω_mean differing from the linearisation by O(Cs²) ≈ 2e-4); the
/// time mean speed 450 rpm to 1e-3; and the flywheel sized for Cs = 0.01526 is 360 kg·m² to
/// 2e-3 (Cs ∝ 1/I: the same errors, and the sizing's 1e-6).
#[test]
fn the_textbook_flywheel_problem_through_a_case_file() {
    let linear = DELTA_E / (INERTIA * MEAN_SPEED * MEAN_SPEED);
    assert!((linear - 0.01526).abs() < 1e-5, "the book's Cs {linear}");
    let r = &results(&flywheel_problem("inertia = \"360 kg*m^2\""))[0];
    let (lo, hi) = (metric(r, "speed_min"), metric(r, "speed_max"));
    let de = 0.5 * INERTIA * (hi * hi - lo * lo);
    let reported = metric(r, "kinetic_energy_fluctuation");
    let solved = metric(r, "speed_fluctuation_coefficient");
    let linearised = metric(r, "fluctuation_coefficient_linear");
    let mean = metric(r, "speed_mean");
    println!(
        "ΔE {de:.2} J (reported {reported:.2}), Cs solved {solved:.6}, linear {linearised:.6} \
         (book {linear:.6}), mean speed {mean:.5} rad/s, ω {lo:.5}..{hi:.5}"
    );
    for (what, got, want, tol) in [
        ("ΔE from the speeds", de, DELTA_E, 1e-3),
        ("kinetic_energy_fluctuation", reported, DELTA_E, 1e-3),
        ("speed_fluctuation_coefficient", solved, linear, 1e-3),
        ("fluctuation_coefficient_linear", linearised, linear, 1e-3),
        ("speed_mean", mean, MEAN_SPEED, 1e-3),
        (
            "flywheel_inertia",
            metric(r, "flywheel_inertia"),
            INERTIA,
            1e-12,
        ),
    ] {
        assert!(
            (got - want).abs() <= tol * want,
            "{what}: {got} against {want} (tolerance {tol:e})"
        );
    }
    let sized = &results(&flywheel_problem("fluctuation_coefficient = 0.01526"))[0];
    let required = metric(sized, "flywheel_inertia_required");
    println!(
        "flywheel for Cs 0.01526: {required:.3} kg*m^2 (Cs met {})",
        metric(sized, "speed_fluctuation_coefficient")
    );
    assert!(
        (required - INERTIA).abs() <= 2e-3 * INERTIA,
        "flywheel {required} against {INERTIA}"
    );
    assert!(metric(sized, "speed_fluctuation_coefficient") <= 0.01526);
}

/// The shipped run-up of a pump driven by a motor (configs/karhula-pump-motor-runup.toml's
/// tables), here over `cycles` cycles, with `friction` (a `[friction]` table or nothing).
fn pump(cycles: usize, motor: &str, friction: &str) -> String {
    format!(
        r#"
name = "pump-friction"
machine = "pump"
mechanisms = ["slider_crank", "cardan_gear"]
[geometry]
crank_length = 0.06
rod_length = 0.14
bore = 0.12
[motion]
mode = "dynamic"
start_angle = 90.0
end_angle = 810.0
initial_speed = 0.0
angular_acceleration = 0.0
steps = 720
cycles = {cycles}
[masses.slider_crank]
rod_inertia = 0.0167
[gas]
model = "karhula_pump"
compression_ratio = 12
polytropic_exponent = 1.4
filling = 1.07
ambient_pressure = "101325 Pa"
[load]
{motor}
[flywheel]
inertia = "2 kg*m^2"
{friction}
"#
    )
}

const MOTOR: &str = "torque = \"223.4 N*m\"\ntorque_per_speed = -1.1851";

/// `[friction]` on a solved motion is accepted and its torque is among the motion's: the pump
/// (Coulomb losses at their limit at vanishing speed from rest) runs slower than without
/// friction, and at every step of the reported cycle the per-step columns, computed by the
/// run from the solved state apart from the solver (the joint loads' drive torque, the loss
/// budget's friction torque Σ P/ω), meet the machine equation: total_torque +
/// friction_torque + J_f·α = the motor's 223.4 − 1.1851·ω N·m, to 1e-9 of the torques (the solver's fixed
/// point in α is converged to 1e-12 of them). The losses the summary reports are thus those of
/// the solved motion; their work (loss_work, ∫P dt) is ∫T_f dθ to 1e-4 (trapezoidal rules).
#[test]
fn friction_is_among_the_solved_torques() {
    let friction = "[friction]\nrings = \"karhula\"";
    let bare = results(&pump(3, MOTOR, ""));
    let run = cardan_runner::memory::run_in_memory(&case(&pump(3, MOTOR, friction)), true)
        .unwrap_or_else(|e| panic!("{e}"));
    for ((b, f), steps) in bare.iter().zip(&run.results).zip(&run.steps) {
        let (wb, wf) = (metric(b, "speed_mean"), metric(f, "speed_mean"));
        let lost = metric(f, "loss_work");
        println!(
            "{}: ω_mean {wb:.4} rad/s without friction, {wf:.4} with; loss_work {lost:.3} J",
            f.label
        );
        assert!(wf < wb, "{}: friction does not slow the machine", f.label);
        let column = |name: &str| steps.get(name).unwrap_or_else(|| panic!("no {name}"));
        let (w, a) = (
            column("crank_speed_rad_s"),
            column("crank_acceleration_rad_s2"),
        );
        let (drive, friction) = (column("total_torque_nm"), column("friction_torque_nm"));
        let angle = column("crank_angle_deg");
        let mut work = 0.0;
        for k in 0..w.len() {
            let motor = 223.4 - 1.1851 * w[k];
            let got = drive[k] + friction[k] + 2.0 * a[k];
            let scale = motor.abs() + drive[k].abs() + friction[k] + (2.0 * a[k]).abs();
            assert!(
                (got - motor).abs() <= 1e-9 * scale,
                "{} step {k}: {got} against the motor's {motor} N·m",
                f.label
            );
            assert!(friction[k] > 0.0, "{} step {k}: no friction", f.label);
            if k > 0 {
                let h = (angle[k] - angle[k - 1]).to_radians();
                work += 0.5 * h * (friction[k] + friction[k - 1]);
            }
        }
        assert!(
            (work - lost).abs() <= 1e-4 * lost,
            "{}: ∫T_f dθ {work} J against loss_work {lost} J",
            f.label
        );
    }
}

/// A loss that carries its history from step to step (the ring films' squeeze term) has no
/// value at the solved motion's Runge-Kutta stages: refused on reading, naming the field (so
/// `cardan check` refuses it as `cardan run` would); Karhula's ring pack is taken.
#[test]
fn ring_films_are_refused_with_a_solved_motion() {
    let text = pump(1, MOTOR, "[friction]\nrings = \"film\"");
    let e = match parse(Path::new("machine-motion-test.toml"), &text) {
        Ok(_) => panic!("ring films accepted with a solved motion"),
        Err(e) => e.to_string(),
    };
    assert!(e.contains("friction.rings") && e.contains("dynamic"), "{e}");
    case(&pump(1, MOTOR, "[friction]\nrings = \"karhula\""));
}

/// From rest, a Coulomb loss takes its limit torque (the breakaway torque): a motor of 0.01 N·m
/// starts the frictionless pump at top dead centre (no gas lever, no inertial torque at rest)
/// but not the one with friction (its bearings carry the compressed gas's force there), which
/// fails naming the start.
#[test]
fn friction_holds_a_weak_motor_at_rest() {
    let weak = "torque = \"0.01 N*m\"";
    let message = |text: &str| match run_case(&case(text), None) {
        Ok(_) => String::new(),
        Err(e) => e,
    };
    let bare = message(&pump(1, weak, ""));
    assert!(!bare.contains("cannot start from rest"), "{bare}");
    let held = message(&pump(1, weak, "[friction]\nrings = \"karhula\""));
    assert!(held.contains("cannot start from rest"), "{held}");
}

/// Several cylinders on a solved motion: the pump as an inline three, two-stroke (a cylinder
/// fires every 120°), run up by a motor three times the single pump's. At every step of the
/// reported cycle the machine's drive torque that the run computes apart from the solver, at
/// the solved state (`machine_torque_nm`: each cylinder by the general planar solve at its own
/// crank angle, speed, acceleration and gas phase, `cardan_dynamics::MachineStage`), and the
/// flywheel's J_f·α meet the motor's torque: the solver's Σ J*_i, Σ dJ*_i/dθ and Σ gas lever of
/// the cylinders (`machine_motion::Acceleration`) are the machine's, to 1e-9 of the torques.
/// Three cylinders 120° apart even out the pump's torque: their speed fluctuates less than one
/// cylinder's under a third of the motor.
#[test]
fn several_cylinders_are_solved_as_one_machine() {
    let motor = "torque = \"670.2 N*m\"\ntorque_per_speed = -3.5553";
    let layout = "[layout]\nkind = \"inline\"\ncylinders = 3\ncycle = \"two_stroke\"";
    let text = pump(3, motor, layout);
    let run =
        cardan_runner::memory::run_in_memory(&case(&text), true).unwrap_or_else(|e| panic!("{e}"));
    let single = results(&pump(3, MOTOR, ""));
    for ((r, steps), one) in run.results.iter().zip(&run.steps).zip(&single) {
        let column = |name: &str| steps.get(name).unwrap_or_else(|| panic!("no {name}"));
        let (w, a) = (
            column("crank_speed_rad_s"),
            column("crank_acceleration_rad_s2"),
        );
        let machine = column("machine_torque_nm");
        let cylinder = column("total_torque_nm");
        let mut differs = 0.0f64;
        for k in 0..w.len() {
            let motor = 670.2 - 3.5553 * w[k];
            let got = machine[k] + 2.0 * a[k];
            let scale = motor.abs() + machine[k].abs() + (2.0 * a[k]).abs();
            assert!(
                (got - motor).abs() <= 1e-9 * scale,
                "{} step {k}: {got} against the motor's {motor} N·m",
                r.label
            );
            differs = differs.max((machine[k] - cylinder[k]).abs());
        }
        assert!(
            differs > 1.0,
            "{}: the other cylinders add nothing",
            r.label
        );
        let (three, alone) = (
            metric(r, "speed_fluctuation_coefficient"),
            metric(one, "speed_fluctuation_coefficient"),
        );
        println!(
            "{}: Cs {three:.5} with three cylinders, {alone:.5} with one",
            r.label
        );
        assert!(three < alone, "{}: {three} against {alone}", r.label);
    }
}

/// A periodic torque table closes within 1e-9 of its largest torque (issue 35 §4): the
/// round-off a table computed from a periodic function leaves at its end (−1.7e-13 N·m where
/// 0 was meant, against 400 N·m) is accepted and runs as the exact table, bit for bit (the
/// last torque is taken as the first's); a mismatch of 1e-3 N·m (2.5e-6 of the largest) is
/// refused naming the point, the first's torque and the tolerance.
#[test]
fn a_torque_table_closes_within_its_stated_tolerance() {
    let with = |last: &str| {
        let load = format!("{MOTOR}\ntorque_table = [[90, 0], [270, \"400 N*m\"], [450, {last}]]");
        pump(1, &load, "")
    };
    let values = |text: &str| -> Vec<(String, u64)> {
        let r = results(text);
        r.iter()
            .flat_map(|r| r.summary.metrics.iter())
            .map(|m| (m.name.clone(), m.value.to_bits()))
            .collect()
    };
    assert_eq!(values(&with("-1.7e-13")), values(&with("0")));
    let e = match parse(
        Path::new("machine-motion-test.toml"),
        &with("\"-1e-3 N*m\""),
    ) {
        Ok(_) => panic!("a table 1e-3 N*m from periodic accepted"),
        Err(e) => e.to_string(),
    };
    for part in [
        "load.torque_table[2]",
        "-1e-3 N*m",
        "first's torque (0)",
        "1e-9",
        "400",
    ] {
        assert!(e.contains(part), "{part}: {e}");
    }
}

/// The shipped pump under its motor (configs/karhula-pump-motor-dynamic.toml) on `steps` steps
/// a cycle, three cycles.
fn pump_motor(steps: usize) -> String {
    pump(3, MOTOR, "")
        .replace("initial_speed = 0.0", "initial_speed = 94.24777960769379")
        .replace("steps = 720", &format!("steps = {steps}"))
        .replace("inertia = \"2 kg*m^2\"", "inertia = \"0.2 kg*m^2\"")
}

/// The speed extremes of a solved motion lie between the rows (issue 35 §4): speed_min,
/// speed_max and the coefficient of fluctuation δ are the extremes of the solution, the cubic
/// Hermite interpolant of ½·ω² on each step (its values and slopes α at both rows, O(h⁴) as
/// the RK4 step), not the rows' (whose extremes miss the true ones by up to half a step in
/// angle: O(h²) low). On 720 steps a cycle the pump's δ is within a tenth of the rows' error of
/// the δ of 11 520 steps, and never below the rows' (the rows are among the points it takes).
#[test]
fn the_speed_extremes_are_taken_between_the_rows() {
    let fine = results(&pump_motor(11520));
    let coarse = cardan_runner::memory::run_in_memory(&case(&pump_motor(720)), true)
        .unwrap_or_else(|e| panic!("{e}"));
    for ((f, c), steps) in fine.iter().zip(&coarse.results).zip(&coarse.steps) {
        let w = steps.get("crank_speed_rad_s").expect("crank_speed_rad_s");
        let (lo, hi) = w.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), &w| {
            (lo.min(w), hi.max(w))
        });
        let rows = (hi - lo) / metric(c, "speed_mean");
        let (between, truth) = (
            metric(c, "speed_fluctuation_coefficient"),
            metric(f, "speed_fluctuation_coefficient"),
        );
        println!(
            "{}: δ rows {rows:.9}, between {between:.9}, 11520 steps {truth:.9}",
            c.label
        );
        assert!(
            between >= rows,
            "{}: {between} below the rows' {rows}",
            c.label
        );
        assert!(
            (between - truth).abs() <= 0.1 * (rows - truth).abs(),
            "{}: δ {between} against {truth} (the rows' {rows})",
            c.label
        );
    }
}
