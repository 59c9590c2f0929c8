//! Engine losses of one cylinder of a four-stroke engine, step by step: the models of
//! `cardan_friction::engine` bound to a mechanism's crank.
//!
//! Three components, each switchable ([`EngineLosses`]), each a power in W at the step's crank
//! angle θ, speed ω and acceleration α, so that they follow an accelerating run:
//!
//! - `valve_train`: one intake and one exhaust valve, each opened by a circular-arc cam acting
//!   on a flat-faced or a roller follower (Thai thesis §2.5.d; note
//!   `docs/validation/thai-thesis.md` §5.4), the camshaft at half the crank speed. This
//!   is a **per-step cam model**, not a cycle mean: the cam is tied to the crank, so the lift,
//!   the follower load (spring + preload + inertia, eq. 2.5.d.15) and the contact friction
//!   (eq. 2.5.d.18) are known at every step and the friction torque shows the cam events. The
//!   geometry is scaled from the bore ([`ValveTrainGeometry::two_valve`]).
//! - `accessories`: water pump, oil pump and miscellaneous, Bishop (1964) as used by the Thai
//!   thesis, mep = 2.69 kPa·(N/1000)^1.5 (eq. 2.5.e.3.1), P = mep·V_d·ω/(4π) (eq. 2.5.e.3.2).
//! - `pumping`: Bishop's throttling loss at the intake-manifold pressure p_i (eqs 2.5.f.1-2,
//!   [`bishop_throttling_mep`]), P = mep·V_d·ω/(4π) (eq. 2.5.f.6); p_i = p_a (wide-open
//!   throttle) by default. Bishop's valve-flow and blow-by terms (eqs 2.5.f.3-4) are left out:
//!   their exponents are unreadable in the thesis's scan (`docs/validation/thai-thesis.md`). The gas models hold the
//!   open strokes at ambient pressure (no pumping work), so nothing is counted twice.
//!
//! V_d is the swept volume of the crank train, π/4·B²·stroke (of an opposed-piston cylinder,
//! each crank train carries its own piston's share, as every loss metric is per crank train).
//! The cycle starts at the mechanism's top dead centre with the intake stroke, as in the gas
//! models (`cardan-gas`, 720° cycle: intake, compression, power, exhaust).
//!
//! The whole-engine fmep cross-check after a run is [`crate::fmep`]'s.

use cardan_friction::engine::BISHOP_EXHAUST_FULL_LOAD;
use cardan_friction::{
    bishop_pumps_misc_mep, bishop_throttling_mep, flat_follower_friction, follower_load, mep_power,
    roller_follower_friction, Follower, Valvetrain,
};
use std::f64::consts::{FRAC_PI_2, PI};

/// Ambient pressure p_a of the pumping loss and of the PNH gas-loading term, Pa.
pub const AMBIENT_PRESSURE: f64 = 101_325.0;

/// Crank revolutions per cycle of a four-stroke engine (the Bishop and PNH correlations are
/// four-stroke).
pub const REVOLUTIONS_PER_CYCLE: f64 = 2.0;

/// Swept volume of one piston, π/4·B²·stroke, m³.
pub fn displacement(bore: f64, stroke: f64) -> f64 {
    PI / 4.0 * bore * bore * stroke
}

/// The contact between a cam and its follower.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FollowerContact {
    /// Flat-faced follower: Coulomb friction μ·W on the sliding speed ω_cam·(R + S) (Thai thesis
    /// eq. 2.5.d.18, [`flat_follower_friction`]).
    Flat {
        /// μ at the cam/follower contact (the thesis gives no value; 0.08 by default, a
        /// boundary-lubricated steel contact \[M\]).
        friction_coefficient: f64,
    },
    /// Roller follower: rolling resistance plus the roller's pin bearing,
    /// P = W·v_r·(c_rr + μ_pin·r_pin/r_roller) ([`roller_follower_friction`]), with the rolling
    /// speed v_r taken as the flat follower's ω_cam·(R + S) (exact on the base circle; the
    /// roller's pressure angle is not modelled).
    Roller {
        /// c_rr, rolling-friction arm over roller radius (0.002 by default \[M\]).
        rolling_resistance: f64,
        /// μ_pin of the needle bearing on the roller's pin (0.0025 by default \[M\]).
        pin_friction: f64,
        /// r_pin/r_roller (0.5 by default \[M\]).
        pin_radius_ratio: f64,
    },
}

