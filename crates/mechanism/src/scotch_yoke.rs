//! The Scotch yoke: the crank pin carries a sliding block that runs in a slot of the yoke,
//! across the cylinder axis; the yoke, its rod and the piston reciprocate on the axis. Pure
//! harmonic piston motion, the same as the cardan gear's of equal stroke, with a sliding pair
//! where the cardan gear has its gear pair (Karhula 2008 ch. 2 mentions it as the Bourke
//! engine's mechanism; kinematics below from the geometry).
//!
//! The crank OA has length r (half the stroke); the slot's centre line is at y = r·sin θ, so the
//! piston pin is at x = r·sin θ + l (l from the slot centre line to the piston pin).
//!
//! Bodies: crankshaft, block (on the crank pin, massless: it is small and rides on the pin),
//! yoke (with its rod and the piston). Joints: `main_bearing` (crankshaft–frame), `crank_pin`
//! (crankshaft–block), `yoke_slot` (yoke–block, a slide across the cylinder axis),
//! `piston_side` (yoke–cylinder and guides, a slide along the axis). The slot can push only
//! along the cylinder axis, at the block, off the axis by r·cos θ: the guides answer with a
//! couple and no side force.

use crate::mass::{self, MassInputs, MassProperties};
use crate::model::{cross, Bearings, Body, Joint, Piston, PistonMotion, Topology};
use crate::{check_length, check_rod_cg, Entry, Input, MachineGeometry, Mechanism};
use crate::{vectorised, Column, LoadsBlock, StateBlock, LANES, ZERO};
use crate::{MechanismError, Options, PointMotion, C};

/// The registry line.
pub const ENTRY: Entry = Entry {
    name: "scotch_yoke",
    summary: "crank pin with a block sliding in a slotted yoke: harmonic piston motion, slot and guide loads",
    options: &[],
    unused_masses: &["wheel_inertia", "wheel_mass"],
    pin_offset: false,
    build: |g, m, o| Ok(Box::new(ScotchYoke::build(g, m, o)?)),
};

const CRANKSHAFT: usize = 0;
const BLOCK: usize = 1;
const YOKE: usize = 2;

/// Scotch yoke geometry and masses.
#[derive(Debug, Clone, PartialEq)]
pub struct ScotchYoke {
    /// Crank length, m: half the stroke.
    pub crank: f64,
    /// From the slot centre line to the piston pin, m.
    pub rod: f64,
    pub masses: MassProperties,
    topology: Topology,
}

impl ScotchYoke {
    /// The yoke of `geometry`'s stroke and rod. Masses: the chapter-10 rules of the other
    /// mechanisms, the yoke with its rod estimated as the cardan gear's rod (this project's
    /// estimate: a bar of the rod rule; override `rod_mass` for a real yoke).
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
            MassProperties::resolve(estimate, inputs),
            geometry.bearings(),
        )
    }

    /// A yoke of crank `crank` and rod `rod` (m), with `masses` and bearings [piston pin
    /// (unused), crank pin, main axis].
    pub fn new(
        crank: f64,
        rod: f64,
        masses: MassProperties,
        bearings: [Bearings; 3],
    ) -> Result<Self, MechanismError> {
        check_length(Input::CrankLength, crank)?;
        check_length(Input::RodLength, rod)?;
        if rod <= crank {
            return Err(MechanismError::new(
                Input::RodLength,
                rod,
                format!("must be longer than geometry.crank_length ({crank} m): the piston would reach the crank"),
            ));
        }
        check_rod_cg(masses.rod_cg, rod)?;
        let [_, r_crank, r_main] = bearings;
        let topology = Topology {
            bodies: vec![
                Body::new("crankshaft", 0.0, masses.crankshaft_inertia),
                Body::new("block", 0.0, 0.0),
                Body::new(
                    "yoke",
                    masses.rod_mass + masses.piston_mass,
                    masses.rod_inertia,
                ),
            ],
            joints: vec![
                Joint::pin("main_bearing", r_main, CRANKSHAFT, None),
                Joint::pin("crank_pin", r_crank, CRANKSHAFT, Some(BLOCK)),
                Joint::slide("yoke_slot", YOKE, Some(BLOCK)),
                Joint::slide("piston_side", YOKE, None),
            ],
            pistons: vec![Piston::in_line(YOKE, 0.0)],
            crankshaft: CRANKSHAFT,
            extras: vec![],
        };
        Ok(Self {
            crank,
            rod,
            masses,
            topology,
        })
    }
}

