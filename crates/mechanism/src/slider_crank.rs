//! The slider-crank mechanism, Karhula (2008) eqs. (A4.2.2.1)-(A4.2.2.55) and its closed-form
//! kinetostatics (A5.2.1.1)-(A5.2.1.39), extended with a piston-pin offset and a force on the
//! piston (the gas).
//!
//! The piston pin B slides on the line Re(Z) = e (e = pin offset; e = 0 is the thesis's in-line
//! machine). The closure Z_AA0·cos θ + Z_BA·cos θ_BA = e gives θ_BA = arccos((e − Z_AA0·cos θ)/Z_BA),
//! which for e = 0 is (A4.2.2.3). Its time derivatives give ω_BA (A4.2.2.12) and α_BA
//! (A4.2.2.31) unchanged, because e is constant.
//!
//! Bodies: crankshaft (centre of gravity on the main axis), rod, piston (with its pin, a point
//! mass at the pin). Joints: `main_bearing` (crankshaft–frame), `crank_pin` (crankshaft–rod),
//! `piston_pin` (piston–rod), `piston_side` (piston–cylinder wall, a slide along the axis).

use crate::mass::{self, MassInputs, MassProperties};
use crate::model::{
    cross, Bearings, Body, ExtraColumn, Joint, Piston, PistonMotion, State, Topology,
};
use crate::{check_length, check_rod_cg, CrankState, Entry, Input, MachineGeometry, Mechanism};
use crate::{
    vectorised, BodyColumns, Column, CrankColumns, JointColumns, LoadsBlock, PistonColumns,
    StateBlock, LANES, ZERO,
};
use crate::{BodyMotion, MechanismError, Options, PointMotion, C};

/// The registry line.
pub const ENTRY: Entry = Entry {
    name: "slider_crank",
    summary:
        "crank, connecting rod and piston (Karhula 2008 A4.2.2, A5.2.1), with a piston-pin offset",
    options: &[],
    unused_masses: &["wheel_inertia", "wheel_mass"],
    pin_offset: true,
    build: |g, m, o| Ok(Box::new(SliderCrank::build(g, m, o)?)),
};

const CRANKSHAFT: usize = 0;
const ROD: usize = 1;
const PISTON: usize = 2;

/// The columns of a block that the slider-crank's fill reads (the crank's) and writes (the
/// rest stay zero).
struct SliderCrankColumns<'a> {
    crank: &'a CrankColumns,
    shaft: &'a mut BodyColumns,
    rod: &'a mut BodyColumns,
    piston: &'a mut BodyColumns,
    joints: &'a mut [JointColumns; 4],
    cylinder: &'a mut PistonColumns,
}

/// Slider-crank geometry and masses.
#[derive(Debug, Clone, PartialEq)]
pub struct SliderCrank {
    /// Crank length Z_AA0, m.
    pub crank: f64,
    /// Connecting rod length Z_BA (pin centre to pin centre), m.
    pub rod: f64,
    /// Piston pin offset e from the cylinder axis through the main bearing, m (positive towards +x).
    pub pin_offset: f64,
    pub masses: MassProperties,
    topology: Topology,
    /// 1/rod, 1/m.
    inverse_rod: f64,
}

impl SliderCrank {
    /// The slider-crank of `geometry` with the masses of `inputs` (chapter-10 rules elsewhere).
    pub fn build(
        geometry: &MachineGeometry,
        inputs: &MassInputs,
        _options: &Options,
    ) -> Result<Self, MechanismError> {
        let (crank, rod) = (geometry.crank_length, geometry.rod_length);
        let estimate = mass::estimate_for(inputs, crank, rod, geometry.bore);
        Self::new(
            crank,
            rod,
            geometry.pin_offset,
            MassProperties::resolve(estimate, inputs),
            geometry.bearings(),
        )
    }

