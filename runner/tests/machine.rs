//! The whole machine through case files (issue 35; `docs/results.md`, the machine's metrics):
//! a machine of one cylinder has the cylinder's figures bit for bit; evenly phased cylinders at
//! constant speed add up; and every cylinder's main-journal and crank-pin loads meet an
//! independent model: each cylinder by the general planar solve at the crank angle and axis
//! its layout gives it (written out here from the layout's definition, not read from the
//! program), the crank's masses added by hand, the journals shared by the statically
//! determinate split. Mechanisms are named only in the case texts.

use cardan_case::case::{parse, Case};
use cardan_dynamics::planar;
use cardan_mechanism::{CrankState, JointKind, Loads, C};
use cardan_runner::memory::run_in_memory;
use cardan_runner::output::MechanismResult;
use cardan_runner::per_step::StepColumns;
use cardan_testing::cases::loaded_thesis_pump;
use cardan_testing::{close, within};
use std::f64::consts::PI;
use std::path::Path;

fn case(text: &str) -> Case {
    parse(Path::new("machine-test.toml"), text).unwrap_or_else(|e| panic!("{e}"))
}

fn metric(r: &MechanismResult, name: &str) -> f64 {
    let m = r.summary.metrics.iter().find(|m| m.name == name);
    m.unwrap_or_else(|| panic!("{}: no {name}", r.label)).value
}

fn has(r: &MechanismResult, name: &str) -> bool {
    r.summary.metrics.iter().any(|m| m.name == name)
}

/// `a` and `b` the same bits.
fn same(what: &str, a: f64, b: f64) {
    assert_eq!(a.to_bits(), b.to_bits(), "{what}: {a} against {b}");
}

/// The thesis engine's cylinder (crank 60 mm, rod 140 mm, bore 120 mm), every mechanism that
/// forms a machine, with the Karhula engine gas over one four-stroke cycle, and `extra`.
fn engine(name: &str, extra: &str) -> String {
    format!(
        r#"
name = "{name}"
machine = "engine"
mechanisms = ["slider_crank", "cardan_gear", "scotch_yoke"]
[geometry]
crank_length = "60 mm"
rod_length = "140 mm"
bore = "120 mm"
[motion]
start_angle = "0 deg"
end_angle = "720 deg"
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
{extra}
"#
    )
}

/// A machine of one cylinder: its machine metrics are the cylinder's own figures, bit for bit
/// (pump and engine, with and without friction, every mechanism), and its per-step machine
/// columns the cylinder's.
#[test]
fn a_machine_of_one_cylinder_has_the_cylinder_s_figures() {
    let pump = loaded_thesis_pump("one-pump")
        .replace(
            "mechanisms = [\"slider_crank\", \"cardan_gear\"]",
            "mechanisms = [\"slider_crank\", \"cardan_gear\", \"scotch_yoke\"]",
        )
        .replace("[gear]\n", "");
    for (text, friction) in [
        (pump.replace("[friction]\n", ""), false),
        (pump, true),
        (engine("one-engine", "[friction]"), true),
        (engine("one-engine-bare", ""), false),
    ] {
        let c = case(&text);
        let engine = text.contains("\"engine\"");
        let run = run_in_memory(&c, true).unwrap();
        for (r, steps) in run.results.iter().zip(&run.steps) {
            let m = |name: &str| metric(r, name);
            same(
                "main journal",
                m("machine_main_bearing_force_max"),
                m("total_main_bearing_force_max"),
            );
            same(
                "crank pin",
                m("machine_crank_pin_force_max"),
                m("total_crank_pin_force_max"),
            );
            if !friction {
                same(
                    "torque mean",
                    m("machine_torque_mean"),
                    m("total_torque_mean"),
                );
                assert!(
                    !has(r, "machine_loss_power_mean") && !has(r, "machine_mechanical_efficiency")
                );
            } else if engine {
                same(
                    "torque mean",
                    m("machine_torque_mean"),
                    -m("output_torque_mean"),
                );
                same(
                    "power mean",
                    m("machine_power_mean"),
                    -m("output_power_mean"),
                );
            } else {
                same(
                    "torque mean",
                    m("machine_torque_mean"),
                    m("torque_need_mean"),
                );
                same("power mean", m("machine_power_mean"), m("power_need_mean"));
            }
            if friction {
                same("loss", m("machine_loss_power_mean"), m("power_loss_mean"));
                same(
                    "efficiency",
                    m("machine_mechanical_efficiency"),
                    m("mechanical_efficiency"),
                );
            }
            let col = |name: &str| {
                steps
                    .get(name)
                    .unwrap_or_else(|| panic!("{}: no {name}", r.label))
            };
            let friction_torque = steps.get("friction_torque_nm");
            for k in 0..steps.rows() {
                let t = col("total_torque_nm")[k] + friction_torque.map_or(0.0, |f| f[k]);
                same("machine torque", col("machine_torque_nm")[k], t);
                for axis in ["x", "y"] {
                    let journal = col(&format!("main_bearing_1_force_{axis}_n"))[k];
                    same(
                        "journal",
                        journal,
                        col(&format!("total_main_bearing_force_{axis}_n"))[k],
                    );
                    let pin = col(&format!("cylinder_1_crank_pin_force_{axis}_n"))[k];
                    same(
                        "pin",
                        pin,
                        col(&format!("total_crank_pin_force_{axis}_n"))[k],
                    );
                }
                same(
                    "gas force",
                    col("cylinder_1_gas_force_n")[k],
                    col("gas_force_n")[k],
                );
            }
            let (lo, hi) = col("machine_torque_nm")
                .iter()
                .fold((f64::MAX, f64::MIN), |(lo, hi), &t| (lo.min(t), hi.max(t)));
            same("torque max", m("machine_torque_max"), hi);
            same("torque min", m("machine_torque_min"), lo);
        }
    }
}

