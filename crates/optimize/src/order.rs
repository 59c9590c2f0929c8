//! What an evaluation gives and how two are compared: the objective (minimised), each
//! constraint's margin (≥ 0 where it holds), or a failure; compared by Deb's feasibility rules
//! (Deb 2000, "An efficient constraint handling method for genetic algorithms", Comput.
//! Methods Appl. Mech. Engrg. 186, 311-338, §3): a feasible point beats an infeasible one, two
//! feasible points are compared by their objective, two infeasible ones by their total
//! violation. No penalty weight is chosen: the rules need only comparisons, which is all the
//! Nelder-Mead and compass searches do with values.

use std::cmp::Ordering;

/// What one evaluation of the problem gave.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// The objective (to be minimised) and each constraint's margin, scaled by the caller so
    /// that the margins are commensurate (a margin ≥ 0: the constraint holds).
    Value { objective: f64, margins: Vec<f64> },
    /// The evaluation failed (the model refused the point, or a number was not finite): the
    /// reason, kept for the report. A failed point ranks below every other.
    Failed(String),
}

impl Outcome {
    /// The sum of the constraints' violations, Σ max(0, −margin); infinite for a failure or a
    /// margin that is not a number.
    pub fn violation(&self) -> f64 {
        match self {
            Outcome::Value { margins, .. } => margins
                .iter()
                .map(|&m| {
                    if m.is_nan() {
                        f64::INFINITY
                    } else {
                        (-m).max(0.0)
                    }
                })
                .sum(),
            Outcome::Failed(_) => f64::INFINITY,
        }
    }

    /// Whether every constraint holds (and the evaluation did not fail).
    pub fn feasible(&self) -> bool {
        self.violation() == 0.0
            && matches!(self, Outcome::Value { objective, .. } if objective.is_finite())
    }

    /// The objective, if the evaluation did not fail.
    pub fn objective(&self) -> Option<f64> {
        match self {
            Outcome::Value { objective, .. } => Some(*objective),
            Outcome::Failed(_) => None,
        }
    }

    /// Deb's order (module docs): `Less` when `self` is the better point.
    pub fn compare(&self, other: &Outcome) -> Ordering {
        let key = |o: &Outcome| -> (u8, f64) {
            match o {
                Outcome::Failed(_) => (3, 0.0),
                Outcome::Value { objective, .. } if !objective.is_finite() => (2, 0.0),
                _ if o.feasible() => (0, o.objective().unwrap_or(f64::INFINITY)),
                _ => (1, o.violation()),
            }
        };
        let (a, b) = (key(self), key(other));
        a.0.cmp(&b.0).then(a.1.total_cmp(&b.1))
    }

    /// Whether `self` is strictly better than `other` by Deb's order.
    pub fn better_than(&self, other: &Outcome) -> bool {
        self.compare(other) == Ordering::Less
    }
}

#[cfg(test)]
mod tests {
    use super::Outcome;

    fn v(objective: f64, margins: &[f64]) -> Outcome {
        Outcome::Value {
            objective,
            margins: margins.to_vec(),
        }
    }

    #[test]
    fn feasible_beats_infeasible_beats_failed() {
        assert!(v(10.0, &[0.0]).better_than(&v(-10.0, &[-0.1])));
        assert!(v(10.0, &[-0.1]).better_than(&v(-10.0, &[-0.2, 0.5])));
        assert!(v(1e9, &[-1e9]).better_than(&Outcome::Failed("x".into())));
        assert!(v(1.0, &[]).better_than(&v(2.0, &[])));
        assert!(!v(2.0, &[]).better_than(&v(2.0, &[])));
        assert!(v(0.0, &[f64::NAN]).violation().is_infinite());
    }
}
