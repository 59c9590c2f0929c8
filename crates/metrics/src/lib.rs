//! The metric registry: one definition per summary metric (name, unit, meaning, what it
//! aggregates, its group and which way is better), from which `summary.json`'s units and the
//! metric table of docs/results.md are produced; and a run's metrics ([`Summary`]). The registry
//! is made of parts, one per producer: the summary's own, each per-step stage's
//! (`cardan_dynamics::Stage::metrics` is its part), the engine's fmep, the gas models'.
//! A name may hold `{piston}`, `{body}`, `{joint}` (a name from the mechanism's topology) and
//! `{family}` (`inertial`; with a gas model also `gas` and `total`).

/// What a metric describes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Aggregation {
    /// One crank train (one mechanism; of an opposed-piston engine, one of its two).
    CrankTrain,
    /// The cylinder's working chamber (both pistons of an opposed-piston engine).
    Cylinder,
    /// The run as a whole.
    Run,
}

impl Aggregation {
    pub fn name(self) -> &'static str {
        match self {
            Aggregation::CrankTrain => "crank train",
            Aggregation::Cylinder => "cylinder",
            Aggregation::Run => "run",
        }
    }
}

/// The subject a metric belongs to: the sections of a case report's metric tables, in report
/// order.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Group {
    /// Motion of the pistons and bodies, the mechanism's leverage, the run's duration.
    Kinematics,
    /// Forces and couples at one joint (a report makes one section per joint).
    JointLoads,
    /// Drive torque, power and work, the energy check, a pump's need and an engine's output.
    DriveTorque,
    /// The cylinder's pressure, the gas force and the closed cycle's or compressor's results.
    Gas,
    /// The rating of the gear meshes (AGMA, Buckingham, mesh losses).
    GearRating,
    /// Friction losses, friction mean effective pressures and the mechanical efficiency.
    Losses,
    /// The machine's shaking force and free moments, their orders, the torque's uniformity
    /// (issue 24, `cardan-balance`).
    Balance,
    /// The whole machine: every cylinder's drive torque, power, losses and efficiency, the
    /// loads of its main journals and crank pins (issue 35, `cardan_dynamics::Machine`).
    Machine,
}

impl Group {
    /// Every group, in report order.
    pub const ALL: [Group; 8] = [
        Group::Machine,
        Group::Kinematics,
        Group::JointLoads,
        Group::DriveTorque,
        Group::Gas,
        Group::GearRating,
        Group::Losses,
        Group::Balance,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Group::Kinematics => "kinematics",
            Group::JointLoads => "joint loads",
            Group::DriveTorque => "drive torque, power and work",
            Group::Gas => "cylinder and gas",
            Group::GearRating => "gear rating",
            Group::Losses => "losses and efficiency",
            Group::Balance => "balance: shaking forces and moments",
            Group::Machine => "the whole machine",
        }
    }
}

/// Which way a metric is better, comparing two mechanisms on the same duty.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Better {
    /// Loads, stresses, peak torques, needs, losses, errors.
    Lower,
    /// Efficiencies, outputs, safety factors, contact ratio, mechanical advantage.
    Higher,
    /// Neither (a state or a signed sum: stroke, speeds, mean drive power, kinetic energy
    /// change, cycle time, pressures).
    Neither,
}

impl Better {
    pub fn name(self) -> &'static str {
        match self {
            Better::Lower => "lower",
            Better::Higher => "higher",
            Better::Neither => "—",
        }
    }
}

/// One metric's definition.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MetricDef {
    pub name: &'static str,
    /// SI unit, as written in summary.json ("1" for fractions).
    pub unit: &'static str,
    pub meaning: &'static str,
    pub aggregation: Aggregation,
    /// The report section it belongs to.
    pub group: Group,
    /// Which way is better.
    pub better: Better,
}

const fn def(
    name: &'static str,
    unit: &'static str,
    aggregation: Aggregation,
    group: Group,
    better: Better,
    meaning: &'static str,
) -> MetricDef {
    MetricDef {
        name,
        unit,
        meaning,
        aggregation,
        group,
        better,
    }
}

