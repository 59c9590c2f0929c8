//! Reports of output folders written by hand (no run): a synthetic grid sweep's heat maps; the
//! friction metrics' loss budget and charts of a synthetic case; categorical, zipped and empty
//! sweeps; no difference in % of round-off, and the sign legend. The reports of the shipped
//! configs' runs are tested with the runner (`runner/tests/report.rs`).

use cardan_report::{case_report, index, sweep_report, MAX_POINTS};
use cardan_testing::chart::{attr_f64, check_series, data_area, Axes};

/// A 10 × 10 grid sweep written by hand: a value map per mechanism, the difference map with
/// its colour scale symmetric about 0 and its 0 contour between the 5th and 6th columns.
#[test]
fn heat_maps_of_a_grid_sweep() {
    let dir = tempfile::tempdir().unwrap();
    let sweep = dir.path().join("grid");
    std::fs::create_dir(&sweep).unwrap();
    let mut csv = String::from(
        "case,motion.initial_speed,geometry.rod_length,slider_crank.total_torque_max,cardan_gear.total_torque_max\n",
    );
    // Rows in reverse order: the report sorts the axes by value.
    for i in (0..10).rev() {
        for j in (0..10).rev() {
            let c = 50.5 + 10.0 * i as f64 + j as f64;
            csv.push_str(&format!(
                "p{i}{j},{} rpm,{} mm,100.0,{c}\n",
                100 * (i + 1),
                140 + 10 * j
            ));
        }
    }
    std::fs::write(sweep.join("sweep.csv"), csv).unwrap();
    sweep_report(&sweep, &sweep.file_name().unwrap().to_string_lossy(), None).unwrap();
    let parse = |name: &str| std::fs::read_to_string(sweep.join("plots").join(name)).unwrap();
    let cells = |doc: &roxmltree::Document| -> Vec<(usize, usize, f64, String)> {
        doc.descendants()
            .filter(|n| n.attribute("class") == Some("cell"))
            .map(|n| {
                (
                    n.attribute("data-i").unwrap().parse().unwrap(),
                    n.attribute("data-j").unwrap().parse().unwrap(),
                    attr_f64(n, "data-value"),
                    n.attribute("fill").unwrap().to_string(),
                )
            })
            .collect()
    };
    let legend = |doc: &roxmltree::Document| {
        let g = doc
            .descendants()
            .find(|n| n.attribute("class") == Some("legend"))
            .unwrap();
        (attr_f64(g, "data-min"), attr_f64(g, "data-max"))
    };
    // The cardan gear's values: column i is the i-th speed, row j the j-th rod length.
    let text = parse("total_torque_max_cardan_gear.svg");
    let doc = roxmltree::Document::parse(&text).unwrap();
    let c = cells(&doc);
    assert_eq!(c.len(), 100);
    for (i, j, v, _) in &c {
        assert_eq!(*v, 50.5 + 10.0 * *i as f64 + *j as f64);
    }
    assert_eq!(legend(&doc), (50.5, 149.5));
    // Viridis ends: #440154 at the smallest value, #fde725 at the largest.
    let fill = |c: &[(usize, usize, f64, String)], i: usize, j: usize| {
        c.iter().find(|x| x.0 == i && x.1 == j).unwrap().3.clone()
    };
    assert_eq!(fill(&c, 0, 0), "#440154");
    assert_eq!(fill(&c, 9, 9), "#fde725");
    assert_eq!(
        cells(&roxmltree::Document::parse(&parse("total_torque_max_slider_crank.svg")).unwrap())
            .len(),
        100
    );
    // The difference: Δ = c − 100 (%), from −49.5 to +49.5, scale ±49.5: blue, white at 0, red.
    let text = parse("total_torque_max_difference_cardan_gear.svg");
    let doc = roxmltree::Document::parse(&text).unwrap();
    let c = cells(&doc);
    assert_eq!(c.len(), 100);
    for (i, j, v, _) in &c {
        assert!((v - (-49.5 + 10.0 * *i as f64 + *j as f64)).abs() < 1e-12);
    }
    assert_eq!(legend(&doc), (-49.5, 49.5));
    assert_eq!(fill(&c, 0, 0), "#2166ac");
    assert_eq!(fill(&c, 9, 9), "#b2182b");
    // Δ = 0.5 % at (5, 0): t = 50/99 on the 5-stop scale, 2 % of the way from #f7f7f7 to
    // #f4a582: nearly white.
    assert_eq!(fill(&c, 5, 0), "#f7f5f5");
    // The 0 contour: in each of the 9 bands between rows, one segment between the centres of
    // columns 4 and 5.
    let g = doc
        .descendants()
        .find(|n| n.attribute("class") == Some("heatmap"))
        .unwrap();
    let area = data_area(g);
    let centre = |i: f64| area[0] + (i + 0.5) * area[2] / 10.0;
    let contour = doc
        .descendants()
        .find(|n| n.attribute("class") == Some("contour"))
        .unwrap();
    assert_eq!(contour.attribute("data-segments"), Some("9"));
    let d = contour.attribute("d").unwrap();
    let xs: Vec<f64> = d
        .split(['M', 'L'])
        .filter(|s| !s.is_empty())
        .map(|p| p.split(' ').next().unwrap().parse().unwrap())
        .collect();
    assert_eq!(xs.len(), 18);
    for x in xs {
        assert!(x > centre(4.0) && x < centre(5.0), "{x}");
    }
    let md = std::fs::read_to_string(sweep.join("report.md")).unwrap();
    assert!(md.contains("a full grid of two fields"));
    assert!(
        md.contains("`cardan_gear` is better than `slider_crank` at 50 of 100 points"),
        "{md}"
    );
}

