//! A mechanism over the crank-angle grid, and the cycle summary.

use crate::{kinetic_energy, loads, Loads, MassProperties};
use cardan_mechanism::{CrankState, KinematicState, Mechanism};

/// One step of the cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Step {
    pub kinematics: KinematicState,
    /// Loads from the inertia of the links (Karhula A5.2.1).
    pub inertial: Loads,
    /// Gas force on the piston along the cylinder axis, towards the crankshaft, N, and the
    /// loads it causes in massless links (A6.2.1); `None` without a gas model.
    pub gas: Option<(f64, Loads)>,
}

impl Step {
    /// The summed lossless loads (A7.1): inertial plus gas.
    pub fn total(&self) -> Loads {
        match self.gas {
            Some((_, gas)) => self.inertial + gas,
            None => self.inertial,
        }
    }
}

/// Kinematics and loads at every crank state of `grid`; `piston_forces`, if given, holds the
/// gas force at each grid point (N, towards the crankshaft). The rod point of `mechanism` must
/// be the rod's centre of gravity `masses.rod_cg`.
pub fn run_cycle(
    mechanism: &dyn Mechanism,
    masses: &MassProperties,
    grid: &[CrankState],
    piston_forces: Option<&[f64]>,
) -> Vec<Step> {
    let kind = mechanism.kind();
    grid.iter()
        .enumerate()
        .map(|(k, &crank)| {
            let kinematics = mechanism.state(crank);
            let inertial = loads(kind, &kinematics, masses, 0.0);
            let gas = piston_forces
                .map(|f| (f[k], loads(kind, &kinematics, &MassProperties::NONE, f[k])));
            Step {
                kinematics,
                inertial,
                gas,
            }
        })
        .collect()
}

/// One named scalar result, in SI units.
#[derive(Debug, Clone, PartialEq)]
pub struct Metric {
    pub name: &'static str,
    pub unit: &'static str,
    pub value: f64,
}

/// The cycle summary: metrics in a fixed order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Summary {
    pub metrics: Vec<Metric>,
}

/// Peaks, work and crank-angle-averaged power of one family of loads over the steps.
struct LoadTotals {
    /// Squared peaks: crank pin, main pin, piston pin, piston side, gear mesh, torque.
    peaks: [f64; 6],
    work: f64,
    energy_flow: f64,
}

impl LoadTotals {
    fn of(steps: &[Step], get: impl Fn(&Step) -> Loads) -> Self {
        let mut t = LoadTotals {
            peaks: [0.0; 6],
            work: 0.0,
            energy_flow: 0.0,
        };
        let mut prev: Option<(f64, f64, f64)> = None;
        for s in steps {
            let l = get(s);
            // Squared magnitudes: one square root per metric instead of one per step.
            let squares = [
                l.crank_pin.norm_sqr(),
                l.main_bearing.norm_sqr(),
                l.piston_pin.norm_sqr(),
                l.piston_side.powi(2),
                l.gear_mesh.norm_sqr(),
                l.crank_torque.powi(2),
            ];
            for (p, v) in t.peaks.iter_mut().zip(squares) {
                *p = p.max(v);
            }
            let (angle, speed) = (s.kinematics.crank.angle, s.kinematics.crank.speed);
            // (A5.2.1.37) W = ∫ T dθ and the crank-angle integral of the power T·ω, by the
            // trapezoidal rule on the crank-angle grid.
            if let Some((a0, t0, w0)) = prev {
                let h = 0.5 * (angle - a0);
                t.work += h * (l.crank_torque + t0);
                t.energy_flow += h * (l.crank_torque * speed + t0 * w0);
            }
            prev = Some((angle, l.crank_torque, speed));
        }
        t
    }
}

impl Summary {
    pub fn get(&self, name: &str) -> Option<f64> {
        self.metrics
            .iter()
            .find(|m| m.name == name)
            .map(|m| m.value)
    }

    pub fn push(&mut self, name: &'static str, unit: &'static str, value: f64) {
        self.metrics.push(Metric { name, unit, value });
    }

