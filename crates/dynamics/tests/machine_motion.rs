//! The machine motion (Petrescu 2015, docs/validation/machine-motion.md): the reduced inertia
//! of every registered mechanism against the kinetic energy, a finite difference and the
//! inertial drive torque.

mod common;
use cardan_dynamics::{kinetic_energy, ReducedInertiaOf};
use cardan_mechanism::{CrankState, Loads};
use common::*;

/// T = ½·J*·ω² at any speed and acceleration (the kinetic energy of the state's bodies);
/// dJ*/dθ is the central difference of J* to its truncation error; the pistons' lever is
/// Σ dx/dθ; and the inertial drive torque of the closed forms is J*·α + ½·dJ*/dθ·ω²
/// (Petrescu eq. 5), for every registered mechanism and reading.
#[test]
fn reduced_inertia_is_the_kinetic_energy_and_the_inertial_torque() {
    for (name, m) in every_machine() {
        let t = m.topology();
        let mut j = ReducedInertiaOf::new(m.as_ref());
        let mut largest = 0.0_f64;
        for k in 0..97 {
            let theta = 0.3 + k as f64 * 0.0654;
            let r = j.at(theta);
            assert!(r.inertia > 0.0, "{name}: J* = {}", r.inertia);
            largest = largest.max(r.inertia);
            for (w, a) in [(10.0, 0.0), (157.0, -300.0), (0.5, 4000.0)] {
                let s = m.state(&CrankState::new(theta, w, a, 0.0));
                let ke = kinetic_energy(t, &s);
                let expected = 0.5 * r.inertia * w * w;
                assert!(
                    (ke - expected).abs() <= 1e-12 * expected,
                    "{name} at {theta}: T = {ke}, ½J*ω² = {expected}"
                );
                let lever: f64 = s.pistons.iter().map(|p| p.dx_dtheta).sum();
                assert!((lever - r.piston_lever).abs() <= 1e-12 * lever.abs().max(1e-3));
                let mut loads = Loads::for_topology(t);
                if !m.closed_form_loads(&s, true, &[], &mut loads) {
                    cardan_dynamics::planar::loads(t, &s, true, &[], &mut loads);
                }
                let torque = r.inertia * a + 0.5 * r.derivative * w * w;
                let scale = r.inertia * a.abs() + r.derivative.abs() * w * w + 1e-9;
                assert!(
                    (loads.crank_torque - torque).abs() <= 1e-9 * scale,
                    "{name} at {theta}, ω {w}, α {a}: inertial torque {} against J*α + ½J*'ω² {torque}",
                    loads.crank_torque
                );
            }
            // Central difference, error h²/6·J*''' : below 1e-6 of J* at h = 1e-4.
            let h = 1e-4;
            let fd = (j.at(theta + h).inertia - j.at(theta - h).inertia) / (2.0 * h);
            assert!(
                (fd - r.derivative).abs() <= 1e-6 * r.inertia,
                "{name} at {theta}: dJ*/dθ {} against the difference {fd}",
                r.derivative
            );
        }
        assert!(largest > 0.0);
    }
}

use cardan_balance::Phase;
use cardan_dynamics::machine_motion::{
    size_flywheel, solve_cycles, LoadTorque, MachineTorques, SolvedMotion, SolvedRun, Table,
};
use cardan_dynamics::GasAt;
use cardan_mechanism::{Material, MotionSource};
use std::f64::consts::{PI, TAU};

/// A gas-like piston force, N: a compression peak once a revolution.
fn gas_force(theta: f64) -> f64 {
    100.0 * (1.0 + (theta - PI / 2.0).cos()).powi(3)
}

/// The cylinder's (pressure, Pa; piston force, N) of [`gas_force`] on the 0.12 m bore.
fn gas_at(theta: f64) -> (f64, f64) {
    let f = gas_force(theta);
    (1e5 + f / (PI / 4.0 * 0.12 * 0.12), f)
}

fn run(steps: usize, cycles: usize, w0: f64) -> SolvedRun {
    SolvedRun {
        start: PI / 2.0,
        end: PI / 2.0 + TAU,
        steps,
        initial_speed: w0,
        cycles,
        steady_tolerance: None,
    }
}