/// Friction metrics and columns, when present: the loss budget (W and % of the total per
/// component) and the friction charts.
#[test]
fn loss_budget_and_friction_charts() {
    let dir = tempfile::tempdir().unwrap();
    let case = dir.path().join("lossy");
    std::fs::create_dir(&case).unwrap();
    let mechanism = |loss: [f64; 3], eff: f64| {
        serde_json::json!({
            "bodies": {}, "joints": {"crank_pin": {}, "main_bearing": {}}, "mass_properties": {},
            "metrics": {
                "power_loss_mean": loss[0], "power_loss_mean_crank_pin": loss[1],
                "power_loss_mean_main_bearing": loss[2], "mechanical_efficiency": eff,
                "total_torque_max": 10.0
            },
            "units": {
                "power_loss_mean": "W", "power_loss_mean_crank_pin": "W",
                "power_loss_mean_main_bearing": "W", "mechanical_efficiency": "1",
                "total_torque_max": "N*m"
            }
        })
    };
    let summary = serde_json::json!({
        "schema_version": 2, "case": "lossy", "machine": "pump", "gas_model": null,
        "mechanisms": {
            "slider_crank": mechanism([100.0, 60.0, 40.0], 0.90),
            "cardan_gear": mechanism([80.0, 20.0, 60.0], 0.92),
        }
    });
    std::fs::write(case.join("summary.json"), summary.to_string()).unwrap();
    let mut peak = 0.0f64;
    for (m, scale) in [("slider_crank", 1.0), ("cardan_gear", 0.8)] {
        let mut csv = String::from(
            "crank_angle_deg,friction_torque_nm,power_loss_crank_pin_w,power_loss_main_bearing_w\n",
        );
        for k in 0..2000 {
            let a = k as f64 * 0.36;
            let (p1, p2) = (scale * (1.0 + a.to_radians().sin().abs()), scale * 0.5);
            peak = peak.max(p1 + p2);
            csv.push_str(&format!("{a},{},{p1},{p2}\n", scale * 0.1));
        }
        std::fs::write(case.join(format!("{m}.csv")), csv).unwrap();
    }
    case_report(&case, None).unwrap();
    let md = std::fs::read_to_string(case.join("report.md")).unwrap();
    assert!(md.contains("## Loss budget"));
    assert!(
        md.contains("| `crank_pin` | 60 | 60.0 % | 20 | 25.0 % |"),
        "{md}"
    );
    assert!(md.contains("| `main_bearing` | 40 | 40.0 % | 60 | 75.0 % |"));
    assert!(md.contains("| **total** | 100 | 100.0 % | 80 | 100.0 % |"));
    assert!(
        md.contains("**Mean power loss** (`power_loss_mean`, lower is better): best `cardan_gear`")
    );
    assert!(md.contains(
        "**Mechanical efficiency** (`mechanical_efficiency`, higher is better): best `cardan_gear`"
    ));
    assert!(md.contains("| `mechanical_efficiency` |  | 0.9 | 0.92 | +2.2 % |"));
    for chart in [
        "friction_torque.svg",
        "power_loss.svg",
        "power_loss_crank_pin.svg",
        "power_loss_main_bearing.svg",
    ] {
        assert!(case.join("plots").join(chart).is_file(), "{chart}");
    }
    let text = std::fs::read_to_string(case.join("plots/power_loss.svg")).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    let axes = Axes::of(&doc);
    let s = doc
        .descendants()
        .find(|n| n.attribute("data-label") == Some("slider_crank"))
        .unwrap();
    let x: Vec<f64> = (0..2000).map(|k| k as f64 * 0.36).collect();
    let y: Vec<f64> = x.iter().map(|a| 1.5 + a.to_radians().sin().abs()).collect();
    check_series(
        &case.join("plots/power_loss.svg"),
        &axes,
        s,
        &x,
        &y,
        MAX_POINTS,
    );
    assert!((peak - 2.5).abs() < 1e-6);
}

