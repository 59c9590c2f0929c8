//! Fuzzing the case schema and its validator (issue 26, item 5): case files built from the
//! schema's own tables and fields (read from the JSON Schema, so a new field is fuzzed without
//! a change here), each field given a random value of a random type (numbers of every size
//! and sign, numbers with right, wrong and unknown units, words, booleans, arrays, tables),
//! fields dropped, unknown keys added. Every document is either refused with an error that
//! names the file and a field or line, or runs to complete, finite results (or a failure naming
//! the case); never a panic, a hang (large cases are only validated) or a partial folder. The
//! number of documents is bounded for CI; `fuzz/` holds a cargo-fuzz target for long runs
//! (docs/fuzzing.md).

use cardan_case::json_schema::case_schema;
use cardan_runner::{run_paths, RunOptions};
use proptest::prelude::*;
use serde_json::Value;
use toml::Value as Toml;

/// A valid case with every optional table: the starting point that mutations break.
const BASE: &str = r#"
name = "fuzz"
machine = "pump"
mechanisms = ["slider_crank", "cardan_gear"]
[geometry]
crank_length = "60 mm"
rod_length = "140 mm"
bore = "120 mm"
[motion]
start_angle = 90.0
end_angle = 450.0
initial_speed = "30 rad/s"
angular_acceleration = 0.0
steps = 72
[gas]
model = "karhula_pump"
compression_ratio = 12
polytropic_exponent = 1.4
[friction]
[output]
csv = true
"#;

/// The schema's tables and their fields: (table, fields), with "" for the top level.
fn schema_fields() -> Vec<(String, Vec<String>)> {
    let schema = case_schema();
    let defs = &schema["$defs"];
    let props = |v: &Value| -> Vec<String> {
        v["properties"]
            .as_object()
            .map(|o| o.keys().cloned().collect())
            .unwrap_or_default()
    };
    let mut out = vec![(String::new(), props(&schema))];
    for (table, v) in schema["properties"].as_object().unwrap() {
        let def = v["$ref"]
            .as_str()
            .and_then(|r| r.strip_prefix("#/$defs/"))
            .map(|d| &defs[d]);
        if let Some(def) = def {
            let fields = props(def);
            if !fields.is_empty() {
                out.push((table.clone(), fields));
            }
        }
    }
    out
}

/// A random TOML value of a random type.
fn value() -> impl Strategy<Value = Toml> {
    let number = prop_oneof![
        Just(0.0),
        Just(-1.0),
        Just(1e300),
        Just(-1e-300),
        Just(f64::NAN),
        Just(f64::INFINITY),
        -1e6..1e6f64,
        0.0..2.0f64,
    ];
    let units = prop_oneof![
        Just("mm"),
        Just("m"),
        Just("rad/s"),
        Just("rpm"),
        Just("deg"),
        Just("bar"),
        Just("kg"),
        Just("furlong"),
        Just(""),
    ];
    let leaf = prop_oneof![
        number.clone().prop_map(Toml::Float),
        (-100_000i64..100_000).prop_map(Toml::Integer),
        prop_oneof![Just(i64::MAX), Just(i64::MIN), Just(0)].prop_map(Toml::Integer),
        (number, units).prop_map(|(x, u)| Toml::String(format!("{x} {u}"))),
        "[a-z_]{0,12}".prop_map(Toml::String),
        any::<bool>().prop_map(Toml::Boolean),
    ];
    leaf.prop_recursive(2, 6, 3, |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 0..3).prop_map(Toml::Array),
            prop::collection::vec(("[a-z_]{1,8}", inner), 0..3)
                .prop_map(|kv| Toml::Table(kv.into_iter().collect())),
        ]
    })
}

/// One change to the document: set (table, field) to a value, drop it, or add a key the
/// schema does not have.
#[derive(Debug, Clone)]
enum Change {
    Set(usize, usize, Toml),
    Drop(usize, usize),
    Unknown(usize, String, Toml),
}

fn change(tables: usize) -> impl Strategy<Value = Change> {
    prop_oneof![
        4 => (0..tables, any::<prop::sample::Index>().prop_map(|i| i.index(1000)), value())
            .prop_map(|(t, f, v)| Change::Set(t, f, v)),
        1 => (0..tables, any::<prop::sample::Index>().prop_map(|i| i.index(1000)))
            .prop_map(|(t, f)| Change::Drop(t, f)),
        1 => (0..tables, "[a-z_]{1,10}", value()).prop_map(|(t, k, v)| Change::Unknown(t, k, v)),
    ]
}

