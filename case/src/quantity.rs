//! The typed schema's quantities: a field of a dimension that reads a bare number in the
//! dimension's documented unit or a string "NUMBER UNIT" (`"60 mm"`), converted to SI once,
//! here (by [`to_si`], which also refuses an implausible bare number with the likely unit).
//! A quantity may carry a sign rule ([`Positive`], [`NonNegative`]); the rule is checked on
//! reading and written into the JSON Schema.
//!
//! A rule a value breaks is a serde error whose message starts with `"= "`: the value as
//! written, then the rule; [`crate::schema::read`] puts the field's path in front of it.

use crate::units::{show, to_si, Dimension};
use schemars::{json_schema, JsonSchema, Schema, SchemaGenerator};
use serde::{de::Error as _, Deserialize, Deserializer};
use std::borrow::Cow;
use std::marker::PhantomData;

/// A physical dimension as a type, so that a field's type names what it measures.
pub trait Dim {
    const DIMENSION: Dimension;
    /// The name used in the JSON Schema's definitions (`Length`).
    const NAME: &'static str;
}

macro_rules! dimensions {
    ($($(#[$doc:meta])* $name:ident),* $(,)?) => {$(
        $(#[$doc])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq)]
        pub struct $name;
        impl Dim for $name {
            const DIMENSION: Dimension = Dimension::$name;
            const NAME: &'static str = stringify!($name);
        }
    )*};
}

dimensions!(
    /// m; mm, cm, µm, in, ft.
    Length,
    /// A bare number in degrees; deg, °, rad.
    Angle,
    /// rad/s; rpm, rev/s, Hz.
    AngularSpeed,
    /// rad/s²; rpm/s.
    AngularAcceleration,
    /// kg; g, lb.
    Mass,
    /// kg·m²; g·cm².
    Inertia,
    /// kg·m (a mass times its radius); g·mm, g·cm.
    MassRadius,
    /// Pa (absolute); kPa, MPa, bar, atm, psi.
    Pressure,
    /// K; °C.
    Temperature,
    /// J/kg.
    SpecificEnergy,
    /// J/(kg·K).
    GasConstant,
    /// s (rad per rad/s); deg/rpm.
    AnglePerSpeed,
    /// m²/s; mm²/s, cSt.
    KinematicViscosity,
    /// kg/m³; g/cm³.
    Density,
    /// N; kN, lbf.
    Force,
    /// W; kW, hp.
    Power,
    /// N·m; kN·m, lbf·in, lbf·ft.
    Torque,
    /// √Pa; √MPa, √psi.
    RootStress,
    /// A pure number, or a coefficient in the SI unit its field names.
    Number,
);

/// No sign rule.
pub const ANY: u8 = 0;
/// Must be greater than zero.
pub const POSITIVE: u8 = 1;
/// Must not be negative.
pub const NON_NEGATIVE: u8 = 2;

/// A value of dimension `D` in SI, read from a case or gear file; `RULE` is its sign rule.
#[derive(Debug, Clone, PartialEq)]
pub struct Quantity<D, const RULE: u8 = ANY> {
    /// The value in SI units.
    pub si: f64,
    /// The value as the file wrote it, for messages (`"60 mm"`, `0.06`).
    pub written: String,
    dimension: PhantomData<D>,
}

/// A quantity that must be greater than zero.
pub type Positive<D> = Quantity<D, POSITIVE>;
/// A quantity that must not be negative.
pub type NonNegative<D> = Quantity<D, NON_NEGATIVE>;

impl<D: Dim, const RULE: u8> Quantity<D, RULE> {
    /// Reads a TOML value: the unit, the plausibility of a bare number, the sign rule.
    /// `Err` is the rule broken.
    pub fn from_value(value: &toml::Value) -> Result<Self, String> {
        let si = to_si(value, D::DIMENSION)?;
        match RULE {
            POSITIVE if si <= 0.0 => return Err("must be positive".into()),
            NON_NEGATIVE if si < 0.0 => return Err("must not be negative".into()),
            _ => {}
        }
        Ok(Self {
            si,
            written: show(&value.to_string()),
            dimension: PhantomData,
        })
    }
}

/// The message of a rule broken by `written`, in the form [`crate::schema::read`] expects.
pub fn broken(written: &dyn std::fmt::Display, rule: &str) -> String {
    format!("= {}: {rule}", show(&written.to_string()))
}

impl<'de, D: Dim, const RULE: u8> Deserialize<'de> for Quantity<D, RULE> {
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        let value = toml::Value::deserialize(deserializer)?;
        Self::from_value(&value).map_err(|rule| De::Error::custom(broken(&value, &rule)))
    }
}

/// Its SI value (the case's input hash serializes the typed case: "60 mm" and 0.06 are one
/// input).
impl<D, const RULE: u8> serde::Serialize for Quantity<D, RULE> {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_f64(self.si)
    }
}