    /// A slider-crank of crank `crank`, rod `rod`, pin offset `pin_offset` (m), with `masses`
    /// and bearings [piston pin, crank pin, main axis].
    pub fn new(
        crank: f64,
        rod: f64,
        pin_offset: f64,
        masses: MassProperties,
        bearings: [Bearings; 3],
    ) -> Result<Self, MechanismError> {
        check_length(Input::CrankLength, crank)?;
        check_length(Input::RodLength, rod)?;
        if !pin_offset.is_finite() {
            return Err(MechanismError::new(
                Input::PinOffset,
                pin_offset,
                "must be finite",
            ));
        }
        if rod <= crank {
            return Err(MechanismError::new(
                Input::RodLength,
                rod,
                format!("must be longer than geometry.crank_length ({crank} m): a rod no longer than its crank cannot turn it"),
            ));
        }
        if rod <= crank + pin_offset.abs() {
            return Err(MechanismError::new(
                Input::PinOffset,
                pin_offset,
                format!(
                    "geometry.rod_length {rod} m must be longer than geometry.crank_length {crank} m \
                     plus |pin_offset|, or the rod cannot reach the cylinder axis at every crank angle"
                ),
            ));
        }
        check_rod_cg(masses.rod_cg, rod)?;
        let [r_pis, r_crank, r_main] = bearings;
        let topology = Topology {
            bodies: vec![
                Body::new("crankshaft", 0.0, masses.crankshaft_inertia),
                Body::new("rod", masses.rod_mass, masses.rod_inertia),
                Body::new("piston", masses.piston_mass, 0.0),
            ],
            joints: vec![
                Joint::pin("main_bearing", r_main, CRANKSHAFT, None),
                Joint::pin("crank_pin", r_crank, CRANKSHAFT, Some(ROD)),
                Joint::pin("piston_pin", r_pis, PISTON, Some(ROD)),
                Joint::slide("piston_side", PISTON, None),
            ],
            pistons: vec![Piston::in_line(PISTON, pin_offset)],
            crankshaft: CRANKSHAFT,
            extras: vec![ExtraColumn {
                name: "rod_percussion_centre_m",
                meaning: "distance from the crank pin along the rod of the rod's centre of percussion, where its inertial force acts with no couple (A5.2.1.6-7); empty where undefined",
            }],
        };
        Ok(Self {
            crank,
            rod,
            pin_offset,
            masses,
            topology,
            inverse_rod: 1.0 / rod,
        })
    }

    /// cos θ_BA, sin θ_BA, and dθ_BA/dθ and d²θ_BA/dθ² (the rod's angular velocity and
    /// acceleration per unit crank speed at zero crank acceleration), from cos θ and sin θ.
    #[inline(always)]
    fn rod_angles(&self, c: f64, s: f64) -> (f64, f64, f64, f64) {
        let (r, l) = (self.crank, self.rod);
        // One division per step: 1/l is the topology's constant.
        let cos_ba = (self.pin_offset - r * c) * self.inverse_rod; // (A4.2.2.3)
        let sin_ba = (1.0 - cos_ba * cos_ba).sqrt(); // θ_BA in (0, π): the piston is above the crank
        let inv = self.inverse_rod / sin_ba;
        let d1 = -r * s * inv; // (A4.2.2.12) at ω = 1
        let d2 = -(r * c + l * d1 * d1 * cos_ba) * inv; // (A4.2.2.31) at ω = 1, α = 0
        (cos_ba, sin_ba, d1, d2)
    }

