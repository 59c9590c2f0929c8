//! The indicator diagram (`pv_diagram.svg`, and `pv_diagram_log.svg` on log-log axes): the
//! cylinder pressure over the chamber's volume, every mechanism with a gas chamber on one
//! chart (issue 38). The volume of each row is V = V_comp + A·(x_TDC − x) (Karhula 2008,
//! A6.1.1.7; `cardan_gas::Cylinder::volume_curve`) of its piston position x, with the
//! chamber's V_comp, A and x_TDC from `summary.json` (`chamber`); the path is the locus of
//! (x, p) the run recorded (`locus.rs`: rows in order, the extremes of both kept), so its
//! extreme volumes and pressures are drawn. Pressure in bar and volume in cm³ (the units an
//! engineer reads an indicator diagram in); on log-log axes a polytropic change p·Vⁿ = const
//! is a straight line of slope −n (log p = log C − n·log V).

use crate::chart_columns::locus_key;
use crate::data::CaseSummary;
use crate::envelope::ChartData;
use crate::log_chart::log_chart;
use crate::svg::{self, LineChart, Series};

/// Pa to bar (ISO 80000-4: 1 bar = 10⁵ Pa).
pub(crate) const BAR_PER_PA: f64 = 1e-5;
/// m³ to cm³.
pub(crate) const CM3_PER_M3: f64 = 1e6;

/// The indicator diagrams of the case: none if no mechanism has a chamber and its pressure.
pub(super) fn indicator_charts(
    s: &CaseSummary,
    data: &[Option<ChartData>],
) -> Vec<(String, String, String)> {
    let mut series = Vec::new();
    for (k, m) in s.mechanisms.iter().enumerate() {
        let (Some(d), Some(chamber)) = (&data[k], &m.chamber) else {
            continue;
        };
        let x_column = format!("{}_position_m", chamber.piston);
        let Some(t) = d.traces.get(&locus_key(&x_column, "cylinder_pressure_pa")) else {
            continue;
        };
        let (x, y): (Vec<f64>, Vec<f64>) =
            t.x.iter()
                .zip(&t.y)
                .filter(|(x, p)| x.is_finite() && p.is_finite())
                .map(|(x, p)| (chamber.volume(*x) * CM3_PER_M3, p * BAR_PER_PA))
                .unzip();
        if x.is_empty() {
            continue;
        }
        series.push(Series {
            label: m.name.clone(),
            source: format!("{}:cylinder_pressure_pa", d.file),
            x,
            y,
            colour: k,
            dash: series.len(),
            markers: false,
            x_column: Some(x_column),
        });
    }
    if series.is_empty() {
        return Vec::new();
    }
    let chart = LineChart {
        title: "Indicator diagram: cylinder pressure over volume".into(),
        x_label: "cylinder volume V, cm³".into(),
        y_label: "pressure (absolute)".into(),
        y_unit: "bar".into(),
        series,
        factors: Some((CM3_PER_M3, BAR_PER_PA)),
        ..LineChart::default()
    };
    vec![
        (
            "pv_diagram.svg".into(),
            svg::line_chart(&chart),
            "Indicator diagram (p–V): absolute cylinder pressure over the chamber's volume \
             V = V_comp + A·(x_TDC − x), every mechanism; the area enclosed is the indicated \
             work per cycle"
                .into(),
        ),
        (
            "pv_diagram_log.svg".into(),
            log_chart(&chart),
            "Indicator diagram on log-log axes: a polytropic change p·Vⁿ = const is a \
             straight line of slope −n"
                .into(),
        ),
    ]
}