/// The document after `changes`.
fn document(fields: &[(String, Vec<String>)], changes: &[Change]) -> String {
    let mut doc: toml::Table = BASE.parse().unwrap();
    fn table<'a>(doc: &'a mut toml::Table, name: &str) -> &'a mut toml::Table {
        if name.is_empty() {
            return doc;
        }
        let entry = doc
            .entry(name.to_string())
            .or_insert_with(|| Toml::Table(toml::Table::new()));
        if !entry.is_table() {
            *entry = Toml::Table(toml::Table::new());
        }
        entry.as_table_mut().unwrap()
    }
    for c in changes {
        match c {
            Change::Set(t, f, v) => {
                let (name, keys) = &fields[*t];
                let key = keys[f % keys.len()].clone();
                table(&mut doc, name).insert(key, v.clone());
            }
            Change::Drop(t, f) => {
                let (name, keys) = &fields[*t];
                let key = &keys[f % keys.len()];
                table(&mut doc, name).remove(key);
            }
            Change::Unknown(t, k, v) => {
                table(&mut doc, &fields[*t].0).insert(format!("x_{k}"), v.clone());
            }
        }
    }
    toml::to_string(&doc).unwrap_or_else(|_| BASE.to_string())
}

/// Whether every number in a summary is finite (JSON has no NaN: `null` is one; the two
/// entries whose `null` means "none" are not numbers: `gas_model`, `layout.counterweight`).
fn finite(v: &Value) -> bool {
    match v {
        Value::Null => false,
        Value::Number(n) => n.as_f64().is_some_and(f64::is_finite),
        Value::Array(a) => a.iter().all(finite),
        Value::Object(o) => o.iter().all(|(k, v)| {
            k == "gas_model" || k == "counterweight" || finite(v) || v.is_string() || v.is_boolean()
        }),
        _ => true,
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 128, ..ProptestConfig::default() })]

    #[test]
    fn any_document_is_refused_clearly_or_runs_to_complete_results(
        changes in prop::collection::vec(change(16), 1..5)
    ) {
        let fields = schema_fields();
        let changes: Vec<Change> = changes
            .into_iter()
            .map(|c| match c {
                Change::Set(t, f, v) => Change::Set(t % fields.len(), f, v),
                Change::Drop(t, f) => Change::Drop(t % fields.len(), f),
                Change::Unknown(t, k, v) => Change::Unknown(t % fields.len(), k, v),
            })
            .collect();
        let text = document(&fields, &changes);
        let tmp = tempfile::tempdir().unwrap();
        let file = tmp.path().join("fuzz.toml");
        std::fs::write(&file, &text).unwrap();
        let cases = match cardan_case::case::load_file(&file) {
            Err(e) => {
                let said = e.to_string();
                prop_assert!(said.contains("fuzz.toml"), "no file in: {said}\n{text}");
                let names_a_place = said.contains("line ")
                    || fields.iter().any(|(t, f)| {
                        (!t.is_empty() && said.contains(t.as_str()))
                            || f.iter().any(|f| said.contains(f.as_str()))
                    })
                    || said.contains("x_");
                prop_assert!(names_a_place, "no field in: {said}\n{text}");
                return Ok(());
            }
            Ok(cases) => cases,
        };
        // Large cases are validated only: running them is no test of the validator.
        let small = cases.len() <= 4
            && cases.iter().all(|c| c.steps * c.mechanisms.len() <= 20_000);
        if !small {
            return Ok(());
        }
        let out = tmp.path().join("out");
        let report = run_paths(&[file], &out, RunOptions::default());
        for f in &report.failures {
            prop_assert!(f.contains("fuzz.toml"), "failure without its file: {f}");
            prop_assert!(!f.contains("internal error"), "a panic: {f}\n{text}");
        }
        for (name, dir) in &report.written {
            let summary: Value = serde_json::from_str(
                &std::fs::read_to_string(dir.join("summary.json")).unwrap(),
            )
            .unwrap();
            prop_assert!(finite(&summary["mechanisms"]), "{name}: not finite\n{text}");
            prop_assert!(dir.join("run.json").is_file(), "{name}: incomplete");
        }
        // No partial folder: nothing but the written cases (and the index) in `out`.
        if let Ok(entries) = std::fs::read_dir(&out) {
            for e in entries {
                let name = e.unwrap().file_name().to_string_lossy().into_owned();
                prop_assert!(!name.starts_with('.'), "leftover {name}");
                let expected = name == "index.html"
                    || report.written.iter().any(|(_, d)| {
                        d.strip_prefix(&out).ok().and_then(|p| p.iter().next())
                            == Some(std::ffi::OsStr::new(&name))
                    });
                prop_assert!(expected, "{name} written but not reported\n{text}");
            }
        }
    }
}
