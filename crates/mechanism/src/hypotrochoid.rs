//! The hypotrochoid mechanism (HM) of Vidinsky (2021), "Mechanical Advantage of a Hypotrochoid
//! Mechanism" (extraction: docs/validation/vidinsky-2021.md). A rotary machine: m piston
//! links pivoted on the main axis turn with a multi-rod rotor, and the angle δ between adjacent
//! links (the working chamber between them) swings harmonically.
//!
//! # The chain (paper §1.2, Figs 2b, 5, 6, 11)
//!
//! - A ring gear G of pitch radius (m+1)·u is the frame (eq 6: R = r_G/u = m + 1).
//! - The **carrier** OO_u (length v = m·u, eqs 2, 4) turns about O; it carries the **planet**
//!   (pitch radius u) that rolls inside the ring, so the planet turns m times as fast as the
//!   carrier, in the opposite sense (eq 4; Willis: ω_planet = ω_carrier·(1 − (m+1))).
//! - The **crankshaft** OA (length p, the case's `geometry.crank_length`) is the body the drive
//!   turns (the validation model drives the crankshaft at 1 rad/s, paper §6, L355). The
//!   parallelogram crank chain (PCC) OAC_uO_u keeps it parallel to the planet's radius O_uC_u:
//!   the **rotor** is the PCC's coupler, pinned to the crankshaft at A and to the planet at
//!   C_u = O_u + (A − O), so the rotor stays parallel to the carrier. Its m rods AB_k are spaced by
//!   2π/m (Fig 5).
//! - Each **piston link** OB_k (length r) turns about O; a **block** pinned to it at B_k slides
//!   along rotor rod k (the kinematic equivalent "rRPRR", §2).
//!
//! # Frame, angles and signs
//!
//! The paper's frame: x to the right, y up, O at the origin. Its parameter θ is the carrier
//! angle, positive clockwise (eq 8: rods along [cos θ, −sin θ], A = p·[cos mθ, sin mθ]).
//! The case's crank angle φ is the crankshaft's angle, counter-clockwise positive, growing in
//! the direction of rotation. Like the in-line mechanisms, whose top dead centre is at φ = π/2,
//! φ = π/2 is the first chamber's minimum (the state L_m of the paper, §3.3):
//! `θ = L_m + (φ − π/2)/m` (the crank turns m times as fast as the carrier, eq 4). The
//! crankshaft's orientation is e^{iφ}, a line fixed in it at π/2 − m·L_m from OA.
//! [`Hypotrochoid::carrier_angle`] and [`Hypotrochoid::crank_angle`] convert.
//!
//! # Topology
//!
//! Bodies: `crankshaft` (inertia `crankshaft_inertia`), `carrier` (massless: no mass field
//! describes it), `planet` (inertia `wheel_inertia`, estimated as the cardan wheel's rule for a
//! steel disc of pitch diameter 2u; no mass), `rotor` (massless), `piston_link_k` (mass
//! `rod_mass`, inertia `rod_inertia`, centre of gravity `rod_cg` from O along OB_k: the link is
//! a bar of length r, estimated by the rod rule), `block_k` (massless). `piston_mass` has no use
//! (there is no reciprocating piston) and is 0.
//!
//! One planet: the real machine has m planets, one per carrier rod, each with its own PCC.
//! Kinematically they are copies of the first, rotated by 2π/m; statically they are redundant
//! (each adds two unknown pin forces), so the model keeps one planet and one PCC and stays
//! statically determinate. The price: a single parallelogram folds where OA is parallel to
//! OO_u, at sin((m+1)θ) = 0 (2(m+1) times per carrier turn), where its coupler cannot hold the
//! rotor's angle. There the planar solve is singular and, near there, its joint loads grow as
//! 1/sin((m+1)θ) (the drive torque does not: it is fixed by the power balance). In the real
//! machine with m ≥ 3 the other planets carry the rotor through the fold of the first; for
//! m = 2 the two parallelograms fold together (a change point of the paper's chain, at θ = 0°,
//! 60°, 120° = M_2, …). [`Hypotrochoid::fold_sine`] gives sin((m+1)θ) to keep tests and grids
//! away from the folds. The crank angle convention above puts no fold at φ = 0 for m = 2 (the
//! default).
//!
//! Joints: `main_bearing` (crankshaft–frame at O), `carrier_bearing` (carrier–frame at O),
//! `planet_bearing` (planet–carrier at O_u), `ring_mesh` (planet–ring, involute, ratio m+1,
//! 20° pressure angle, at the pitch point (v+u)·e^{−iθ}), `crank_pin` (crankshaft–rotor at A),
//! `coupler_pin` (planet–rotor at C_u), and per link k: `link_pivot_k` (link–frame at O),
//! `link_pin_k` (link–block at B_k), `rod_slide_k` (block–rotor, sliding along rod k).
//!
//! # Pistons (a rotary piston link)
//!
//! Piston k rides on `piston_link_k`. Its coordinate is the arc length of B_k on its circle,
//! x_k = r·ψ_k (ψ_k = ψ(θ + 2π(k−1)/m), eq 11, unwrapped, growing as the links turn
//! clockwise), so x, dx/dθ and d²x/dθ² are consistent derivatives. The piston's axis is −y and
//! its origin (r, 0): a piston force F (towards the crankshaft, i.e. along +y) on that line has
//! the moment r·F about O, counter-clockwise, whatever x: the moment of a tangential force F
//! at B_k, so the drive torque and the power F·ẋ are exact. The line of action is fixed, so the
//! pivot force at O is not that of a truly tangential force (it does not turn with the link).
//! The links turn without end, so x has no top and bottom; [`Mechanism::piston_top`] is x_1 at
//! φ = π/2 (L_m) and [`Mechanism::stroke`] is the first chamber's arc swing at radius r,
//! r·(δ(N_m) − δ(L_m)) (eq 15). Gas models (which assume a bounded, reciprocating x) do not
//! apply to it.
//!
//! Extras: `carrier_angle_vidinsky_deg` (θ, paper frame, clockwise positive, in [0°, 360°)),
//! `chamber_angle_deg` (δ between links 1 and 2, eq 15), `mechanical_advantage` (eq 21).

