//! The cycle summary, accumulated step by step in O(1) memory: peaks, works, mean torques and
//! powers, the energy check. Metric names and units come from [`crate::metrics`].

use crate::energy::kinetic_energy;
use crate::metrics;
use crate::stepper::{Sink, StepBlock};
use cardan_mechanism::vectorised;
use cardan_mechanism::{JointKind, JointMotion, LoadsBlock, Mechanism, State, Topology, C, LANES};
use std::ops::Range;

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
        let unit = metrics::find(&name).map_or("?", |d| d.unit);
        debug_assert!(unit != "?", "metric {name} is not in the registry");
        self.metrics.push(Metric { name, unit, value });
    }

    /// Adds a metric named from the registry's `template` (its unit found by the template's
    /// exact name, without matching the filled name against every template).
    fn push_as(&mut self, template: &'static str, name: String, value: f64) {
        let unit = metrics::METRICS
            .iter()
            .find(|d| d.name == template)
            .map_or("?", |d| d.unit);
        debug_assert!(
            metrics::find(&name).map(|d| d.name) == Some(template),
            "metric {name} is not the registry's {template}"
        );
        self.metrics.push(Metric { name, unit, value });
    }
}

/// Largest energy-check error a run may have, relative to the energy the drive moves
/// (∫|T| dθ): the trapezoidal work of a smooth torque on a grid fine enough to describe it is
/// far closer than this (1e-9 on the shipped cases); a coarser grid fails the case.
pub const ENERGY_TOLERANCE: f64 = 1e-3;

/// The most steps in a chunk of [`summary_chunk`].
pub const MAX_CHUNK: usize = 4096;

/// Steps whose integral terms a summary adds up apart before adding their sum to the run's,
/// in a run of `points` states: the pieces a run is shared in among threads
/// ([`crate::run_parallel`]), each piece whole chunks, whose sums are added in the chunks'
/// order. Within a chunk the order of the terms is a function of their steps' indices alone
/// (four running sums by index mod 4), so a summary is the same bit for bit however the run
/// is shared (tested). A function of the run's length alone, not of the threads, so that a
/// run on one thread and a shared one agree: an even number of near-equal chunks, so that two
/// cores share a run evenly, of whole grid blocks ([`cardan_mechanism::REANCHOR`], where a
/// grid can be split), none longer than [`MAX_CHUNK`] (bounding what a piece holds).
pub fn summary_chunk(points: usize) -> usize {
    const BLOCK: usize = cardan_mechanism::REANCHOR;
    let blocks = points.saturating_sub(1).div_ceil(BLOCK).max(1);
    let chunks = blocks.div_ceil(MAX_CHUNK / BLOCK).next_multiple_of(2);
    blocks.div_ceil(chunks) * BLOCK
}

/// Running sums an integral's terms are shared among, by their step's index modulo `SLOTS`.
const SLOTS: usize = 4;

/// A trapezoidal integral summed chunk by chunk ([`summary_chunk`]). Within a chunk, the term
/// of the interval ending at step k goes to running sum k mod [`SLOTS`], each sum taking its
/// terms in the steps' order; a chunk's value is the sums added pairwise. The order is a
/// function of the steps' indices alone, so a run gives the same bits however it is cut into
/// blocks and pieces; the sums are independent, so four terms are added at once (one add's
/// latency per four steps, not per step; the error bound is that of sequential summation of
/// a quarter as many terms).
#[derive(Debug, Clone, Copy, Default)]
struct Integral {
    /// The sum of the chunks closed so far, and the running sums of the chunk under way.
    closed: f64,
    open: [f64; SLOTS],
}

impl Integral {
    /// Adds `term`, the trapezoid of the interval ending at step `step`.
    fn add(&mut self, step: usize, term: f64) {
        self.open[step % SLOTS] += term;
    }

    /// The running sums added pairwise.
    fn chunk(&self) -> f64 {
        let [a, b, c, d] = self.open;
        (a + b) + (c + d)
    }

    fn close_chunk(&mut self) {
        self.closed += self.chunk();
        self.open = [0.0; SLOTS];
    }

    fn value(&self) -> f64 {
        self.closed + self.chunk()
    }

    /// Continues with the chunks of `later`, a summary of the steps after these (its first
    /// step closed this one's last chunk).
    fn merge(&mut self, later: &Integral) {
        self.closed += later.closed;
        self.open = later.open;
    }
}