use Aggregation::{CrankTrain as T, Cylinder as Y, Run as R};
use Better::{Higher as Hi, Lower as Lo, Neither as Ne};
use Group::{
    DriveTorque as D, Gas as G, GearRating as GR, JointLoads as J, Kinematics as K, Losses as L,
};

/// The metrics of every run, from the summary's own accumulators (`summary/`: the motion's peaks,
/// each family's joint peaks and drive work, the lever, the energy check).
pub const RUN: &[MetricDef] = &[
    def("piston_stroke", "m", T, K, Ne, "top minus bottom dead-centre position of the piston pin"),
    def("{piston}_velocity_max", "m/s", T, K, Ne, "largest piston speed along the cylinder"),
    def("{piston}_acceleration_max", "m/s^2", T, K, Ne, "largest piston acceleration along the cylinder"),
    def("{body}_cg_velocity_max", "m/s", T, K, Ne, "largest speed of the body's centre of gravity"),
    def("{body}_cg_acceleration_max", "m/s^2", T, K, Ne, "largest acceleration of the body's centre of gravity"),
    def("{body}_angular_velocity_max", "rad/s", T, K, Ne, "largest angular speed of the body"),
    def("{body}_angular_acceleration_max", "rad/s^2", T, K, Ne, "largest angular acceleration of the body"),
    def("{family}_{joint}_force_max", "N", T, J, Lo, "largest force magnitude at the joint (frictionless)"),
    def("{family}_{joint}_moment_max", "N*m", T, J, Lo, "largest couple a slide carries (slides only)"),
    def("{family}_{joint}_tangential_max", "N", T, J, Lo, "gear meshes: largest tangential (torque-transmitting) tooth load, along the pitch-circle tangent (Karhula A8.1.10)"),
    def("{family}_torque_max", "N*m", T, D, Lo, "largest drive torque magnitude on the crankshaft"),
    def("{family}_work", "J", T, D, Ne, "drive work ∫ T dθ over the run (Karhula A5.2.1.37); an engine's gas work is negative"),
    def("{family}_torque_mean", "N*m", T, D, Ne, "work / crank-angle span (A5.2.1.38)"),
    def("{family}_power_mean", "W", T, D, Ne, "T·ω averaged over crank angle, as the thesis tabulates (A5.2.1.39); the time average at constant speed"),
    def("mechanical_advantage_max", "1", T, K, Hi, "largest drive torque per unit piston force, over the crank radius: |dx/dθ|/p, Vidinsky's (2021) F_out/F_in (eq 21)"),
    def("mechanical_advantage_mean", "1", T, K, Hi, "the same averaged over the crank angle"),
    def("torque_per_force_stroke_max", "1", T, K, Hi, "largest drive torque per unit piston force per unit stroke, |dx/dθ|/stroke: the fair comparison at equal displacement"),
    def("kinetic_energy_change", "J", T, D, Ne, "kinetic energy of all bodies, end minus start: equals inertial_work (energy check)"),
    def("energy_balance_error", "1", T, D, Lo, "|inertial_work − kinetic_energy_change| / ∫|T_inertial| dθ (or 1e-12 of the kinetic energy where the drive moves less: a constant reduced inertia at constant speed): a case fails above 1e-3"),
    def("cycle_time", "s", R, K, Ne, "duration of the run"),
];

