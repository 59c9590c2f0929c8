//! The starts: a Latin hypercube in the unit cube (McKay, Beckman & Conover 1979,
//! Technometrics 21(2), 239-245: each variable's range cut into as many equal strata as there
//! are starts, each stratum holding one start, the strata's order a random permutation per
//! variable and the point uniform within its stratum), drawn from SplitMix64 (Steele, Lea &
//! Flood 2014, "Fast splittable pseudorandom number generators", OOPSLA, the `mix64` finaliser
//! with Weyl increment 0x9e3779b97f4a7c15): the same seed gives the same starts on every
//! machine and thread count.

/// SplitMix64: a 64-bit state advanced by a Weyl increment and mixed (Steele et al. 2014).
pub struct SplitMix64(u64);

impl SplitMix64 {
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A uniform number in [0, 1): the top 53 bits over 2⁵³.
    pub fn next_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A uniform integer in 0..n (n ≥ 1), by rejection so that no value is favoured.
    pub fn below(&mut self, n: usize) -> usize {
        let n = n as u64;
        let zone = u64::MAX - u64::MAX % n;
        loop {
            let r = self.next_u64();
            if r < zone {
                return (r % n) as usize;
            }
        }
    }
}

/// `count` points of a Latin hypercube in [0, 1]^`dimension` from `seed`.
pub fn latin_hypercube(count: usize, dimension: usize, seed: u64) -> Vec<Vec<f64>> {
    let mut rng = SplitMix64::new(seed);
    let mut points = vec![vec![0.0; dimension]; count];
    for d in 0..dimension {
        // Fisher-Yates (Knuth, TAOCP vol. 2, §3.4.2, Algorithm P).
        let mut strata: Vec<usize> = (0..count).collect();
        for i in (1..count).rev() {
            strata.swap(i, rng.below(i + 1));
        }
        for (point, stratum) in points.iter_mut().zip(strata) {
            point[d] = (stratum as f64 + rng.next_f64()) / count as f64;
        }
    }
    points
}

#[cfg(test)]
mod tests {
    use super::latin_hypercube;

    #[test]
    fn each_stratum_of_each_variable_holds_one_start() {
        let points = latin_hypercube(7, 3, 42);
        for d in 0..3 {
            let mut strata: Vec<usize> = points.iter().map(|p| (p[d] * 7.0) as usize).collect();
            strata.sort();
            assert_eq!(strata, (0..7).collect::<Vec<_>>());
        }
        assert_eq!(points, latin_hypercube(7, 3, 42));
        assert_ne!(points, latin_hypercube(7, 3, 43));
    }
}