/// Three cylinders of the thesis pump phased 120° apart (a two-stroke inline three, its throws
/// on the 1° grid), at constant speed over a whole pump cycle: the machine's mean torque and
/// mean power are three times the one cylinder's (each cylinder runs the same periodic cycle
/// shifted by whole steps), to 1e-9 (the sums' round-off). Its loss and efficiency to 1e-6: a
/// loss model with a jump (the cardan gear's mesh loss) takes either side of it at a grid point
/// within round-off of it, which moves the trapezoidal integral by up to h·jump/2; measured
/// 3e-8 at 1° for the cardan gear against the one cylinder's own run shifted by a turn
/// (8e-10 at ¼°), 4e-16 for the slider-crank.
#[test]
fn evenly_phased_cylinders_add_up_at_constant_speed() {
    let one = loaded_thesis_pump("pump-one")
        .replace("[gear]\n", "")
        .replace("end_angle = \"810 deg\"", "end_angle = \"450 deg\"")
        .replace("steps = 1441", "steps = 360");
    let three = format!(
        "{}\n[layout]\ncylinders = 3\ncycle = \"two_stroke\"\nfiring_order = [1, 2, 3]\n",
        one.replace("pump-one", "pump-three")
    );
    let one = run_in_memory(&case(&one), false).unwrap();
    let three = run_in_memory(&case(&three), false).unwrap();
    for (a, b) in one.results.iter().zip(&three.results) {
        for (machine, single, tolerance) in [
            ("machine_torque_mean", "torque_need_mean", 1e-9),
            ("machine_power_mean", "power_need_mean", 1e-9),
            ("machine_loss_power_mean", "power_loss_mean", 1e-6),
        ] {
            let what = format!("{}: {machine}", b.label);
            within(
                &what,
                metric(b, machine),
                3.0 * metric(a, single),
                tolerance,
            );
        }
        // Pump: Σ gas work / need, each three times the cylinder's.
        let efficiency = metric(a, "mechanical_efficiency");
        within(
            &b.label,
            metric(b, "machine_mechanical_efficiency"),
            efficiency,
            1e-6,
        );
        assert!(metric(b, "machine_loss_power_mean") > 0.0);
    }
}

/// One cylinder of a layout, written out from its definition (docs/case-file.md, `[layout]`):
/// its throw φ and axis angle β (rad), its throw plane.
struct Place {
    throw: f64,
    axis: f64,
    plane: usize,
}

/// The crank's carried masses (kg·m) as the case gives them: `crank_unbalance`, no
/// counterweight.
const UNBALANCE: f64 = 0.012;

