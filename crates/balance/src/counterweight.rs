//! Rotating masses: the crank's own unbalance, counterweights, Lanchester balance shafts and the
//! cardan gear's wheel and its counterweight pair.
//!
//! Each is a [`Rotor`]: a mass·radius product u (kg·m, a complex number: its direction at
//! crank angle θ = 0) turning at k times the crank angle, z = c + u·e^{ikθ}/m about a fixed centre
//! c. Its acceleration is (u/m)·(i·k·α − k²·ω²)·e^{ikθ}, so it shakes the frame with
//! F = −m·a = u·(k²·ω² − i·k·α)·e^{ikθ} (the time derivatives of Karhula 2008 A4.2.2.2,
//! A4.2.2.11, A4.2.2.30 at k·θ), whatever its mass and centre. k = 1: on the crank;
//! k = −1: on a body turning backwards at the crank speed (the cardan wheel); k = ±2: a
//! Lanchester shaft geared 2:1 to the crank.
//!
//! What each device cancels is computed from the masses, never assumed: the counterweight from
//! the rotating and reciprocating masses ([`FirstOrderMasses`]), the balance shafts from the
//! second order to cancel, the cardan pair from the rod, wheel and crank masses
//! ([`CardanMasses`]); the tests add the rotors' forces to the mechanism's own and find what
//! is left.

use crate::harmonics::Order;
use cardan_mechanism::{CrankState, C};

/// A mass·radius turning at `order` times the crank angle (module note).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rotor {
    /// u = m·ρ·e^{iγ}, kg·m: the mass times the radius of its centre of gravity from its axis,
    /// directed where that centre is at crank angle θ = 0 (in the frame of the mechanism or
    /// machine it belongs to).
    pub mass_radius: C,
    /// k: +1 turns with the crank, −1 against it at the same speed, ±2 at twice its speed.
    pub order: i32,
    /// Position along the crank axis, m (for the free moments of a machine; 0 in one plane).
    pub axial_position: f64,
}

impl Rotor {
    /// A mass·radius `mass_radius` (kg·m) on the crank in the plane at `axial_position` (m).
    pub fn on_crank(mass_radius: C, axial_position: f64) -> Self {
        Self {
            mass_radius,
            order: 1,
            axial_position,
        }
    }

    /// The crank's own unbalance m·e (kg·m, crank pin, webs, without counterweights), towards
    /// the crank pin (the crank's direction e^{iθ}).
    pub fn crank_unbalance(mass_radius: f64) -> Self {
        Self::on_crank(C::new(mass_radius, 0.0), 0.0)
    }

    /// Its shaking force at `crank`, N: u·(k²·ω² − i·k·α)·e^{ikθ} (module note).
    pub fn force(&self, crank: &CrankState) -> C {
        let k = self.order as f64;
        let (w, a) = (crank.speed, crank.acceleration);
        self.mass_radius * C::new(k * k * w * w, -k * a) * C::from_polar(1.0, k * crank.angle)
    }
}

/// A cylinder's first-order masses as the balancing texts split them: the mass·radius that
/// turns with the crank, and the reciprocating mass times the crank radius, whose first-order
/// force m·r·ω²·cos φ along the cylinder is half a forward and half a backward rotating vector
/// (`docs/validation/balance.md`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FirstOrderMasses {
    /// Σ m·ρ of the masses turning with the crank, kg·m, in the crank's frame (real and positive
    /// towards the crank pin).
    pub rotating: C,
    /// Reciprocating mass times the crank radius, m_rec·r, kg·m.
    pub reciprocating: f64,
}

impl FirstOrderMasses {
    /// The masses that give `first`, a mechanism's first order at constant speed `speed`
    /// (rad/s), in the frame of its cylinder: the axis along +y, top dead centre at θ = π/2, as
    /// every in-line mechanism has it ([`cardan_mechanism::Mechanism::top_dead_centre`]).
    ///
    /// A reciprocating m·r on the axis i moving as r·sin θ shakes with m·r·ω²·sin θ·i =
    /// (m·r·ω²/2)·(e^{iθ} − e^{−iθ}); a rotating u with u·ω²·e^{iθ}. So B₁ = −m·r·ω²/2 and
    /// A₁ = (u + m·r/2)·ω²: m·r = 2·|B₁|/ω², u = A₁/ω² − m·r/2. Other first-order content
    /// (a piston-pin offset's phase) shows as a rotating part off the crank's direction.
    pub fn from_first_order(first: &Order, speed: f64) -> Self {
        let w2 = speed * speed;
        let reciprocating = 2.0 * first.backward.norm() / w2;
        Self {
            rotating: first.forward / w2 - reciprocating / 2.0,
            reciprocating,
        }
    }

    /// These masses with the crank's own unbalance `crank_unbalance` (kg·m) added.
    pub fn with_crank_unbalance(self, crank_unbalance: f64) -> Self {
        Self {
            rotating: self.rotating + crank_unbalance,
            ..self
        }
    }
}

