//! The crank's motion solved from its torques: Petrescu & Petrescu (2015) eq. (5), the
//! Lagrange equation of a one-degree-of-freedom machine,
//!
//! (J*(θ) + J_f)·α + ½·dJ*/dθ·ω² = M_load(θ, ω) − M_gas(θ) − T_f(θ, ω, α),
//!
//! with J* the mechanism's reduced inertia ([`mod@crate::reduced_inertia`]), J_f a flywheel on the
//! crankshaft, M_gas = F_gas·Σ dx/dθ the drive torque the gas asks for, M_load the torque a
//! load or motor applies to the crankshaft, positive in the direction of rotation, and T_f the
//! torque the friction losses take, Σ P_loss/ω ([`mod@crate::machine_friction`]; Petrescu's
//! resisting torque M_r* holds it with the load) (docs/validation/machine-motion.md).
//!
//! **Friction.** The losses depend on the joint loads, and these on α (the inertial loads):
//! the equation is implicit in α. At every evaluation α is the fixed point of
//! α ← (M_load − M_gas − ½·J*'·ω² − T_f(θ, ω, α))/(J* + J_f), from the frictionless α, to
//! 1e-12 of the torques (at most [`FRICTION_ITERATIONS`] iterations: the contraction factor
//! ∂T_f/∂α / J is a friction coefficient times a bearing radius over the crank radius).
//!
//! **Scheme.** The independent variable is the crank angle, on the run's uniform grid of step
//! h, and the state is e = ½·ω²: de/dθ = ω·dω/dθ = dω/dt = α(θ, ω), with no division by ω
//! (a run-up from rest starts at e = 0). It advances by the classical fourth-order Runge-Kutta
//! step (global error O(h⁴), tested). Time follows from dt = dθ/ω by Simpson's rule on the
//! step, ω at its middle from the cubic Hermite interpolant of e (its value and slope at both
//! ends: e_m = (e0 + e1)/2 + h·(α0 − α1)/8, error O(h⁴)); on a step that starts at rest,
//! where 1/ω is not finite, by the constant-acceleration step 2h/(ω0 + ω1).
//!
//! A crank that would stop or turn back (e < 0 at any stage of a step) fails the run naming the
//! step and angle; a total inertia that is not positive fails it too. Every loop is bounded.

use crate::flywheel_sizing::SizingError;
use crate::machine_friction::{FrictionAt, MotionFriction};
use crate::reduced_inertia::ReducedInertiaOf;
use crate::runup::RunUp;
use crate::stage::GasAt;
use cardan_balance::Phase;
use cardan_mechanism::{CrankState, Mechanism, MotionError, MotionSource};
use std::f64::consts::TAU;

/// The torque a load or a motor applies to the crankshaft, N·m, positive in the direction of
/// rotation (a brake, a pump or a driven machine is negative; a motor positive): the sum of a
/// term of the crank angle and terms of the speed.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LoadTorque {
    /// A constant torque, N·m.
    pub constant: f64,
    /// A torque over one period of crank angle: (angle from the period's start, rad; torque,
    /// N·m) sorted, the first at 0, the last at the period (with the first's torque), linear in
    /// between and repeated every period.
    pub table: Option<Table>,
    /// k in k·ω, N·m·s/rad: a motor's falling characteristic (negative).
    pub per_speed: f64,
    /// k in k·ω², N·m·s²/rad²: the fan, pump and propeller law (negative for a load).
    pub per_speed_squared: f64,
}

/// A periodic torque table.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// The crank angle where the table's angle 0 is, rad.
    pub start: f64,
    /// (angle from `start`, rad; torque, N·m), sorted, from 0 to the period.
    pub points: Vec<(f64, f64)>,
}

impl Table {
    /// The table's period, rad.
    pub fn period(&self) -> f64 {
        self.points.last().map_or(TAU, |p| p.0)
    }