/// A sweep over a field that is not a number, and a zip of two fields: charts along the
/// points, one per key metric, with every point drawn; an empty sweep still gets a report.
#[test]
fn categorical_zipped_and_empty_sweeps() {
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, text: &str| {
        let sweep = dir.path().join(name);
        std::fs::create_dir(&sweep).unwrap();
        std::fs::write(sweep.join("sweep.csv"), text).unwrap();
        sweep_report(&sweep, &sweep.file_name().unwrap().to_string_lossy(), None).unwrap();
        sweep
    };
    let sweep = write(
        "material",
        "case,masses.rod_material,slider_crank.inertial_torque_max,cardan_gear.inertial_torque_max\n\
         a,steel,10,20\nb,titanium,6,12\nc,aluminium,4,8\n",
    );
    let text = std::fs::read_to_string(sweep.join("plots/inertial_torque_max.svg")).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    for s in doc
        .descendants()
        .filter(|n| n.attribute("class") == Some("series"))
    {
        assert_eq!(s.attribute("data-n"), Some("3"));
    }
    for label in ["steel", "titanium", "aluminium"] {
        assert!(
            doc.descendants().any(|n| n.text() == Some(label)),
            "{label}"
        );
    }
    let md = std::fs::read_to_string(sweep.join("report.md")).unwrap();
    // Δ = +100 % at every point: the cardan gear is never better here.
    assert!(
        md.contains("at 0 of 3 points; Δ from +100.0 % to +100.0 %"),
        "{md}"
    );
    let sweep = write(
        "zip",
        "case,motion.initial_speed,geometry.rod_length,slider_crank.total_torque_max,cardan_gear.total_torque_max\n\
         a,100 rpm,140 mm,10,5\nb,200 rpm,150 mm,10,15\n",
    );
    let md = std::fs::read_to_string(sweep.join("report.md")).unwrap();
    assert!(md.contains("charts along the points"), "{md}");
    assert!(
        md.contains("Δ crosses 0 between 100 rpm and 200 rpm (≈ 150 rpm"),
        "{md}"
    );
    let sweep = write(
        "empty",
        "case,motion.initial_speed,slider_crank.total_torque_max\n",
    );
    assert!(sweep.join("report.html").is_file());
}

