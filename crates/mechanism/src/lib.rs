//! Reciprocating mechanisms on the complex plane: what each is made of (bodies, joints,
//! pistons), how it moves, and its closed-form kinetostatics.
//!
//! Conventions of Karhula (2008), chapter 4: the main bearing axis is the origin, the cylinder
//! lies on the imaginary (iy) axis, the crank angle θ is measured from the real axis and grows in
//! the direction of rotation, so θ = 90° is top dead centre. Every quantity is SI: m, m/s, m/s²,
//! rad, rad/s, rad/s², s, kg, N.
//!
//! A mechanism declares its [`Topology`] and fills the motion of its bodies, joints and pistons
//! at a block of crank states, as columns ([`StateBlock`]; a lane of it is one [`State`]); code
//! outside a mechanism's own module reads bodies, joints and pistons from those lists and never
//! asks which mechanism it has. The mechanisms a case file may name are listed in
//! [`MECHANISMS`].

pub mod block;
pub mod cardan_gear;
mod crank;
pub mod hypotrochoid;
mod input;
mod interface;
pub mod mass;
pub mod model;
pub mod motion;
pub mod polar;
pub mod scotch_yoke;
pub mod slider_crank;

pub use block::{
    use_avx2, BodyColumns, Column, CrankColumns, JointColumns, JointLoadColumns, LoadsBlock,
    PistonColumns, PointColumns, StateBlock, LANES, ZERO,
};
pub use cardan_gear::{CardanGear, MeshModel};
pub use crank::CrankState;
pub use crank::C;
pub use hypotrochoid::Hypotrochoid;
pub use input::Input;
pub(crate) use interface::{check_length, check_rod_cg, number, word};
pub use interface::{
    Build, Entry, MachineGeometry, Mechanism, MechanismError, OptionKind, OptionSpec, OptionValue,
    Options,
};
pub use mass::{MassInputs, MassProperties, MassRules, Material};
pub use model::{
    cross, Bearings, Body, BodyMotion, ExtraColumn, Joint, JointKind, JointLoad, JointMotion,
    Loads, MeshForce, Piston, PistonMotion, PointMotion, State, Topology,
};
pub use motion::{CrankMotion, Grid, MotionError, MotionSource, CHAINS, REANCHOR};
pub use polar::PolarComponents;
pub use scotch_yoke::ScotchYoke;
pub use slider_crank::SliderCrank;

/// Every mechanism a case file may name.
pub const MECHANISMS: &[Entry] = &[
    slider_crank::ENTRY,
    cardan_gear::ENTRY,
    scotch_yoke::ENTRY,
    hypotrochoid::ENTRY,
];

impl Input {
    /// Every input a mechanism error can name: [`Input::SHARED`] and every option of every
    /// registry entry (here, at the root, since it reads the registry).
    pub fn all() -> Vec<Input> {
        let options = MECHANISMS.iter().flat_map(|e| {
            e.options.iter().map(move |o| Input::Option {
                mechanism: e.name,
                name: o.name,
            })
        });
        Input::SHARED.into_iter().chain(options).collect()
    }
}

/// The registry entry called `name`.
pub fn entry(name: &str) -> Option<&'static Entry> {
    MECHANISMS.iter().find(|e| e.name == name)
}

/// The names of every registered mechanism, quoted, for messages.
pub fn names() -> String {
    MECHANISMS
        .iter()
        .map(|e| format!("\"{}\"", e.name))
        .collect::<Vec<_>>()
        .join(", ")
}