impl FollowerContact {
    /// A flat follower with μ = 0.08.
    pub const FLAT: Self = FollowerContact::Flat {
        friction_coefficient: 0.08,
    };
    /// A roller follower with c_rr = 0.002, μ_pin = 0.0025, r_pin/r_roller = 0.5.
    pub const ROLLER: Self = FollowerContact::Roller {
        rolling_resistance: 0.002,
        pin_friction: 0.0025,
        pin_radius_ratio: 0.5,
    };

    /// The PNH follower type of this contact.
    pub fn pnh_follower(&self) -> Follower {
        match self {
            FollowerContact::Flat { .. } => Follower::Flat,
            FollowerContact::Roller { .. } => Follower::Roller,
        }
    }
}

/// A circular-arc ("three-arc") cam for a flat-faced follower, Thai thesis Figs 2.5.d.2-3 (the
/// Petter AV1 cam): base circle R, flanks of radius f from cam angle φ, nose of radius r; lift
/// L at θ = 90°, the event from φ to 180° − φ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CircularArcCam {
    /// Base-circle radius R, m.
    pub base_radius: f64,
    /// Maximum lift L, m.
    pub lift: f64,
    /// Nose radius r, m.
    pub nose_radius: f64,
    /// Cam angle φ where the opening flank starts, rad.
    pub flank_start: f64,
    /// Flank radius f (eq. 2.5.d.13), m.
    pub flank_radius: f64,
    /// Cam angle θ_n of the flank-to-nose transition (eq. 2.5.d.12), rad.
    pub nose_start: f64,
}

impl CircularArcCam {
    /// The cam of base radius R, lift L, nose radius r and flank start φ; the flank radius from
    /// eq. 2.5.d.13,
    /// f = [R² − r² + (R + L − r)² − 2R(R + L − r) sin φ] / (2 [R − r − (R + L − r) sin φ]),
    /// and θ_n = arccos[(f − R) cos φ / (f − r)] (eq. 2.5.d.12). Fails unless
    /// 0 < r < R, L > 0, 0 < φ < 90° and the flank is convex and wider than the base circle
    /// (R − r > (R + L − r) sin φ, f > R).
    pub fn new(
        base_radius: f64,
        lift: f64,
        nose_radius: f64,
        flank_start: f64,
    ) -> Result<Self, String> {
        let (rb, l, r, phi) = (base_radius, lift, nose_radius, flank_start);
        if !(rb.is_finite() && l.is_finite() && r.is_finite() && phi.is_finite()) {
            return Err("the cam's dimensions must be finite".into());
        }
        if !(r > 0.0 && r < rb && l > 0.0 && phi > 0.0 && phi < FRAC_PI_2) {
            return Err(format!(
                "a circular-arc cam needs 0 < nose radius < base radius, a positive lift and a flank start between 0 and 90° (R = {rb} m, L = {l} m, r = {r} m, φ = {}°)",
                phi.to_degrees()
            ));
        }
        let h = rb + l - r;
        let denominator = 2.0 * (rb - r - h * phi.sin());
        let f = (rb * rb - r * r + h * h - 2.0 * rb * h * phi.sin()) / denominator;
        if !(denominator > 0.0 && f.is_finite() && f > rb) {
            return Err(format!(
                "no convex flank joins a base circle of {rb} m to a nose of {r} m at {l} m lift from {}°: R − r must exceed (R + L − r)·sin φ",
                phi.to_degrees()
            ));
        }
        let nose_start = ((f - rb) * phi.cos() / (f - r)).acos();
        Ok(Self {
            base_radius: rb,
            lift: l,
            nose_radius: r,
            flank_start: phi,
            flank_radius: f,
            nose_start,
        })
    }

