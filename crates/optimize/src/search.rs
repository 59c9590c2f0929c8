//! One start's search in the unit cube: Nelder-Mead (Lagarias, Reeds, Wright & Wright 1998,
//! "Convergence properties of the Nelder-Mead simplex method in low dimensions", SIAM J.
//! Optim. 9(1), 112-147, §2: reflection ρ = 1, expansion χ = 2, contraction γ = ½, shrink
//! σ = ½) with every trial point projected onto the bounds, then a compass search from its
//! best point (Kolda, Lewis & Torczon 2003, "Optimization by direct search", SIAM Review
//! 45(3), 385-482, §3.1 and Algorithm 3.2: the 2n coordinate directions, the step halved
//! after a poll without improvement, stopped when the step is below the tolerance). The
//! simplex finds the basin quickly; the compass search ends only where no step of the final
//! size along any variable improves, which the simplex alone does not guarantee (its
//! simplex may collapse against a bound or a constraint, Lagarias et al. §1).
//! Values are compared by Deb's rules ([`crate::order`]).

use crate::order::Outcome;
use crate::settings::{Record, Settings, Stop};
use std::collections::HashMap;

/// The evaluations of one start: its history, a cache of points already evaluated (the compass
/// search returns to points), and its budget.
pub(crate) struct Tracker<'f> {
    f: &'f (dyn Fn(&[f64]) -> Outcome + Sync),
    start: usize,
    budget: usize,
    pub records: Vec<Record>,
    cache: HashMap<Vec<u64>, usize>,
}

impl<'f> Tracker<'f> {
    pub fn new(f: &'f (dyn Fn(&[f64]) -> Outcome + Sync), start: usize, budget: usize) -> Self {
        Self {
            f,
            start,
            budget,
            records: Vec::new(),
            cache: HashMap::new(),
        }
    }

    /// The outcome at `x` (projected onto the unit cube), evaluated once; `None` once the
    /// budget is spent.
    pub fn eval(&mut self, x: &[f64], phase: &'static str) -> Option<Outcome> {
        let x: Vec<f64> = x.iter().map(|v| v.clamp(0.0, 1.0)).collect();
        let key: Vec<u64> = x.iter().map(|v| v.to_bits()).collect();
        if let Some(&k) = self.cache.get(&key) {
            return Some(self.records[k].outcome.clone());
        }
        if self.records.len() >= self.budget {
            return None;
        }
        let outcome = (self.f)(&x);
        self.cache.insert(key, self.records.len());
        self.records.push(Record {
            start: self.start,
            evaluation: self.records.len(),
            x,
            outcome: outcome.clone(),
            phase,
        });
        Some(outcome)
    }
}

type Vertex = (Vec<f64>, Outcome);

/// Restarts of the simplex from its best point, at most.
const RESTARTS: usize = 4;

fn sort(simplex: &mut [Vertex]) {
    // Stable: of equal vertices the older stays first (Lagarias et al.'s tie rule).
    simplex.sort_by(|a, b| a.1.compare(&b.1));
}

/// The largest distance (∞-norm) of a vertex from the best.
fn size(simplex: &[Vertex]) -> f64 {
    let best = &simplex[0].0;
    simplex
        .iter()
        .flat_map(|(x, _)| x.iter().zip(best).map(|(a, b)| (a - b).abs()))
        .fold(0.0, f64::max)
}

fn along(from: &[f64], to: &[f64], t: f64) -> Vec<f64> {
    from.iter()
        .zip(to)
        .map(|(a, b)| (a + t * (b - a)).clamp(0.0, 1.0))
        .collect()
}

