//! Reading a run's output back: `summary.json`, the needed columns of the per-step CSVs (a
//! plain comma split: the runner writes numbers only, no quoting), and `sweep.csv`.

use anyhow::{bail, Context};
use serde_json::Value;
use std::collections::BTreeMap;
use std::path::Path;

/// One mechanism of a `summary.json`.
#[derive(Debug, Clone)]
pub struct MechanismSummary {
    pub name: String,
    /// Metric values (NaN where the file holds `null`).
    pub metrics: BTreeMap<String, f64>,
    pub units: BTreeMap<String, String>,
    /// Joint names of the topology.
    pub joints: Vec<String>,
    /// The gas chamber its piston works on (`summary.json`'s `chamber`), if the case has one.
    pub chamber: Option<Chamber>,
    /// A solved motion's (time s, crank speed rad/s) at the start of every cycle it ran, the
    /// reported one's last (`summary.json`'s `cycle_starts`); empty without.
    pub cycle_starts: Vec<(f64, f64)>,
    /// A solved motion's (time s, crank speed rad/s) through its cycles before the reported
    /// one, thinned, to the reported cycle's start (`summary.json`'s `runup`); empty without.
    pub runup: Vec<(f64, f64)>,
}

/// The gas chamber of a crank train (`summary.json`'s `chamber`): V = V_comp + A·(x_TDC − x),
/// x the piston's position (Karhula 2008, A6.1.1.7).
#[derive(Debug, Clone, PartialEq)]
pub struct Chamber {
    /// The piston whose position column (`<piston>_position_m`) gives the volume.
    pub piston: String,
    /// x_TDC, m.
    pub piston_top: f64,
    /// The crown area of all the pistons on the chamber, m².
    pub piston_area: f64,
    /// V_comp, m³.
    pub clearance_volume: f64,
    /// V_stroke, m³.
    pub swept_volume: f64,
}

impl Chamber {
    /// The chamber's volume at the piston position `x` (m), m³.
    pub fn volume(&self, x: f64) -> f64 {
        self.clearance_volume + self.piston_area * (self.piston_top - x)
    }

    fn read(v: &Value) -> Option<Self> {
        let num = |k: &str| v.get(k).and_then(Value::as_f64).filter(|x| x.is_finite());
        Some(Self {
            piston: v.get("piston")?.as_str()?.to_string(),
            piston_top: num("piston_top_m")?,
            piston_area: num("piston_area_m2")?,
            clearance_volume: num("clearance_volume_m3")?,
            swept_volume: num("swept_volume_m3")?,
        })
    }
}

/// `summary.json`'s `cycle_starts` or `runup` (`time_s` and `crank_speed_rad_s`, of one
/// length) as (time, speed) pairs; empty where the two lists are not numbers of one length.
fn speed_over_time(v: &Value) -> Vec<(f64, f64)> {
    let list =
        |k: &str| -> Option<Vec<f64>> { v.get(k)?.as_array()?.iter().map(Value::as_f64).collect() };
    match (list("time_s"), list("crank_speed_rad_s")) {
        (Some(t), Some(w)) if t.len() == w.len() => t.into_iter().zip(w).collect(),
        _ => Vec::new(),
    }
}

impl MechanismSummary {
    /// The metric's value, if the mechanism has it.
    pub fn get(&self, metric: &str) -> Option<f64> {
        self.metrics.get(metric).copied()
    }

    /// The metric's unit as written in `summary.json` (empty if unknown).
    pub fn unit(&self, metric: &str) -> &str {
        self.units.get(metric).map_or("", String::as_str)
    }
}

/// A case's `summary.json`, mechanisms in report order (reference first).
#[derive(Debug, Clone)]
pub struct CaseSummary {
    pub case: String,
    pub machine: String,
    pub gas_model: Option<String>,
    /// The machine the balance metrics are of (`summary.json`'s `layout`), in words: its kind,
    /// cylinders and balancing devices; `None` in a summary without it.
    pub layout: Option<String>,
    /// The machine's cylinders (`layout.cylinders`; 1 in a summary without a layout).
    pub cylinders: usize,
    /// The layout's kind (`layout.kind`: "inline", "vee", ...), if the summary has one.
    pub layout_kind: Option<String>,
    pub mechanisms: Vec<MechanismSummary>,
    /// The run's warnings (`summary.json`'s `warnings`), e.g. a grid too coarse for its peaks.
    pub warnings: Vec<String>,
}