    /// Lift S (m) and its cam-angle derivatives S′ (m/rad) and S″ (m/rad²) at cam angle θ
    /// (rad), Thai thesis table L1099-1133 (V = S′ω, A = S″ω² at constant cam speed): zero on
    /// the base circle; (f − R)[1 − cos(θ − φ)] on the opening flank; (R + L − r) sin θ + r − R
    /// on the nose; (f − R)[1 + cos(θ + φ)] on the closing flank. S and S′ are continuous, S″
    /// jumps where the arcs meet (as on any circular-arc cam).
    pub fn lift_at(&self, theta: f64) -> (f64, f64, f64) {
        let (phi, tn) = (self.flank_start, self.nose_start);
        let flank = self.flank_radius - self.base_radius;
        let nose = self.base_radius + self.lift - self.nose_radius;
        if !(phi..=PI - phi).contains(&theta) {
            (0.0, 0.0, 0.0)
        } else if theta < tn {
            let a = theta - phi;
            (flank * (1.0 - a.cos()), flank * a.sin(), flank * a.cos())
        } else if theta <= PI - tn {
            let (s, c) = theta.sin_cos();
            (
                nose * s + self.nose_radius - self.base_radius,
                nose * c,
                -nose * s,
            )
        } else {
            let a = theta + phi;
            (flank * (1.0 + a.cos()), -flank * a.sin(), -flank * a.cos())
        }
    }

    /// Cam angle of the valve event, 180° − 2φ, rad.
    pub fn event(&self) -> f64 {
        PI - 2.0 * self.flank_start
    }
}

/// The valve train of one cylinder: two valves (intake, exhaust), each with its own cam, spring
/// and follower mass; all dimensions SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ValveTrainGeometry {
    /// The cam of each valve.
    pub cam: CircularArcCam,
    /// Equivalent mass m reduced to the follower (follower + valve + ⅓ spring), kg.
    pub equivalent_mass: f64,
    /// Valve-spring rate k, N/m.
    pub spring_rate: f64,
    /// Spring preload F_pl with the valve seated, N.
    pub preload: f64,
    /// Crank angle of each valve's maximum lift from the cycle's first top dead centre (the
    /// start of the intake stroke), rad: intake 110°, exhaust 610°.
    pub max_lift_angles: [f64; 2],
}

impl ValveTrainGeometry {
    /// A two-valve head scaled from the bore B, sized for the crank speed `spring_speed`
    /// (rad/s). Engineering proportions \[M\], not from the sources:
    /// - lift L = 0.1·B (valve head ≈ 0.45·B, L/D_v ≈ 0.22; the PNH round engine's 10 mm at
    ///   100 mm bore), base radius R = 0.15·B, nose radius r = 0.05·B, flank start φ = 25°:
    ///   a 130° cam event, 260° of crank angle seat to seat (intake opens 20° before top dead
    ///   centre and closes 60° after bottom dead centre; exhaust opens 60° before bottom dead
    ///   centre and closes 20° after top dead centre);
    /// - equivalent mass m = 0.1 kg·(B/86 mm)³ (bucket tappet, valve and a third of the spring
    ///   of an 86 mm-bore engine, scaled with the volume);
    /// - spring: on the nose the lift is (R + L − r) sin θ + r − R and the deceleration
    ///   (R + L − r) ω_cam² sin θ, so k = 1.5·m·ω_d² and F_pl = k·(R − r) make the spring force
    ///   1.5 times the inertia force over the whole nose at the cam speed ω_d = spring_speed/2;
    ///   above 1.22 times that crank speed the follower leaves the nose (valve float).
    pub fn two_valve(bore: f64, spring_speed: f64) -> Result<Self, String> {
        if !(bore > 0.0 && bore.is_finite()) {
            return Err(format!("the bore must be positive, got {bore} m"));
        }
        if !(spring_speed > 0.0 && spring_speed.is_finite()) {
            return Err(format!(
                "the valve spring's design speed must be positive, got {spring_speed} rad/s"
            ));
        }
        let cam = CircularArcCam::new(0.15 * bore, 0.1 * bore, 0.05 * bore, 25f64.to_radians())?;
        let equivalent_mass = 0.1 * (bore / 0.086).powi(3);
        let cam_speed = spring_speed / 2.0;
        let spring_rate = 1.5 * equivalent_mass * cam_speed * cam_speed;
        Ok(Self {
            cam,
            equivalent_mass,
            spring_rate,
            preload: spring_rate * (cam.base_radius - cam.nose_radius),
            max_lift_angles: [110f64.to_radians(), 610f64.to_radians()],
        })
    }
}

