//! The cardan gear (geared hypocycloid with a 2:1 internal pair), Karhula (2008) appendix 4.2.1,
//! eqs. (A4.2.2.56)-(A4.2.2.74), and its closed-form kinetostatics (A5.2.1.40)-(A5.2.1.72),
//! extended with a force on the piston (the gas).
//!
//! The crank OS has length r = Z_AA0C; the cardan wheel (planet, pitch radius r) turns on the
//! crank pin S and rolls inside the ring gear (pitch radius 2r). The wheel pin T, on the wheel's
//! pitch circle, moves on the cylinder axis: Z_TO = 2r·sin θ·e^{i·90°} (A4.2.2.60). The rod
//! carries the piston at its upper end b = T + Z_bB·e^{i·90°} (A4.2.2.62-63) and does not turn.
//! Same stroke as the slider-crank of crank 2r.
//!
//! Bodies: crankshaft, cardan wheel (its mass carried by the balanced crankshaft, ch. 11.2,
//! unless the case gives `wheel_mass`: then the wheel carries it at its centre S, which moves on
//! the crank's circle; its inertia force −m_w·a_S acts at S and reaches the crank pin, and the
//! drive supplies m_w·r²·α for it, S × (m_w·a_S)), rod (with the piston: they move together on the cylinder axis). Joints: `main_bearing`
//! (crankshaft–frame), `crank_pin` (crankshaft–wheel at S), `piston_pin` (rod–wheel at T, the
//! rod's big end, which Karhula A9.1 calls the piston pin bearing), `gear_mesh` (wheel–ring at
//! the pitch point). There is no piston side force: the gears guide the rod.
//!
//! Two readings of the mesh force ([`MeshModel`]):
//! - `karhula` (default, the thesis's): the ring's force on the wheel equals the rod's force P
//!   and is parallel to the cylinder axis, so the crank pin carries 2·P (A5.2.1.48-51). The
//!   wheel's moment balance then holds with no wheel inertia, so the thesis lumps the wheel's
//!   inertia into the crankshaft's. Reading of (A5.2.1.43)-(A5.2.1.46): the thesis adds the
//!   wheel's inertial torque with the opposite sign to the crankshaft's; the wheel's kinetic
//!   energy ½·J_2c·ω² grows whenever the crankshaft speeds up, so that sign breaks the energy
//!   balance. We add the wheel's inertia to the crankshaft's: the drive supplies (J_1c + J_2c)·α
//!   (for the thesis geometry 2·J_2c·α = 0.13 N·m at α = 100π rad/s², 0.9 % of the mean
//!   inertial torque).
//! - `involute`: involute teeth can only push along the line of action, so the mesh force has a
//!   tangential component F_t, fixed by the wheel's moment balance about S including its own
//!   inertia J_w·α_w, and a radial one |F_t|·tan α_p towards the wheel's centre. The drive
//!   torque and the rod force are those of the `karhula` reading; the crank-pin and mesh forces
//!   are not.
//!
//! A rigid mass added to the wheel ([`Mechanism::with_added_mass`]: the cardan counterweight
//! pair's m₂ at ρ from S opposite T, placed by `cardan_balance::MachineBalance::equip`) is part
//! of the wheel: its centre of gravity leaves S for g, and its moment of inertia about g follows
//! from the parallel-axis theorem. The wheel's inertia force −M·a_g acts at g. Its force reaches
//! the crank pin (and through the crankshaft the main bearing) in either reading. Its moment
//! about S, with J_g·α_w, is M_S: what the wheel's loads must supply about S.
//! - `involute`: the mesh's tangential force supplies M_S (the wheel's moment balance, as
//!   for J_w alone).
//! - `karhula`: the mesh force stays the rod's. As the thesis does with the wheel's own inertia,
//!   the drive supplies M_S, through the wheel's speed ratio −1 (virtual power: a moment M on
//!   the wheel turning at −ω takes −M·ω): T += −M_S. For the wheel's own J_w that rule gives
//!   the drive's J_w·α above. It keeps the drive's work equal to the change of kinetic energy
//!   (`crates/dynamics/tests/cross_checks.rs`). In the topology, the wheel with an added
//!   mass is [`crate::Body::lumped`] with ratio −1 (without one the tie holds its moment
//!   balance alone, the general solve as before): the general solve adds the wheel's moment
//!   equation about S, times −1, to the crankshaft's. That is how the general solve meets this
//!   closed form. The added mass's polar moment and offset enter the drive torque in both
//!   readings.