/// The order of mechanisms in a report: the reference first, then registry order (the order
/// of `cardan_mechanism::MECHANISMS`), then by name.
pub fn order_mechanisms(names: &mut [String], reference: &str) {
    let rank = |n: &str| {
        if n == reference {
            return (0, 0);
        }
        let k = cardan_mechanism::MECHANISMS
            .iter()
            .position(|e| e.name == n)
            .unwrap_or(usize::MAX);
        (1, k)
    };
    names.sort_by(|a, b| rank(a).cmp(&rank(b)).then_with(|| a.cmp(b)));
}

impl CaseSummary {
    /// Whose figures the per-joint and per-crank-train metrics are, when the machine has more
    /// than one cylinder: the mechanism run at the machine's crank angle, cylinder 1 for every
    /// layout but a vee (whose pair shares a pin at the machine angle); `None` for a machine of
    /// one cylinder, whose figures they are.
    pub fn one_cylinder(&self) -> Option<&'static str> {
        (self.cylinders > 1).then(|| {
            if self.layout_kind.as_deref() == Some("vee") {
                "one cylinder at the machine's crank angle"
            } else {
                "cylinder 1"
            }
        })
    }

    /// Whether the machine is an engine (`machine = "engine"`: the gas drives the crank) rather
    /// than a pump or compressor.
    pub fn is_engine(&self) -> bool {
        self.machine == "engine"
    }
}

/// Load families in display order: the registry's (inertial, gas, total), then by name.
pub fn family_rank(f: &str) -> (usize, String) {
    let k = ["inertial", "gas", "total"]
        .iter()
        .position(|x| *x == f)
        .unwrap_or(3);
    (k, f.to_string())
}

/// The reference mechanism: `requested` if given (it must be present), else the first of the
/// registry's order that is present (the slider-crank when the case has it), else the first
/// by name.
pub fn pick_reference(names: &[String], requested: Option<&str>) -> anyhow::Result<String> {
    if let Some(r) = requested {
        if names.iter().any(|n| n == r) {
            return Ok(r.to_string());
        }
        bail!(
            "reference mechanism \"{r}\" is not among the mechanisms of the results ({})",
            names.join(", ")
        );
    }
    let mut sorted = names.to_vec();
    order_mechanisms(&mut sorted, "");
    sorted
        .into_iter()
        .next()
        .context("no mechanisms in the results")
}

/// Reads `summary.json`; mechanisms ordered by [`order_mechanisms`] around the reference
/// chosen by [`pick_reference`]. Returns the summary and the reference's name.
pub fn read_summary(path: &Path, reference: Option<&str>) -> anyhow::Result<(CaseSummary, String)> {
    let text = crate::files::read_text(path, crate::files::RESULT_RECORD)
        .with_context(|| format!("read {}", path.display()))?;
    let json: Value =
        serde_json::from_str(&text).with_context(|| format!("parse {}", path.display()))?;
    summary_of(&json, path, reference)
}

/// [`read_summary`] of the `summary.json` at `path` whose contents are `json`: the run's
/// own, which writes `json` there (its numbers read back as they are: serde_json's
/// `float_roundtrip`), or the file's as read.
pub fn summary_of(
    json: &Value,
    path: &Path,
    reference: Option<&str>,
) -> anyhow::Result<(CaseSummary, String)> {
    let string = |key: &str| json.get(key).and_then(Value::as_str).map(String::from);
    let Some(mechanisms) = json.get("mechanisms").and_then(Value::as_object) else {
        bail!("{}: no \"mechanisms\" object", path.display());
    };
    let mut names: Vec<String> = mechanisms.keys().cloned().collect();
    let reference =
        pick_reference(&names, reference).with_context(|| path.display().to_string())?;
    order_mechanisms(&mut names, &reference);
    let mechanisms = names
        .iter()
        .map(|name| {
            let m = &mechanisms[name];
            let metrics = m
                .get("metrics")
                .and_then(Value::as_object)
                .map(|o| {
                    o.iter()
                        .map(|(k, v)| (k.clone(), v.as_f64().unwrap_or(f64::NAN)))
                        .collect()
                })
                .unwrap_or_default();
            let units = m
                .get("units")
                .and_then(Value::as_object)
                .map(|o| {
                    o.iter()
                        .map(|(k, v)| (k.clone(), v.as_str().unwrap_or("").to_string()))
                        .collect()
                })
                .unwrap_or_default();
            let joints = m
                .get("joints")
                .and_then(Value::as_object)
                .map(|o| o.keys().cloned().collect())
                .unwrap_or_default();
            MechanismSummary {
                name: name.clone(),
                metrics,
                units,
                joints,
                chamber: m.get("chamber").and_then(Chamber::read),
                cycle_starts: m.get("cycle_starts").map_or_else(Vec::new, speed_over_time),
                runup: m.get("runup").map_or_else(Vec::new, speed_over_time),
            }
        })
        .collect();
    Ok((
        CaseSummary {
            case: string("case").unwrap_or_default(),
            machine: string("machine").unwrap_or_default(),
            gas_model: string("gas_model"),
            layout: json.get("layout").map(layout_words),
            cylinders: json
                .get("layout")
                .and_then(|l| l.get("cylinders"))
                .and_then(Value::as_f64)
                .filter(|n| n.is_finite() && *n >= 1.0)
                .map_or(1, |n| n.round() as usize),
            layout_kind: json
                .get("layout")
                .and_then(|l| l.get("kind"))
                .and_then(Value::as_str)
                .map(String::from),
            mechanisms,
            warnings: json
                .get("warnings")
                .and_then(Value::as_array)
                .map(|a| {
                    a.iter()
                        .filter_map(Value::as_str)
                        .map(String::from)
                        .collect()
                })
                .unwrap_or_default(),
        },
        reference,
    ))
}