    /// Lane `lane` of a block's `parts` at the crank state `crank`, with the rod angles
    /// (cos θ_BA, sin θ_BA, dθ_BA/dθ, d²θ_BA/dθ²) of [`Self::rod_angles`] given.
    // Inlined into `fill_block`'s loop, which the compiler then vectorises across lanes.
    #[inline(always)]
    fn fill_lane(
        &self,
        crank: &CrankState,
        (cos_ba, sin_ba, d1, d2): (f64, f64, f64, f64),
        parts: &mut SliderCrankColumns,
        lane: usize,
    ) {
        let (w, a) = (crank.speed, crank.acceleration);
        let (r, l) = (self.crank, self.rod);
        let i = C::i();
        let e_a = crank.direction;
        let crank_pin = PointMotion::on_crank(r, crank);
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
        let rod_cg = along(self.masses.rod_cg);
        // The crankshaft turns about its centre of gravity, on the main axis.
        let shaft = &mut *parts.shaft;
        shaft.orientation_x[lane] = e_a.re;
        shaft.orientation_y[lane] = e_a.im;
        shaft.angular_velocity[lane] = w;
        shaft.angular_acceleration[lane] = a;
        parts.rod.set(
            lane,
            &BodyMotion {
                cg: rod_cg,
                orientation: e_ba,
                angular_velocity: w_ba,
                angular_acceleration: a_ba,
            },
        );
        // The piston slides along the cylinder without turning.
        let piston = &mut *parts.piston;
        piston.cg.x[lane] = piston_pin.position.re;
        piston.cg.y[lane] = piston_pin.position.im;
        piston.cg.vy[lane] = piston_pin.velocity.im;
        piston.cg.ay[lane] = piston_pin.acceleration.im;
        piston.orientation_x[lane] = 1.0;
        // Relative speeds of the joints (A9.1.14-18), body relative to other.
        let [main, crank_pin_joint, piston_pin_joint, slide] = &mut *parts.joints;
        main.relative_speed[lane] = w;
        crank_pin_joint.x[lane] = crank_pin.position.re;
        crank_pin_joint.y[lane] = crank_pin.position.im;
        crank_pin_joint.relative_speed[lane] = w - w_ba;
        piston_pin_joint.x[lane] = piston_pin.position.re;
        piston_pin_joint.y[lane] = piston_pin.position.im;
        piston_pin_joint.relative_speed[lane] = -w_ba;
        slide.x[lane] = piston_pin.position.re;
        slide.y[lane] = piston_pin.position.im;
        slide.direction_y[lane] = 1.0; // the cylinder axis
        slide.relative_speed[lane] = pin.velocity.im;
        // dx/dθ and d²x/dθ²: the piston velocity and acceleration at ω = 1 rad/s, α = 0.
        parts.cylinder.set(
            lane,
            &PistonMotion {
                position: pin.position.im,
                velocity: pin.velocity.im,
                acceleration: pin.acceleration.im,
                dx_dtheta: r * e_a.re + l * d1 * cos_ba,
                d2x_dtheta2: -r * e_a.im + l * (d2 * cos_ba - d1 * d1 * sin_ba),
            },
        );
    }
}

impl Mechanism for SliderCrank {
    fn name(&self) -> &'static str {
        ENTRY.name
    }

    fn topology(&self) -> &Topology {
        &self.topology
    }

    fn masses(&self) -> &MassProperties {
        &self.masses
    }

    fn fill_block(&self, block: &mut StateBlock) {
        fill(self, block);
    }

    fn fill_extras(&self, st: &mut State) {
        let rod = &st.bodies[ROD];
        let (e_ba, a_ba) = (rod.orientation, rod.angular_acceleration);
        let rod_cg = rod.cg;
        // The centre of percussion (A5.2.1.6-8): where the rod's inertial force −m·a_g, with
        // the inertial couple −J·α_BA, acts alone; undefined where that force is along the rod.
        let f = -self.masses.rod_mass * rod_cg.acceleration;
        let moment = cross(self.masses.rod_cg * e_ba, f) - self.masses.rod_inertia * a_ba;
        let arm = cross(e_ba, f);
        st.extras[0] = if arm.abs() > 1e-12 * f.norm().max(f64::MIN_POSITIVE) {
            moment / arm
        } else {
            f64::NAN
        };
    }

    /// x = Z_AA0·sin θ + Z_BA·sin θ_BA and its θ-derivative, as in [`Mechanism::fill_block`].
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

    /// Karhula (2008) A5.2.1.1-39. As in the thesis the loads are superposed: the rod's inertia
    /// with a massless piston, then the piston's inertia (and the applied force) with a
    /// massless rod. All joints are frictionless.
    fn closed_form_block(
        &self,
        st: &StateBlock,
        inertia: bool,
        piston_force: Option<&Column>,
        out: &mut LoadsBlock,
    ) -> bool {
        closed_form(self, st, inertia, piston_force, out)
    }
}