use crate::mass::{self, MassInputs, MassProperties};
use crate::model::{
    cross, Bearings, Body, Joint, JointKind, JointMotion, MeshForce, Piston, PistonMotion, Topology,
};
use crate::{check_length, check_rod_cg, number, word, Entry, Input, MachineGeometry, Mechanism};
use crate::{vectorised, Column, LoadsBlock, StateBlock, LANES, ZERO};
use crate::{MechanismError, OptionKind, OptionSpec, Options, PointMotion, C};

/// The registry line.
pub const ENTRY: Entry = Entry {
    name: "cardan_gear",
    summary: "geared hypocycloid: crank, cardan wheel rolling in a ring gear of twice its size, straight-line rod (Karhula 2008 A4.2.1, A5.2.1)",
    options: &[
        OptionSpec {
            name: "gear_mesh_model",
            kind: OptionKind::Choice(&["karhula", "involute"]),
            meaning: "reading of the mesh force: \"karhula\" (the thesis's, parallel to the cylinder, equal to the rod force) or \"involute\" (along the line of action, with the wheel's own inertia)",
        },
        OptionSpec {
            name: "pressure_angle",
            kind: OptionKind::Angle,
            meaning: "pressure angle of the cardan pair (20° by default; used by the involute reading)",
        },
    ],
    unused_masses: &[],
    pin_offset: false,
    build: |g, m, o| Ok(Box::new(CardanGear::build(g, m, o)?)),
};

const CRANKSHAFT: usize = 0;
const WHEEL: usize = 1;
const ROD: usize = 2;
const PISTON_PIN: usize = 2;

/// Which direction the ring gear's force on the cardan wheel takes (module note).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MeshModel {
    Karhula,
    Involute,
}

/// What has been added to the cardan wheel, in the wheel's frame (real axis along S→T, from
/// its centre S): the sum of the added masses, kg, their first moment Σ m·d, kg·m (complex),
/// and their polar moment about S, Σ (J + m·|d|²), kg·m².
#[derive(Debug, Clone, Copy, PartialEq, Default)]
struct AddedMasses {
    mass: f64,
    first: C,
    polar: f64,
    /// The wheel's centre of gravity (its own mass at S and the added ones) from S, m, in the
    /// wheel's frame: first / (m_w + mass).
    cg: C,
}

/// Cardan gear geometry and masses.
#[derive(Debug, Clone, PartialEq)]
pub struct CardanGear {
    /// Crank length Z_AA0C, m: half the slider-crank crank of equal stroke (eq. 6.1); also the
    /// pitch radius of the cardan wheel, the ring gear having twice it.
    pub crank: f64,
    /// Rod length Z_bBC from the wheel pin T to the piston pin b, m.
    pub rod: f64,
    pub mesh: MeshModel,
    pub masses: MassProperties,
    topology: Topology,
    /// A rigid mass added to the wheel ([`Mechanism::with_added_mass`]: the wheel's
    /// counterweight of the cardan pair); `None` without.
    added: Option<AddedMasses>,
    /// tan of the pair's pressure angle (the involute mesh's radial force per unit tangential
    /// force), computed once: a libm call per block of steps is measurable. The angle itself
    /// is the mesh joint's (`JointKind::GearMesh`).
    tan_pressure_angle: f64,
}

