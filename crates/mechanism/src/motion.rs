//! Crank motion: the prescribed law, the crank-angle grid, and the source a run steps through.

use crate::{vectorised, CrankColumns, CrankState, C, LANES};

/// Grid points between exact evaluations of e^{iθ}: in between, e^{iθ} advances by complex
/// multiplications by e^{i·CHAINS·h}, along [`CHAINS`] interleaved chains that start from the
/// exact value at the block's start times e^{i·j·h}, j < [`CHAINS`]. Each multiplication adds
/// at most about 4 ulp of error, so the direction stays within
/// (`REANCHOR`/`CHAINS` + 1)·4·ε ≈ 1.5e-14 of the exact one (tested).
pub const REANCHOR: usize = 64;

/// Independent chains of rotations in a block of [`REANCHOR`] grid points: the processor works
/// on them side by side instead of waiting on each multiplication for the one before (one
/// chain was a fifth of a run).
pub const CHAINS: usize = 4;

/// Crank motion with constant angular acceleration, Karhula (2008) eq. (A4.2.2.1):
/// θ(t) = θ0 + ω0·t + ½·α·t².
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CrankMotion {
    /// Crank angle at t = 0, rad.
    pub start_angle: f64,
    /// Crank angular velocity at t = 0, rad/s.
    pub initial_speed: f64,
    /// Constant crank angular acceleration, rad/s².
    pub angular_acceleration: f64,
}

/// Why a motion cannot reach a crank angle.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MotionError {
    #[error("the crank must turn forwards: initial_speed {0} rad/s is negative")]
    Backwards(f64),
    #[error("the crank never turns: initial_speed and angular_acceleration are both 0")]
    Still,
    /// A solved motion (the machine equation) cannot go on: why, with the step and angle.
    #[error("{0}")]
    Solved(String),
    #[error(
        "the crank stops at {stop_deg:.3}° before the end angle {angle_deg:.3}°: \
         ω² = ω0² + 2·α·Δθ would be {omega2:.3e} rad²/s² there, below 0 by more than round-off \
         (initial_speed {speed} rad/s, angular_acceleration {acceleration} rad/s²)"
    )]
    Stops {
        /// The angle asked for, degrees.
        angle_deg: f64,
        /// Where the crank comes to rest, θ0 + ω0²/(2·|α|), degrees.
        stop_deg: f64,
        /// ω0² + 2·α·Δθ at the angle asked for, rad²/s².
        omega2: f64,
        speed: f64,
        acceleration: f64,
    },
}

impl CrankMotion {
    /// The crank state at angle `theta`, with the time obtained by inverting (A4.2.2.1) and
    /// ω = sqrt(ω0² + 2·α·(θ − θ0)) (constant acceleration, so ω = ω0 + α·t as in A4.2.2.64).
    pub fn at_angle(&self, theta: f64) -> Result<CrankState, MotionError> {
        self.at_angle_in(theta, C::from_polar(1.0, theta))
    }

    /// [`CrankMotion::at_angle`] with e^{iθ} supplied.
    fn at_angle_in(&self, theta: f64, direction: C) -> Result<CrankState, MotionError> {
        let (w, time) = self.speed_and_time(theta)?;
        Ok(CrankState {
            angle: theta,
            direction,
            speed: w,
            acceleration: self.angular_acceleration,
            time,
        })
    }

    /// Whether the motion reaches angle `theta` (the checks of [`Self::speed_and_time`]).
    fn speed_and_time_checked(&self, theta: f64) -> Result<(), MotionError> {
        let (w0, a) = (self.initial_speed, self.angular_acceleration);
        if w0 < 0.0 {
            return Err(MotionError::Backwards(w0));
        }
        if w0 == 0.0 && a == 0.0 {
            return Err(MotionError::Still);
        }
        let dtheta = theta - self.start_angle;
        let w2 = w0 * w0 + 2.0 * a * dtheta;
        // A crank decelerated to rest exactly at `theta` has ω² = 0 there, which the sum
        // gives to within its round-off, a few ulp either side: that crank reaches `theta` (at
        // rest), and ω is taken as 0. Only ω² below 0 by more than that stops it before.
        if w2 < -Self::round_off(w0, a, theta, self.start_angle) {
            return Err(MotionError::Stops {
                angle_deg: theta.to_degrees(),
                stop_deg: (self.start_angle + w0 * w0 / (2.0 * a.abs())).to_degrees(),
                omega2: w2,
                speed: w0,
                acceleration: a,
            });
        }
        Ok(())
    }

