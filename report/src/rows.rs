//! Which of a run's steps make rows: every n-th and the last, both for a per-step file
//! ([`row_count`], its `decimation`) and for the rows the charts take of a run ([`ChartRows`]).

/// The number of rows written for steps 0..=`last_step`: every `decimation`-th and the last.
pub fn row_count(last_step: usize, decimation: usize) -> usize {
    last_step / decimation + 1 + usize::from(last_step % decimation != 0)
}

/// The most rows a chart series takes from a run (why so many:
/// [`ChartRecorder`](crate::ChartRecorder)).
pub const MAX_CHART_ROWS: usize = 16 * crate::svg::MAX_POINTS;

/// Which of a run's per-step rows the charts take: every `stride`-th of the `rows` and the
/// last, the fewest that keeps them within `MAX_CHART_ROWS` (16 000).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChartRows {
    rows: usize,
    pub(crate) stride: usize,
}

impl ChartRows {
    pub(crate) fn new(rows: usize) -> Self {
        Self {
            rows,
            stride: rows.div_ceil(MAX_CHART_ROWS).max(1),
        }
    }

    /// Every how many rows the charts take one (and the last).
    pub fn stride(&self) -> usize {
        self.stride
    }

    /// Whether the charts take the row of index `k`.
    pub fn takes(&self, k: usize) -> bool {
        k % self.stride == 0 || k + 1 == self.rows
    }

    /// The first row from `k` on that the charts take (`rows - 1` or more past the last
    /// stride-th row).
    pub fn next_taken(&self, k: usize) -> usize {
        k.div_ceil(self.stride) * self.stride
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn row_count_is_every_nth_step_and_the_last() {
        for (last, d) in [(0, 1), (10, 1), (10, 3), (9, 3), (7200, 7), (5, 10)] {
            let expected = (0..=last).filter(|i| i % d == 0 || *i == last).count();
            assert_eq!(row_count(last, d), expected, "last {last}, every {d}");
        }
    }
}
