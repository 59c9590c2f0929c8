//! The slider-crank mechanism, Karhula (2008) eqs. (A4.2.2.1)-(A4.2.2.55), extended with a
//! piston-pin offset.
//!
//! The piston pin B slides on the line Re(Z) = e (e = pin offset; e = 0 is the thesis's in-line
//! machine). The closure Z_AA0·cos θ + Z_BA·cos θ_BA = e gives θ_BA = arccos((e − Z_AA0·cos θ)/Z_BA),
//! which for e = 0 is (A4.2.2.3). Its time derivatives give ω_BA (A4.2.2.12) and α_BA
//! (A4.2.2.31) unchanged, because e is constant.

use crate::{check_length, CrankState, GeometryError, KinematicState, Mechanism, MechanismKind};
use crate::{JointSpeeds, PistonMotion, PointMotion, RodMotion, C};

/// Slider-crank geometry.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SliderCrank {
    /// Crank length Z_AA0, m.
    pub crank: f64,
    /// Connecting rod length Z_BA (pin centre to pin centre), m.
    pub rod: f64,
    /// Piston pin offset e from the cylinder axis through the main bearing, m (positive towards +x).
    pub pin_offset: f64,
    /// Distance of the reported rod point from the crank pin along the rod, m (Z_PA).
    pub rod_point: f64,
}

impl SliderCrank {
    pub fn new(
        crank: f64,
        rod: f64,
        pin_offset: f64,
        rod_point: f64,
    ) -> Result<Self, GeometryError> {
        check_length("crank_length", crank)?;
        check_length("rod_length", rod)?;
        if !pin_offset.is_finite() {
            return Err(GeometryError::NotFinite {
                field: "pin_offset",
                value: pin_offset,
            });
        }
        if rod <= crank + pin_offset.abs() {
            return Err(GeometryError::RodTooShort {
                rod,
                crank,
                offset: pin_offset.abs(),
            });
        }
        if !(0.0..=rod).contains(&rod_point) {
            return Err(GeometryError::PointOffRod {
                point: rod_point,
                rod,
            });
        }
        Ok(Self {
            crank,
            rod,
            pin_offset,
            rod_point,
        })
    }

    /// cos θ_BA, sin θ_BA, and dθ_BA/dθ and d²θ_BA/dθ² (the rod's angular velocity and
    /// acceleration per unit crank speed at zero crank acceleration), from cos θ and sin θ.
    fn rod_angles(&self, c: f64, s: f64) -> (f64, f64, f64, f64) {
        let (r, l) = (self.crank, self.rod);
        let cos_ba = (self.pin_offset - r * c) / l; // (A4.2.2.3)
        let sin_ba = (1.0 - cos_ba * cos_ba).sqrt(); // θ_BA in (0, π): the piston is above the crank
        let inv = 1.0 / (l * sin_ba);
        let d1 = -r * s * inv; // (A4.2.2.12) at ω = 1
        let d2 = -(r * c + l * d1 * d1 * cos_ba) * inv; // (A4.2.2.31) at ω = 1, α = 0
        (cos_ba, sin_ba, d1, d2)
    }
}

impl Mechanism for SliderCrank {
    fn kind(&self) -> MechanismKind {
        MechanismKind::SliderCrank
    }

