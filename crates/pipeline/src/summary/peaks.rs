//! The summary's peaks: of each piston's and body's motion, of each family's joint loads, of
//! the gas. Each is raised over a block's columns (the lanes side by side) and joined with a
//! later piece's by the larger value (a maximum does not depend on the order).

use crate::step::StepBlock;
use cardan_losses::mesh::tangential;
use cardan_mechanism::{JointKind, JointMotion, LoadsBlock, StateBlock, Topology, C, LANES};
use cardan_metrics::Summary;
use std::ops::Range;

/// Raises `peak` to `value`. The stepper has checked every value is finite, so a plain
/// comparison serves (cheaper than `f64::max`, which must handle NaN); written as a select, not
/// a branch, so that it compiles to one `maxsd` instead of a jump the processor mispredicts
/// whenever a peak rises (the same result for every pair of numbers).
#[inline(always)]
pub fn raise(peak: &mut f64, value: f64) {
    *peak = if value > *peak { value } else { *peak };
}

/// Raises `peak` to the largest of `value(i)` over the lanes `lanes`: eight running maxima
/// side by side (independent, so that the compiler keeps them in vector registers), then the
/// largest of them (the same result as raising one at a time: a maximum does not depend on
/// the order).
#[inline(always)]
pub fn raise_over(peak: &mut f64, lanes: Range<usize>, value: impl Fn(usize) -> f64) {
    // A whole block (most blocks): a loop of a known count, which the compiler unrolls. The
    // maxima begin at the first eight values (the peak, compared last, still wins a tie).
    if lanes.start == 0 && lanes.end >= LANES {
        let mut m: [f64; 8] = std::array::from_fn(&value);
        for chunk in 1..LANES / 8 {
            for (k, m) in m.iter_mut().enumerate() {
                raise(m, value(8 * chunk + k));
            }
        }
        for v in m {
            raise(peak, v);
        }
        return;
    }
    raise_over_lanes(peak, lanes, value);
}

/// [`raise_over`] by a loop over the lanes whose count the compiler does not see: for a value
/// of one column, which it vectorises so and leaves scalar once it unrolls a whole block's
/// loop (measured).
#[inline(always)]
pub fn raise_over_lanes(peak: &mut f64, lanes: Range<usize>, value: impl Fn(usize) -> f64) {
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

/// Raises each of `peaks` to the one of `later` beside it.
fn raise_each(peaks: &mut [f64], later: &[f64]) {
    for (a, b) in peaks.iter_mut().zip(later) {
        raise(a, *b);
    }
}

/// Squared peaks of the motion: each piston's velocity and acceleration, each body's cg velocity
/// and acceleration, angular velocity and acceleration.
#[derive(Debug, Clone)]
pub(crate) struct MotionPeaks {
    pistons: Vec<[f64; 2]>,
    bodies: Vec<[f64; 4]>,
}

impl MotionPeaks {
    pub(crate) fn new(topology: &Topology) -> Self {
        Self {
            pistons: vec![[0.0; 2]; topology.pistons.len()],
            bodies: vec![[0.0; 4]; topology.bodies.len()],
        }
    }

    /// Raised over the lanes `lanes` of `state`.
    #[inline(always)]
    pub(crate) fn push(&mut self, state: &StateBlock, lanes: Range<usize>) {
        for (peaks, p) in self.pistons.iter_mut().zip(&state.pistons) {
            let [v, a] = peaks;
            raise_over_lanes(v, lanes.clone(), |i| p.velocity[i] * p.velocity[i]);
            raise_over_lanes(a, lanes.clone(), |i| p.acceleration[i] * p.acceleration[i]);
        }
        for (peaks, b) in self.bodies.iter_mut().zip(&state.bodies) {
            let [v, a, w, e] = peaks;
            let p = &b.cg;
            raise_over(v, lanes.clone(), |i| p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]);
            raise_over(a, lanes.clone(), |i| p.ax[i] * p.ax[i] + p.ay[i] * p.ay[i]);
            let (w0, e0) = (&b.angular_velocity, &b.angular_acceleration);
            raise_over_lanes(w, lanes.clone(), |i| w0[i] * w0[i]);
            raise_over_lanes(e, lanes.clone(), |i| e0[i] * e0[i]);
        }
    }

    pub(crate) fn merge(&mut self, later: &Self) {
        for (a, b) in self.pistons.iter_mut().zip(&later.pistons) {
            raise_each(a, b);
        }
        for (a, b) in self.bodies.iter_mut().zip(&later.bodies) {
            raise_each(a, b);
        }
    }

    /// The peaks of the pistons (`{piston}_velocity_max`, ...), then of the bodies. (Names are
    /// joined by `concat`, not `format!`: a sweep's point names its metrics anew, and the
    /// formatting machinery cost more than the peaks.)
    pub(crate) fn finish(&self, t: &Topology, m: &mut Summary) {
        for (p, peaks) in t.pistons.iter().zip(&self.pistons) {
            for (k, template) in ["{piston}_velocity_max", "{piston}_acceleration_max"]
                .into_iter()
                .enumerate()
            {
                let name = [p.name, &template["{piston}".len()..]].concat();
                m.push_as(template, name, peaks[k].sqrt());
            }
        }
        for (b, peaks) in t.bodies.iter().zip(&self.bodies) {
            for (k, template) in [
                "{body}_cg_velocity_max",
                "{body}_cg_acceleration_max",
                "{body}_angular_velocity_max",
                "{body}_angular_acceleration_max",
            ]
            .into_iter()
            .enumerate()
            {
                let name = [b.name, &template["{body}".len()..]].concat();
                m.push_as(template, name, peaks[k].sqrt());
            }
        }
    }
}

