//! The parts of the documentation that are made from the code's registries: the metric table,
//! the CSV column table, the mechanism list, the case file's fields and the plausible ranges of
//! its bare numbers (in README.md or docs/, [`DOCUMENTS`]).
//! `cargo xtask readme` writes them; a test fails when a document and the registries disagree.

use cardan_mechanism::{JointKind, MachineGeometry, MassInputs, OptionKind, Options, MECHANISMS};

/// (marker name, Markdown) of every generated section.
pub fn sections() -> Vec<(&'static str, String)> {
    vec![
        ("metrics", cardan_dynamics::metrics::markdown_table()),
        ("columns", columns_table()),
        ("mechanisms", mechanisms_table()),
        (
            "case-fields",
            fields_tables(&cardan_case::json_schema::case_schema()),
        ),
        ("ranges", ranges_table()),
    ]
}

/// The plausible ranges of the case file's bare numbers (`cardan_case::plausible::TABLE`):
/// each range's ends and its rule with the reason.
fn ranges_table() -> String {
    let mut t = String::from("| range | from | to | rule and reason |\n|---|---|---|---|\n");
    for (name, min, max, rule) in cardan_case::plausible::TABLE {
        t.push_str(&format!("| `{name}` | {min} | {max} | {rule} |\n"));
    }
    t
}

/// The field tables of a case file, one per table, from its JSON Schema: each field, what its
/// value must be, whether it is required, and its doc's first sentence. Sibling tables of one
/// definition (`[masses.<mechanism>]`) are described once.
fn fields_tables(root: &serde_json::Value) -> String {
    use cardan_case::schema::{first_sentence, resolve, value_kind};
    /// A table to describe: its parent's path, its names there, its schema.
    struct Table<'a> {
        parent: String,
        names: Vec<String>,
        schema: &'a serde_json::Value,
    }
    let mut out = String::new();
    let mut tables = vec![Table {
        parent: String::new(),
        names: Vec::new(),
        schema: root,
    }];
    while let Some(table) = tables.pop() {
        let node = resolve(root, table.schema);
        let Some(properties) = node.get("properties").and_then(|p| p.as_object()) else {
            continue;
        };
        if properties.is_empty() {
            continue;
        }
        let path = match &table.names[..] {
            [] => String::new(),
            [one] => join(&table.parent, one),
            _ => join(&table.parent, "<mechanism>"),
        };
        let title = match &table.names[..] {
            [] => "top level".to_string(),
            [_] => format!("[{path}]"),
            names => format!("[{path}], for each of {}", names.join(", ")),
        };
        let required: Vec<&str> = node
            .get("required")
            .and_then(|r| r.as_array())
            .map(|r| r.iter().filter_map(|v| v.as_str()).collect())
            .unwrap_or_default();
        out.push_str(&format!(
            "\n**{title}**\n\n| field | value | required | meaning |\n|---|---|---|---|\n"
        ));
        let mut nested: Vec<Table> = Vec::new();
        for (name, schema) in properties {
            let full = join(&path, name);
            let kind = value_kind(root, schema, &full).unwrap_or_default();
            let doc = schema
                .get("description")
                .or_else(|| resolve(root, schema).get("description"))
                .and_then(|d| d.as_str())
                .map(|d| first_sentence(d).replace('\n', " "))
                .unwrap_or_default();
            let needed = if required.contains(&name.as_str()) {
                "yes"
            } else {
                "no"
            };
            out.push_str(&format!("| `{name}` | {kind} | {needed} | {doc} |\n"));
            if resolve(root, schema).get("properties").is_none() {
                continue;
            }
            let reference = schema.get("$ref");
            match nested
                .iter_mut()
                .find(|t| reference.is_some() && t.schema.get("$ref") == reference)
            {
                Some(same) => same.names.push(name.clone()),
                None => nested.push(Table {
                    parent: path.clone(),
                    names: vec![name.clone()],
                    schema,
                }),
            }
        }
        // Depth first, in the order of the fields.
        tables.extend(nested.into_iter().rev());
    }
    out
}

fn join(table: &str, key: &str) -> String {
    if table.is_empty() {
        key.to_string()
    } else {
        format!("{table}.{key}")
    }
}

fn columns_table() -> String {
    let mut t = String::from("| column | meaning |\n|---|---|\n");
    for (name, meaning) in cardan_runner::per_step::COLUMNS {
        t.push_str(&format!("| `{name}` | {meaning} |\n"));
    }
    t
}

