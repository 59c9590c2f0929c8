//! A power x^y of many arguments at once, written so that a loop over a block's lanes
//! vectorises: no branch and no table, plain IEEE `+ − × ÷` and bit operations, no fused
//! multiply-add. The same arithmetic therefore gives the same bits whether the loop is compiled
//! for AVX2 or the baseline SSE2 (the project's block kernels are compiled both ways).
//!
//! The method is the textbook one (J.-M. Muller, *Elementary Functions: Algorithms and
//! Implementation*, 3rd ed. 2016, on range reduction and double-word arithmetic; T. J.
//! Dekker, "A floating-point technique for extending the available precision", Numer. Math.
//! 18, 1971, for the exact product of two numbers of at most 26 significant bits and the exact
//! sum of two numbers ordered by size):
//!
//! 1. x = 2^k m with m in [√½, √2) from the bits of x.
//! 2. ln m = 2 atanh s, s = (m − 1)/(m + 1), |s| ≤ 0.1716 (Abramowitz & Stegun, *Handbook of
//!    Mathematical Functions*, 1964, 4.1.27), with s as a pair s_h + s_l (s_h of 21
//!    significant bits, so that s_h (m + 1) is exact), and the series' tail past 2s as a
//!    polynomial of degree 7 in s² (error below 2⁻⁶²).
//! 3. ln x = k ln 2 + ln m as a double-double, ln 2 = ln2_hi + ln2_lo (ln2_hi of 42 bits, so
//!    k ln2_hi is exact).
//! 4. t = y ln x as a double-double, from y and ln x cut into 26-bit heads (exact products).
//! 5. e^t = 2^n e^r, n = round(t / ln 2), r = t − n ln 2 (|r| ≤ 0.347, the head exact), and
//!    e^r = 1 + r + r²/2 + r³ P(r) (A&S 4.2.1), P a polynomial of degree 9 (error below
//!    2⁻⁶⁰), summed as a double-double; one rounding at the end.
//!
//! The two polynomials are Chebyshev interpolants of the series' tails (near-minimax: fewer
//! terms than the truncated series for the same error), fitted by
//! `crates/numeric/tools/fit_lane_power.py`.
//!
//! The error before the final rounding is below about 2⁻⁵⁸ of the result (the rounding of the
//! two series' cubic terms dominates), so the result is the correctly rounded x^y except where
//! x^y lies within that of the midpoint between two doubles, and never more than one ulp from
//! `f64::powf` (which is itself within about 0.52 ulp of the exact value).
//!
//! Measured against `f64::powf` (`lane_power::tests::within_one_ulp_of_powf`, 10⁶ arguments
//! log-uniform over [10⁻⁶, 10⁹] per exponent plus the edges, for each of the bearing models'
//! exponents 1.55, 0.54, 5/3, 0.55, 0.5, 0.6, 1.28, 0.64, 1.4, 2/3 and −0.26): at most 1 ulp
//! apart, on average 0.0019 (y = −0.26) to 0.0033 (y = 5/3) ulp: 0.2 to 0.3 % of the
//! arguments differ from `powf` by one ulp, the rest have its bits.
//!
//! Cost (callgrind, a loop of 64 lanes at y = 1.55 compiled for AVX2 / the baseline SSE2):
//! about 40 / 86 instructions a value, against about 130 for a call of `powf` (glibc).
//!
//! Where the method does not hold (x ≤ 0, subnormal, infinite or NaN; y not finite; a result
//! that could overflow or be subnormal, |y ln x| ≥ 700) the lane takes `f64::powf`: the vector
//! loop marks it NaN and a second, scalar pass computes it. Every argument therefore has a
//! correct answer.