use crate::mass::{self, MassInputs, MassProperties};
use crate::model::{
    Bearings, Body, ExtraColumn, Joint, JointKind, MeshForce, Piston, State, Topology,
};
use crate::{
    check_length, number, CrankState, Entry, Input, MachineGeometry, Mechanism, StateBlock,
};
use crate::{BodyMotion, MechanismError, OptionKind, OptionSpec, Options, PointMotion, C};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// The largest angular modulus the model names bodies for.
pub const MAX_MODULUS: usize = 8;

/// Pressure angle of the ring–planet pair, rad (the paper gives no gear data).
pub const PRESSURE_ANGLE: f64 = 20.0 * PI / 180.0;

/// The validation model of the paper (§6, L365-369), m: crank p = 75 mm, planet 100 mm, piston
/// link 340 mm (m = 2). The defaults scale it to the case's crank: u = (4/3)·p, r = 1.7·m·u.
const MODEL_CRANK: f64 = 0.075;
const MODEL_PLANET: f64 = 0.100;

/// The registry line.
pub const ENTRY: Entry = Entry {
    name: "hypotrochoid",
    summary: "hypotrochoid mechanism: planetary carrier, parallelogram crank chain, multi-rod rotor and m piston links whose angle δ swings harmonically (Vidinsky 2021)",
    options: &[
        OptionSpec {
            name: "angular_modulus",
            kind: OptionKind::Number {
                min: 2.0,
                max: MAX_MODULUS as f64,
                whole: true,
            },
            meaning: "m, an integer from 2 to 8: rotor rods and piston links; the ring gear has m+1 times the planet's radius, the crank turns m times as fast as the carrier (2 by default)",
        },
        OptionSpec {
            name: "piston_link_length",
            kind: OptionKind::Length,
            meaning: "r = OB, longer than the crank (1.7·m planet radii by default, the paper's r = 1.7m)",
        },
        OptionSpec {
            name: "planet_radius",
            kind: OptionKind::Length,
            meaning: "u, pitch radius of the planet; the carrier is m·u (4/3 of the crank by default, the paper's 100 mm for a 75 mm crank)",
        },
    ],
    unused_masses: &["piston_mass", "wheel_mass"],
    pin_offset: false,
    build: |g, m, o| Ok(Box::new(Hypotrochoid::build(g, m, o)?)),
};