/// The valve-train model of a case.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ValveTrain {
    /// The cam/follower contact.
    pub follower: FollowerContact,
    /// Crank speed the valve springs are sized for, rad/s (6000 rpm by default; see
    /// [`ValveTrainGeometry::two_valve`]).
    pub spring_speed: f64,
    /// `None`: [`ValveTrainGeometry::two_valve`] of the cylinder's bore.
    pub geometry: Option<ValveTrainGeometry>,
}

impl ValveTrain {
    /// The default valve train with `follower`: springs for 6000 rpm, geometry from the bore.
    pub fn new(follower: FollowerContact) -> Self {
        Self {
            follower,
            spring_speed: 6000.0 * PI / 30.0,
            geometry: None,
        }
    }
}

/// Which form of the whole-engine fmep correlation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FmepModel {
    /// Patton, Nitschke & Heywood (1989), SAE 890836.
    Pnh1989,
    /// Sandoval & Heywood (2003), SAE 2003-01-0725: hydrodynamic terms × √(ν/ν₀) with the
    /// case's oil, boundary factor 1 + 500/N.
    SandovalHeywood2003,
}

/// The engine components of a four-stroke engine's loss budget and the settings of its fmep
/// cross-check. [`crate::Friction::engine`] holds it for engines only (the runner sets it when
/// `machine = "engine"`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EngineLosses {
    /// `None`: no valve-train loss.
    pub valve_train: Option<ValveTrain>,
    /// Bishop's pumps and miscellaneous accessories.
    pub accessories: bool,
    /// Bishop's throttling (pumping) loss.
    pub pumping: bool,
    /// Absolute intake-manifold pressure p_i, Pa (of the pumping loss and the PNH gas-loading
    /// term); from 0.1·p_a (where Bishop's standard imep vanishes) to p_a.
    pub intake_pressure: f64,
    /// Ambient pressure p_a, Pa.
    pub ambient_pressure: f64,
    /// Exhaust gauge pressure at full load and 4000 rev/min, Pa (Bishop: 10 inHg).
    pub exhaust_back_pressure: f64,
    /// The fmep correlation of the cross-check.
    pub fmep_model: FmepModel,
    /// Compression ratio of the PNH gas-loading term (the runner takes the gas model's, else 10).
    pub compression_ratio: f64,
    /// Valve-train layout of the PNH cross-check (single overhead cam, direct acting: the cam on
    /// the follower, as modelled here).
    pub pnh_valvetrain: Valvetrain,
}

impl EngineLosses {
    /// Every component off, wide-open throttle at 101 325 Pa, Bishop's exhaust back pressure,
    /// Sandoval & Heywood's fmep, compression ratio 10, SOHC direct-acting valve train.
    pub fn off() -> Self {
        Self {
            valve_train: None,
            accessories: false,
            pumping: false,
            intake_pressure: AMBIENT_PRESSURE,
            ambient_pressure: AMBIENT_PRESSURE,
            exhaust_back_pressure: BISHOP_EXHAUST_FULL_LOAD,
            fmep_model: FmepModel::SandovalHeywood2003,
            compression_ratio: 10.0,
            pnh_valvetrain: Valvetrain::SohcDirect,
        }
    }

