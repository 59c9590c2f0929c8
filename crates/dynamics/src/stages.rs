//! The per-step stages of a run ([`Stage`]): the gear ratings ([`GearStage`]) and the loss
//! budget ([`LossStage`]), each evaluated on the block's columns, with the accumulator that
//! totals its values into the summary. A run takes the ratings before the budget, which
//! charges a rated mesh's loss as the rating computed it ([`PassedOn::mesh_losses`]).

use crate::gear_rating::{GearRatings, MeshRating};
use crate::losses::LossBudget;
use crate::machine::MachineKind;
use crate::metrics::{self, MetricDef, Summary};
use crate::stage::{
    Block, LaneError, PassedOn, RunTotals, Stage, StageColumn, StageError, StageTotals,
};
use crate::step::StepBlock;
use crate::summary::peaks::{raise, raise_over};
use crate::summary::{add_trapezoids, Integral};
use crate::LossLanes;
use cardan_mechanism::{Column, ZERO};
use std::any::Any;
use std::ops::Range;

/// The loss budget as a stage. Its values at a step: the drive torque that covers the losses,
/// Σ losses / |ω|, N·m (0 at rest, where the losses are 0 too), then the power loss of each
/// component ([`LossBudget::names`]), W. It passes the sum of the losses on
/// ([`PassedOn::loss_power`]).
#[derive(Debug, Clone)]
pub struct LossStage {
    budget: LossBudget,
}

impl LossStage {
    /// The stage of `budget`.
    pub fn new(budget: LossBudget) -> Self {
        Self { budget }
    }
}

impl Stage for LossStage {
    fn width(&self) -> usize {
        1 + self.budget.names().len()
    }

    fn evaluate(
        &mut self,
        block: &Block,
        passed: &mut PassedOn,
        out: &mut [Column],
    ) -> Result<(), LaneError> {
        let at = LossLanes {
            lanes: 0..block.len,
            states: block.states,
            total: block.total,
            pressure: block.pressure,
            rated_meshes: &passed.mesh_losses,
        };
        let (torque, parts) = out.split_first_mut().expect("a torque column");
        let failed = self.budget.evaluate(&at, parts).err();
        let complete = failed.as_ref().map_or(block.len, |f| f.lane);
        let mut power = ZERO;
        for i in 0..complete {
            let sum: f64 = parts.iter().map(|c| c[i]).sum();
            if !sum.is_finite() {
                let k = parts.iter().position(|c| !c[i].is_finite()).unwrap_or(0);
                let quantity = format!("power_loss_{}", self.budget.names()[k]);
                let value = parts[k][i];
                return Err(StageError::NonFinite { quantity, value }.at_lane(i));
            }
            let speed = block.states.crank.speed[i];
            torque[i] = if speed != 0.0 { sum / speed.abs() } else { 0.0 };
            power[i] = sum;
        }
        if let Some(f) = failed {
            return Err(StageError::Failed(f.why).at_lane(f.lane));
        }
        passed.loss_power = Some(power);
        Ok(())
    }

    fn columns(&self) -> Vec<StageColumn> {
        let torque = std::iter::once("friction_torque_nm".to_string());
        let losses = self
            .budget
            .names()
            .iter()
            .map(|c| ["power_loss_", c.as_str(), "_w"].concat());
        torque
            .chain(losses)
            .enumerate()
            .map(|(value, name)| StageColumn { name, value })
            .collect()
    }

    fn metrics(&self) -> &'static [MetricDef] {
        metrics::LOSSES
    }

    fn totals(&self) -> Box<dyn StageTotals> {
        let n = self.budget.names().len();
        Box::new(LossTotals {
            kind: self.budget.kind(),
            names: self.budget.names().to_vec(),
            work: vec![Integral::default(); n],
            previous: vec![0.0; n],
            friction_torque: 0.0,
        })
    }

    fn carries_history(&self) -> bool {
        self.budget.carries_history()
    }

    fn fork(&self) -> Box<dyn Stage> {
        Box::new(self.clone())
    }
}