/// The states of a solved run's reported cycle.
fn states(t: &MachineTorques, r: &SolvedRun) -> Vec<CrankState> {
    let c = solve_cycles(t, r).unwrap();
    let mut m = SolvedMotion::new(t, *r, &c);
    std::iter::from_fn(|| m.next(None))
        .map(Result::unwrap)
        .collect()
}

/// Without load, gas or friction the kinetic energy ½·J*·ω² of every mechanism is conserved:
/// to 1e-6 of itself per cycle at 360 steps a revolution (10 cycles), and at every step of
/// the reported one (the state's kinetic energy, from the bodies).
#[test]
fn a_free_machine_keeps_its_kinetic_energy() {
    let load = LoadTorque::default();
    for (name, m) in every_machine() {
        let t = MachineTorques {
            mechanism: m.as_ref(),
            cylinders: &[Phase::FIRST],
            gas: None,
            load: &load,
            flywheel: 0.0,
            friction: None,
        };
        let r = run(360, 10, 150.0);
        let c = solve_cycles(&t, &r).unwrap();
        for w in c.starts.windows(2) {
            let drift = (w[1].1 * w[1].1 - w[0].1 * w[0].1).abs() / (w[0].1 * w[0].1);
            assert!(
                drift < 1e-6,
                "{name}: kinetic energy drifts {drift} in a cycle"
            );
        }
        let ke0 = kinetic_energy(
            m.topology(),
            &m.state(&CrankState::new(r.start, 150.0, 0.0, 0.0)),
        );
        for s in states(&t, &r) {
            let ke = kinetic_energy(m.topology(), &m.state(&s));
            assert!(
                (ke - ke0).abs() < 1e-5 * ke0,
                "{name} at {}: {ke} against {ke0}",
                s.angle
            );
        }
        assert!(c.speed_max > c.speed_min, "{name}: J* varies, so does ω");
    }
}

/// The RK4 scheme converges at fourth order: the end speed and time of a cycle under gas, a
/// periodic load and a pump law, against a run at 64 times the steps.
#[test]
fn the_scheme_converges_at_fourth_order() {
    let m = thesis("slider_crank", Material::Steel);
    let load = LoadTorque {
        constant: 40.0,
        table: Some(Table {
            start: 0.0,
            points: vec![(0.0, 0.0), (PI, 30.0), (TAU, 0.0)],
        }),
        per_speed: 0.0,
        per_speed_squared: -0.002,
    };
    let t = MachineTorques {
        mechanism: m.as_ref(),
        cylinders: &[Phase::FIRST],
        gas: Some(&gas_at),
        load: &load,
        flywheel: 0.02,
        friction: None,
    };
    let end = |steps| {
        let c = solve_cycles(&t, &run(steps, 2, 120.0)).unwrap();
        (c.start.speed, c.start.time + c.duration)
    };
    let exact = end(24 * 64);
    let errors: Vec<(f64, f64)> = [24, 48, 96]
        .iter()
        .map(|&n| {
            let (w, time) = end(n);
            ((w - exact.0).abs(), (time - exact.1).abs())
        })
        .collect();
    for k in 0..2 {
        for (what, a, b) in [
            ("speed", errors[k].0, errors[k + 1].0),
            ("time", errors[k].1, errors[k + 1].1),
        ] {
            let order = (a / b).log2();
            assert!(order > 3.5, "{what}: order {order} ({a:e} → {b:e})");
        }
    }
}