/// `summary.json`'s `layout` in words: "inline, 4 cylinders; counterweight 0.5 of the
/// reciprocating mass, Lanchester shafts" (no devices: "no balancing device").
fn layout_words(layout: &Value) -> String {
    let kind = layout.get("kind").and_then(Value::as_str).unwrap_or("?");
    let n = layout.get("cylinders").and_then(Value::as_u64).unwrap_or(0);
    let mut devices = Vec::new();
    if let Some(c) = layout.get("counterweight").and_then(Value::as_f64) {
        devices.push(format!(
            "crank counterweight ({c} of the reciprocating mass)"
        ));
    }
    if layout.get("balance_shafts").and_then(Value::as_str) == Some("lanchester") {
        devices.push("Lanchester shafts".to_string());
    }
    if layout.get("cardan_counterweights").and_then(Value::as_bool) == Some(true) {
        devices.push("cardan counterweight pair".to_string());
    }
    let devices = if devices.is_empty() {
        "no balancing device".to_string()
    } else {
        devices.join(", ")
    };
    let cylinders = if n == 1 { "cylinder" } else { "cylinders" };
    format!("{kind}, {n} {cylinders}; {devices}")
}

/// Some columns of a per-step CSV.
#[derive(Debug, Clone, Default)]
pub struct Columns {
    /// The whole header.
    pub header: Vec<String>,
    /// The selected columns by name (empty cells are NaN).
    pub values: BTreeMap<String, Vec<f64>>,
}

impl Columns {
    /// The column `name`, if it was selected and exists.
    pub fn get(&self, name: &str) -> Option<&[f64]> {
        self.values.get(name).map(Vec::as_slice)
    }
}

/// Reads the columns of the CSV at `path` whose header names `select` picks. Numbers only:
/// fields are split at commas; an empty cell is NaN, a cell that is not a number an error.
pub fn read_columns(
    path: &Path,
    select: impl Fn(&[String]) -> Vec<String>,
) -> anyhow::Result<Columns> {
    let bytes = crate::files::read_limited(path, crate::files::PER_STEP_FILE)
        .with_context(|| format!("read {}", path.display()))?;
    let text =
        std::str::from_utf8(&bytes).with_context(|| format!("{}: not UTF-8", path.display()))?;
    let header_end = text.find('\n').unwrap_or(text.len());
    let header: Vec<String> = text[..header_end]
        .split(',')
        .map(|s| s.trim().to_string())
        .collect();
    let mut wanted = select(&header);
    let mut seen = std::collections::BTreeSet::new();
    wanted.retain(|w| seen.insert(w.clone()));
    // The slot of each header column (usize::MAX: not wanted).
    let mut slot_of = vec![usize::MAX; header.len()];
    for (slot, w) in wanted.iter().enumerate() {
        if let Some(k) = header.iter().position(|h| h == w) {
            slot_of[k] = slot;
        }
    }
    let last = slot_of.iter().rposition(|s| *s != usize::MAX);
    let rows_guess = text.len() / (header.len() * 12).max(1);
    let mut data: Vec<Vec<f64>> = vec![Vec::with_capacity(rows_guess); wanted.len()];
    if let Some(last) = last {
        // A byte scan: each field up to the last wanted one, then on to the end of the line.
        let bytes = text.as_bytes();
        let (mut i, mut row) = (header_end + 1, 0usize);
        while i < bytes.len() {
            let mut field = 0;
            loop {
                let end = memchr::memchr2(b',', b'\n', &bytes[i..]).map_or(bytes.len(), |p| i + p);
                let slot = slot_of[field];
                if slot != usize::MAX {
                    let cell = text[i..end].trim_end_matches('\r');
                    let v = if cell.is_empty() {
                        f64::NAN
                    } else {
                        cell.parse::<f64>().with_context(|| {
                            format!(
                                "{}: row {}, column {}: \"{cell}\" is not a number",
                                path.display(),
                                row + 2,
                                header[field]
                            )
                        })?
                    };
                    data[slot].push(v);
                }
                i = end + 1;
                if end >= bytes.len() || bytes[end] == b'\n' {
                    break;
                }
                field += 1;
                if field > last {
                    // Skip the rest of the line.
                    i = memchr::memchr(b'\n', &bytes[end..]).map_or(bytes.len(), |p| end + p + 1);
                    break;
                }
            }
            // A short row: its missing wanted cells are NaN.
            for k in field + 1..=last {
                if slot_of[k] != usize::MAX {
                    data[slot_of[k]].push(f64::NAN);
                }
            }
            row += 1;
        }
    }
    let values = wanted
        .into_iter()
        .zip(data)
        .filter(|(w, _)| header.contains(w))
        .collect();
    Ok(Columns { header, values })
}

