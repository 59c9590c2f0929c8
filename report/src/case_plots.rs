//! The charts of a case over crank angle, every mechanism on one axis: piston position,
//! velocity and acceleration; cylinder pressure; the drive torque of each load family; the
//! force at each joint (total loads, else the last family); and, when the CSVs have them, the
//! friction torque and the power loss (all components, and each one). Only the series a chart
//! draws are kept ([`traces`]), thinned as the run makes them (`envelope.rs`) or read from
//! the CSV.

use crate::chart_columns::{load_family, locus_key, loss_columns, sum_key, LOCI};
use crate::data::{family_rank, CaseSummary};
use crate::envelope::ChartData;
use crate::locus::{locus_chart, LocusChart};
use crate::svg::{self, LineChart, Series};
use rayon::prelude::*;

/// One chart over crank angle: the file name, title, y quantity and unit, and per mechanism
/// the columns to draw (column name, label suffix).
pub(super) struct PlotSpec {
    file: String,
    title: String,
    y_label: String,
    unit: String,
    zero_line: bool,
    /// Per mechanism (index into the summary's order): (column, label suffix).
    columns: Vec<Vec<(String, String)>>,
    /// Sum the columns of a mechanism into one series (the total power loss).
    sum: bool,
}

/// The columns of the charts a CSV header allows.
pub(super) fn plot_specs(s: &CaseSummary, headers: &[Option<Vec<String>>]) -> Vec<PlotSpec> {
    let n = s.mechanisms.len();
    let single = |column: &str| single_column(headers, n, column);
    let mut specs = piston_specs(headers, n);
    specs.push(PlotSpec {
        file: "cylinder_pressure".into(),
        title: "Cylinder pressure (absolute)".into(),
        y_label: "pressure".into(),
        unit: "Pa".into(),
        zero_line: false,
        columns: single("cylinder_pressure_pa"),
        sum: false,
    });
    let families: Vec<String> = {
        let mut f: Vec<String> = headers
            .iter()
            .flatten()
            .flat_map(|h| h.iter())
            .filter_map(|c| load_family(c))
            .map(String::from)
            .collect();
        f.sort_by_key(|x| family_rank(x));
        f.dedup();
        f
    };
    for f in &families {
        specs.push(PlotSpec {
            file: format!("torque_{f}"),
            title: format!("Drive torque, {f} loads"),
            y_label: "torque".into(),
            unit: "N*m".into(),
            zero_line: true,
            columns: single(&format!("{f}_torque_nm")),
            sum: false,
        });
    }
    // Joint forces of the total loads (else the last family).
    if let Some(f) = families.last() {
        let mut joints: Vec<String> = s
            .mechanisms
            .iter()
            .flat_map(|m| m.joints.iter().cloned())
            .collect();
        joints.sort();
        joints.dedup();
        for j in joints {
            specs.push(PlotSpec {
                file: format!("force_{j}"),
                title: format!("Force at {j}, {f} loads"),
                y_label: "force magnitude".into(),
                unit: "N".into(),
                zero_line: false,
                columns: single(&format!("{f}_{j}_force_magnitude_n")),
                sum: false,
            });
        }
    }
    specs.extend(friction_specs(headers, n));
    // The charts so far are of one cylinder's columns: said so when the machine has more.
    if let Some(w) = s.one_cylinder() {
        for spec in &mut specs {
            spec.title = format!("{} ({w})", spec.title);
        }
    }
    specs.extend(balance_specs(headers, n, families.last()));
    specs
}

/// The balance charts of the first `n` of `headers` (issue 24): the shaking force's and the
/// free moment's components over crank angle, and the machine's summed torque against one
/// cylinder's (the last load family's, the total).
fn balance_specs(
    headers: &[Option<Vec<String>>],
    n: usize,
    family: Option<&String>,
) -> Vec<PlotSpec> {
    let both = |a: &str, b: &str, la: &str, lb: &str| -> Vec<Vec<(String, String)>> {
        let x = single_column(headers, n, a);
        let y = single_column(headers, n, b);
        x.into_iter()
            .zip(y)
            .map(|(x, y)| {
                let x = x.into_iter().map(|(c, _)| (c, la.to_string()));
                x.chain(y.into_iter().map(|(c, _)| (c, lb.to_string())))
                    .collect()
            })
            .collect()
    };
    let mut specs = vec![
        PlotSpec {
            file: "shaking_force".into(),
            title: "Shaking force on the frame (x and y)".into(),
            y_label: "force".into(),
            unit: "N".into(),
            zero_line: true,
            columns: both("shaking_force_x_n", "shaking_force_y_n", " x", " y"),
            sum: false,
        },
        PlotSpec {
            file: "shaking_moment".into(),
            title: "Free moment (pitch and yaw)".into(),
            y_label: "moment".into(),
            unit: "N*m".into(),
            zero_line: true,
            columns: both(
                "shaking_moment_pitch_nm",
                "shaking_moment_yaw_nm",
                " pitch",
                " yaw",
            ),
            sum: false,
        },
    ];
    if let Some(f) = family {
        specs.push(PlotSpec {
            file: "torque_machine".into(),
            title: "Machine torque (all cylinders) against one cylinder's".into(),
            y_label: "torque".into(),
            unit: "N*m".into(),
            zero_line: true,
            columns: both(
                "machine_torque_nm",
                &format!("{f}_torque_nm"),
                " machine",
                " one cylinder",
            )
            .into_iter()
            .map(|c| if c.len() == 2 { c } else { Vec::new() })
            .collect(),
            sum: false,
        });
    }
    specs
}

