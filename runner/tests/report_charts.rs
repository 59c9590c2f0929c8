//! The charts engineers read first (issue 38), read back from the SVG and checked against the
//! CSV rows they claim to draw: the indicator diagram (`pv_diagram.svg`, `pv_diagram_log.svg`)
//! of every case with a gas chamber, the crank speed with its fluctuation band
//! (`crank_speed.svg`) of every dynamic run and the crank speed over time of a run-up
//! (`crank_speed_time.svg`), the polar load diagrams (`main_bearing_polar.svg`,
//! `main_bearing_polar_crank.svg`, `crank_pin_polar.svg`); and every chart's lines told apart by
//! their dash. Shipped configs of each kind, run in-process with their reports.

use cardan_dynamics::runup::MAX_RUNUP_POINTS;
use cardan_report::MAX_POINTS;
use cardan_runner::{run_paths, RunOptions};
use cardan_testing::chart::{attr_f64, points, Axes};
use std::collections::BTreeMap;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// The configs run: a compressor (gas, prescribed speed), an engine and a pump of solved
/// motion (dynamic), a three-cylinder machine (several journals and pins), a gas-less case,
/// and an opposed-piston engine with a crank phase (a chamber of two trains' pistons).
const CONFIGS: [&str; 7] = [
    "example-compressor",
    "balance-thesis-single-cw0",
    "karhula-engine-dynamic-flywheel",
    "karhula-pump-motor-runup",
    "balance-inline3",
    "karhula-r60-l140-a0-w200pi",
    "nunes-op-r26-l90-2000rpm-lead10",
];

fn out() -> &'static Path {
    static OUT: OnceLock<PathBuf> = OnceLock::new();
    OUT.get_or_init(|| {
        let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("report-charts");
        if dir.exists() {
            std::fs::remove_dir_all(&dir).unwrap();
        }
        std::fs::create_dir_all(&dir).unwrap();
        let configs = Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs");
        let paths: Vec<PathBuf> = CONFIGS
            .iter()
            .map(|c| configs.join(format!("{c}.toml")))
            .collect();
        let options = RunOptions {
            reports: true,
            ..RunOptions::default()
        };
        let report = run_paths(&paths, &dir, options);
        assert!(report.failures.is_empty(), "{:#?}", report.failures);
        dir
    })
}

/// A CSV read whole: column name → values (NaN for empty cells).
fn read_csv(path: &Path) -> BTreeMap<String, Vec<f64>> {
    let mut r = csv::Reader::from_path(path).unwrap();
    let header: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    let mut cols: Vec<Vec<f64>> = vec![Vec::new(); header.len()];
    for rec in r.records() {
        for (k, cell) in rec.unwrap().iter().enumerate() {
            cols[k].push(cell.parse().unwrap_or(f64::NAN));
        }
    }
    header.into_iter().zip(cols).collect()
}