/// The metrics of the loss stage (`cardan_dynamics::LossBudget`), with friction: the losses, and the
/// need or output and the efficiency that follow from them.
pub const LOSSES: &[MetricDef] = &[
    def("loss_work", "J", T, L, Lo, "friction: energy lost over the run, Σ ∫ P dt of every loss component (Karhula A9.1.68-71)"),
    def("power_loss_mean", "W", T, L, Lo, "friction: loss_work / cycle_time (A9.1.56-59)"),
    def("power_loss_mean_{component}", "W", T, L, Lo, "friction: one component's mean power loss: rings, skirt, a slide, a revolute joint's bearings, a gear mesh (by joint name); of an engine also valve_train, accessories, pumping"),
    def("friction_torque_max", "N*m", T, L, Lo, "friction: largest drive torque that covers the losses, Σ P / ω"),
    def("torque_need_mean", "N*m", T, D, Lo, "pump (net work into the crank): (total_work + loss_work) / crank-angle span (A9.1.64-65)"),
    def("power_need_mean", "W", T, D, Lo, "pump: (total_work + loss_work) / cycle_time (A9.1.60-61)"),
    def("output_torque_mean", "N*m", T, D, Hi, "engine (net work out of the crank): (−total_work − loss_work) / crank-angle span (A9.1.66-67)"),
    def("output_power_mean", "W", T, D, Hi, "engine: (−total_work − loss_work) / cycle_time (A9.1.62-63)"),
    def("mechanical_efficiency", "1", T, L, Hi, "pump: gas_work / (total_work + loss_work) (A9.1.72-73); engine: (−total_work − loss_work) / −total_work (A9.1.74-75)"),
];

/// The metrics of the gear-rating stage (`cardan_dynamics::GearRatings`), with gear meshes rated.
pub const GEAR_RATING: &[MetricDef] = &[
    def("contact_ratio", "1", T, GR, Hi, "gear rating: transverse contact ratio of the mesh's pair (the smallest over the meshes)"),
    def("mesh_tangential_load_max", "N", T, GR, Lo, "gear rating: largest rated tooth load per gear set: the tangential mesh force (A8.1.10), or the ring force's magnitude with gear.tooth_load = \"ring_force\", or Karhula's reading with \"thesis\""),
    def("dynamic_tooth_load_max", "N", T, GR, Lo, "gear rating: largest Buckingham dynamic tooth load (Karhula A8.1.1-14)"),
    def("contact_stress_max", "Pa", T, GR, Lo, "gear rating: largest AGMA 2001-D04 contact stress"),
    def("contact_safety_factor", "1", T, GR, Hi, "gear rating: smallest AGMA pitting safety factor S_H over the run (stress ratio)"),
    def("bending_stress_max", "Pa", T, GR, Lo, "gear rating: largest AGMA bending stress (with the bending geometry factors J known)"),
    def("bending_safety_factor", "1", T, GR, Hi, "gear rating: smallest AGMA bending safety factor S_F over the run"),
    def("gear_mesh_power_loss_mean", "W", T, GR, Lo, "gear rating: mean Anderson & Loewenthal mesh loss (A9.1.40-55), all gear sets"),
    def("iso_contact_stress_max", "Pa", T, GR, Lo, "gear rating: largest ISO 6336-2:2019 method B contact stress σ_H over the run, members and meshes, at the rated tooth load (with gear.standard = \"iso6336\" or \"both\")"),
    def("iso_contact_safety_factor", "1", T, GR, Hi, "gear rating: smallest ISO 6336-2 pitting safety factor S_H = σ_HG/σ_H over the run (stress ratio, as AGMA's)"),
    def("iso_bending_stress_max", "Pa", T, GR, Lo, "gear rating: largest ISO 6336-3:2019 method B tooth root stress σ_F (Y_F, Y_S from the tooth form)"),
    def("iso_bending_safety_factor", "1", T, GR, Hi, "gear rating: smallest ISO 6336-3 root safety factor S_F = σ_FG/σ_F over the run"),
];

/// The metrics of [`GEAR_RATING`] that only an ISO 6336 rating gives (`[gear] standard =
/// "iso6336"` or `"both"`): its last four.
pub const GEAR_RATING_ISO: &[MetricDef] = GEAR_RATING.split_at(GEAR_RATING.len() - 4).1;

