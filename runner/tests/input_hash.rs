//! The input hash (`run.json`, `shard.json`; `--resume` and `cardan merge` trust it) covers the
//! whole input: every field of the case file's schema, each found in the JSON Schema (not
//! listed here), mutated to another valid value, changes it; so do the bytes of a pressure
//! trace the case reads, a sweep point's own input, and an optimisation's definition.

use cardan_case::case::{case_of_table, load_file};
use cardan_runner::run::stamp::input_hash;
use serde_json::Value;
use std::path::{Path, PathBuf};

fn configs() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs")
}

/// A leaf field of the schema: its dotted path, its schema, and the gas model whose branch of
/// `[gas]` it belongs to.
#[derive(Debug, Clone)]
struct Leaf {
    path: Vec<String>,
    schema: Value,
    gas_model: Option<String>,
}

impl Leaf {
    fn name(&self) -> String {
        let path = self.path.join(".");
        match &self.gas_model {
            Some(m) => format!("{path} (model = \"{m}\")"),
            None => path,
        }
    }
}

/// `node` with its `$ref` followed and an optional value's `null` branch taken away.
fn resolve<'a>(node: &'a Value, root: &'a Value) -> &'a Value {
    if let Some(r) = node.get("$ref").and_then(Value::as_str) {
        let name = r.trim_start_matches("#/$defs/");
        return resolve(&root["$defs"][name], root);
    }
    if let Some(branches) = node.get("anyOf").and_then(Value::as_array) {
        let some: Vec<&Value> = branches
            .iter()
            .filter(|b| b.get("type") != Some(&Value::from("null")))
            .collect();
        if some.len() == 1 && some.len() < branches.len() {
            return resolve(some[0], root);
        }
    }
    node
}

/// Every leaf under `node` at `path`.
fn leaves(node: &Value, root: &Value, path: &[String], gas: Option<&str>, out: &mut Vec<Leaf>) {
    // A field's default is on the field, beside the reference to its type.
    let default = node.get("default").filter(|d| !d.is_null()).cloned();
    let node = resolve(node, root);
    let at = |k: &str| [path, &[k.to_string()]].concat();
    let gas_branches = node
        .get("allOf")
        .and_then(Value::as_array)
        .map(|b| b.iter().map(|b| &b["then"]).collect::<Vec<&Value>>())
        .filter(|b| {
            !b.is_empty()
                && b.iter()
                    .all(|b| b["properties"]["model"]["const"].is_string())
        });
    if let Some(branches) = gas_branches {
        // [gas]: an `if`/`then` per model, `model` a constant in its `then`.
        for branch in branches {
            let model = branch["properties"]["model"]["const"].as_str().unwrap();
            for (k, v) in branch["properties"].as_object().unwrap() {
                if k != "model" {
                    leaves(v, root, &at(k), Some(model), out);
                }
            }
        }
        out.push(Leaf {
            path: at("model"),
            schema: Value::Null,
            gas_model: None,
        });
        return;
    }
    if let Some(properties) = node.get("properties").and_then(Value::as_object) {
        for (k, v) in properties {
            leaves(v, root, &at(k), gas, out);
        }
        return;
    }
    // A table of named entries (`[friction.joints]`): an entry named as the cases name one, in
    // each of its forms (a word, a table).
    if let Some(entry) = node.get("additionalProperties").filter(|e| e.is_object()) {
        let name = at("crank_pin");
        match entry.get("anyOf").and_then(Value::as_array) {
            Some(forms) => forms
                .iter()
                .for_each(|form| leaves(form, root, &name, gas, out)),
            None => leaves(entry, root, &name, gas, out),
        }
        return;
    }
    let mut schema = node.clone();
    if let (Some(d), Some(o)) = (default, schema.as_object_mut()) {
        o.insert("default".into(), d);
    }
    out.push(Leaf {
        path: path.to_vec(),
        schema,
        gas_model: gas.map(String::from),
    });
}

/// The fields no valid mutation reaches alone, each with its reason. Kept short: every other
/// field of the schema is mutated.
const UNMUTABLE: &[(&str, &str)] = &[
    (
        "sweep",
        "a sweep's definition is not a case's input: each of its points is a case, whose \
         values and document are hashed (tested by a_sweep_points_hash_covers_its_input)",
    ),
    (
        "optimize",
        "an optimisation's definition is not a case's input: its folder's record has an input \
         hash of its own, made of its whole definition (tested by \
         an_optimisations_hash_covers_its_definition), and each point it runs is a case \
         validated as any other",
    ),
    (
        "gas.model",
        "a model's fields are its own: another model with the same fields is refused; every \
         model's fields are mutated, each in a case of that model",
    ),
];