    /// A bound of the round-off of ω0² + 2·α·(θ − θ0) in f64: each of the products, the
    /// difference θ − θ0 and the sum rounds by at most ε/2 of its size, so 4·ε of the terms'
    /// magnitudes (with |θ| + |θ0| for |θ − θ0|) bounds the sum's error with a margin.
    fn round_off(w0: f64, a: f64, theta: f64, start: f64) -> f64 {
        4.0 * f64::EPSILON * (w0 * w0 + 2.0 * a.abs() * (theta.abs() + start.abs()))
    }

    /// ω and t at angle `theta`.
    fn speed_and_time(&self, theta: f64) -> Result<(f64, f64), MotionError> {
        self.speed_and_time_checked(theta)?;
        let (w0, a) = (self.initial_speed, self.angular_acceleration);
        let dtheta = theta - self.start_angle;
        // ω² within round-off below 0 is a crank at rest (see `speed_and_time_checked`).
        let w = (w0 * w0 + 2.0 * a * dtheta).max(0.0).sqrt();
        // t = 2Δθ/(ω0 + ω) is the root of ½αt² + ω0t − Δθ = 0 without the cancellation of
        // (−ω0 + ω)/α, and it also holds for α = 0.
        let time = if dtheta == 0.0 {
            0.0
        } else {
            2.0 * dtheta / (w0 + w)
        };
        Ok((w, time))
    }

    /// `steps + 1` crank states, uniformly spaced in crank angle from `start` to `end` (rad).
    pub fn grid(&self, start: f64, end: f64, steps: usize) -> Result<Vec<CrankState>, MotionError> {
        let mut g = Grid::new(*self, start, end, steps);
        std::iter::from_fn(|| g.next(None)).collect()
    }
}

/// Where the crank states of a run come from, one after the other. A prescribed motion
/// ignores the loads; a solved one (the machine equation, Petrescu 2015) advances θ and ω
/// from the drive torque the previous step needed.
pub trait MotionSource {
    /// Number of crank states the run will have.
    fn len(&self) -> usize;