/// Issue 22: a Δ in % of quadrature round-off ("+144 %" on −4.8e-15 J, the inertial work of a
/// constant-speed run over whole turns) is no result. Below its metric's round-off floor
/// (1e-9 of the work, torque or power the drive's peak torque could make over the run) a
/// value gets no Δ: "≈ 0" where both are below it, "—" where one is; the legend says so, and a
/// sign convention follows the table of signed quantities.
#[test]
fn no_difference_in_percent_of_round_off_and_signs_are_explained() {
    let dir = tempfile::tempdir().unwrap();
    let case = dir.path().join("steady");
    std::fs::create_dir(&case).unwrap();
    // Scales: 0.2 N·m × 9.42 rad/s × 1.33 s = 2.5 J, 1.9 W; the floors 2.5e-9 J, 1.9e-9 W,
    // 2e-10 N·m.
    let mechanism = |work: f64, mean: f64, power: f64, total: f64| {
        serde_json::json!({
            "bodies": {}, "joints": {}, "mass_properties": {},
            "metrics": {
                "inertial_torque_max": 0.2, "crankshaft_angular_velocity_max": 9.42,
                "cycle_time": 1.33, "inertial_work": work, "inertial_torque_mean": mean,
                "inertial_power_mean": power, "total_torque_max": 0.4, "total_work": total,
                "energy_balance_error": work.abs() * 1e-2
            },
            "units": {
                "inertial_torque_max": "N*m", "crankshaft_angular_velocity_max": "rad/s",
                "cycle_time": "s", "inertial_work": "J", "inertial_torque_mean": "N*m",
                "inertial_power_mean": "W", "total_torque_max": "N*m", "total_work": "J"
            }
        })
    };
    let summary = serde_json::json!({
        "schema_version": 2, "case": "steady", "machine": "pump", "gas_model": null,
        "mechanisms": {
            "slider_crank": mechanism(2e-15, 3e-16, 1e-3, 1.0),
            "cardan_gear": mechanism(-4.8e-15, -1e-16, 1e-10, 1.25),
        }
    });
    std::fs::write(case.join("summary.json"), summary.to_string()).unwrap();
    case_report(&case, None).unwrap();
    let md = std::fs::read_to_string(case.join("report.md")).unwrap();
    // Both within round-off: no Δ.
    assert!(
        md.contains("| `inertial_work` | J | 2e-15 | -4.8e-15 | ≈ 0 |"),
        "{md}"
    );
    assert!(md.contains("| `inertial_torque_mean` | N·m | 3e-16 | -1e-16 | ≈ 0 |"));
    // One within round-off (1e-10 W of a 1.9 W scale), the other not: no Δ either.
    assert!(md.contains("| `inertial_power_mean` | W | 0.001 | 1e-10 | — |"));
    // A relative error of round-off (2e-17 against 4.8e-17): no Δ of it (issue 38).
    assert!(
        md.contains("| `energy_balance_error` |  | 2e-17 | 4.8e-17 | ≈ 0 |"),
        "{md}"
    );
    // Above the floor: the Δ as ever, (1.25 − 1) / 1.
    assert!(md.contains("| `total_work` | J | 1 | 1.25 | +25.0 % |"));
    // The engineer's unit beside SI (issue 38): 9.42 rad/s is 89.95 rpm (× 60/2π).
    assert!(md.contains(
        "| `crankshaft_angular_velocity_max` | rad/s | 9.42 (89.954 rpm) | 9.42 (89.954 rpm) |"
    ));
    // The results ("Which is better") before the paragraph on how Δ is made.
    let (results, method) = (
        md.find("## Which is better").unwrap(),
        md.find("Δ = (mechanism − reference)").unwrap(),
    );
    assert!(results < method, "{md}");
    assert!(
        md.contains("round-off"),
        "the legend explains the floor: {md}"
    );
    let torque_table = md.split("### Drive torque, power and work").nth(1).unwrap();
    let after = torque_table.split("\n\n").nth(2).unwrap_or("");
    for part in [
        "positive in the direction of rotation",
        "pump",
        "engine",
        "negative",
    ] {
        assert!(
            after.contains(part),
            "the sign line under the torque table names {part:?}: {after}"
        );
    }
}

/// The "which is better" items of a report.md: its `- **...` lines, in order.
fn headline_items(md: &str) -> Vec<&str> {
    md.lines().filter(|l| l.starts_with("- **")).collect()
}

/// A case folder with a `summary.json` written by hand: `machine`, `layout` (or none) and per
/// mechanism its metrics (units from the metric registry).
fn hand_case(
    dir: &std::path::Path,
    machine: &str,
    layout: Option<(&str, u32)>,
    mechanisms: &[(&str, &[(&str, f64)])],
) -> std::path::PathBuf {
    let case = dir.join("hand");
    hand_summary(&case, machine, layout, mechanisms);
    case_report(&case, None).unwrap();
    case
}

/// Writes `<case>/summary.json` by hand (see [`hand_case`]).
fn hand_summary(
    case: &std::path::Path,
    machine: &str,
    layout: Option<(&str, u32)>,
    mechanisms: &[(&str, &[(&str, f64)])],
) {
    std::fs::create_dir_all(case).unwrap();
    let mut ms = serde_json::Map::new();
    for (name, metrics) in mechanisms {
        let values: serde_json::Map<String, serde_json::Value> = metrics
            .iter()
            .map(|(k, v)| (k.to_string(), serde_json::json!(v)))
            .collect();
        let units: serde_json::Map<String, serde_json::Value> = metrics
            .iter()
            .map(|(k, _)| {
                let unit = cardan_metrics::find(k).map_or("", |d| d.unit);
                (k.to_string(), serde_json::json!(unit))
            })
            .collect();
        ms.insert(
            name.to_string(),
            serde_json::json!({"bodies": {}, "joints": {}, "mass_properties": {},
                "metrics": values, "units": units}),
        );
    }
    let mut summary = serde_json::json!({
        "schema_version": 2, "case": "hand", "machine": machine, "gas_model": null,
        "mechanisms": ms,
    });
    if let Some((kind, n)) = layout {
        summary["layout"] = serde_json::json!({"kind": kind, "cylinders": n,
            "balance_shafts": "none", "cardan_counterweights": false, "counterweight": null});
    }
    std::fs::write(case.join("summary.json"), summary.to_string()).unwrap();
}

