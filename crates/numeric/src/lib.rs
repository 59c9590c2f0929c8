//! Numeric helpers shared by the physics crates that depend on nothing of each other (the
//! friction models of `cardan-friction`, the gear physics of `cardan-gears`). Its own crate, at
//! the bottom, depending on nothing: neither physics crate is the other's natural home. Also
//! the block kernels' power, common logarithm and hypot over a block's lanes ([`lane_power`],
//! [`lane_log10`], [`lane_hypot`]),
//! written to vectorise with the same bits on every instruction set.

pub mod lane_hypot;
pub mod lane_log10;
pub mod lane_power;
#[cfg(test)]
mod split_mix;

pub use lane_hypot::hypot_lanes;
pub use lane_log10::{log10_lane, log10_lanes};
pub use lane_power::{powf_lane, powf_lanes};

/// The bits of a signalling NaN: no arithmetic result has them (a NaN that an operation
/// produces is quiet), so no argument a model computes matches the "nothing kept" state.
const NOTHING_KEPT: f64 = f64::from_bits(0x7FF0_0000_0000_0001);

/// A power x^e of one exponent kept with its argument x, so that a model evaluated step by
/// step with an argument that does not change (a joint's speed at a constant crank speed)
/// takes it once. A power is taken again whenever the argument's bits change, so the result
/// is always `x.powf(e)`'s bits: the memo changes speed, never a result.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KeptPower {
    argument: f64,
    power: f64,
}

impl Default for KeptPower {
    /// Nothing kept: the first call takes its power.
    fn default() -> Self {
        Self {
            argument: NOTHING_KEPT,
            power: f64::NAN,
        }
    }
}

impl KeptPower {
    /// `x.powf(e)`, `e` being the same at every call of this memo (it keeps the power, not
    /// the exponent).
    #[inline]
    pub fn pow(&mut self, x: f64, e: f64) -> f64 {
        if self.argument.to_bits() != x.to_bits() {
            (self.argument, self.power) = (x, x.powf(e));
        }
        self.power
    }

    /// [`powf_lane`]`(x, e)` (the bits of a lane of [`powf_lanes`]), kept as
    /// [`KeptPower::pow`] keeps `powf`'s: a memo takes one of the two, never both.
    #[inline]
    pub fn pow_lane(&mut self, x: f64, e: f64) -> f64 {
        if self.argument.to_bits() != x.to_bits() {
            (self.argument, self.power) = (x, powf_lane(x, e));
        }
        self.power
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The kept power has `powf`'s bits whether the argument stays, changes or comes back,
    /// for ordinary arguments and the edges of `powf` (zero of either sign, a subnormal, an
    /// infinity, a NaN, a negative base), including the exponent 0 (x^0 = 1 even for a NaN x).
    #[test]
    fn a_kept_power_has_the_bits_of_powf() {
        let arguments = [
            2000.0,
            2000.0,
            2000.0 + f64::EPSILON * 2000.0,
            2000.0,
            0.0,
            -0.0,
            f64::MIN_POSITIVE / 4.0,
            f64::INFINITY,
            f64::NAN,
            f64::NAN,
            -3.5,
            1.0,
            2000.0,
        ];
        for e in [2.0 / 3.0, 0.67, 2.8, -0.26, 0.0, 1.0] {
            let mut kept = KeptPower::default();
            for x in arguments {
                assert_eq!(kept.pow(x, e).to_bits(), x.powf(e).to_bits(), "{x}^{e}");
            }
            let mut kept = KeptPower::default();
            for x in arguments {
                let want = powf_lane(x, e);
                let got = kept.pow_lane(x, e);
                assert!(got.to_bits() == want.to_bits() || (got.is_nan() && want.is_nan()));
            }
        }
    }

    /// A fresh memo keeps nothing: its first call takes the power, even for an argument whose
    /// bits are those of `f64::NAN` (a quiet NaN, which arithmetic can produce).
    #[test]
    fn a_fresh_memo_takes_its_first_power() {
        assert_eq!(KeptPower::default().pow(f64::NAN, 0.0), 1.0);
        assert_eq!(KeptPower::default().pow(0.0, 2.0), 0.0);
    }
}