impl CardanGear {
    /// The cardan gear of the same stroke and the same top-dead-centre piston height as the
    /// slider-crank of `geometry` (Karhula eq. 6.1), with the masses of `inputs`.
    pub fn build(
        geometry: &MachineGeometry,
        inputs: &MassInputs,
        options: &Options,
    ) -> Result<Self, MechanismError> {
        let (crank, rod) = (geometry.crank_length, geometry.rod_length);
        check_length(Input::CrankLength, crank)?;
        let mut estimate = mass::estimate_for(inputs, crank, rod, geometry.bore);
        estimate.wheel_inertia = mass::cardan_wheel_inertia(crank);
        let mesh = match word(options, "gear_mesh_model", "karhula") {
            "involute" => MeshModel::Involute,
            _ => MeshModel::Karhula,
        };
        let pressure_angle = number(options, "pressure_angle", 20f64.to_radians());
        if !(pressure_angle > 0.0 && pressure_angle < 45f64.to_radians()) {
            return Err(MechanismError::new(
                Input::Option {
                    mechanism: ENTRY.name,
                    name: "pressure_angle",
                },
                format!("{}°", pressure_angle.to_degrees()),
                "must be between 0° and 45°",
            ));
        }
        Self::new(
            crank / 2.0,
            rod,
            mesh,
            pressure_angle,
            MassProperties::resolve(estimate, inputs),
            geometry.bearings(),
        )
    }

    /// A cardan gear of crank `crank` (the wheel's pitch radius) and rod `rod` (m).
    pub fn new(
        crank: f64,
        rod: f64,
        mesh: MeshModel,
        pressure_angle: f64,
        masses: MassProperties,
        bearings: [Bearings; 3],
    ) -> Result<Self, MechanismError> {
        check_length(Input::CrankLength, crank)?;
        check_length(Input::RodLength, rod)?;
        check_rod_cg(masses.rod_cg, rod)?;
        let [r_pis, r_crank, r_main] = bearings;
        // In the thesis reading the wheel's inertia rides with the crankshaft's (module note).
        let (crankshaft_inertia, wheel_inertia, force) = match mesh {
            MeshModel::Karhula => (
                masses.crankshaft_inertia + masses.wheel_inertia,
                0.0,
                MeshForce::Tied {
                    direction: C::new(0.0, 1.0),
                    joint: PISTON_PIN,
                    factor: -1.0,
                },
            ),
            MeshModel::Involute => (
                masses.crankshaft_inertia,
                masses.wheel_inertia,
                MeshForce::Involute,
            ),
        };
        let topology = Topology {
            bodies: vec![
                Body::new("crankshaft", 0.0, crankshaft_inertia),
                // Without an added mass the thesis's tie holds the wheel's moment balance by
                // itself; with one, the wheel is lumped (`with_wheel_addition`).
                Body::new("wheel", masses.wheel_mass, wheel_inertia),
                Body::new(
                    "rod",
                    masses.rod_mass + masses.piston_mass,
                    masses.rod_inertia,
                ),
            ],
            joints: vec![
                Joint::pin("main_bearing", r_main, CRANKSHAFT, None),
                Joint::pin(
                    "crank_pin",
                    // Two bearings side by side hold the wheel steady (Karhula A9.1.23).
                    Bearings {
                        count: 2,
                        ..r_crank
                    },
                    CRANKSHAFT,
                    Some(WHEEL),
                ),
                Joint::pin("piston_pin", r_pis, ROD, Some(WHEEL)),
                Joint {
                    name: "gear_mesh",
                    kind: JointKind::GearMesh {
                        ratio: 2.0,
                        pitch_radius: crank,
                        internal: true,
                        pressure_angle,
                        force,
                    },
                    body: WHEEL,
                    other: None,
                },
            ],
            pistons: vec![Piston::in_line(ROD, 0.0)],
            crankshaft: CRANKSHAFT,
            extras: vec![],
        };
        Ok(Self {
            crank,
            rod,
            mesh,
            masses,
            topology,
            added: None,
            tan_pressure_angle: pressure_angle.tan(),
        })
    }