    /// The torque at crank angle `angle` (rad), linear between the points.
    pub fn at(&self, angle: f64) -> f64 {
        let p = &self.points;
        let period = self.period();
        let x = (angle - self.start).rem_euclid(period);
        let k = p.partition_point(|q| q.0 <= x).clamp(1, p.len() - 1);
        let ((x0, y0), (x1, y1)) = (p[k - 1], p[k]);
        if x1 == x0 {
            return y1;
        }
        y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    }
}

impl LoadTorque {
    /// The torque at crank angle `angle` (rad) and speed `speed` (rad/s), N·m.
    pub fn at(&self, angle: f64, speed: f64) -> f64 {
        self.constant
            + self.table.as_ref().map_or(0.0, |t| t.at(angle))
            + self.per_speed * speed
            + self.per_speed_squared * speed * speed
    }
}

/// What drives and brakes a machine besides its own mechanism.
#[derive(Clone, Copy)]
pub struct MachineTorques<'a> {
    pub mechanism: &'a dyn Mechanism,
    /// The machine's cylinders on the one crankshaft, each the mechanism at its own crank angle
    /// and gas phase ([`Phase::FIRST`] alone: one cylinder). Their reduced inertias, gas torques
    /// and friction torques add: the machine's J* is Σ J*_i(θ + lead_i) (Petrescu 2015 eq. 1
    /// over every body of the machine, each cylinder's crankshaft body its own throw's).
    pub cylinders: &'a [Phase],
    /// Cylinder 1's (absolute pressure, Pa; gas force on every piston, N, towards the
    /// crankshaft) at a crank angle; cylinder i's is this at θ − its firing delay.
    pub gas: Option<GasAt<'a>>,
    pub load: &'a LoadTorque,
    /// Flywheel inertia on the crankshaft, kg·m².
    pub flywheel: f64,
    /// The friction losses, charged to the crank (`None`: no friction).
    pub friction: Option<MotionFriction<'a>>,
}

/// The most fixed-point iterations of α under friction at one evaluation.
pub const FRICTION_ITERATIONS: usize = 50;

/// Why a solved motion cannot go on.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SolveError {
    #[error(
        "the machine stops or turns back at step {step} (crank angle {angle_deg:.3}°): the \
         load and the gas take more than its kinetic energy ({speed:.4} rad/s there); [load] \
         torques are positive in the direction of rotation: a motor driving the crank forwards is \
         positive, a load or brake negative"
    )]
    Stops {
        step: usize,
        angle_deg: f64,
        speed: f64,
    },
    #[error("the total reduced inertia J* + flywheel is {0} kg·m² at crank angle {1:.3}°: it must be positive")]
    NoInertia(f64, f64),
    #[error("the machine cannot start from rest at crank angle {0:.3}°: its torque there is {1} N·m, not positive")]
    CannotStart(f64, f64),
    #[error("the crank speed is not finite at step {0}")]
    NonFinite(usize),
    #[error("the friction at crank angle {angle_deg:.3}°: {message}")]
    Friction { angle_deg: f64, message: String },
}

/// The right-hand side of the machine equation: α at (θ, ω).
pub struct Acceleration<'a> {
    torques: &'a MachineTorques<'a>,
    inertia: ReducedInertiaOf<'a>,
    friction: Option<FrictionAt<'a>>,
}

impl<'a> Acceleration<'a> {
    pub fn new(torques: &'a MachineTorques<'a>) -> Self {
        Self {
            torques,
            inertia: ReducedInertiaOf::new(torques.mechanism),
            friction: torques
                .friction
                .map(|f| FrictionAt::new(torques.mechanism, torques.gas, f)),
        }
    }

    /// (α, J* + J_f) at crank angle `angle` (rad) and speed `speed` (rad/s).
    pub fn at(&mut self, angle: f64, speed: f64) -> Result<(f64, f64), SolveError> {
        self.at_slope(angle, speed).map(|(a, j, _)| (a, j))
    }

