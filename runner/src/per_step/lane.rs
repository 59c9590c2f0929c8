//! One step's values as the per-step row reads them ([`Lane`]): a [`Step`] the run made, or a
//! lane of a block's columns ([`BlockLane`]), so that a sink taking one step in many fills its
//! rows from the columns without gathering each step whole first. The row itself is defined
//! once, in `row.rs`, for both.

use cardan_dynamics::{Step, StepBlock};
use cardan_mechanism::{BodyMotion, CrankState, JointLoad, JointMotion, PistonMotion};
use std::ops::Deref;

/// One step's values, by the topology's indices (pistons, bodies, joints, extras), the run's
/// load families (the family after the last: their total) and its stages.
pub(super) trait Lane {
    /// A body's motion, a joint's motion, a joint's load: borrowed from a step (not copied
    /// whole for the few fields a column reads), made from a block's columns.
    type Body<'x>: Deref<Target = BodyMotion>
    where
        Self: 'x;
    type Joint<'x>: Deref<Target = JointMotion>
    where
        Self: 'x;
    type Load<'x>: Deref<Target = JointLoad>
    where
        Self: 'x;
    /// Index of the step in the run.
    fn index(&self) -> usize;
    fn crank(&self) -> CrankState;
    fn piston(&self, p: usize) -> PistonMotion;
    fn body(&self, b: usize) -> Self::Body<'_>;
    fn joint(&self, j: usize) -> Self::Joint<'_>;
    fn extra(&self, e: usize) -> f64;
    /// The absolute cylinder pressure, Pa, and the gas force on the first piston, N (0 without
    /// a piston), if a gas model loads the pistons.
    fn gas(&self) -> Option<(f64, f64)>;
    /// The number of the run's load families.
    fn families(&self) -> usize;
    /// Family `f`'s load on joint `j` (`f` = [`Lane::families`]: their total).
    fn load(&self, f: usize, j: usize) -> Self::Load<'_>;
    /// Family `f`'s drive torque (`f` = [`Lane::families`]: their total), N·m.
    fn crank_torque(&self, f: usize) -> f64;
    /// Family `f`'s torque share of body `b`, N·m.
    fn share(&self, f: usize, b: usize) -> f64;
    /// The number of the run's stages, and value `k` of stage `s`.
    fn stages(&self) -> usize;
    fn stage(&self, s: usize, k: usize) -> f64;
}

impl Lane for Step<'_> {
    type Body<'x>
        = &'x BodyMotion
    where
        Self: 'x;
    type Joint<'x>
        = &'x JointMotion
    where
        Self: 'x;
    type Load<'x>
        = &'x JointLoad
    where
        Self: 'x;

    fn index(&self) -> usize {
        self.index
    }

    fn crank(&self) -> CrankState {
        self.state.crank
    }

    fn piston(&self, p: usize) -> PistonMotion {
        self.state.pistons[p]
    }

    fn body(&self, b: usize) -> &BodyMotion {
        &self.state.bodies[b]
    }

    fn joint(&self, j: usize) -> &JointMotion {
        &self.state.joints[j]
    }

    fn extra(&self, e: usize) -> f64 {
        self.state.extras[e]
    }

    fn gas(&self) -> Option<(f64, f64)> {
        let force = self.piston_forces.first().copied().unwrap_or(0.0);
        self.pressure.map(|p| (p, force))
    }

    fn families(&self) -> usize {
        self.families.len()
    }

    fn load(&self, f: usize, j: usize) -> &JointLoad {
        &self.families.get(f).unwrap_or(self.total).joints[j]
    }

    fn crank_torque(&self, f: usize) -> f64 {
        self.families.get(f).unwrap_or(self.total).crank_torque
    }

    fn share(&self, f: usize, b: usize) -> f64 {
        self.shares[f][b]
    }

    fn stages(&self) -> usize {
        self.stages.len()
    }

    fn stage(&self, s: usize, k: usize) -> f64 {
        self.stages[s][k]
    }
}

/// Lane `i` of a block's columns: the step [`StepBlock::step`] would gather (no details, as
/// a run without steps has none: extras and torque shares 0).
pub(super) struct BlockLane<'b> {
    pub block: &'b StepBlock<'b>,
    pub i: usize,
}

/// A value made from a block's columns.
pub(super) struct Made<T>(T);

impl<T> Deref for Made<T> {
    type Target = T;

    fn deref(&self) -> &T {
        &self.0
    }
}

impl Lane for BlockLane<'_> {
    type Body<'x>
        = Made<BodyMotion>
    where
        Self: 'x;
    type Joint<'x>
        = Made<JointMotion>
    where
        Self: 'x;
    type Load<'x>
        = Made<JointLoad>
    where
        Self: 'x;

    fn index(&self) -> usize {
        self.block.first + self.i
    }

    fn crank(&self) -> CrankState {
        self.block.state.crank.at(self.i)
    }

    fn piston(&self, p: usize) -> PistonMotion {
        self.block.state.pistons[p].at(self.i)
    }

    fn body(&self, b: usize) -> Made<BodyMotion> {
        Made(self.block.state.bodies[b].at(self.i))
    }

    fn joint(&self, j: usize) -> Made<JointMotion> {
        Made(self.block.state.joints[j].at(self.i))
    }

    fn extra(&self, _: usize) -> f64 {
        0.0
    }

    fn gas(&self) -> Option<(f64, f64)> {
        let b = self.block;
        let force = (b.piston_force)
            .filter(|_| !b.state.pistons.is_empty())
            .map_or(0.0, |f| f[self.i]);
        b.pressure.map(|p| (p[self.i], force))
    }

    fn families(&self) -> usize {
        self.block.families.len()
    }

    fn load(&self, f: usize, j: usize) -> Made<JointLoad> {
        Made(
            self.block
                .families
                .get(f)
                .unwrap_or(self.block.total)
                .joints[j]
                .at(self.i),
        )
    }

    fn crank_torque(&self, f: usize) -> f64 {
        self.block
            .families
            .get(f)
            .unwrap_or(self.block.total)
            .crank_torque[self.i]
    }

    fn share(&self, _: usize, _: usize) -> f64 {
        0.0
    }

    fn stages(&self) -> usize {
        self.block.stage_columns.len()
    }

    fn stage(&self, s: usize, k: usize) -> f64 {
        self.block.stage_columns[s][k][self.i]
    }
}