/// The works of the loss components and the peak friction torque.
#[derive(Debug, Clone)]
struct LossTotals {
    /// Pump or engine: which need or output and efficiency it reports.
    kind: MachineKind,
    names: Vec<String>,
    /// ∫ P dt of each component, J (Karhula A9.1.68-71), by the trapezoidal rule in time.
    work: Vec<Integral>,
    /// Each component's power at the last step taken, W.
    previous: Vec<f64>,
    friction_torque: f64,
}

impl StageTotals for LossTotals {
    fn push_lanes(
        &mut self,
        block: &StepBlock,
        lanes: Range<usize>,
        stage: usize,
        previous: Option<f64>,
    ) {
        let Some(last) = lanes.end.checked_sub(1) else {
            return;
        };
        let (torque, losses) = block.stage_columns[stage]
            .split_first()
            .expect("a friction torque");
        let time = &block.state.crank.time;
        // Each component's ∫ P dt over the lanes, a column at a time (the terms of the
        // trapezoids in the steps' order, as `Integral::add` step by step).
        for ((w, p0), c) in self.work.iter_mut().zip(&mut self.previous).zip(losses) {
            let before = *p0;
            add_trapezoids(
                w,
                block.first,
                lanes.clone(),
                || previous.map(|t0| 0.5 * (time[0] - t0) * (c[0] + before)),
                |i| 0.5 * (time[i] - time[i - 1]) * (c[i] + c[i - 1]),
            );
            *p0 = c[last];
        }
        raise_over(&mut self.friction_torque, lanes, |i| torque[i]);
    }

    fn close_chunk(&mut self) {
        self.work.iter_mut().for_each(Integral::close_chunk);
    }

    fn merge(&mut self, later: &dyn StageTotals) {
        let later = later.as_any().downcast_ref::<Self>().expect("loss totals");
        for (x, y) in self.work.iter_mut().zip(&later.work) {
            x.merge(y);
        }
        raise(&mut self.friction_torque, later.friction_torque);
        self.previous.clone_from(&later.previous);
    }

    /// The loss metrics (Karhula A9.1.56-75): mean power loss in all and per component, the
    /// work lost, the peak friction torque, and, with a gas model, the efficiency and the
    /// torque and power the machine needs (a pump or compressor: net work into the crank) or
    /// gives (an engine: net work out), one definition per machine kind, whatever the sign of
    /// the run's work (a decelerating pump is still a pump; issue 36); the efficiency where its
    /// denominator, the work the drive gives (pump) or takes (engine), is positive. Karhula's
    /// definitions are of a steady cycle: in a run-up or coast-down the drive work includes
    /// the change of the bodies' kinetic energy.
    fn finish(&self, run: &RunTotals, m: &mut Summary) {
        let (span, time) = (run.span, run.time);
        let lost: f64 = self.work.iter().map(Integral::value).sum();
        m.push("loss_work", lost);
        m.push("power_loss_mean", lost / time);
        for (name, work) in self.names.iter().zip(&self.work) {
            m.push_as(
                "power_loss_mean_{component}",
                ["power_loss_mean_", name.as_str()].concat(),
                work.value() / time,
            );
        }
        m.push("friction_torque_max", self.friction_torque);
        let (Some(gas), Some(total)) = (run.work("gas"), run.work("total")) else {
            return;
        };
        match self.kind {
            // (A9.1.60-61, 64-65)
            MachineKind::Pump => {
                let need = total + lost;
                m.push("torque_need_mean", need / span);
                m.push("power_need_mean", need / time);
            }
            // (A9.1.62-63, 66-67)
            MachineKind::Engine => {
                let out = -total - lost;
                m.push("output_torque_mean", out / span);
                m.push("output_power_mean", out / time);
            }
        }
        if let Some(e) = self.kind.efficiency(gas, total, lost) {
            m.push("mechanical_efficiency", e);
        }
    }