impl<const LOW: i64, const HIGH: i64> serde::Serialize for Whole<LOW, HIGH> {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_i64(self.0)
    }
}

impl<D: Dim, const RULE: u8> JsonSchema for Quantity<D, RULE> {
    fn schema_name() -> Cow<'static, str> {
        match RULE {
            POSITIVE => format!("Positive{}", D::NAME).into(),
            NON_NEGATIVE => format!("NonNegative{}", D::NAME).into(),
            _ => D::NAME.into(),
        }
    }

    fn json_schema(_: &mut SchemaGenerator) -> Schema {
        let dim = D::DIMENSION;
        let units: Vec<&str> = dim.unit_names().collect();
        let number = bare_number(dim, RULE);
        if dim.default_unit().is_empty() {
            return number;
        }
        let plausible = match dim.plausible() {
            Some((low, high, unit, meant)) => format!(
                " (a bare number must lie within {low}...{high} {default}{zero}; write \"60 {unit}\" for {meant})",
                default = dim.default_unit(),
                zero = if RULE == POSITIVE { "" } else { ", or be 0" },
            ),
            None => String::new(),
        };
        let description = format!(
            "A bare number in {}{plausible} or a string \"NUMBER UNIT\"; units: {}",
            dim.default_unit(),
            units.join(", ")
        );
        json_schema!({
            "description": description,
            "x-unit": dim.default_unit(),
            "anyOf": [
                number,
                { "type": "string", "pattern": unit_pattern(&units) }
            ]
        })
    }
}

/// The schema of a bare number of `dim` under the sign rule `rule`: the sign, and the range a
/// bare number must lie in to be read (`Dimension::plausible`: 0, or a magnitude from its low
/// to its high end), so that an editor flags `crank_length = 60` (60 m, meant "60 mm") as the
/// reader refuses it (issue 38.5). A value with a unit is checked on reading only.
fn bare_number(dim: Dimension, rule: u8) -> Schema {
    let Some((low, high, _, _)) = dim.plausible() else {
        return match rule {
            POSITIVE => json_schema!({ "type": "number", "exclusiveMinimum": 0 }),
            NON_NEGATIVE => json_schema!({ "type": "number", "minimum": 0 }),
            _ => json_schema!({ "type": "number" }),
        };
    };
    // The magnitudes from `low` to `high`, of the signs the rule allows; 0 besides, where the
    // rule allows it.
    let range = |from: f64, to: f64, open_from: bool| {
        let min = if open_from {
            "exclusiveMinimum"
        } else {
            "minimum"
        };
        let mut n = json_schema!({ "type": "number", "maximum": to });
        n.insert(min.into(), from.into());
        n
    };
    let positive = range(low, high, low == 0.0);
    let mut branches = match rule {
        POSITIVE => return positive,
        NON_NEGATIVE if low == 0.0 => return range(0.0, high, false),
        NON_NEGATIVE => vec![positive],
        _ if low == 0.0 => return range(-high, high, false),
        _ => vec![positive, range(-high, -low, false)],
    };
    branches.insert(0, json_schema!({ "const": 0 }));
    json_schema!({ "type": "number", "anyOf": branches })
}

