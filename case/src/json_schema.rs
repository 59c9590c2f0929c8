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
    root
}