    fn state(&self, crank: CrankState) -> KinematicState {
        let (w, a) = (crank.speed, crank.acceleration);
        let (r, l) = (self.crank, self.rod);
        let i = C::i();
        let e_a = crank.direction;
        let crank_pin = PointMotion {
            position: r * e_a,                       // (A4.2.2.2)
            velocity: r * i * w * e_a,               // (A4.2.2.11)
            acceleration: r * (i * a - w * w) * e_a, // (A4.2.2.30)
        };
        let (cos_ba, sin_ba, d1, d2) = self.rod_angles(e_a.re, e_a.im);
        // (A4.2.2.12) and (A4.2.2.31): ω_BA = ω·dθ_BA/dθ, α_BA = α·dθ_BA/dθ + ω²·d²θ_BA/dθ².
        let (w_ba, a_ba) = (w * d1, a * d1 + w * w * d2);
        let e_ba = C::new(cos_ba, sin_ba);
        let along = |len: f64| PointMotion {
            position: crank_pin.position + len * e_ba, // (A4.2.2.9)
            velocity: crank_pin.velocity + len * i * w_ba * e_ba, // (A4.2.2.22-23)
            acceleration: crank_pin.acceleration + len * (i * a_ba - w_ba * w_ba) * e_ba, // (A4.2.2.44-45)
        };
        // The piston pin on the cylinder line (A4.2.2.5, A4.2.2.14, A4.2.2.33), its exact
        // abscissa avoiding the round-off of the rod closure.
        let pin = along(l);
        let piston_pin = PointMotion {
            position: C::new(self.pin_offset, pin.position.im),
            velocity: C::new(0.0, pin.velocity.im),
            acceleration: C::new(0.0, pin.acceleration.im),
        };
        // dx/dθ and d²x/dθ²: the piston velocity and acceleration at ω = 1 rad/s, α = 0.
        let dx = r * e_a.re + l * d1 * cos_ba;
        let d2x = -r * e_a.im + l * (d2 * cos_ba - d1 * d1 * sin_ba);
        KinematicState {
            crank,
            crank_pin,
            piston_pin,
            piston: PistonMotion {
                position: pin.position.im,
                velocity: pin.velocity.im,
                acceleration: pin.acceleration.im,
                dx_dtheta: dx,
                d2x_dtheta2: d2x,
            },
            rod: RodMotion {
                direction: e_ba,
                angular_velocity: w_ba,
                angular_acceleration: a_ba,
                lower_pin: crank_pin,
                point: along(self.rod_point),
            },
            wheel: None,
            joint_speeds: JointSpeeds {
                main_bearing: w,
                crank_pin: w_ba - w,
                piston_pin: w_ba,
            }, // (A9.1.14-18)
        }
    }

    /// x = Z_AA0·sin θ + Z_BA·sin θ_BA and its θ-derivative, as in [`Mechanism::state`].
    fn piston_position(&self, angle: f64) -> (f64, f64) {
        let (s, c) = angle.sin_cos();
        let (cos_ba, sin_ba, d1, _) = self.rod_angles(c, s);
        (
            self.crank * s + self.rod * sin_ba,
            self.crank * c + self.rod * d1 * cos_ba,
        )
    }

    fn piston_top(&self) -> f64 {
        ((self.rod + self.crank).powi(2) - self.pin_offset.powi(2)).sqrt()
    }

    fn piston_bottom(&self) -> f64 {
        ((self.rod - self.crank).powi(2) - self.pin_offset.powi(2)).sqrt()
    }

