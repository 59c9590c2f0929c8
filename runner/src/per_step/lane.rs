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

/// Lane `i` of a block's columns: the step the run makes for a sink that wants its steps
/// ([`StepBlock::steps`]) but not their details (no details, as
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::per_step::row::{Row, RunLayout};
    use cardan_dynamics::{
        run, Friction, Gas, Inertial, LoadFamily, LossBudget, LossStage, Sink, Solver, Stage,
    };
    use cardan_mechanism::{
        CrankMotion, Grid, MachineGeometry, MassInputs, Material, Options, MECHANISMS,
    };
    use std::f64::consts::PI;

    /// Compares, at every lane of every block, the row filled from the block's columns with the
    /// row of the run's own step there ([`StepBlock::steps`], made as the sink wants them),
    /// bit for bit.
    struct Compare<'a> {
        row: Row<'a>,
        lanes: usize,
    }

    impl Sink for Compare<'_> {
        fn wants_steps(&self) -> bool {
            true
        }

        fn push_block(&mut self, block: &StepBlock) -> Result<(), (usize, String)> {
            let width = self.row.header().len();
            for i in 0..block.len() {
                let (mut from_lane, mut from_step) = (vec![0.0; width], vec![0.0; width]);
                self.row.fill_slice(&BlockLane { block, i }, &mut from_lane);
                self.row.fill_slice(&block.steps[i], &mut from_step);
                for (k, (a, b)) in from_lane.iter().zip(&from_step).enumerate() {
                    if a.to_bits() != b.to_bits() {
                        let name = &self.row.header()[k];
                        return Err((block.first + i, format!("{name}: {a} from the lane, {b}")));
                    }
                }
                self.lanes += 1;
            }
            Ok(())
        }
    }

    /// A block's lane is the run's own step there, column for column: for every registered
    /// mechanism, with two load families and their total, a gas model and a stage's columns,
    /// over blocks whole and a last one part-filled.
    #[test]
    fn a_block_lane_fills_the_row_of_the_runs_own_step() {
        let geometry = MachineGeometry {
            crank_length: 0.06,
            rod_length: 0.14,
            bore: 0.12,
            pin_offset: 0.0,
        };
        let motion = CrankMotion {
            start_angle: PI / 2.0,
            initial_speed: 30.0 * PI,
            angular_acceleration: 400.0 * PI,
        };
        // A made-up gas load for the 0.12 m bore: (pressure, Pa; piston force, N).
        let gas = |theta: f64| {
            let f = 2e4 * (1.0 + theta.sin());
            (f / (PI / 4.0 * 0.12 * 0.12), f)
        };
        let (inertial, gas_family) = (Inertial::new(Solver::ClosedForm), Gas(Solver::ClosedForm));
        let families: [&dyn LoadFamily; 2] = [&inertial, &gas_family];
        // Steel rods: the default rules' masses (a machine without mass has no torque to share).
        let masses = MassInputs {
            rod_material: Some(Material::Steel),
            ..MassInputs::default()
        };
        for entry in MECHANISMS {
            let m = (entry.build)(&geometry, &masses, &Options::new()).unwrap();
            let budget = LossBudget::new(&Friction::karhula(), m.as_ref(), 0.12).unwrap();
            let mut losses = LossStage::new(budget);
            let columns = vec![losses.columns()];
            let layout = RunLayout {
                families: &["inertial", "gas"],
                gas: true,
                stages: &columns,
            };
            let mut sink = Compare {
                row: Row::new(m.as_ref(), &layout),
                lanes: 0,
            };
            let steps = 150;
            // 90° to 140°: the hypotrochoid of the default readings stops at 150°.
            let mut grid = Grid::new(motion, PI / 2.0, 140f64.to_radians(), steps);
            let mut stages: [&mut dyn Stage; 1] = [&mut losses];
            run(
                m.as_ref(),
                &mut grid,
                &families,
                Some(&gas),
                &mut stages,
                &mut [&mut sink],
            )
            .unwrap_or_else(|e| panic!("{}: {e}", entry.name));
            assert_eq!(sink.lanes, steps + 1, "{}", entry.name);
            assert!(sink.row.header().iter().any(|h| h == "total_torque_nm"));
        }
    }
}