    /// Peaks, work, mean torque and mean power of one family of loads, under `names` (the six
    /// peaks of [`LoadTotals`], then work, mean torque, mean power; an empty name is left out).
    fn push_loads(&mut self, names: [&'static str; 9], t: &LoadTotals, span: f64) {
        const UNITS: [&str; 6] = ["N", "N", "N", "N", "N", "N*m"];
        for ((name, unit), square) in names.iter().zip(UNITS).zip(t.peaks) {
            if !name.is_empty() {
                self.push(name, unit, square.sqrt());
            }
        }
        self.push(names[6], "J", t.work);
        // (A5.2.1.38)
        self.push(names[7], "N*m", t.work / span);
        // (A5.2.1.39) averaged over the crank angle, as the thesis's tables are; at constant
        // speed this is the time average.
        self.push(names[8], "W", t.energy_flow / span);
    }

    /// The kinematic, inertial and (with a gas model) gas and total metrics of a cycle; see
    /// README.md for their definitions.
    pub fn of_cycle(mechanism: &dyn Mechanism, masses: &MassProperties, steps: &[Step]) -> Self {
        let kind = mechanism.kind();
        let mut kin_peaks = [0.0f64; 6];
        for s in steps {
            let k = &s.kinematics;
            let squares = [
                k.piston.velocity.powi(2),
                k.piston.acceleration.powi(2),
                k.rod.point.velocity.norm_sqr(),
                k.rod.point.acceleration.norm_sqr(),
                k.rod.angular_velocity.powi(2),
                k.rod.angular_acceleration.powi(2),
            ];
            for (p, v) in kin_peaks.iter_mut().zip(squares) {
                *p = p.max(v);
            }
        }
        let (first, last) = (&steps[0], &steps[steps.len() - 1]);
        let span = last.kinematics.crank.angle - first.kinematics.crank.angle;

        let mut m = Summary::default();
        m.push("piston_stroke", "m", mechanism.stroke());
        let kin_names = [
            ("piston_velocity_max", "m/s"),
            ("piston_acceleration_max", "m/s^2"),
            ("rod_cg_velocity_max", "m/s"),
            ("rod_cg_acceleration_max", "m/s^2"),
            ("rod_angular_velocity_max", "rad/s"),
            ("rod_angular_acceleration_max", "rad/s^2"),
        ];
        for ((name, unit), square) in kin_names.into_iter().zip(kin_peaks) {
            m.push(name, unit, square.sqrt());
        }
        m.push_loads(
            [
                "inertial_crank_pin_force_max",
                "inertial_main_pin_force_max",
                "inertial_piston_pin_force_max",
                "inertial_piston_side_force_max",
                "inertial_gear_mesh_force_max",
                "inertial_torque_max",
                "inertial_work",
                "inertial_torque_mean",
                "inertial_power_mean",
            ],
            &LoadTotals::of(steps, |s| s.inertial),
            span,
        );
        let energy = |s: &Step| kinetic_energy(kind, &s.kinematics, masses);
        m.push("kinetic_energy_change", "J", energy(last) - energy(first));
        m.push(
            "cycle_time",
            "s",
            last.kinematics.crank.time - first.kinematics.crank.time,
        );
        if steps.iter().all(|s| s.gas.is_some()) {
            let force = steps
                .iter()
                .map(|s| s.gas.map_or(0.0, |g| g.0.abs()))
                .fold(0.0, f64::max);
            m.push("gas_force_max", "N", force);
            let gas = LoadTotals::of(steps, |s| s.gas.map_or_else(Loads::default, |g| g.1));
            m.push_loads(
                [
                    "",
                    "",
                    "",
                    "",
                    "",
                    "gas_torque_max",
                    "gas_work",
                    "gas_torque_mean",
                    "gas_power_mean",
                ],
                &gas,
                span,
            );
            m.push_loads(
                [
                    "total_crank_pin_force_max",
                    "total_main_pin_force_max",
                    "total_piston_pin_force_max",
                    "total_piston_side_force_max",
                    "total_gear_mesh_force_max",
                    "total_torque_max",
                    "total_work",
                    "total_torque_mean",
                    "total_power_mean",
                ],
                &LoadTotals::of(steps, Step::total),
                span,
            );
        }
        m
    }
}