/// Work of every torque = change of kinetic energy (flywheel included), to the scheme's
/// order: the works by Simpson's rule on the grid (fourth order as well).
#[test]
fn the_torques_work_is_the_change_of_kinetic_energy() {
    let m = thesis("cardan_gear", Material::Steel);
    let load = LoadTorque {
        constant: 25.0,
        per_speed_squared: -0.003,
        ..LoadTorque::default()
    };
    let flywheel = 0.05;
    let t = MachineTorques {
        mechanism: m.as_ref(),
        cylinders: &[Phase::FIRST],
        gas: Some(&gas_at),
        load: &load,
        flywheel,
        friction: None,
    };
    let mismatch = |steps: usize| {
        let mut j = ReducedInertiaOf::new(m.as_ref());
        let mut j2 = ReducedInertiaOf::new(m.as_ref());
        let r = run(steps, 1, 80.0);
        let s = states(&t, &r);
        let mut torque = |c: &CrankState| {
            load.at(c.angle, c.speed) - gas_force(c.angle) * j.at(c.angle).piston_lever
        };
        let h = TAU / steps as f64;
        let work: f64 = s
            .windows(2)
            .step_by(2)
            .zip(s[1..].iter().step_by(2).zip(s[2..].iter().step_by(2)))
            .map(|(w, (mid, last))| h / 3.0 * (torque(&w[0]) + 4.0 * torque(mid) + torque(last)))
            .sum();
        let mut ke = |c: &CrankState| 0.5 * (j2.at(c.angle).inertia + flywheel) * c.speed * c.speed;
        let dke = ke(s.last().unwrap()) - ke(&s[0]);
        ((work - dke) / dke.abs().max(work.abs())).abs()
    };
    let (a, b) = (mismatch(180), mismatch(360));
    assert!(b < 1e-6, "work against ΔKE: {b:e}");
    assert!(
        (a / b).log2() > 3.5,
        "order {} ({a:e} → {b:e})",
        (a / b).log2()
    );
}

/// Driven by the torque a prescribed run needs (the inertial and gas drive torque of the
/// closed forms at the prescribed states, as a fine table), the solved motion is the
/// prescribed one: ω = sqrt(ω0² + 2·α·Δθ) and t to 1e-6.
#[test]
fn the_prescribed_torque_reproduces_the_prescribed_motion() {
    for (name, m) in every_machine() {
        let (w0, alpha) = (90.0, 400.0);
        let prescribed = cardan_mechanism::CrankMotion {
            start_angle: PI / 2.0,
            initial_speed: w0,
            angular_acceleration: alpha,
        };
        let n = 20_000;
        let points: Vec<(f64, f64)> = (0..=n)
            .map(|k| {
                // A period a little longer than the run: the prescribed torque is not periodic.
                let x = (TAU + 0.01) * k as f64 / n as f64;
                let s = m.state(&prescribed.at_angle(PI / 2.0 + x).unwrap());
                let t = m.topology();
                let f = [if m.has_cylinder() {
                    gas_force(PI / 2.0 + x)
                } else {
                    0.0
                }];
                let mut l = Loads::for_topology(t);
                let mut g = Loads::for_topology(t);
                if !m.closed_form_loads(&s, true, &[], &mut l) {
                    cardan_dynamics::planar::loads(t, &s, true, &[], &mut l);
                }
                if !m.closed_form_loads(&s, false, &f, &mut g) {
                    cardan_dynamics::planar::loads(t, &s, false, &f, &mut g);
                }
                (x, l.crank_torque + g.crank_torque)
            })
            .collect();
        // A mechanism whose loads are singular on the grid (the hypotrochoid's folds) has no
        // prescribed torque there to be driven by.
        if points.iter().any(|p| !p.1.is_finite()) {
            continue;
        }
        let load = LoadTorque {
            table: Some(Table {
                start: PI / 2.0,
                points,
            }),
            ..LoadTorque::default()
        };
        let gas: Option<GasAt> = m.has_cylinder().then_some(&gas_at);
        let t = MachineTorques {
            mechanism: m.as_ref(),
            cylinders: &[Phase::FIRST],
            gas,
            load: &load,
            flywheel: 0.0,
            friction: None,
        };
        for s in states(&t, &run(720, 1, w0)) {
            let p = prescribed.at_angle(s.angle).unwrap();
            assert!(
                (s.speed - p.speed).abs() < 1e-6 * p.speed,
                "{name} at {}: ω {} against {}",
                s.angle,
                s.speed,
                p.speed
            );
            assert!(
                (s.time - p.time).abs() < 1e-6 * p.time.max(1e-3),
                "{name}: t {} against {}",
                s.time,
                p.time
            );
            assert!(
                (s.acceleration - alpha).abs() < 1e-3 * alpha,
                "{name}: α {}",
                s.acceleration
            );
        }
    }
}