vectorised! {
    /// One loop over the lanes, square roots and divisions included, which the compiler
    /// vectorises: columns written straight, the columns that are zero at every step left alone.
    fn fill(slider: &SliderCrank, block: &mut StateBlock) {
        let Some((n, crank, [shaft, rod, piston], joints, [cylinder])) = block.split() else {
            unreachable!("the slider-crank's topology")
        };
        let mut parts = SliderCrankColumns {
            crank,
            shaft,
            rod,
            piston,
            joints,
            cylinder,
        };
        for i in 0..n {
            let c = parts.crank.at(i);
            let angles = slider.rod_angles(c.direction.re, c.direction.im);
            slider.fill_lane(&c, angles, &mut parts, i);
        }
    }
}

vectorised! {
    /// Karhula (2008) A5.2.1.1-39. As in the thesis the loads are superposed: the rod's inertia
    /// with a massless piston, then the piston's inertia (and the applied force) with a
    /// massless rod. All joints are frictionless.
    fn closed_form(
        slider: &SliderCrank,
        st: &StateBlock,
        inertia: bool,
        piston_force: Option<&Column>,
        out: &mut LoadsBlock,
    ) -> bool {
        let m = &slider.masses;
        let (rod_mass, rod_inertia, piston_mass, crank_inertia) = if inertia {
            (
                m.rod_mass,
                m.rod_inertia,
                m.piston_mass,
                m.crankshaft_inertia,
            )
        } else {
            (0.0, 0.0, 0.0, 0.0)
        };
        let (rod, piston, crank_pin) = (&st.bodies[ROD], &st.bodies[PISTON], &st.joints[1]);
        let gas = piston_force.unwrap_or(&ZERO);
        let Some(([main, crank_pin_load, piston_pin_load, slide_load], crank_torque)) = out.split()
        else {
            unreachable!("the slider-crank's topology")
        };
        for i in 0..st.len.min(LANES) {
            let rod = rod.at(i);
            let a_pin = crank_pin.at(i).position;
            let e_rod = rod.orientation;
            // One reciprocal of the rod's sine serves both divisions below.
            let inverse_sin = 1.0 / e_rod.im;

            // Rod with a massless piston. Its inertial force −m2·a_g2 (A5.2.1.4) and inertial
            // couple −J2·α_BA (5.1.2) have the moment M_i about the crank pin (A5.2.1.6-8). The
            // massless piston can only pass on a force across the cylinder, so the piston pin
            // force on the rod is horizontal, and moments about the crank pin give it
            // (A5.2.1.9-10).
            let f_ine2 = -rod_mass * rod.cg.acceleration;
            let couple = -rod_inertia * rod.angular_acceleration;
            let moment_about_crank_pin = cross(m.rod_cg * e_rod, f_ine2) + couple;
            let f_piston_on_rod =
                C::new(moment_about_crank_pin * slider.inverse_rod * inverse_sin, 0.0);
            let f_crank_on_rod_2 = -f_ine2 - f_piston_on_rod; // (A5.2.1.11)

            // Piston with a massless rod: the rod is a two-force member along its line
            // (A5.2.1.17-22).
            let load = -piston_mass * piston.at(i).cg.acceleration - C::new(0.0, gas[i]);
            let f_rod_on_piston_3 = -load.im * inverse_sin * e_rod;
            let side_3 = -(load.re + f_rod_on_piston_3.re); // (A5.2.1.20)

            let f_crank_on_rod = f_crank_on_rod_2 + f_rod_on_piston_3; // (A5.2.1.27)
            let crankshaft = crank_inertia * st.crank.acceleration[i]; // −T_ine1 (A5.2.1.1)
            let rod_share = -cross(a_pin, -f_crank_on_rod_2); // −T_2i10 (A5.2.1.15)
            let piston_share = -cross(a_pin, -f_rod_on_piston_3); // −T_3i10 (A5.2.1.23)

            // (A5.2.1.25): the crankshaft's centre of gravity is on its axis. No couple at the
            // pins nor, with the pin at the piston's centre of gravity, at the slide; and the
            // slide carries no force along it (those columns stay zero).
            main.set_force(i, f_crank_on_rod);
            crank_pin_load.set_force(i, -f_crank_on_rod); // (A5.2.1.28)
            piston_pin_load.set_force(i, f_rod_on_piston_3 - f_piston_on_rod);
            slide_load.fx[i] = f_piston_on_rod.re + side_3;
            crank_torque[i] = crankshaft + rod_share + piston_share; // −T_Σi10 (A5.2.1.36)
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mass::Material;
    use approx::assert_relative_eq;

    fn machine(offset: f64) -> SliderCrank {
        let mut masses = mass::estimate(0.06, 0.14, 0.12, Material::Steel);
        masses.rod_cg = 0.07;
        SliderCrank::new(0.06, 0.14, offset, masses, [Bearings::single(0.01, 1e4); 3]).unwrap()
    }

    #[test]
    fn rod_closes_on_the_piston_pin_and_dead_centres() {
        let m = machine(0.0);
        let st = m.state(&CrankState::new(1.0, 10.0, 3.0, 0.0));
        let tip = st.joints[1].position + m.rod * st.bodies[ROD].orientation;
        assert!((tip - st.joints[2].position).norm() < 1e-15);
        let top = m.state(&CrankState::new(std::f64::consts::FRAC_PI_2, 1.0, 0.0, 0.0));
        assert_relative_eq!(top.pistons[0].position, 0.2, max_relative = 1e-15);
        assert_relative_eq!(m.stroke(), 0.12, max_relative = 1e-14);
        // With an offset the stroke grows slightly: sqrt((l+r)²−e²) − sqrt((l−r)²−e²).
        let off = machine(0.02);
        assert_relative_eq!(
            off.stroke(),
            (0.2f64.powi(2) - 0.0004).sqrt() - (0.08f64.powi(2) - 0.0004).sqrt(),
            max_relative = 1e-14
        );
        assert!(off.stroke() > 0.12);
        // Top dead centre: the pin reaches piston_top there, with zero dx/dθ; an offset
        // towards +x turns it back from π/2.
        for m in [machine(0.0), off, machine(-0.02)] {
            let tdc = m.state(&CrankState::new(m.top_dead_centre(), 1.0, 0.0, 0.0));
            assert_relative_eq!(
                tdc.pistons[0].position,
                m.piston_top(),
                max_relative = 1e-14
            );
            assert!(tdc.pistons[0].dx_dtheta.abs() < 1e-14);
        }
        assert!(machine(0.02).top_dead_centre() < std::f64::consts::FRAC_PI_2);
    }

    #[test]
    fn impossible_machines_are_refused() {
        let masses = mass::estimate(0.06, 0.14, 0.12, Material::Steel);
        let new = |crank, rod, offset| {
            SliderCrank::new(crank, rod, offset, masses, [Bearings::single(0.01, 1e4); 3])
        };
        let field = |r: Result<SliderCrank, MechanismError>| r.unwrap_err().field;
        assert_eq!(field(new(0.06, 0.06, 0.0)), Input::RodLength);
        assert_eq!(field(new(0.06, 0.1, 0.05)), Input::PinOffset);
        assert_eq!(field(new(-0.06, 0.14, 0.0)), Input::CrankLength);
        assert_eq!(field(new(0.06, f64::NAN, 0.0)), Input::RodLength);
        let mut far = masses;
        far.rod_cg = 0.2;
        assert_eq!(
            field(SliderCrank::new(
                0.06,
                0.14,
                0.0,
                far,
                [Bearings::single(0.01, 1e4); 3]
            )),
            Input::RodCg
        );
    }
}