/// Adds to `integral` the trapezoids of the intervals ending at the lanes `lanes` of a block
/// whose lane 0 is step `first`:
/// `term(i)` that of lane i ≥ 1 (from lane i − 1), `first_term` that of lane 0 (from the step
/// before the block; `None` at the first step a summary takes, which ends no interval of its
/// own). Up to a step whose index is a multiple of [`SLOTS`] a term at a time, then [`SLOTS`]
/// at once, each to its own sum, kept in one vector register; a whole block starting on such a
/// step (a run's blocks do) takes lane 0's term with lanes 1 to 3 (the term a summary's first
/// step lacks counted as +0, which leaves the fresh sums' bits as they are).
#[inline(always)]
fn add_trapezoids(
    integral: &mut Integral,
    first: usize,
    lanes: Range<usize>,
    first_term: impl FnOnce() -> Option<f64>,
    term: impl Fn(usize) -> f64,
) {
    let end = lanes.end.min(LANES);
    let mut open = integral.open;
    let mut i = lanes.start;
    if i == 0 && first % SLOTS == 0 && end >= SLOTS {
        let head = [first_term().unwrap_or(0.0), term(1), term(2), term(3)];
        for (o, t) in open.iter_mut().zip(head) {
            *o += t;
        }
        i = SLOTS;
    } else if i == 0 && i < end {
        if let Some(t) = first_term() {
            open[first % SLOTS] += t;
        }
        i = 1;
    }
    while i < end && (first + i) % SLOTS != 0 {
        open[(first + i) % SLOTS] += term(i);
        i += 1;
    }
    while i + SLOTS <= end {
        for (k, o) in open.iter_mut().enumerate() {
            *o += term(i + k);
        }
        i += SLOTS;
    }
    for i in i..end {
        open[(first + i) % SLOTS] += term(i);
    }
    integral.open = open;
}

/// Raises `peak` to `value`. The stepper has checked every value is finite, so a plain
/// comparison serves (cheaper than `f64::max`, which must handle NaN); written as a select, not
/// a branch, so that it compiles to one `maxsd` instead of a jump the processor mispredicts
/// whenever a peak rises (the same result for every pair of numbers).
#[inline(always)]
fn raise(peak: &mut f64, value: f64) {
    *peak = if value > *peak { value } else { *peak };
}

/// Raises `peak` to the largest of `value(i)` over the lanes `lanes`: eight running maxima
/// side by side (independent, so that the compiler keeps them in vector registers), then the
/// largest of them (the same result as raising one at a time: a maximum does not depend on
/// the order).
#[inline(always)]
fn raise_over(peak: &mut f64, lanes: Range<usize>, value: impl Fn(usize) -> f64) {
    // Lanes of a block: bounded so, the compiler drops the columns' bounds checks.
    let end = lanes.end.min(LANES);
    let mut m = [*peak; 8];
    let mut i = lanes.start;
    while i + 8 <= end {
        for (k, m) in m.iter_mut().enumerate() {
            raise(m, value(i + k));
        }
        i += 8;
    }
    for i in i..end {
        raise(&mut m[0], value(i));
    }
    for v in m {
        raise(peak, v);
    }
}

/// The component of a mesh force along the pitch-circle tangent t = i·d (d: from the pitch
/// point towards the centre of the mesh's first gear): the tooth load that transmits torque
/// (Karhula A8.1.10).
pub fn tangential(force: C, mesh: &JointMotion) -> f64 {
    let t = C::i() * mesh.direction;
    force.re * t.re + force.im * t.im
}

/// The component of a mesh force along d, towards the centre of the mesh's first gear.
pub fn radial(force: C, mesh: &JointMotion) -> f64 {
    force.re * mesh.direction.re + force.im * mesh.direction.im
}

/// Peaks, work and crank-angle-averaged power of one family's loads.
#[derive(Debug, Clone)]
struct FamilyTotals {
    name: &'static str,
    /// Squared peak force of each joint, peak couple of each joint (of the slides only: the
    /// only joints with a couple; 0 for the others).
    force: Vec<f64>,
    moment: Vec<f64>,
    /// Peak |tangential force| of each gear mesh (0 for other joints), N.
    tangential: Vec<f64>,
    torque: f64,
    work: Integral,
    abs_work: Integral,
    energy_flow: Integral,
}

impl FamilyTotals {
    fn new(name: &'static str, joints: usize) -> Self {
        Self {
            name,
            force: vec![0.0; joints],
            moment: vec![0.0; joints],
            tangential: vec![0.0; joints],
            torque: 0.0,
            work: Integral::default(),
            abs_work: Integral::default(),
            energy_flow: Integral::default(),
        }
    }

    fn close_chunk(&mut self) {
        self.work.close_chunk();
        self.abs_work.close_chunk();
        self.energy_flow.close_chunk();
    }