    fn fork(&self) -> Box<dyn StageTotals> {
        Box::new(self.clone())
    }

    fn as_any(&self) -> &dyn Any {
        self
    }
}

/// The gear ratings as a stage, on the block's columns ([`GearRatings::evaluate_block`]). Its
/// values at a step: each rated mesh's [`MeshRating`] as its [values](MeshRating::values); it
/// passes each mesh's loss on ([`PassedOn::mesh_losses`]).
#[derive(Debug, Clone)]
pub struct GearStage {
    ratings: GearRatings,
    /// The values of each mesh: [`MeshRating::WIDTH`] with an ISO 6336 rating, else
    /// [`MeshRating::AGMA_WIDTH`] (a run rated by AGMA alone keeps the columns it had).
    per_mesh: usize,
}

impl GearStage {
    /// The stage of `ratings`.
    pub fn new(ratings: GearRatings) -> Self {
        let per_mesh = if ratings.iso() {
            MeshRating::WIDTH
        } else {
            MeshRating::AGMA_WIDTH
        };
        Self { ratings, per_mesh }
    }
}

impl Stage for GearStage {
    fn width(&self) -> usize {
        self.per_mesh * self.ratings.joints().count()
    }

    fn evaluate(
        &mut self,
        block: &Block,
        passed: &mut PassedOn,
        out: &mut [Column],
    ) -> Result<(), LaneError> {
        let first = passed.mesh_losses.len();
        passed
            .mesh_losses
            .extend(self.ratings.joints().map(|joint| (joint, ZERO)));
        let losses = &mut passed.mesh_losses[first..];
        (self.ratings)
            .evaluate_block(block, out, self.per_mesh, losses)
            .map_err(|(i, e)| StageError::Failed(e).at_lane(i))
    }

    /// Each mesh's dynamic tooth load; by AGMA its contact stress, and its bending stress where
    /// it gets a bending rating; by ISO 6336 its contact and root stresses.
    fn columns(&self) -> Vec<StageColumn> {
        let mut c = Vec::new();
        let ratings = &self.ratings;
        let (agma, iso) = (ratings.standard().agma(), ratings.iso());
        let meshes = ratings
            .names()
            .into_iter()
            .zip(ratings.bending())
            .enumerate();
        for (k, (name, bending)) in meshes {
            let at = |value: usize, what: &str| StageColumn {
                name: [name, "_", what].concat(),
                value: k * self.per_mesh + value,
            };
            c.push(at(1, "dynamic_tooth_load_n"));
            if agma {
                c.push(at(2, "contact_stress_pa"));
                if bending {
                    c.push(at(4, "bending_stress_pa"));
                }
            }
            if iso {
                c.push(at(7, "iso_contact_stress_pa"));
                c.push(at(9, "iso_bending_stress_pa"));
            }
        }
        c
    }

    fn metrics(&self) -> &'static [MetricDef] {
        metrics::GEAR_RATING
    }

    fn totals(&self) -> Box<dyn StageTotals> {
        Box::new(GearTotals {
            contact_ratio: (self.ratings.contact_ratios().into_iter())
                .fold(f64::INFINITY, f64::min),
            bending: self.ratings.bending().iter().all(|b| *b),
            per_mesh: self.per_mesh,
            agma: self.ratings.standard().agma(),
            iso: IsoTotals {
                contact_stress: 0.0,
                contact_safety: f64::INFINITY,
                bending_stress: 0.0,
                bending_safety: f64::INFINITY,
            },
            tooth_load: 0.0,
            dynamic_load: 0.0,
            contact_stress: 0.0,
            contact_safety: f64::INFINITY,
            bending_stress: 0.0,
            bending_safety: f64::INFINITY,
            loss_work: Integral::default(),
            previous_loss: 0.0,
        })
    }

    fn fork(&self) -> Box<dyn Stage> {
        Box::new(self.clone())
    }
}

