//! Radial, Coriolis, tangential and normal decomposition of a point's motion about the origin,
//! Karhula (2008) eqs. (4.1.2)-(4.1.3) and (A4.2.2.23)-(A4.2.2.55).

use crate::model::PointMotion;

/// Motion of a point described in polar form about the main bearing axis: Z = |Z|·e^{iθ},
/// v = v_r·e^{iθ} + |Z|·i·ω·e^{iθ}, a = a_r·e^{iθ} + 2·v_r·ω·i·e^{iθ} + |Z|·α·i·e^{iθ} − |Z|·ω²·e^{iθ}.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PolarComponents {
    /// Distance |Z| from the origin, m.
    pub radius: f64,
    /// Radial velocity v_r = d|Z|/dt (A4.2.2.25), m/s.
    pub radial_velocity: f64,
    /// Tangential velocity v_t = |Z|·ω (A4.2.2.27), m/s.
    pub tangential_velocity: f64,
    /// Angular velocity ω of the position vector (A4.2.2.29), rad/s.
    pub angular_velocity: f64,
    /// Radial acceleration a_r = d²|Z|/dt² (A4.2.2.47), m/s².
    pub radial_acceleration: f64,
    /// Coriolis acceleration 2·v_r·ω (A4.2.2.49), m/s².
    pub coriolis_acceleration: f64,
    /// Tangential acceleration |Z|·α (A4.2.2.51), m/s².
    pub tangential_acceleration: f64,
    /// Normal (centripetal) acceleration −|Z|·ω² (A4.2.2.53), m/s², along e^{iθ}.
    pub normal_acceleration: f64,
    /// Angular acceleration α of the position vector (A4.2.2.55), rad/s².
    pub angular_acceleration: f64,
}

impl PolarComponents {
    /// Decomposes `p`. At the origin itself the direction is undefined and every component but
    /// the radius is reported as 0.
    pub fn of(p: &PointMotion) -> Self {
        let radius = p.position.norm();
        if radius == 0.0 {
            return Self::default();
        }
        let er = p.position / radius;
        let et = crate::C::new(-er.im, er.re);
        let dot = |a: crate::C, b: crate::C| a.re * b.re + a.im * b.im;
        let radial_velocity = dot(p.velocity, er);
        let tangential_velocity = dot(p.velocity, et);
        let angular_velocity = tangential_velocity / radius;
        let coriolis_acceleration = 2.0 * radial_velocity * angular_velocity;
        let normal_acceleration = -radius * angular_velocity * angular_velocity;
        let radial_acceleration = dot(p.acceleration, er) - normal_acceleration;
        let tangential_acceleration = dot(p.acceleration, et) - coriolis_acceleration;
        Self {
            radius,
            radial_velocity,
            tangential_velocity,
            angular_velocity,
            radial_acceleration,
            coriolis_acceleration,
            tangential_acceleration,
            normal_acceleration,
            angular_acceleration: tangential_acceleration / radius,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::C;
    use approx::assert_relative_eq;

    /// A point on a spiral r(t) = 1 + t², φ(t) = 2t + t³: the components must match the
    /// derivatives of r and φ taken by hand.
    #[test]
    fn components_match_hand_derivatives() {
        let t: f64 = 0.7;
        let (r, dr, ddr) = (1.0 + t * t, 2.0 * t, 2.0);
        let (phi, dphi, ddphi) = (2.0 * t + t.powi(3), 2.0 + 3.0 * t * t, 6.0 * t);
        let e = C::from_polar(1.0, phi);
        let i = C::i();
        let p = PointMotion {
            position: r * e,
            velocity: dr * e + r * i * dphi * e,
            acceleration: ddr * e + 2.0 * dr * dphi * i * e + r * ddphi * i * e
                - r * dphi * dphi * e,
        };
        let c = PolarComponents::of(&p);
        assert_relative_eq!(c.radial_velocity, dr, max_relative = 1e-13);
        assert_relative_eq!(c.angular_velocity, dphi, max_relative = 1e-13);
        assert_relative_eq!(c.radial_acceleration, ddr, max_relative = 1e-12);
        assert_relative_eq!(c.angular_acceleration, ddphi, max_relative = 1e-12);
        assert_relative_eq!(
            c.coriolis_acceleration,
            2.0 * dr * dphi,
            max_relative = 1e-13
        );
        assert_relative_eq!(
            c.normal_acceleration,
            -r * dphi * dphi,
            max_relative = 1e-13
        );
    }
}
