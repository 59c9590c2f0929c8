//! A mechanism over the crank-angle grid, and the cycle summary.

use crate::{kinetic_energy, loads, Loads, MassProperties};
use cardan_mechanism::{CrankState, KinematicState, Mechanism};

/// One step of the cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Step {
    pub kinematics: KinematicState,
    pub loads: Loads,
}

/// Kinematics and inertial loads (plus `piston_force(step index)`, the applied gas force, N)
/// at every crank state of `grid`. The rod point of `mechanism` must be the rod's centre of
/// gravity `masses.rod_cg`.
pub fn run_cycle(
    mechanism: &dyn Mechanism,
    masses: &MassProperties,
    grid: &[CrankState],
    piston_force: impl Fn(usize) -> f64,
) -> Vec<Step> {
    let kind = mechanism.kind();
    grid.iter()
        .enumerate()
        .map(|(k, &crank)| {
            let kinematics = mechanism.state(crank);
            Step {
                kinematics,
                loads: loads(kind, &kinematics, masses, piston_force(k)),
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

impl Summary {
    pub fn get(&self, name: &str) -> Option<f64> {
        self.metrics
            .iter()
            .find(|m| m.name == name)
            .map(|m| m.value)
    }

    fn push(&mut self, name: &'static str, unit: &'static str, value: f64) {
        self.metrics.push(Metric { name, unit, value });
    }

    /// The kinematic and inertial metrics of a cycle (see README.md for their definitions),
    /// in one pass over the steps.
    pub fn of_cycle(mechanism: &dyn Mechanism, masses: &MassProperties, steps: &[Step]) -> Self {
        const PEAKS: [(&str, &str); 12] = [
            ("piston_velocity_max", "m/s"),
            ("piston_acceleration_max", "m/s^2"),
            ("rod_cg_velocity_max", "m/s"),
            ("rod_cg_acceleration_max", "m/s^2"),
            ("rod_angular_velocity_max", "rad/s"),
            ("rod_angular_acceleration_max", "rad/s^2"),
            ("inertial_crank_pin_force_max", "N"),
            ("inertial_main_pin_force_max", "N"),
            ("inertial_piston_pin_force_max", "N"),
            ("inertial_piston_side_force_max", "N"),
            ("inertial_gear_mesh_force_max", "N"),
            ("inertial_torque_max", "N*m"),
        ];
        let kind = mechanism.kind();
        let mut peak = [0.0f64; 12];
        // (A5.2.1.37) W = ∫ T dθ and the crank-angle integral of the power T·ω, by the
        // trapezoidal rule on the crank-angle grid.
        let (mut work, mut energy_flow) = (0.0, 0.0);
        for (k, s) in steps.iter().enumerate() {
            let (kin, l) = (&s.kinematics, &s.loads);
            // Squared magnitudes: one square root per metric instead of one per step.
            let squares = [
                kin.piston.velocity.powi(2),
                kin.piston.acceleration.powi(2),
                kin.rod.point.velocity.norm_sqr(),
                kin.rod.point.acceleration.norm_sqr(),
                kin.rod.angular_velocity.powi(2),
                kin.rod.angular_acceleration.powi(2),
                l.crank_pin.norm_sqr(),
                l.main_bearing.norm_sqr(),
                l.piston_pin.norm_sqr(),
                l.piston_side.powi(2),
                l.gear_mesh.norm_sqr(),
                l.crank_torque.powi(2),
            ];
            for (p, v) in peak.iter_mut().zip(squares) {
                *p = p.max(v);
            }
            if k > 0 {
                let prev = &steps[k - 1];
                let h = 0.5 * (kin.crank.angle - prev.kinematics.crank.angle);
                work += h * (l.crank_torque + prev.loads.crank_torque);
                energy_flow += h
                    * (l.crank_torque * kin.crank.speed
                        + prev.loads.crank_torque * prev.kinematics.crank.speed);
            }
        }
        let (first, last) = (&steps[0], &steps[steps.len() - 1]);
        let span = last.kinematics.crank.angle - first.kinematics.crank.angle;

        let mut m = Summary::default();
        m.push("piston_stroke", "m", mechanism.stroke());
        for ((name, unit), square) in PEAKS.iter().zip(peak) {
            m.push(name, unit, square.sqrt());
        }
        m.push("inertial_work", "J", work);
        m.push("inertial_torque_mean", "N*m", work / span); // (A5.2.1.38)
                                                            // (A5.2.1.39) averaged over the crank angle, as the thesis's tables are; at constant
                                                            // speed this is the time average.
        m.push("inertial_power_mean", "W", energy_flow / span);
        let energy = |s: &Step| kinetic_energy(kind, &s.kinematics, masses);
        m.push("kinetic_energy_change", "J", energy(last) - energy(first));
        m.push(
            "cycle_time",
            "s",
            last.kinematics.crank.time - first.kinematics.crank.time,
        );
        m
    }
}
