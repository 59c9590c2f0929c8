//! Orders of a planar vector over one crank revolution: forward and backward rotating
//! components.
//!
//! A planar vector V(θ) (a force, or a free moment, as the complex number x + i·y) sampled at
//! constant crank speed over one revolution is a Fourier series in the crank angle θ whose
//! terms pair up by order k ≥ 1 (k times per revolution):
//!
//! V(θ) = V₀ + Σ_k (A_k·e^{ikθ} + B_k·e^{−ikθ}),
//!
//! A_k rotating with the crank (forward), B_k against it (backward): the "direct and reverse
//! cranks" of the theory-of-machines texts, a reciprocating harmonic P·cos kφ along a fixed
//! axis being two half-size vectors turning at ±k·ω (`docs/validation/balance.md`). On N
//! equally spaced samples θ_j = θ₀ + 2πj/N the discrete transform gives them exactly for every
//! order below N/2 whose aliases (orders k ± N, …) are absent:
//! A_k = (1/N)·Σ_j V_j·e^{−ikθ_j}, B_k = (1/N)·Σ_j V_j·e^{ikθ_j}.
//!
//! The amplitude of order k is the largest magnitude its vector A_k·e^{ikθ} + B_k·e^{−ikθ}
//! takes over a revolution: the two turn towards each other and line up twice per turn of
//! their difference, so it is |A_k| + |B_k| (and the smallest, ||A_k| − |B_k||): issue 24's
//! order amplitude. A reciprocating harmonic has |A_k| = |B_k| (a line); a rotating one a single
//! component (a circle of constant magnitude).

use cardan_mechanism::{CrankState, C};
use std::f64::consts::TAU;

/// One order of a planar vector over a revolution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Order {
    /// k: times per crank revolution (0: the mean).
    pub order: usize,
    /// A_k, the component turning with the crank at k·ω, in the vector's unit (N, N·m); its
    /// argument is the component's direction at θ = 0.
    pub forward: C,
    /// B_k, the component turning against the crank at k·ω (0 for the mean).
    pub backward: C,
}

impl Order {
    /// The largest magnitude of this order's vector over a revolution, |A_k| + |B_k|.
    pub fn amplitude(&self) -> f64 {
        self.forward.norm() + self.backward.norm()
    }

    /// The smallest magnitude over a revolution, ||A_k| − |B_k||.
    pub fn least(&self) -> f64 {
        (self.forward.norm() - self.backward.norm()).abs()
    }

    /// This order's vector at crank angle `theta` (rad): A_k·e^{ikθ} + B_k·e^{−ikθ}.
    pub fn at(&self, theta: f64) -> C {
        let e = C::from_polar(1.0, self.order as f64 * theta);
        self.forward * e + self.backward * e.conj()
    }
}

/// The orders 0..=`max_order` of `samples`, taken at the crank angles `start + 2πj/N` (rad),
/// j = 0..N, N = `samples.len()`, at constant speed over one revolution.
///
/// # Panics
/// If N ≤ 2·`max_order` (the highest order asked for would alias with a lower one).
pub fn orders(samples: &[C], start: f64, max_order: usize) -> Vec<Order> {
    orders_on(samples, start, max_order, &factors(samples.len(), start))
}

/// The factors of [`orders_on`] for N = `n` samples from `start`: from θ₀ = 0 every order's
/// factors are among the N of e^{i·m·2π/N}, made once (the same arguments as the sum's,
/// m·step + k·0 = m·step, so the same bits); from another start none (each is made where
/// used).
pub fn factors(n: usize, start: f64) -> Vec<C> {
    let step = TAU / n as f64;
    match start == 0.0 {
        true => (0..n)
            .map(|m| C::from_polar(1.0, m as f64 * step))
            .collect(),
        false => Vec::new(),
    }
}

/// [`orders`] with the factors of [`factors`]`(samples.len(), start)` made beforehand (several
/// vectors sampled at the same angles share them).
pub fn orders_on(samples: &[C], start: f64, max_order: usize, table: &[C]) -> Vec<Order> {
    let [out] = orders_of(samples.iter().map(|&v| [v]), start, max_order, table);
    out
}