    /// (α, J* + J_f, dJ*/dθ) at crank angle `angle` (rad) and speed `speed` (rad/s).
    pub fn at_slope(&mut self, angle: f64, speed: f64) -> Result<(f64, f64, f64), SolveError> {
        // Summed from zero in the cylinders' order: one cylinder's sums are its own terms, bit
        // for bit.
        let (mut inertia, mut derivative, mut gas) = (0.0, 0.0, 0.0);
        for c in self.torques.cylinders {
            let r = self.inertia.at(angle + c.lead);
            inertia += r.inertia;
            derivative += r.derivative;
            if let Some(f) = self.torques.gas {
                gas += f.at(angle - c.firing_delay).1 * r.piston_lever;
            }
        }
        let j = inertia + self.torques.flywheel;
        if j.is_nan() || j <= 0.0 {
            return Err(SolveError::NoInertia(j, angle.to_degrees()));
        }
        let load = self.torques.load.at(angle, speed);
        let drive = load - gas - 0.5 * derivative * speed * speed;
        let Some(friction) = self.friction.as_mut() else {
            return Ok((drive / j, j, derivative));
        };
        // α = (drive − T_f(α))/j by fixed-point iteration from the frictionless α.
        let failed = |message: String| SolveError::Friction {
            angle_deg: angle.to_degrees(),
            message,
        };
        let scale = load.abs() + gas.abs() + (drive - load + gas).abs();
        let mut alpha = drive / j;
        for _ in 0..FRICTION_ITERATIONS {
            let mut torque = 0.0;
            for c in self.torques.cylinders {
                let at = (angle + c.lead, angle - c.firing_delay);
                torque += friction.torque(at, speed, alpha).map_err(&failed)?;
            }
            let next = (drive - torque) / j;
            if !next.is_finite() {
                return Err(failed(format!("its torque is not finite ({torque} N·m)")));
            }
            if (next - alpha).abs() * j <= 1e-12 * (scale + torque) {
                return Ok((next, j, derivative));
            }
            alpha = next;
        }
        Err(failed(format!(
            "the acceleration it depends on does not settle in {FRICTION_ITERATIONS} iterations \
             (the friction's dependence on the acceleration is not small beside the inertia)"
        )))
    }
}

/// The crank at one grid point of a solved motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Point {
    pub angle: f64,
    /// ½·ω², rad²/s².
    pub energy: f64,
    pub speed: f64,
    pub acceleration: f64,
    pub time: f64,
    /// J* + J_f there, kg·m².
    pub inertia: f64,
    /// dJ*/dθ there, kg·m²/rad.
    pub inertia_slope: f64,
}

/// One RK4 step of the machine equation from `p` over `h` (rad), at step `step` (for errors).
pub fn rk4_step(f: &mut Acceleration, p: &Point, h: f64, step: usize) -> Result<Point, SolveError> {
    let stops = |angle: f64, e: f64| SolveError::Stops {
        step,
        angle_deg: angle.to_degrees(),
        speed: (2.0 * e.max(0.0)).sqrt(),
    };
    let speed = |angle: f64, e: f64| {
        if e < 0.0 {
            Err(stops(angle, e))
        } else {
            Ok((2.0 * e).sqrt())
        }
    };
    let (t0, e0, k1) = (p.angle, p.energy, p.acceleration);
    let k2 = f
        .at(t0 + 0.5 * h, speed(t0 + 0.5 * h, e0 + 0.5 * h * k1)?)?
        .0;
    let k3 = f
        .at(t0 + 0.5 * h, speed(t0 + 0.5 * h, e0 + 0.5 * h * k2)?)?
        .0;
    let k4 = f.at(t0 + h, speed(t0 + h, e0 + h * k3)?)?.0;
    let e1 = e0 + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    let w1 = speed(t0 + h, e1)?;
    if w1 == 0.0 || !w1.is_finite() {
        return Err(if w1.is_finite() {
            stops(t0 + h, e1)
        } else {
            SolveError::NonFinite(step)
        });
    }
    let (a1, j1, dj1) = f.at_slope(t0 + h, w1)?;
    let dt = if p.speed > 0.0 {
        let em = 0.5 * (e0 + e1) + h * (k1 - a1) / 8.0;
        let wm = speed(t0 + 0.5 * h, em)?;
        h / 6.0 * (1.0 / p.speed + 4.0 / wm + 1.0 / w1)
    } else {
        2.0 * h / (p.speed + w1)
    };
    Ok(Point {
        angle: t0 + h,
        energy: e1,
        speed: w1,
        acceleration: a1,
        time: p.time + dt,
        inertia: j1,
        inertia_slope: dj1,
    })
}

