//! The steps this process has run so far, for a progress display inside a long case (issue
//! 38.1: a one-case run showed "0/1 cases" until its end). Every crank train's run takes a
//! `StepCounter` among its sinks, which adds each block's steps (up to 64) to one atomic
//! counter: one relaxed addition per block, nothing per step, so the step loop is not slowed.
//! The count covers the steps streamed to the sinks (every prescribed-motion run, the reported
//! cycle of a solved motion), not the solved motion's earlier cycles, the sampling check's
//! shifted runs or the writing of files.

use cardan_dynamics::{Joinable, Sink, StepBlock};
use std::sync::atomic::{AtomicU64, Ordering};

static STEPS: AtomicU64 = AtomicU64::new(0);

/// The steps run by every case of this process so far (all threads, all batches).
pub fn steps_run() -> u64 {
    STEPS.load(Ordering::Relaxed)
}

/// A sink that counts the steps it is given into [`steps_run`].
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct StepCounter;

impl Sink for StepCounter {
    fn push_block(&mut self, block: &StepBlock) -> Result<(), (usize, String)> {
        STEPS.fetch_add(block.len() as u64, Ordering::Relaxed);
        Ok(())
    }

    fn wants_steps(&self) -> bool {
        false
    }
}

/// Each piece of a shared run counts its own steps: nothing to join.
impl Joinable for StepCounter {
    fn join(&mut self, _later: Self) {}
}