    /// The same gear with `mass` (kg) added to the wheel at `offset` (m, in the wheel's frame,
    /// from S) with its own polar moment `inertia` (kg·m²): the wheel body's mass, centre of
    /// gravity and moment of inertia about it (its own J_w in the involute reading, 0 in the
    /// thesis's where the crankshaft carries J_w; the added masses' by parallel axes).
    fn with_wheel_addition(mut self, mass: f64, offset: C, inertia: f64) -> Self {
        let m = &self.masses;
        let own = match self.mesh {
            MeshModel::Karhula => 0.0,
            MeshModel::Involute => m.wheel_inertia,
        };
        let mut added = self.added.unwrap_or_default();
        added.mass += mass;
        added.first += mass * offset;
        added.polar += inertia + mass * offset.norm_sqr();
        let total = m.wheel_mass + added.mass;
        added.cg = if total > 0.0 {
            added.first / total
        } else {
            C::new(0.0, 0.0)
        };
        let wheel = &mut self.topology.bodies[WHEEL];
        // The thesis lumps the wheel with the crankshaft (module note).
        wheel.lumped = (self.mesh == MeshModel::Karhula).then_some(-1.0);
        wheel.mass = total;
        // I_S = J_g + M·|e|² (Beer & Johnston's parallel-axis theorem).
        wheel.inertia = own + added.polar - total * added.cg.norm_sqr();
        self.added = Some(added);
        self
    }
}

impl Mechanism for CardanGear {
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
        (2.0 * self.crank * s + self.rod, 2.0 * self.crank * c)
    }

    fn piston_top(&self) -> f64 {
        self.rod + 2.0 * self.crank
    }

    fn piston_bottom(&self) -> f64 {
        self.rod - 2.0 * self.crank
    }

    /// The cardan wheel (body 1) takes an added mass: its centre of gravity leaves S, its
    /// inertia force reaches the crank pin, and its moment about S the mesh (involute reading)
    /// or the drive (the thesis's, module note).
    fn with_added_mass(
        &self,
        body: usize,
        mass: f64,
        offset: C,
        inertia: f64,
    ) -> Option<Box<dyn Mechanism>> {
        let valid = mass.is_finite() && mass >= 0.0 && inertia.is_finite() && inertia >= 0.0;
        let placed = offset.re.is_finite() && offset.im.is_finite();
        (body == WHEEL && valid && placed).then(|| {
            Box::new(self.clone().with_wheel_addition(mass, offset, inertia)) as Box<dyn Mechanism>
        })
    }

    /// The crank OS: the cardan wheel's centre, where the crank takes the wheel's force.
    fn crank_radius(&self) -> f64 {
        self.crank
    }

    /// The reciprocating assembly (piston, pin and rod, ch. 11.2) moves on the cylinder axis;
    /// its inertial force plus the applied force, P, reaches the cardan wheel at T
    /// (A5.2.1.47-48). The mesh force follows the reading (module note).
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
    fn fill(gear: &CardanGear, block: &mut StateBlock) {
        let Some((n, cc, [shaft, wheel, rod], [main, pin, rod_pin, mesh], [piston])) = block.split()
        else {
            unreachable!("the cardan gear's topology")
        };
        let r = gear.crank;
        let added = gear.added.map(|a| a.cg);
        for i in 0..n {
            let crank = &cc.at(i);
            let (w, a) = (crank.speed, crank.acceleration);
            let e_a = crank.direction;
            let (s, c) = (e_a.im, e_a.re);
            // T on the cylinder axis: (A4.2.2.60), (A4.2.2.68), (A4.2.2.73).
            let y = 2.0 * r * s;
            let v = 2.0 * r * w * c;
            let acc = 2.0 * r * (a * c - w * w * s);
            // The crankshaft turns about its centre of gravity, on the main axis.
            shaft.orientation_x[i] = c;
            shaft.orientation_y[i] = s;
            shaft.angular_velocity[i] = w;
            shaft.angular_acceleration[i] = a;
            // The wheel's centre is the crank pin; it turns at −ω (A4.2.2.66, A4.2.2.71); the
            // line S→T is at π − θ.
            let crank_pin = PointMotion::on_crank(r, crank);
            match added {
                // Its centre of gravity e off S in its frame, turning at −ω: o·e, o·e·(−iω),
                // o·e·(−iα − ω²), o = −c + i·s its orientation.
                Some(e) => {
                    let p = C::new(-c, s) * e;
                    wheel.cg.set(
                        i,
                        &PointMotion {
                            position: crank_pin.position + p,
                            velocity: crank_pin.velocity + p * C::new(0.0, -w),
                            acceleration: crank_pin.acceleration + p * C::new(-w * w, -a),
                        },
                    );
                }
                None => wheel.cg.set(i, &crank_pin),
            }
            wheel.orientation_x[i] = -c;
            wheel.orientation_y[i] = s;
            wheel.angular_velocity[i] = -w;
            wheel.angular_acceleration[i] = -a;
            // The rod slides along the cylinder axis (+y) without turning.
            rod.cg.y[i] = y + gear.masses.rod_cg;
            rod.cg.vy[i] = v;
            rod.cg.ay[i] = acc;
            rod.orientation_y[i] = 1.0;
            // Body relative to other: crankshaft to wheel 2ω; rod to wheel +ω (A9.1.15,
            // A9.1.17).
            main.relative_speed[i] = w;
            pin.x[i] = crank_pin.position.re;
            pin.y[i] = crank_pin.position.im;
            pin.relative_speed[i] = 2.0 * w;
            rod_pin.y[i] = y;
            rod_pin.relative_speed[i] = w;
            // The pitch point, towards the wheel's centre, and (A8.1.7) the pitch-line
            // velocity, twice the crank-pin speed.
            mesh.set(
                i,
                &JointMotion {
                    position: 2.0 * r * e_a,
                    direction: -e_a,
                    relative_speed: 2.0 * r * w,
                },
            );
            piston.set(
                i,
                &PistonMotion {
                    position: y + gear.rod,
                    velocity: v,
                    acceleration: acc,
                    dx_dtheta: 2.0 * r * c,
                    d2x_dtheta2: -2.0 * r * s,
                },
            );
        }
    }
}