    /// Whether the run is empty.
    fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The next crank state, given the drive torque (N·m) the previous one needed (`None`
    /// at the first); `None` after the last.
    fn next(&mut self, previous_torque: Option<f64>) -> Option<Result<CrankState, MotionError>>;

    /// Whether the states do not depend on the torques (a prescribed motion): then a run may
    /// take several at once.
    fn prescribed(&self) -> bool {
        false
    }

    /// Fills the lanes of `out` from the first with the next states of a prescribed motion, at
    /// most [`LANES`]: how many (fewer after the last), and the error at the first state that
    /// cannot be reached (the states before it filled).
    fn next_block(&mut self, out: &mut CrankColumns) -> (usize, Option<MotionError>) {
        next_one_by_one(self, out)
    }

    /// The index in the whole run of the first state this source gives (not 0 for a
    /// [`MotionSource::part`]).
    fn first_index(&self) -> usize {
        0
    }

    /// The states of indices `first..=last` alone, exactly as this source gives them, if it
    /// can give them apart from the others (a prescribed motion can, from any `first` that is
    /// a multiple of [`REANCHOR`]): the pieces of a run that several threads share.
    fn part(&self, first: usize, last: usize) -> Option<Box<dyn MotionSource + Send>> {
        let _ = (first, last);
        None
    }
}

/// The prescribed motion on a grid uniform in crank angle, from `start` to exactly `end`.
///
/// The states are made a block of [`REANCHOR`] at a time, as columns: the angles and directions
/// first, then every speed and time of the block in one loop of independent square roots and
/// divisions, which the processor overlaps (made one per step, each waited for its own: about
/// 11 ns per step of an accelerating crank). Each state is computed by the same expressions as
/// [`CrankMotion::at_angle`], so bit for bit the same (tested). A run takes the blocks straight
/// into its own columns ([`MotionSource::next_block`]).
#[derive(Debug, Clone)]
pub struct Grid {
    spacing: Spacing,
    /// The next state's index.
    k: usize,
    /// The indices of the first and the last state this grid gives (0 and `steps`, unless it
    /// is a part).
    first: usize,
    last: usize,
    /// The block being handed out one state at a time ([`MotionSource::next`]): its states
    /// from index `block_start`, how many, and a motion error at its end.
    block: Box<CrankColumns>,
    block_len: usize,
    block_start: usize,
    error: Option<MotionError>,
}

/// What places a grid's points.
#[derive(Debug, Clone, Copy)]
struct Spacing {
    motion: CrankMotion,
    start: f64,
    end: f64,
    steps: usize,
    h: f64,
    /// e^{i·j·h} for j < CHAINS, and e^{i·CHAINS·h}, the step of a chain.
    starts: [C; CHAINS],
    rotation: C,
}

// A grid block fills a run's block.
const _: () = assert!(REANCHOR == LANES);

impl Grid {
    /// `steps` intervals (`steps + 1` states) from `start` to `end`, rad.
    pub fn new(motion: CrankMotion, start: f64, end: f64, steps: usize) -> Self {
        let h = (end - start) / steps as f64;
        Self {
            spacing: Spacing {
                motion,
                start,
                end,
                steps,
                h,
                starts: std::array::from_fn(|j| C::from_polar(1.0, h * j as f64)),
                rotation: C::from_polar(1.0, h * CHAINS as f64),
            },
            k: 0,
            first: 0,
            last: steps,
            block: Box::new(CrankColumns::ZEROED),
            block_len: 0,
            block_start: 0,
            error: None,
        }
    }
}

/// [`MotionSource::next_block`] a state at a time.
fn next_one_by_one<M: MotionSource + ?Sized>(
    motion: &mut M,
    out: &mut CrankColumns,
) -> (usize, Option<MotionError>) {
    for i in 0..LANES {
        match motion.next(None) {
            None => return (i, None),
            Some(Ok(c)) => out.set(i, &c),
            Some(Err(e)) => return (i, Some(e)),
        }
    }
    (LANES, None)
}

impl MotionSource for Grid {
    fn len(&self) -> usize {
        self.last + 1 - self.first_index()
    }

    fn prescribed(&self) -> bool {
        true
    }

    fn first_index(&self) -> usize {
        self.first
    }

    /// Bit for bit the states of the whole grid: a part starts on a block's start, where the
    /// direction is anchored (tested).
    fn part(&self, first: usize, last: usize) -> Option<Box<dyn MotionSource + Send>> {
        if first % REANCHOR != 0 || first > last || last > self.spacing.steps {
            return None;
        }
        let s = self.spacing;
        Some(Box::new(Grid {
            k: first,
            first,
            last,
            block_start: first,
            ..Grid::new(s.motion, s.start, s.end, s.steps)
        }))
    }

    /// From a block's start (where a run's blocks start), the grid's block made straight into
    /// `out`; elsewhere a state at a time. The states of [`MotionSource::next`], bit for bit.
    fn next_block(&mut self, out: &mut CrankColumns) -> (usize, Option<MotionError>) {
        if self.k > self.last {
            return (0, None);
        }
        if self.k % REANCHOR != 0 {
            return next_one_by_one(self, out);
        }
        let (n, error) = grid_block(&self.spacing, self.k, self.last, out);
        if error.is_some() {
            // Past the state the motion cannot reach, where `next` goes on failing.
            (self.block_start, self.block_len, self.error) = (self.k, 0, error.clone());
            self.k += 1;
        }
        self.k += n;
        (n, error)
    }

