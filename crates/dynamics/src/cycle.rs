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
            Step { kinematics, loads: loads(kind, &kinematics, masses, piston_force(k)) }
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
        self.metrics.iter().find(|m| m.name == name).map(|m| m.value)
    }

    fn push(&mut self, name: &'static str, unit: &'static str, value: f64) {
        self.metrics.push(Metric { name, unit, value });
    }

    /// The kinematic and inertial metrics of a cycle (see README.md for their definitions).
    pub fn of_cycle(mechanism: &dyn Mechanism, masses: &MassProperties, steps: &[Step]) -> Self {
        let kind = mechanism.kind();
        let max = |f: &dyn Fn(&Step) -> f64| steps.iter().map(|s| f(s).abs()).fold(0.0, f64::max);
        let angle = |s: &Step| s.kinematics.crank.angle;
        let (first, last) = (&steps[0], &steps[steps.len() - 1]);
        let span = angle(last) - angle(first);
        // (A5.2.1.37): W = ∫ T dθ, by the trapezoidal rule on the crank-angle grid.
        let integral = |f: &dyn Fn(&Step) -> f64| {
            steps.windows(2).map(|w| 0.5 * (f(&w[0]) + f(&w[1])) * (angle(&w[1]) - angle(&w[0]))).sum::<f64>()
        };
        let work = integral(&|s| s.loads.crank_torque);

        let mut m = Summary::default();
        m.push("piston_stroke", "m", mechanism.stroke());
        m.push("piston_velocity_max", "m/s", max(&|s| s.kinematics.piston.velocity));
        m.push("piston_acceleration_max", "m/s^2", max(&|s| s.kinematics.piston.acceleration));
        m.push("rod_cg_velocity_max", "m/s", max(&|s| s.kinematics.rod.point.velocity.norm()));
        m.push("rod_cg_acceleration_max", "m/s^2", max(&|s| s.kinematics.rod.point.acceleration.norm()));
        m.push("rod_angular_velocity_max", "rad/s", max(&|s| s.kinematics.rod.angular_velocity));
        m.push("rod_angular_acceleration_max", "rad/s^2", max(&|s| s.kinematics.rod.angular_acceleration));
        m.push("inertial_crank_pin_force_max", "N", max(&|s| s.loads.crank_pin.norm()));
        m.push("inertial_main_pin_force_max", "N", max(&|s| s.loads.main_bearing.norm()));
        m.push("inertial_piston_pin_force_max", "N", max(&|s| s.loads.piston_pin.norm()));
        m.push("inertial_piston_side_force_max", "N", max(&|s| s.loads.piston_side));
        m.push("inertial_gear_mesh_force_max", "N", max(&|s| s.loads.gear_mesh.norm()));
        m.push("inertial_torque_max", "N*m", max(&|s| s.loads.crank_torque));
        m.push("inertial_work", "J", work);
        m.push("inertial_torque_mean", "N*m", work / span); // (A5.2.1.38)
        // (A5.2.1.39) averaged over the crank angle, as the thesis's tables are; at constant
        // speed this is the time average.
        m.push("inertial_power_mean", "W", integral(&|s| s.loads.crank_torque * s.kinematics.crank.speed) / span);
        let energy = |s: &Step| kinetic_energy(kind, &s.kinematics, masses);
        m.push("kinetic_energy_change", "J", energy(last) - energy(first));
        m.push("cycle_time", "s", last.kinematics.crank.time - first.kinematics.crank.time);
        m
    }
}