const CRANKSHAFT: usize = 0;
const CARRIER: usize = 1;
const PLANET: usize = 2;
const ROTOR: usize = 3;
const FIRST_LINK: usize = 4;
/// Joints before the per-link ones.
const FIXED_JOINTS: usize = 6;

const LINKS: [&str; MAX_MODULUS] = [
    "piston_link_1",
    "piston_link_2",
    "piston_link_3",
    "piston_link_4",
    "piston_link_5",
    "piston_link_6",
    "piston_link_7",
    "piston_link_8",
];
const BLOCKS: [&str; MAX_MODULUS] = [
    "block_1", "block_2", "block_3", "block_4", "block_5", "block_6", "block_7", "block_8",
];
const PIVOTS: [&str; MAX_MODULUS] = [
    "link_pivot_1",
    "link_pivot_2",
    "link_pivot_3",
    "link_pivot_4",
    "link_pivot_5",
    "link_pivot_6",
    "link_pivot_7",
    "link_pivot_8",
];
const PINS: [&str; MAX_MODULUS] = [
    "link_pin_1",
    "link_pin_2",
    "link_pin_3",
    "link_pin_4",
    "link_pin_5",
    "link_pin_6",
    "link_pin_7",
    "link_pin_8",
];
const SLIDES: [&str; MAX_MODULUS] = [
    "rod_slide_1",
    "rod_slide_2",
    "rod_slide_3",
    "rod_slide_4",
    "rod_slide_5",
    "rod_slide_6",
    "rod_slide_7",
    "rod_slide_8",
];
const PISTONS: [&str; MAX_MODULUS] = [
    "piston_1", "piston_2", "piston_3", "piston_4", "piston_5", "piston_6", "piston_7", "piston_8",
];

/// Hypotrochoid mechanism geometry and masses.
#[derive(Debug, Clone, PartialEq)]
pub struct Hypotrochoid {
    /// Angular modulus m (eq 4): rotor rods, piston links; crank-to-carrier speed ratio.
    pub modulus: usize,
    /// Crank OA, m: p (eq 8).
    pub crank: f64,
    /// Piston link OB, m: r (eq 8).
    pub link: f64,
    /// Planet pitch radius, m: u (eq 5); the ring has (m+1)·u (eq 6), the carrier m·u (eq 4).
    pub planet: f64,
    pub masses: MassProperties,
    topology: Topology,
}

/// The modulus and lengths of [`Hypotrochoid::new`] checked: `m` from 2 to [`MAX_MODULUS`],
/// positive lengths, a piston link longer than the crank, its centre of gravity on it.
fn check_dimensions(
    m: usize,
    p: f64,
    r: f64,
    u: f64,
    masses: &MassProperties,
) -> Result<(), MechanismError> {
    if !(2..=MAX_MODULUS).contains(&m) {
        return Err(MechanismError::new(
            Input::Option {
                mechanism: ENTRY.name,
                name: "angular_modulus",
            },
            m,
            format!("must be an integer from 2 to {MAX_MODULUS}"),
        ));
    }
    check_length(Input::CrankLength, p)?;
    check_length(
        Input::Option {
            mechanism: ENTRY.name,
            name: "piston_link_length",
        },
        r,
    )?;
    check_length(
        Input::Option {
            mechanism: ENTRY.name,
            name: "planet_radius",
        },
        u,
    )?;
    // Eq 11 has a real branch for every θ, and the rod AB keeps a positive length
    // q ∈ [r − p, r + p] (eq 13), only if r > p.
    if r <= p {
        return Err(MechanismError::new(
            Input::Option {
                mechanism: ENTRY.name,
                name: "piston_link_length",
            },
            r,
            format!("must be longer than geometry.crank_length ({p} m): ψ(θ) = θ − asin(p·sin((m+1)θ)/r) (Vidinsky eq 11) needs r > p, and B would reach A"),
        ));
    }
    if !(0.0..=r).contains(&masses.rod_cg) {
        return Err(MechanismError::new(
            Input::RodCg,
            masses.rod_cg,
            format!("the piston link's centre of gravity must lie on it, between 0 and hypotrochoid.piston_link_length ({r} m)"),
        ));
    }
    Ok(())
}