/// Fields of the shared `[masses.<mechanism>]` schema for a body the mechanism lacks: refused on
/// reading (issue 36.15, the tables they apply to named), so no valid case holds them.
const NO_SUCH_BODY: &[&str] = &[
    "masses.hypotrochoid.piston_mass",
    "masses.hypotrochoid.wheel_mass",
    "masses.scotch_yoke.wheel_inertia",
    "masses.scotch_yoke.wheel_mass",
    "masses.slider_crank.wheel_inertia",
    "masses.slider_crank.wheel_mass",
];

/// The shipped cases (one case each; not the sweeps) and a case with `[friction.joints]`.
fn bases() -> Vec<(PathBuf, toml::Table)> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(configs())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    let mut bases: Vec<(PathBuf, toml::Table)> = files
        .into_iter()
        .map(|f| {
            let mut table: toml::Table =
                toml::from_str(&std::fs::read_to_string(&f).unwrap()).unwrap();
            // An optimisation's case, as a case: its `[optimize]` is hashed apart.
            table.remove("optimize");
            (f, table)
        })
        .collect();
    let joints = r#"
name = "joints"
machine = "pump"
mechanisms = ["slider_crank"]
[geometry]
crank_length = 0.06
rod_length = 0.14
bore = 0.12
[motion]
start_angle = 0.0
end_angle = 360.0
initial_speed = 31.4
angular_acceleration = 0.0
steps = 360
[friction]
[friction.joints]
crank_pin = { model = "palmgren", pitch_diameter = "50 mm", static_load_rating = "20 kN", count = 1 }
"#;
    bases.push((
        configs().join("joints.toml"),
        toml::from_str(joints).unwrap(),
    ));
    // The other loss models' parameters (each refused where no model of the case reads it).
    let models = "rings = \"film\"\nskirt = \"viscous\"\nbearings = \"petroff\"\n[friction.joints]";
    let films = joints
        .replace("[friction.joints]", models)
        .replace("\"joints\"", "\"films\"");
    bases.push((
        configs().join("films.toml"),
        toml::from_str(&films).unwrap(),
    ));
    // An engine with a valve train (the fields of the valve train's models).
    let engine = "karhula-engine-r60-l140-a0-w200pi-titanium.toml";
    let (file, table) = bases.iter().find(|(f, _)| f.ends_with(engine)).unwrap();
    let path = ["friction".to_string(), "valve_train".to_string()];
    let valves = set(table, &path, toml::Value::String("flat".into()));
    bases.push((file.clone(), valves));
    // A gear rated by ISO 6336 beside AGMA 2001 (the fields ISO reads, refused without it).
    let gear = "nunes-op-r26-l90-2000rpm-lead10.toml";
    let (file, table) = bases.iter().find(|(f, _)| f.ends_with(gear)).unwrap();
    let standard = ["gear".to_string(), "standard".to_string()];
    let grade = ["gear".to_string(), "accuracy_grade".to_string()];
    let iso = set(table, &standard, toml::Value::String("both".into()));
    bases.push((file.clone(), set(&iso, &grade, toml::Value::Integer(7))));
    bases
}

fn get<'a>(table: &'a toml::Table, path: &[String]) -> Option<&'a toml::Value> {
    let (last, parents) = path.split_last()?;
    let mut t = table;
    for p in parents {
        t = t.get(p)?.as_table()?;
    }
    t.get(last)
}

/// `table` with `value` at `path` (missing tables made).
fn set(table: &toml::Table, path: &[String], value: toml::Value) -> toml::Table {
    let mut table = table.clone();
    let (last, parents) = path.split_last().unwrap();
    let mut t = &mut table;
    for p in parents {
        t = t
            .entry(p.clone())
            .or_insert_with(|| toml::Value::Table(Default::default()))
            .as_table_mut()
            .unwrap();
    }
    t.insert(last.clone(), value);
    table
}

/// A bare number a field of any dimension may take, for a field the base leaves out.
const NUMBERS: &[f64] = &[
    0.5, 1.0, 2.0, 0.1, 0.01, 10.0, 0.9, 0.05, 3.0, 100.0, 0.001, 300.0, 1000.0, 1e5, 1e6, 1e-5,
    20.0, 6000.0, 1e4, 0.3, 5e6, 1e9, 2e11, 500.0,
];

