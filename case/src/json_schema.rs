//! The JSON Schema of case files, generated from the typed schema ([`crate::case::CaseFile`]
//! and the tables it holds) and the registries (mechanisms' own tables and mass tables).
//! `cargo xtask schema` writes it to `schema/case.schema.json`, which editors use to complete
//! and check case files (`.taplo.toml`); the docs' field tables are generated from it.

use crate::case::CaseFile;
use crate::quantity::{Angle, Length, Quantity};
use schemars::generate::SchemaSettings;
use serde_json::{json, Value};

/// The case files' JSON Schema (draft 2020-12).
pub fn case_schema() -> Value {
    let mut generator = SchemaSettings::draft2020_12().into_generator();
    // The quantities the mechanisms' options refer to.
    generator.subschema_for::<Quantity<Angle>>();
    generator.subschema_for::<Quantity<Length>>();
    let sweep = crate::sweep::json_schema(&mut generator);
    let optimize =
        serde_json::to_value(generator.subschema_for::<crate::optimize::OptimizeTable>())
            .unwrap_or_default();
    let root = generator.into_root_schema_for::<CaseFile>();
    let mut root = serde_json::to_value(root).unwrap_or_default();
    root["title"] = "cardan case file".into();
    for entry in cardan_mechanism::MECHANISMS {
        root["properties"][entry.name] = crate::mechanism_table::json_schema(entry);
    }
    // A mechanism's own mass table: the mass fields without the machine's `rules`.
    let mut own = root["$defs"]["MassTable"].clone();
    if let Some(p) = own["properties"].as_object_mut() {
        p.remove("rules");
    }
    root["$defs"]["MechanismMassTable"] = own;
    for entry in cardan_mechanism::MECHANISMS {
        root["$defs"]["MassTable"]["properties"][entry.name] =
            json!({ "$ref": "#/$defs/MechanismMassTable" });
    }
    root["properties"]["sweep"] = sweep;
    root["properties"]["optimize"] = optimize;
    plain_descriptions(&mut root);
    root
}

/// Every `description` of `schema` as an editor shows it (issue 38.5): the doc comments'
/// links to the code dropped (`([`crate::gas::MODELS`])`, `(`ClosedCycle::nunes_2017`)`: the
/// reader of a case file does not read the code), and a link's text kept (`[`Foo`]` is `Foo`).
/// The lines stay as the doc comment wraps them (the docs' field tables take a description's
/// first sentence up to ". " and a capital: a line break ends none).
pub fn plain_descriptions(schema: &mut Value) {
    match schema {
        Value::Object(map) => {
            for (key, value) in map.iter_mut() {
                match value {
                    Value::String(text) if key == "description" => *text = plain(text),
                    _ => plain_descriptions(value),
                }
            }
        }
        Value::Array(items) => items.iter_mut().for_each(plain_descriptions),
        _ => {}
    }
}

/// `doc` without links to the code.
fn plain(doc: &str) -> String {
    let mut text = doc.to_string();
    // A parenthesis holding only a link or a path of the code: dropped with its space.
    while let Some((start, end)) = code_parenthesis(&text) {
        text.replace_range(start..end, "");
    }
    // A link's text kept: [`Foo`] and [`Foo`](path) are `Foo`.
    while let Some(open) = text.find("[`") {
        let Some(close) = text[open..].find("`]").map(|i| open + i) else {
            break;
        };
        let mut end = close + 2;
        if text[end..].starts_with('(') {
            end += text[end..].find(')').map_or(0, |i| i + 1);
        }
        let name = text[open + 1..close + 1].to_string();
        text.replace_range(open..end, &name);
    }
    text
}

/// The first " (...)" (or the parenthesis after a line break) of `text` that holds only a link
/// to the code (`[`Foo`]`) or a path of it (`` `a::b` ``): its start (the space) and end.
fn code_parenthesis(text: &str) -> Option<(usize, usize)> {
    for (open, _) in text.match_indices('(') {
        if !text[..open].ends_with([' ', '\n']) {
            continue;
        }
        let inner = open + 1;
        let Some(len) = text[inner..].find(')') else {
            continue;
        };
        let content = &text[inner..inner + len];
        let link = content.starts_with("[`") && content.ends_with("`]");
        let path = content.trim_start_matches('[').trim_end_matches(']');
        let one = path.len() > 2
            && path.starts_with('`')
            && path.ends_with('`')
            && !path[1..path.len() - 1].contains('`');
        if one && (link || path.contains("::")) {
            return Some((open - 1, inner + len + 1));
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn descriptions_lose_the_links_to_the_code_and_keep_their_words() {
        let cases = [
            (
                "Read by the model `model` names ([`crate::gas::MODELS`]).",
                "Read by the model `model` names.",
            ),
            (
                "Default 287.05, air (`cardan_gas::compressor::AIR_GAS_CONSTANT`).",
                "Default 287.05, air.",
            ),
            (
                "The reading of the rules ([`MassRules`]).",
                "The reading of the rules.",
            ),
            (
                "See [`Foo`] and [`Bar`](crate::bar).",
                "See `Foo` and `Bar`.",
            ),
            ("in m (`60 mm`), kept", "in m (`60 mm`), kept"),
        ];
        for (doc, plain_doc) in cases {
            assert_eq!(plain(doc), plain_doc, "{doc}");
        }
    }
}