/// The bodies, joints and pistons of a mechanism of modulus `m`, piston link `r` and planet
/// radius `u`, with `masses` and bearings [link pin, crank and coupler pins, main axis].
fn topology(
    m: usize,
    r: f64,
    u: f64,
    masses: &MassProperties,
    bearings: [Bearings; 3],
) -> Topology {
    let pistons = (0..m)
        .map(|k| Piston {
            name: PISTONS[k],
            body: FIRST_LINK + k,
            axis: C::new(0.0, -1.0),
            origin: C::new(r, 0.0),
        })
        .collect();
    Topology {
        bodies: bodies(m, masses),
        joints: joints(m, u, bearings),
        pistons,
        crankshaft: CRANKSHAFT,
        extras: vec![
            ExtraColumn {
                name: "carrier_angle_vidinsky_deg",
                meaning: "carrier angle θ of Vidinsky (2021), clockwise positive, deg",
            },
            ExtraColumn {
                name: "chamber_angle_deg",
                meaning: "angle δ between piston links 1 and 2 (Vidinsky eq 15), deg",
            },
            ExtraColumn {
                name: "mechanical_advantage",
                meaning:
                    "F_out at the crank pin over F_in between piston links 1 and 2 (Vidinsky eq 21)",
            },
        ],
    }
}

/// The bodies: crankshaft, carrier, planet, rotor, then the `m` piston links and their `m`
/// sliding blocks (the indices [`FIRST_LINK`] on).
fn bodies(m: usize, masses: &MassProperties) -> Vec<Body> {
    let mut bodies = vec![
        Body {
            name: "crankshaft",
            mass: 0.0,
            inertia: masses.crankshaft_inertia,
            lumped: None,
        },
        Body {
            name: "carrier",
            mass: 0.0,
            inertia: 0.0,
            lumped: None,
        },
        Body {
            name: "planet",
            mass: 0.0,
            inertia: masses.wheel_inertia,
            lumped: None,
        },
        Body {
            name: "rotor",
            mass: 0.0,
            inertia: 0.0,
            lumped: None,
        },
    ];
    bodies.extend(LINKS[..m].iter().map(|&name| Body {
        name,
        mass: masses.rod_mass,
        inertia: masses.rod_inertia,
        lumped: None,
    }));
    bodies.extend(BLOCKS[..m].iter().map(|&name| Body {
        name,
        mass: 0.0,
        inertia: 0.0,
        lumped: None,
    }));
    bodies
}

/// The joints: the main axis's bearings, the planet's, its ring mesh, the crank and coupler
/// pins, then each piston link's pivot, pin and slide.
fn joints(m: usize, u: f64, bearings: [Bearings; 3]) -> Vec<Joint> {
    let [r_pin, r_crank, r_main] = bearings;
    let pin = |name, radius, body, other| Joint {
        name,
        kind: JointKind::Revolute(radius),
        body,
        other,
    };
    let mut joints = vec![
        pin("main_bearing", r_main, CRANKSHAFT, None),
        pin("carrier_bearing", r_main, CARRIER, None),
        pin("planet_bearing", r_crank, PLANET, Some(CARRIER)),
        Joint {
            name: "ring_mesh",
            kind: JointKind::GearMesh {
                ratio: (m + 1) as f64,
                pitch_radius: u,
                internal: true,
                pressure_angle: PRESSURE_ANGLE,
                force: MeshForce::Involute,
            },
            body: PLANET,
            other: None,
        },
        pin("crank_pin", r_crank, CRANKSHAFT, Some(ROTOR)),
        pin("coupler_pin", r_crank, PLANET, Some(ROTOR)),
    ];
    for k in 0..m {
        let (link, block) = (FIRST_LINK + k, FIRST_LINK + m + k);
        joints.push(pin(PIVOTS[k], r_main, link, None));
        joints.push(pin(PINS[k], r_pin, link, Some(block)));
        joints.push(Joint {
            name: SLIDES[k],
            kind: JointKind::Prismatic,
            body: block,
            other: Some(ROTOR),
        });
    }
    joints
}

/// A point P(θ) with dP/dθ and d²P/dθ², m, m/rad, m/rad².
#[derive(Clone, Copy)]
struct Curve(C, C, C);

impl Curve {
    /// Its motion under the carrier angle's rate θ̇ and θ̈ (rad/s, rad/s²).
    fn motion(self, td: f64, tdd: f64) -> PointMotion {
        PointMotion {
            position: self.0,
            velocity: self.1 * td,
            acceleration: self.2 * td * td + self.1 * tdd,
        }
    }
}