/// A swept field's value, e.g. `900 rpm`: the number and the unit, if it reads as one.
pub fn parse_quantity(s: &str) -> Option<(f64, String)> {
    let s = s.trim();
    let split = s.find(char::is_whitespace).unwrap_or(s.len());
    let (number, unit) = s.split_at(split);
    let v: f64 = number.parse().ok()?;
    v.is_finite().then(|| (v, unit.trim().to_string()))
}

/// `sweep.csv`.
#[derive(Debug, Clone)]
pub struct SweepTable {
    /// The swept fields' dotted paths.
    pub swept: Vec<String>,
    /// Mechanism names (reference first).
    pub mechanisms: Vec<String>,
    /// Point names, in file order.
    pub cases: Vec<String>,
    /// `params[row][k]`: the text of swept field k at that point.
    pub params: Vec<Vec<String>>,
    /// `<mechanism>.<metric>` → value per row (NaN where empty).
    pub metrics: BTreeMap<String, Vec<f64>>,
    /// Metric → unit, from the points' summaries.
    pub units: BTreeMap<String, String>,
    /// The cylinders of the first point's machine (its `summary.json`'s `layout`; 1 without
    /// one, or without a point folder).
    pub cylinders: usize,
    /// Its layout's kind, if any.
    pub layout_kind: Option<String>,
}

impl SweepTable {
    /// The column of `metric` of `mechanism`, if present.
    pub fn column(&self, mechanism: &str, metric: &str) -> Option<&[f64]> {
        self.metrics
            .get(&format!("{mechanism}.{metric}"))
            .map(Vec::as_slice)
    }
}

