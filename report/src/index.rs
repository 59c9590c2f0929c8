//! `<out>/index.html`: every case, sweep and optimisation of an output folder, each linked to
//! its report (or, without one, to its results), and a table of headline metrics per case and
//! mechanism.

use crate::data;
use crate::doc::{href, Align, Block, Doc};
use crate::numbers::fmt_num;
use std::borrow::Cow;
use std::collections::BTreeMap;
use std::path::Path;

/// How a headline cell is read from a mechanism's metrics.
#[derive(Debug, Clone, Copy)]
enum Cell {
    /// The metric as it is.
    Metric(&'static str),
    /// The larger magnitude of a signed maximum and minimum (the machine's peak torque).
    Peak(&'static str, &'static str),
}

impl Cell {
    fn value(self, m: &data::MechanismSummary) -> Option<f64> {
        match self {
            Cell::Metric(k) => {
                let v = m.get(k)?;
                Some(if k.ends_with("_power_mean") {
                    round_off_to_zero(v, k, m)
                } else {
                    v
                })
            }
            Cell::Peak(hi, lo) => Some(m.get(hi)?.abs().max(m.get(lo)?.abs())),
        }
    }
}

/// The headline columns, the whole machine's (issue 35: every cylinder at its own crank
/// angle): (title, the machine's figure, alternatives for a summary without it of a machine of
/// one cylinder, whose figures are its cylinder's; the first present is shown).
const HEADLINES: &[(&str, Cell, &[Cell])] = &[
    (
        "machine: peak drive torque, N·m",
        Cell::Peak("machine_torque_max", "machine_torque_min"),
        &[
            Cell::Metric("total_torque_max"),
            Cell::Metric("inertial_torque_max"),
        ],
    ),
    (
        "machine: peak main-journal load, N",
        Cell::Metric("machine_main_bearing_force_max"),
        &[
            Cell::Metric("total_main_bearing_force_max"),
            Cell::Metric("inertial_main_bearing_force_max"),
        ],
    ),
    (
        "machine: peak crank-pin load, N",
        Cell::Metric("machine_crank_pin_force_max"),
        &[
            Cell::Metric("total_crank_pin_force_max"),
            Cell::Metric("inertial_crank_pin_force_max"),
        ],
    ),
    (
        "machine: mean drive power, W",
        Cell::Metric("machine_power_mean"),
        &[
            Cell::Metric("total_power_mean"),
            Cell::Metric("inertial_power_mean"),
        ],
    ),
    (
        "machine: mean power loss, W",
        Cell::Metric("machine_loss_power_mean"),
        &[Cell::Metric("power_loss_mean")],
    ),
    (
        "machine: mechanical efficiency",
        Cell::Metric("machine_mechanical_efficiency"),
        &[Cell::Metric("mechanical_efficiency")],
    ),
];

/// A mean drive power `v` (metric `metric`, `<family>_power_mean`, the machine's
/// `machine_power_mean` too) as 0 when it is below 1e-12 of the largest |T|·|ω| of the run
/// (the family's peak torque, the machine's the larger of |`machine_torque_max`| and
/// |`machine_torque_min`|, times the crank's peak speed): the round-off left of a zero mean,
/// e.g. an inertia-only run over whole cycles at constant speed, whose drive work is the
/// kinetic energy change, 0 (a headline of "−5.6e−11 W" would read as a result). The case's
/// own metric tables keep the raw value.
fn round_off_to_zero(v: f64, metric: &str, m: &data::MechanismSummary) -> f64 {
    let family = metric.trim_end_matches("_power_mean");
    let torque = if family == "machine" {
        Cell::Peak("machine_torque_max", "machine_torque_min")
            .value(m)
            .unwrap_or(f64::NAN)
    } else {
        m.get(&format!("{family}_torque_max")).unwrap_or(f64::NAN)
    };
    let scale = torque * m.get("crankshaft_angular_velocity_max").unwrap_or(f64::NAN);
    if v.abs() < 1e-12 * scale {
        0.0
    } else {
        v
    }
}

/// The machine's layout in a few words: "inline, 3 cylinders"; "1 cylinder" without a layout.
fn layout_cell(s: &data::CaseSummary) -> String {
    let cylinders = if s.cylinders == 1 {
        "1 cylinder".to_string()
    } else {
        format!("{} cylinders", s.cylinders)
    };
    match &s.layout_kind {
        Some(kind) => format!("{kind}, {cylinders}"),
        None => cylinders,
    }
}

/// The folders of `dir` (not hidden), sorted by name.
fn folders(dir: &Path) -> anyhow::Result<Vec<String>> {
    let mut names = Vec::new();
    for entry in std::fs::read_dir(dir)? {
        let entry = entry?;
        let name = entry.file_name().to_string_lossy().into_owned();
        if entry.file_type()?.is_dir() && !name.starts_with('.') {
            names.push(name);
        }
    }
    names.sort();
    Ok(names)
}

/// The link to a folder's report, else to its results file.
fn target(dir: &Path, name: &str, results: &str) -> String {
    if dir.join(name).join("report.html").is_file() {
        href(&format!("{name}/report.html"))
    } else {
        href(&format!("{name}/{results}"))
    }
}

/// Writes `<out>/index.html`: the folders listed, then a section for each kind that has any.
pub(super) fn index(out_dir: &Path, known: &Known) -> anyhow::Result<()> {
    let listing = Listing::read(out_dir, known)?;
    let mut doc = Doc {
        title: "cardan results".into(),
        blocks: Vec::new(),
    };
    let optimized = if listing.optimizations.is_empty() {
        String::new()
    } else {
        format!(", {} optimisation(s)", listing.optimizations.len())
    };
    doc.push(Block::Paragraph(format!(
        "{} case(s){optimized} and {} sweep(s). Headline metrics: the whole machine's, every cylinder at \
         its own crank angle (`machine_*`; in a summary without them, of a machine of one \
         cylinder, its cylinder's: the total loads where a gas model adds them, else the \
         inertial ones); — where a mechanism has no such metric.",
        listing.cases.len(),
        listing.sweeps.len()
    )));
    if !listing.cases.is_empty() {
        push_cases(&mut doc, out_dir, &listing.cases, &listing.summaries);
    }
    if !listing.sweeps.is_empty() {
        push_sweeps(&mut doc, out_dir, &listing.sweeps);
    }
    if !listing.optimizations.is_empty() {
        push_optimizations(&mut doc, &listing.optimizations);
    }
    crate::files::write_file_replacing(&out_dir.join("index.html"), doc.html().as_bytes())
}

/// The summaries of case folders known without reading them (a run's own, as it wrote
/// them), by folder name, mechanisms in the order of the default reference.
pub(super) type Known<'a> = BTreeMap<&'a str, &'a data::CaseSummary>;

/// An output folder's folders by kind, each kind in the order of [`folders`].
struct Listing<'a> {
    /// The case folders whose summary was read.
    cases: Vec<String>,
    /// Their summaries, one per case, in the same order: those known, and those read.
    summaries: Vec<Cow<'a, data::CaseSummary>>,
    /// The sweep folders (those holding `sweep.csv`).
    sweeps: Vec<String>,
    /// The optimisation folders (see [`OPTIMUM_CHART`]).
    optimizations: Vec<String>,
}

