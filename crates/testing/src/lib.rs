//! Checks for tests: each failure message names the quantity, both values and the tolerance, so
//! a failing validation test reads like a line of a validation report; and that a message names
//! what it must. And [`OneThread`], a crank grid the benchmarks run on one thread; [`OneByOne`],
//! a grid handed out a state at a time, as a solved motion's; and
//! [`chart`], the reports' SVG charts read back; [`cases`], case-file text several tests start from.

pub mod cases;
pub mod chart;

use cardan_mechanism::{CrankColumns, CrankState, Grid, MotionError, MotionSource};

/// A grid that cannot be split (it offers no [`MotionSource::part`]): its run takes one thread,
/// for the benchmarks that time a run per core.
pub struct OneThread(pub Grid);

impl MotionSource for OneThread {
    fn len(&self) -> usize {
        self.0.len()
    }

    fn next(&mut self, t: Option<f64>) -> Option<Result<CrankState, MotionError>> {
        self.0.next(t)
    }

    fn prescribed(&self) -> bool {
        true
    }

    fn next_block(&mut self, out: &mut CrankColumns) -> (usize, Option<MotionError>) {
        self.0.next_block(out)
    }
}

/// A grid's states handed out one at a time, as a solved motion hands them out (it offers no
/// blocks): the step loop takes blocks of one lane.
pub struct OneByOne(pub Grid);

impl MotionSource for OneByOne {
    fn len(&self) -> usize {
        self.0.len()
    }

    fn next(&mut self, previous: Option<f64>) -> Option<Result<CrankState, MotionError>> {
        self.0.next(previous)
    }
}

/// Asserts |got/want − 1| ≤ `rel`.
#[track_caller]
pub fn within(name: &str, got: f64, want: f64, rel: f64) {
    assert!(
        (got / want - 1.0).abs() <= rel,
        "{name}: got {got}, expected {want}, tolerance {}%",
        rel * 100.0
    );
}

/// Asserts |got − want| ≤ `abs`.
#[track_caller]
pub fn near(name: &str, got: f64, want: f64, abs: f64) {
    assert!(
        (got - want).abs() <= abs,
        "{name}: got {got}, expected {want}, tolerance ±{abs}"
    );
}

/// Asserts |got − want| ≤ `rel`·max(|want|, `floor`): relative, with a floor for values that
/// vanish.
#[track_caller]
pub fn close(name: &str, got: f64, want: f64, rel: f64, floor: f64) {
    let scale = want.abs().max(floor);
    assert!(
        (got - want).abs() <= rel * scale,
        "{name}: got {got}, expected {want}, tolerance {rel:e} of {scale}"
    );
}

/// Asserts that `message` (an error or a report) contains every one of `parts`.
#[track_caller]
pub fn mentions(message: &str, parts: &[&str]) {
    for p in parts {
        assert!(
            message.contains(p),
            "message {message:?} does not mention {p:?}"
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_checks_pass_and_fail_where_they_should() {
        within("a", 1.001, 1.0, 1.1e-3);
        near("b", 1.001, 1.0, 1.1e-3);
        close("c", 1e-9, 0.0, 1e-6, 1e-3);
        assert!(std::panic::catch_unwind(|| within("a", 1.01, 1.0, 1e-3)).is_err());
        assert!(std::panic::catch_unwind(|| near("b", 1.01, 1.0, 1e-3)).is_err());
        assert!(std::panic::catch_unwind(|| close("c", 1e-2, 0.0, 1e-6, 1e-3)).is_err());
        mentions(
            "gear.teeth: must be a whole number",
            &["gear.teeth", "whole"],
        );
        assert!(std::panic::catch_unwind(|| mentions("gear.teeth", &["hardness"])).is_err());
    }
}
