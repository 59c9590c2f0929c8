//! The cardan gear (geared hypocycloid with a 2:1 internal pair), Karhula (2008) appendix 4.2.1
//! and eqs. (A4.2.2.56)-(A4.2.2.74).
//!
//! The crank OS has length r = Z_AA0C; the cardan wheel (planet, pitch radius r) turns on the
//! crank pin S and rolls inside the ring gear (pitch radius 2r). The wheel pin T, on the wheel's
//! pitch circle, moves on the cylinder axis: Z_TO = 2r·sin θ·e^{i·90°} (A4.2.2.60). The rod
//! carries the piston at its upper end b = T + Z_bB·e^{i·90°} (A4.2.2.62-63) and does not turn.
//! Same stroke as the slider-crank of crank 2r.

use crate::{check_length, CrankState, GeometryError, KinematicState, Mechanism, MechanismKind};
use crate::{JointSpeeds, PistonMotion, PointMotion, RodMotion, WheelMotion, C};

/// Cardan gear geometry.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CardanGear {
    /// Crank length Z_AA0C, m: half the slider-crank crank of equal stroke (eq. 6.1); also the
    /// pitch radius of the cardan wheel, the ring gear having twice it.
    pub crank: f64,
    /// Rod length Z_bBC from the wheel pin T to the piston pin b, m.
    pub rod: f64,
    /// Distance of the reported rod point from the wheel pin T along the rod, m.
    pub rod_point: f64,
}

impl CardanGear {
    /// The cardan gear of the same stroke and the same top-dead-centre piston height as a
    /// slider-crank of crank `slider_crank_crank` and rod `rod` (Karhula eq. 6.1).
    pub fn equivalent_to_slider_crank(
        slider_crank_crank: f64,
        rod: f64,
        rod_point: f64,
    ) -> Result<Self, GeometryError> {
        check_length("crank_length", slider_crank_crank)?;
        check_length("rod_length", rod)?;
        if !(0.0..=rod).contains(&rod_point) {
            return Err(GeometryError::PointOffRod {
                point: rod_point,
                rod,
            });
        }
        Ok(Self {
            crank: slider_crank_crank / 2.0,
            rod,
            rod_point,
        })
    }
}

impl Mechanism for CardanGear {
    fn kind(&self) -> MechanismKind {
        MechanismKind::CardanGear
    }

    fn state(&self, crank: CrankState) -> KinematicState {
        let (w, a) = (crank.speed, crank.acceleration);
        let r = self.crank;
        let i = C::i();
        let e_a = crank.direction;
        let (s, c) = (e_a.im, e_a.re);
        let crank_pin = PointMotion {
            position: r * e_a,                       // (A4.2.2.57)
            velocity: r * i * w * e_a,               // (A4.2.2.65)
            acceleration: r * (i * a - w * w) * e_a, // (A4.2.2.70)
        };
        // T on the cylinder axis: (A4.2.2.60), (A4.2.2.68), (A4.2.2.73).
        let y = 2.0 * r * s;
        let v = 2.0 * r * w * c;
        let acc = 2.0 * r * (a * c - w * w * s);
        let on_axis = |height: f64| PointMotion {
            position: C::new(0.0, y + height),
            velocity: C::new(0.0, v),
            acceleration: C::new(0.0, acc),
        };
        let wheel_pin = on_axis(0.0);
        let piston_pin = on_axis(self.rod);
        KinematicState {
            crank,
            crank_pin,
            piston_pin,
            piston: PistonMotion {
                position: y + self.rod,
                velocity: v,
                acceleration: acc,
                dx_dtheta: 2.0 * r * c,
                d2x_dtheta2: -2.0 * r * s,
            },
            rod: RodMotion {
                direction: C::new(0.0, 1.0),
                angular_velocity: 0.0,
                angular_acceleration: 0.0,
                lower_pin: wheel_pin,
                point: on_axis(self.rod_point),
            },
            wheel: Some(WheelMotion {
                angular_velocity: -w,     // (A4.2.2.66)
                angular_acceleration: -a, // (A4.2.2.71)
                mesh_point: 2.0 * r * e_a,
                pitch_line_velocity: 2.0 * r * w, // (A8.1.7): twice the crank-pin speed
            }),
            // Wheel on crank turns at −2ω; the rod's big end on the wheel at +ω (A9.1.15, A9.1.17).
            joint_speeds: JointSpeeds {
                main_bearing: w,
                crank_pin: -2.0 * w,
                piston_pin: w,
            },
        }
    }

    /// x = 2·Z_AA0·sin θ + Z_bBC (A4.2.2.60) and its θ-derivative, as in [`Mechanism::state`].
    fn piston_position(&self, angle: f64) -> (f64, f64) {
        let (s, c) = angle.sin_cos();
        (2.0 * self.crank * s + self.rod, 2.0 * self.crank * c)
    }

    fn piston_top(&self) -> f64 {
        self.rod + 2.0 * self.crank
    }

    fn piston_bottom(&self) -> f64 {
        self.rod - 2.0 * self.crank
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// Appendix 4.2.1: T is the point of the wheel's pitch circle that started at the mesh
    /// point; rolling inside the ring without slip, it stays on the cylinder axis. Checked by
    /// building T from the wheel's own rotation instead of (A4.2.2.60).
    #[test]
    fn wheel_pin_from_rolling_stays_on_the_axis() {
        let g = CardanGear::equivalent_to_slider_crank(0.06, 0.14, 0.0).unwrap();
        for k in 0..50 {
            let th = 0.3 + 0.13 * k as f64;
            let st = g.state(CrankState::new(th, 7.0, 1.5, 0.0));
            // The wheel turns by −θ relative to the frame; at θ = 90° T sits on the mesh point.
            let wheel_turn = -(th - std::f64::consts::FRAC_PI_2);
            let t_from_rolling = st.crank_pin.position
                + g.crank * C::from_polar(1.0, std::f64::consts::FRAC_PI_2 + wheel_turn);
            assert!((t_from_rolling - st.rod.lower_pin.position).norm() < 1e-15);
            assert!((st.wheel.unwrap().mesh_point.norm() - 2.0 * g.crank).abs() < 1e-15);
        }
    }

    #[test]
    fn same_stroke_as_the_slider_crank() {
        let g = CardanGear::equivalent_to_slider_crank(0.06, 0.14, 0.07).unwrap();
        assert_relative_eq!(g.stroke(), 0.12, max_relative = 1e-15);
        assert_relative_eq!(g.piston_top(), 0.2, max_relative = 1e-15);
    }
}