/// The metrics of [`GEAR_RATING`] that only an AGMA 2001 rating gives (`[gear] standard =
/// "agma2001"`, the default, or `"both"`).
pub const GEAR_RATING_AGMA: &[&str] = &[
    "contact_stress_max",
    "contact_safety_factor",
    "bending_stress_max",
    "bending_safety_factor",
];

/// The metrics of [`MACHINE`] taken from the machine's shaking at every step, which a run
/// computes only where its case asks (`[layout]` or `[balance]`); the orders are every run's.
pub const SHAKING_PEAKS: &[&str] = &["shaking_force_max", "shaking_moment_max"];

/// The fmep metrics of an engine with friction (`cardan_dynamics::engine_metrics`, after the run).
pub const ENGINE_FRICTION: &[MetricDef] = &[
    def("fmep", "Pa", T, L, Lo, "engine with friction: the run's friction mean effective pressure, loss_work per swept volume π/4·B²·stroke per four-stroke cycle (4π of crank angle)"),
    def("fmep_mechanical", "Pa", T, L, Lo, "engine with friction: fmep without the pumping component (the scope of fmep_pnh)"),
    def("fmep_pnh", "Pa", T, L, Lo, "engine with friction: whole-engine mechanical fmep of Patton, Nitschke & Heywood (1989), or with Sandoval & Heywood's (2003) update, on a one-cylinder engine of this bore and stroke, crank-angle mean over the run: a cross-check of fmep_mechanical"),
    def("fmep_pnh_crankshaft", "Pa", T, L, Lo, "engine with friction: fmep_pnh's main-bearing seals, main bearings and turbulent dissipation"),
    def("fmep_pnh_reciprocating", "Pa", T, L, Lo, "engine with friction: fmep_pnh's piston skirt, rings, rod bearing and gas-pressure loading of the rings"),
    def("fmep_pnh_valve_train", "Pa", T, L, Lo, "engine with friction: fmep_pnh's cam bearings, followers and oscillating valve-train terms"),
    def("fmep_pnh_auxiliaries", "Pa", T, L, Lo, "engine with friction: fmep_pnh's oil and water pumps and non-charging alternator"),
];

/// The peaks of a run with a gas model (the summary's own).
pub const GAS: &[MetricDef] = &[
    def(
        "cylinder_pressure_max",
        "Pa",
        Y,
        G,
        Ne,
        "largest absolute cylinder pressure",
    ),
    def(
        "gas_force_max",
        "N",
        T,
        G,
        Lo,
        "largest gas force on the piston",
    ),
];

/// The metrics a gas model gives of its cycle (`cardan_gas`, added by the runner).
pub const GAS_MODEL: &[MetricDef] = &[
    def(
        "imep",
        "Pa",
        Y,
        G,
        Ne,
        "closed cycle: indicated mean effective pressure W/V_d (Nunes eq 2.50)",
    ),
    def(
        "indicated_work",
        "J",
        Y,
        G,
        Ne,
        "closed cycle: ∮p dV of the chamber (eq 2.48)",
    ),
    def(
        "indicated_torque_mean",
        "N*m",
        Y,
        G,
        Ne,
        "closed cycle: W/(4π), the chamber's mean torque",
    ),
    def(
        "indicated_power",
        "W",
        Y,
        G,
        Ne,
        "closed cycle: W·ω/(4π) (eqs 2.46, 2.49); compressor: W·ω/(2π)",
    ),
    def(
        "peak_pressure",
        "Pa",
        Y,
        G,
        Ne,
        "closed cycle: largest pressure on its own integration step",
    ),
    def(
        "peak_pressure_angle_deg",
        "deg",
        Y,
        G,
        Ne,
        "closed cycle: crank angle of the peak from the cycle's first top dead centre",
    ),
    def(
        "combustion_efficiency",
        "1",
        Y,
        G,
        Hi,
        "closed cycle: η_c from λ (eq 2.56)",
    ),
    def(
        "isfc",
        "kg/J",
        Y,
        G,
        Lo,
        "closed cycle: gross indicated specific fuel consumption (eq 2.52)",
    ),
    def(
        "indicated_efficiency",
        "1",
        Y,
        G,
        Hi,
        "closed cycle: W over the fuel energy (eq 2.53)",
    ),
    def(
        "heat_loss_fraction",
        "1",
        Y,
        G,
        Lo,
        "closed cycle: heat lost to the walls and to vaporisation, share of the fuel energy",
    ),
    def(
        "exhaust_fraction",
        "1",
        Y,
        G,
        Lo,
        "closed cycle: energy left in the gas at exhaust opening, share of the fuel energy",
    ),
    def(
        "unreleased_fraction",
        "1",
        Y,
        G,
        Lo,
        "closed cycle: fuel energy never released, share",
    ),
    def(
        "delivered_mass_flow",
        "kg/s",
        Y,
        G,
        Hi,
        "compressor: mass delivered per second at the periodic steady state",
    ),
    def(
        "volumetric_efficiency",
        "1",
        Y,
        G,
        Hi,
        "compressor: inducted volume at suction state over the swept volume",
    ),
    def(
        "specific_energy",
        "J/kg",
        Y,
        G,
        Lo,
        "compressor: indicated work per kilogram delivered",
    ),
    def(
        "discharge_temperature",
        "K",
        Y,
        G,
        Ne,
        "compressor: gas temperature at the end of compression",
    ),
];