/// The gear meshes' rating over the run: peaks of the loads and stresses, the smallest safety
/// factors, the mesh loss work.
#[derive(Debug, Clone)]
struct GearTotals {
    /// The smallest contact ratio of the meshes.
    contact_ratio: f64,
    /// Whether every mesh gets a bending rating.
    bending: bool,
    /// The stage's values of each mesh ([`GearStage`]).
    per_mesh: usize,
    /// Whether AGMA's stresses and safety factors are reported.
    agma: bool,
    /// ISO 6336's (reported with an ISO rating: `per_mesh` is [`MeshRating::WIDTH`]).
    iso: IsoTotals,
    tooth_load: f64,
    dynamic_load: f64,
    contact_stress: f64,
    contact_safety: f64,
    bending_stress: f64,
    bending_safety: f64,
    /// ∫ P dt of the meshes' loss, J, by the trapezoidal rule in time.
    loss_work: Integral,
    /// The meshes' loss at the last step taken, W.
    previous_loss: f64,
}

/// The ISO 6336 rating over the run: peaks of the stresses, the smallest safety factors.
#[derive(Debug, Clone, Copy)]
struct IsoTotals {
    contact_stress: f64,
    contact_safety: f64,
    bending_stress: f64,
    bending_safety: f64,
}

impl IsoTotals {
    fn take(&mut self, r: &MeshRating) {
        raise(&mut self.contact_stress, r.iso_contact_stress);
        self.contact_safety = self.contact_safety.min(r.iso_contact_safety);
        raise(&mut self.bending_stress, r.iso_bending_stress);
        self.bending_safety = self.bending_safety.min(r.iso_bending_safety);
    }

    fn merge(&mut self, b: &Self) {
        raise(&mut self.contact_stress, b.contact_stress);
        self.contact_safety = self.contact_safety.min(b.contact_safety);
        raise(&mut self.bending_stress, b.bending_stress);
        self.bending_safety = self.bending_safety.min(b.bending_safety);
    }

    /// The ISO metrics; a safety factor only where a mesh carried a load.
    fn finish(&self, m: &mut Summary) {
        m.push("iso_contact_stress_max", self.contact_stress);
        if self.contact_safety.is_finite() {
            m.push("iso_contact_safety_factor", self.contact_safety);
        }
        m.push("iso_bending_stress_max", self.bending_stress);
        if self.bending_safety.is_finite() {
            m.push("iso_bending_safety_factor", self.bending_safety);
        }
    }
}

impl StageTotals for GearTotals {
    fn push_lanes(
        &mut self,
        block: &StepBlock,
        lanes: Range<usize>,
        stage: usize,
        previous: Option<f64>,
    ) {
        let (mut started, mut t0) = (previous.is_some(), previous.unwrap_or(0.0));
        let meshes = block.stage_columns[stage].chunks_exact(self.per_mesh);
        let iso = self.per_mesh == MeshRating::WIDTH;
        for i in lanes {
            let (k, time) = (block.first + i, block.state.crank.time[i]);
            let ratings = meshes.clone().map(|c| MeshRating::at_lane(c, i));
            let loss: f64 = ratings.clone().map(|r| r.loss).sum();
            if started {
                let dt = time - t0;
                self.loss_work
                    .add(k, 0.5 * dt * (loss + self.previous_loss));
            }
            self.previous_loss = loss;
            for r in ratings {
                raise(&mut self.tooth_load, r.tooth_load);
                raise(&mut self.dynamic_load, r.dynamic_load);
                raise(&mut self.contact_stress, r.contact_stress);
                self.contact_safety = self.contact_safety.min(r.contact_safety);
                if self.bending {
                    raise(&mut self.bending_stress, r.bending_stress);
                    self.bending_safety = self.bending_safety.min(r.bending_safety);
                }
                if iso {
                    self.iso.take(&r);
                }
            }
            (started, t0) = (true, time);
        }
    }

    fn close_chunk(&mut self) {
        self.loss_work.close_chunk();
    }