/// The flywheel problem of docs/validation/machine-motion.md (a three-crank engine, T =
/// 25 − 7.5·sin 3θ kN·m against T_r = 25 + 3.6·sin θ kN·m, I = 360 kg·m², 450 rpm): the
/// fluctuation of energy ΔE = 12.2 kJ = ½·I·(ω_max² − ω_min²) to 1e-3 (the mechanism's own
/// J*, about 1e-5 of I, and the 1° table), Cs = ΔE/(I·ω_m²) = 0.01526 to 2 % (the textbook's
/// linearisation), and the flywheel sized for that Cs is 360 kg·m² to 2 %.
#[test]
fn the_textbook_flywheel_problem_is_reproduced() {
    let m = thesis("slider_crank", Material::Steel);
    let points: Vec<(f64, f64)> = (0..=360)
        .map(|k| {
            let x = (k as f64).to_radians();
            (x, -7_500.0 * (3.0 * x).sin() - 3_600.0 * x.sin())
        })
        .collect();
    let load = LoadTorque {
        table: Some(Table { start: 0.0, points }),
        ..LoadTorque::default()
    };
    let wm = 450.0 * TAU / 60.0;
    let r = SolvedRun {
        start: 0.0,
        end: TAU,
        steps: 720,
        initial_speed: wm * (1.0 + 0.01526 / 2.0),
        cycles: 1,
        steady_tolerance: None,
    };
    let t = MachineTorques {
        mechanism: m.as_ref(),
        cylinders: &[Phase::FIRST],
        gas: None,
        load: &load,
        flywheel: 360.0,
        friction: None,
    };
    let c = solve_cycles(&t, &r).unwrap();
    let de = 0.5 * 360.0 * (c.speed_max.powi(2) - c.speed_min.powi(2));
    assert!((de - 12_200.0).abs() < 1e-3 * 12_200.0, "ΔE {de}");
    let cs = c.fluctuation(&r);
    assert!((cs - 0.01526).abs() < 0.02 * 0.01526, "Cs {cs}");
    assert!(
        (c.speed_mean(&r) - wm).abs() < 0.01 * wm,
        "mean speed {}",
        c.speed_mean(&r)
    );
    let bare = MachineTorques { flywheel: 0.0, ..t };
    let (inertia, met) = size_flywheel(&bare, &r, 0.01526).unwrap();
    assert!(
        (inertia - 360.0).abs() < 0.02 * 360.0,
        "flywheel {inertia} (Cs {met})"
    );
    assert!(met <= 0.01526);
}

/// A load the machine cannot overcome fails naming the step and angle; a run-up from rest
/// needs a positive torque; a zero inertia is refused; never a NaN.
#[test]
fn a_machine_that_stops_fails_with_its_step_and_angle() {
    let m = thesis("slider_crank", Material::Steel);
    let brake = LoadTorque {
        constant: -500.0,
        ..LoadTorque::default()
    };
    let t = MachineTorques {
        mechanism: m.as_ref(),
        cylinders: &[Phase::FIRST],
        gas: None,
        load: &brake,
        flywheel: 0.01,
        friction: None,
    };
    let e = solve_cycles(&t, &run(360, 3, 20.0))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("stops or turns back at step") && e.contains("crank angle"),
        "{e}"
    );
    // Issue 36.15: the sign convention, as a stop may come from a load's sign.
    assert!(
        e.contains("positive in the direction of rotation")
            && e.contains("a load or brake negative"),
        "{e}"
    );
    let e = solve_cycles(&t, &run(360, 3, 0.0)).unwrap_err().to_string();
    assert!(e.contains("cannot start from rest"), "{e}");
    let motor = LoadTorque {
        constant: 30.0,
        per_speed: -0.2,
        ..LoadTorque::default()
    };
    let t = MachineTorques { load: &motor, ..t };
    let c = solve_cycles(&t, &run(360, 40, 0.0)).unwrap();
    assert!(c.speed_min.is_finite() && c.speed_min > 0.0);
    // The motor settles where 30 − 0.2·ω covers nothing but the inertia's ripple: ω ≈ 150.
    assert!(
        (c.speed_mean(&run(360, 40, 0.0)) - 150.0).abs() < 5.0,
        "{}",
        c.speed_mean(&run(360, 40, 0.0))
    );
    assert!(
        c.runup_time().is_some_and(|t| t > 0.0),
        "{:?}",
        c.runup_time()
    );
}