/// The whole machine's metrics (issue 35, the `cardan_dynamics::MachineStage`): its drive torque and
/// power, losses and efficiency, the loads of its main journals and crank pins, every cylinder
/// at its own crank angle, axis and gas phase; and its balance (issue 24): the shaking force and
/// free moments of all its cylinders and rotors on the frame, their orders at constant speed,
/// the machine torque's uniformity.
pub const MACHINE: &[MetricDef] = &[
    def("machine_torque_max", "N*m", R, Group::Machine, Ne, "largest drive torque of the whole crankshaft, signed (positive turning it forwards): every cylinder's gas and inertia at its own crank angle and gas phase, plus with [friction] every cylinder's losses Σ P / ω; equal to the one cylinder's total (and friction) torque for a machine of one cylinder"),
    def("machine_torque_min", "N*m", R, Group::Machine, Ne, "smallest drive torque of the whole crankshaft, signed (as machine_torque_max)"),
    def("machine_torque_mean", "N*m", R, Group::Machine, Ne, "(Σ of every cylinder's drive work ∫ T dθ + with [friction] the machine's loss work) / crank-angle span: what the motor gives (positive) or the engine gives out (negative); one cylinder: total_torque_mean, or torque_need_mean, or −output_torque_mean"),
    def("machine_power_mean", "W", R, Group::Machine, Ne, "the same work / cycle_time: a pump's or compressor's mean power need (positive), an engine's mean output with its sign turned (negative); one cylinder with friction: power_need_mean or −output_power_mean"),
    def("machine_loss_power_mean", "W", R, Group::Machine, Lo, "with [friction]: every cylinder's friction losses, Σ ∫ P dt / cycle_time (each cylinder's loss budget at its own state and loads)"),
    def("machine_mechanical_efficiency", "1", R, Group::Machine, Hi, "with [friction] and a gas model, one definition per machine kind whatever the run's motion, where its denominator is positive (Karhula's definitions are of a steady cycle): pump Σ gas work / (Σ drive work + loss work) (Karhula A9.1.72-73), engine (−Σ drive work − loss work) / −Σ drive work (A9.1.74-75), over every cylinder"),
    def("machine_main_bearing_force_max", "N", R, Group::Machine, Lo, "largest load over the run on any main journal of the crankshaft: one journal for a one-throw machine (the mechanism's main bearing, every cylinder's sum), else one each side of every throw, each throw's main-bearing load split half to each (statically determinate, docs/results.md)"),
    def("machine_crank_pin_force_max", "N", R, Group::Machine, Lo, "largest load over the run on any crank pin, a pin carrying every rod on it (a vee's pair, a radial's star)"),
    def("shaking_force_max", "N", R, Group::Balance, Lo, "largest magnitude over the run of the machine's shaking force on the frame, −Σ m·a of every moving body and rotor (counterweights, balance shafts) of every cylinder; with [layout] or [balance] (the shaking taken step by step)"),
    def("shaking_force_order_1", "N", R, Group::Balance, Lo, "amplitude of the shaking force's first order (once per revolution): the largest magnitude over a revolution of its forward and backward rotating components together, |A₁| + |B₁|, at constant speed (the case's initial speed)"),
    def("shaking_force_order_2", "N", R, Group::Balance, Lo, "the same, second order (twice per revolution)"),
    def("shaking_force_order_4", "N", R, Group::Balance, Lo, "the same, fourth order"),
    def("shaking_moment_max", "N*m", R, Group::Balance, Lo, "largest magnitude over the run of the machine's free moment about the crank-axis point midway between its outermost cylinders (pitch and yaw; the roll reaction is not part of it); with [layout] or [balance]"),
    def("shaking_moment_order_1", "N*m", R, Group::Balance, Lo, "amplitude of the free moment's first order, |A₁| + |B₁|, at constant speed (the case's initial speed)"),
    def("shaking_moment_order_2", "N*m", R, Group::Balance, Lo, "the same, second order"),
    def("torque_nonuniformity", "1", R, Group::Balance, Lo, "(machine_torque_max − machine_torque_min)/|machine_torque_mean| of the machine's drive torque (every cylinder's, with [friction] its losses), where its mean is not zero"),
];