/// Per mechanism (the first `n` of `headers`), `column` if its header has it.
fn single_column(
    headers: &[Option<Vec<String>>],
    n: usize,
    column: &str,
) -> Vec<Vec<(String, String)>> {
    let has = |k: usize, c: &str| {
        headers[k]
            .as_ref()
            .is_some_and(|h| h.iter().any(|x| x == c))
    };
    (0..n)
        .map(|k| {
            if has(k, column) {
                vec![(column.to_string(), String::new())]
            } else {
                Vec::new()
            }
        })
        .collect()
}

/// The piston charts (position, velocity, acceleration) of the first `n` of `headers`: every
/// piston of a mechanism, each named when it has several.
fn piston_specs(headers: &[Option<Vec<String>>], n: usize) -> Vec<PlotSpec> {
    let mut specs = Vec::new();
    let pistons = |k: usize| -> Vec<String> {
        headers[k]
            .iter()
            .flatten()
            .filter_map(|h| h.strip_suffix("_dx_dtheta_m_rad"))
            .map(String::from)
            .collect()
    };
    let per_piston = |suffix: &str| -> Vec<Vec<(String, String)>> {
        (0..n)
            .map(|k| {
                let ps = pistons(k);
                let many = ps.len() > 1;
                ps.iter()
                    .map(|p| {
                        (
                            format!("{p}_{suffix}"),
                            if many { format!(" {p}") } else { String::new() },
                        )
                    })
                    .collect()
            })
            .collect()
    };
    for (file, title, quantity, unit, suffix) in [
        (
            "piston_position",
            "Piston position",
            "position",
            "m",
            "position_m",
        ),
        (
            "piston_velocity",
            "Piston velocity",
            "velocity",
            "m/s",
            "velocity_m_s",
        ),
        (
            "piston_acceleration",
            "Piston acceleration",
            "acceleration",
            "m/s^2",
            "acceleration_m_s2",
        ),
    ] {
        specs.push(PlotSpec {
            file: file.into(),
            title: title.into(),
            y_label: quantity.into(),
            unit: unit.into(),
            zero_line: suffix != "position_m",
            columns: per_piston(suffix),
            sum: false,
        });
    }
    specs
}

/// The friction charts of the first `n` of `headers`: the friction torque, the power loss of
/// all components (their sum) and of each.
fn friction_specs(headers: &[Option<Vec<String>>], n: usize) -> Vec<PlotSpec> {
    let single = |column: &str| single_column(headers, n, column);
    let mut specs = Vec::new();
    specs.push(PlotSpec {
        file: "friction_torque".into(),
        title: "Friction torque".into(),
        y_label: "torque".into(),
        unit: "N*m".into(),
        zero_line: true,
        columns: single("friction_torque_nm"),
        sum: false,
    });
    let losses_of =
        |k: usize| -> Vec<String> { headers[k].as_deref().map_or(Vec::new(), loss_columns) };
    let total_loss: Vec<Vec<(String, String)>> = (0..n)
        .map(|k| {
            losses_of(k)
                .into_iter()
                .map(|c| (c, String::new()))
                .collect()
        })
        .collect();
    specs.push(PlotSpec {
        file: "power_loss".into(),
        title: "Friction power loss, all components".into(),
        y_label: "power loss".into(),
        unit: "W".into(),
        zero_line: false,
        columns: total_loss,
        sum: true,
    });
    let mut components: Vec<String> = (0..n).flat_map(losses_of).collect();
    components.sort();
    components.dedup();
    for c in components {
        let name = c
            .strip_prefix("power_loss_")
            .and_then(|x| x.strip_suffix("_w"))
            .unwrap_or(&c)
            .to_string();
        specs.push(PlotSpec {
            file: format!("power_loss_{name}"),
            title: format!("Friction power loss: {name}"),
            y_label: "power loss".into(),
            unit: "W".into(),
            zero_line: false,
            columns: single(&c),
            sum: false,
        });
    }
    specs
}