impl Hypotrochoid {
    /// The mechanism of `geometry`'s crank (p) with the options of its `[hypotrochoid]` table
    /// and the masses of `inputs` (module note).
    pub fn build(
        geometry: &MachineGeometry,
        inputs: &MassInputs,
        options: &Options,
    ) -> Result<Self, MechanismError> {
        let p = check_length(Input::CrankLength, geometry.crank_length)?;
        let m = number(options, "angular_modulus", 2.0);
        if !(m.fract() == 0.0 && (2.0..=MAX_MODULUS as f64).contains(&m)) {
            return Err(MechanismError::new(
                Input::Option {
                mechanism: ENTRY.name,
                name: "angular_modulus",
            },
                m,
                format!("must be an integer from 2 to {MAX_MODULUS}: the ring gear has m+1 ≥ 3 planet radii (Vidinsky eqs 3, 6)"),
            ));
        }
        let u = number(options, "planet_radius", p * MODEL_PLANET / MODEL_CRANK);
        check_length(
            Input::Option {
                mechanism: ENTRY.name,
                name: "planet_radius",
            },
            u,
        )?;
        let r = number(options, "piston_link_length", 1.7 * m * u);
        check_length(
            Input::Option {
                mechanism: ENTRY.name,
                name: "piston_link_length",
            },
            r,
        )?;
        let mut estimate = mass::estimate_for(inputs, p, r, geometry.bore);
        estimate.wheel_inertia = mass::cardan_wheel_inertia(2.0 * u);
        estimate.piston_mass = 0.0;
        let mut masses = MassProperties::resolve(estimate, inputs);
        masses.piston_mass = 0.0;
        Self::new(m as usize, p, r, u, masses, geometry.bearings())
    }

    /// A mechanism of modulus `m`, crank `p`, piston link `r` and planet radius `u` (m), with
    /// `masses` and bearings [link pin, crank and coupler pins, main axis].
    pub fn new(
        m: usize,
        p: f64,
        r: f64,
        u: f64,
        masses: MassProperties,
        bearings: [Bearings; 3],
    ) -> Result<Self, MechanismError> {
        check_dimensions(m, p, r, u, &masses)?;
        let topology = topology(m, r, u, &masses, bearings);
        Ok(Self {
            modulus: m,
            crank: p,
            link: r,
            planet: u,
            masses,
            topology,
        })
    }

    fn mf(&self) -> f64 {
        self.modulus as f64
    }

    /// The states L_m, M_m, N_m of the first chamber (paper §3.3): minimum, middle and maximum
    /// of δ, carrier angles θ in rad: ((2π, 5π/2, 3π) − π/m)/(m+1) (derived in the extraction,
    /// §2.5; the paper's (π/2, 5π/6) for m = 2 and (5π/12, 2π/3) for m = 3, L229).
    pub fn working_range(&self) -> (f64, f64, f64) {
        let (m, k) = (self.mf(), self.mf() + 1.0);
        (
            (TAU - PI / m) / k,
            (2.5 * PI - PI / m) / k,
            (3.0 * PI - PI / m) / k,
        )
    }

    /// The carrier angle θ (paper, clockwise positive) at crank angle `phi` (rad): φ = π/2 at
    /// L_m, the crank turning m times as fast (eq 4).
    pub fn carrier_angle(&self, phi: f64) -> f64 {
        self.working_range().0 + (phi - FRAC_PI_2) / self.mf()
    }

    /// The crank angle φ at carrier angle `theta` (rad): the inverse of
    /// [`Hypotrochoid::carrier_angle`].
    pub fn crank_angle(&self, theta: f64) -> f64 {
        FRAC_PI_2 + self.mf() * (theta - self.working_range().0)
    }

    /// sin((m+1)θ): zero where the parallelogram crank chain folds (module note).
    pub fn fold_sine(&self, theta: f64) -> f64 {
        ((self.mf() + 1.0) * theta).sin()
    }

    /// The transmission angle χ(θ) = asin(p·sin((m+1)θ)/r) (eq 12) and its first and second
    /// θ-derivatives (the first is the term of ψ' in eq 17).
    pub fn chi(&self, theta: f64) -> (f64, f64, f64) {
        let (k, lambda) = (self.mf() + 1.0, self.crank / self.link);
        let (s, c) = (k * theta).sin_cos();
        let sin_chi = lambda * s;
        let cos_chi = (1.0 - sin_chi * sin_chi).sqrt();
        let d1 = k * lambda * c / cos_chi;
        let d2 = k * lambda * (-k * s / cos_chi + c * sin_chi * d1 / (cos_chi * cos_chi));
        (sin_chi.asin(), d1, d2)
    }