fn summary(case: &str) -> serde_json::Value {
    let text = std::fs::read_to_string(out().join(case).join("summary.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

fn chart(case: &str, file: &str) -> Option<String> {
    std::fs::read_to_string(out().join(case).join("plots").join(file)).ok()
}

fn series<'a>(doc: &'a roxmltree::Document) -> Vec<roxmltree::Node<'a, 'a>> {
    doc.descendants()
        .filter(|n| n.attribute("class") == Some("series"))
        .collect()
}

/// The chart's factors from SI to its units (`<desc class="factors">`), (1, 1) in SI.
fn factors(doc: &roxmltree::Document) -> (f64, f64) {
    doc.descendants()
        .find(|n| n.attribute("class") == Some("factors"))
        .map_or((1.0, 1.0), |n| {
            (attr_f64(n, "data-x-factor"), attr_f64(n, "data-y-factor"))
        })
}

/// A path's pixels against the data rows it draws (`px`, `py`: data to pixels): every point
/// a row, x and y of the same row, the rows in order (to the drawing's 0.1 px); every row
/// when they fit [`MAX_POINTS`]; the first row first, the last last; both coordinates'
/// extremes drawn.
#[track_caller]
fn check_path(
    label: &str,
    node: roxmltree::Node,
    rows: &[(f64, f64)],
    px: &dyn Fn(f64) -> f64,
    py: &dyn Fn(f64) -> f64,
) {
    let pts = points(node);
    let n: usize = node.attribute("data-n").unwrap().parse().unwrap();
    assert_eq!(pts.len(), n, "{label}");
    assert!(!rows.is_empty(), "{label}");
    if rows.len() <= MAX_POINTS {
        assert_eq!(n, rows.len(), "{label}: every row");
    } else {
        assert!((4..=MAX_POINTS).contains(&n), "{label}: {n} points");
    }
    let near = |p: (f64, f64), r: (f64, f64)| {
        (p.0 - px(r.0)).abs() <= 0.06 && (p.1 - py(r.1)).abs() <= 0.06
    };
    let mut next = 0;
    for (k, p) in pts.iter().enumerate() {
        let row = (next..rows.len())
            .find(|&r| near(*p, rows[r]))
            .unwrap_or_else(|| panic!("{label}: point {k} {p:?} is no row after row {next}"));
        next = row + 1;
    }
    assert!(near(pts[0], rows[0]), "{label}: the first row first");
    assert!(
        near(pts[n - 1], rows[rows.len() - 1]),
        "{label}: the last row last"
    );
    let (xs, ys): (Vec<f64>, Vec<f64>) = rows.iter().copied().unzip();
    for (v, on) in [(&xs, 0), (&ys, 1)] {
        let hi = v.iter().copied().fold(f64::MIN, f64::max);
        let lo = v.iter().copied().fold(f64::MAX, f64::min);
        for e in [hi, lo] {
            let at = if on == 0 { px(e) } else { py(e) };
            assert!(
                pts.iter()
                    .any(|p| ((if on == 0 { p.0 } else { p.1 }) - at).abs() <= 0.06),
                "{label}: the extreme {e} drawn"
            );
        }
    }
}

/// Every case whose crank trains have a gas chamber (`summary.json`'s `chamber`) has its
/// indicator diagram, linear and log-log, one series per such mechanism: each point the
/// pressure (bar) over the volume V = V_comp + A·(x_TDC − x) (cm³) of one CSV row. The
/// compressor's volumes are the case file's: V_stroke = π/4 · (100 mm)² · 80 mm, V_comp =
/// 0.05 · V_stroke (its `clearance_ratio`), the smallest and largest volume drawn.
#[test]
fn the_indicator_diagram_draws_pressure_over_volume() {
    let mut drawn = 0;
    for case in CONFIGS {
        let s = summary(case);
        let chambers: Vec<(String, serde_json::Value)> = s["mechanisms"]
            .as_object()
            .unwrap()
            .iter()
            .filter_map(|(m, v)| Some((m.clone(), v.get("chamber")?.clone())))
            .collect();
        for file in ["pv_diagram.svg", "pv_diagram_log.svg"] {
            let Some(text) = chart(case, file) else {
                assert!(chambers.is_empty(), "{case}: no {file}");
                continue;
            };
            assert!(!chambers.is_empty(), "{case}: {file} without a chamber");
            let doc = roxmltree::Document::parse(&text).unwrap();
            let axes = Axes::of(&doc);
            let (fx, fy) = factors(&doc);
            assert_eq!((fx, fy), (1e6, 1e-5), "{case}: cm³ and bar");
            let log = doc
                .descendants()
                .any(|n| n.attribute("class") == Some("log-axes"));
            assert_eq!(log, file.contains("log"), "{case} {file}");
            let map = |v: f64, (lo, hi): (f64, f64), from: f64, size: f64, up: bool| {
                let t = if log {
                    (v.log10() - lo.log10()) / (hi.log10() - lo.log10())
                } else {
                    (v - lo) / (hi - lo)
                };
                if up {
                    from + (1.0 - t) * size
                } else {
                    from + t * size
                }
            };
            let px = |v: f64| map(v, axes.x, axes.left, axes.width, false);
            let py = |v: f64| map(v, axes.y, axes.top, axes.height, true);
            let nodes = series(&doc);
            assert_eq!(nodes.len(), chambers.len(), "{case} {file}");
            for (m, chamber) in &chambers {
                let label = format!("{case} {file} {m}");
                let csv = format!("{m}.csv");
                let source = format!("{csv}:cylinder_pressure_pa");
                let node = nodes
                    .iter()
                    .find(|n| n.attribute("data-source") == Some(source.as_str()))
                    .unwrap_or_else(|| panic!("{label}: no series of {source}"));
                let x_column = format!("{}_position_m", chamber["piston"].as_str().unwrap());
                assert_eq!(node.attribute("data-x-column"), Some(x_column.as_str()));
                let data = read_csv(&out().join(case).join(&csv));
                let num = |k: &str| chamber[k].as_f64().unwrap();
                let volume = |x: f64| {
                    num("clearance_volume_m3") + num("piston_area_m2") * (num("piston_top_m") - x)
                };
                let rows: Vec<(f64, f64)> = data[&x_column]
                    .iter()
                    .zip(&data["cylinder_pressure_pa"])
                    .filter(|(x, p)| x.is_finite() && p.is_finite())
                    .map(|(x, p)| (volume(*x) * fx, p * fy))
                    .collect();
                check_path(&label, *node, &rows, &px, &py);
                if case == "example-compressor" {
                    let swept = PI / 4.0 * 0.1f64.powi(2) * 0.08;
                    let (lo, hi) = rows
                        .iter()
                        .fold((f64::MAX, f64::MIN), |(a, b), r| (a.min(r.0), b.max(r.0)));
                    // The rows pass both dead centres (every 0.1° from 90°): exact but for
                    // the CSV's rounding.
                    assert!((lo - 0.05 * swept * 1e6).abs() < 1e-9 * lo, "{label}: {lo}");
                    assert!((hi - 1.05 * swept * 1e6).abs() < 1e-9 * hi, "{label}: {hi}");
                }
                drawn += 1;
            }
        }
    }
    // The compressor's, the two dynamic runs' and the three-cylinder machine's two
    // mechanisms, on both charts; the opposed pair with a crank phase and the gas-less case
    // have none.
    assert_eq!(drawn, 16);
}

/// Every dynamic run (the `speed_*` metrics of a solved motion) has its crank-speed chart: per
/// mechanism the CSV's crank speed in rpm over crank angle, its band from `speed_min` to
/// `speed_max` holding every row; a run at prescribed speed has none.
#[test]
fn the_crank_speed_of_a_dynamic_run_is_drawn_with_its_band() {
    let mut drawn = 0;
    for case in CONFIGS {
        let s = summary(case);
        let dynamic: Vec<(String, [f64; 2])> = s["mechanisms"]
            .as_object()
            .unwrap()
            .iter()
            .filter_map(|(m, v)| {
                let metric = |k: &str| v["metrics"].get(k)?.as_f64();
                Some((m.clone(), [metric("speed_min")?, metric("speed_max")?]))
            })
            .collect();
        let Some(text) = chart(case, "crank_speed.svg") else {
            assert!(dynamic.is_empty(), "{case}: no crank_speed.svg");
            continue;
        };
        let doc = roxmltree::Document::parse(&text).unwrap();
        let axes = Axes::of(&doc);
        let (_, fy) = factors(&doc);
        assert!((fy - 60.0 / (2.0 * PI)).abs() < 1e-15, "{case}: rpm");
        let nodes = series(&doc);
        let bands: Vec<roxmltree::Node> = doc
            .descendants()
            .filter(|n| n.attribute("class") == Some("band"))
            .collect();
        assert_eq!((nodes.len(), bands.len()), (dynamic.len(), dynamic.len()));
        for (m, [lo, hi]) in &dynamic {
            let label = format!("{case} {m}");
            let source = format!("{m}.csv:crank_speed_rad_s");
            let k = nodes
                .iter()
                .position(|n| n.attribute("data-source") == Some(source.as_str()))
                .unwrap_or_else(|| panic!("{label}: no series of {source}"));
            // The bands are in the series' order, each labelled with its mechanism.
            let (node, band) = (&nodes[k], &bands[k]);
            assert!(
                band.attribute("data-label")
                    .unwrap()
                    .starts_with(&format!("{m}:")),
                "{label}"
            );
            assert_eq!(attr_f64(*band, "data-from"), lo * fy, "{label}");
            assert_eq!(attr_f64(*band, "data-to"), hi * fy, "{label}");
            let data = read_csv(&out().join(case).join(format!("{m}.csv")));
            let rows: Vec<(f64, f64)> = data["crank_angle_deg"]
                .iter()
                .zip(&data["crank_speed_rad_s"])
                .map(|(t, w)| (*t, w * fy))
                .collect();
            for (t, w) in &rows {
                assert!(
                    *w >= lo * fy * (1.0 - 1e-12) && *w <= hi * fy * (1.0 + 1e-12),
                    "{label}: {w} rpm at {t}° outside the band"
                );
            }
            check_path(&label, *node, &rows, &|v| axes.px(v), &|v| axes.py(v));
            drawn += 1;
        }
    }
    assert_eq!(drawn, 4, "two dynamic runs of two mechanisms");
}

/// A dynamic run that solved cycles before the reported one (`summary.json`'s `cycle_starts`
/// lists more than one; the motor-driven pump's run-up from rest above all) has its crank speed
/// over time (`crank_speed_time.svg`): per mechanism the run-up (`summary.json`'s `runup`), the
/// speed at each cycle's start and the reported cycle's CSV rows over `time_s`, in rpm; its time
/// axis spans the run, from its start (t = 0, the case file's initial speed) to the reported
/// cycle's last row; a run without earlier cycles has none. The run-up is in time order from
/// the run's start to the reported cycle's first CSV row, holds every cycle start, and is
/// bounded: at most `MAX_RUNUP_POINTS` (the pump's 104 cycles of 720 steps, 75 000 steps, were
/// thinned to fit) and 65 points a cycle.
#[test]
fn the_crank_speed_of_a_run_up_is_drawn_over_time() {
    let mut drawn = Vec::new();
    for case in CONFIGS {
        let s = summary(case);
        let runs: Vec<(String, Vec<f64>, Vec<f64>, f64)> = s["mechanisms"]
            .as_object()
            .unwrap()
            .iter()
            .filter_map(|(m, v)| {
                let starts = v.get("cycle_starts")?;
                let list = |k: &str| -> Vec<f64> {
                    let a = starts[k].as_array().unwrap();
                    a.iter().map(|x| x.as_f64().unwrap()).collect()
                };
                let mean = v["metrics"]["speed_mean"].as_f64().unwrap();
                Some((m.clone(), list("time_s"), list("crank_speed_rad_s"), mean))
            })
            .filter(|(_, t, _, _)| t.len() > 1)
            .collect();
        let Some(text) = chart(case, "crank_speed_time.svg") else {
            assert!(runs.is_empty(), "{case}: no crank_speed_time.svg");
            continue;
        };
        assert!(
            !runs.is_empty(),
            "{case}: a time chart without earlier cycles"
        );
        let doc = roxmltree::Document::parse(&text).unwrap();
        let axes = Axes::of(&doc);
        let (fx, fy) = factors(&doc);
        assert_eq!(fx, 1.0, "{case}: seconds");
        assert!((fy - 60.0 / (2.0 * PI)).abs() < 1e-15, "{case}: rpm");
        let nodes = series(&doc);
        assert_eq!(nodes.len(), 3 * runs.len(), "{case}");
        let mut end = 0.0f64;
        for (m, times, speeds, mean) in &runs {
            let label = format!("{case} {m}");
            let data = read_csv(&out().join(case).join(format!("{m}.csv")));
            let (t, w) = (&data["time_s"], &data["crank_speed_rad_s"]);
            let last = t.len() - 1;
            // The run starts at t = 0; the reported cycle where the last cycle starts, and it
            // lasts its crank angle over its mean speed, 4π/ω_mean (two revolutions).
            assert_eq!(times[0], 0.0, "{label}");
            let n = times.len();
            assert!(
                (t[0] - times[n - 1]).abs() <= 1e-9 * t[0],
                "{label}: {}",
                t[0]
            );
            assert!(
                (w[0] - speeds[n - 1]).abs() <= 1e-9 * w[0],
                "{label}: {}",
                w[0]
            );
            let duration = t[last] - t[0];
            let expected = 4.0 * PI / mean;
            assert!(
                (duration - expected).abs() <= 1e-6 * expected,
                "{label}: {duration} s"
            );
            if case == "karhula-pump-motor-runup" {
                // From rest: the case file's `initial_speed = 0.0`.
                assert_eq!(speeds[0], 0.0, "{label}");
                let runup = s["mechanisms"][m]["metrics"]["runup_time"]
                    .as_f64()
                    .unwrap();
                assert!(
                    runup > 0.0 && runup < t[last],
                    "{label}: run-up time {runup} s"
                );
            }
            end = end.max(t[last]);
            let find = |source: &str| {
                let node = nodes
                    .iter()
                    .find(|n| n.attribute("data-source") == Some(source));
                let node = *node.unwrap_or_else(|| panic!("{label}: no series of {source}"));
                assert_eq!(node.attribute("data-x-column"), Some("time_s"), "{label}");
                node
            };
            let starts: Vec<(f64, f64)> = times
                .iter()
                .zip(speeds)
                .map(|(a, b)| (*a, b * fy))
                .collect();
            let node = find(&format!("summary.json:{m}:cycle_starts"));
            check_path(&label, node, &starts, &|v| axes.px(v), &|v| axes.py(v));
            let runup = runup_of(&s["mechanisms"][m], &label);
            assert_eq!(
                runup[0],
                (times[0], speeds[0]),
                "{label}: from the run's start"
            );
            assert!(
                (runup[runup.len() - 1].0 - t[0]).abs() <= 1e-9 * t[0]
                    && (runup[runup.len() - 1].1 - w[0]).abs() <= 1e-9 * w[0],
                "{label}: to the reported cycle's first row"
            );
            assert!(
                runup.windows(2).all(|p| p[0].0 < p[1].0),
                "{label}: in time order"
            );
            for (time, speed) in times.iter().zip(speeds) {
                assert!(
                    runup.contains(&(*time, *speed)),
                    "{label}: the cycle start at {time} s"
                );
            }
            assert!(
                runup.len() <= MAX_RUNUP_POINTS && runup.len() <= 65 * (n - 1) + 1,
                "{label}: {} points for {n} cycles",
                runup.len()
            );
            let points: Vec<(f64, f64)> = runup.iter().map(|(a, b)| (*a, b * fy)).collect();
            let node = find(&format!("summary.json:{m}:runup"));
            check_path(&label, node, &points, &|v| axes.px(v), &|v| axes.py(v));
            let rows: Vec<(f64, f64)> = t.iter().zip(w).map(|(a, b)| (*a, b * fy)).collect();
            let node = find(&format!("{m}.csv:crank_speed_rad_s"));
            check_path(&label, node, &rows, &|v| axes.px(v), &|v| axes.py(v));
            drawn.push(label);
        }
        // The time axis spans the run, from its start to the last row of the latest train (its
        // ends rounded out to ticks, as every chart's: not more than twice the run).
        let (lo, hi) = axes.x;
        assert!(
            lo <= 0.0 && hi >= end && hi - lo <= 2.0 * end,
            "{case}: {:?} for {end} s",
            axes.x
        );
    }
    assert!(
        drawn
            .iter()
            .filter(|l| l.starts_with("karhula-pump-motor-runup "))
            .count()
            == 2,
        "the run-up's two mechanisms: {drawn:?}"
    );
}

/// `summary.json`'s `runup` of a mechanism as (time s, speed rad/s): two lists of one length.
fn runup_of(mechanism: &serde_json::Value, label: &str) -> Vec<(f64, f64)> {
    let list = |k: &str| -> Vec<f64> {
        let a = mechanism["runup"][k].as_array();
        let a = a.unwrap_or_else(|| panic!("{label}: no runup.{k}"));
        a.iter().map(|x| x.as_f64().unwrap()).collect()
    };
    let (time, speed) = (list("time_s"), list("crank_speed_rad_s"));
    assert_eq!(time.len(), speed.len(), "{label}");
    time.into_iter().zip(speed).collect()
}

/// The bearing loads of the `prefix` (`main_bearing_` or `cylinder_`) in a CSV header: the
/// prefixes of their `_force_x_n` columns.
fn bearings(data: &BTreeMap<String, Vec<f64>>, prefix: &str) -> Vec<String> {
    data.keys()
        .filter_map(|c| c.strip_suffix("_force_x_n"))
        .filter(|p| {
            p.starts_with(prefix)
                && (prefix == "main_bearing_" || p.ends_with("_crank_pin"))
                && p.len() > prefix.len()
        })
        .map(String::from)
        .collect()
}

/// The polar load diagrams: every case whose rows hold the machine's bearing loads has the
/// main bearing's relative to the frame and to the crank and the crank pin's relative to the
/// crank, one series per mechanism, the most loaded journal or pin (its CSV peak within 1 % of
/// the largest: the chart picks by its drawn points), each point a row of the CSV turned into
/// the crank's frame by −(θ − 90°); at top dead centre (θ = 90° + k·360°) both frames draw
/// the same point.
#[test]
fn the_polar_load_diagrams_draw_the_bearing_loads() {
    let mut drawn = 0;
    for case in CONFIGS {
        for (file, prefix, crank) in [
            ("main_bearing_polar.svg", "main_bearing_", false),
            ("main_bearing_polar_crank.svg", "main_bearing_", true),
            ("crank_pin_polar.svg", "cylinder_", true),
        ] {
            let text = chart(case, file).unwrap_or_else(|| panic!("{case}: no {file}"));
            let doc = roxmltree::Document::parse(&text).unwrap();
            let axes = Axes::of(&doc);
            assert_eq!(axes.x, axes.y, "{case} {file}: equal axes");
            let nodes = series(&doc);
            let trains = summary(case)["mechanisms"].as_object().unwrap().len();
            assert_eq!(nodes.len(), trains, "{case} {file}: every crank train");
            for node in nodes {
                let source = node.attribute("data-source").unwrap();
                let (csv, y_column) = source.split_once(':').unwrap();
                let label = format!("{case} {file} {source}");
                assert_eq!(
                    node.attribute("data-frame") == Some("crank"),
                    crank,
                    "{label}"
                );
                let data = read_csv(&out().join(case).join(csv));
                let p = y_column.strip_suffix("_force_y_n").unwrap();
                assert_eq!(
                    node.attribute("data-x-column"),
                    Some(format!("{p}_force_x_n").as_str())
                );
                let peak = |p: &str| {
                    let (x, y) = (
                        &data[&format!("{p}_force_x_n")],
                        &data[&format!("{p}_force_y_n")],
                    );
                    x.iter()
                        .zip(y)
                        .map(|(a, b)| a.hypot(*b))
                        .fold(0.0, f64::max)
                };
                let all = bearings(&data, prefix);
                assert!(all.iter().any(|b| b == p), "{label}");
                let most = all.iter().map(|b| peak(b)).fold(0.0, f64::max);
                assert!(peak(p) >= 0.99 * most, "{label}: {} of {most}", peak(p));
                let theta = &data["crank_angle_deg"];
                let rows: Vec<(f64, f64)> = (0..theta.len())
                    .map(|r| {
                        let (x, y) = (data[&format!("{p}_force_x_n")][r], data[y_column][r]);
                        if crank {
                            let (s, c) = (theta[r] - 90.0).to_radians().sin_cos();
                            (x * c + y * s, -x * s + y * c)
                        } else {
                            (x, y)
                        }
                    })
                    .collect();
                // At top dead centre (θ = 90° + k·360°) the frames agree.
                let tdc: Vec<usize> = (0..theta.len())
                    .filter(|&r| (theta[r] - 90.0).rem_euclid(360.0) == 0.0)
                    .collect();
                for &r in &tdc {
                    let (x, y) = (data[&format!("{p}_force_x_n")][r], data[y_column][r]);
                    let tol = 1e-12 * x.hypot(y);
                    assert!(
                        (rows[r].0 - x).abs() <= tol && (rows[r].1 - y).abs() <= tol,
                        "{label}: the frames agree at top dead centre, row {r}"
                    );
                }
                assert!(
                    !tdc.is_empty() || csv.contains("crank2"),
                    "{label}: a TDC row"
                );
                check_path(&label, node, &rows, &|v| axes.px(v), &|v| axes.py(v));
                drawn += 1;
            }
        }
    }
    // Two mechanisms in each case, two crank trains each in the opposed pair's.
    assert_eq!(drawn, (CONFIGS.len() + 1) * 3 * 2);
}

/// Every chart's series are told apart by their dash as well as their colour (issue 38: a
/// report printed in black and white): no two series of a chart draw the same dash pattern.
#[test]
fn every_series_of_a_chart_has_its_own_dash() {
    let mut charts = 0;
    for case in CONFIGS {
        let plots = out().join(case).join("plots");
        for entry in std::fs::read_dir(&plots).unwrap() {
            let path = entry.unwrap().path();
            let text = std::fs::read_to_string(&path).unwrap();
            let doc = roxmltree::Document::parse(&text).unwrap();
            let mut dashes: Vec<&str> = series(&doc)
                .iter()
                .map(|n| n.attribute("stroke-dasharray").unwrap_or("solid"))
                .collect();
            let n = dashes.len();
            dashes.sort();
            dashes.dedup();
            assert_eq!(dashes.len(), n, "{}", path.display());
            charts += 1;
        }
    }
    assert!(charts > 50, "{charts}");
}

/// No chart without data (issue 38): a machine of one cylinder has no free moment, so no
/// chart of it; the three-cylinder machine's free moment is drawn. A case that does not ask
/// for the shaking at every step (no `[layout]`, no `[balance]`) has no shaking columns and no
/// shaking chart.
#[test]
fn a_quantity_zero_throughout_has_no_chart() {
    let case = "balance-thesis-single-cw0";
    let data = read_csv(&out().join(case).join("slider_crank.csv"));
    assert!(data["shaking_moment_pitch_nm"]
        .iter()
        .chain(&data["shaking_moment_yaw_nm"])
        .all(|v| *v == 0.0));
    assert!(chart(case, "shaking_moment.svg").is_none(), "{case}");
    assert!(chart(case, "shaking_force.svg").is_some(), "{case}");
    for case in ["example-compressor", "karhula-engine-dynamic-flywheel"] {
        let data = read_csv(&out().join(case).join("slider_crank.csv"));
        assert!(!data.contains_key("shaking_force_x_n"), "{case}");
        for file in [
            "shaking_moment.svg",
            "shaking_force.svg",
            "shaking_force_locus.svg",
        ] {
            assert!(chart(case, file).is_none(), "{case}: {file}");
        }
    }
    assert!(chart("balance-inline3", "shaking_moment.svg").is_some());
}