/// Draws the charts of `specs` from each mechanism's series (None: the mechanism has no
/// chart data).
pub(super) fn charts(
    s: &CaseSummary,
    specs: &[PlotSpec],
    data: &[Option<ChartData>],
) -> Vec<(String, String, String)> {
    // Each chart drawn on a thread of the pool (a long run's charts are most of its report),
    // in the specs' order.
    let chart = |spec: &PlotSpec| {
        let mut series = Vec::new();
        for (k, m) in s.mechanisms.iter().enumerate() {
            let Some(d) = &data[k] else { continue };
            let file = &d.file;
            if spec.sum {
                let names: Vec<String> = spec.columns[k].iter().map(|(c, _)| c.clone()).collect();
                let Some(t) = d.traces.get(&sum_key(&names)).filter(|t| !t.x.is_empty()) else {
                    continue;
                };
                series.push(Series {
                    label: m.name.clone(),
                    source: format!("{file}:{}", names.join("+")),
                    x: t.x.clone(),
                    y: t.y.clone(),
                    colour: k,
                    // Every series of a chart its own dash (issue 38): black and white prints.
                    dash: series.len(),
                    markers: false,
                    x_column: None,
                });
                continue;
            }
            for (column, suffix) in &spec.columns[k] {
                let Some(t) = d.traces.get(column) else {
                    continue;
                };
                if !t.y.iter().any(|v| v.is_finite()) {
                    continue;
                }
                series.push(Series {
                    label: format!("{}{suffix}", m.name),
                    source: format!("{file}:{column}"),
                    x: t.x.clone(),
                    y: t.y.clone(),
                    colour: k,
                    dash: series.len(),
                    markers: false,
                    x_column: None,
                });
            }
        }
        // No chart without data (issue 38): a quantity zero throughout in every mechanism
        // (the free moment of one cylinder) says nothing a chart could show.
        let zero = |s: &Series| s.y.iter().all(|v| !v.is_finite() || *v == 0.0);
        if series.iter().all(zero) {
            return None;
        }
        let chart = LineChart {
            title: spec.title.clone(),
            x_label: "crank angle θ, °".into(),
            y_label: spec.y_label.clone(),
            y_unit: spec.unit.clone(),
            series,
            zero_line: spec.zero_line,
            x_categories: None,
            angle_axis: true,
            ..LineChart::default()
        };
        Some((
            format!("{}.svg", spec.file),
            svg::line_chart(&chart),
            format!("{}: every mechanism over crank angle", spec.title),
        ))
    };
    specs.par_iter().filter_map(chart).collect()
}

/// The locus charts (`locus.rs`): the shaking force's F_y against F_x over the run, every
/// mechanism whose rows have both (issue 24's polar plot), each the thinned locus its run
/// recorded.
pub(super) fn locus_charts(
    s: &CaseSummary,
    data: &[Option<ChartData>],
) -> Vec<(String, String, String)> {
    let mut out = Vec::new();
    for (file, x_column, y_column) in LOCI {
        let mut chart = LocusChart {
            title: "Shaking force on the frame: F_y against F_x".into(),
            x_label: "F_x".into(),
            y_label: "F_y".into(),
            unit: "N".into(),
            ..LocusChart::default()
        };
        for (k, m) in s.mechanisms.iter().enumerate() {
            let Some(d) = &data[k] else { continue };
            let Some(t) = d.traces.get(&locus_key(x_column, y_column)) else {
                continue;
            };
            if t.x.is_empty() {
                continue;
            }
            chart.series.push(Series {
                label: m.name.clone(),
                source: format!("{}:{y_column}", d.file),
                x: t.x.clone(),
                y: t.y.clone(),
                colour: k,
                dash: chart.series.len(),
                markers: false,
                x_column: None,
            });
            chart.x_columns.push(x_column.to_string());
        }
        if chart.series.is_empty() {
            continue;
        }
        out.push((
            format!("{file}.svg"),
            locus_chart(&chart),
            "Shaking force on the frame, the tip of its vector over the run (the crank axis at \
             the origin, the cylinder along +y; equal scales; a dot at the first step): every \
             mechanism"
                .into(),
        ));
    }
    out
}