    fn merge(&mut self, later: &dyn StageTotals) {
        let b = later.as_any().downcast_ref::<Self>().expect("gear totals");
        raise(&mut self.tooth_load, b.tooth_load);
        raise(&mut self.dynamic_load, b.dynamic_load);
        raise(&mut self.contact_stress, b.contact_stress);
        self.contact_safety = self.contact_safety.min(b.contact_safety);
        raise(&mut self.bending_stress, b.bending_stress);
        self.bending_safety = self.bending_safety.min(b.bending_safety);
        self.iso.merge(&b.iso);
        self.loss_work.merge(&b.loss_work);
        self.previous_loss = b.previous_loss;
    }

    /// The gear metrics (issue 10): peaks over the run and the meshes, smallest safety factors
    /// (infinite only if no mesh ever carried a load), mean mesh loss.
    fn finish(&self, run: &RunTotals, m: &mut Summary) {
        m.push("contact_ratio", self.contact_ratio);
        m.push("mesh_tangential_load_max", self.tooth_load);
        m.push("dynamic_tooth_load_max", self.dynamic_load);
        if self.agma {
            m.push("contact_stress_max", self.contact_stress);
            // A mesh that never carried a load has no finite safety factor: none is reported.
            if self.contact_safety.is_finite() {
                m.push("contact_safety_factor", self.contact_safety);
            }
            if self.bending {
                m.push("bending_stress_max", self.bending_stress);
                if self.bending_safety.is_finite() {
                    m.push("bending_safety_factor", self.bending_safety);
                }
            }
        }
        m.push(
            "gear_mesh_power_loss_mean",
            self.loss_work.value() / run.time,
        );
        if self.per_mesh == MeshRating::WIDTH {
            self.iso.finish(m);
        }
    }

    fn fork(&self) -> Box<dyn StageTotals> {
        Box::new(self.clone())
    }

    fn as_any(&self) -> &dyn Any {
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::GearStandard;
    use crate::{Friction, GearSpec};
    use cardan_mechanism::{MachineGeometry, MassInputs, Options, MECHANISMS};

    /// Each stage's columns hold values it gives, and its totals give only metrics of its own
    /// part of the registry.
    #[test]
    fn a_stage_declares_its_columns_and_metrics() {
        let g = MachineGeometry {
            crank_length: 0.06,
            rod_length: 0.14,
            bore: 0.12,
            pin_offset: 0.0,
        };
        for entry in MECHANISMS {
            let m = (entry.build)(&g, &MassInputs::default(), &Options::new()).unwrap();
            let mut stages: Vec<Box<dyn Stage>> = Vec::new();
            // AGMA alone, ISO alone and both: each declares the columns and metrics it gives.
            let iso = |standard| GearSpec {
                standard,
                accuracy_grade: Some(7.0),
                ..GearSpec::default()
            };
            for spec in [
                GearSpec::default(),
                iso(GearStandard::Iso6336),
                iso(GearStandard::Both),
            ] {
                if let Ok(r) = GearRatings::new(&spec, m.as_ref(), None) {
                    stages.push(Box::new(GearStage::new(r)));
                }
            }
            let budget = LossBudget::new(&Friction::karhula(), m.as_ref(), 0.12).unwrap();
            stages.push(Box::new(LossStage::new(budget)));
            for s in &stages {
                assert!(
                    s.columns().iter().all(|c| c.value < s.width()),
                    "{}",
                    entry.name
                );
                let works = [("gas", -1.0), ("total", -2.0)];
                let run = RunTotals {
                    span: 1.0,
                    time: 1.0,
                    works: &works,
                };
                let mut summary = Summary::default();
                s.totals().finish(&run, &mut summary);
                assert!(!summary.metrics.is_empty());
                for x in &summary.metrics {
                    let own = metrics::find_in(s.metrics(), &x.name);
                    assert!(own.is_some(), "{}: {}", entry.name, x.name);
                }
            }
        }
    }
}
