//! Reading a TOML table into the typed schema's structs, and saying what went wrong as a
//! person would: the field's dotted path, then what is wrong with it. The structs carry the
//! rules (`deny_unknown_fields`, enums of words, [`crate::quantity`]'s units and signs); this
//! module only turns serde's messages into the project's:
//! - a rule a value breaks: `path = value: rule` ([`crate::quantity::broken`]);
//! - a misspelled field or word: `path: unknown field "x": did you mean "y"? (...)`, the
//!   nearest valid name by edit distance;
//! - a value of the wrong form: `path: must be a whole number, not 360.5` rather than serde's
//!   Rust type names.

use serde::de::DeserializeOwned;

/// Where a field went wrong and what is wrong with it (the file and case are the caller's).
#[derive(Debug, Clone, PartialEq)]
pub struct FieldError {
    /// Dotted path of the field (`geometry.crank_length`, `masses.cardan_gear.rod_mass`).
    pub field: String,
    /// What is wrong: `= value: rule`, or a sentence.
    pub message: String,
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

/// Reads `value` (the table at `prefix`, "" for the whole file) as a `T`.
pub fn read<T: DeserializeOwned>(value: toml::Value, prefix: &str) -> Result<T, FieldError> {
    serde_path_to_error::deserialize(value).map_err(|e| {
        let path = e.path().to_string();
        let mut field = match (prefix, path.as_str()) {
            (p, ".") => p.to_string(),
            ("", p) => p.to_string(),
            (p, q) => format!("{p}.{q}"),
        };
        let message = e.into_inner().message().trim_end().to_string();
        let message = if let Some((name, expected)) = unknown(&message, "field") {
            suggest("field", name, &expected)
        } else if let Some((name, expected)) = unknown(&message, "variant") {
            suggest("word", name, &expected)
        } else if let Some(name) = between(&message, "missing field `", "`") {
            field = join(&field, name);
            "required, and missing".to_string()
        } else {
            plain(&message)
        };
        FieldError { field, message }
    })
}

fn join(table: &str, key: &str) -> String {
    if table.is_empty() || table == "." {
        key.to_string()
    } else {
        format!("{table}.{key}")
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

/// "unknown field "x": did you mean "y"? (the fields here: ...)".
pub fn suggest(what: &str, name: &str, expected: &[&str]) -> String {
    let listed = match expected {
        [] => format!("there are no {what}s here"),
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

/// serde's wrong-type message in words: "invalid type: floating point `360.5`, expected u64"
/// → "must be a whole number, not 360.5".
fn plain(message: &str) -> String {
    let Some(rest) = message.strip_prefix("invalid type: ") else {
        return message.to_string();
    };
    let Some((found, expected)) = rest.split_once(", expected ") else {
        return message.to_string();
    };
    // "floating point `8.5`", "string \"60\"": the value as written.
    let found = match found.find(['`', '"']) {
        Some(i) => found[i..].trim_matches('`'),
        None => found,
    };
    let expected = match expected {
        "i64" | "u64" | "usize" | "u32" | "i32" | "u8" => "a whole number (without quotes)",
        "f64" => "a number",
        "a boolean" => "true or false (without quotes)",
        "a string" => "a string in quotes",
        "a sequence" => "a list in brackets, even of one: [...]",
        e if e.starts_with("struct ") || e == "a map" => "a table",
        e => e,
    };
    format!("must be {expected}, not {found}")
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde::Deserialize;

    #[derive(Debug, Deserialize)]
    #[serde(deny_unknown_fields)]
    #[allow(dead_code)]
    struct Inner {
        crank_length: f64,
        steps: u64,
        machine: Option<Word>,
    }

    #[derive(Debug, Deserialize)]
    #[serde(rename_all = "snake_case")]
    enum Word {
        Pump,
        Engine,
    }

    #[derive(Debug, Deserialize)]
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

    #[test]
    fn a_missing_field_and_a_wrong_type_are_said_in_words() {
        let e = error("[geometry]\nsteps = 8");
        assert_eq!(e, "geometry.crank_length: required, and missing");
        let e = error("[geometry]\ncrank_length = 1.0\nsteps = 8.5");
        assert_eq!(
            e,
            "geometry.steps: must be a whole number (without quotes), not 8.5"
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
