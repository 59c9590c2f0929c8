use crate::motion::CrankState;
use crate::C;

/// Position, velocity and acceleration of a point in the frame of the main bearing axis.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PointMotion {
    /// Position, m.
    pub position: C,
    /// Velocity, m/s.
    pub velocity: C,
    /// Acceleration, m/s².
    pub acceleration: C,
}

/// The piston along the cylinder axis (the imaginary axis).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PistonMotion {
    /// Piston pin distance from the main bearing axis along the cylinder, m.
    pub position: f64,
    /// Piston velocity along the cylinder axis, m/s (positive away from the crankshaft).
    pub velocity: f64,
    /// Piston acceleration along the cylinder axis, m/s².
    pub acceleration: f64,
    /// dx/dθ, m/rad: a pure function of the geometry. The cylinder volume follows as
    /// V(θ) = V_c + A·(x_TDC − x(θ)) and dV/dθ = −A·dx/dθ.
    pub dx_dtheta: f64,
    /// d²x/dθ², m/rad².
    pub d2x_dtheta2: f64,
}

/// The connecting rod.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RodMotion {
    /// Unit vector along the rod from its lower pin to its upper pin, e^{iθ_BA}; its argument
    /// is the rod angle θ_BA.
    pub direction: C,
    /// Rod angular velocity, rad/s.
    pub angular_velocity: f64,
    /// Rod angular acceleration, rad/s².
    pub angular_acceleration: f64,
    /// The rod's lower pin: the crank pin A in the slider-crank, the wheel pin T in the cardan gear.
    pub lower_pin: PointMotion,
    /// The chosen point of the rod centre line (its centre of gravity by default).
    pub point: PointMotion,
}

/// The cardan wheel (planet gear); absent in the slider-crank.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WheelMotion {
    /// Wheel angular velocity in the frame, rad/s (−ω, A4.2.2.66).
    pub angular_velocity: f64,
    /// Wheel angular acceleration in the frame, rad/s² (−α, A4.2.2.71).
    pub angular_acceleration: f64,
    /// The pitch point P where the wheel meshes with the ring gear, m.
    pub mesh_point: C,
    /// Pitch-line velocity of the mesh, m/s (Karhula A8.1.7: twice the crank-pin speed).
    pub pitch_line_velocity: f64,
}

/// Relative angular speeds of the joints (the speeds that turn their bearings), rad/s, signed.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct JointSpeeds {
    /// Crankshaft relative to the frame.
    pub main_bearing: f64,
    /// Rod (slider-crank) or cardan wheel (cardan gear) relative to the crankshaft.
    pub crank_pin: f64,
    /// Rod relative to the piston (slider-crank) or to the cardan wheel (cardan gear: the
    /// rod's big-end bearing, which Karhula A9.1 calls the piston pin bearing).
    pub piston_pin: f64,
}

/// Everything known about a mechanism at one crank state. Complex vectors are in the frame of
/// the main bearing axis with the cylinder on the imaginary axis.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct KinematicState {
    pub crank: CrankState,
    /// The crank pin: A in the slider-crank, S (the cardan wheel centre) in the cardan gear.
    pub crank_pin: PointMotion,
    /// The piston pin: B in the slider-crank, b (the rod's upper end) in the cardan gear.
    pub piston_pin: PointMotion,
    pub piston: PistonMotion,
    pub rod: RodMotion,
    pub wheel: Option<WheelMotion>,
    pub joint_speeds: JointSpeeds,
}