/// [`orders_on`] of `V` vectors sampled at the same angles (`samples`: each angle's `V`
/// samples, in the angles' order), in one pass over the samples per order: each vector's sums
/// take its samples in their order with the same operations as alone (the same bits), the
/// factor of each sample looked up once for all.
///
/// A sample v times e^{∓ikθ} shares its four products: v·ē = (v_re·e_re + v_im·e_im,
/// v_im·e_re − v_re·e_im) and v·e = (v_re·e_re − v_im·e_im, v_re·e_im + v_im·e_re), the
/// complex products of `num_complex` with ē's negated part (x − (−y) is x + y, and
/// (−x) + y is y − x, in IEEE 754: the same bits).
///
/// # Panics
/// If N ≤ 2·`max_order`.
pub(crate) fn orders_of<const V: usize>(
    samples: impl ExactSizeIterator<Item = [C; V]> + Clone,
    start: f64,
    max_order: usize,
    table: &[C],
) -> [Vec<Order>; V] {
    let n = samples.len();
    assert!(
        n > 2 * max_order,
        "{n} samples per revolution resolve orders below {}, not {max_order}",
        n.div_ceil(2)
    );
    let step = TAU / n as f64;
    let mut out: [Vec<Order>; V] = std::array::from_fn(|_| Vec::with_capacity(max_order + 1));
    for k in 0..=max_order {
        let zero = C::new(0.0, 0.0);
        let (mut forward, mut backward) = ([zero; V], [zero; V]);
        // m = (k·j) mod N, stepped by k (k < N/2) without a division per sample.
        let mut m = 0;
        for at_angle in samples.clone() {
            // e^{ikθ_j} from k·θ_j reduced to one turn: exact to an ulp of 2π.
            let e = match table.get(m) {
                Some(&e) => e,
                None => C::from_polar(1.0, m as f64 * step + k as f64 * start),
            };
            for x in 0..V {
                let v = at_angle[x];
                let (rr, ii) = (v.re * e.re, v.im * e.im);
                let (ri, ir) = (v.re * e.im, v.im * e.re);
                forward[x] += C::new(rr + ii, ir - ri);
                backward[x] += C::new(rr - ii, ri + ir);
            }
            m += k;
            if m >= n {
                m -= n;
            }
        }
        for ((o, f), b) in out.iter_mut().zip(forward).zip(backward) {
            let (forward, backward) = (f / n as f64, b / n as f64);
            o.push(match k {
                0 => Order {
                    order: 0,
                    forward,
                    backward: zero,
                },
                _ => Order {
                    order: k,
                    forward,
                    backward,
                },
            });
        }
    }
    out
}

/// The orders 0..=`max_order` of `n` samples that are all zeros (+0 or −0, as a free moment
/// about the plane of the only cylinder is): every component +0, the bits [`orders_on`] gives.
/// Each of its sums starts at +0 and adds products of a zero and a finite factor, which are
/// zeros, and +0 + (±0) is +0 when rounding to nearest (IEEE 754 §6.3); +0 / N is +0.
///
/// # Panics
/// If N ≤ 2·`max_order`, as [`orders_on`].
pub(crate) fn zero_orders(n: usize, max_order: usize) -> Vec<Order> {
    assert!(
        n > 2 * max_order,
        "{n} samples per revolution resolve orders below {}, not {max_order}",
        n.div_ceil(2)
    );
    let zero = C::new(0.0, 0.0);
    (0..=max_order)
        .map(|order| Order {
            order,
            forward: zero,
            backward: zero,
        })
        .collect()
}

/// `steps` crank states over one revolution from `start` (rad) at the constant speed `speed`
/// (rad/s): θ_j = start + 2πj/steps, the angles [`orders`] expects.
pub fn revolution(start: f64, speed: f64, steps: usize) -> Vec<CrankState> {
    revolution_states(start, speed, steps).collect()
}