/// The metrics of a solved machine motion (`[motion] mode = "dynamic"`,
/// `cardan_dynamics::machine_motion`), over the reported cycle; Petrescu's (2015) first approximation
/// (eq. 1-2: ω = ω_m·sqrt(J*_m/J*), J*_m = (J*_max + J*_min)/2) and dynamic coefficient
/// (eq. 4: D = ω/ω_m) beside the solved motion.
pub const MACHINE_MOTION: &[MetricDef] = &[
    def("speed_mean", "rad/s", T, K, Ne, "dynamic: time mean of the crank speed over the reported cycle, crank-angle span / cycle_time"),
    def("speed_min", "rad/s", T, K, Ne, "dynamic: smallest crank speed of the reported cycle, between the rows too (the cubic Hermite interpolant of ½ω² on each step)"),
    def("speed_max", "rad/s", T, K, Ne, "dynamic: largest crank speed of the reported cycle, between the rows too (the cubic Hermite interpolant of ½ω² on each step)"),
    def("speed_fluctuation_coefficient", "1", T, K, Lo, "dynamic: (speed_max − speed_min) / speed_mean"),
    def("kinetic_energy_fluctuation", "J", T, K, Ne, "dynamic: largest minus smallest kinetic energy ½·(J* + flywheel)·ω² of the reported cycle (the textbooks' fluctuation of energy ΔE)"),
    def("fluctuation_coefficient_linear", "1", T, K, Ne, "dynamic: the textbooks' linear approximation ΔE / (J_m·speed_mean²), J_m = (reduced_inertia_min + reduced_inertia_max)/2, beside speed_fluctuation_coefficient"),
    def("flywheel_inertia", "kg*m^2", T, K, Ne, "dynamic: the flywheel inertia the run used (given, or sized)"),
    def("flywheel_inertia_required", "kg*m^2", T, K, Lo, "dynamic, with flywheel.fluctuation_coefficient: the flywheel inertia that meets it on the solved motion (0: none needed)"),
    def("runup_time", "s", T, K, Ne, "dynamic: time from the start until the cycles' start speeds stay within 1 % of the reported cycle's (absent after one cycle or if not reached)"),
    def("reduced_inertia_min", "kg*m^2", T, K, Ne, "dynamic: smallest J* + flywheel over the reported cycle"),
    def("reduced_inertia_max", "kg*m^2", T, K, Ne, "dynamic: largest J* + flywheel over the reported cycle"),
    def("petrescu_speed_min", "rad/s", T, K, Ne, "dynamic: Petrescu's first approximation ω_m·sqrt(J*_m/J*_max), ω_m = speed_mean (eq. 1-2)"),
    def("petrescu_speed_max", "rad/s", T, K, Ne, "dynamic: Petrescu's first approximation ω_m·sqrt(J*_m/J*_min)"),
    def("petrescu_fluctuation_coefficient", "1", T, K, Ne, "dynamic: the fluctuation coefficient of Petrescu's first approximation, beside speed_fluctuation_coefficient"),
    def("dynamic_coefficient_min", "1", T, K, Ne, "dynamic: Petrescu's dynamic coefficient D = ω/ω_m (eq. 4) at its smallest, speed_min/speed_mean"),
    def("dynamic_coefficient_max", "1", T, K, Ne, "dynamic: the same at its largest, speed_max/speed_mean"),
];

