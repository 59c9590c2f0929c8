//! The loads of any mechanism of `cardan-mechanism` at a block of steps, apart from the step
//! loop that streams them: the load families ([`family`]: the bodies' inertia, the gas on the
//! pistons, each a force on every joint and a torque on the drive, [`LoadFamily`]), the general
//! planar Newton-Euler solve with every joint reaction unknown ([`planar`], faer), the bodies'
//! kinetic energy and each body's share of the drive torque ([`energy`]), and the reduced
//! inertia J*(θ) of the machine motion ([`reduced_inertia`](mod@reduced_inertia)). `cardan-dynamics` runs them at
//! every step and re-exports this crate's items.

pub mod energy;
pub mod family;
pub mod planar;
pub mod reduced_inertia;

pub use energy::{kinetic_energy, torque_shares};
pub use family::{main_bearing, Gas, Inertial, LoadFamily, Solver};
pub use reduced_inertia::{reduced_inertia, ReducedInertia, ReducedInertiaOf};