    /// Crank and rod in line: the crank pin lies on the line from the main bearing to the
    /// piston pin (e, x_TDC), so cos θ_TDC = e/(Z_AA0 + Z_BA).
    fn top_dead_centre(&self) -> f64 {
        (self.pin_offset / (self.rod + self.crank)).acos()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::CrankMotion;
    use approx::assert_relative_eq;

    fn machine(offset: f64) -> SliderCrank {
        SliderCrank::new(0.06, 0.14, offset, 0.07).unwrap()
    }

    /// Velocities and accelerations are the time derivatives of the positions: central
    /// differences over a short time step agree to the differencing error.
    #[test]
    fn derivatives_match_finite_differences() {
        for offset in [0.0, 0.012] {
            let m = machine(offset);
            let motion = CrankMotion {
                start_angle: 0.3,
                initial_speed: 30.0,
                angular_acceleration: 400.0,
            };
            for theta in [0.4, 1.2, 2.5, 4.0, 5.9] {
                let s = m.state(motion.at_angle(theta).unwrap());
                let h = 1e-5;
                let at = |t: f64| {
                    let st = motion.at_angle(theta).unwrap();
                    let dt = t - st.time;
                    let w = st.speed + st.acceleration * dt;
                    m.state(CrankState::new(
                        theta + st.speed * dt + 0.5 * st.acceleration * dt * dt,
                        w,
                        st.acceleration,
                        t,
                    ))
                };
                let (p, q) = (at(s.crank.time - h), at(s.crank.time + h));
                type Get = fn(&KinematicState) -> C;
                let pairs: [(Get, Get); 4] = [
                    (
                        |k: &KinematicState| k.rod.point.position,
                        |k: &KinematicState| k.rod.point.velocity,
                    ),
                    (
                        |k: &KinematicState| k.rod.point.velocity,
                        |k: &KinematicState| k.rod.point.acceleration,
                    ),
                    (
                        |k: &KinematicState| k.piston_pin.position,
                        |k: &KinematicState| k.piston_pin.velocity,
                    ),
                    (
                        |k: &KinematicState| k.piston_pin.velocity,
                        |k: &KinematicState| k.piston_pin.acceleration,
                    ),
                ];
                for (f, df) in pairs {
                    let numeric = (f(&q) - f(&p)) / (2.0 * h);
                    let scale = df(&s).norm().max(1.0);
                    assert!(
                        (numeric - df(&s)).norm() < 1e-5 * scale,
                        "θ = {theta}, offset = {offset}"
                    );
                }
                let numeric_w = (q.rod.direction.arg() - p.rod.direction.arg()) / (2.0 * h);
                assert_relative_eq!(
                    numeric_w,
                    s.rod.angular_velocity,
                    epsilon = 1e-5,
                    max_relative = 1e-6
                );
                // dx/dθ is v/ω for any motion.
                assert_relative_eq!(
                    s.piston.dx_dtheta * s.crank.speed,
                    s.piston.velocity,
                    max_relative = 1e-12,
                    epsilon = 1e-12
                );
            }
        }
    }

    #[test]
    fn rod_closes_on_the_piston_pin_and_dead_centres() {
        let m = machine(0.0);
        let st = m.state(CrankState::new(1.0, 10.0, 3.0, 0.0));
        let tip = st.crank_pin.position + m.rod * st.rod.direction;
        assert!((tip - st.piston_pin.position).norm() < 1e-15);
        let top = m.state(CrankState::new(std::f64::consts::FRAC_PI_2, 1.0, 0.0, 0.0));
        assert_relative_eq!(top.piston.position, 0.2, max_relative = 1e-15);
        assert_relative_eq!(m.stroke(), 0.12, max_relative = 1e-14);
        // With an offset the stroke grows slightly: sqrt((l+r)²−e²) − sqrt((l−r)²−e²).
        let off = machine(0.02);
        assert!(off.stroke() > 0.12);
        // Top dead centre: the pin reaches piston_top there, with zero dx/dθ; an offset
        // towards +x turns it back from π/2.
        for m in [machine(0.0), off, machine(-0.02)] {
            let tdc = m.state(CrankState::new(m.top_dead_centre(), 1.0, 0.0, 0.0));
            assert_relative_eq!(tdc.piston.position, m.piston_top(), max_relative = 1e-14);
            assert!(
                tdc.piston.dx_dtheta.abs() < 1e-14,
                "{}",
                tdc.piston.dx_dtheta
            );
        }
        assert!(off.top_dead_centre() < std::f64::consts::FRAC_PI_2);
    }

    #[test]
    fn impossible_machines_are_refused() {
        assert!(matches!(
            SliderCrank::new(0.06, 0.06, 0.0, 0.0),
            Err(GeometryError::RodTooShort { .. })
        ));
        assert!(matches!(
            SliderCrank::new(0.06, 0.1, 0.05, 0.0),
            Err(GeometryError::RodTooShort { .. })
        ));
        assert!(matches!(
            SliderCrank::new(-0.06, 0.14, 0.0, 0.0),
            Err(GeometryError::NotPositive { .. })
        ));
        assert!(matches!(
            SliderCrank::new(0.06, f64::NAN, 0.0, 0.0),
            Err(GeometryError::NotPositive { .. })
        ));
        assert!(matches!(
            SliderCrank::new(0.06, 0.14, 0.0, 0.2),
            Err(GeometryError::PointOffRod { .. })
        ));
    }
}