/// Every cylinder's main-bearing and crank-pin loads by the general planar solve at its own
/// crank angle ψ = θ + φ − β, turned into the machine frame by e^{iβ}, the crank's unbalance
/// u·(iα − ω²)·e^{iψ} added to its main bearing; the journals by the split (one plane: one
/// journal; else each plane's load half to each neighbour); compared at every row with the
/// run's columns, to 1e-9 of the peak (the closed forms against the general solve).
fn check_against_general_solve(text: &str, places: &[Place], planes: usize) {
    let c = case(text);
    let run = run_in_memory(&c, true).unwrap();
    for ((r, steps), mechanism) in run.results.iter().zip(&run.steps).zip(&c.mechanisms) {
        let t = mechanism.topology();
        let find = |other: bool| {
            t.joints
                .iter()
                .position(|j| {
                    j.body == t.crankshaft
                        && j.other.is_some() == other
                        && matches!(j.kind, JointKind::Revolute(_))
                })
                .unwrap()
        };
        let (main, pin) = (find(false), find(true));
        let col = |name: &str| {
            steps
                .get(name)
                .unwrap_or_else(|| panic!("{}: no {name}", r.label))
        };
        let journals = if planes == 1 { 1 } else { planes + 1 };
        let mut want = vec![vec![C::new(0.0, 0.0); journals]; steps.rows()];
        let mut pins = vec![vec![C::new(0.0, 0.0); places.len()]; steps.rows()];
        let mut loads = Loads::for_topology(t);
        for k in 0..steps.rows() {
            let theta = col("crank_angle_deg")[k].to_radians();
            let (w, a, time) = (
                col("crank_speed_rad_s")[k],
                col("crank_acceleration_rad_s2")[k],
                col("time_s")[k],
            );
            for (i, p) in places.iter().enumerate() {
                let psi = theta + p.throw - p.axis;
                let state = mechanism.state(&CrankState::new(psi, w, a, time));
                let gas = steps
                    .get(&format!("cylinder_{}_gas_force_n", i + 1))
                    .map_or(0.0, |g| g[k]);
                let forces = vec![gas; t.pistons.len()];
                planar::loads(t, &state, true, &forces, &mut loads);
                let turn = C::from_polar(1.0, p.axis);
                let carried = UNBALANCE * C::new(-w * w, a) * C::from_polar(1.0, psi);
                let f_main = turn * (loads.joints[main].force + carried);
                pins[k][i] = turn * loads.joints[pin].force;
                if planes == 1 {
                    want[k][0] += f_main;
                } else {
                    want[k][p.plane] += 0.5 * f_main;
                    want[k][p.plane + 1] += 0.5 * f_main;
                }
            }
        }
        let check = |what: &str,
                     got: &dyn Fn(usize, usize) -> C,
                     want: &dyn Fn(usize, usize) -> C,
                     count: usize| {
            let peak = (0..steps.rows())
                .flat_map(|k| (0..count).map(move |j| (k, j)))
                .map(|(k, j)| want(k, j).norm())
                .fold(0.0, f64::max);
            assert!(peak > 100.0, "{}: {what} peak {peak}", r.label);
            for k in 0..steps.rows() {
                for j in 0..count {
                    let d = (got(k, j) - want(k, j)).norm();
                    assert!(
                        d <= 1e-9 * peak,
                        "{}: {what} {} at row {k}: {} against {} (peak {peak})",
                        r.label,
                        j + 1,
                        got(k, j),
                        want(k, j)
                    );
                }
            }
        };
        let journal = |k: usize, j: usize| {
            let x = col(&format!("main_bearing_{}_force_x_n", j + 1))[k];
            C::new(x, col(&format!("main_bearing_{}_force_y_n", j + 1))[k])
        };
        check("main journal", &journal, &|k, j| want[k][j], journals);
        let pin_col = |k: usize, i: usize| {
            let x = col(&format!("cylinder_{}_crank_pin_force_x_n", i + 1))[k];
            C::new(
                x,
                col(&format!("cylinder_{}_crank_pin_force_y_n", i + 1))[k],
            )
        };
        check("crank pin", &pin_col, &|k, i| pins[k][i], places.len());
        assert!(
            steps
                .get(&format!("main_bearing_{}_force_x_n", journals + 1))
                .is_none(),
            "{}: one journal too many",
            r.label
        );
        // The peaks: over the journals, and over the pins with every rod on a pin summed.
        let peak_journal = (0..steps.rows())
            .flat_map(|k| want[k].iter().map(|f| f.norm()))
            .fold(0.0, f64::max);
        within(
            &format!("{}: journal peak", r.label),
            metric(r, "machine_main_bearing_force_max"),
            peak_journal,
            1e-9,
        );
    }
}

const ACCELERATING: &str = "angular_acceleration = \"300 rad/s^2\"";

/// A 90° vee twin (both rods on one pin, banks at ∓45°: one throw plane, one journal) of the
/// thesis engine, accelerating, with its gas and its crank unbalance.
#[test]
fn a_vee_twin_meets_the_general_solve() {
    let text = engine(
        "vee-twin",
        &format!("[masses]\ncrank_unbalance = {UNBALANCE}\n[layout]\nkind = \"vee\"\ncylinders = 2\nbank_angle = \"90 deg\"\n"),
    )
    .replace("angular_acceleration = 0.0", ACCELERATING);
    let q = PI / 4.0;
    let places = [
        Place {
            throw: 0.0,
            axis: -q,
            plane: 0,
        },
        Place {
            throw: 0.0,
            axis: q,
            plane: 0,
        },
    ];
    check_against_general_solve(&text, &places, 1);
    // Both rods on the one pin: the pin's peak is that of the two loads summed.
    let run = run_in_memory(&case(&text), true).unwrap();
    for (r, steps) in run.results.iter().zip(&run.steps) {
        let col = |n: &str| steps.get(n).unwrap();
        let peak = (0..steps.rows())
            .map(|k| {
                let x = col("cylinder_1_crank_pin_force_x_n")[k]
                    + col("cylinder_2_crank_pin_force_x_n")[k];
                let y = col("cylinder_1_crank_pin_force_y_n")[k]
                    + col("cylinder_2_crank_pin_force_y_n")[k];
                x.hypot(y)
            })
            .fold(0.0, f64::max);
        within(
            &format!("{}: pin peak", r.label),
            metric(r, "machine_crank_pin_force_max"),
            peak,
            1e-12,
        );
    }
}

