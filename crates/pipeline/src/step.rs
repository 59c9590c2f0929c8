//! What the step loop ([`crate::run`]) hands to its sinks: a block of consecutive steps as
//! columns ([`StepBlock`]), and the same steps one at a time where wanted ([`Step`]); the
//! [`Sink`] trait; a sink that keeps every step ([`Steps`]).

use cardan_mechanism::{Column, Loads, LoadsBlock, State, StateBlock};

/// One step, as the sinks that take steps one at a time see it.
#[derive(Debug, Clone, Copy)]
pub struct Step<'a> {
    /// Index of the step in the run, from 0.
    pub index: usize,
    pub state: &'a State,
    /// Absolute cylinder pressure, Pa, if a gas model loads the pistons.
    pub pressure: Option<f64>,
    /// Gas force on each piston along its axis, towards the crankshaft, N (empty without gas).
    pub piston_forces: &'a [f64],
    /// The loads of each family, in the order of the run's families.
    pub families: &'a [Loads],
    /// Their sum.
    pub total: &'a Loads,
    /// The values of each of the run's stages ([`crate::Stage`]), in the run's order (empty
    /// without stages).
    pub stages: &'a [Vec<f64>],
    /// Each family's torque shares by body ([`cardan_loads::torque_shares`]), N·m; computed, with the
    /// state's extras, only when a sink [wants](Sink::wants_details) them (zeros otherwise).
    pub shares: &'a [Vec<f64>],
}

/// Consecutive steps (at most [`cardan_mechanism::LANES`]), as columns, and one by one where wanted.
#[derive(Debug, Clone, Copy)]
pub struct StepBlock<'a> {
    /// Index of the block's first step in the run.
    pub first: usize,
    /// The mechanism's states: lane `i` is step `first + i`.
    pub state: &'a StateBlock,
    /// Absolute cylinder pressure at each step, Pa, if a gas model loads the pistons.
    pub pressure: Option<&'a Column>,
    /// Gas force on every piston at each step, along its axis towards the crankshaft, N, if a
    /// gas model loads the pistons.
    pub piston_force: Option<&'a Column>,
    /// The loads of each family, in the order of the run's families.
    pub families: &'a [LoadsBlock],
    /// Their sum.
    pub total: &'a LoadsBlock,
    /// The same steps one at a time, with the values of the run's stages: made only when a
    /// sink [wants](Sink::wants_steps) them or [details](Sink::wants_details) (empty
    /// otherwise).
    pub steps: &'a [Step<'a>],
    /// The values of the run's stages, by stage in the run's order: a column per value, lane
    /// `i` step `first + i`.
    pub stage_columns: &'a [Vec<Column>],
}

impl StepBlock<'_> {
    /// Steps in the block.
    pub fn len(&self) -> usize {
        self.state.len
    }

    pub fn is_empty(&self) -> bool {
        self.state.len == 0
    }
}

/// Where steps go.
pub trait Sink {
    /// Takes one step (a sink that [wants](Sink::wants_steps) steps); an error stops the run (a
    /// file that cannot be written).
    fn push(&mut self, _step: &Step) -> Result<(), String> {
        Ok(())
    }

    /// Takes a block of consecutive steps, in order; an error names the index of the step it
    /// stopped at. By default each of [`StepBlock::steps`] in turn.
    fn push_block(&mut self, block: &StepBlock) -> Result<(), (usize, String)> {
        for s in block.steps {
            self.push(s).map_err(|message| (s.index, message))?;
        }
        Ok(())
    }

    /// Whether it reads the steps one at a time ([`StepBlock::steps`]); a sink that reads only
    /// the columns spares the run a copy of every step.
    fn wants_steps(&self) -> bool {
        true
    }

    /// Whether it reads [`Step::shares`] and the state's extras (they cost divisions and square
    /// roots per step that a summary does not need).
    fn wants_details(&self) -> bool {
        false
    }
}

/// One step kept whole, for tests and callers that want every step in memory.
#[derive(Debug, Clone, PartialEq)]
pub struct StepRecord {
    pub state: State,
    pub pressure: Option<f64>,
    pub piston_forces: Vec<f64>,
    pub families: Vec<Loads>,
    pub total: Loads,
    /// Each stage's values ([`Step::stages`]).
    pub stages: Vec<Vec<f64>>,
    pub shares: Vec<Vec<f64>>,
}

/// A sink that keeps every step (memory grows with the steps: for tests and small runs).
#[derive(Debug, Clone, Default)]
pub struct Steps(pub Vec<StepRecord>);

impl Sink for Steps {
    fn wants_details(&self) -> bool {
        true
    }

    fn push(&mut self, s: &Step) -> Result<(), String> {
        self.0.push(StepRecord {
            state: s.state.clone(),
            pressure: s.pressure,
            piston_forces: s.piston_forces.to_vec(),
            families: s.families.to_vec(),
            total: s.total.clone(),
            stages: s.stages.to_vec(),
            shares: s.shares.to_vec(),
        });
        Ok(())
    }
}