/// A range a bare number must lie in, with the rule (the range and its reason) a value outside
/// it breaks. Every range of the case file's bare numbers is one line of the table in
/// [`crate::plausible`].
pub trait Range {
    /// The name in the JSON Schema's definitions.
    const NAME: &'static str;
    const MIN: f64;
    const MAX: f64;
    /// The lower end itself is outside.
    const MIN_OPEN: bool = false;
    /// The upper end itself is outside.
    const MAX_OPEN: bool = false;
    /// Only whole numbers.
    const WHOLE: bool = false;
    /// What a value outside breaks: "must be ..." with the range and its reason or source.
    const RULE: &'static str;
}

/// A number of dimension `D` (SI) in the range `R`: read as a [`Quantity`], then checked
/// against the range; its JSON Schema carries the range's bounds and rule.
#[derive(Debug, Clone, PartialEq)]
pub struct Ranged<R, D = Number> {
    pub si: f64,
    /// As the file wrote it.
    pub written: String,
    range: PhantomData<(R, D)>,
}

impl<R: Range, D: Dim> Ranged<R, D> {
    /// Whether `x` (SI) lies in the range.
    pub fn holds(x: f64) -> bool {
        let above = if R::MIN_OPEN { x > R::MIN } else { x >= R::MIN };
        let below = if R::MAX_OPEN { x < R::MAX } else { x <= R::MAX };
        above && below && (!R::WHOLE || x.fract() == 0.0)
    }

    /// Reads a TOML value: its unit, then the range. `Err` is the rule broken.
    pub fn from_value(value: &toml::Value) -> Result<Self, String> {
        let q = Quantity::<D>::from_value(value)?;
        if !Self::holds(q.si) {
            return Err(R::RULE.to_string());
        }
        Ok(Self {
            si: q.si,
            written: q.written,
            range: PhantomData,
        })
    }
}

impl<'de, R: Range, D: Dim> Deserialize<'de> for Ranged<R, D> {
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        let value = toml::Value::deserialize(deserializer)?;
        Self::from_value(&value).map_err(|rule| De::Error::custom(broken(&value, &rule)))
    }
}

/// Its SI value, as a [`Quantity`]'s (the input digest, `crate::digest`).
impl<R, D> serde::Serialize for Ranged<R, D> {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_f64(self.si)
    }
}

impl<R: Range, D: Dim> JsonSchema for Ranged<R, D> {
    fn schema_name() -> Cow<'static, str> {
        R::NAME.into()
    }

    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        let mut schema = Quantity::<D>::json_schema(generator);
        let bounds = |n: &mut serde_json::Map<String, serde_json::Value>| {
            let min = if R::MIN_OPEN {
                "exclusiveMinimum"
            } else {
                "minimum"
            };
            let max = if R::MAX_OPEN {
                "exclusiveMaximum"
            } else {
                "maximum"
            };
            n.insert(min.into(), R::MIN.into());
            n.insert(max.into(), R::MAX.into());
            if R::WHOLE {
                n.insert("multipleOf".into(), 1.into());
            }
        };
        // A bare number in the range (a string with a unit is checked on reading).
        if let Some(object) = schema.as_object_mut() {
            if object.contains_key("anyOf") {
                if let Some(n) = object["anyOf"].get_mut(0).and_then(|n| n.as_object_mut()) {
                    bounds(n);
                }
            } else {
                bounds(object);
            }
        }
        schema.insert("description".into(), R::RULE.into());
        schema
    }
}

/// A whole number from `LOW` to `HIGH` (a count of steps, digits, points).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Whole<const LOW: i64, const HIGH: i64>(pub i64);

impl<const LOW: i64, const HIGH: i64> Whole<LOW, HIGH> {
    /// The rule in words, for messages.
    pub fn rule() -> String {
        if HIGH == i64::MAX {
            format!("must be a whole number of at least {LOW}")
        } else {
            format!("must be a whole number from {LOW} to {HIGH}")
        }
    }
}