    fn merge(&mut self, later: &FamilyTotals) {
        for (a, b) in self.force.iter_mut().zip(&later.force) {
            raise(a, *b);
        }
        for (a, b) in self.moment.iter_mut().zip(&later.moment) {
            raise(a, *b);
        }
        for (a, b) in self.tangential.iter_mut().zip(&later.tangential) {
            raise(a, *b);
        }
        raise(&mut self.torque, later.torque);
        self.work.merge(&later.work);
        self.abs_work.merge(&later.abs_work);
        self.energy_flow.merge(&later.energy_flow);
    }

    /// Takes the lanes `lanes` of `block` (`loads`: this family's loads there; `previous` the
    /// angle and speed of the step before them, `torque` its torque, then the last step's).
    #[inline(always)]
    fn take(
        &mut self,
        block: &StepBlock,
        loads: &LoadsBlock,
        lanes: Range<usize>,
        joints: &Joints,
        previous: Option<(f64, f64)>,
        torque: &mut f64,
    ) {
        for (f, l) in self.force.iter_mut().zip(&loads.joints) {
            raise_over(f, lanes.clone(), |i| l.fx[i] * l.fx[i] + l.fy[i] * l.fy[i]);
        }
        for &j in &joints.slides {
            let l = &loads.joints[j];
            raise_over(&mut self.moment[j], lanes.clone(), |i| l.moment[i].abs());
        }
        for &j in &joints.meshes {
            let (l, m) = (&loads.joints[j], &block.state.joints[j]);
            raise_over(&mut self.tangential[j], lanes.clone(), |i| {
                let mesh = JointMotion {
                    direction: C::new(m.direction_x[i], m.direction_y[i]),
                    ..JointMotion::default()
                };
                tangential(C::new(l.fx[i], l.fy[i]), &mesh).abs()
            });
        }
        let t = &loads.crank_torque;
        raise_over(&mut self.torque, lanes.clone(), |i| t[i].abs());
        // (A5.2.1.37) W = ∫ T dθ and the crank-angle integral of the power T·ω, by the
        // trapezoidal rule on the crank-angle grid.
        let (c, t0) = (&block.state.crank, *torque);
        let (a, w) = (&c.angle, &c.speed);
        let before = |f: fn(f64, f64, f64, f64) -> f64| {
            move || previous.map(|(a0, w0)| 0.5 * (a[0] - a0) * f(t[0], t0, w[0], w0))
        };
        add_trapezoids(
            &mut self.work,
            block.first,
            lanes.clone(),
            before(|t, t0, _, _| t + t0),
            |i| 0.5 * (a[i] - a[i - 1]) * (t[i] + t[i - 1]),
        );
        add_trapezoids(
            &mut self.abs_work,
            block.first,
            lanes.clone(),
            before(|t, t0, _, _| t.abs() + t0.abs()),
            |i| 0.5 * (a[i] - a[i - 1]) * (t[i].abs() + t[i - 1].abs()),
        );
        add_trapezoids(
            &mut self.energy_flow,
            block.first,
            lanes.clone(),
            before(|t, t0, w, w0| t * w + t0 * w0),
            |i| 0.5 * (a[i] - a[i - 1]) * (t[i] * w[i] + t[i - 1] * w[i - 1]),
        );
        if let Some(last) = lanes.end.checked_sub(1) {
            *torque = t[last.min(LANES - 1)];
        }
    }
}

/// The joints whose couples and tangential forces a summary reports, by index.
#[derive(Debug, Clone)]
struct Joints {
    /// The slides (the joints that carry a couple).
    slides: Vec<usize>,
    /// The gear meshes.
    meshes: Vec<usize>,
}

/// The works of the loss components and the peak friction torque.
#[derive(Debug, Clone)]
struct LossTotals {
    names: Vec<String>,
    /// ∫ P dt of each component, J (Karhula A9.1.68-71), by the trapezoidal rule in time.
    work: Vec<Integral>,
    previous: Vec<f64>,
    friction_torque: f64,
}

/// The gear meshes' rating over the run: peaks of the loads and stresses, the smallest safety
/// factors, the mesh loss work.
#[derive(Debug, Clone)]
struct GearTotals {
    contact_ratio: f64,
    bending: bool,
    tooth_load: f64,
    dynamic_load: f64,
    contact_stress: f64,
    contact_safety: f64,
    bending_stress: f64,
    bending_safety: f64,
    loss_work: Integral,
    previous_loss: f64,
}