    /// ψ(θ) = θ − χ(θ) (eq 11), the piston link's clockwise angle, with ψ' (eq 17: ψ' =
    /// 1 − (m+1)·p·cos((m+1)θ)/√(r² − p²·sin²((m+1)θ))) and ψ''.
    pub fn psi(&self, theta: f64) -> (f64, f64, f64) {
        let (chi, d1, d2) = self.chi(theta);
        (theta - chi, 1.0 - d1, -d2)
    }

    /// The rod length q(θ) = AB = r·cos χ − p·cos((m+1)θ) (eq 13 in its simpler equivalent
    /// form, extraction §2.3), with q' and q'' (m, m/rad, m/rad²).
    pub fn rod(&self, theta: f64) -> (f64, f64, f64) {
        let (k, p, r) = (self.mf() + 1.0, self.crank, self.link);
        let (chi, d1, d2) = self.chi(theta);
        let (sc, cc) = chi.sin_cos();
        let (s, c) = (k * theta).sin_cos();
        (
            r * cc - p * c,
            -r * sc * d1 + k * p * s,
            -r * (cc * d1 * d1 + sc * d2) + k * k * p * c,
        )
    }

    /// δ(θ) = ψ(θ + 2π/m) − ψ(θ) (eq 15), rad, and dδ/dθ.
    pub fn chamber_angle(&self, theta: f64) -> (f64, f64) {
        let next = theta + TAU / self.mf();
        let (a, b) = (self.psi(theta), self.psi(next));
        (b.0 - a.0, b.1 - a.1)
    }

    /// The mechanical advantage F_out/F_in (eq 21 with eqs 18-20) in its scalar reading:
    /// MA = r·[ψ'(θ + 2π/m) − ψ'(θ)]/(m·p) = r·δ'(θ)/(m·p), the power balance
    /// F_in·r·δ̇ = F_out·p·m·θ̇ (extraction §2.5; the vector reading does not give the paper's
    /// maxima).
    pub fn mechanical_advantage(&self, theta: f64) -> f64 {
        self.link * self.chamber_angle(theta).1 / (self.mf() * self.crank)
    }

    /// Piston k's coordinate x = r·ψ(θ + 2πk/m) and its crank-angle derivatives (module note).
    fn piston_curve(&self, k: usize, theta: f64) -> (f64, f64, f64) {
        let m = self.mf();
        let (psi, d1, d2) = self.psi(theta + TAU * k as f64 / m);
        let r = self.link;
        (r * psi, r * d1 / m, r * d2 / (m * m))
    }
}

/// No mass anywhere: the paper's kinematic model (its validation model has none either).
pub fn massless() -> MassProperties {
    MassProperties {
        crankshaft_inertia: 0.0,
        wheel_inertia: 0.0,
        rod_mass: 0.0,
        rod_inertia: 0.0,
        rod_cg: 0.0,
        piston_mass: 0.0,
        rod_material: crate::Material::Steel,
        wheel_mass: 0.0,
        crank_unbalance: 0.0,
    }
}

/// The inline slider-crank's mechanical advantage (Vidinsky eq 29, with eq 22),
/// MA_SC = sin θ·(1 + a·cos θ/√(h² − a²·sin²θ)), for crank `a` and coupler `h` at crank angle
/// `theta` (rad from the cylinder axis): the tangential crank-pin force over the piston force
/// (eq 28), for comparison with [`Hypotrochoid::mechanical_advantage`].
pub fn slider_crank_mechanical_advantage(a: f64, h: f64, theta: f64) -> f64 {
    let (s, c) = theta.sin_cos();
    s * (1.0 + a * c / (h * h - a * a * s * s).sqrt())
}

