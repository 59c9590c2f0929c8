//! The common logarithm log₁₀ x of many arguments at once, written, like [`crate::lane_power`],
//! so that a loop over a block's lanes vectorises with the same bits on every instruction set:
//! no branch, no table, plain IEEE `+ − × ÷` and bit operations, no fused multiply-add.
//!
//! The method: ln x as a double-double l_hi + l_lo by the lanes' logarithm of
//! [`crate::lane_power`] (x = 2^k m, ln m = 2 atanh s, A&S 4.1.27; its error below 2⁻⁵⁸),
//! times log₁₀e = e_hi + e_lo (e_hi the double nearest) as a double-double product (Dekker
//! 1971: l_hi e_hi exactly from 26-bit heads, plus l_hi e_lo + l_lo e_hi), rounded once. The
//! result is the correctly rounded log₁₀ x except within about 2⁻⁵⁸ of a midpoint between two
//! doubles. glibc's `log10` (fdlibm's `e_log10.c`, Sun Microsystems 1993: k log₁₀2 +
//! log₁₀e · ln m with ln m rounded first) is not correctly rounded everywhere (up to 2 ulp in
//! glibc's own tables), so the two can differ by one ulp where it is not.
//!
//! Measured against `f64::log10` (`lane_log10::tests`): over 10⁶ arguments log-uniform over
//! [10⁻³⁰⁰, 10³⁰⁰] and the edges at most 1 ulp apart, on average 0.0023 ulp (0.23 % of the
//! arguments one ulp apart, the rest with its bits); within 2⁻²⁰ of 1, where glibc rounds ln x
//! before the product (up to about 1.5 ulp off), up to 2 ulp apart, the lanes then the nearer
//! the exact value.
//!
//! Where the method does not hold (x ≤ 0, subnormal, infinite or NaN) the lane takes
//! `f64::log10`: the vector loop marks it NaN and a second, scalar pass computes it. Every
//! argument therefore has a correct answer.

use crate::lane_power::ln_double;

/// log₁₀e as the double nearest (`std::f64::consts::LOG10_E`) and the rest, 1.098e-17.
const LOG10_E_HI: f64 = std::f64::consts::LOG10_E;
const LOG10_E_LO: f64 = f64::from_bits(0x3C69_5355_BAAA_FAD3);
/// Clears the low 27 bits of the significand: 26 significant bits left, so that the product
/// of two such numbers is exact (Dekker 1971).
const HEAD_26: u64 = 0xFFFF_FFFF_F800_0000;

#[inline(always)]
fn head(v: f64) -> f64 {
    f64::from_bits(v.to_bits() & HEAD_26)
}

/// log₁₀ x by the method of the module doc, or NaN where it does not hold (then
/// `f64::log10`'s answer is wanted; no argument it holds for gives NaN).
#[inline(always)]
fn log10_or_nan(x: f64) -> f64 {
    let (l_hi, l_lo) = ln_double(x);
    // l_hi e_hi = p + p_err exactly (Dekker's product of the 26-bit heads and tails).
    let (lh, eh) = (head(l_hi), head(LOG10_E_HI));
    let (lt, et) = (l_hi - lh, LOG10_E_HI - eh);
    let p = l_hi * LOG10_E_HI;
    let p_err = (((lh * eh - p) + lh * et) + lt * eh) + lt * et;
    let log = p + (p_err + (l_hi * LOG10_E_LO + l_lo * LOG10_E_HI));
    if (f64::MIN_POSITIVE..f64::INFINITY).contains(&x) {
        log
    } else {
        f64::NAN
    }
}

/// `out[i] = log₁₀ x[i]` (within one ulp of `f64::log10`, see the module doc) for the lanes of
/// `x` and `out` (the shorter's length). Inlined into its caller so that a caller compiled for
/// AVX2 (a `vectorised!` block kernel) vectorises it for AVX2.
#[inline(always)]
pub fn log10_lanes(x: &[f64], out: &mut [f64]) {
    let mut any_nan = false;
    for (o, &x) in out.iter_mut().zip(x) {
        let v = log10_or_nan(x);
        any_nan |= v.is_nan();
        *o = v;
    }
    if any_nan {
        for (o, &x) in out.iter_mut().zip(x) {
            if o.is_nan() {
                *o = x.log10();
            }
        }
    }
}

/// One lane of [`log10_lanes`]: the same bits.
#[inline]
pub fn log10_lane(x: f64) -> f64 {
    let v = log10_or_nan(x);
    if v.is_nan() {
        x.log10()
    } else {
        v
    }
}

#[cfg(test)]
mod tests;
