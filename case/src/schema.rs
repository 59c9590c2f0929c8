//! Reading a TOML table into the typed schema's structs, and saying what went wrong as a
//! person would: the field's dotted path, then what is wrong with it. The structs carry the
//! rules (`deny_unknown_fields`, enums of words, [`crate::quantity`]'s units and signs); this
//! module only turns serde's messages into the project's:
//! - a rule a value breaks: `path = value: rule` ([`crate::quantity::broken`]);
//! - a misspelled field or word: `path: unknown field "x": did you mean "y"? (...)`, the
//!   nearest valid name by edit distance;
//! - a value of the wrong form: `path: must be a whole number, not 360.5` rather than serde's
//!   Rust type names.

use schemars::JsonSchema;
use serde::de::DeserializeOwned;
use serde_json::Value;

/// Where a field went wrong and what is wrong with it (the file and case are the caller's).
#[derive(Debug, Clone, PartialEq)]
pub struct FieldError {
    /// Dotted path of the field (`geometry.crank_length`, `masses.cardan_gear.rod_mass`).
    pub field: String,
    /// What is wrong: `= value: rule`, or a sentence.
    pub message: String,
    /// For an unknown field: the valid names of its table (a caller that also takes other
    /// names there, e.g. the mechanisms' tables, says so with [`FieldError::unknown_among`]).
    pub expected: Box<[String]>,
}

impl FieldError {
    /// An unknown field's error again, with `more` names also valid in its table.
    pub fn unknown_among(mut self, more: &[&str]) -> Self {
        if self.message.starts_with("unknown field") {
            let name = self
                .field
                .rsplit('.')
                .next()
                .unwrap_or_default()
                .to_string();
            let mut expected: Vec<&str> = self.expected.iter().map(String::as_str).collect();
            expected.extend(more);
            self.message = suggest("field", &name, &expected);
        }
        self
    }
}

impl std::fmt::Display for FieldError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.message.starts_with("= ") {
            write!(f, "{} {}", self.field, self.message)
        } else {
            write!(f, "{}: {}", self.field, self.message)
        }
    }
}

/// Reads `value` (the table at `prefix`, "" for the whole file) as a `T`. A field missing or of
/// the wrong form is said with what its schema says it must be.
pub fn read<T: DeserializeOwned + JsonSchema>(
    value: toml::Value,
    prefix: &str,
) -> Result<T, FieldError> {
    // The value is kept to show a wrong one as written (serde names only its type).
    let written = value.clone();
    serde_path_to_error::deserialize(value).map_err(|e| {
        let path = e.path().to_string();
        let inner = if path == "." { String::new() } else { path };
        let message = e.into_inner().message().trim_end().to_string();
        let root = || serde_json::to_value(schemars::schema_for!(T)).unwrap_or_default();
        let shown = at(&written, &inner).map(|v| crate::units::show(&v.to_string()));
        explain(prefix, &inner, &message, shown, root)
    })
}

/// serde's `message` for the field at `inner` (relative to `T`, whose schema `root` gives) in
/// the project's words.
fn explain(
    prefix: &str,
    inner: &str,
    message: &str,
    shown: Option<String>,
    root: impl Fn() -> Value,
) -> FieldError {
    let mut field = join(prefix, inner);
    let mut expected = Box::default();
    // A table written as an array of tables (`[[geometry]]`) reads, as serde may read a
    // struct from a list, as `geometry[0]` of the wrong form.
    if let Some(i) = inner.find('[') {
        let table = &inner[..i];
        if what(&root(), table, table).is_some_and(|w| w.starts_with("a table")) {
            let field = join(prefix, table);
            return FieldError {
                message: format!(
                    "= [[{field}]]: must be a table ([{field}]), not an array of tables ([[{field}]]): write [{field}] once"
                ),
                field,
                expected,
            };
        }
    }
    let message = if let Some((name, valid)) = unknown(message, "field") {
        expected = valid.iter().map(|v| v.to_string()).collect();
        suggest("field", name, &valid)
    } else if let Some((name, valid)) = unknown(message, "variant") {
        suggest("word", name, &valid)
    } else if let Some(name) = between(message, "missing field `", "`") {
        let path = join(inner, name);
        field = join(prefix, &path);
        match what(&root(), &path, &field) {
            Some(what) => format!("= (missing): required: {what}"),
            None => "= (missing): required".to_string(),
        }
    } else if message.starts_with("wanted exactly 1 element") {
        // A word (an enum) written as a list or table (`machine = []`): serde reads an enum
        // from a one-element list or table and says only how many elements it found.
        let shown = shown.as_deref().unwrap_or("(a list or table)");
        match what(&root(), inner, &field) {
            Some(w) => format!("= {shown}: must be {w}"),
            None => format!("= {shown}: must be one word, not a list or table"),
        }
    } else if let Some((found, _)) = wrong_type(message) {
        let what = what(&root(), inner, &field);
        match (found, what) {
            (found, Some(w)) => format!("= {}: must be {w}", shown.as_deref().unwrap_or(found)),
            (_, None) => message.to_string(),
        }
    } else {
        message.to_string()
    };
    FieldError {
        field,
        message,
        expected,
    }
}