/// Other values than `current` for a value of `schema`: the mutations tried, in order.
fn candidates(
    schema: &Value,
    current: Option<&toml::Value>,
    root: &Value,
    field: &str,
) -> Vec<toml::Value> {
    use toml::Value as T;
    let metric = field == "metrics";
    let schema = resolve(schema, root);
    // Words: an enum, or a oneOf of constants (words with their descriptions).
    let words: Option<Vec<&str>> = match (schema.get("enum"), schema.get("oneOf")) {
        (Some(Value::Array(words)), _) => Some(words.iter().filter_map(Value::as_str).collect()),
        (_, Some(Value::Array(branches))) => branches
            .iter()
            .map(|b| b.get("const").and_then(Value::as_str))
            .collect(),
        _ => None,
    };
    if let Some(words) = words {
        // Left out, the field is its default: another word than that.
        let now = current
            .and_then(T::as_str)
            .or(schema.get("default").and_then(Value::as_str));
        return words
            .into_iter()
            .filter(|w| now != Some(w))
            .map(|w| T::String(w.into()))
            .collect();
    }
    let types: Vec<&str> = match &schema["type"] {
        Value::String(t) => vec![t.as_str()],
        Value::Array(ts) => ts.iter().filter_map(Value::as_str).collect(),
        _ => vec![],
    };
    if types.contains(&"boolean") {
        return match (current, schema.get("default")) {
            (Some(T::Boolean(b)), _) => vec![T::Boolean(!b)],
            (None, Some(Value::Bool(b))) => vec![T::Boolean(!b)],
            _ => vec![T::Boolean(true), T::Boolean(false)],
        };
    }
    if types.contains(&"array") {
        let items = &schema["items"];
        // Rows of a table over one period (a torque table): a constant row, over a pump's
        // period and an engine's.
        if let Some([x, y]) = items
            .get("prefixItems")
            .and_then(|p| p.as_array().map(Vec::as_slice))
        {
            let mut out = Vec::new();
            // The first column an angle in degrees.
            assert!(x.to_string().contains("Angle"), "{x}");
            for b in candidates(y, None, root, field) {
                for period in [360.0, 720.0] {
                    let row = |angle: f64| T::Array(vec![T::Float(angle), b.clone()]);
                    out.push(T::Array(vec![row(0.0), row(period / 2.0), row(period)]));
                }
            }
            return out;
        }
        return match current.and_then(T::as_array) {
            Some(a) if !a.is_empty() => {
                let mut out: Vec<T> = candidates(items, Some(&a[0]), root, field)
                    .into_iter()
                    .map(|c| {
                        let mut b = a.clone();
                        b[0] = c;
                        T::Array(b)
                    })
                    .collect();
                // Another element, or one fewer.
                for c in candidates(items, None, root, field) {
                    out.push(T::Array([a.clone(), vec![c]].concat()));
                }
                out.push(T::Array(a[1..].to_vec()));
                out
            }
            _ => {
                let mut out = Vec::new();
                for c in candidates(items, None, root, field) {
                    for n in 1..=6 {
                        out.push(T::Array(vec![c.clone(); n]));
                    }
                }
                // Distinct whole numbers (a firing order), pairs (a torque table).
                for n in 1..=6 {
                    out.push(T::Array((1..=n).rev().map(T::Integer).collect()));
                }
                out
            }
        };
    }
    if types.contains(&"integer") {
        let low = schema["minimum"].as_i64().unwrap_or(0);
        let high = schema["maximum"].as_i64().unwrap_or(i64::MAX);
        let values: Vec<i64> = match current.and_then(T::as_integer) {
            Some(n) => vec![n + 1, n - 1],
            None => vec![low, low + 1, 2, 3, 4, 10, 100, 1000],
        };
        return values
            .into_iter()
            .filter(|n| (low..=high).contains(n))
            .map(T::Integer)
            .collect();
    }
    if types.contains(&"string") && schema.get("anyOf").is_none() {
        return match current.and_then(T::as_str) {
            // A metric's name (`[output] metrics`): the registry's.
            None if metric => cardan_dynamics::metrics::METRICS
                .iter()
                .filter(|m| !m.name.contains('{'))
                .map(|m| T::String(m.name.into()))
                .collect(),
            // A file's name: the same file by another name (its bytes: the trace test).
            Some(s) if s.contains('/') => vec![T::String(format!("./{s}"))],
            Some(s) => vec![T::String(format!("{s}x"))],
            None => vec![T::String("x".into())],
        };
    }
    if types.contains(&"number") || schema.get("anyOf").is_some() {
        let scaled = |x: f64| -> Vec<f64> {
            if x == 0.0 {
                vec![0.5, 0.1, 1.0, 1e-3, -0.1]
            } else {
                vec![x * 1.01, x * 0.99, x * 1.1, x * 0.9]
            }
        };
        return match current {
            Some(T::Float(x)) => scaled(*x).into_iter().map(T::Float).collect(),
            Some(T::Integer(n)) => scaled(*n as f64).into_iter().map(T::Float).collect(),
            Some(T::String(s)) => {
                let s = s.trim();
                let end = s
                    .find(|c: char| !(c.is_ascii_digit() || "+-.eE".contains(c)))
                    .unwrap_or(s.len());
                let x: f64 = s[..end].trim().parse().unwrap();
                scaled(x)
                    .into_iter()
                    .map(|y| T::String(format!("{y} {}", s[end..].trim())))
                    .collect()
            }
            _ => NUMBERS.iter().map(|&x| T::Float(x)).collect(),
        };
    }
    Vec::new()
}