/// A sink that accumulates the summary of one mechanism's run.
#[derive(Debug, Clone)]
pub struct SummarySink {
    topology: Topology,
    joints: Joints,
    /// Squared peaks: each piston's velocity and acceleration.
    pistons: Vec<[f64; 2]>,
    /// Squared peaks: each body's cg velocity and acceleration, angular velocity and acceleration.
    bodies: Vec<[f64; 4]>,
    /// Each family, then the total if there is more than one family.
    families: Vec<FamilyTotals>,
    /// Previous step's angle and speed (`None` before the first), and each family's torque
    /// (then the total's).
    previous: Option<(f64, f64)>,
    previous_torques: Vec<f64>,
    first: Option<(f64, f64, f64)>,
    last: (f64, f64, f64),
    /// Index of the run's last step (where the kinetic energy is taken again).
    last_step: usize,
    /// Steps of the chunks of its integrals ([`summary_chunk`]).
    chunk: usize,
    gas_force: f64,
    pressure: Option<f64>,
    /// Largest |dx/dθ| of the first piston, m/rad, and ∫|dx/dθ| dθ, m.
    lever: f64,
    lever_integral: Integral,
    previous_lever: f64,
    /// Time of the previous step, s.
    previous_time: f64,
    /// A lane of a block as a state (where the kinetic energy is taken).
    scratch: State,
    losses: Option<LossTotals>,
    gears: Option<GearTotals>,
    /// Whether [`SummarySink::finish`] enforces the energy balance (all but a run kept for its
    /// peaks alone).
    energy_check: bool,
}

