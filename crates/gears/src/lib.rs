//! Spur gear physics for the cardan gear (geared hypocycloid) and its comparison with the
//! slider-crank: pure functions and plain structs, SI units inside (m, N, Pa, rad, rad/s, W).
//!
//! * [`geometry`] — ISO 21771 spur pair, external and internal (internal gear = negative tooth
//!   count, ISO profile-shift signs): diameters, working pressure angle by involute inversion,
//!   working centre distance, path of contact, transverse contact ratio, backlash; checks for
//!   an internal pair (KHK involute and trochoid interference, ring tip inside its base circle,
//!   minimum teeth difference, backlash sign, contact ratio, undercut) with margins and
//!   remedies; Karhula's printed path-of-contact and contact-ratio formulas (A9.1.40, A9.1.52)
//!   and the cardan module `m = 2e/z1` (A9.1.37).
//! * [`buckingham`] — Buckingham's dynamic tooth load exactly as Karhula 2008 (A8.1.1–14),
//!   with its US-unit constant converted exactly; the simplified `K3 v` form.
//! * [`agma`] — AGMA 2001-D04 bending and contact stresses and safety factors with the full
//!   factor set ([`agma::factors`]), AGMA 908 geometry factors ([`agma::geometry_factors`]:
//!   `I` by formula for external and internal pairs, the AGMA 908 tables reproduced by Nunes
//!   2017), face-width sizing for single and twin sets, and Nunes 2017's own reading of
//!   the internal pair ([`agma::nunes`]).
//! * [`agma908`] — AGMA 908-B89's `J` of external gears computed from the generated tooth
//!   form (Lewis parabola in the trochoid fillet, load at HPSTC, `K_f`); for an internal ring
//!   `J` from ISO 6336-3 method B; [`bending_memo`] keeps them by their exact inputs for the
//!   points of a sweep.
//! * [`tooth_root`] — the generated fillet and ISO 6336-3 method B's `Y_F`, `Y_S` and critical
//!   section (`s_Fn`, `h_Fe`, `ρ_F`, `α_Fen`), external and internal.
//! * [`mod@mesh_loss`] — Anderson & Loewenthal mesh power loss (sliding with Benedict & Kelley,
//!   rolling with the EHD film, windage) in Karhula's printed reading and a corrected reading
//!   ([`mesh_loss::Reading`]).
//! * [`iso6336`] — ISO 6336-1/-2/-3:2019 method B rating (`S_H`, `S_F`) beside AGMA's, with
//!   the factors in [`iso6336_load`], [`iso6336_pitting`], [`iso6336_bending`].
//! * [`materials`] — named gear materials: E, ν, AGMA 2001 allowables by grade and hardness,
//!   ISO 6336-5 `σ_Hlim`, `σ_Flim` by quality grade.
//! * [`tooth_measurement`] — span width `W_k` and dimension over pins/balls (ISO 21771 §6).
//! * [`gear_set`] — per crank-angle step: tangential load and speeds in, dynamic load,
//!   stresses, safety factors and mesh loss out.
//!
//! Sources: Karhula 2008 (thesis, Lappeenranta), Nunes 2017 (thesis), ISO 21771:2007, AGMA
//! 2001-D04 / 2101-D04, AGMA 908-B89, Budynas & Nisbett *Shigley's MED* ch. 14, KHK *Gear
//! Technical Reference*, Anderson & Loewenthal NASA TP-1622. Nothing panics on bad input:
//! errors are [`GearError`].

pub mod agma;
pub mod agma908;
pub mod bending_memo;
pub mod buckingham;
pub mod error;
pub mod gear_set;
pub mod geometry;
pub mod involute;
pub mod iso6336;
pub mod iso6336_bending;
pub mod iso6336_load;
pub mod iso6336_pitting;
pub mod materials;
pub mod mesh_loss;
pub mod tooth_measurement;
pub mod tooth_root;
pub mod units;

pub use agma::factors::{
    bending_cycle_factor, dynamic_factor, elastic_coefficient, hardness_ratio_factor,
    pitting_cycle_factor, reliability_factor_fit, reliability_factor_table, size_factor_shigley,
    BendingHighCycle, BendingLowCycle, DynamicFactor, Enclosure, HardnessPairing, LoadDistribution,
    Quality,
};
pub use agma::geometry_factors::{agma908_table, pitting_geometry_factor, IForm, ShiftCase};
pub use agma::{
    CheckedRating, FaceWidths, GearSetRating, MemberData, PreparedRating, Rating, SizeFactor,
};
pub use agma908::{bending_geometry_factor, BendingJ, JMethod};
pub use bending_memo::BendingJMemo;
pub use buckingham::{BuckinghamPair, DynamicLoad, SaturatedLoad, ToothForm, FULL_DEPTH_20};
pub use error::GearError;
pub use gear_set::{GearSet, MeshStep, StepResult};
pub use geometry::checks::{CheckKind, CheckReport, Remedy};
pub use geometry::{
    cardan_module, check_pitch_line_velocity, Diameters, GearPair, GearSpec, PairSpec, Tip,
    MAX_PITCH_LINE_VELOCITY,
};
pub use mesh_loss::{
    mesh_loss, mesh_loss_with, LossOptions, Lubricant, MeshGeometry, MeshLoss, MeshSpeeds,
    PreparedMeshLoss, Reading,
};
pub use tooth_root::{iso6336_method_b, GeneratedMember, PairMember, RootFactors, RootSection};