/// How a solved run goes: from `initial_speed` (rad/s) at `start` (rad), `cycles` repetitions
/// of the span `start..end` of `steps` steps each, the last one reported.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolvedRun {
    pub start: f64,
    pub end: f64,
    pub steps: usize,
    pub initial_speed: f64,
    pub cycles: usize,
    /// Stop early once a cycle ends within this fraction of its start speed (periodic steady
    /// state); `None`: run every cycle.
    pub steady_tolerance: Option<f64>,
}

/// What the cycles before the reported one found.
#[derive(Debug, Clone, PartialEq)]
pub struct Cycles {
    /// The point where the reported cycle starts.
    pub start: Point,
    /// (time, speed) at the start of every cycle run, the reported one's last.
    pub starts: Vec<(f64, f64)>,
    /// (time s, speed rad/s) through every cycle before the reported one, thinned in bounded
    /// memory ([`RunUp`]: each cycle's start and its buckets' extremes, at most
    /// [`crate::runup::MAX_RUNUP_POINTS`]), ending at the reported cycle's start.
    pub runup: Vec<(f64, f64)>,
    /// The reported cycle's smallest and largest speed, rad/s (between the rows too:
    /// [`hermite_extremes`] of e = ½·ω² on each step), and its duration, s.
    pub speed_min: f64,
    pub speed_max: f64,
    pub duration: f64,
    /// The reported cycle's smallest and largest J* + J_f, kg·m².
    pub inertia_min: f64,
    pub inertia_max: f64,
    /// The reported cycle's smallest and largest kinetic energy ½·(J* + J_f)·ω², J (between
    /// the rows too, as the speeds).
    pub energy_min: f64,
    pub energy_max: f64,
}

impl Cycles {
    /// The reported cycle's time-mean speed, rad/s.
    pub fn speed_mean(&self, run: &SolvedRun) -> f64 {
        (run.end - run.start) / self.duration
    }

    /// (ω_max − ω_min)/ω_mean over the reported cycle.
    pub fn fluctuation(&self, run: &SolvedRun) -> f64 {
        (self.speed_max - self.speed_min) / self.speed_mean(run)
    }

    /// The time from the start to where the cycles' start speeds stay within 1 % of the
    /// reported cycle's, s; `None` after one cycle, or if the last two cycles' starts differ
    /// by more.
    pub fn runup_time(&self) -> Option<f64> {
        let (_, last) = *self.starts.last()?;
        let within = |w: f64| (w - last).abs() <= 0.01 * last;
        let n = self.starts.len();
        if n < 2 || !within(self.starts[n - 2].1) {
            return None;
        }
        let first = (0..n)
            .rev()
            .take_while(|&k| within(self.starts[k].1))
            .last()?;
        Some(self.starts[first].0)
    }
}