impl<'a> Listing<'a> {
    /// Sorts `out_dir`'s folders by kind, reading each case's summary but those `known`.
    fn read(out_dir: &Path, known: &Known<'a>) -> anyhow::Result<Self> {
        let mut listing = Listing {
            cases: Vec::new(),
            summaries: Vec::new(),
            sweeps: Vec::new(),
            optimizations: Vec::new(),
        };
        for name in folders(out_dir)? {
            let dir = out_dir.join(&name);
            if dir.join("sweep.csv").is_file() {
                listing.sweeps.push(name);
            } else if dir.join(OPTIMUM_CHART).is_file() && dir.join("report.md").is_file() {
                listing.optimizations.push(name);
            } else if let Some(s) = known.get(name.as_str()) {
                listing.cases.push(name);
                listing.summaries.push(Cow::Borrowed(*s));
            } else if dir.join("summary.json").is_file() {
                match data::read_summary(&dir.join("summary.json"), None) {
                    Ok((s, _)) => {
                        listing.cases.push(name);
                        listing.summaries.push(Cow::Owned(s));
                    }
                    // Gone since it was listed: another run is replacing this folder (and writes
                    // the index again when it has). The file may be back by the time this looks,
                    // so the read's own error says so, not a second look at the folder.
                    Err(e)
                        if e.chain().any(|c| {
                            c.downcast_ref::<std::io::Error>()
                                .is_some_and(|io| io.kind() == std::io::ErrorKind::NotFound)
                        }) => {}
                    Err(e) => return Err(e),
                }
            }
        }
        Ok(listing)
    }
}

/// The cases' section: their links, the headline table and what its peaks mean.
fn push_cases(
    doc: &mut Doc,
    out_dir: &Path,
    cases: &[String],
    summaries: &[Cow<data::CaseSummary>],
) {
    doc.push(Block::Heading(2, "Cases".into()));
    doc.push(Block::Links(
        cases
            .iter()
            .map(|c| (c.clone(), target(out_dir, c, "summary.json"), String::new()))
            .collect(),
    ));
    doc.push(Block::Heading(2, "Headline metrics".into()));
    doc.push(headline_table(cases, summaries));
    doc.push(Block::Paragraph(
        "Mean drive power: of the torque the drive applies to the crankshaft, positive in \
         the direction of rotation: positive when the drive delivers power to the machine \
         (a pump's need), negative when the machine delivers it (an engine whose gas drives \
         the crank). Peaks are magnitudes: the peak drive torque is the larger of \
         |`machine_torque_max`| and |`machine_torque_min`|. A main-journal or crank-pin load \
         is the peak over the machine's journals or pins."
            .into(),
    ));
}