impl Mechanism for ScotchYoke {
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

    fn piston_position(&self, angle: f64) -> (f64, f64) {
        let (s, c) = angle.sin_cos();
        (self.crank * s + self.rod, self.crank * c)
    }

    fn piston_top(&self) -> f64 {
        self.rod + self.crank
    }

    fn piston_bottom(&self) -> f64 {
        self.rod - self.crank
    }

    /// Newton-Euler by hand. The yoke assembly (mass M, on the axis) takes from the block, along
    /// the axis, F_s = M·a + F_gas (all its other forces are along the axis too, so the guides
    /// carry no side force); F_s acts at the block, r·cos θ off the axis, so the guides answer
    /// with the couple −r·cos θ·F_s. The massless block passes F_s on to the crank pin; the
    /// drive supplies J·α + r·cos θ·F_s (= (M·a + F_gas)·v/ω: the power balance).
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
    /// Writes only the columns that are not zero at every step (a block starts zeroed): the
    /// fill is bound by its stores.
    fn fill(machine: &ScotchYoke, block: &mut StateBlock) {
        let Some((n, cc, [shaft, slider, yoke], [main, pin, slot, guide], [piston])) = block.split()
        else {
            unreachable!("the Scotch yoke's topology")
        };
        let r = machine.crank;
        for i in 0..n {
            let crank = &cc.at(i);
            let (w, a) = (crank.speed, crank.acceleration);
            let e_a = crank.direction;
            let (s, c) = (e_a.im, e_a.re);
            let crank_pin = PointMotion::on_crank(r, crank);
            // The slot centre line follows the pin's height: y = r·sin θ and its derivatives.
            let (y, v, acc) = (r * s, r * w * c, r * (a * c - w * w * s));
            // The crankshaft turns about its centre of gravity, on the main axis.
            shaft.orientation_x[i] = c;
            shaft.orientation_y[i] = s;
            shaft.angular_velocity[i] = w;
            shaft.angular_acceleration[i] = a;
            // The block rides on the crank pin without turning.
            slider.cg.set(i, &crank_pin);
            slider.orientation_x[i] = 1.0;
            // The yoke slides along the cylinder axis (+y) without turning.
            yoke.cg.y[i] = y + machine.masses.rod_cg;
            yoke.cg.vy[i] = v;
            yoke.cg.ay[i] = acc;
            yoke.orientation_y[i] = 1.0;
            main.relative_speed[i] = w;
            pin.x[i] = crank_pin.position.re;
            pin.y[i] = crank_pin.position.im;
            pin.relative_speed[i] = w; // the block does not turn
                                       // The yoke relative to the block, along +x.
            slot.x[i] = crank_pin.position.re;
            slot.y[i] = crank_pin.position.im;
            slot.direction_x[i] = 1.0;
            slot.relative_speed[i] = -crank_pin.velocity.re;
            // The guides, along the axis.
            guide.y[i] = y + machine.rod;
            guide.direction_y[i] = 1.0;
            guide.relative_speed[i] = v;
            piston.set(
                i,
                &PistonMotion {
                    position: y + machine.rod,
                    velocity: v,
                    acceleration: acc,
                    dx_dtheta: r * c,
                    d2x_dtheta2: -r * s,
                },
            );
        }
    }
}