/// Reads `<sweep_dir>/sweep.csv`; mechanism names come from the first point's `summary.json`
/// (else from the metric columns' prefixes). Returns the table and the reference's name.
pub fn read_sweep(
    sweep_dir: &Path,
    reference: Option<&str>,
) -> anyhow::Result<(SweepTable, String)> {
    let path = sweep_dir.join("sweep.csv");
    let bytes = crate::files::read_limited(&path, crate::files::RESULT_RECORD)
        .with_context(|| format!("read {}", path.display()))?;
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(true)
        .from_reader(&bytes[..]);
    let header: Vec<String> = reader.headers()?.iter().map(String::from).collect();
    if header.first().map(String::as_str) != Some("case") {
        bail!("{}: the first column is not \"case\"", path.display());
    }
    let mut rows: Vec<Vec<String>> = Vec::new();
    for r in reader.records() {
        let r = r.with_context(|| format!("read {}", path.display()))?;
        rows.push(r.iter().map(String::from).collect());
    }
    // Mechanism names and units from the points' summaries.
    let mut names: Vec<String> = Vec::new();
    let mut units = BTreeMap::new();
    let (mut cylinders, mut layout_kind) = (1, None);
    for row in &rows {
        let summary = sweep_dir.join(&row[0]).join("summary.json");
        if !summary.is_file() {
            continue;
        }
        let (s, _) = read_summary(&summary, None)?;
        cylinders = s.cylinders;
        layout_kind = s.layout_kind.clone();
        for m in &s.mechanisms {
            if !names.contains(&m.name) {
                names.push(m.name.clone());
            }
            for (k, u) in &m.units {
                units.entry(k.clone()).or_insert_with(|| u.clone());
            }
        }
        break;
    }
    let is_metric_column = |h: &str, names: &[String]| {
        names.iter().any(|m| {
            h.strip_prefix(m.as_str())
                .is_some_and(|r| r.starts_with('.'))
        })
    };
    if names.is_empty() {
        // No point folder: the prefixes of the columns whose rest is a registered metric.
        for h in &header[1..] {
            if let Some((m, metric)) = h.split_once('.') {
                if cardan_metrics::find(metric).is_some() && !names.iter().any(|n| n == m) {
                    names.push(m.to_string());
                }
            }
        }
    }
    if names.is_empty() {
        bail!("{}: no mechanism columns", path.display());
    }
    let first_metric = header
        .iter()
        .skip(1)
        .position(|h| is_metric_column(h, &names))
        .map_or(header.len(), |k| k + 1);
    let swept: Vec<String> = header[1..first_metric].to_vec();
    let reference =
        pick_reference(&names, reference).with_context(|| path.display().to_string())?;
    order_mechanisms(&mut names, &reference);
    let mut metrics = BTreeMap::new();
    for (k, h) in header.iter().enumerate().skip(first_metric) {
        let column = rows
            .iter()
            .map(|r| {
                let cell = r.get(k).map_or("", String::as_str);
                if cell.is_empty() {
                    Ok(f64::NAN)
                } else {
                    cell.parse::<f64>()
                        .with_context(|| format!("{}: column {h}: \"{cell}\"", path.display()))
                }
            })
            .collect::<anyhow::Result<Vec<f64>>>()?;
        metrics.insert(h.clone(), column);
    }
    Ok((
        SweepTable {
            swept,
            mechanisms: names,
            cases: rows.iter().map(|r| r[0].clone()).collect(),
            params: rows.iter().map(|r| r[1..first_metric].to_vec()).collect(),
            metrics,
            units,
            cylinders,
            layout_kind,
        },
        reference,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_are_read_by_name_with_empty_and_missing_cells_as_nan() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("m.csv");
        std::fs::write(
            &path,
            "a,b,c,d\r\n1,2,3,4\r\n5,,7,8\r\n9,10\r\n-1.5e3,0,1,2",
        )
        .unwrap();
        let cols = read_columns(&path, |h| {
            assert_eq!(h, ["a", "b", "c", "d"]);
            vec!["c".into(), "a".into(), "zz".into(), "b".into(), "c".into()]
        })
        .unwrap();
        assert_eq!(cols.get("a").unwrap(), [1.0, 5.0, 9.0, -1500.0]);
        let b = cols.get("b").unwrap();
        assert_eq!((b[0], b[2], b[3]), (2.0, 10.0, 0.0));
        assert!(b[1].is_nan());
        let c = cols.get("c").unwrap();
        assert_eq!((c[0], c[1], c[3]), (3.0, 7.0, 1.0));
        assert!(c[2].is_nan());
        assert!(cols.get("zz").is_none() && cols.get("d").is_none());
        std::fs::write(&path, "a,b\n1,x\n").unwrap();
        let e = read_columns(&path, |_| vec!["b".into()]).unwrap_err();
        assert!(e.to_string().contains("row 2, column b"), "{e}");
    }

    #[test]
    fn quantities_and_reference_choice() {
        assert_eq!(parse_quantity("900 rpm"), Some((900.0, "rpm".into())));
        assert_eq!(parse_quantity("0.14"), Some((0.14, String::new())));
        assert_eq!(parse_quantity("titanium"), None);
        // The registry's first mechanism present, whatever the order of the names.
        let (first, second) = (
            cardan_mechanism::MECHANISMS[0].name,
            cardan_mechanism::MECHANISMS[1].name,
        );
        let names: Vec<String> = ["zeta", second, first].map(String::from).to_vec();
        assert_eq!(pick_reference(&names, None).unwrap(), first);
        assert_eq!(pick_reference(&names, Some("zeta")).unwrap(), "zeta");
        assert!(pick_reference(&names, Some("nope")).is_err());
        assert_eq!(
            pick_reference(&["b".to_string(), "a".to_string()], None).unwrap(),
            "a"
        );
    }
}