    /// Checks the pressures and the compression ratio: input and rule of the first broken one.
    pub fn check(&self) -> Result<(), (EngineInput, String)> {
        let pa = self.ambient_pressure;
        if !(pa > 0.0 && pa.is_finite()) {
            return Err((
                EngineInput::AmbientPressure,
                format!("must be positive, got {pa} Pa"),
            ));
        }
        let pi = self.intake_pressure;
        if !(pi > 0.1 * pa && pi <= pa) {
            return Err((
                EngineInput::IntakePressure,
                format!(
                    "must be above 0.1 × ambient ({} Pa, where Bishop's standard imep is zero) and at most ambient ({pa} Pa, wide-open throttle: Bishop's engines are not boosted), got {pi} Pa",
                    0.1 * pa
                ),
            ));
        }
        if !(self.exhaust_back_pressure >= 0.0 && self.exhaust_back_pressure.is_finite()) {
            return Err((
                EngineInput::ExhaustBackPressure,
                format!(
                    "must not be negative, got {} Pa",
                    self.exhaust_back_pressure
                ),
            ));
        }
        if !(self.compression_ratio > 1.0 && self.compression_ratio.is_finite()) {
            return Err((
                EngineInput::CompressionRatio,
                format!("must exceed 1, got {}", self.compression_ratio),
            ));
        }
        Ok(())
    }
}

/// An input of [`EngineLosses`] its check can refuse.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EngineInput {
    /// [`EngineLosses::ambient_pressure`].
    AmbientPressure,
    /// [`EngineLosses::intake_pressure`].
    IntakePressure,
    /// [`EngineLosses::exhaust_back_pressure`].
    ExhaustBackPressure,
    /// [`EngineLosses::compression_ratio`].
    CompressionRatio,
}

impl EngineInput {
    /// Every input.
    pub const ALL: [EngineInput; 4] = [
        EngineInput::AmbientPressure,
        EngineInput::IntakePressure,
        EngineInput::ExhaustBackPressure,
        EngineInput::CompressionRatio,
    ];
}

/// The valve train of one cylinder bound to a mechanism's crank.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ValveTrainLoss {
    /// Its geometry.
    pub geometry: ValveTrainGeometry,
    /// Its cam/follower contact.
    pub follower: FollowerContact,
    /// Crank angle of the cycle's first top dead centre, rad.
    pub top_dead_centre: f64,
}

impl ValveTrainLoss {
    /// `train` in a cylinder of `bore` (m) whose cycle starts at crank angle `top_dead_centre`.
    pub fn new(train: &ValveTrain, bore: f64, top_dead_centre: f64) -> Result<Self, String> {
        let geometry = match train.geometry {
            Some(g) => g,
            None => ValveTrainGeometry::two_valve(bore, train.spring_speed)?,
        };
        Ok(Self {
            geometry,
            follower: train.follower,
            top_dead_centre,
        })
    }

    /// Cam angle (rad) of `valve` (0 intake, 1 exhaust) at crank angle `angle`: the camshaft
    /// turns at half the crank speed and reaches 90° (maximum lift) at the valve's
    /// [`ValveTrainGeometry::max_lift_angles`].
    pub fn cam_angle(&self, valve: usize, angle: f64) -> f64 {
        let from_max = (angle - self.top_dead_centre - self.geometry.max_lift_angles[valve] + PI)
            .rem_euclid(4.0 * PI)
            - PI;
        FRAC_PI_2 + from_max / 2.0
    }

