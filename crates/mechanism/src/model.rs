//! The open mechanism model: what a mechanism declares (bodies, joints, pistons) and what it
//! fills at every step (their motion). Everything downstream (loads, gas, outputs, losses)
//! iterates over these lists and never asks which mechanism produced them.

use crate::CrankState;
use crate::C;

/// A rigid body of the mechanism with its mass properties.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Body {
    /// Name used in outputs (`rod`, `piston`, `wheel`, ...).
    pub name: &'static str,
    /// Mass, kg. A body whose mass belongs to another assembly (the cardan wheel, carried by the
    /// balanced crankshaft in Karhula ch. 11.2) has 0 here.
    pub mass: f64,
    /// Moment of inertia about the centre of gravity, kg·m².
    pub inertia: f64,
    /// `Some(ratio)`: a body whose moment balance its own joints do not hold, lumped with the
    /// crankshaft's (Karhula's reading of the cardan wheel, A5.2.1.43-46, whose mesh force is
    /// tied to the rod's): the drive supplies the moment its loads need about the joint that
    /// carries it on the crankshaft, through its speed `ratio` to the crank's (virtual power:
    /// a moment M on a body turning at ratio·ω takes the power M·ratio·ω, so the drive gives
    /// ratio·M). The general solve adds the body's moment equation about that joint, times
    /// `ratio`, to the crankshaft's. `None`: its own joints hold it (every other body).
    pub lumped: Option<f64>,
}

impl Body {
    /// A body that its joints hold ([`Body::lumped`] `None`).
    pub fn new(name: &'static str, mass: f64, inertia: f64) -> Self {
        Self {
            name,
            mass,
            inertia,
            lumped: None,
        }
    }
}

/// How a joint transmits force.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum JointKind {
    /// A pin on its bearings: any force in the plane, no moment.
    Revolute(Bearings),
    /// A slide along the joint's direction ([`JointMotion::direction`]): a force across it
    /// and a couple.
    Prismatic,
    /// A gear mesh at the pitch point ([`JointMotion::position`]).
    GearMesh {
        /// Teeth of the gear on `other` over teeth of the gear on `body` (2 for the cardan pair).
        ratio: f64,
        /// Pitch radius of the gear on `body`, m.
        pitch_radius: f64,
        /// Whether the gear on `other` is an internal (ring) gear.
        internal: bool,
        /// Pressure angle of the tooth profiles, rad.
        pressure_angle: f64,
        /// Which direction the mesh force takes.
        force: MeshForce,
    },
}

/// The bearings a revolute joint turns on. The friction models read them; the dynamics only
/// needs the joint's position. Default sizes follow Karhula (2008) App. 9.1 (see
/// [`crate::MachineGeometry::bearings`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bearings {
    /// Journal radius, m: half the rolling bearing's pitch (mean) diameter d_m.
    pub radius: f64,
    /// Bearings side by side, sharing the joint's load equally (2 main bearings, A9.1.24-25;
    /// 2 crank-pin bearings in the cardan wheel, A9.1.23).
    pub count: u32,
    /// Basic static load rating C0 of one bearing, N.
    pub static_load_rating: f64,
}

impl Bearings {
    /// One bearing of journal radius `radius` (m) and static load rating `static_load_rating` (N).
    pub fn single(radius: f64, static_load_rating: f64) -> Self {
        Self {
            radius,
            count: 1,
            static_load_rating,
        }
    }
}

/// The direction of a gear-mesh force.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MeshForce {
    /// Involute teeth push along the line of action: a tangential component F_t of either sign
    /// and a radial component |F_t|·tan α towards the centre of the gear on `body`.
    Involute,
    /// A force along the fixed unit vector `direction`, tied to another joint: its component
    /// along `direction` equals `factor` times that of the force of joint `joint` (Karhula's
    /// reading of the cardan pair, A5.2.1.48-51).
    Tied {
        direction: C,
        joint: usize,
        factor: f64,
    },
}

/// A joint between `body` and `other` (`None`: the frame). Its load is the force (and couple)
/// on `body` from `other`; `other` receives the opposite.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Joint {
    /// Name used in outputs (`main_bearing`, `crank_pin`, ...).
    pub name: &'static str,
    pub kind: JointKind,
    pub body: usize,
    pub other: Option<usize>,
}

impl Joint {
    /// A pin on `bearings` between `body` and `other`.
    pub fn pin(name: &'static str, bearings: Bearings, body: usize, other: Option<usize>) -> Self {
        Self {
            name,
            kind: JointKind::Revolute(bearings),
            body,
            other,
        }
    }

    /// A slide between `body` and `other`.
    pub fn slide(name: &'static str, body: usize, other: Option<usize>) -> Self {
        Self {
            name,
            kind: JointKind::Prismatic,
            body,
            other,
        }
    }
}

/// A piston: the face the gas pushes, carried by `body`, sliding along `axis`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Piston {
    pub name: &'static str,
    pub body: usize,
    /// Unit vector of the cylinder axis, pointing away from the crankshaft.
    pub axis: C,
    /// The point of the cylinder axis from which the piston position is measured, m.
    pub origin: C,
}

impl Piston {
    /// The piston of an in-line machine: on `body`, along +y, its line `offset` (m) off the
    /// main axis.
    pub fn in_line(body: usize, offset: f64) -> Self {
        Self {
            name: "piston",
            body,
            axis: C::new(0.0, 1.0),
            origin: C::new(offset, 0.0),
        }
    }
}

/// A per-step quantity only one mechanism has (a column of its per-step output).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ExtraColumn {
    /// Column name, with its unit in it.
    pub name: &'static str,
    pub meaning: &'static str,
}