impl Hypotrochoid {
    /// The state at `crank`, all but its extras.
    fn fill_state(&self, crank: &CrankState, st: &mut State) {
        let (m, p, r, u) = (self.mf(), self.crank, self.link, self.planet);
        let n = self.modulus;
        let i = C::i();
        let theta = self.carrier_angle(crank.angle);
        // θ̇, θ̈: the carrier turns 1/m as fast as the crank (eq 4).
        let (td, tdd) = (crank.speed / m, crank.acceleration / m);
        let e_c = C::from_polar(1.0, -theta); // carrier and rotor rod 1 (eq 8)
        let e_a = C::from_polar(1.0, m * theta); // OA (eq 8)
                                                 // A = p·e^{imθ} (eq 8, eq 16 for A').
        let a = Curve(p * e_a, i * m * p * e_a, -m * m * p * e_a);
        // O_u = v·e^{−iθ}, v = m·u (eqs 2, 4).
        let ou = m * u * e_c;
        let ou = Curve(ou, -i * ou, -ou);
        // C_u = O_u + (A − O): the parallelogram.
        let cu = Curve(ou.0 + a.0, ou.1 + a.1, ou.2 + a.2);
        st.crank = *crank;
        let spin = |orientation, w: f64, alpha: f64, cg: PointMotion| BodyMotion {
            cg,
            orientation,
            angular_velocity: w,
            angular_acceleration: alpha,
        };
        st.bodies[CRANKSHAFT] = spin(
            crank.direction,
            crank.speed,
            crank.acceleration,
            PointMotion::default(),
        );
        st.bodies[CARRIER] = spin(e_c, -td, -tdd, PointMotion::default());
        // The planet turns with OA (PCC): +mθ̇ (eq 4, eq 8).
        st.bodies[PLANET] = spin(e_a, crank.speed, crank.acceleration, ou.motion(td, tdd));
        // The rotor: the PCC's coupler, parallel to the carrier, its centre of gravity at A (its
        // m rods are spaced evenly).
        st.bodies[ROTOR] = spin(e_c, -td, -tdd, a.motion(td, tdd));
        st.joints[0].relative_speed = crank.speed;
        st.joints[1].relative_speed = -td;
        st.joints[2].position = ou.0;
        st.joints[2].relative_speed = (m + 1.0) * td;
        // The pitch point, on the carrier line at (v + u); direction towards the planet centre;
        // pitch-line speed relative to the carrier u·(m+1)·θ̇.
        st.joints[3].position = (m + 1.0) * u * e_c;
        st.joints[3].direction = -e_c;
        st.joints[3].relative_speed = (m + 1.0) * u * td;
        st.joints[4].position = a.0;
        st.joints[4].relative_speed = (m + 1.0) * td;
        st.joints[5].position = cu.0;
        st.joints[5].relative_speed = (m + 1.0) * td;
        let cg = self.masses.rod_cg / r;
        for k in 0..n {
            let tk = theta + TAU * k as f64 / m;
            let (psi, d1, d2) = self.psi(tk);
            let e_b = C::from_polar(1.0, -psi);
            // B_k = r·e^{−iψ} (eq 8), B' (eq 17), B''.
            let b = Curve(r * e_b, -i * r * d1 * e_b, r * (-i * d2 - d1 * d1) * e_b);
            let e_k = C::from_polar(1.0, -tk);
            let (link, block) = (FIRST_LINK + k, FIRST_LINK + n + k);
            let w_link = -d1 * td;
            st.bodies[link] = spin(
                e_b,
                w_link,
                -(d2 * td * td + d1 * tdd),
                Curve(cg * b.0, cg * b.1, cg * b.2).motion(td, tdd),
            );
            st.bodies[block] = spin(e_k, -td, -tdd, b.motion(td, tdd));
            let j = FIXED_JOINTS + 3 * k;
            st.joints[j].relative_speed = w_link;
            st.joints[j + 1].position = b.0;
            st.joints[j + 1].relative_speed = w_link + td;
            st.joints[j + 2].position = b.0;
            st.joints[j + 2].direction = e_k;
            st.joints[j + 2].relative_speed = self.rod(tk).1 * td;
            let (x, dx, ddx) = self.piston_curve(k, theta);
            st.pistons[k] = crate::PistonMotion {
                position: x,
                velocity: dx * crank.speed,
                acceleration: ddx * crank.speed * crank.speed + dx * crank.acceleration,
                dx_dtheta: dx,
                d2x_dtheta2: ddx,
            };
        }
    }
}