    /// Follower load W (N) of `valve` at crank angle `angle`, speed ω and acceleration α:
    /// W = F_pl + k·S + m·A (Thai thesis eqs 2.5.d.14-15) with the follower acceleration
    /// A = S″·ω_cam² + S′·α_cam, ω_cam = ω/2, α_cam = α/2, during the valve event; zero on the
    /// base circle, where the seat carries the spring (valve lash; the thesis's table would
    /// leave F_pl on the cam for the whole revolution), and zero where the inertia would pull
    /// the follower off the nose (valve float).
    pub fn load(&self, valve: usize, angle: f64, speed: f64, acceleration: f64) -> f64 {
        let g = &self.geometry;
        let theta = self.cam_angle(valve, angle);
        let phi = g.cam.flank_start;
        if !(phi..=PI - phi).contains(&theta) {
            return 0.0;
        }
        let (s, s1, s2) = g.cam.lift_at(theta);
        let (w, a) = (speed / 2.0, acceleration / 2.0);
        follower_load(
            g.preload,
            g.spring_rate,
            s,
            g.equivalent_mass,
            s2 * w * w + s1 * a,
        )
        .max(0.0)
    }

    /// Friction power of `valve` at crank angle `angle`, speed ω and acceleration α, W:
    /// flat follower μ·W·(R + S)·|ω_cam| (Thai thesis eq. 2.5.d.18 times the cam speed), roller
    /// W·(c_rr + μ_pin·r_pin/r_roller)·(R + S)·|ω_cam|.
    pub fn valve_power(&self, valve: usize, angle: f64, speed: f64, acceleration: f64) -> f64 {
        let w = self.load(valve, angle, speed, acceleration);
        if w == 0.0 {
            return 0.0;
        }
        let cam = &self.geometry.cam;
        let (s, _, _) = cam.lift_at(self.cam_angle(valve, angle));
        let cam_speed = speed / 2.0;
        match self.follower {
            FollowerContact::Flat {
                friction_coefficient,
            } => {
                flat_follower_friction(friction_coefficient, w, cam.base_radius, s, cam_speed).power
            }
            FollowerContact::Roller {
                rolling_resistance,
                pin_friction,
                pin_radius_ratio,
            } => {
                roller_follower_friction(
                    w,
                    cam_speed * (cam.base_radius + s),
                    rolling_resistance,
                    pin_friction,
                    pin_radius_ratio,
                    1.0,
                )
                .power
            }
        }
    }

    /// Friction power of both valves, W.
    pub fn power(&self, angle: f64, speed: f64, acceleration: f64) -> f64 {
        self.valve_power(0, angle, speed, acceleration)
            + self.valve_power(1, angle, speed, acceleration)
    }
}

/// Power of Bishop's pumps and miscellaneous accessories on a swept volume `displacement`
/// (m³) at crank speed ω (rad/s), W: mep = 2.69 kPa·(N/1000)^1.5 (Thai thesis eq. 2.5.e.3.1),
/// P = mep·V_d·ω/(4π) (eq. 2.5.e.3.2, = mep·V_d·N/(60·2)).
pub fn accessories_power(displacement: f64, crank_speed: f64) -> f64 {
    mep_power(
        bishop_pumps_misc_mep(crank_speed),
        displacement,
        crank_speed,
        REVOLUTIONS_PER_CYCLE,
    )
}

/// Power of Bishop's throttling loss of `engine` on a swept volume `displacement` (m³) at crank
/// speed ω (rad/s), W: mep = (p_a − p_i) + p′_e·[(imep_s/3904 kPa)(N/1000)]², imep_s =
/// 12.87·(p_i − 0.1·p_a) (Thai thesis eqs 2.5.f.1-2), P = mep·V_d·ω/(4π) (eq. 2.5.f.6).
pub fn pumping_power(engine: &EngineLosses, displacement: f64, crank_speed: f64) -> f64 {
    let mep = bishop_throttling_mep(
        engine.ambient_pressure,
        engine.intake_pressure,
        engine.exhaust_back_pressure,
        crank_speed,
    );
    mep_power(mep, displacement, crank_speed, REVOLUTIONS_PER_CYCLE)
}