/// What a mechanism is made of.
#[derive(Debug, Clone, PartialEq)]
pub struct Topology {
    pub bodies: Vec<Body>,
    pub joints: Vec<Joint>,
    pub pistons: Vec<Piston>,
    /// The body the drive turns (its angle is the crank angle, its centre of gravity on the
    /// main axis).
    pub crankshaft: usize,
    /// Per-step quantities of this mechanism alone.
    pub extras: Vec<ExtraColumn>,
}

impl Topology {
    /// Whether every joint's reaction is linear in the loads, so that the loads of several
    /// load families add up to those of their sum. An involute mesh's is not: its teeth push on
    /// the flank that the *total* tangential force loads, with a radial part |F_t|·tan α, and
    /// |F_t,1| + |F_t,2| ≠ |F_t,1 + F_t,2| wherever the families' tangential forces have
    /// opposite signs. Such a mechanism's total loads are solved from the summed loads.
    pub fn superposable(&self) -> bool {
        !self.joints.iter().any(|j| {
            matches!(
                j.kind,
                JointKind::GearMesh {
                    force: MeshForce::Involute,
                    ..
                }
            )
        })
    }
}

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

impl PointMotion {
    /// A point at `radius` (m) on the crank, at the crank state `crank`: Z = r·e^{iθ},
    /// v = r·i·ω·e^{iθ}, a = r·(i·α − ω²)·e^{iθ} (Karhula 2008 A4.2.2.2, A4.2.2.11, A4.2.2.30; the
    /// same for the cardan crank, A4.2.2.57, A4.2.2.65, A4.2.2.70).
    pub fn on_crank(radius: f64, crank: &CrankState) -> Self {
        let (w, a, e) = (crank.speed, crank.acceleration, crank.direction);
        let i = C::i();
        Self {
            position: radius * e,
            velocity: radius * i * w * e,
            acceleration: radius * (i * a - w * w) * e,
        }
    }
}

/// The motion of a body.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BodyMotion {
    /// Its centre of gravity.
    pub cg: PointMotion,
    /// Orientation: the unit vector e^{iφ} of a line fixed in the body; its argument φ is the
    /// body's angle from the +x axis.
    pub orientation: C,
    /// rad/s, counter-clockwise positive.
    pub angular_velocity: f64,
    /// rad/s².
    pub angular_acceleration: f64,
}

/// The motion of a joint.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct JointMotion {
    /// Where it acts (pin centre, slide contact point, pitch point), m.
    pub position: C,
    /// Unit vector: the slide direction of a prismatic joint; for a gear mesh, from the pitch
    /// point towards the centre of the gear on `body`; unused for a pin.
    pub direction: C,
    /// The speed that turns or slides the joint, signed: relative angular velocity of `body`
    /// to `other` for a pin (rad/s), sliding velocity along `direction` for a slide (m/s),
    /// pitch-line velocity relative to the gear carrier for a mesh (m/s).
    pub relative_speed: f64,
}

/// A piston along its cylinder axis.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PistonMotion {
    /// Piston-pin distance from the piston's `origin` along its axis, m.
    pub position: f64,
    /// m/s, positive away from the crankshaft.
    pub velocity: f64,
    /// m/s².
    pub acceleration: f64,
    /// dx/dθ, m/rad: the cylinder volume is V(θ) = V_c + A·(x_TDC − x(θ)), dV/dθ = −A·dx/dθ.
    pub dx_dtheta: f64,
    /// d²x/dθ², m/rad².
    pub d2x_dtheta2: f64,
}

/// Everything known about a mechanism at one crank state, in the order of its [`Topology`].
#[derive(Debug, Clone, PartialEq, Default)]
pub struct State {
    pub crank: CrankState,
    pub bodies: Vec<BodyMotion>,
    pub joints: Vec<JointMotion>,
    pub pistons: Vec<PistonMotion>,
    /// The values of [`Topology::extras`]; NaN where undefined at this step (an empty cell).
    pub extras: Vec<f64>,
}

impl State {
    /// A state with room for every body, joint, piston and extra of `topology`.
    pub fn for_topology(topology: &Topology) -> Self {
        Self {
            crank: CrankState::default(),
            bodies: vec![BodyMotion::default(); topology.bodies.len()],
            joints: vec![JointMotion::default(); topology.joints.len()],
            pistons: vec![PistonMotion::default(); topology.pistons.len()],
            extras: vec![0.0; topology.extras.len()],
        }
    }
}

/// The load one family (inertia, gas, ...) puts on a joint.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct JointLoad {
    /// Force on the joint's `body` from its `other`, N.
    pub force: C,
    /// Couple on `body` from `other`, N·m (a slide's; zero for pins and meshes).
    pub moment: f64,
}

/// The loads of one family at one step, keyed by joint.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Loads {
    /// In the order of [`Topology::joints`].
    pub joints: Vec<JointLoad>,
    /// Torque the drive applies to the crankshaft, positive in the direction of rotation, N·m.
    pub crank_torque: f64,
}

impl Loads {
    pub fn for_topology(topology: &Topology) -> Self {
        Self {
            joints: vec![JointLoad::default(); topology.joints.len()],
            crank_torque: 0.0,
        }
    }

    /// Sets every load to zero.
    pub fn clear(&mut self) {
        self.joints.fill(JointLoad::default());
        self.crank_torque = 0.0;
    }

    /// Adds `other` (superposition of load families, Karhula A7.1).
    pub fn add(&mut self, other: &Loads) {
        for (a, b) in self.joints.iter_mut().zip(&other.joints) {
            a.force += b.force;
            a.moment += b.moment;
        }
        self.crank_torque += other.crank_torque;
    }
}

/// z × f, the moment about the origin of force f applied at z (scalar, counter-clockwise +).
pub fn cross(z: C, f: C) -> f64 {
    z.re * f.im - z.im * f.re
}
