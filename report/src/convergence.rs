//! The convergence chart of an optimisation (`[optimize]`, issue 40): the best objective found
//! so far over the evaluations, one series per mechanism, drawn by the line charts of `svg.rs`.

use crate::svg::{line_chart, LineChart, Series};

/// One mechanism's search: its label, and the best objective so far (SI) after each
/// evaluation (x: the evaluation's number from 1; NaN where nothing feasible was found yet,
/// which the chart leaves out).
pub struct Convergence {
    pub label: String,
    pub best_so_far: Vec<f64>,
}

/// The chart's SVG: `objective` (a metric name) in `unit` (SI) over the evaluations.
pub fn convergence_chart(objective: &str, unit: &str, searches: &[Convergence]) -> String {
    let series = searches
        .iter()
        .enumerate()
        .map(|(k, s)| {
            let (x, y): (Vec<f64>, Vec<f64>) = s
                .best_so_far
                .iter()
                .enumerate()
                .filter(|(_, y)| y.is_finite())
                .map(|(i, y)| ((i + 1) as f64, *y))
                .unzip();
            Series {
                label: s.label.clone(),
                source: format!("{}/history.csv:best_so_far", s.label),
                x,
                y,
                colour: k,
                dash: k,
                markers: false,
                x_column: None,
            }
        })
        .collect();
    line_chart(&LineChart {
        title: format!("Convergence: best feasible {objective} so far"),
        x_label: "evaluation".into(),
        y_label: objective.into(),
        y_unit: unit.into(),
        series,
        ..LineChart::default()
    })
}