/// The value at a dotted path (`a.b`, `list[0]`) of a TOML value.
fn at<'a>(value: &'a toml::Value, path: &str) -> Option<&'a toml::Value> {
    let mut node = value;
    for key in path.split('.').filter(|k| !k.is_empty()) {
        let (name, index) = match key.split_once('[') {
            Some((n, i)) => (n, i.trim_end_matches(']').parse::<usize>().ok()),
            None => (key, None),
        };
        node = node.get(name)?;
        if let Some(i) = index {
            node = node.get(i)?;
        }
    }
    Some(node)
}

fn join(table: &str, key: &str) -> String {
    match (table, key) {
        ("", k) => k.to_string(),
        (t, "") => t.to_string(),
        (t, k) => format!("{t}.{k}"),
    }
}

fn between<'a>(s: &'a str, start: &str, end: &str) -> Option<&'a str> {
    let rest = s.strip_prefix(start)?;
    Some(&rest[..rest.find(end)?])
}

/// serde's "unknown field `x`, expected one of `a`, `b`" (or "expected `a`", or "there are no
/// fields"): the name and the valid names.
fn unknown<'a>(message: &'a str, what: &str) -> Option<(&'a str, Vec<&'a str>)> {
    let name = between(message, &format!("unknown {what} `"), "`")?;
    let rest = &message[message.find(", ")? + 2..];
    let expected = rest.split('`').skip(1).step_by(2).collect();
    Some((name, expected))
}

/// serde's "invalid type: floating point `360.5`, expected u64": the value as written
/// ("360.5", "\"yes\"", or "sequence" for an array) and what serde expected.
fn wrong_type(message: &str) -> Option<(&str, &str)> {
    let rest = message.strip_prefix("invalid type: ")?;
    let (found, expected) = rest.split_once(", expected ")?;
    let found = match found.find(['`', '"']) {
        Some(i) => found[i..].trim_matches('`'),
        None => found,
    };
    Some((found, expected))
}

/// "unknown field "x": did you mean "y"? (the fields here: ...)"; for a word (a value among
/// some), "unknown word "x": did you mean "y"? (must be "a", "b" or "c")".
pub fn suggest(what: &str, name: &str, expected: &[&str]) -> String {
    let listed = match expected {
        [] => format!("there are no {what}s here"),
        [one] if what != "field" => format!("must be \"{one}\""),
        [rest @ .., last] if what != "field" => {
            let rest: Vec<String> = rest.iter().map(|w| format!("\"{w}\"")).collect();
            format!("must be {} or \"{last}\"", rest.join(", "))
        }
        _ => format!("the {what}s here: {}", expected.join(", ")),
    };
    match nearest(name, expected) {
        Some(near) => format!("unknown {what} \"{name}\": did you mean \"{near}\"? ({listed})"),
        None => format!("unknown {what} \"{name}\" ({listed})"),
    }
}

/// The valid name nearest to `name`, if one is near enough to be a slip: at most a third of
/// its letters (and at least one) edited, or one contains the other.
pub fn nearest<'a>(name: &str, expected: &[&'a str]) -> Option<&'a str> {
    let (best, distance) = expected
        .iter()
        .map(|e| (*e, strsim::damerau_levenshtein(name, e)))
        .min_by_key(|(_, d)| *d)?;
    let close = distance <= (name.chars().count() / 3).max(1);
    let part = name.len() > 3 && (best.contains(name) || name.contains(best));
    (close || part).then_some(best)
}