fn mechanisms_table() -> String {
    // Any valid machine shows the topology: the Karhula thesis machine.
    let geometry = MachineGeometry {
        crank_length: 0.06,
        rod_length: 0.14,
        bore: 0.12,
        pin_offset: 0.0,
    };
    let mut t = String::from(
        "| `mechanisms` name | what it is | bodies | joints | options |\n|---|---|---|---|---|\n",
    );
    for e in MECHANISMS {
        let m = (e.build)(&geometry, &MassInputs::default(), &Options::new())
            .expect("the thesis machine is valid for every mechanism");
        let top = m.topology();
        let bodies: Vec<String> = top.bodies.iter().map(|b| format!("`{}`", b.name)).collect();
        let joints: Vec<String> = top
            .joints
            .iter()
            .map(|j| {
                let kind = match j.kind {
                    JointKind::Revolute(_) => "pin",
                    JointKind::Prismatic => "slide",
                    JointKind::GearMesh { .. } => "gear mesh",
                };
                format!("`{}` ({kind})", j.name)
            })
            .collect();
        let options: Vec<String> = e
            .options
            .iter()
            .map(|o| {
                let kind = match o.kind {
                    OptionKind::Angle => "angle".to_string(),
                    OptionKind::Length => "length".to_string(),
                    OptionKind::Number { min, max, whole } => {
                        let what = if whole { "whole number" } else { "number" };
                        format!("{what} from {min} to {max}")
                    }
                    OptionKind::Choice(w) => w.join(" / "),
                };
                format!("`{}` ({kind}): {}", o.name, o.meaning)
            })
            .collect();
        t.push_str(&format!(
            "| `{}` | {} | {} | {} | {} |\n",
            e.name,
            e.summary,
            bodies.join(", "),
            joints.join(", "),
            if options.is_empty() {
                "none".to_string()
            } else {
                options.join("; ")
            }
        ));
    }
    t
}

/// The documents that hold generated sections, relative to the repository's root.
pub const DOCUMENTS: &[&str] = &["README.md", "docs/case-file.md", "docs/results.md"];

/// `text` with every generated section it holds replaced by the registries' current text, and
/// the names of the sections it held.
pub fn regenerate(text: &str) -> Result<(String, Vec<&'static str>), String> {
    let mut text = text.to_string();
    let mut held = Vec::new();
    for (name, body) in sections() {
        let (begin, end) = (
            format!("<!-- generated:{name} -->\n"),
            format!("<!-- end:{name} -->"),
        );
        let Some(start) = text.find(&begin).map(|i| i + begin.len()) else {
            continue;
        };
        let stop = text[start..]
            .find(&end)
            .ok_or_else(|| format!("{begin:?} has no {end:?} after it"))?
            + start;
        text.replace_range(start..stop, &body);
        held.push(name);
    }
    Ok((text, held))
}

/// Every document of [`DOCUMENTS`] under `root` regenerated: (path, current text, fresh text);
/// an error where a section is in no document or in two.
pub fn regenerate_all(
    root: &std::path::Path,
) -> Result<Vec<(std::path::PathBuf, String, String)>, String> {
    let mut out = Vec::new();
    let mut seen: Vec<&str> = Vec::new();
    for doc in DOCUMENTS {
        let path = root.join(doc);
        let text =
            std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
        let (fresh, held) = regenerate(&text).map_err(|e| format!("{doc}: {e}"))?;
        for h in held {
            if seen.contains(&h) {
                return Err(format!("the generated section {h} is in two documents"));
            }
            seen.push(h);
        }
        out.push((path, text, fresh));
    }
    for (name, _) in sections() {
        if !seen.contains(&name) {
            return Err(format!("no document has the generated section {name}"));
        }
    }
    Ok(out)
}

/// The JSON Schemas shipped for editors: (path under the root, generated text).
/// `cargo xtask schema` writes them; a test checks that the shipped ones are fresh.
pub fn schemas() -> Vec<(&'static str, String)> {
    let text = |schema: serde_json::Value| {
        let mut text = serde_json::to_string_pretty(&schema).unwrap_or_default();
        text.push('\n');
        text
    };
    vec![
        (
            "schema/case.schema.json",
            text(cardan_case::json_schema::case_schema()),
        ),
        (
            "schema/gear-file.schema.json",
            text(cardan_gear_file::gear_file_schema()),
        ),
    ]
}