impl SummarySink {
    /// A summary of `mechanism` under the load families named `families` (in the run's order),
    /// over a run of `points` steps (numbered from 0: the motion's first index plus its
    /// length), which set its chunks ([`summary_chunk`]) as [`crate::run_parallel`] sets its
    /// pieces.
    pub fn new(mechanism: &dyn Mechanism, families: &[&'static str], points: usize) -> Self {
        let topology = mechanism.topology().clone();
        let joints = topology.joints.len();
        let mut totals: Vec<FamilyTotals> = families
            .iter()
            .map(|&f| FamilyTotals::new(f, joints))
            .collect();
        if families.len() > 1 {
            totals.push(FamilyTotals::new("total", joints));
        }
        let of_kind = |kind: fn(&JointKind) -> bool| {
            let joints = topology.joints.iter().enumerate();
            joints
                .filter(|(_, j)| kind(&j.kind))
                .map(|(k, _)| k)
                .collect()
        };
        let joints = Joints {
            slides: of_kind(|k| matches!(k, JointKind::Prismatic)),
            meshes: of_kind(|k| matches!(k, JointKind::GearMesh { .. })),
        };
        Self {
            joints,
            pistons: vec![[0.0; 2]; topology.pistons.len()],
            bodies: vec![[0.0; 4]; topology.bodies.len()],
            topology,
            previous_torques: vec![0.0; totals.len()],
            families: totals,
            previous: None,
            first: None,
            last: (0.0, 0.0, 0.0),
            last_step: points.saturating_sub(1),
            chunk: summary_chunk(points),
            gas_force: 0.0,
            pressure: None,
            lever: 0.0,
            lever_integral: Integral::default(),
            previous_lever: 0.0,
            previous_time: 0.0,
            scratch: State::for_topology(mechanism.topology()),
            losses: None,
            gears: None,
            energy_check: true,
        }
    }

    /// The same summary, without enforcing the energy balance at its end: for a run kept for
    /// its peaks alone (the runner's sampling check, whose shifted grids do not span whole
    /// cycles and may be too coarse for the quadrature of the works).
    pub fn for_peaks(mut self) -> Self {
        self.energy_check = false;
        self
    }

    /// The same summary, with the gear meshes of `ratings` rated (their smallest contact ratio
    /// is reported, and the bending rating if every mesh has one).
    pub fn with_gears(mut self, ratings: &crate::GearRatings) -> Self {
        self.gears = Some(GearTotals {
            contact_ratio: ratings
                .contact_ratios()
                .into_iter()
                .fold(f64::INFINITY, f64::min),
            bending: ratings.bending().iter().all(|b| *b),
            tooth_load: 0.0,
            dynamic_load: 0.0,
            contact_stress: 0.0,
            contact_safety: f64::INFINITY,
            bending_stress: 0.0,
            bending_safety: f64::INFINITY,
            loss_work: Integral::default(),
            previous_loss: 0.0,
        });
        self
    }

    /// The gear metrics (issue 10): peaks over the run and the meshes, smallest safety factors
    /// (infinite only if no mesh ever carried a load), mean mesh loss.
    fn push_gears(&self, m: &mut Summary, time: f64) {
        let Some(g) = &self.gears else { return };
        m.push("contact_ratio", g.contact_ratio);
        m.push("mesh_tangential_load_max", g.tooth_load);
        m.push("dynamic_tooth_load_max", g.dynamic_load);
        m.push("contact_stress_max", g.contact_stress);
        // A mesh that never carried a load has no finite safety factor: none is reported.
        if g.contact_safety.is_finite() {
            m.push("contact_safety_factor", g.contact_safety);
        }
        if g.bending {
            m.push("bending_stress_max", g.bending_stress);
            if g.bending_safety.is_finite() {
                m.push("bending_safety_factor", g.bending_safety);
            }
        }
        m.push("gear_mesh_power_loss_mean", g.loss_work.value() / time);
    }

    /// The same summary, with the loss components named `names` (a [`crate::LossBudget`]'s).
    pub fn with_losses(mut self, names: &[String]) -> Self {
        self.losses = Some(LossTotals {
            names: names.to_vec(),
            work: vec![Integral::default(); names.len()],
            previous: vec![0.0; names.len()],
            friction_torque: 0.0,
        });
        self
    }

    /// The loss metrics (Karhula A9.1.56-75): mean power loss in all and per component, the
    /// work lost, the peak friction torque, and, with a gas model, the efficiency and the
    /// torque and power the machine needs (a pump: net work into the crank) or gives (an
    /// engine: net work out).
    fn push_losses(&self, m: &mut Summary, span: f64, time: f64) {
        let Some(l) = &self.losses else { return };
        let lost: f64 = l.work.iter().map(Integral::value).sum();
        m.push("loss_work", lost);
        m.push("power_loss_mean", lost / time);
        for (name, work) in l.names.iter().zip(&l.work) {
            m.push_as(
                "power_loss_mean_{component}",
                format!("power_loss_mean_{name}"),
                work.value() / time,
            );
        }
        m.push("friction_torque_max", l.friction_torque);
        let work = |name: &str| {
            self.families
                .iter()
                .find(|f| f.name == name)
                .map(|f| f.work.value())
        };
        let (Some(gas), Some(total)) = (work("gas"), work("total")) else {
            return;
        };
        if total > 0.0 {
            // (A9.1.60-61, 64-65, 72-73)
            let need = total + lost;
            m.push("torque_need_mean", need / span);
            m.push("power_need_mean", need / time);
            m.push("mechanical_efficiency", gas / need);
        } else if total < 0.0 {
            // (A9.1.62-63, 66-67, 74-75)
            let out = -total - lost;
            m.push("output_torque_mean", out / span);
            m.push("output_power_mean", out / time);
            m.push("mechanical_efficiency", out / -total);
        }
    }

    /// Closes the chunk of every integral (at each step whose index is a multiple of
    /// its chunk, after its interval was added).
    fn close_chunk(&mut self) {
        for f in &mut self.families {
            f.close_chunk();
        }
        self.lever_integral.close_chunk();
        if let Some(l) = &mut self.losses {
            l.work.iter_mut().for_each(Integral::close_chunk);
        }
        if let Some(g) = &mut self.gears {
            g.loss_work.close_chunk();
        }
    }

    /// Continues this summary with `later`, the summary of the steps from the last one this
    /// summary took (a chunk boundary: its index a multiple of its chunk) on, made
    /// from a copy of the same fresh summary: the summary of all the steps, the same bit for
    /// bit as if one summary had taken them all (peaks are maxima; the integrals add the same
    /// chunk sums in the same order).
    pub fn merge(&mut self, later: &SummarySink) {
        for (a, b) in self.pistons.iter_mut().zip(&later.pistons) {
            for (a, b) in a.iter_mut().zip(b) {
                raise(a, *b);
            }
        }
        for (a, b) in self.bodies.iter_mut().zip(&later.bodies) {
            for (a, b) in a.iter_mut().zip(b) {
                raise(a, *b);
            }
        }
        for (a, b) in self.families.iter_mut().zip(&later.families) {
            a.merge(b);
        }
        raise(&mut self.lever, later.lever);
        self.lever_integral.merge(&later.lever_integral);
        if let (Some(a), Some(b)) = (&mut self.losses, &later.losses) {
            for (x, y) in a.work.iter_mut().zip(&b.work) {
                x.merge(y);
            }
            raise(&mut a.friction_torque, b.friction_torque);
            a.previous.clone_from(&b.previous);
        }
        if let (Some(a), Some(b)) = (&mut self.gears, &later.gears) {
            raise(&mut a.tooth_load, b.tooth_load);
            raise(&mut a.dynamic_load, b.dynamic_load);
            raise(&mut a.contact_stress, b.contact_stress);
            a.contact_safety = a.contact_safety.min(b.contact_safety);
            raise(&mut a.bending_stress, b.bending_stress);
            a.bending_safety = a.bending_safety.min(b.bending_safety);
            a.loss_work.merge(&b.loss_work);
            a.previous_loss = b.previous_loss;
        }
        if later.first.is_some() {
            self.first = self.first.or(later.first);
            self.last = later.last;
            self.previous = later.previous;
            self.previous_torques.clone_from(&later.previous_torques);
            self.previous_lever = later.previous_lever;
            self.previous_time = later.previous_time;
        }
        self.pressure = match (self.pressure, later.pressure) {
            (Some(a), Some(b)) => Some(a.max(b)),
            (a, b) => a.or(b),
        };
        raise(&mut self.gas_force, later.gas_force);
    }

    /// The summary, or why the run cannot be trusted (the energy check).
    pub fn finish(&self, mechanism: &dyn Mechanism) -> Result<Summary, String> {
        let mut m = Summary::default();
        let (Some(first), last) = (self.first, self.last) else {
            return Err("the run has no steps".into());
        };
        let t = &self.topology;
        m.push("piston_stroke", mechanism.stroke());
        for (p, peaks) in t.pistons.iter().zip(&self.pistons) {
            m.push_as(
                "{piston}_velocity_max",
                format!("{}_velocity_max", p.name),
                peaks[0].sqrt(),
            );
            m.push_as(
                "{piston}_acceleration_max",
                format!("{}_acceleration_max", p.name),
                peaks[1].sqrt(),
            );
        }
        for (b, peaks) in t.bodies.iter().zip(&self.bodies) {
            m.push_as(
                "{body}_cg_velocity_max",
                format!("{}_cg_velocity_max", b.name),
                peaks[0].sqrt(),
            );
            m.push_as(
                "{body}_cg_acceleration_max",
                format!("{}_cg_acceleration_max", b.name),
                peaks[1].sqrt(),
            );
            m.push_as(
                "{body}_angular_velocity_max",
                format!("{}_angular_velocity_max", b.name),
                peaks[2].sqrt(),
            );
            m.push_as(
                "{body}_angular_acceleration_max",
                format!("{}_angular_acceleration_max", b.name),
                peaks[3].sqrt(),
            );
        }
        let span = last.0 - first.0;
        for f in &self.families {
            for (j, (force, moment)) in t.joints.iter().zip(f.force.iter().zip(&f.moment)) {
                m.push_as(
                    "{family}_{joint}_force_max",
                    format!("{}_{}_force_max", f.name, j.name),
                    force.sqrt(),
                );
                if matches!(j.kind, JointKind::Prismatic) {
                    m.push_as(
                        "{family}_{joint}_moment_max",
                        format!("{}_{}_moment_max", f.name, j.name),
                        *moment,
                    );
                }
            }
            for &k in &self.joints.meshes {
                let name = t.joints[k].name;
                m.push_as(
                    "{family}_{joint}_tangential_max",
                    format!("{}_{name}_tangential_max", f.name),
                    f.tangential[k],
                );
            }
            m.push_as(
                "{family}_torque_max",
                format!("{}_torque_max", f.name),
                f.torque,
            );
            let work = f.work.value();
            m.push_as("{family}_work", format!("{}_work", f.name), work);
            m.push_as(
                "{family}_torque_mean",
                format!("{}_torque_mean", f.name),
                work / span,
            ); // (A5.2.1.38)
               // (A5.2.1.39) averaged over the crank angle, as the thesis's tables are; at
               // constant speed this is the time average.
            m.push_as(
                "{family}_power_mean",
                format!("{}_power_mean", f.name),
                f.energy_flow.value() / span,
            );
        }
        // Power balance: the drive torque per unit force on the piston is dx/dθ. Vidinsky's
        // (2021) mechanical advantage refers it to the crank radius (F_out = T/p, eq 21 and
        // L225); per unit stroke it compares mechanisms of equal displacement fairly.
        let radius = mechanism.crank_radius();
        m.push("mechanical_advantage_max", self.lever / radius);
        m.push(
            "mechanical_advantage_mean",
            self.lever_integral.value() / span / radius,
        );
        m.push(
            "torque_per_force_stroke_max",
            self.lever / mechanism.stroke(),
        );
        let change = last.2 - first.2;
        m.push("kinetic_energy_change", change);
        if let Some(inertial) = self.families.iter().find(|f| f.name == "inertial") {
            let (work, abs_work) = (inertial.work.value(), inertial.abs_work.value());
            let error = (work - change).abs();
            let relative = if error == 0.0 { 0.0 } else { error / abs_work };
            m.push("energy_balance_error", relative);
            if relative > ENERGY_TOLERANCE && self.energy_check {
                return Err(format!(
                    "the energy check fails: inertial work {} J against a kinetic energy change of {} J, \
                     {relative:.2e} of the {} J the drive moves (tolerance {ENERGY_TOLERANCE:e}): \
                     the crank-angle grid is too coarse for this motion; raise motion.steps",
                    work, change, abs_work
                ));
            }
        }
        m.push("cycle_time", last.1 - first.1);
        self.push_losses(&mut m, span, last.1 - first.1);
        self.push_gears(&mut m, last.1 - first.1);
        if let Some(p) = self.pressure {
            m.push("cylinder_pressure_max", p);
            m.push("gas_force_max", self.gas_force);
        }
        Ok(m)
    }
}

impl Sink for SummarySink {
    /// The lanes up to each one that closes a chunk (its step's index a multiple of its chunk)
    /// taken together, then the chunk closed.
    fn push_block(&mut self, block: &StepBlock) -> Result<(), (usize, String)> {
        let (n, mut lo) = (block.len(), 0);
        while lo < n {
            // The lane of the next step whose index is a multiple of the chunk.
            let closing = (block.first + lo).next_multiple_of(self.chunk) - block.first;
            let hi = (closing + 1).min(n);
            take_lanes(self, block, lo..hi);
            if closing < n {
                self.close_chunk();
            }
            lo = hi;
        }
        Ok(())
    }

