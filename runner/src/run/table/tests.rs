//! The table's rows: a point's metrics matched to the columns by index where they line up,
//! by name where not; the NPY header.

use super::{npy_header, place, Column, Table};
use crate::output::MechanismResult;
use cardan_dynamics::{Metric, Summary};
use cardan_mechanism::{MachineGeometry, MassInputs, Options, MECHANISMS};
use std::path::Path;
use std::sync::Arc;

/// The columns' values of a point's `metrics` as the table filled them before it matched
/// by index: each metric's name formatted and looked for among every column.
fn by_search(columns: &[&str], metrics: &[(&str, &str, f64)]) -> Vec<f64> {
    let mut values = vec![f64::NAN; columns.len()];
    let mut filled = vec![false; columns.len()];
    for (label, metric, value) in metrics {
        let name = format!("{label}.{metric}");
        if let Some(k) = columns.iter().position(|c| *c == name) {
            if !filled[k] {
                values[k] = *value;
                filled[k] = true;
            }
        }
    }
    values
}

#[test]
fn a_point_whose_metrics_differ_from_the_columns_fills_them_by_name() {
    let columns = ["sc.a", "sc.b", "cg.a", "cg.b", "cg.c.d"];
    // (metrics, expected values, first metric left out); NaN: no value.
    let nan = f64::NAN;
    #[allow(clippy::type_complexity)]
    let points: [(&[(&str, &str, f64)], [f64; 5], Option<(&str, &str)>); 7] = [
        // The columns' own order: every metric at its index.
        (
            &[
                ("sc", "a", 1.),
                ("sc", "b", 2.),
                ("cg", "a", 3.),
                ("cg", "b", 4.),
                ("cg", "c.d", 5.),
            ],
            [1., 2., 3., 4., 5.],
            None,
        ),
        // sc.b missing: every later metric one index early.
        (
            &[
                ("sc", "a", 1.),
                ("cg", "a", 3.),
                ("cg", "b", 4.),
                ("cg", "c.d", 5.),
            ],
            [1., nan, 3., 4., 5.],
            None,
        ),
        // An extra metric: every later one an index late, the extra left out.
        (
            &[
                ("sc", "a", 1.),
                ("sc", "z", 9.),
                ("sc", "b", 2.),
                ("cg", "a", 3.),
                ("cg", "b", 4.),
            ],
            [1., 2., 3., 4., nan],
            Some(("sc", "z")),
        ),
        // A name twice: the first fills the column, at the second's index or not.
        (
            &[
                ("sc", "a", 1.),
                ("sc", "a", 7.),
                ("cg", "a", 3.),
                ("cg", "a", 8.),
                ("cg", "c.d", 5.),
            ],
            [1., nan, 3., nan, 5.],
            None,
        ),
        // Another order (the mechanisms swapped).
        (
            &[
                ("cg", "a", 3.),
                ("cg", "b", 4.),
                ("cg", "c.d", 5.),
                ("sc", "a", 1.),
                ("sc", "b", 2.),
            ],
            [1., 2., 3., 4., 5.],
            None,
        ),
        // Names that are not a column's, or are one's split at another dot (the first fills it).
        (
            &[
                ("sc", "ab", 1.),
                ("s", "c.b", 2.),
                ("cg.c", "d", 5.),
                ("cg", "cd", 6.),
                ("cg", "c.d", 7.),
            ],
            [nan, nan, nan, nan, 5.],
            Some(("sc", "ab")),
        ),
        // No metric: every column NaN.
        (&[], [nan; 5], None),
    ];
    for (metrics, expected, left_out) in points {
        let mut values = vec![f64::NAN; columns.len()];
        let out = place(&columns, metrics.iter().copied(), &mut values);
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&values), bits(&expected), "{metrics:?}");
        assert_eq!(
            bits(&values),
            bits(&by_search(&columns, metrics)),
            "{metrics:?}"
        );
        assert_eq!(out, left_out, "{metrics:?}");
    }
}

#[test]
fn the_header_is_aligned_and_names_type_and_length() {
    for (descr, rows) in [("<f8", 3), ("|S17", 1_000_000)] {
        let h = npy_header(descr, rows);
        assert_eq!(h.len() % 64, 0);
        assert_eq!(&h[..8], b"\x93NUMPY\x01\x00");
        let text = String::from_utf8_lossy(&h[10..]);
        assert!(text.contains(&format!("'descr': '{descr}'")), "{text}");
        assert!(text.contains(&format!("'shape': ({rows},)")), "{text}");
        assert!(text.ends_with('\n'));
    }
}

/// A point's results: each mechanism's label with its metrics (name, value) in their order.
fn results(mechanisms: &[(&str, &[(&str, f64)])]) -> Result<Vec<MechanismResult>, String> {
    // Any mechanism: the table reads only the label and the summary.
    let geometry = MachineGeometry {
        crank_length: 0.06,
        rod_length: 0.14,
        bore: 0.12,
        pin_offset: 0.0,
    };
    let build = MECHANISMS[0].build;
    let mechanism: Arc<dyn cardan_mechanism::Mechanism> =
        Arc::from(build(&geometry, &MassInputs::default(), &Options::new()).unwrap());
    let result = |(label, metrics): &(&str, &[(&str, f64)])| MechanismResult {
        mechanism: mechanism.clone(),
        label: label.to_string(),
        summary: Summary {
            metrics: metrics
                .iter()
                .map(|&(name, value)| Metric {
                    name: name.to_string(),
                    unit: "N",
                    value,
                })
                .collect(),
        },
        warnings: Vec::new(),
        cycle_starts: Vec::new(),
        runup: Vec::new(),
    };
    Ok(mechanisms.iter().map(result).collect())
}

