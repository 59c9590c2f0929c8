//! A mechanism's own table (`[cardan_gear]`, `[hypotrochoid]`): the options its registry
//! entry declares, read by their kind. The registry is the schema here: adding an option to a
//! mechanism adds it to case files, to their JSON Schema and to the docs.

use crate::quantity::{self, Angle, Length, Number, Quantity};
use crate::schema::{suggest, FieldError};
use cardan_mechanism::{Entry, OptionKind, OptionValue, Options};
use serde_json::{json, Map, Value};

/// Reads the table of `entry` (`None`: the case has none, every option at its default).
pub(crate) fn options(table: Option<&toml::Value>, entry: &Entry) -> Result<Options, FieldError> {
    let mut options = Options::new();
    let Some(table) = table else {
        return Ok(options);
    };
    let error = |field: String, message: String| FieldError {
        field,
        message,
        expected: Box::default(),
    };
    let Some(table) = table.as_table() else {
        let rule = "must be a table of the mechanism's options";
        return Err(error(entry.name.into(), quantity::broken(table, rule)));
    };
    let declared: Vec<&str> = entry.options.iter().map(|o| o.name).collect();
    for (key, value) in table {
        let field = format!("{}.{key}", entry.name);
        let Some(spec) = entry.options.iter().find(|o| o.name == key) else {
            let what = format!("option of the {}", entry.name);
            return Err(error(field, suggest(&what, key, &declared)));
        };
        let number = match spec.kind {
            OptionKind::Choice(words) => match value.as_str() {
                Some(w) if words.contains(&w) => {
                    options.insert(key.clone(), OptionValue::Word(w.to_string()));
                    continue;
                }
                Some(w) => return Err(error(field, suggest("word", w, words))),
                None => {
                    let rule = format!("must be one of {}", quoted(words));
                    return Err(error(field, quantity::broken(value, &rule)));
                }
            },
            OptionKind::Angle => Quantity::<Angle>::from_value(value).map(|q| q.si),
            OptionKind::Length => Quantity::<Length>::from_value(value).map(|q| q.si),
            OptionKind::Number { min, max, whole } => Quantity::<Number>::from_value(value)
                .and_then(|q| {
                    let inside = (min..=max).contains(&q.si) && (!whole || q.si.fract() == 0.0);
                    inside.then_some(q.si).ok_or_else(|| {
                        let what = if whole { "a whole number" } else { "a number" };
                        format!("must be {what} from {min} to {max}: {}", spec.meaning)
                    })
                }),
        };
        let number = number.map_err(|rule| error(field, quantity::broken(value, &rule)))?;
        options.insert(key.clone(), OptionValue::Number(number));
    }
    Ok(options)
}

fn quoted(words: &[&str]) -> String {
    words
        .iter()
        .map(|w| format!("\"{w}\""))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The JSON Schema of `entry`'s table, from its declared options; `definitions` holds the
/// quantities' schemas (`Angle`, `Length`, `Number`).
pub fn json_schema(entry: &Entry) -> Value {
    let mut properties = Map::new();
    for o in entry.options {
        let schema = match o.kind {
            OptionKind::Choice(words) => json!({ "type": "string", "enum": words }),
            OptionKind::Angle => json!({ "$ref": "#/$defs/Angle" }),
            OptionKind::Length => json!({ "$ref": "#/$defs/Length" }),
            OptionKind::Number { min, max, whole } => {
                if whole {
                    json!({ "type": "integer", "minimum": min as i64, "maximum": max as i64 })
                } else {
                    json!({ "type": "number", "minimum": min, "maximum": max })
                }
            }
        };
        let mut schema = schema;
        schema["description"] = o.meaning.into();
        properties.insert(o.name.into(), schema);
    }
    json!({
        "type": "object",
        "description": format!("The {}'s own options: {}", entry.name, entry.summary),
        "properties": properties,
        "additionalProperties": false,
    })
}

/// The mechanisms' own tables of a case (`[cardan_gear]`) and their mass tables
/// (`[masses.cardan_gear]`), taken out of `table` (named by the registry, they are not part of
/// the typed schema).
#[derive(Default)]
pub(crate) struct MechanismTables {
    pub options: toml::Table,
    pub masses: toml::Table,
}

/// Takes the mechanisms' own tables and their mass tables out of a case's `table`.
pub(crate) fn mechanism_tables(table: &mut toml::Table) -> MechanismTables {
    let mut own = MechanismTables::default();
    let registered = |k: &String| cardan_mechanism::entry(k).is_some();
    let move_registered = |from: &mut toml::Table, into: &mut toml::Table| {
        for key in from
            .keys()
            .filter(|k| registered(k))
            .cloned()
            .collect::<Vec<_>>()
        {
            if let Some(value) = from.remove(&key) {
                into.insert(key, value);
            }
        }
    };
    move_registered(table, &mut own.options);
    if let Some(toml::Value::Table(masses)) = table.get_mut("masses") {
        move_registered(masses, &mut own.masses);
    }
    own
}