/// The states of [`revolution`] one at a time (into a kept vector).
pub(crate) fn revolution_states(
    start: f64,
    speed: f64,
    steps: usize,
) -> impl ExactSizeIterator<Item = CrankState> {
    let step = TAU / steps as f64;
    (0..steps).map(move |j| {
        let angle = start + j as f64 * step;
        CrankState::new(angle, speed, 0.0, (angle - start) / speed)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A vector built from known components comes back apart, and its amplitude is the
    /// largest magnitude sampled.
    #[test]
    fn known_components_come_back() {
        let (a1, b1, a2, b2) = (
            C::new(3.0, 1.0),
            C::new(-0.5, 2.0),
            C::new(0.0, 0.7),
            C::new(1.1, 0.0),
        );
        let v = |t: f64| {
            C::new(0.25, -0.5)
                + a1 * C::from_polar(1.0, t)
                + b1 * C::from_polar(1.0, -t)
                + a2 * C::from_polar(1.0, 2.0 * t)
                + b2 * C::from_polar(1.0, -2.0 * t)
        };
        let start = 0.4;
        let samples: Vec<C> = (0..64).map(|j| v(start + TAU * j as f64 / 64.0)).collect();
        let o = orders(&samples, start, 4);
        let tol = 1e-13;
        assert!((o[0].forward - C::new(0.25, -0.5)).norm() < tol);
        assert!((o[1].forward - a1).norm() < tol && (o[1].backward - b1).norm() < tol);
        assert!((o[2].forward - a2).norm() < tol && (o[2].backward - b2).norm() < tol);
        assert!(o[3].amplitude() < tol && o[4].amplitude() < tol);
        let largest = (0..100_000)
            .map(|j| o[1].at(TAU * j as f64 / 100_000.0).norm())
            .fold(0.0, f64::max);
        assert!((largest - o[1].amplitude()).abs() < 1e-6 * o[1].amplitude());
    }

    /// The revolution's cos θ and sin θ are the transform's factors from θ₀ = 0 to the bit (the
    /// same angles j·2π/N), which the machine's orders take from its crank states.
    #[test]
    fn the_revolution_holds_the_factors() {
        for n in [7, 64, 120, 360, 960, 1001] {
            let table = factors(n, 0.0);
            let cranks = revolution(0.0, 123.4, n);
            for (j, (e, c)) in table.iter().zip(&cranks).enumerate() {
                let bits = |z: C| (z.re.to_bits(), z.im.to_bits());
                assert_eq!(bits(*e), bits(c.direction), "N = {n}, j = {j}");
            }
        }
    }

    /// Several vectors at once give the bits of each alone, from θ₀ = 0 (the factors' table)
    /// and from another start (factors made where used).
    #[test]
    fn vectors_taken_together_have_the_bits_of_each_alone() {
        let v = |j: usize, a: f64| C::new((a * j as f64).sin() * 7.0 + 0.3, (j as f64).cos() - a);
        let (x, y): (Vec<C>, Vec<C>) = (0..90).map(|j| (v(j, 0.7), v(j, -1.9))).unzip();
        for start in [0.0, 0.4] {
            let table = factors(x.len(), start);
            let pairs = x.iter().zip(&y).map(|(&x, &y)| [x, y]);
            let [a, b] = orders_of(pairs, start, 6, &table);
            assert_eq!(a, orders(&x, start, 6));
            assert_eq!(b, orders(&y, start, 6));
        }
    }

    /// Samples of +0 and −0 (a moment about the only cylinder's plane) have the orders of
    /// [`zero_orders`], every bit: the transform's sums stay +0.
    #[test]
    fn signed_zeros_have_orders_of_positive_zeros() {
        let z = [0.0, -0.0];
        let samples: Vec<C> = (0..120).map(|j| C::new(z[j % 2], z[j / 7 % 2])).collect();
        let bits = |o: &[Order]| -> Vec<(usize, [u64; 4])> {
            o.iter()
                .map(|o| {
                    let parts = [o.forward.re, o.forward.im, o.backward.re, o.backward.im];
                    (o.order, parts.map(f64::to_bits))
                })
                .collect()
        };
        assert!(samples.iter().any(|s| s.re.is_sign_negative()));
        assert_eq!(bits(&orders(&samples, 0.0, 6)), bits(&zero_orders(120, 6)));
    }

    #[test]
    #[should_panic(expected = "resolve orders below")]
    fn too_few_samples_are_refused() {
        orders(&[C::new(1.0, 0.0); 8], 0.0, 4);
    }
}