impl Mechanism for Hypotrochoid {
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
        block.fill_each(&self.topology, |c, st| self.fill_state(c, st));
    }

    /// Refuses a grid with a step on a fold of the parallelogram chain (module note), where
    /// the planar solve is singular: |sin((m+1)θ)| below 1e-6 (the loads grow as its inverse).
    /// Only the grid points nearest each fold in the run's carrier range are looked at.
    fn check_angles(&self, first: f64, step: f64, steps: usize) -> Result<(), MechanismError> {
        let k = self.mf() + 1.0;
        let (a, d) = (self.carrier_angle(first), step / self.mf());
        let b = a + d * steps as f64;
        let (lo, hi) = ((a.min(b) * k / PI).floor(), (a.max(b) * k / PI).ceil());
        let mut fold = lo;
        while fold <= hi {
            let i = ((fold * PI / k - a) / d).round();
            if (0.0..=steps as f64).contains(&i) {
                let angle = first + i * step;
                if self.fold_sine(self.carrier_angle(angle)).abs() < 1e-6 {
                    return Err(MechanismError::new(
                        Input::Steps,
                        steps,
                        format!(
                            "step {i} (crank angle {:.4}°) lands on a fold of the hypotrochoid's parallelogram chain, sin((m+1)θ) = 0, where its loads are singular; choose a number of steps or a start angle that avoids it (e.g. steps = {})",
                            angle.to_degrees(),
                            steps + 1
                        ),
                    ));
                }
            }
            fold += 1.0;
        }
        Ok(())
    }

    fn fill_extras(&self, st: &mut State) {
        let theta = self.carrier_angle(st.crank.angle);
        st.extras[0] = theta.to_degrees().rem_euclid(360.0);
        st.extras[1] = self.chamber_angle(theta).0.to_degrees();
        st.extras[2] = self.mechanical_advantage(theta);
    }

    /// x₁ = r·ψ(θ) and dx₁/dφ (module note), as in [`Mechanism::fill_block`].
    fn piston_position(&self, angle: f64) -> (f64, f64) {
        let (x, dx, _) = self.piston_curve(0, self.carrier_angle(angle));
        (x, dx)
    }

    /// The crank OA = p: the radius of Vidinsky's F_out (L225). A summary's
    /// |dx/dθ|/p for one piston link is r·ψ'/(m·p), the single-link ratio; eq 21's MA (the
    /// `mechanical_advantage` extra) takes the difference of two adjacent links.
    fn crank_radius(&self) -> f64 {
        self.crank
    }

    /// The piston links turn: their chambers are the angles between them, not cylinders.
    fn has_cylinder(&self) -> bool {
        false
    }

    /// x₁ at φ = π/2, the first chamber's minimum L_m (module note).
    fn piston_top(&self) -> f64 {
        self.piston_position(FRAC_PI_2).0
    }

    /// [`Mechanism::piston_top`] less the first chamber's arc swing r·(δ(N_m) − δ(L_m)).
    fn piston_bottom(&self) -> f64 {
        let (l, _, n) = self.working_range();
        self.piston_top() - self.link * (self.chamber_angle(n).0 - self.chamber_angle(l).0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn paper(m: usize) -> Hypotrochoid {
        Hypotrochoid::new(
            m,
            0.75,
            1.7 * m as f64,
            1.0,
            massless(),
            [Bearings::single(0.01, 1e4); 3],
        )
        .unwrap()
    }

    /// Loop closure A + (B − A) = B (eq 8) with q of eq 13 (both forms) along rod k.
    #[test]
    fn loop_closure() {
        for m in 2..=4 {
            let h = paper(m);
            for j in 0..50 {
                let th = -3.0 + 0.17 * j as f64;
                let st = h.state(&CrankState::new(h.crank_angle(th), 1.0, 0.0, 0.0));
                let a = st.joints[4].position;
                for k in 0..m {
                    let tk = th + TAU * k as f64 / m as f64;
                    let b = st.joints[FIXED_JOINTS + 3 * k + 1].position;
                    let q = h.rod(tk).0;
                    assert!((a + q * C::from_polar(1.0, -tk) - b).norm() < 1e-12);
                    let (chi, ..) = h.chi(tk);
                    let k1 = (m + 1) as f64;
                    let q13 = (0.75f64.powi(2) + h.link.powi(2)
                        - 2.0 * 0.75 * h.link * (k1 * tk - chi).cos())
                    .sqrt();
                    assert!((q - q13).abs() < 1e-12);
                }
            }
        }
    }
}