/// Issue 35: a two-cylinder compressor's report said "Mean power need 1839.9 W" (cylinder 1's)
/// for a machine that takes 3.75 kW. The machine's figures lead the "which is better" summary
/// (its mean power need, peak torque as the larger magnitude of its signed extremes, journal
/// and pin loads, efficiency, losses), then the cylinder's, each labelled "of cylinder 1"; the
/// per-cylinder tables and the loss budget say whose they are.
#[test]
fn a_multi_cylinder_report_leads_with_the_machine_and_labels_the_cylinder() {
    let dir = tempfile::tempdir().unwrap();
    let mechanism = |scale: f64| -> Vec<(&'static str, f64)> {
        vec![
            ("machine_power_mean", 3750.0 * scale),
            ("machine_torque_max", 120.0 * scale),
            ("machine_torque_min", -150.0 * scale),
            ("machine_torque_mean", 39.8 * scale),
            ("machine_main_bearing_force_max", 9000.0 * scale),
            ("machine_crank_pin_force_max", 8000.0 * scale),
            ("machine_mechanical_efficiency", 0.9 + (1.0 - scale) * 0.25),
            ("machine_loss_power_mean", 375.0 * scale),
            ("power_need_mean", 1839.9 * scale),
            ("mechanical_efficiency", 0.91 + (1.0 - scale) * 0.25),
            ("power_loss_mean", 180.0 * scale),
            ("power_loss_mean_crank_pin", 180.0 * scale),
            ("total_torque_max", 100.0 * scale),
            ("total_main_bearing_force_max", 7000.0 * scale),
        ]
    };
    let (s, c) = (mechanism(1.0), mechanism(0.8));
    let case = hand_case(
        dir.path(),
        "pump",
        Some(("inline", 2)),
        &[("slider_crank", &s), ("cardan_gear", &c)],
    );
    let md = std::fs::read_to_string(case.join("report.md")).unwrap();
    let items = headline_items(&md);
    let expected_starts = [
        "- **Mean power need of the machine** (`machine_power_mean`, lower is better): best `cardan_gear`; `cardan_gear` 3000 W (3 kW) vs `slider_crank` 3750 W (3.75 kW) (lower by 20.0 %: better).",
        "- **Peak drive torque of the machine** (the larger of |`machine_torque_max`| and |`machine_torque_min`|, lower is better): best `cardan_gear`; `cardan_gear` 120 N·m vs `slider_crank` 150 N·m",
        "- **Peak main-journal load of the machine** (`machine_main_bearing_force_max`, lower is better): best `cardan_gear`; `cardan_gear` 7200 N (7.2 kN) vs `slider_crank` 9000 N (9 kN)",
        "- **Peak crank-pin load of the machine** (`machine_crank_pin_force_max`,",
        "- **Mechanical efficiency of the machine** (`machine_mechanical_efficiency`, higher is better): best `cardan_gear`; `cardan_gear` 0.95 vs `slider_crank` 0.9",
        "- **Mean friction power loss of the machine** (`machine_loss_power_mean`, lower is better): best `cardan_gear`; `cardan_gear` 300 W vs `slider_crank` 375 W",
        "- **Peak drive torque of cylinder 1** (`total_torque_max`,",
        "- **Peak main-bearing force of cylinder 1** (`total_main_bearing_force_max`,",
        "- **Mean power loss of cylinder 1** (`power_loss_mean`,",
        "- **Mechanical efficiency of cylinder 1** (`mechanical_efficiency`,",
        "- **Mean power need of cylinder 1** (`power_need_mean`, lower is better): best `cardan_gear`; `cardan_gear` 1471.9 W (1.4719 kW) vs `slider_crank` 1839.9 W (1.8399 kW)",
    ];
    assert_eq!(items.len(), expected_starts.len(), "{items:#?}");
    for (item, start) in items.iter().zip(expected_starts) {
        assert!(
            item.starts_with(start),
            "{item}\nshould start with\n{start}"
        );
    }
    // No figure of one cylinder under a machine's name.
    assert!(!md.contains("**Mean power need** ("), "{md}");
    for heading in [
        "### The whole machine\n",
        "### Drive torque, power and work: cylinder 1\n",
        "### Losses and efficiency: cylinder 1\n",
        "## Loss budget of cylinder 1\n",
        "The machine has 2 cylinders",
    ] {
        assert!(md.contains(heading), "{heading:?}\n{md}");
    }
    assert!(md.find("### The whole machine") < md.find("### Drive torque"));

    // A vee engine: its mean output is −machine_power_mean, higher is better, and its one
    // cylinder is the mechanism at the machine's crank angle.
    let dir = tempfile::tempdir().unwrap();
    let engine = |scale: f64| -> Vec<(&'static str, f64)> {
        vec![
            ("machine_power_mean", -60000.0 * scale),
            ("machine_torque_max", 500.0 * scale),
            ("machine_torque_min", -2000.0 * scale),
            ("total_torque_max", 1500.0 * scale),
        ]
    };
    let (s, c) = (engine(1.0), engine(0.9));
    let case = hand_case(
        dir.path(),
        "engine",
        Some(("vee", 2)),
        &[("slider_crank", &s), ("cardan_gear", &c)],
    );
    let md = std::fs::read_to_string(case.join("report.md")).unwrap();
    let items = headline_items(&md);
    assert_eq!(items.len(), 3, "{items:#?}");
    assert!(items[0].starts_with(
        "- **Mean output power of the machine** (−`machine_power_mean`, higher is better): best `slider_crank`; `cardan_gear` 54000 W (54 kW) vs `slider_crank` 60000 W (60 kW) (lower by 10.0 %: worse)."
    ), "{}", items[0]);
    assert!(items[1].contains("`cardan_gear` 1800 N·m vs `slider_crank` 2000 N·m"));
    assert!(items[2].starts_with(
        "- **Peak drive torque of one cylinder at the machine's crank angle** (`total_torque_max`,"
    ), "{}", items[2]);
    assert!(md
        .contains("### Drive torque, power and work: one cylinder at the machine's crank angle\n"));
}