/// Every metric a summary may hold, in summary order: the parts above, one after another.
pub const METRICS: &[MetricDef] = &concat::<{ count(PARTS) }>(PARTS);

/// The registry's parts, in summary order.
const PARTS: &[&[MetricDef]] = &[
    RUN,
    LOSSES,
    GEAR_RATING,
    ENGINE_FRICTION,
    GAS,
    GAS_MODEL,
    MACHINE,
    MACHINE_MOTION,
];

/// Definitions in all of `parts`.
const fn count(parts: &[&[MetricDef]]) -> usize {
    let (mut n, mut p) = (0, 0);
    while p < parts.len() {
        n += parts[p].len();
        p += 1;
    }
    n
}

/// The definitions of `parts`, one part after another (`N` of them in all).
const fn concat<const N: usize>(parts: &[&[MetricDef]]) -> [MetricDef; N] {
    let mut out = [def("", "", R, K, Ne, ""); N];
    let (mut k, mut p) = (0, 0);
    while p < parts.len() {
        let mut i = 0;
        while i < parts[p].len() {
            out[k] = parts[p][i];
            (k, i) = (k + 1, i + 1);
        }
        p += 1;
    }
    assert!(k == N, "the parts hold N definitions");
    out
}

/// The definition a metric name falls under: the matching template with the most fixed
/// characters (so `rod_cg_velocity_max` is a body's, not a piston's, `{piston}_velocity_max`).
/// A template without placeholders equal to the name has the most (a placeholder takes at least
/// one character): it is looked for first, by plain comparison.
pub fn find(name: &str) -> Option<&'static MetricDef> {
    // As `find_in(METRICS, name)` (tested), with the templates and their first and last
    // fixed texts found once (a report looks up every metric name: issue 37).
    static TEMPLATES: std::sync::OnceLock<Vec<(&'static MetricDef, &'static str, &'static str)>> =
        std::sync::OnceLock::new();
    if let Some(exact) = METRICS.iter().find(|d| d.name == name) {
        return Some(exact);
    }
    let templates = TEMPLATES.get_or_init(|| {
        METRICS
            .iter()
            .filter_map(|d| {
                let open = d.name.find('{')?;
                let close = d.name.rfind('}')?;
                Some((d, &d.name[..open], &d.name[close + 1..]))
            })
            .collect()
    });
    templates
        .iter()
        .filter(|(d, first, last)| {
            name.starts_with(first) && name.ends_with(last) && matches_template(d.name, name)
        })
        .map(|(d, _, _)| *d)
        .max_by_key(|d| fixed_length(d.name))
}

/// The definition of `defs` a metric name falls under, as [`find`] looks for it in the registry.
pub fn find_in<'d>(defs: &'d [MetricDef], name: &str) -> Option<&'d MetricDef> {
    if let Some(exact) = defs.iter().find(|d| d.name == name) {
        return Some(exact);
    }
    defs.iter()
        .filter(|d| matches_template(d.name, name))
        .max_by_key(|d| fixed_length(d.name))
}