/// The counterweight opposite the crank pin that balances all the rotating mass and the
/// fraction `fraction` of the reciprocating mass of `masses`: u = −(Σ m·ρ_rot + c·m_rec·r)
/// (the balancing texts' B·b = (m₁ + c·m)·r, `docs/validation/balance.md`), on the crank at
/// `axial_position` (m). A fraction 0 balances the rotating masses only, 1 all of the first
/// order along the cylinder (moving it across).
pub fn crank_counterweight(masses: &FirstOrderMasses, fraction: f64, axial_position: f64) -> Rotor {
    Rotor::on_crank(
        -(masses.rotating + fraction * masses.reciprocating),
        axial_position,
    )
}

/// Two shafts at twice the crank speed, one each way, that cancel `second` (a second order at
/// constant speed `speed`, rad/s): a shaft of u at k = ±2 shakes with 4·u·ω²·e^{±2iθ}, so
/// u₊ = −A₂/(4ω²), u₋ = −B₂/(4ω²) (Lanchester's balancer; equal and counter-rotating for a
/// reciprocating second order, |A₂| = |B₂|). Both at `axial_position` (m).
pub fn lanchester_shafts(second: &Order, speed: f64, axial_position: f64) -> [Rotor; 2] {
    let w2 = 4.0 * speed * speed;
    [
        Rotor {
            mass_radius: -second.forward / w2,
            order: 2,
            axial_position,
        },
        Rotor {
            mass_radius: -second.backward / w2,
            order: -2,
            axial_position,
        },
    ]
}

/// The cardan gear's moving masses as balance needs them (the mechanism may fold the wheel's
/// mass into its crankshaft: these are given explicitly).
///
/// The crank of length r_c carries the wheel's centre S = r_c·e^{iθ}; the wheel (pitch radius
/// r_c) turns at −θ, the line S→T to its pin at angle π − θ, so T = S + r_c·e^{i(π−θ)} =
/// 2·r_c·sin θ·i stays on the cylinder axis (Karhula 2008 A4.2.2.56-60). A point of the wheel
/// is a forward rotor on the crank plus a backward one about S.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CardanMasses {
    /// r_c, m: the cardan crank (a quarter of the stroke), the wheel's pitch radius.
    pub crank: f64,
    /// Mass moving with the wheel pin T on the cylinder axis (rod, piston), kg.
    pub reciprocating: f64,
    /// The wheel's mass, kg, its centre of gravity at its centre S.
    pub wheel: f64,
    /// The crank's own m·e towards S, kg·m.
    pub crank_unbalance: f64,
}

impl CardanMasses {
    /// The wheel's mass and the crank's unbalance as rotors (the reciprocating mass is the
    /// mechanism's own body): both forward, (m_w·r_c + m·e) towards S. Add them to a shaking
    /// force only where the mechanism's topology does not carry them already (today it folds
    /// the wheel into a massless body and the crankshaft is balanced: both masses 0); the
    /// counterweights ([`CardanCounterweights::for_masses`]) need them either way.
    pub fn rotors(&self) -> Vec<Rotor> {
        vec![Rotor::on_crank(
            C::new(self.wheel * self.crank + self.crank_unbalance, 0.0),
            0.0,
        )]
    }
}

/// The counterweight pair that cancels a cardan gear's shaking force.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CardanCounterweights {
    /// The wheel's counterweight, kg, at `wheel_radius` from S opposite the pin T.
    pub wheel_mass: f64,
    /// Its radius on the wheel, m.
    pub wheel_radius: f64,
    /// The crank's counterweight, kg·m, opposite S.
    pub crank_mass_radius: f64,
}

impl CardanCounterweights {
    /// The pair for `masses`, the wheel's counterweight at `wheel_radius` (m) from S.
    ///
    /// The reciprocating mass m at T = r_c·e^{iθ} − r_c·e^{−iθ} is a forward m·r_c and a backward
    /// −m·r_c. A mass m₂ on the wheel at ρ opposite T sits at S − ρ·e^{i(π−θ)} = r_c·e^{iθ} +
    /// ρ·e^{−iθ}: forward m₂·r_c, backward m₂·ρ. The backward parts cancel for m₂·ρ = m·r_c; the
    /// forward ones, (m + m_w + m₂)·r_c + m·e, are cancelled by the crank's counterweight
    /// opposite S. Every point then has its mirror, at any crank acceleration.
    pub fn for_masses(masses: &CardanMasses, wheel_radius: f64) -> Self {
        let wheel_mass = masses.reciprocating * masses.crank / wheel_radius;
        let forward = (masses.reciprocating + masses.wheel + wheel_mass) * masses.crank
            + masses.crank_unbalance;
        Self {
            wheel_mass,
            wheel_radius,
            crank_mass_radius: forward,
        }
    }

    /// The pair as rotors in the cylinder's frame: the wheel's counterweight (forward
    /// m₂·r_c, backward m₂·ρ) and the crank's (forward, opposite S).
    pub fn rotors(&self, masses: &CardanMasses) -> Vec<Rotor> {
        vec![
            Rotor::on_crank(C::new(self.wheel_mass * masses.crank, 0.0), 0.0),
            Rotor {
                mass_radius: C::new(self.wheel_mass * self.wheel_radius, 0.0),
                order: -1,
                axial_position: 0.0,
            },
            Rotor::on_crank(C::new(-self.crank_mass_radius, 0.0), 0.0),
        ]
    }
}
