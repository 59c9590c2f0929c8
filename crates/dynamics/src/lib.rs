//! Kinetostatics: the joint forces and the crank torque that make a mechanism follow its
//! prescribed motion, from the inertia of its links and the loads applied to its piston.
//!
//! Two independent paths compute the same loads:
//! - the closed forms of Karhula (2008), appendix 5.2.1, per mechanism ([`slider_crank`],
//!   [`cardan_gear`]);
//! - a general planar solve ([`planar`]): Newton-Euler equations of every link with all joint
//!   reactions as unknowns of one linear system per step, solved with faer.
//!
//! Sign conventions: forces are complex vectors in the frame of the main bearing axis (cylinder
//! on the imaginary axis); the crank torque is the torque the drive must apply to the crankshaft,
//! positive in the direction of rotation, so that its work over a crank-angle interval equals the
//! gain of kinetic energy of the links plus the work done on the gas.

pub mod cardan_gear;
pub mod cycle;
pub mod kinetostatics;
pub mod mass_properties;
pub mod planar;
pub mod slider_crank;

pub use cycle::{run_cycle, Metric, Step, Summary};
pub use kinetostatics::{kinetic_energy, loads, Loads};
pub use mass_properties::{MassProperties, Material};