/// The joints whose couples and tangential forces a summary reports, by index.
#[derive(Debug, Clone)]
pub(crate) struct JointKinds {
    /// The slides (the joints that carry a couple).
    slides: Vec<usize>,
    /// The gear meshes.
    meshes: Vec<usize>,
}

impl JointKinds {
    pub(crate) fn new(topology: &Topology) -> Self {
        let of_kind = |kind: fn(&JointKind) -> bool| {
            let joints = topology.joints.iter().enumerate();
            joints
                .filter(|(_, j)| kind(&j.kind))
                .map(|(k, _)| k)
                .collect()
        };
        Self {
            slides: of_kind(|k| matches!(k, JointKind::Prismatic)),
            meshes: of_kind(|k| matches!(k, JointKind::GearMesh { .. })),
        }
    }
}

/// Peaks of one family's joint loads: each joint's squared force, each slide's couple (0 for
/// the other joints), each gear mesh's |tangential force| (Karhula A8.1.10; 0 for the others).
#[derive(Debug, Clone)]
pub(crate) struct JointPeaks {
    force: Vec<f64>,
    moment: Vec<f64>,
    tangential: Vec<f64>,
}

impl JointPeaks {
    pub(crate) fn new(joints: usize) -> Self {
        Self {
            force: vec![0.0; joints],
            moment: vec![0.0; joints],
            tangential: vec![0.0; joints],
        }
    }

    /// Raised over the lanes `lanes` of `block`, whose loads of this family are `loads`.
    #[inline(always)]
    pub(crate) fn push(
        &mut self,
        block: &StepBlock,
        loads: &LoadsBlock,
        lanes: Range<usize>,
        kinds: &JointKinds,
    ) {
        for (f, l) in self.force.iter_mut().zip(&loads.joints) {
            raise_over(f, lanes.clone(), |i| l.fx[i] * l.fx[i] + l.fy[i] * l.fy[i]);
        }
        for &j in &kinds.slides {
            let l = &loads.joints[j];
            raise_over_lanes(&mut self.moment[j], lanes.clone(), |i| l.moment[i].abs());
        }
        for &j in &kinds.meshes {
            let (l, m) = (&loads.joints[j], &block.state.joints[j]);
            raise_over(&mut self.tangential[j], lanes.clone(), |i| {
                let mesh = JointMotion {
                    direction: C::new(m.direction_x[i], m.direction_y[i]),
                    ..JointMotion::default()
                };
                tangential(C::new(l.fx[i], l.fy[i]), &mesh).abs()
            });
        }
    }

    pub(crate) fn merge(&mut self, later: &Self) {
        raise_each(&mut self.force, &later.force);
        raise_each(&mut self.moment, &later.moment);
        raise_each(&mut self.tangential, &later.tangential);
    }

    /// The peaks of the family `family`: each joint's force (and a slide's couple), then each
    /// mesh's tangential force (names joined as in [`MotionPeaks::finish`]).
    pub(crate) fn finish(&self, family: &str, t: &Topology, kinds: &JointKinds, m: &mut Summary) {
        for (j, (force, moment)) in t.joints.iter().zip(self.force.iter().zip(&self.moment)) {
            m.push_as(
                "{family}_{joint}_force_max",
                [family, "_", j.name, "_force_max"].concat(),
                force.sqrt(),
            );
            if matches!(j.kind, JointKind::Prismatic) {
                m.push_as(
                    "{family}_{joint}_moment_max",
                    [family, "_", j.name, "_moment_max"].concat(),
                    *moment,
                );
            }
        }
        for &k in &kinds.meshes {
            let name = t.joints[k].name;
            m.push_as(
                "{family}_{joint}_tangential_max",
                [family, "_", name, "_tangential_max"].concat(),
                self.tangential[k],
            );
        }
    }
}

/// Peaks of a run with a gas model: the cylinder pressure and |the gas force|.
#[derive(Debug, Clone, Default)]
pub(crate) struct GasPeaks {
    pressure: Option<f64>,
    force: f64,
}

impl GasPeaks {
    /// Raised over the lanes `lanes` of `block` (a block without gas leaves them).
    #[inline(always)]
    pub(crate) fn push(&mut self, block: &StepBlock, lanes: Range<usize>) {
        if let (Some(p), Some(f)) = (block.pressure, block.piston_force) {
            // The block's largest pressure first, then the run's (the same maximum).
            let mut highest = p[lanes.start.min(LANES - 1)];
            raise_over(&mut highest, lanes.clone(), |i| p[i]);
            self.pressure = Some(self.pressure.map_or(highest, |q| q.max(highest)));
            if !block.state.pistons.is_empty() {
                raise_over(&mut self.force, lanes, |i| f[i].abs());
            }
        }
    }

    pub(crate) fn merge(&mut self, later: &Self) {
        self.pressure = match (self.pressure, later.pressure) {
            (Some(a), Some(b)) => Some(a.max(b)),
            (a, b) => a.or(b),
        };
        raise(&mut self.force, later.force);
    }

    pub(crate) fn finish(&self, m: &mut Summary) {
        if let Some(p) = self.pressure {
            m.push("cylinder_pressure_max", p);
            m.push("gas_force_max", self.force);
        }
    }
}