/// The characters of a template outside its placeholders.
fn fixed_length(template: &str) -> usize {
    template.split(['{', '}']).step_by(2).map(str::len).sum()
}

/// Whether `name` is `template` with each `{...}` replaced by one or more characters.
fn matches_template(template: &str, name: &str) -> bool {
    // Two byte comparisons first, which reject nearly every template (a report's metric
    // tables look every name up: 20 000 instructions a name before, issue 37): a template
    // without placeholders is the name itself, and the fixed texts before its first and after
    // its last placeholder begin and end the name (the registry's templates alternate `{` and
    // `}`: tested). Bytes, not chars: the braces are ASCII.
    let brace = |b: &u8| *b == b'{' || *b == b'}';
    let bytes = template.as_bytes();
    let Some(close) = bytes.iter().rposition(brace) else {
        return template == name;
    };
    let open = bytes.iter().position(brace).unwrap_or(close);
    if !name.ends_with(&template[close + 1..]) || !name.starts_with(&template[..open]) {
        return false;
    }
    matches_by_walk(template, name)
}

/// [`matches_template`] without its early rejection: the walk over the template's fixed
/// parts, each placeholder one or more characters.
fn matches_by_walk(template: &str, name: &str) -> bool {
    let mut fixed = template.split(['{', '}']).step_by(2);
    let first = fixed.next().unwrap_or("");
    let Some(mut rest) = name.strip_prefix(first) else {
        return false;
    };
    let mut parts = fixed.peekable();
    if parts.peek().is_none() {
        return rest.is_empty();
    }
    while let Some(part) = parts.next() {
        if parts.peek().is_none() {
            // The last fixed part ends the name, after at least one character.
            return rest.len() > part.len() && rest.ends_with(part);
        }
        // A placeholder of at least one character, then this part.
        match rest.get(1..).and_then(|r| r.find(part)) {
            Some(k) => rest = &rest[k + 1 + part.len()..],
            None => return false,
        }
    }
    false
}

/// The registry as a Markdown table (the metric table of docs/results.md).
pub fn markdown_table() -> String {
    let mut t = String::from(
        "| metric | unit | of | group | better | meaning |\n|---|---|---|---|---|---|\n",
    );
    for d in METRICS {
        t.push_str(&format!(
            "| `{}` | {} | {} | {} | {} | {} |\n",
            d.name,
            d.unit,
            d.aggregation.name(),
            d.group.name(),
            d.better.name(),
            d.meaning
        ));
    }
    t
}

/// One named scalar result, in SI units.
#[derive(Debug, Clone, PartialEq)]
pub struct Metric {
    pub name: String,
    pub unit: &'static str,
    pub value: f64,
}

/// The summary of a run: metrics in a fixed order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Summary {
    pub metrics: Vec<Metric>,
}

impl Summary {
    pub fn get(&self, name: &str) -> Option<f64> {
        self.metrics
            .iter()
            .find(|m| m.name == name)
            .map(|m| m.value)
    }

    /// Adds a metric; its unit is the registry's (a name the registry lacks is a programming
    /// error, caught by the tests of every shipped case).
    pub fn push(&mut self, name: impl Into<String>, value: f64) {
        let name = name.into();
        let unit = find(&name).map_or("?", |d| d.unit);
        debug_assert!(unit != "?", "metric {name} is not in the registry");
        self.metrics.push(Metric { name, unit, value });
    }

    /// Adds a metric named from the registry's `template` (its unit found by the template's
    /// exact name, without matching the filled name against every template).
    pub fn push_as(&mut self, template: &'static str, name: String, value: f64) {
        let unit = METRICS
            .iter()
            .find(|d| d.name == template)
            .map_or("?", |d| d.unit);
        debug_assert!(
            find(&name).map(|d| d.name) == Some(template),
            "metric {name} is not the registry's {template}"
        );
        self.metrics.push(Metric { name, unit, value });
    }
}

#[cfg(test)]
mod tests;