/// What the field at `path` (dotted, relative to the schema `root`) must be, in words, from its
/// schema: "a number in m or a string with a unit", "a whole number from 8 to 100000000: the
/// number of crank-angle intervals", "a table [motion]". `shown` is the field's full path.
fn what(root: &Value, path: &str, shown: &str) -> Option<String> {
    let mut node = root;
    let mut doc = None;
    for key in path.split('.').filter(|k| !k.is_empty()) {
        let (name, item) = match key.split_once('[') {
            Some((name, _)) => (name, true),
            None => (key, false),
        };
        let property = resolve(root, node).get("properties")?.get(name)?;
        doc = property.get("description").and_then(Value::as_str);
        node = property;
        if item {
            // An element of a list: what the list holds.
            node = resolve(root, node).get("items")?;
        }
    }
    let what = value_kind(root, node, shown)?;
    // The field's own doc, its first sentence, says what it is for.
    Some(match doc.map(first_sentence) {
        Some(d) if !d.is_empty() => format!("{what}: {}", lower_first(&d.replace('\n', " "))),
        _ => what,
    })
}

/// What a value of the schema `node` must be, in words ("a number in m or a string with a
/// unit", "a string in quotes: \"pump\" or \"engine\"", "a table `[shown]`").
pub fn value_kind(root: &Value, node: &Value, shown: &str) -> Option<String> {
    let node = resolve(root, node);
    // An optional of a plain type is `"type": ["string", "null"]`.
    let kind = match node.get("type") {
        Some(Value::String(t)) => Some(t.as_str()),
        Some(Value::Array(types)) => types
            .iter()
            .filter_map(Value::as_str)
            .find(|t| *t != "null"),
        _ => None,
    };
    let words: Vec<String> = match node.get("enum").and_then(Value::as_array) {
        Some(e) => e
            .iter()
            .filter_map(|w| w.as_str().map(|w| format!("\"{w}\"")))
            .collect(),
        None => node
            .get("oneOf")
            .and_then(Value::as_array)
            .into_iter()
            .flatten()
            .filter_map(|b| b.get("const").and_then(Value::as_str))
            .map(|w| format!("\"{w}\""))
            .collect(),
    };
    if let Some(unit) = node.get("x-unit").and_then(Value::as_str) {
        return Some(format!("a number in {unit} or a string with a unit"));
    }
    if let Some((last, rest)) = words.split_last() {
        return Some(match rest {
            [] => format!("a string in quotes: {last}"),
            _ => format!("a string in quotes: {} or {last}", rest.join(", ")),
        });
    }
    Some(match kind? {
        "integer" => match (node.get("minimum"), node.get("maximum")) {
            (Some(lo), Some(hi)) => format!("a whole number from {lo} to {hi}"),
            (Some(lo), None) if lo != 0 => format!("a whole number of at least {lo}"),
            _ => "a whole number".to_string(),
        },
        "number" => "a number".to_string(),
        "boolean" => "true or false (without quotes)".to_string(),
        "string" => "a string in quotes".to_string(),
        "array" => "a list in brackets, even of one: [...]".to_string(),
        "object" => format!("a table [{shown}]"),
        _ => return None,
    })
}

/// `s` with its first letter in lower case, unless the first word is an acronym ("AGMA",
/// "ISO", "KHK"): "Module m" → "module m", "AGMA bending …" stays.
fn lower_first(s: &str) -> String {
    let mut c = s.chars();
    match c.next() {
        Some(f) if c.clone().next().is_some_and(char::is_uppercase) => {
            std::iter::once(f).chain(c).collect()
        }
        Some(f) => f.to_lowercase().chain(c).collect(),
        None => String::new(),
    }
}

/// The first sentence of a doc comment: up to a full stop before a capital or the end.
pub fn first_sentence(doc: &str) -> &str {
    let ends = doc.match_indices(". ").find(|(i, _)| {
        doc[i + 2..].starts_with(|c: char| c.is_uppercase() || c == '`' || c == '(')
    });
    match ends {
        Some((i, _)) => &doc[..i],
        None => doc.trim_end().trim_end_matches('.'),
    }
}