/// The smallest and largest values over s ∈ [0, 1] of the cubic Hermite interpolant with the
/// values `y0`, `y1` and the slopes `m0`, `m1` (dy/ds) at its ends (the Hermite basis
/// 2s³ − 3s² + 1, s³ − 2s² + s, −2s³ + 3s², s³ − s²: Burden & Faires, *Numerical Analysis*,
/// §3.5): its ends, and its values where its derivative, the quadratic a·s² + b·s + c with
/// a = 6(y0 − y1) + 3(m0 + m1), b = 6(y1 − y0) − 4·m0 − 2·m1, c = m0, vanishes inside (0, 1)
/// (the roots by the cancellation-free form q = −(b + sign(b)·√(b² − 4ac))/2, s = q/a, c/q).
pub fn hermite_extremes(y0: f64, y1: f64, m0: f64, m1: f64) -> (f64, f64) {
    let y = |s: f64| {
        let (s2, s3) = (s * s, s * s * s);
        (2.0 * s3 - 3.0 * s2 + 1.0) * y0
            + (s3 - 2.0 * s2 + s) * m0
            + (-2.0 * s3 + 3.0 * s2) * y1
            + (s3 - s2) * m1
    };
    let (mut lo, mut hi) = (y0.min(y1), y0.max(y1));
    let a = 6.0 * (y0 - y1) + 3.0 * (m0 + m1);
    let b = 6.0 * (y1 - y0) - 4.0 * m0 - 2.0 * m1;
    let c = m0;
    let roots = if a == 0.0 {
        [if b != 0.0 { -c / b } else { f64::NAN }, f64::NAN]
    } else {
        let d = b * b - 4.0 * a * c;
        let q = -0.5 * (b + b.signum() * d.max(0.0).sqrt());
        if d < 0.0 || q == 0.0 {
            [f64::NAN; 2]
        } else {
            [q / a, c / q]
        }
    };
    for s in roots {
        if s > 0.0 && s < 1.0 {
            let v = y(s);
            (lo, hi) = (lo.min(v), hi.max(v));
        }
    }
    (lo, hi)
}

/// The smallest and largest crank speed over the step from `p` to `q` (of `h` rad): those of
/// the cubic Hermite interpolant of e = ½·ω² (the integrator's state, de/dθ = α: its values and
/// slopes h·α at both rows, O(h⁴) as the RK4 step itself; the same interpolant as the step's
/// time), where the net torque changes sign between the rows (ω's extremum) or at the rows.
fn speed_between(p: &Point, q: &Point, h: f64) -> (f64, f64) {
    let (lo, hi) = hermite_extremes(p.energy, q.energy, h * p.acceleration, h * q.acceleration);
    ((2.0 * lo.max(0.0)).sqrt(), (2.0 * hi).sqrt())
}

/// The smallest and largest kinetic energy ½·(J* + J_f)·ω² = (J* + J_f)·e over the step from
/// `p` to `q` (of `h` rad): those of its cubic Hermite interpolant, its slope
/// d((J* + J_f)·e)/dθ = dJ*/dθ·e + (J* + J_f)·α (the net torque on the crank) at both rows.
fn energy_between(p: &Point, q: &Point, h: f64) -> (f64, f64) {
    let slope = |r: &Point| h * (r.inertia_slope * r.energy + r.inertia * r.acceleration);
    hermite_extremes(
        p.inertia * p.energy,
        q.inertia * q.energy,
        slope(p),
        slope(q),
    )
}

/// The first point of `run` under `torques`.
pub fn first_point(f: &mut Acceleration, run: &SolvedRun) -> Result<Point, SolveError> {
    let w = run.initial_speed;
    let (a, j, dj) = f.at_slope(run.start, w)?;
    if w == 0.0 && (a.is_nan() || a <= 0.0) {
        return Err(SolveError::CannotStart(run.start.to_degrees(), a * j));
    }
    Ok(Point {
        angle: run.start,
        energy: 0.5 * w * w,
        speed: w,
        acceleration: a,
        time: 0.0,
        inertia: j,
        inertia_slope: dj,
    })
}