/// The headline table: a row per case and mechanism, a column per [`HEADLINES`] entry.
fn headline_table(cases: &[String], summaries: &[Cow<data::CaseSummary>]) -> Block {
    let mut header = vec![
        "case".to_string(),
        "machine".to_string(),
        "layout".to_string(),
        "mechanism".to_string(),
    ];
    let mut align = vec![Align::Left; 4];
    for (title, _, _) in HEADLINES {
        header.push(title.to_string());
        align.push(Align::Right);
    }
    let mut rows = Vec::new();
    for (c, s) in cases.iter().zip(summaries) {
        for m in &s.mechanisms {
            let mut row = vec![
                c.clone(),
                s.machine.clone(),
                layout_cell(s),
                format!("`{}`", m.name),
            ];
            for (_, machine, one_cylinder) in HEADLINES {
                let v = machine.value(m).or_else(|| {
                    // A cylinder's figure is the machine's only for a machine of one.
                    (s.cylinders == 1)
                        .then(|| one_cylinder.iter().find_map(|c| c.value(m)))
                        .flatten()
                });
                row.push(match v {
                    Some(v) => fmt_num(v),
                    None => "—".into(),
                });
            }
            rows.push(row);
        }
    }
    Block::Table {
        header,
        align,
        rows,
    }
}

/// The sweeps' section: a link to each with its number of points.
fn push_sweeps(doc: &mut Doc, out_dir: &Path, sweeps: &[String]) {
    doc.push(Block::Heading(2, "Sweeps".into()));
    doc.push(Block::Links(
        sweeps
            .iter()
            .map(|s| {
                let points = folders(&out_dir.join(s)).map_or(0, |f| {
                    f.iter()
                        .filter(|p| out_dir.join(s).join(p).join("summary.json").is_file())
                        .count()
                });
                (
                    s.clone(),
                    target(out_dir, s, "sweep.csv"),
                    format!("{points} points"),
                )
            })
            .collect(),
    ));
}

/// The optimisations' section: a link to each one's report.
fn push_optimizations(doc: &mut Doc, optimizations: &[String]) {
    doc.push(Block::Heading(2, "Optimisations".into()));
    doc.push(Block::Links(
        optimizations
            .iter()
            .map(|o| {
                (
                    o.clone(),
                    href(&format!("{o}/report.md")),
                    "each mechanism at its own optimum; compared side by side in \
                     at-optima/report.html"
                        .to_string(),
                )
            })
            .collect(),
    ));
}

/// The chart only an optimisation's folder holds (`[optimize]`, issue 40: its folder has no
/// `summary.json` of its own, each mechanism's search in a folder of its own): how the index
/// tells one.
const OPTIMUM_CHART: &str = "convergence.svg";

#[cfg(test)]
mod tests {
    use super::*;

    fn mechanism(metrics: &[(&str, f64)]) -> data::MechanismSummary {
        data::MechanismSummary {
            name: "m".into(),
            metrics: metrics.iter().map(|(k, v)| (k.to_string(), *v)).collect(),
            units: Default::default(),
            joints: Vec::new(),
            chamber: None,
            cycle_starts: Vec::new(),
            runup: Vec::new(),
        }
    }

    #[test]
    fn a_round_off_mean_power_is_shown_as_zero_and_a_real_one_is_not() {
        let m = mechanism(&[
            ("inertial_torque_max", 556.0),
            ("crankshaft_angular_velocity_max", 628.3),
        ]);
        // 556 N·m × 628 rad/s = 3.5e5 W: 5.6e-11 W is 1.6e-16 of it.
        assert_eq!(round_off_to_zero(-5.6e-11, "inertial_power_mean", &m), 0.0);
        assert_eq!(round_off_to_zero(8309.0, "inertial_power_mean", &m), 8309.0);
        assert_eq!(round_off_to_zero(1e-3, "inertial_power_mean", &m), 1e-3);
        // The machine's scale: its peak torque is the larger of its signed extremes.
        let machine = mechanism(&[
            ("machine_torque_max", -1.0),
            ("machine_torque_min", -556.0),
            ("crankshaft_angular_velocity_max", 628.3),
        ]);
        assert_eq!(
            round_off_to_zero(-5.6e-11, "machine_power_mean", &machine),
            0.0
        );
        assert_eq!(
            round_off_to_zero(-1e-3, "machine_power_mean", &machine),
            -1e-3
        );
        // Without the scale the value stays as it is.
        let bare = mechanism(&[("inertial_torque_max", 556.0)]);
        assert_eq!(
            round_off_to_zero(-5.6e-11, "inertial_power_mean", &bare),
            -5.6e-11
        );
    }
}
