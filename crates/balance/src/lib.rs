//! Balance of reciprocating machines, for any declared mechanism: the shaking force and moment
//! its moving masses exert on the frame, summed over the cylinders of a multi-cylinder layout,
//! split into orders of the crank speed (forward and backward rotating components), and the
//! rotating masses that cancel them (counterweights, Lanchester shafts, the cardan gear's
//! counterweight pair).
//!
//! Pure functions and plain structs over [`cardan_mechanism`]'s [`Topology`](cardan_mechanism::Topology)
//! and [`State`](cardan_mechanism::State): no code here names a mechanism (its tests check
//! that, `tests/architecture.rs`). SI throughout: m, kg, kg·m (mass·radius), N, N·m, rad,
//! rad/s. Planar vectors are complex numbers x + i·y in the frame of Karhula (2008) ch. 4 (the
//! crank axis at the origin, the cylinder along +y, the crank angle θ from +x, counter-clockwise
//! in the direction of rotation). The published values and equations relied on are written out
//! in `docs/validation/balance.md`.
//!
//! - [`shaking`](fn@shaking): one mechanism's [`Shaking`] at one state: F = −Σ m·a, and its roll moment;
//! - [`Layout`]: cylinders on one crankshaft (throw, axis angle, axial position):
//!   [`MachineShaking`] (force, free pitch and yaw moments), [`MachineOrders`];
//! - [`orders`]: the [`Order`]s of a planar vector over a revolution, each with its forward and
//!   backward components and amplitude |A| + |B|;
//! - [`Rotor`]: a mass·radius turning at k times the crank angle, and the devices built from
//!   masses: [`crank_counterweight`] (from [`FirstOrderMasses`]), [`lanchester_shafts`],
//!   [`CardanCounterweights`] (from [`CardanMasses`]).

pub mod counterweight;
mod device_error;
pub mod harmonics;
pub mod layout;
pub mod machine;
pub mod shaking;

pub use counterweight::{
    crank_counterweight, lanchester_shafts, CardanCounterweights, CardanMasses, FirstOrderMasses,
    Rotor,
};
pub use device_error::{Device, DeviceError};
pub use harmonics::{orders, revolution, Order};
pub use layout::{
    throws_from_firing_order, Cylinder, Layout, MachineOrders, MachineShaking, OrdersScratch,
};
pub use machine::{
    CylinderScratch, MachineBalance, Phase, PreparedBalance, MAX_ORDER, ORDER_STEPS,
};
pub use shaking::{shaking, shaking_lane, Shaking};