/// Integrates the cycles of `run` before the reported one, and the reported one for its
/// extremes (no state is kept but the thinned run-up, [`RunUp`]: memory does not grow with
/// the steps).
pub fn solve_cycles(torques: &MachineTorques, run: &SolvedRun) -> Result<Cycles, SolveError> {
    let mut f = Acceleration::new(torques);
    let h = (run.end - run.start) / run.steps as f64;
    let span = run.end - run.start;
    let mut p = first_point(&mut f, run)?;
    let mut starts = Vec::new();
    let mut runup = RunUp::new(run.steps);
    let mut cycle = 0;
    loop {
        starts.push((p.time, p.speed));
        runup.start(p.time, p.speed);
        let begin = p;
        let (mut lo, mut hi) = (p.speed, p.speed);
        let (mut jlo, mut jhi) = (p.inertia, p.inertia);
        let (mut elo, mut ehi) = (p.inertia * p.energy, p.inertia * p.energy);
        for k in 0..run.steps {
            let step = cycle * run.steps + k + 1;
            let q = rk4_step(&mut f, &p, h, step)?;
            let (wlo, whi) = speed_between(&p, &q, h);
            (lo, hi) = (lo.min(wlo), hi.max(whi));
            (jlo, jhi) = (jlo.min(q.inertia), jhi.max(q.inertia));
            let (klo, khi) = energy_between(&p, &q, h);
            (elo, ehi) = (elo.min(klo), ehi.max(khi));
            if k + 1 < run.steps {
                runup.row(k + 1, q.time, q.speed);
            }
            p = q;
        }
        // The next cycle starts exactly a span on, as the grid's last point is `end`.
        p.angle = run.start + span;
        let steady = run
            .steady_tolerance
            .is_some_and(|tol| (p.speed - begin.speed).abs() <= tol * begin.speed);
        cycle += 1;
        if cycle == run.cycles || steady {
            return Ok(Cycles {
                start: begin,
                starts,
                runup: runup.finish(),
                speed_min: lo,
                speed_max: hi,
                duration: p.time - begin.time,
                inertia_min: jlo,
                inertia_max: jhi,
                energy_min: elo,
                energy_max: ehi,
            });
        }
        p.angle = run.start;
        if f.friction.is_some() {
            // The friction's acceleration at the grid's own angle, as the run's state is
            // loaded (a loss may jump at a dead centre, where the previous cycle's end angle
            // differs from it by a rounding).
            p.acceleration = f.at(p.angle, p.speed)?.0;
        }
    }
}

/// The flywheel inertia (kg·m²) that brings the reported cycle's coefficient of fluctuation
/// (ω_max − ω_min)/ω_mean down to `target`, to 1e-6 of the inertia, and that coefficient: the
/// case's own flywheel if the machine meets it with it. Found by
/// [`crate::flywheel_sizing::inertia_for`] (the textbook law brackets it, regula falsi closes
/// it); an unreachable target is an error.
pub fn size_flywheel(
    torques: &MachineTorques,
    run: &SolvedRun,
    target: f64,
) -> Result<(f64, f64), SizingError> {
    let cs = |flywheel: f64| {
        let t = MachineTorques {
            flywheel,
            ..*torques
        };
        // A flywheel too small to carry the machine through its cycle (it stops) meets no
        // coefficient: infinitely far from the target.
        match solve_cycles(&t, run) {
            Ok(c) => Ok((c.fluctuation(run), c.inertia_max)),
            Err(SolveError::Stops { .. }) => Ok((f64::INFINITY, 0.0)),
            // A mechanism of no mass without a flywheel: no inertia to carry it at all.
            Err(SolveError::NoInertia(..)) if flywheel == 0.0 => Ok((f64::INFINITY, 0.0)),
            Err(e) => Err(e.to_string()),
        }
    };
    // Where the solve gives no inertia (it stopped): the mechanism's at the start; a
    // mechanism of none, a milligram-metre-squared (1e-6 kg·m², far below any machine's).
    let scale = ReducedInertiaOf::new(torques.mechanism)
        .at(run.start)
        .inertia;
    let scale = if scale > 0.0 { scale } else { 1e-6 };
    crate::flywheel_sizing::inertia_for(cs, torques.flywheel, target, scale)
}