/// The run-up a solved run keeps (`Cycles::runup`, issue 38): from the run's start (t = 0, the
/// start speed) to the reported cycle's start, in time order, every point a row of its cycle
/// (each cycle's rows made apart as the reported cycle of a run of that many cycles), each
/// cycle's start and its smallest and largest row speed among them; bounded by
/// `MAX_RUNUP_POINTS` however many cycles and steps (a long run-up of 3000 cycles).
#[test]
fn the_run_up_is_kept_thinned_from_the_start_to_the_reported_cycle() {
    use cardan_dynamics::runup::MAX_RUNUP_POINTS;
    let m = thesis("slider_crank", Material::Steel);
    let motor = LoadTorque {
        constant: 30.0,
        per_speed: -0.2,
        ..LoadTorque::default()
    };
    let t = MachineTorques {
        mechanism: m.as_ref(),
        cylinders: &[Phase::FIRST],
        gas: None,
        load: &motor,
        flywheel: 0.01,
        friction: None,
    };
    let c = solve_cycles(&t, &run(360, 40, 0.0)).unwrap();
    let up = &c.runup;
    assert_eq!(up[0], (0.0, 0.0), "from rest at t = 0");
    assert_eq!(up.last(), c.starts.last(), "to the reported cycle's start");
    assert!(up.windows(2).all(|w| w[0].0 < w[1].0), "in time order");
    assert!(
        up.len() <= MAX_RUNUP_POINTS && up.len() > 40 * 16,
        "{}",
        up.len()
    );
    for s in &c.starts {
        assert!(up.contains(s), "the cycle start {s:?}");
    }
    for cycle in [0, 1, 7, 38] {
        let rows: Vec<(f64, f64)> = states(&t, &run(360, cycle + 1, 0.0))
            .iter()
            .map(|s| (s.time, s.speed))
            .collect();
        let (from, to) = (c.starts[cycle].0, c.starts[cycle + 1].0);
        let kept: Vec<&(f64, f64)> = up.iter().filter(|p| p.0 >= from && p.0 < to).collect();
        for p in &kept {
            assert!(rows.contains(p), "cycle {cycle}: {p:?} is no row");
        }
        let inner = &rows[..rows.len() - 1];
        for extreme in [
            inner.iter().map(|r| r.1).fold(f64::MAX, f64::min),
            inner.iter().map(|r| r.1).fold(f64::MIN, f64::max),
        ] {
            assert!(
                kept.iter().any(|p| p.1 == extreme),
                "cycle {cycle}: its extreme {extreme} rad/s"
            );
        }
    }
    let long = solve_cycles(&t, &run(16, 3000, 0.0)).unwrap();
    let up = &long.runup;
    assert_eq!(long.starts.len(), 3000);
    assert!(up.len() <= MAX_RUNUP_POINTS, "{}", up.len());
    assert!(up.windows(2).all(|w| w[0].0 < w[1].0));
    assert_eq!((up[0], up.last()), ((0.0, 0.0), long.starts.last()));
}

use cardan_dynamics::machine_friction::MotionFriction;
use cardan_dynamics::{Friction, Gas, Inertial, LoadFamily, LossBudget, Solver};
use cardan_mechanism::Mechanism;

/// The friction torque Σ P/ω (N·m) of `budget` at the crank state `c`, computed apart from the
/// solver: the closed-form loads of the inertia and of [`gas_at`] summed (every mechanism
/// here superposes), the budget evaluated on them.
fn friction_torque(m: &dyn Mechanism, budget: &mut LossBudget, c: &CrankState) -> f64 {
    let t = m.topology();
    let s = m.state(c);
    let (p, f) = gas_at(c.angle);
    let mut total = Loads::for_topology(t);
    let mut gas = Loads::for_topology(t);
    assert!(m.closed_form_loads(&s, true, &[], &mut total));
    assert!(m.closed_form_loads(&s, false, &[f], &mut gas));
    total.add(&gas);
    let mut out = vec![0.0; budget.names().len()];
    budget
        .at_state(m.topology(), (&s, &total), Some(p), &mut out)
        .unwrap();
    out.iter().sum::<f64>() / c.speed
}