/// A one-cylinder machine's report: the machine's figures are its cylinder's, said once and
/// labelled with no cylinder; a figure the machine has no counterpart of stays.
#[test]
fn a_single_cylinder_report_says_each_figure_once() {
    let dir = tempfile::tempdir().unwrap();
    let mechanism = |scale: f64| -> Vec<(&'static str, f64)> {
        vec![
            ("machine_power_mean", 1839.9 * scale),
            ("machine_torque_max", 100.0 * scale),
            ("machine_torque_min", -30.0 * scale),
            ("machine_main_bearing_force_max", 7000.0 * scale),
            ("power_need_mean", 1839.9 * scale),
            ("total_torque_max", 100.0 * scale),
            ("total_main_bearing_force_max", 7000.0 * scale),
            ("friction_torque_max", 5.0 * scale),
        ]
    };
    let (s, c) = (mechanism(1.0), mechanism(1.25));
    for layout in [None, Some(("inline", 1))] {
        let case = hand_case(
            dir.path(),
            "pump",
            layout,
            &[("slider_crank", &s), ("cardan_gear", &c)],
        );
        let md = std::fs::read_to_string(case.join("report.md")).unwrap();
        let items = headline_items(&md);
        let starts = [
            "- **Mean power need of the machine** (`machine_power_mean`,",
            "- **Peak drive torque of the machine** (the larger of",
            "- **Peak main-journal load of the machine** (`machine_main_bearing_force_max`,",
            "- **Peak friction torque** (`friction_torque_max`,",
        ];
        assert_eq!(items.len(), starts.len(), "{layout:?}: {items:#?}");
        for (item, start) in items.iter().zip(starts) {
            assert!(item.starts_with(start), "{item}");
        }
        assert!(!md.contains("cylinder 1"), "{md}");
        assert!(md.contains("### Drive torque, power and work\n"));
    }
}