vectorised! {
    fn closed_form(
        gear: &CardanGear,
        st: &StateBlock,
        inertia: bool,
        piston_force: Option<&Column>,
        out: &mut LoadsBlock,
    ) -> bool {
        let m = &gear.masses;
        let (mass, crank_inertia, wheel_inertia, wheel_mass) = if inertia {
            (
                m.rod_mass + m.piston_mass,
                m.crankshaft_inertia,
                m.wheel_inertia,
                m.wheel_mass,
            )
        } else {
            (0.0, 0.0, 0.0, 0.0)
        };
        // −T_1i10c − T_2i10c (A5.2.1.40-46, module note) and −T_3i10c (A5.2.1.52): in the
        // involute reading the wheel's inertia enters through F_t instead.
        let lumped = match gear.mesh {
            MeshModel::Karhula => crank_inertia + wheel_inertia,
            MeshModel::Involute => crank_inertia,
        };
        let (c, rod, rod_pin, pin) = (&st.crank, &st.bodies[ROD], &st.joints[2], &st.joints[1]);
        let wheel = &st.bodies[WHEEL];
        // With an added mass the wheel's centre of gravity g leaves S: its inertia force −M·a_g
        // has a moment about S, which with the wheel's own J_g·α_w is what the wheel's loads
        // must supply about S, M_S (module note).
        let body = &gear.topology.bodies[WHEEL];
        let (wheel_mass, added) = match gear.added {
            Some(_) if inertia => (body.mass, Some(body.inertia)),
            _ => (wheel_mass, None),
        };
        let gas = piston_force.unwrap_or(&ZERO);
        let tan = gear.tan_pressure_angle;
        let Some(([main, crank_pin_load, rod_pin_load, mesh_load], crank_torque)) = out.split()
        else {
            unreachable!("the cardan gear's topology")
        };
        // Pins and a mesh: no couple (their columns stay zero).
        for i in 0..st.len.min(LANES) {
            let p = -mass * C::new(rod.cg.ax[i], rod.cg.ay[i]) - C::new(0.0, gas[i]);
            let alpha = c.acceleration[i];
            let s = C::new(pin.x[i], pin.y[i]);
            let a_g = C::new(wheel.cg.ax[i], wheel.cg.ay[i]);
            let moment_s = added.map(|j_g| {
                let g = C::new(wheel.cg.x[i], wheel.cg.y[i]);
                j_g * wheel.angular_acceleration[i] + cross(g - s, wheel_mass * a_g)
            });
            let mesh = match gear.mesh {
                MeshModel::Karhula => p, // (A5.2.1.48-51)
                MeshModel::Involute => {
                    // Moments about S: (T − S)×P + r·F_t = J_w·α_w, with α_w = −α.
                    let t = C::new(rod_pin.x[i], rod_pin.y[i]);
                    let f_t = match moment_s {
                        // J_g includes J_w here: M_S is all the wheel's need.
                        Some(m_s) => (m_s - cross(t - s, p)) / gear.crank,
                        None => (-wheel_inertia * alpha - cross(t - s, p)) / gear.crank,
                    };
                    let e = C::new(c.cos[i], c.sin[i]);
                    f_t * C::i() * e - f_t.abs() * tan * e
                }
            };
            // The wheel's inertia force at its centre of gravity: at S without an added mass,
            // its moment about S then zero and the mesh force the same in either reading.
            let wheel_force = -wheel_mass * a_g;
            // 2·P in the thesis reading (A5.2.1.51), with the wheel's inertia force.
            let crank_pin = p + mesh + wheel_force;
            main.set_force(i, -crank_pin); // (A5.2.1.54)
            crank_pin_load.set_force(i, crank_pin);
            rod_pin_load.set_force(i, -p); // (A5.2.1.49)
            mesh_load.set_force(i, mesh);
            crank_torque[i] = lumped * alpha - cross(s, crank_pin); // −T_Σi10c (A5.2.1.69)
            if let (MeshModel::Karhula, Some(m_s)) = (gear.mesh, moment_s) {
                // The thesis's lumping: the drive supplies M_S through the wheel's speed ratio
                // −1 (module note; `Body::lumped`).
                crank_torque[i] -= m_s;
            }
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mass::Material;
    use crate::CrankState;
    use approx::assert_relative_eq;

    fn gear() -> CardanGear {
        let g = MachineGeometry {
            crank_length: 0.06,
            rod_length: 0.14,
            bore: 0.12,
            pin_offset: 0.0,
        };
        CardanGear::build(&g, &MassInputs::default(), &Options::new()).unwrap()
    }

    /// Appendix 4.2.1: T is the point of the wheel's pitch circle that started at the mesh
    /// point; rolling inside the ring without slip, it stays on the cylinder axis. Checked by
    /// building T from the wheel's own rotation instead of (A4.2.2.60).
    #[test]
    fn wheel_pin_from_rolling_stays_on_the_axis() {
        let g = gear();
        for k in 0..50 {
            let th = 0.3 + 0.13 * k as f64;
            let st = g.state(&CrankState::new(th, 7.0, 1.5, 0.0));
            // The wheel turns by −θ relative to the frame; at θ = 90° T sits on the mesh point.
            let wheel_turn = -(th - std::f64::consts::FRAC_PI_2);
            let s = st.joints[1].position;
            let t_from_rolling =
                s + g.crank * C::from_polar(1.0, std::f64::consts::FRAC_PI_2 + wheel_turn);
            assert!((t_from_rolling - st.joints[2].position).norm() < 1e-15);
            assert!((st.joints[3].position.norm() - 2.0 * g.crank).abs() < 1e-15);
            // The wheel's orientation is the line S→T.
            let s_to_t = (st.joints[2].position - s) / g.crank;
            assert!((s_to_t - st.bodies[WHEEL].orientation).norm() < 1e-15);
        }
    }

    #[test]
    fn same_stroke_as_the_slider_crank() {
        let g = gear();
        assert_relative_eq!(g.stroke(), 0.12, max_relative = 1e-15);
        assert_relative_eq!(g.piston_top(), 0.2, max_relative = 1e-15);
        assert_eq!(g.masses.rod_material, Material::Steel);
    }

    #[test]
    fn a_pressure_angle_out_of_range_is_refused() {
        let g = MachineGeometry {
            crank_length: 0.06,
            rod_length: 0.14,
            bore: 0.12,
            pin_offset: 0.0,
        };
        let mut o = Options::new();
        o.insert("pressure_angle".into(), crate::OptionValue::Number(0.0));
        let e = CardanGear::build(&g, &MassInputs::default(), &o).unwrap_err();
        assert_eq!(
            e.field,
            Input::Option {
                mechanism: "cardan_gear",
                name: "pressure_angle"
            }
        );
    }
}