/// An inline twin of the thesis engine (four-stroke, throws 0° and 0°... its default: both
/// pins together, firing 360° apart; three journals), accelerating: the journals share each
/// throw's load; and cylinder 2's gas is cylinder 1's a revolution later.
#[test]
fn an_inline_twin_meets_the_general_solve_and_fires_a_revolution_apart() {
    let text = engine(
        "inline-twin",
        &format!("[masses]\ncrank_unbalance = {UNBALANCE}\n[layout]\ncylinders = 2\nfiring_order = [1, 2]\n"),
    );
    let places = [
        Place {
            throw: 0.0,
            axis: 0.0,
            plane: 0,
        },
        Place {
            throw: 0.0,
            axis: 0.0,
            plane: 1,
        },
    ];
    check_against_general_solve(
        &text.replace("angular_acceleration = 0.0", ACCELERATING),
        &places,
        2,
    );
    let run = run_in_memory(&case(&text), true).unwrap();
    for steps in &run.steps {
        let (g1, g2) = (
            steps.get("cylinder_1_gas_force_n").unwrap(),
            steps.get("cylinder_2_gas_force_n").unwrap(),
        );
        // 1440 steps over 720°: a revolution is 720 rows.
        // The same gas-model angle up to the rounding of θ − 4π against the grid's θ − 2π.
        for k in 720..steps.rows() {
            close(
                &format!("gas a revolution later, row {k}"),
                g2[k],
                g1[k - 720],
                1e-12,
                1e-6,
            );
        }
    }
}

/// The per-step machine columns are named once each (pandas finds them by name).
#[test]
fn the_machine_columns_are_named_once() {
    let text = engine("inline-four", "[layout]\ncylinders = 4\n");
    let run = run_in_memory(&case(&text), true).unwrap();
    for steps in &run.steps {
        let StepColumns { names, .. } = steps;
        let mut seen = std::collections::BTreeSet::new();
        for n in names {
            assert!(seen.insert(n), "{n} twice");
        }
        for k in 1..=5 {
            assert!(
                names.contains(&format!("main_bearing_{k}_force_x_n")),
                "journal {k}"
            );
        }
        for k in 1..=4 {
            assert!(
                names.contains(&format!("cylinder_{k}_gas_force_n")),
                "cylinder {k}"
            );
        }
    }
}

/// One definition per machine kind (issue 36): a pump coasting down, no motor and no flywheel
/// (its drive work negative: its bodies' kinetic energy feeds the gas and the losses), is
/// scored as a pump by every mechanism, the cylinder's metrics and the machine's alike: a need,
/// no output, the pump's efficiency where the need is positive (before, the sign of the work
/// chose the engine's formula).
#[test]
fn a_coasting_pump_is_scored_as_a_pump() {
    let text = r#"
name = "coasting-pump"
machine = "pump"
mechanisms = ["slider_crank", "cardan_gear", "scotch_yoke"]
[geometry]
crank_length = "60 mm"
rod_length = "140 mm"
bore = "120 mm"
[motion]
mode = "dynamic"
start_angle = "90 deg"
end_angle = "450 deg"
initial_speed = "200 rad/s"
angular_acceleration = 0.0
steps = 1440
cycles = 1
[gas]
model = "karhula_pump"
compression_ratio = 12
polytropic_exponent = 1.4
[friction]
[load]
torque = "0 N*m"
"#;
    let run = run_in_memory(&case(text), false).unwrap();
    for r in &run.results {
        assert!(
            metric(r, "total_work") < 0.0,
            "{}: the pump coasts",
            r.label
        );
        assert!(
            has(r, "power_need_mean") && !has(r, "output_power_mean"),
            "{}",
            r.label
        );
        same(
            &r.label,
            metric(r, "machine_mechanical_efficiency"),
            metric(r, "mechanical_efficiency"),
        );
        same(
            &r.label,
            metric(r, "machine_power_mean"),
            metric(r, "power_need_mean"),
        );
    }
}