    fn next(&mut self, _previous_torque: Option<f64>) -> Option<Result<CrankState, MotionError>> {
        if self.k > self.last {
            return None;
        }
        if self.k % REANCHOR == 0 {
            (self.block_len, self.error) =
                grid_block(&self.spacing, self.k, self.last, &mut self.block);
            self.block_start = self.k;
        }
        let lane = self.k - self.block_start;
        self.k += 1;
        Some(if lane < self.block_len {
            Ok(self.block.at(lane))
        } else {
            // Past the block's valid states: the motion cannot reach this angle.
            Err(self.error.clone().unwrap_or(MotionError::Still))
        })
    }
}

/// 0, 1, …, [`LANES`] − 1 as numbers.
const LANE_NUMBERS: [f64; LANES] = {
    let mut numbers = [0.0; LANES];
    let mut j = 0;
    while j < LANES {
        numbers[j] = j as f64;
        j += 1;
    }
    numbers
};

vectorised! {
    /// Makes the states of the block from index `k` (a multiple of [`REANCHOR`]) to at most
    /// `last` into `out`: how many it could make, and the motion's error at the next one if it
    /// stopped short.
    fn grid_block(
        spacing: &Spacing,
        k: usize,
        last: usize,
        out: &mut CrankColumns,
    ) -> (usize, Option<MotionError>) {
        let n = (last + 1 - k).min(REANCHOR);
        let m = spacing.motion;
        // (k + j) as f64 is k as f64 + j as f64 exactly (integers below 2⁵³): added as a vector.
        let first = k as f64;
        for (angle, j) in out.angle.iter_mut().zip(LANE_NUMBERS) {
            *angle = spacing.start + spacing.h * (first + j);
        }
        out.acceleration = [m.angular_acceleration; LANES];
        // Exact at the block's start (every REANCHOR points); then CHAINS chains, each
        // turned by e^{i·CHAINS·h} from the point CHAINS before (written out as C's product,
        // the same arithmetic, so that the compiler turns the chains side by side).
        let anchor = C::from_polar(1.0, out.angle[0]);
        (out.cos[0], out.sin[0]) = (anchor.re, anchor.im);
        for (j, start) in spacing.starts.iter().enumerate().skip(1) {
            let z = anchor * start;
            (out.cos[j], out.sin[j]) = (z.re, z.im);
        }
        let r = spacing.rotation;
        for j in CHAINS..LANES {
            let (c, s) = (out.cos[j - CHAINS], out.sin[j - CHAINS]);
            out.cos[j] = c * r.re - s * r.im;
            out.sin[j] = c * r.im + s * r.re;
        }
        // The last point is `end` itself, not start + h·steps, which can land a rounding step
        // past it (and past the angle where a decelerating crank stops), and exact.
        if let Some(j) = spacing.steps.checked_sub(k).filter(|j| *j < n) {
            out.angle[j] = spacing.end;
            (out.sin[j], out.cos[j]) = spacing.end.sin_cos();
        }
        let (w0, a) = (m.initial_speed, m.angular_acceleration);
        if a == 0.0 && w0 > 0.0 {
            // Constant speed: ω = ω0 and t = Δθ/ω0, what at_angle gives without its square root.
            for j in 0..n {
                out.speed[j] = w0;
                out.time[j] = (out.angle[j] - m.start_angle) / w0;
            }
            return (n, None);
        }
        // The checks of `speed_and_time` (one test for the block where the crank turns
        // forwards and ω² stays above 0 throughout: the smallest ω², from four running minima),
        // then its arithmetic on the whole block.
        // A whole block (most blocks): a loop of a known count, which the compiler unrolls.
        let lowest = match n == LANES {
            true => lowest_squared_speeds(&m, out, LANES),
            false => lowest_squared_speeds(&m, out, n),
        };
        let mut error = None;
        let valid = if w0 > 0.0 && lowest.iter().all(|l| *l > 0.0) {
            n
        } else {
            (0..n)
                .position(|j| {
                    m.speed_and_time_checked(out.angle[j])
                        .map_err(|e| error = Some(e))
                        .is_err()
                })
                .unwrap_or(n)
        };
        // A whole block (most blocks): a loop of a known count, which the compiler unrolls.
        match valid == LANES {
            true => speeds_and_times(&m, out, LANES),
            false => speeds_and_times(&m, out, valid),
        }
        (valid, error)
    }
}

/// Four running minima of ω² = ω0² + 2α(θ − θ0) over the first `n` states of `out` under `m`.
#[inline(always)]
fn lowest_squared_speeds(m: &CrankMotion, out: &CrankColumns, n: usize) -> [f64; 4] {
    let (w0, a) = (m.initial_speed, m.angular_acceleration);
    let n = n.min(LANES);
    let mut lowest = [f64::INFINITY; 4];
    let w2 = |j: usize| w0 * w0 + 2.0 * a * (out.angle[j] - m.start_angle);
    let mut j = 0;
    while j + 4 <= n {
        for (k, l) in lowest.iter_mut().enumerate() {
            *l = if w2(j + k) < *l { w2(j + k) } else { *l };
        }
        j += 4;
    }
    for j in j..n {
        lowest[0] = if w2(j) < lowest[0] { w2(j) } else { lowest[0] };
    }
    lowest
}

/// The speed and time of the first `n` states of `out` from their angles under the
/// accelerating motion `m` ([`CrankMotion::at_angle`]'s arithmetic, its checks passed).
#[inline(always)]
fn speeds_and_times(m: &CrankMotion, out: &mut CrankColumns, n: usize) {
    let (w0, a) = (m.initial_speed, m.angular_acceleration);
    for j in 0..n.min(LANES) {
        let dtheta = out.angle[j] - m.start_angle;
        let w = (w0 * w0 + 2.0 * a * dtheta).max(0.0).sqrt();
        out.speed[j] = w;
        out.time[j] = if dtheta == 0.0 {
            0.0
        } else {
            2.0 * dtheta / (w0 + w)
        };
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn time_inverts_the_motion_law() {
        let m = CrankMotion {
            start_angle: 0.5,
            initial_speed: 3.0,
            angular_acceleration: 100.0,
        };
        for theta in [0.5, 1.0, 7.0, 14.1] {
            let s = m.at_angle(theta).unwrap();
            let t = s.time;
            assert_relative_eq!(0.5 + 3.0 * t + 50.0 * t * t, theta, max_relative = 1e-14);
            assert_relative_eq!(s.speed, 3.0 + 100.0 * t, max_relative = 1e-13);
        }
    }

    /// At constant speed the grid's shortcut gives what `at_angle` gives.
    #[test]
    fn constant_speed_states_are_the_motion_laws() {
        let m = CrankMotion {
            start_angle: 0.7,
            initial_speed: 628.3185307,
            angular_acceleration: 0.0,
        };
        for s in m.grid(0.7, 13.3, 997).unwrap() {
            let exact = m.at_angle(s.angle).unwrap();
            assert_relative_eq!(s.speed, exact.speed, max_relative = 1e-15);
            assert_relative_eq!(s.time, exact.time, max_relative = 1e-15, epsilon = 1e-300);
        }
    }

    /// The grid makes its states a block at a time; each is what `at_angle` gives at its angle
    /// (bit for bit: the same expressions), with its direction within the rotation's bound.
    #[test]
    fn block_states_are_the_motion_law_bit_for_bit() {
        for m in [
            CrankMotion {
                start_angle: 1.5,
                initial_speed: 200.0 * std::f64::consts::PI,
                angular_acceleration: 100.0 * std::f64::consts::PI,
            },
            CrankMotion {
                start_angle: 0.0,
                initial_speed: 0.0,
                angular_acceleration: 3.0,
            },
        ] {
            let grid = m.grid(m.start_angle, m.start_angle + 12.6, 7201).unwrap();
            assert_eq!(grid.len(), 7202);
            for s in &grid {
                let exact = m.at_angle(s.angle).unwrap();
                assert_eq!(s.speed.to_bits(), exact.speed.to_bits(), "{}", s.angle);
                assert_eq!(s.time.to_bits(), exact.time.to_bits(), "{}", s.angle);
                assert_eq!(s.acceleration, m.angular_acceleration);
            }
        }
    }

    /// A part of a grid gives the whole grid's states of its indices, bit for bit; it starts
    /// on a block's start only.
    #[test]
    fn grid_parts_are_the_whole_grids_states() {
        let m = CrankMotion {
            start_angle: 1.5,
            initial_speed: 3.0,
            angular_acceleration: 10.0,
        };
        let whole = Grid::new(m, 1.5, 14.1, 1000);
        let states: Vec<CrankState> = m.grid(1.5, 14.1, 1000).unwrap();
        for (first, last) in [(0, 1000), (128, 256), (960, 1000), (64, 64), (0, 0)] {
            let mut part = whole.part(first, last).unwrap();
            assert_eq!((part.first_index(), part.len()), (first, last + 1 - first));
            let got: Vec<CrankState> = std::iter::from_fn(|| part.next(None))
                .map(Result::unwrap)
                .collect();
            assert_eq!(got, states[first..=last], "{first}..={last}");
        }
        assert!(whole.part(100, 200).is_none(), "not on a block's start");
        assert!(whole.part(64, 1001).is_none(), "past the end");
        assert!(whole.part(128, 64).is_none(), "empty");
        assert_eq!(whole.first_index(), 0);
    }

    /// States taken several at a time are the ones taken one at a time, to the same error.
    #[test]
    fn states_taken_in_blocks_are_the_ones_taken_singly() {
        let stopping = CrankMotion {
            start_angle: 0.0,
            initial_speed: 1.0,
            angular_acceleration: -1.0,
        };
        let running = CrankMotion {
            angular_acceleration: 1.0,
            ..stopping
        };
        for (m, steps) in [
            (stopping, 200),
            (running, 200),
            (running, 64),
            (running, 130),
        ] {
            let mut g = Grid::new(m, 0.0, 0.99, steps);
            let mut singly = Vec::new();
            let end = loop {
                match g.next(None) {
                    Some(Ok(s)) => singly.push(s),
                    Some(Err(e)) => break Err(e),
                    None => break Ok(()),
                }
            };
            // Blocks from the start (made straight into the columns), or after a few states
            // taken one at a time (off the grid's blocks).
            for lead in [0, 1, 5] {
                let mut g = Grid::new(m, 0.0, 0.99, steps);
                let mut states: Vec<CrankState> = (0..lead)
                    .map_while(|_| g.next(None).and_then(Result::ok))
                    .collect();
                let mut columns = CrankColumns::ZEROED;
                let end_in_blocks = loop {
                    let (n, error) = g.next_block(&mut columns);
                    states.extend((0..n).map(|i| columns.at(i)));
                    if let Some(e) = error {
                        break Err(e);
                    }
                    if n < LANES {
                        break Ok(());
                    }
                };
                assert_eq!(states, singly, "{steps} steps, {lead} first");
                assert_eq!(end_in_blocks, end, "{steps} steps, {lead} first");
                // Past the unreachable state, the motion goes on failing.
                if end.is_err() {
                    assert!(matches!(g.next(None), Some(Err(_))), "{steps} steps");
                }
            }
        }
    }

    /// A crank that stops inside a block: every state before the stop, then the error of
    /// `at_angle` at the first angle it cannot reach.
    #[test]
    fn a_crank_stopping_mid_block_fails_at_the_first_unreachable_angle() {
        let m = CrankMotion {
            start_angle: 0.0,
            initial_speed: 1.0,
            angular_acceleration: -1.0,
        };
        // ω² = 1 − 2Δθ: stops at Δθ = 0.5, i.e. between grid points 100 and 101 of h = 0.00495.
        let mut g = Grid::new(m, 0.0, 0.99, 200);
        let mut ok = 0;
        let error = loop {
            match g.next(None) {
                Some(Ok(_)) => ok += 1,
                Some(Err(e)) => break e,
                None => panic!("the grid ran past the stop"),
            }
        };
        assert_eq!(ok, 102);
        assert_eq!(Err(error), m.at_angle(0.99 / 200.0 * 102.0).map(|_| ()));
    }

    /// The rotated directions stay within the bound stated at [`REANCHOR`]; the sine and
    /// cosine are computed independently of the rotation.
    #[test]
    fn grid_directions_stay_within_the_reanchoring_bound() {
        let m = CrankMotion {
            start_angle: 1.5,
            initial_speed: 3.0,
            angular_acceleration: 10.0,
        };
        let bound = (REANCHOR / CHAINS + 1) as f64 * 4.0 * f64::EPSILON;
        let grid = m.grid(1.5, 14.1, 100_003).unwrap();
        let worst = grid
            .iter()
            .map(|s| (s.direction - C::new(s.angle.cos(), s.angle.sin())).norm())
            .fold(0.0, f64::max);
        assert!(worst < bound, "{worst} >= {bound}");
        assert!(worst > 0.0, "the rotation is in use");
        assert_eq!(grid.len(), 100_004);
        assert_eq!(grid.last().unwrap().angle, 14.1);
    }

    /// The panic reproducer of issue 7: start + h·steps lands one rounding step past an end
    /// angle where the decelerating crank just stops; the grid must end at `end` itself.
    #[test]
    fn the_last_grid_point_is_the_end_angle() {
        let end = 7.658914712828217;
        let m = CrankMotion {
            start_angle: 0.0,
            initial_speed: 1.0,
            angular_acceleration: -0.06528340094485323,
        };
        let h = end / 3077.0;
        assert!(h * 3077.0 > end, "the reproducer lands past the end");
        assert!(m.at_angle(end).is_ok());
        let g = m.grid(0.0, end, 3077).unwrap();
        assert_eq!(g.last().unwrap().angle, end);
        // And for a crank that stops exactly at the end.
        let span = 3.0;
        let stops = CrankMotion {
            start_angle: 0.1,
            initial_speed: 2.0,
            angular_acceleration: -4.0 / (2.0 * span) * (1.0 - 1e-15),
        };
        let g = stops.grid(0.1, 0.1 + span, 3077).unwrap();
        assert_eq!(g.len(), 3078);
    }

    /// Decelerated to rest exactly at the end: ω² there is 0 up to round-off, some ulp below 0
    /// for some accelerations. That crank reaches the end, at rest; one that stops a round-off
    /// short of it by more than round-off (−1e-9 of ω0² at the end) does not.
    #[test]
    fn a_crank_at_rest_at_the_end_within_round_off_reaches_it() {
        let (w0, end) = (2.0_f64, 3.0_f64);
        let exact = -(w0 * w0) / (2.0 * end);
        let mut below = 0;
        for ulps in -4_i64..=4 {
            let a = f64::from_bits((exact.to_bits() as i64 + ulps) as u64);
            let m = CrankMotion {
                start_angle: 0.0,
                initial_speed: w0,
                angular_acceleration: a,
            };
            if w0 * w0 + 2.0 * a * end < 0.0 {
                below += 1;
            }
            let last = m.at_angle(end).unwrap();
            assert!(last.speed < 1e-7, "ω at the end {} (α = {a:?})", last.speed);
            let g = m.grid(0.0, end, 1001).unwrap();
            assert_eq!(g.last().unwrap().speed, last.speed);
        }
        assert!(below > 0, "test set-up: no ω² a round-off below 0");
        let short = CrankMotion {
            start_angle: 0.0,
            initial_speed: w0,
            angular_acceleration: exact * (1.0 + 1e-9),
        };
        assert!(matches!(
            short.at_angle(end),
            Err(MotionError::Stops { .. })
        ));
        assert!(short.grid(0.0, end, 1001).is_err());
    }

    #[test]
    fn start_from_rest_and_stopping_crank() {
        let m = CrankMotion {
            start_angle: 0.0,
            initial_speed: 0.0,
            angular_acceleration: 2.0,
        };
        assert_relative_eq!(m.at_angle(1.0).unwrap().time, 1.0, max_relative = 1e-15);
        let m = CrankMotion {
            start_angle: 0.0,
            initial_speed: 1.0,
            angular_acceleration: -1.0,
        };
        assert!(matches!(m.at_angle(0.6), Err(MotionError::Stops { .. })));
        let m = CrankMotion {
            start_angle: 0.0,
            initial_speed: 0.0,
            angular_acceleration: 0.0,
        };
        assert_eq!(m.at_angle(1.0), Err(MotionError::Still));
    }
}