/// Clears the low 27 bits of the significand: 26 significant bits left, so that the product
/// of two such numbers is exact (Dekker 1971; a mask in place of Veltkamp's split).
const HEAD_26: u64 = 0xFFFF_FFFF_F800_0000;
/// Clears the low 32 bits of the significand: 21 significant bits left.
const HEAD_21: u64 = 0xFFFF_FFFF_0000_0000;
/// ln 2 to 42 significant bits (so that n ln2_hi is exact for |n| < 2¹¹) and the rest.
const LN2_HI: f64 = 0.693_147_180_559_890_3;
const LN2_LO: f64 = 5.497_923_018_708_371e-14;
const INV_LN2: f64 = std::f64::consts::LOG2_E;
/// 1.5 · 2⁵²: adding it rounds a number of magnitude below 2⁵¹ to an integer (ties to even).
const ROUND: f64 = 6_755_399_441_055_744.0;
/// The significand bits of √2: a significand at or above them takes the next exponent, so
/// that m lands in [√½, √2).
const SQRT2_SIGNIFICAND: u64 = 0x0006_a09e_667f_3bcd;
/// 2⁵² as a bit pattern's exponent field: `from_bits(TWO52_BITS | e) − 2⁵²` is the integer e.
const TWO52_BITS: u64 = 0x4330_0000_0000_0000;
const TWO52: f64 = 4_503_599_627_370_496.0;
/// |y ln x| below this: e^t is a normal number far from overflow (e^±700 ≈ 10^±304).
const T_LIMIT: f64 = 700.0;

/// Q(u) of 2 atanh s = 2s + s³ Q(s²), Q(u) = 2/3 + 2u/5 + 2u²/7 + … (A&S 4.1.27), as a
/// Chebyshev interpolant of degree 7 on u ∈ [0, 0.02944] (near-minimax; fitted by
/// `crates/numeric/tools/fit_lane_power.py`): s³ times its error is below 1.9e-19 (2⁻⁶²).
const LOG_TAIL: [f64; 8] = [
    0.666_666_666_666_666_6,
    0.400_000_000_000_008_8,
    0.285_714_285_708_036,
    0.222_222_223_917_153_43,
    0.181_817_956_399_806_3,
    0.153_862_397_110_971_55,
    0.132_687_729_168_442_26,
    0.130_866_284_675_365_49,
];

/// P(r) of e^r = 1 + r + r²/2 + r³ P(r), P(r) = 1/3! + r/4! + … (A&S 4.2.1), as a Chebyshev
/// interpolant of degree 9 on r ∈ [−0.34658, 0.34658] (fitted by the same script): r³ times
/// its error is below 7e-19 (2⁻⁶⁰).
const EXP_TAIL: [f64; 10] = [
    0.166_666_666_666_666_69,
    0.041_666_666_666_666_664,
    0.008_333_333_333_330_063,
    0.001_388_888_888_888_655_4,
    0.000_198_412_698_630_429_63,
    2.480_158_731_713_689_2e-5,
    2.755_726_847_655_369_5e-6,
    2.755_728_298_137_34e-7,
    2.510_037_761_960_637_2e-8,
    2.091_123_100_592_285e-9,
];

#[inline(always)]
fn head(v: f64, mask: u64) -> f64 {
    f64::from_bits(v.to_bits() & mask)
}

/// Horner's rule over `c` (constant first) at `u`.
#[inline(always)]
fn horner<const N: usize>(c: &[f64; N], u: f64) -> f64 {
    let mut acc = c[N - 1];
    for j in (0..N - 1).rev() {
        acc = acc * u + c[j];
    }
    acc
}

/// An exponent y prepared for [`Exponent::pow_or_nan`]: y and its 26-bit head and tail.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Exponent {
    y: f64,
    head: f64,
    tail: f64,
}

impl Exponent {
    /// The exponent `y` (any value; a non-finite one sends every lane to `powf`).
    #[inline(always)]
    pub fn new(y: f64) -> Self {
        let h = head(y, HEAD_26);
        Self {
            y,
            head: h,
            tail: y - h,
        }
    }

    /// x^y by the method of the module doc, or NaN where it does not hold (then `powf`'s
    /// answer is wanted; no argument it holds for gives NaN).
    #[inline(always)]
    pub fn pow_or_nan(&self, x: f64) -> f64 {
        let (l_hi, l_lo) = ln_double(x);
        // t = y ln x: the heads' product is exact; the rest is 2⁻²⁶ of it.
        let lh = head(l_hi, HEAD_26);
        let ll = (l_hi - lh) + l_lo;
        let p = self.head * lh;
        let q = self.tail * lh + self.y * ll;
        let t_hi = p + q;
        let t_lo = q - (t_hi - p);
        let power = exp_double(t_hi, t_lo);
        let ok = (f64::MIN_POSITIVE..f64::INFINITY).contains(&x) && t_hi.abs() < T_LIMIT;
        if ok {
            power
        } else {
            f64::NAN
        }
    }
}