/// A schema with its `$ref` followed and an optional's `null` branch dropped.
pub fn resolve<'a>(root: &'a Value, mut node: &'a Value) -> &'a Value {
    for _ in 0..8 {
        if let Some(r) = node.get("$ref").and_then(Value::as_str) {
            let name = r.rsplit('/').next().unwrap_or_default();
            match root.get("$defs").and_then(|d| d.get(name)) {
                Some(def) => node = def,
                None => return node,
            }
        } else if let Some(branches) = node.get("anyOf").and_then(Value::as_array) {
            let not_null: Vec<&Value> = branches
                .iter()
                .filter(|b| b.get("type").and_then(Value::as_str) != Some("null"))
                .collect();
            match not_null[..] {
                [one] if branches.len() == 2 => node = one,
                _ => return node,
            }
        } else {
            return node;
        }
    }
    node
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde::Deserialize;

    #[derive(Debug, Deserialize, JsonSchema)]
    #[serde(deny_unknown_fields)]
    #[allow(dead_code)]
    struct Inner {
        /// The crank. More words.
        crank_length: f64,
        steps: u64,
        machine: Option<Word>,
    }

    #[derive(Debug, Deserialize, JsonSchema)]
    #[serde(rename_all = "snake_case")]
    enum Word {
        Pump,
        Engine,
    }

    #[derive(Debug, Deserialize, JsonSchema)]
    #[serde(deny_unknown_fields)]
    #[allow(dead_code)]
    struct Outer {
        geometry: Inner,
    }

    fn error(text: &str) -> String {
        let value: toml::Value = toml::from_str(text).unwrap();
        read::<Outer>(value, "").unwrap_err().to_string()
    }

    #[test]
    fn a_misspelled_field_names_its_path_and_the_nearest_name() {
        let e = error("[geometry]\ncrank_lenght = 1.0\nsteps = 8");
        assert!(
            e.starts_with("geometry.crank_lenght: unknown field \"crank_lenght\": did you mean \"crank_length\"?"),
            "{e}"
        );
    }

    #[test]
    fn a_misspelled_word_names_the_nearest_word() {
        let e = error("[geometry]\ncrank_length = 1.0\nsteps = 8\nmachine = \"pmup\"");
        assert!(
            e.starts_with("geometry.machine: unknown word \"pmup\": did you mean \"pump\"?"),
            "{e}"
        );
    }

    /// Issue 39.1: "AGMA bending geometry factor J" was said "aGMA bending …".
    #[test]
    fn an_acronym_keeps_its_capitals() {
        assert_eq!(
            lower_first("AGMA bending geometry factor J"),
            "AGMA bending geometry factor J"
        );
        assert_eq!(lower_first("ISO 21771 signs"), "ISO 21771 signs");
        assert_eq!(lower_first("Module m"), "module m");
        assert_eq!(lower_first(""), "");
    }

    #[test]
    fn a_missing_field_and_a_wrong_type_are_said_in_words() {
        let e = error("[geometry]\nsteps = 8");
        assert_eq!(
            e,
            "geometry.crank_length = (missing): required: a number: the crank"
        );
        let e = error("[geometry]\ncrank_length = 1.0\nsteps = 8.5");
        assert_eq!(e, "geometry.steps = 8.5: must be a whole number");
        let e = error("[geometry]\ncrank_length = 1.0\nsteps = 8\nmachine = 1");
        assert_eq!(
            e,
            "geometry.machine = 1: must be a string in quotes: \"pump\" or \"engine\""
        );
        let e = error("[[geometry]]\ncrank_length = 1.0\nsteps = 8");
        assert!(e.contains("not an array of tables ([[geometry]])"), "{e}");
    }

    /// A word written as a list or table (found by fuzzing: serde said only "wanted exactly 1
    /// element, found 0 elements"): the field and what it must be.
    #[test]
    fn a_word_written_as_a_list_or_table_names_the_field_and_the_rule() {
        for (written, shown) in [
            ("[]", "[]"),
            ("[\"pump\", \"engine\"]", "[\"pump\", \"engine\"]"),
        ] {
            let e = error(&format!(
                "[geometry]\ncrank_length = 1.0\nsteps = 8\nmachine = {written}"
            ));
            assert_eq!(
                e,
                format!("geometry.machine = {shown}: must be a string in quotes: \"pump\" or \"engine\"")
            );
        }
        let e = error("[geometry]\ncrank_length = 1.0\nsteps = 8\nmachine = {}");
        assert!(
            e.starts_with("geometry.machine = {}: must be a string in quotes"),
            "{e}"
        );
    }

    #[test]
    fn a_name_far_from_every_field_gets_no_guess() {
        assert_eq!(nearest("colour", &["crank_length", "steps"]), None);
        assert_eq!(
            nearest("rod_len", &["rod_length", "bore"]),
            Some("rod_length")
        );
    }
}