fn hash(file: &Path, table: toml::Table) -> Option<String> {
    case_of_table(file, table)
        .ok()
        .map(|case| input_hash(&case, false))
}

/// Every leaf field of the case schema, mutated alone to another valid value in a case that
/// reads it, changes the input hash.
#[test]
fn every_field_of_the_schema_changes_the_input_hash() {
    let root = cardan_case::json_schema::case_schema();
    let mut all = Vec::new();
    leaves(&root, &root, &[], None, &mut all);
    assert!(
        all.len() > 100,
        "{} leaves: the schema was not walked",
        all.len()
    );
    let bases = bases();
    let (mut unchanged, mut unmutated, mut mutated) = (Vec::new(), Vec::new(), 0);
    for leaf in &all {
        let name = leaf.name();
        if UNMUTABLE
            .iter()
            .any(|(f, _)| leaf.path.join(".") == *f || leaf.path[0] == *f)
            || NO_SUCH_BODY.contains(&leaf.path.join(".").as_str())
        {
            continue;
        }
        // The cases of the leaf's gas model; those that give the field first.
        let mut fitting: Vec<&(PathBuf, toml::Table)> = bases
            .iter()
            .filter(|(_, t)| match &leaf.gas_model {
                Some(m) => {
                    get(t, &["gas".into(), "model".into()]).and_then(toml::Value::as_str)
                        == Some(m.as_str())
                }
                None => true,
            })
            .collect();
        fitting.sort_by_key(|(_, t)| get(t, &leaf.path).is_none());
        let mut done = false;
        'bases: for (file, base) in fitting {
            let current = get(base, &leaf.path);
            for value in candidates(&leaf.schema, current, &root, leaf.path.last().unwrap()) {
                let changed = set(base, &leaf.path, value.clone());
                let Some(after) = hash(file, changed) else {
                    continue;
                };
                let before = hash(file, base.clone()).expect("a shipped case validates");
                if before == after {
                    unchanged.push(format!(
                        "{name} = {value} in {} ({current:?} before)",
                        file.display()
                    ));
                }
                mutated += 1;
                done = true;
                break 'bases;
            }
        }
        if !done {
            unmutated.push(name);
        }
    }
    assert!(
        unchanged.is_empty(),
        "the input hash does not change with:\n{}",
        unchanged.join("\n")
    );
    assert!(
        unmutated.is_empty(),
        "no valid mutation found for (add a mutation, or the field and its reason to UNMUTABLE):\n{}",
        unmutated.join("\n")
    );
    assert!(mutated > 100, "{mutated} fields mutated");
}

/// A copy of the shipped pressure-trace case and its trace in a folder of their own.
fn trace_case(dir: &Path) -> (PathBuf, PathBuf) {
    let case = dir.join("case.toml");
    let text = std::fs::read_to_string(configs().join("example-pressure-trace.toml")).unwrap();
    std::fs::write(&case, text).unwrap();
    std::fs::create_dir(dir.join("traces")).unwrap();
    let trace = dir.join("traces/karhula-engine-r60-l140-6000rpm.csv");
    std::fs::copy(
        configs().join("traces/karhula-engine-r60-l140-6000rpm.csv"),
        &trace,
    )
    .unwrap();
    (case, trace)
}