/// Issue 35: the index showed the same peak torque (cylinder 1's) for an inline-3, -4 and -6.
/// Its headline columns are the machine's (`machine_*`; the peak torque the larger of
/// |`machine_torque_max`| and |`machine_torque_min`|), with the layout; a summary without
/// them shows its cylinder's figures only for a machine of one cylinder.
#[test]
fn the_index_shows_the_machine() {
    let dir = tempfile::tempdir().unwrap();
    let twin: &[(&str, f64)] = &[
        ("machine_torque_max", 120.0),
        ("machine_torque_min", -150.0),
        ("machine_main_bearing_force_max", 9000.0),
        ("machine_crank_pin_force_max", 8000.0),
        ("machine_power_mean", 3750.0),
        ("machine_loss_power_mean", 375.0),
        ("machine_mechanical_efficiency", 0.9),
        ("total_torque_max", 100.0),
        ("total_main_bearing_force_max", 7000.0),
        ("total_crank_pin_force_max", 7000.0),
        ("total_power_mean", 1700.0),
        ("power_loss_mean", 180.0),
        ("mechanical_efficiency", 0.91),
    ];
    let cylinder: &[(&str, f64)] = &[
        ("total_torque_max", 100.0),
        ("total_main_bearing_force_max", 7000.0),
        ("total_power_mean", 1700.0),
    ];
    hand_summary(
        &dir.path().join("a-twin"),
        "pump",
        Some(("inline", 2)),
        &[("slider_crank", twin)],
    );
    hand_summary(
        &dir.path().join("b-single"),
        "pump",
        None,
        &[("slider_crank", cylinder)],
    );
    hand_summary(
        &dir.path().join("c-vee-without-machine-metrics"),
        "engine",
        Some(("vee", 2)),
        &[("slider_crank", cylinder)],
    );
    index(dir.path()).unwrap();
    let html = std::fs::read_to_string(dir.path().join("index.html")).unwrap();
    let rows: Vec<Vec<String>> = html
        .split("<tr>")
        .skip(1)
        .map(|r| {
            let r = r.split("</tr>").next().unwrap();
            r.split("<t")
                .skip(1)
                .map(|c| {
                    let c = &c[c.find('>').unwrap() + 1..];
                    c.split("</t").next().unwrap().to_string()
                })
                .collect()
        })
        .collect();
    assert_eq!(
        rows[0],
        [
            "case",
            "machine",
            "layout",
            "mechanism",
            "machine: peak drive torque, N·m",
            "machine: peak main-journal load, N",
            "machine: peak crank-pin load, N",
            "machine: mean drive power, W",
            "machine: mean power loss, W",
            "machine: mechanical efficiency",
        ]
    );
    let code = "<code>slider_crank</code>";
    assert_eq!(
        rows[1],
        [
            "a-twin",
            "pump",
            "inline, 2 cylinders",
            code,
            "150",
            "9000",
            "8000",
            "3750",
            "375",
            "0.9"
        ]
    );
    assert_eq!(
        rows[2],
        [
            "b-single",
            "pump",
            "1 cylinder",
            code,
            "100",
            "7000",
            "—",
            "1700",
            "—",
            "—"
        ]
    );
    assert_eq!(
        rows[3],
        [
            "c-vee-without-machine-metrics",
            "engine",
            "vee, 2 cylinders",
            code,
            "—",
            "—",
            "—",
            "—",
            "—",
            "—"
        ]
    );
    assert_eq!(rows.len(), 4);
}