/// With friction (Karhula's models: ring pack, Coulomb skirt, rolling bearings, mesh loss),
/// the work of the load, the gas and the friction torque −Σ P/ω (evaluated apart from the
/// solver, on its states) equals the change of kinetic energy, to the scheme's order: the
/// works by Simpson's rule on the grid.
#[test]
fn with_friction_the_torques_work_is_the_change_of_kinetic_energy() {
    let inertial = Inertial::new(Solver::ClosedForm);
    let gas = Gas(Solver::ClosedForm);
    let families: [&dyn LoadFamily; 2] = [&inertial, &gas];
    // Karhula's models; and his bearings alone (smooth: a bearing's load is a vector norm that
    // does not pass through zero), where the scheme keeps its fourth order.
    let mut smooth = Friction::karhula();
    (smooth.rings, smooth.skirt, smooth.gear_mesh) = (None, None, None);
    for (name, friction, order) in [
        ("slider_crank", Friction::karhula(), 0.9),
        ("cardan_gear", Friction::karhula(), 0.9),
        ("slider_crank", smooth.clone(), 3.5),
        ("cardan_gear", smooth, 3.5),
    ] {
        let m = thesis(name, Material::Steel);
        let budget = LossBudget::new(&friction, m.as_ref(), 0.12).unwrap();
        let load = LoadTorque {
            constant: 40.0,
            per_speed_squared: -0.002,
            ..LoadTorque::default()
        };
        let flywheel = 0.05;
        let t = MachineTorques {
            mechanism: m.as_ref(),
            cylinders: &[Phase::FIRST],
            gas: Some(&gas_at),
            load: &load,
            flywheel,
            friction: Some(MotionFriction {
                budget: &budget,
                families: &families,
            }),
        };
        let mismatch = |steps: usize| {
            let mut j = ReducedInertiaOf::new(m.as_ref());
            let mut b = budget.clone();
            let r = run(steps, 1, 80.0);
            let s = states(&t, &r);
            let mut lost = 0.0;
            let mut torque = |c: &CrankState| {
                let f = friction_torque(m.as_ref(), &mut b, c);
                lost += f;
                load.at(c.angle, c.speed) - gas_force(c.angle) * j.at(c.angle).piston_lever - f
            };
            let h = TAU / steps as f64;
            let work: f64 = s
                .windows(2)
                .step_by(2)
                .zip(s[1..].iter().step_by(2).zip(s[2..].iter().step_by(2)))
                .map(|(w, (mid, last))| {
                    h / 3.0 * (torque(&w[0]) + 4.0 * torque(mid) + torque(last))
                })
                .sum();
            let mut j2 = ReducedInertiaOf::new(m.as_ref());
            let mut ke =
                |c: &CrankState| 0.5 * (j2.at(c.angle).inertia + flywheel) * c.speed * c.speed;
            let dke = ke(s.last().unwrap()) - ke(&s[0]);
            let friction_work = lost * h;
            println!("{name} {steps}: work {work} ΔKE {dke} friction ≈ {friction_work}");
            assert!(friction_work > 0.0);
            ((work - dke) / dke.abs().max(work.abs())).abs()
        };
        let (a, b, c) = (mismatch(180), mismatch(360), mismatch(720));
        println!(
            "{name}: {a:e} {b:e} {c:e} orders {} {}",
            (a / b).log2(),
            (b / c).log2()
        );
        assert!(b < 1e-6, "{name}: work against ΔKE: {b:e}");
        for (x, y) in [(a, b), (b, c)] {
            assert!(
                (x / y).log2() > order,
                "{name}: order {} ({x:e} → {y:e})",
                (x / y).log2()
            );
        }
    }
}