/// A table of `rows` rows begun in `dir` (a shard's part if `part`), its text column the
/// case's name only.
fn table(dir: &Path, rows: usize, part: bool) -> Table<'_> {
    std::fs::create_dir(dir.join("columns")).unwrap();
    Table {
        dir,
        rows,
        text: vec![Column::create(dir, "case", Some(4), rows).unwrap()],
        metrics: Vec::new(),
        first_row: 0,
        next: 0,
        first_columns: None,
        part,
        only: None,
        failed: Vec::new(),
        warned: false,
        warned_points: 0,
        first_warning: None,
    }
}

/// The metric columns of `table`, finished: each one's name and its values read back from its
/// file, as bits (NaN compared too).
fn columns(table: Table) -> Vec<(String, Vec<u64>)> {
    let names: Vec<String> = table.metrics.iter().map(|c| c.name.clone()).collect();
    let dir = table.dir.to_path_buf();
    table.finish("t", None).unwrap();
    let values = |name: &str| -> Vec<u64> {
        let bytes = std::fs::read(dir.join("columns").join(format!("{name}.npy"))).unwrap();
        let start = 10 + u16::from_le_bytes([bytes[8], bytes[9]]) as usize;
        let chunks = bytes[start..].chunks(8);
        chunks
            .map(|b| f64::from_le_bytes(b.try_into().unwrap()).to_bits())
            .collect()
    };
    names
        .into_iter()
        .map(|n| {
            let v = values(&n);
            (n, v)
        })
        .collect()
}

/// Each column's expected values, as bits.
fn expected(columns: &[(&str, [f64; 4])]) -> Vec<(String, Vec<u64>)> {
    let column = |(name, values): &(&str, [f64; 4])| {
        (
            name.to_string(),
            values.iter().map(|v| v.to_bits()).collect(),
        )
    };
    columns.iter().map(column).collect()
}

#[test]
fn rows_whose_metrics_differ_from_the_first_point_s_fill_its_columns_by_name() {
    let tmp = tempfile::tempdir().unwrap();
    let mut t = table(tmp.path(), 4, false);
    let nan = f64::NAN;
    // The first point makes the columns.
    let first = results(&[
        ("sc", &[("a", 1.), ("b", 2.)]),
        ("cg", &[("a", 3.), ("b", 4.)]),
    ]);
    t.row("p0", &[], first).unwrap();
    // sc.a missing (each later metric an index early), cg.a twice (the first fills).
    let missing = results(&[
        ("sc", &[("b", 12.)]),
        ("cg", &[("a", 13.), ("b", 14.), ("a", 99.)]),
    ]);
    t.row("p1", &[], missing).unwrap();
    assert!(!t.warned, "every metric of p1 is a column");
    // An extra metric (left out, said once), cg's in another order.
    let extra = results(&[
        ("sc", &[("a", 21.), ("z", 98.), ("b", 22.)]),
        ("cg", &[("b", 24.), ("a", 23.)]),
    ]);
    t.row("p2", &[], extra).unwrap();
    assert!(t.warned, "sc.z is not a column");
    t.row("p3", &[], Err("failed".into())).unwrap();
    assert_eq!(
        columns(t),
        expected(&[
            ("sc.a", [1., nan, 21., nan]),
            ("sc.b", [2., 12., 22., nan]),
            ("cg.a", [3., 13., 23., nan]),
            ("cg.b", [4., 14., 24., nan]),
        ])
    );
}

#[test]
fn a_shard_s_part_adds_a_column_for_each_new_metric_wherever_it_comes() {
    let tmp = tempfile::tempdir().unwrap();
    let mut t = table(tmp.path(), 4, true);
    let nan = f64::NAN;
    t.row("p0", &[], results(&[("sc", &[("a", 1.)])])).unwrap();
    t.row("p1", &[], results(&[("sc", &[("b", 2.), ("a", 3.)])]))
        .unwrap();
    t.row(
        "p2",
        &[],
        results(&[("cg", &[("a", 4.)]), ("sc", &[("a", 5.)])]),
    )
    .unwrap();
    t.row(
        "p3",
        &[],
        results(&[("sc", &[("a", 6.), ("b", 7.)]), ("cg", &[("a", 8.)])]),
    )
    .unwrap();
    assert_eq!(t.first_columns, Some(1));
    assert!(!t.warned);
    assert_eq!(
        columns(t),
        expected(&[
            ("sc.a", [1., 3., 5., 6.]),
            ("sc.b", [nan, 2., nan, 7.]),
            ("cg.a", [nan, nan, 4., 8.]),
        ])
    );
}