/// The Nelder-Mead search from `x0` (module docs); `None`: the budget ran out. The initial
/// simplex: `x0` and a step of `settings.initial_step` along each variable (inwards at a bound).
fn nelder_mead(t: &mut Tracker, x0: &[f64], settings: &Settings) -> Option<Vertex> {
    let n = x0.len();
    let mut simplex: Vec<Vertex> = vec![(x0.to_vec(), t.eval(x0, "simplex")?)];
    for i in 0..n {
        let mut x = x0.to_vec();
        let h = settings.initial_step;
        x[i] = if x[i] + h <= 1.0 { x[i] + h } else { x[i] - h };
        let o = t.eval(&x, "simplex")?;
        simplex.push((x, o));
    }
    loop {
        sort(&mut simplex);
        if size(&simplex) <= settings.simplex_tolerance {
            return Some(simplex.swap_remove(0));
        }
        let worst = simplex[n].clone();
        let mut centroid = vec![0.0; n];
        for (x, _) in &simplex[..n] {
            for (c, v) in centroid.iter_mut().zip(x) {
                *c += v / n as f64;
            }
        }
        // x̄ + ρ(x̄ − x_worst), ρ = 1.
        let xr = along(&centroid, &worst.0, -1.0);
        let fr = t.eval(&xr, "simplex")?;
        let replacement = if fr.better_than(&simplex[0].1) {
            // Expansion, χ = 2: x̄ + χ(x̄ − x_worst).
            let xe = along(&centroid, &worst.0, -2.0);
            let fe = t.eval(&xe, "simplex")?;
            Some(if fe.better_than(&fr) {
                (xe, fe)
            } else {
                (xr, fr)
            })
        } else if fr.better_than(&simplex[n - 1].1) {
            Some((xr, fr))
        } else if fr.better_than(&worst.1) {
            // Outside contraction, γ = ½: x̄ + γ(x_r − x̄).
            let xc = along(&centroid, &xr, 0.5);
            let fc = t.eval(&xc, "simplex")?;
            (!fr.better_than(&fc)).then_some((xc, fc))
        } else {
            // Inside contraction: x̄ − γ(x̄ − x_worst).
            let xc = along(&centroid, &worst.0, 0.5);
            let fc = t.eval(&xc, "simplex")?;
            fc.better_than(&worst.1).then_some((xc, fc))
        };
        match replacement {
            Some(v) => simplex[n] = v,
            None => {
                // Shrink towards the best, σ = ½.
                let best = simplex[0].0.clone();
                for vertex in simplex.iter_mut().skip(1) {
                    let x = along(&best, &vertex.0, 0.5);
                    let o = t.eval(&x, "simplex")?;
                    *vertex = (x, o);
                }
            }
        }
    }
}

/// The compass search from `best` (module docs): polls x ± Δ·e_i, takes the first
/// improvement, halves Δ after a poll without one; ends when Δ < `settings.tolerance`.
fn compass(t: &mut Tracker, mut best: Vertex, settings: &Settings) -> (Vertex, Stop) {
    let mut step = settings.compass_step;
    while step >= settings.tolerance {
        let mut improved = false;
        'poll: for i in 0..best.0.len() {
            for sign in [1.0, -1.0] {
                let mut x = best.0.clone();
                x[i] = (x[i] + sign * step).clamp(0.0, 1.0);
                if x[i] == best.0[i] {
                    continue;
                }
                let Some(o) = t.eval(&x, "compass") else {
                    return (best, Stop::Budget);
                };
                if o.better_than(&best.1) {
                    best = (x, o);
                    improved = true;
                    break 'poll;
                }
            }
        }
        if !improved {
            step /= 2.0;
        }
    }
    (best, Stop::Converged { step })
}

/// One start from `x0`: the simplex, then the compass search from its best point; the best
/// point found and why the search stopped.
pub(crate) fn run_start(t: &mut Tracker, x0: &[f64], settings: &Settings) -> Stop {
    let Some(mut best) = nelder_mead(t, x0, settings) else {
        return Stop::Budget;
    };
    // Restarted from its best point with a fresh simplex while that improves it (at most
    // RESTARTS times): a simplex flattened against a bound, or degenerate in a narrow valley,
    // stops before the optimum (Kelley 1999, "Detection and remediation of stagnation in the
    // Nelder-Mead algorithm", SIAM J. Optim. 10(1), 43-55: restart with a new simplex).
    for _ in 0..RESTARTS {
        let Some(again) = nelder_mead(t, &best.0, settings) else {
            return Stop::Budget;
        };
        let improved = again.1.better_than(&best.1);
        best = again;
        if !improved {
            break;
        }
    }
    compass(t, best, settings).1
}