/// ln x as a double-double (head, tail) for a positive normal x (garbage otherwise, caught by
/// the caller's range test).
#[inline(always)]
pub(crate) fn ln_double(x: f64) -> (f64, f64) {
    let ix = x.to_bits();
    // The exponent field, one more where the significand is at or above √2's.
    let field = ix.wrapping_sub(SQRT2_SIGNIFICAND) >> 52;
    let m = f64::from_bits(ix.wrapping_sub(field << 52).wrapping_add(1022 << 52));
    let k = f64::from_bits(TWO52_BITS | field) - (TWO52 + 1022.0);
    // s = f/u, f = m − 1 (exact, Sterbenz), u = 2 + f as u + u_err.
    let f = m - 1.0;
    let u = 2.0 + f;
    let u_err = f - (u - 2.0);
    let s = f / u;
    let s_h = head(s, HEAD_21);
    let u_h = head(u, HEAD_21);
    let u_l = (u - u_h) + u_err;
    let s_l = ((f - s_h * u_h) - s_h * u_l) / u;
    let s2 = s * s;
    let tail = s * s2 * horner(&LOG_TAIL, s2);
    // k ln2_hi + 2 s_h, the larger first (k = 0 gives 2 s_h exactly).
    let a = k * LN2_HI;
    let b = 2.0 * s_h;
    let l_hi = a + b;
    let l_err = b - (l_hi - a);
    let l_lo = k * LN2_LO + (l_err + (2.0 * s_l + tail));
    (l_hi, l_lo)
}

/// e^(t_hi + t_lo) for |t_hi| < 700, |t_lo| ≤ ulp(t_hi)/2.
#[inline(always)]
fn exp_double(t_hi: f64, t_lo: f64) -> f64 {
    let shifted = t_hi * INV_LN2 + ROUND;
    let n = shifted - ROUND;
    // 2ⁿ from the integer in the low bits of `shifted`.
    let scale = f64::from_bits(
        (shifted.to_bits().wrapping_sub(ROUND.to_bits()))
            .wrapping_add(1023)
            .wrapping_shl(52),
    );
    let r = t_hi - n * LN2_HI; // exact: see the module doc
    let r_lo = t_lo - n * LN2_LO;
    let r_h = head(r, HEAD_26);
    let r_t = r - r_h;
    let s1 = 1.0 + r;
    let e1 = r - (s1 - 1.0);
    let half_sq = 0.5 * (r_h * r_h);
    let s2 = s1 + half_sq;
    let e2 = half_sq - (s2 - s1);
    let r2 = r * r;
    let cubic = r2 * r * horner(&EXP_TAIL, r);
    let low = (e1 + e2) + (0.5 * (r_t * (r + r_h)) + cubic);
    // e^(r + r_lo) = e^r + e^r r_lo: r_lo (up to n ln2_lo, 6e-11) wants e^r, not 1 + r + r²/2.
    let low = low + (s2 + low) * r_lo;
    (s2 + low) * scale
}

/// `out[i] = x[i]^y` (to within one ulp of `f64::powf`, see the module doc) for the lanes of
/// `x` and `out` (the shorter's length). Inlined into its caller so that a caller compiled for
/// AVX2 (a `vectorised!` block kernel) vectorises it for AVX2.
#[inline(always)]
pub fn powf_lanes(x: &[f64], y: f64, out: &mut [f64]) {
    let e = Exponent::new(y);
    let mut any_nan = false;
    for (o, &x) in out.iter_mut().zip(x) {
        let v = e.pow_or_nan(x);
        any_nan |= v.is_nan();
        *o = v;
    }
    if any_nan {
        for (o, &x) in out.iter_mut().zip(x) {
            if o.is_nan() {
                *o = x.powf(y);
            }
        }
    }
}

/// One lane of [`powf_lanes`]: the same bits.
#[inline]
pub fn powf_lane(x: f64, y: f64) -> f64 {
    let v = Exponent::new(y).pow_or_nan(x);
    if v.is_nan() {
        x.powf(y)
    } else {
        v
    }
}

#[cfg(test)]
mod tests;
