//! A swept field's values as the axis of a sweep report's charts and tables: its title with
//! the unit, its distinct levels in order, and their tick labels in readable figures.

use crate::data::{parse_quantity, SweepTable};

/// One swept field's values as an axis.
#[derive(Debug, Clone)]
pub(crate) struct Axis {
    /// Axis title: the field's path and unit.
    pub title: String,
    /// Each point's number, when every value reads as a number with one unit.
    pub numbers: Option<Vec<f64>>,
    /// Each point's text.
    pub texts: Vec<String>,
}

impl Axis {
    pub(crate) fn of(t: &SweepTable, k: usize) -> Axis {
        let texts: Vec<String> = t.params.iter().map(|p| p[k].clone()).collect();
        let parsed: Option<Vec<(f64, String)>> = texts.iter().map(|s| parse_quantity(s)).collect();
        let numbers = parsed.as_ref().and_then(|p| {
            let unit = &p.first()?.1;
            p.iter()
                .all(|(_, u)| u == unit)
                .then(|| p.iter().map(|(v, _)| *v).collect())
        });
        let unit = parsed
            .as_ref()
            .and_then(|p| p.first().map(|(_, u)| u.clone()))
            .filter(|u| !u.is_empty() && numbers.is_some());
        Axis {
            title: match unit {
                Some(u) => format!("{}, {u}", t.swept[k]),
                None => t.swept[k].clone(),
            },
            numbers,
            texts,
        }
    }

    /// The distinct values in axis order (numeric ascending, else first appearance): their
    /// texts, and each point's index among them.
    pub(crate) fn levels(&self) -> (Vec<String>, Vec<usize>) {
        let mut order: Vec<usize> = Vec::new();
        for (k, s) in self.texts.iter().enumerate() {
            if !order.iter().any(|&o| self.texts[o] == *s) {
                order.push(k);
            }
        }
        if let Some(n) = &self.numbers {
            order.sort_by(|a, b| n[*a].total_cmp(&n[*b]));
        }
        let labels: Vec<String> = order.iter().map(|&o| self.texts[o].clone()).collect();
        let index = self
            .texts
            .iter()
            .map(|s| labels.iter().position(|l| l == s).unwrap_or(0))
            .collect();
        (labels, index)
    }

    /// The levels as tick labels: without their unit when the axis title carries it.
    pub(crate) fn tick_labels(&self) -> Vec<String> {
        let (levels, _) = self.levels();
        if self.numbers.is_none() {
            return levels;
        }
        let values: Vec<f64> = levels
            .iter()
            .filter_map(|l| parse_quantity(l).map(|(v, _)| v))
            .collect();
        if values.len() == levels.len() {
            return readable(&values);
        }
        levels
            .iter()
            .map(|l| l.split_whitespace().next().unwrap_or(l).to_string())
            .collect()
    }
}

/// Tick labels of `values` rounded to readable numbers (issue 38: "229" for a log-spaced
/// level of 228.852 rpm): the fewest significant figures, three at least, that keep
/// neighbouring levels apart, without trailing zeros.
pub(crate) fn readable(values: &[f64]) -> Vec<String> {
    let round = |v: f64, sig: i32| -> String {
        if v == 0.0 || !v.is_finite() {
            return format!("{v}");
        }
        let decimals = (sig - 1 - v.abs().log10().floor() as i32).max(0) as usize;
        let s = format!("{v:.decimals$}");
        let s = if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            // Beyond the significant figures: round the integer part too.
            let scale = 10f64
                .powi(v.abs().log10().floor() as i32 + 1 - sig)
                .max(1.0);
            format!("{}", (v / scale).round() * scale)
        };
        if s == "-0" {
            "0".into()
        } else {
            s
        }
    };
    for sig in 3..=12 {
        let labels: Vec<String> = values.iter().map(|v| round(*v, sig)).collect();
        if labels.windows(2).all(|w| w[0] != w[1]) {
            return labels;
        }
    }
    values.iter().map(|v| format!("{v}")).collect()
}

#[cfg(test)]
mod tests {
    use super::readable;

    /// A log-spaced speed sweep (90 to 6000 rpm in 10 points) is labelled in three figures,
    /// round values stay as they are, close levels get the figures that tell them apart.
    #[test]
    fn sweep_levels_are_labelled_in_readable_figures() {
        let log: Vec<f64> = (0..10)
            .map(|k| 90.0 * (6000.0f64 / 90.0).powf(k as f64 / 9.0))
            .collect();
        assert_eq!(
            readable(&log),
            ["90", "144", "229", "365", "582", "928", "1480", "2360", "3760", "6000"]
        );
        assert_eq!(readable(&[140.0, 150.0, 160.0]), ["140", "150", "160"]);
        assert_eq!(readable(&[0.0125, 0.05, 1.0]), ["0.0125", "0.05", "1"]);
        assert_eq!(
            readable(&[1000.0, 1001.0, 1002.5]),
            ["1000", "1001", "1003"]
        );
        assert_eq!(readable(&[-3.0, 0.0, 2.5]), ["-3", "0", "2.5"]);
    }
}