/// Issue 35: a sweep of a machine of several cylinders charts the whole machine's figures
/// first (its mean drive power, lower is better; its peak drive torque, the larger of
/// |`machine_torque_max`| and |`machine_torque_min`| of each point), and names one
/// cylinder's figures as cylinder 1's.
#[test]
fn a_multi_cylinder_sweep_reports_the_machine() {
    let dir = tempfile::tempdir().unwrap();
    let sweep = dir.path().join("twin");
    let columns = [
        "machine_power_mean",
        "machine_torque_max",
        "machine_torque_min",
        "total_torque_max",
    ];
    let slider = [
        [1000.0, 100.0, -50.0, 80.0],
        [2000.0, 110.0, -200.0, 90.0],
        [3000.0, 120.0, -60.0, 100.0],
    ];
    let cardan = [
        [900.0, 90.0, -95.0, 88.0],
        [2100.0, 150.0, -100.0, 81.0],
        [2700.0, 130.0, -10.0, 100.0],
    ];
    let metrics = |row: &[f64; 4]| -> Vec<(&'static str, f64)> {
        columns.iter().copied().zip(row.iter().copied()).collect()
    };
    let (s0, c0) = (metrics(&slider[0]), metrics(&cardan[0]));
    hand_summary(
        &sweep.join("p0"),
        "pump",
        Some(("inline", 2)),
        &[("slider_crank", &s0), ("cardan_gear", &c0)],
    );
    let mut csv = String::from("case,motion.initial_speed");
    for m in ["slider_crank", "cardan_gear"] {
        for c in columns {
            csv.push_str(&format!(",{m}.{c}"));
        }
    }
    csv.push('\n');
    for (k, speed) in ["100 rpm", "900 rpm", "3000 rpm"].iter().enumerate() {
        csv.push_str(&format!("p{k},{speed}"));
        for v in slider[k].iter().chain(&cardan[k]) {
            csv.push_str(&format!(",{v}"));
        }
        csv.push('\n');
    }
    std::fs::write(sweep.join("sweep.csv"), csv).unwrap();
    sweep_report(&sweep, "twin", None).unwrap();
    let md = std::fs::read_to_string(sweep.join("report.md")).unwrap();
    assert!(
        md.contains("): `machine_power_mean`, `machine_torque_peak`, `total_torque_max`."),
        "{md}"
    );
    let items: Vec<&str> = md.lines().filter(|l| l.starts_with("- `")).collect();
    assert_eq!(
        items,
        [
            "- `machine_power_mean` (lower is better): `cardan_gear` is better than `slider_crank` at 2 of 3 points; Δ from -10.0 % to +5.0 %; Δ crosses 0 between 100 rpm and 900 rpm (≈ 633.33 rpm by linear interpolation); Δ crosses 0 between 900 rpm and 3000 rpm (≈ 1600 rpm by linear interpolation).",
            "- `machine_torque_peak` (lower is better): `cardan_gear` is better than `slider_crank` at 2 of 3 points; Δ from -25.0 % to +8.3 %; Δ crosses 0 between 900 rpm and 3000 rpm (≈ 2475 rpm by linear interpolation).",
            "- `total_torque_max` of cylinder 1 (lower is better): `cardan_gear` is better than `slider_crank` at 1 of 3 points; Δ from -10.0 % to +10.0 %; Δ crosses 0 between 100 rpm and 900 rpm (≈ 500 rpm by linear interpolation).",
        ],
        "{md}"
    );
    assert!(md.contains("### `machine_torque_peak`, N·m\n"), "{md}");
    assert!(md.contains("| 900 rpm | 200 | 150 | -25.0 % |"), "{md}");
    assert!(
        md.contains("### `total_torque_max` of cylinder 1, N·m\n"),
        "{md}"
    );
    assert!(sweep.join("plots/machine_torque_peak.svg").is_file());
}

/// A machine's mean drive power of inertia alone over whole turns at constant speed is 0 up to
/// round-off for every mechanism: no "which is better" line compares two round-offs (its floor
/// is 1e-9 of the machine's peak torque, the larger of its signed extremes, × the peak speed).
#[test]
fn a_round_off_machine_power_is_not_a_headline() {
    let dir = tempfile::tempdir().unwrap();
    let mechanism = |power: f64| -> Vec<(&'static str, f64)> {
        vec![
            ("machine_power_mean", power),
            ("machine_torque_max", 10.0),
            ("machine_torque_min", -450.0),
            ("crankshaft_angular_velocity_max", 100.0),
        ]
    };
    // 450 N·m × 100 rad/s × 1e-9 = 4.5e-5 W.
    let (s, c) = (mechanism(2.4e-11), mechanism(-4.4e-5));
    let case = hand_case(
        dir.path(),
        "pump",
        Some(("inline", 3)),
        &[("slider_crank", &s), ("cardan_gear", &c)],
    );
    let md = std::fs::read_to_string(case.join("report.md")).unwrap();
    let items = headline_items(&md);
    assert_eq!(items.len(), 1, "{items:#?}");
    assert!(items[0].starts_with("- **Peak drive torque of the machine**"));
    // One of them above its floor: compared, as not comparable.
    let c = mechanism(4.6e-5);
    let case = hand_case(
        dir.path(),
        "pump",
        Some(("inline", 3)),
        &[("slider_crank", &s), ("cardan_gear", &c)],
    );
    let md = std::fs::read_to_string(case.join("report.md")).unwrap();
    assert!(
        md.contains("(not comparable: one is 0 up to round-off)."),
        "{md}"
    );
}