/// A pressure trace's bytes are part of the input: the same file name with another pressure
/// is another input; the same bytes again, the same.
#[test]
fn a_pressure_traces_bytes_change_the_input_hash() {
    let dir = tempfile::tempdir().unwrap();
    let (case, trace) = trace_case(dir.path());
    let hash = || {
        let cases = load_file(&case).unwrap();
        input_hash(&cases[0], false)
    };
    let before = hash();
    assert_eq!(before, hash(), "the hash is not stable");
    let text = std::fs::read_to_string(&trace).unwrap();
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    // The second data row's pressure, one part in a thousand higher.
    let (angle, p) = lines[2].split_once(',').unwrap();
    let p: f64 = p.trim().parse().unwrap();
    lines[2] = format!("{angle},{}", p * 1.001);
    std::fs::write(&trace, lines.join("\n") + "\n").unwrap();
    assert_ne!(before, hash(), "a changed trace kept the input hash");
    std::fs::write(&trace, &text).unwrap();
    assert_eq!(before, hash());
}

/// A sweep's point is hashed with its own input: a field outside the swept ones changed in
/// the sweep's file changes every point's hash (each point's case is its whole document).
#[test]
fn a_sweep_points_hash_covers_its_input() {
    let file = configs().join("sweeps/karhula-engine-speed-sweep.toml");
    let text = std::fs::read_to_string(&file).unwrap();
    assert!(
        text.contains("peak_pressure"),
        "the sweep has no peak_pressure"
    );
    let hashes = |text: &str| -> Vec<String> {
        let table: toml::Table = toml::from_str(text).unwrap();
        cardan_case::case::cases_of_table(&file, table)
            .unwrap()
            .iter()
            .map(|c| input_hash(c, false))
            .collect()
    };
    let before = hashes(&text);
    let mut table: toml::Table = toml::from_str(&text).unwrap();
    let gas = table.get_mut("gas").unwrap().as_table_mut().unwrap();
    gas.insert("peak_pressure".into(), toml::Value::String("13 MPa".into()));
    let after = hashes(&toml::to_string(&table).unwrap());
    assert_eq!(before.len(), after.len());
    for (k, (b, a)) in before.iter().zip(&after).enumerate() {
        assert_ne!(b, a, "point {k} kept its hash after peak_pressure changed");
    }
}

/// An optimisation's folder (`[optimize]`) is hashed by its whole definition: its objective,
/// sense, a variable's range, a constraint, a search setting and a field of the case it varies
/// each change the hash; the same file read from another folder keeps it.
#[test]
fn an_optimisations_hash_covers_its_definition() {
    use cardan_case::optimize::Optimization;
    use cardan_runner::run::stamp::optimization_hash;
    let file = configs().join("optimize-thesis-pump.toml");
    let text = std::fs::read_to_string(&file).unwrap();
    let hash = |file: &Path, text: &str| {
        let table = cardan_case::case::toml_table(file, text).unwrap();
        let o = Optimization::define(file, table).unwrap().unwrap();
        optimization_hash(&o, true)
    };
    let before = hash(&file, &text);
    assert_eq!(before, hash(Path::new("elsewhere/opt.toml"), &text));
    let dir = tempfile::tempdir().unwrap();
    let moved = dir.path().join("optimize-thesis-pump.toml");
    std::fs::write(&moved, &text).unwrap();
    assert_eq!(before, hash(&moved, &text), "moved to another folder");
    assert_ne!(
        before,
        optimization_hash(
            &Optimization::define(&file, cardan_case::case::toml_table(&file, &text).unwrap())
                .unwrap()
                .unwrap(),
            false
        ),
        "with and without reports"
    );
    for (from, to) in [
        ("sense = \"max\"", "sense = \"min\""),
        ("[\"100 mm\", \"300 mm\"]", "[\"100 mm\", \"250 mm\"]"),
        (
            "\"bending_safety_factor >= 1.2\"",
            "\"bending_safety_factor >= 1.3\"",
        ),
        ("seed = 1", "seed = 2"),
        ("max_evaluations = 400", "max_evaluations = 300"),
        ("bore = \"120 mm\"", "bore = \"121 mm\""),
        ("counterweight = 0.5", "counterweight = 0.6"),
        (
            "objective = \"machine_mechanical_efficiency\"",
            "objective = \"machine_mechanical_efficiency\"\nstarts = 3",
        ),
    ] {
        assert!(text.contains(from), "{from}");
        let changed = text.replacen(from, to, 1);
        assert_ne!(
            before,
            hash(&file, &changed),
            "{from} -> {to} kept the hash"
        );
    }
}