impl<'de, const LOW: i64, const HIGH: i64> Deserialize<'de> for Whole<LOW, HIGH> {
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        let value = toml::Value::deserialize(deserializer)?;
        let whole = match &value {
            toml::Value::Integer(n) => Ok(*n),
            toml::Value::Float(x) if x.fract() == 0.0 && x.abs() < 1e15 => Err(format!(
                "must be a whole number ({x:.0}, not {value}), written without a decimal point"
            )),
            toml::Value::String(s) if s.trim().parse::<i64>().is_ok() => Err(format!(
                "must be a whole number, written without quotes ({}, not {value})",
                s.trim()
            )),
            _ => Err(Self::rule()),
        };
        match whole {
            Ok(n) if (LOW..=HIGH).contains(&n) => Ok(Whole(n)),
            Ok(_) => Err(De::Error::custom(broken(&value, &Self::rule()))),
            Err(rule) => Err(De::Error::custom(broken(&value, &rule))),
        }
    }
}

impl<const LOW: i64, const HIGH: i64> JsonSchema for Whole<LOW, HIGH> {
    fn schema_name() -> Cow<'static, str> {
        format!("Whole{LOW}to{HIGH}").into()
    }

    fn json_schema(_: &mut SchemaGenerator) -> Schema {
        let mut schema = json_schema!({ "type": "integer", "minimum": LOW });
        if HIGH != i64::MAX {
            schema.insert("maximum".into(), HIGH.into());
        }
        schema
    }
}

/// A regular expression for "NUMBER UNIT" with one of `units`.
fn unit_pattern(units: &[&str]) -> String {
    let escaped: Vec<String> = units
        .iter()
        .map(|u| {
            u.chars()
                .map(|c| match c {
                    '*' | '^' | '(' | ')' | '/' | '.' | '+' => format!("\\{c}"),
                    c => c.to_string(),
                })
                .collect()
        })
        .collect();
    format!(
        "^\\s*[-+]?(\\d+\\.?\\d*|\\.\\d+)([eE][-+]?\\d+)?\\s*({})\\s*$",
        escaped.join("|")
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read<T: for<'de> Deserialize<'de>>(text: &str) -> Result<T, String> {
        #[derive(Deserialize)]
        struct One<T> {
            x: T,
        }
        toml::from_str::<One<T>>(&format!("x = {text}"))
            .map(|o| o.x)
            .map_err(|e| e.message().to_string())
    }

    #[test]
    fn a_quantity_reads_a_bare_number_or_a_unit_and_keeps_what_was_written() {
        let q: Quantity<Length> = read("\"60 mm\"").unwrap();
        assert_eq!((q.si, q.written.as_str()), (0.06, "\"60 mm\""));
        let q: Quantity<Length> = read("0.06").unwrap();
        assert_eq!(q.si, 0.06);
    }

    #[test]
    fn a_broken_rule_is_the_value_then_the_rule() {
        let e = read::<Positive<Length>>("0").unwrap_err();
        assert_eq!(e, "= 0: must be positive");
        let e = read::<NonNegative<Mass>>("\"-2 g\"").unwrap_err();
        assert_eq!(e, "= \"-2 g\": must not be negative");
        let e = read::<Quantity<Length>>("60").unwrap_err();
        assert!(e.starts_with("= 60: a bare number is in m"), "{e}");
    }

    #[test]
    fn a_whole_number_says_how_it_was_miswritten() {
        assert_eq!(read::<Whole<8, 100>>("20").unwrap(), Whole(20));
        let e = read::<Whole<8, 100>>("4").unwrap_err();
        assert_eq!(e, "= 4: must be a whole number from 8 to 100");
        let e = read::<Whole<8, 100>>("20.0").unwrap_err();
        assert!(e.contains("(20, not 20.0)"), "{e}");
        let e = read::<Whole<8, 100>>("\"20\"").unwrap_err();
        assert!(e.contains("without quotes"), "{e}");
    }

    #[test]
    fn the_schema_pattern_takes_every_unit_of_the_table() {
        let units: Vec<&str> = Dimension::Torque.unit_names().collect();
        let pattern = unit_pattern(&units);
        for u in &units {
            assert!(pattern.contains(&u.replace('*', "\\*")), "{u}: {pattern}");
        }
    }
}