/// The reported cycle of a solved run as a motion source: its `steps + 1` crank states, each
/// made by one RK4 step from the one before (the stepper takes them one at a time and
/// computes the joint loads at their real acceleration).
pub struct SolvedMotion<'a> {
    f: Acceleration<'a>,
    run: SolvedRun,
    next: Option<Point>,
    /// Why the state after the last one given cannot be made.
    pending: Option<SolveError>,
    k: usize,
    /// Steps before the reported cycle (for the errors' step numbers).
    offset: usize,
}

impl<'a> SolvedMotion<'a> {
    /// The reported cycle of `run` under `torques`, from the start `cycles` found.
    pub fn new(torques: &'a MachineTorques<'a>, run: SolvedRun, cycles: &Cycles) -> Self {
        Self {
            f: Acceleration::new(torques),
            offset: (cycles.starts.len() - 1) * run.steps,
            run,
            next: Some(cycles.start),
            pending: None,
            k: 0,
        }
    }
}

impl MotionSource for SolvedMotion<'_> {
    fn len(&self) -> usize {
        self.run.steps + 1
    }

    fn next(&mut self, _: Option<f64>) -> Option<Result<CrankState, MotionError>> {
        if self.k > self.run.steps {
            return None;
        }
        if let Some(e) = self.pending.take() {
            self.k = self.run.steps + 1;
            return Some(Err(MotionError::Solved(e.to_string())));
        }
        let p = self.next?;
        let k = self.k;
        self.k += 1;
        let angle = if k == self.run.steps {
            self.run.end
        } else {
            p.angle
        };
        let mut acceleration = p.acceleration;
        if angle != p.angle && self.f.friction.is_some() {
            // As at a cycle's start (solve_cycles): the acceleration at the grid's last angle.
            match self.f.at(angle, p.speed) {
                Ok((a, _)) => acceleration = a,
                Err(e) => {
                    self.k = self.run.steps + 1;
                    return Some(Err(MotionError::Solved(e.to_string())));
                }
            }
        }
        let state = CrankState::new(angle, p.speed, acceleration, p.time);
        if k < self.run.steps {
            let h = (self.run.end - self.run.start) / self.run.steps as f64;
            match rk4_step(&mut self.f, &p, h, self.offset + k + 1) {
                Ok(q) => self.next = Some(q),
                Err(e) => self.pending = Some(e),
            }
        }
        Some(Ok(state))
    }
}

#[cfg(test)]
mod hermite_tests {
    use super::hermite_extremes;

    /// The Hermite interpolant reproduces cubics: y = s·(1 − s) (values 0, 0; slopes 1, −1) has
    /// its maximum 1/4 at s = 1/2; a cubic with its minimum inside,
    /// y = s³ − s (values 0, 0; slopes −1, 2), minimum −2/(3√3) at s = 1/√3; a monotone one
    /// (slopes of one sign) has its ends only.
    #[test]
    fn the_extremes_of_a_cubic_between_its_ends() {
        let (lo, hi) = hermite_extremes(0.0, 0.0, 1.0, -1.0);
        assert_eq!(lo, 0.0);
        assert!((hi - 0.25).abs() < 1e-15, "{hi}");
        let (lo, hi) = hermite_extremes(0.0, 0.0, -1.0, 2.0);
        assert!((lo + 2.0 / (3.0 * 3f64.sqrt())).abs() < 1e-15, "{lo}");
        assert_eq!(hi, 0.0);
        assert_eq!(hermite_extremes(1.0, 2.0, 1.0, 1.0), (1.0, 2.0));
    }
}