    fn wants_steps(&self) -> bool {
        false
    }
}

vectorised! {
    /// Takes the lanes `lanes` of `block` (in order, none of them but the last closing a
    /// chunk): each peak raised over all of them before it is stored back, each integral's
    /// terms added in the steps' order.
    fn take_lanes(summary: &mut SummarySink, block: &StepBlock, lanes: Range<usize>) {
        let Some(last) = lanes.end.checked_sub(1) else {
            return;
        };
        let st = block.state;
        for (peaks, p) in summary.pistons.iter_mut().zip(&st.pistons) {
            let [v, a] = peaks;
            raise_over(v, lanes.clone(), |i| p.velocity[i] * p.velocity[i]);
            raise_over(a, lanes.clone(), |i| p.acceleration[i] * p.acceleration[i]);
        }
        for (peaks, b) in summary.bodies.iter_mut().zip(&st.bodies) {
            let [v, a, w, e] = peaks;
            let p = &b.cg;
            raise_over(v, lanes.clone(), |i| p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]);
            raise_over(a, lanes.clone(), |i| p.ax[i] * p.ax[i] + p.ay[i] * p.ay[i]);
            let (w0, e0) = (&b.angular_velocity, &b.angular_acceleration);
            raise_over(w, lanes.clone(), |i| w0[i] * w0[i]);
            raise_over(e, lanes.clone(), |i| e0[i] * e0[i]);
        }
        for (k, (f, t0)) in summary
            .families
            .iter_mut()
            .zip(&mut summary.previous_torques)
            .enumerate()
        {
            // The loads of family k (the total after the families).
            let loads = block.families.get(k).unwrap_or(block.total);
            f.take(block, loads, lanes.clone(), &summary.joints, summary.previous, t0);
        }
        let c = &st.crank;
        if let Some(p) = st.pistons.first() {
            let (a, x) = (&c.angle, &p.dx_dtheta);
            raise_over(&mut summary.lever, lanes.clone(), |i| x[i].abs());
            let l0 = summary.previous_lever;
            add_trapezoids(
                &mut summary.lever_integral,
                block.first,
                lanes.clone(),
                || summary.previous.map(|(a0, _)| 0.5 * (a[0] - a0) * (x[0].abs() + l0)),
                |i| 0.5 * (a[i] - a[i - 1]) * (x[i].abs() + x[i - 1].abs()),
            );
            summary.previous_lever = x[last].abs();
        }
        let steps = block.steps.get(lanes.clone()).unwrap_or_default();
        let indices = block.first + lanes.start..;
        if let Some(l) = &mut summary.losses {
            let (mut started, mut t0) = (summary.previous.is_some(), summary.previous_time);
            for (k, s) in indices.clone().zip(steps) {
                let dt = s.state.crank.time - t0;
                for ((w, p0), &p) in l.work.iter_mut().zip(&mut l.previous).zip(s.losses) {
                    if started {
                        w.add(k, 0.5 * dt * (p + *p0));
                    }
                    *p0 = p;
                }
                raise(&mut l.friction_torque, s.friction_torque);
                (started, t0) = (true, s.state.crank.time);
            }
        }
        if let Some(g) = &mut summary.gears {
            let (mut started, mut t0) = (summary.previous.is_some(), summary.previous_time);
            for (k, s) in indices.zip(steps) {
                let loss: f64 = s.gears.iter().map(|r| r.loss).sum();
                if started {
                    let dt = s.state.crank.time - t0;
                    g.loss_work.add(k, 0.5 * dt * (loss + g.previous_loss));
                }
                g.previous_loss = loss;
                for r in s.gears {
                    raise(&mut g.tooth_load, r.tooth_load);
                    raise(&mut g.dynamic_load, r.dynamic_load);
                    raise(&mut g.contact_stress, r.contact_stress);
                    g.contact_safety = g.contact_safety.min(r.contact_safety);
                    if g.bending {
                        raise(&mut g.bending_stress, r.bending_stress);
                        g.bending_safety = g.bending_safety.min(r.bending_safety);
                    }
                }
                (started, t0) = (true, s.state.crank.time);
            }
        }
        // The kinetic energy is wanted at the first and last steps only.
        for i in [lanes.start, last] {
            if summary.first.is_none() || block.first + i == summary.last_step {
                block.state.gather(i, &mut summary.scratch);
                let now = (
                    c.angle[i],
                    c.time[i],
                    kinetic_energy(&summary.topology, &summary.scratch),
                );
                summary.first.get_or_insert(now);
                summary.last = now;
            }
        }
        if let (Some(p), Some(f)) = (block.pressure, block.piston_force) {
            // The block's largest pressure first, then the run's (the same maximum).
            let mut highest = p[lanes.start.min(LANES - 1)];
            raise_over(&mut highest, lanes.clone(), |i| p[i]);
            summary.pressure = Some(summary.pressure.map_or(highest, |q| q.max(highest)));
            if !st.pistons.is_empty() {
                raise_over(&mut summary.gas_force, lanes, |i| f[i].abs());
            }
        }
        summary.previous_time = c.time[last];
        summary.previous = Some((c.angle[last], c.speed[last]));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cardan_mechanism::REANCHOR;

    /// An integral's sums depend on the steps' indices alone: a block taken whole (the fast
    /// path), in the pieces a chunk's close cuts it into, or a lane at a time, and blocks that
    /// start off the slots, give the same bits; the value is the sum of the terms to within
    /// the round-off of summing 64 terms (64·ε of Σ|term|), and exact for terms summed
    /// exactly (small integers).
    #[test]
    fn an_integral_is_the_same_however_its_lanes_are_taken() {
        // Terms of varied sign and size, each from its lane and the one before.
        let column: Vec<f64> = (0..LANES + 1)
            .map(|k| ((k as f64) * 0.7).sin() * 10f64.powi(k as i32 % 5 - 2))
            .collect();
        let term = |i: usize| 0.5 * (column[i] + column[i - 1]);
        for first in [0, 64, 128 + 3, 7] {
            let lane0 = || Some(0.25 * column[LANES]);
            let whole = {
                let mut g = Integral::default();
                add_trapezoids(&mut g, first, 0..LANES, lane0, term);
                g
            };
            let cuts = [
                vec![0, 1, LANES],
                vec![0, 5, 6, 33, LANES],
                (0..=LANES).collect(),
            ];
            for cut in cuts {
                let mut g = Integral::default();
                for w in cut.windows(2) {
                    add_trapezoids(&mut g, first, w[0]..w[1], lane0, term);
                }
                assert_eq!(g.open.map(f64::to_bits), whole.open.map(f64::to_bits));
            }
            let terms: Vec<f64> = std::iter::once(0.25 * column[LANES])
                .chain((1..LANES).map(term))
                .collect();
            let exact: f64 = terms.iter().sum();
            let scale: f64 = terms.iter().map(|t| t.abs()).sum();
            assert!((whole.value() - exact).abs() <= 64.0 * f64::EPSILON * scale);
        }
        // A summary's first step ends no interval: counted as +0, the sums stay fresh.
        let mut g = Integral::default();
        add_trapezoids(&mut g, 0, 0..LANES, || None, |i| i as f64);
        assert_eq!(g.value(), (1..LANES).sum::<usize>() as f64);
        assert!(g.open.iter().all(|o| o.is_sign_positive()));
    }

    /// Chunks are whole grid blocks, at most MAX_CHUNK steps, an even number of them for a
    /// run, differing by less than a block but the last (which takes what is left).
    #[test]
    fn a_run_is_chunked_evenly_in_whole_blocks() {
        for points in (2..40_000).step_by(37).chain([4097, 4098, 7201, 720_001]) {
            let chunk = summary_chunk(points);
            assert_eq!(chunk % REANCHOR, 0, "{points}");
            assert!((REANCHOR..=MAX_CHUNK).contains(&chunk), "{points}: {chunk}");
            let intervals = points - 1;
            let chunks = intervals.div_ceil(chunk);
            let wanted = intervals.div_ceil(REANCHOR).div_ceil(MAX_CHUNK / REANCHOR);
            assert!(
                chunks <= wanted.next_multiple_of(2),
                "{points}: {chunks} chunks"
            );
            if intervals > REANCHOR {
                assert_eq!(chunks % 2, 0, "{points}: {chunks} chunks");
            }
            // The last chunk is short by less than one block per chunk.
            let short = chunks * chunk - intervals;
            assert!(
                short < chunks * REANCHOR,
                "{points}: last chunk short by {short}"
            );
        }
        assert_eq!(summary_chunk(7201), 3648);
    }
}
