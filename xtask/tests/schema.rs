//! The JSON Schema of case files is the typed schema's: the shipped file is fresh, every
//! shipped case validates against it, and a misspelled field does not.

use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn case_schema() -> jsonschema::Validator {
    jsonschema::validator_for(&cardan_case::json_schema::case_schema()).unwrap()
}

/// Every place `value` breaks the schema, with its path.
fn errors(validator: &jsonschema::Validator, value: &serde_json::Value) -> Vec<String> {
    validator
        .iter_errors(value)
        .map(|e| format!("{} at {}", e, e.instance_path()))
        .collect()
}

fn as_json(text: &str) -> serde_json::Value {
    let table: toml::Table = toml::from_str(text).unwrap();
    serde_json::to_value(table).unwrap()
}

#[test]
fn the_shipped_schemas_are_fresh() {
    for (path, fresh) in xtask_gen::schemas() {
        let shipped = std::fs::read_to_string(root().join(path)).unwrap_or_default();
        assert!(
            shipped == fresh,
            "{path} is stale: run `cargo xtask schema`"
        );
    }
}

#[test]
fn every_shipped_case_validates_against_the_schema() {
    let validator = case_schema();
    let mut checked = 0;
    for entry in std::fs::read_dir(root().join("configs")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let value = as_json(&text);
        let errors = errors(&validator, &value);
        assert!(errors.is_empty(), "{}: {errors:#?}", path.display());
        checked += 1;
    }
    assert!(checked > 10, "only {checked} cases");
}

/// What the reader refuses for its form, the schema refuses too: a misspelled field or table,
/// an unknown word, a count out of range, an unknown unit. (The rules between fields and the
/// plausibility of bare numbers are the reader's alone.)
#[test]
fn the_schema_refuses_what_the_reader_refuses() {
    let validator = case_schema();
    let good =
        std::fs::read_to_string(root().join("configs/karhula-r60-l140-a0-w3pi.toml")).unwrap();
    assert!(validator.is_valid(&as_json(&good)));
    for (from, to) in [
        ("crank_length", "crank_lenght"),
        ("machine = \"pump\"", "machine = \"pmup\""),
        ("steps = 7200", "steps = 4"),
        ("bore = 0.12", "bore = \"120 furlongs\""),
        ("[motion]", "[motions]"),
    ] {
        assert!(good.contains(from), "test set-up: {from}");
        let bad = good.replacen(from, to, 1);
        assert!(!validator.is_valid(&as_json(&bad)), "accepted {to}");
    }
}

#[test]
fn every_shipped_gear_file_validates_against_its_schema() {
    let validator = jsonschema::validator_for(&cardan_gear_file::gear_file_schema()).unwrap();
    let mut checked = 0;
    for entry in std::fs::read_dir(root().join("configs-gears")).unwrap() {
        let path = entry.unwrap().path();
        let text = std::fs::read_to_string(&path).unwrap();
        let value = as_json(&text);
        let errors = errors(&validator, &value);
        assert!(errors.is_empty(), "{}: {errors:#?}", path.display());
        // Its first field misspelled is refused.
        let key = text
            .lines()
            .find_map(|l| {
                l.split_once(" =")
                    .map(|(k, _)| k)
                    .filter(|k| !k.starts_with('#'))
            })
            .unwrap();
        let misspelled = text.replacen(&format!("{key} ="), &format!("{key}x ="), 1);
        assert!(!validator.is_valid(&as_json(&misspelled)), "{key}");
        checked += 1;
    }
    assert!(checked >= 2);
}

/// What an editor shows (issue 38.5): a misspelled gas model gets the list of the models (the
/// `enum` of `model`, not "not valid under any of the schemas listed in the 'oneOf'"), and a
/// bare number outside its dimension's plausible range is flagged as the reader refuses it.
#[test]
fn an_editor_names_the_gas_models_and_flags_implausible_bare_numbers() {
    let validator = case_schema();
    let pump = std::fs::read_to_string(root().join("configs/karhula-pump-r60-l140-a0-w30pi.toml"))
        .unwrap();
    assert!(validator.is_valid(&as_json(&pump)));
    let typo = pump.replacen("model = \"karhula_pump\"", "model = \"karhula_pmup\"", 1);
    // One error, at the model, that it is not one of the models (the validator names the first
    // two and counts the others; an editor lists the `enum`, which holds every model).
    let said = errors(&validator, &as_json(&typo));
    assert_eq!(said.len(), 1, "{said:#?}");
    let one = &said[0];
    assert!(one.contains("is not one of"), "{one}");
    assert!(
        one.contains("\"karhula_pump\"") && one.ends_with("at /gas/model"),
        "{one}"
    );
    let schema = cardan_case::json_schema::case_schema();
    let listed = &schema["properties"]["gas"]["properties"]["model"]["enum"];
    for model in cardan_case::gas::MODELS {
        let name = serde_json::Value::from(model.name);
        assert!(listed.as_array().unwrap().contains(&name), "{listed}");
    }
    // A field of another model is refused for this one (the `then` of its `if`).
    let alien = pump.replacen(
        "model = \"karhula_pump\"",
        "model = \"karhula_pump\"\nlambda = 1",
        1,
    );
    assert!(!validator.is_valid(&as_json(&alien)));
    // crank_length = 60 is 60 m: the reader refuses it (a bare length above 10 m), so does the
    // schema; "60 mm" and 0.06 pass.
    let crank = "crank_length = 0.06";
    assert!(pump.contains(crank));
    for (value, valid) in [
        ("60", false),
        ("-0.06", false),
        ("0", false),
        ("\"60 mm\"", true),
        ("0.06", true),
        ("0.05", true),
    ] {
        let text = pump.replacen(crank, &format!("crank_length = {value}"), 1);
        let read = cardan_case::case::parse(Path::new("x.toml"), &text).is_ok();
        assert_eq!(read, valid, "the reader, crank_length = {value}");
        assert_eq!(
            validator.is_valid(&as_json(&text)),
            valid,
            "the schema, crank_length = {value}"
        );
    }
}

/// The descriptions an editor shows hold no links to the code (`[`Foo`]`, `crate::...`).
#[test]
fn descriptions_hold_no_links_to_the_code() {
    fn walk(node: &serde_json::Value, at: &str, bad: &mut Vec<String>) {
        match node {
            serde_json::Value::Object(map) => {
                for (k, v) in map {
                    match v.as_str() {
                        Some(d) if k == "description" => {
                            if d.contains("[`") || d.contains("::") || d.contains("](") {
                                bad.push(format!("{at}: {d}"));
                            }
                        }
                        _ => walk(v, &format!("{at}/{k}"), bad),
                    }
                }
            }
            serde_json::Value::Array(items) => {
                for (i, v) in items.iter().enumerate() {
                    walk(v, &format!("{at}/{i}"), bad);
                }
            }
            _ => {}
        }
    }
    let mut bad = Vec::new();
    walk(&cardan_case::json_schema::case_schema(), "", &mut bad);
    assert!(bad.is_empty(), "{bad:#?}");
}