vectorised! {
    /// Newton-Euler by hand. The yoke assembly (mass M, on the axis) takes from the block, along
    /// the axis, F_s = M·a + F_gas (all its other forces are along the axis too, so the guides
    /// carry no side force); F_s acts at the block, r·cos θ off the axis, so the guides answer
    /// with the couple −r·cos θ·F_s. The massless block passes F_s on to the crank pin; the
    /// drive supplies J·α + r·cos θ·F_s (= (M·a + F_gas)·v/ω: the power balance).
    fn closed_form(
        machine: &ScotchYoke,
        st: &StateBlock,
        inertia: bool,
        piston_force: Option<&Column>,
        out: &mut LoadsBlock,
    ) -> bool {
        let (mass, crank_inertia) = if inertia {
            (
                machine.masses.rod_mass + machine.masses.piston_mass,
                machine.masses.crankshaft_inertia,
            )
        } else {
            (0.0, 0.0)
        };
        let (yoke, pin) = (&st.bodies[YOKE], &st.joints[1]);
        let gas = piston_force.unwrap_or(&ZERO);
        let Some(([main, pin_load, slot_load, guide_load], crank_torque)) = out.split() else {
            unreachable!("the Scotch yoke's topology")
        };
        for i in 0..st.len.min(LANES) {
            let yoke = yoke.at(i).cg;
            let slot = mass * yoke.acceleration + C::new(0.0, gas[i]);
            let a_pin = pin.at(i).position;
            // Forces at the pins and the slot, a couple alone at the guides (the other
            // columns stay zero).
            main.set_force(i, slot);
            pin_load.set_force(i, -slot);
            slot_load.set_force(i, slot);
            guide_load.moment[i] = -cross(a_pin - yoke.position, slot);
            crank_torque[i] = crank_inertia * st.crank.acceleration[i] + cross(a_pin, slot);
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::CrankState;
    use crate::Loads;
    use approx::assert_relative_eq;

    /// With only a gas force F at θ = 0 (pin at (r, 0)): the slot pushes F, the guide couple is
    /// −r·F, the drive torque r·F.
    #[test]
    fn a_gas_force_by_hand() {
        let g = MachineGeometry {
            crank_length: 0.05,
            rod_length: 0.2,
            bore: 0.1,
            pin_offset: 0.0,
        };
        let y = ScotchYoke::build(&g, &MassInputs::default(), &Options::new()).unwrap();
        let st = y.state(&CrankState::new(0.0, 10.0, 0.0, 0.0));
        let mut out = Loads::for_topology(y.topology());
        assert!(y.closed_form_loads(&st, false, &[1000.0], &mut out));
        assert_relative_eq!(out.crank_torque, 50.0, max_relative = 1e-15);
        assert_relative_eq!(out.joints[3].moment, -50.0, max_relative = 1e-15);
        assert_eq!(out.joints[3].force, C::new(0.0, 0.0));
        assert_relative_eq!(out.joints[1].force.im, -1000.0);
        assert_relative_eq!(y.stroke(), 0.1, max_relative = 1e-15);
    }

    /// The yoke moves its piston exactly as the cardan gear of the same stroke does.
    #[test]
    fn piston_motion_is_the_cardan_gears() {
        let g = MachineGeometry {
            crank_length: 0.06,
            rod_length: 0.14,
            bore: 0.12,
            pin_offset: 0.0,
        };
        let yoke = ScotchYoke::build(&g, &MassInputs::default(), &Options::new()).unwrap();
        let cardan = crate::CardanGear::build(&g, &MassInputs::default(), &Options::new()).unwrap();
        let motion = crate::CrankMotion {
            start_angle: 0.3,
            initial_speed: 50.0,
            angular_acceleration: 400.0,
        };
        for crank in motion.grid(0.3, 13.0, 997).unwrap() {
            let (p, q) = (
                yoke.state(&crank).pistons[0],
                cardan.state(&crank).pistons[0],
            );
            for (a, b) in [
                (p.position, q.position),
                (p.velocity, q.velocity),
                (p.acceleration, q.acceleration),
                (p.dx_dtheta, q.dx_dtheta),
                (p.d2x_dtheta2, q.d2x_dtheta2),
            ] {
                assert!((a - b).abs() <= 1e-12 * (1.0 + b.abs()), "{a} vs {b}");
            }
        }
        assert_eq!(yoke.stroke(), cardan.stroke());
    }
}
