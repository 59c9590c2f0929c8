//! Karhula's (2008) totals and efficiency definitions (App. 9.1, A9.1.56–A9.1.75; chapter 9,
//! eqs 9.1–9.16) and an O(1)-memory accumulator for per-step power losses.

/// Instantaneous power losses of one machine, W, grouped as in Karhula A9.1.56–59.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct MachineLosses {
    /// Piston loss P_μpis (rings + skirt; A9.1.8–9), W.
    pub piston: f64,
    /// Sum of the pin-bearing losses ΣP_μb (piston-pin, crank-pin and main bearings;
    /// A9.1.34–35), W.
    pub bearings: f64,
    /// Gear-mesh loss of the cardan wheel P_μwheelc (A9.1.55; zero for a slider crank), W.
    pub gear_mesh: f64,
}

impl MachineLosses {
    /// Total power loss P_μ = P_μpis + ΣP_μb (+ P_μwheelc), W (A9.1.56–59, eqs 9.1–9.4).
    pub fn total(&self) -> f64 {
        self.piston + self.bearings + self.gear_mesh
    }
}

/// Power needed to drive a pump: P_need = P_pump + P_μpump (A9.1.60–61, eqs 9.5–9.6), W, with
/// `lossless_power` the ideal (gas) power and `power_loss` the friction loss.
pub fn pump_power_need(lossless_power: f64, power_loss: f64) -> f64 {
    lossless_power + power_loss
}

/// Output power of an engine: P_out = P_eng − P_μeng (A9.1.62–63, eqs 9.7–9.8), W.
pub fn engine_output_power(lossless_power: f64, power_loss: f64) -> f64 {
    lossless_power - power_loss
}

/// Shaft torque of a power at crank speed ω: T = P/ω (A9.1.64–67, eqs 9.9–9.12), N·m.
pub fn power_to_torque(power: f64, crank_speed: f64) -> f64 {
    power / crank_speed
}

/// Mechanical efficiency of a pump: η = ΣW_comp / (ΣW_pump + ΣW_μpump) (A9.1.72–73, eqs
/// 9.13–9.14), with `compression_work` the work done on the gas, `lossless_work` the work of the
/// lossless mechanism and `loss_work` the friction work per cycle (J).
pub fn pump_mechanical_efficiency(
    compression_work: f64,
    lossless_work: f64,
    loss_work: f64,
) -> f64 {
    compression_work / (lossless_work + loss_work)
}

/// Mechanical efficiency of an engine: η = (ΣW_eng − ΣW_μeng)/ΣW_eng (A9.1.74–75, eqs
/// 9.15–9.16), with `lossless_work` the lossless (indicated) work and `loss_work` the friction
/// work per cycle (J).
pub fn engine_mechanical_efficiency(lossless_work: f64, loss_work: f64) -> f64 {
    (lossless_work - loss_work) / lossless_work
}

/// Accumulates the work of a power over a cycle in O(1) memory: ΣW = ∫ P dt (A9.1.68–71),
/// fed step by step by a simulation loop (left-point rule: each call adds P·Δt).
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct WorkAccumulator {
    /// Accumulated work, J.
    pub work: f64,
    /// Accumulated time, s.
    pub time: f64,
    /// Accumulated crank angle, rad.
    pub angle: f64,
}

impl WorkAccumulator {
    /// An empty accumulator.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds `power` (W) held over the time step `dt` (s); the angle is not advanced.
    pub fn add_time_step(&mut self, power: f64, dt: f64) {
        self.work += power * dt;
        self.time += dt;
    }

    /// Adds `power` (W) held over the crank-angle step `d_theta` (rad) at crank speed
    /// `crank_speed` (rad/s): Δt = |Δθ/ω|.
    pub fn add_angle_step(&mut self, power: f64, d_theta: f64, crank_speed: f64) {
        let dt = (d_theta / crank_speed).abs();
        self.work += power * dt;
        self.time += dt;
        self.angle += d_theta.abs();
    }

    /// Time-mean power ΣW/t, W (NaN before any step).
    pub fn mean_power(&self) -> f64 {
        self.work / self.time
    }

    /// Angle-mean torque ΣW/Δθ, N·m (NaN before any angle step).
    pub fn mean_torque(&self) -> f64 {
        self.work / self.angle
    }
}
