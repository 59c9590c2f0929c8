//! Quantities with units, converted to SI once, at the edge. A case-file value is either a
//! bare number in the field's documented unit or a string "NUMBER UNIT" (`"60 mm"`).

use std::f64::consts::PI;

/// The physical dimension of a case-file field, which fixes the units it accepts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dimension {
    Length,
    /// Angles: a bare number is in degrees, as in the thesis's tables.
    Angle,
    AngularSpeed,
    AngularAcceleration,
    Mass,
    Inertia,
    /// Absolute pressure: a bare number is in Pa.
    Pressure,
    /// Absolute temperature: a bare number is in K; "°C" adds 273.15.
    Temperature,
    /// Energy per unit mass (heating values, specific energy), J/kg.
    SpecificEnergy,
    /// Specific gas constant, J/(kg·K).
    GasConstant,
    /// A change of crank angle per change of crank speed (ignition-timing slopes), s
    /// (rad per rad/s); "deg/rpm" as the correlations print them.
    AnglePerSpeed,
    /// Kinematic viscosity: a bare number is in m²/s; "mm^2/s" and "cSt" are the same unit.
    KinematicViscosity,
    /// Density, kg/m³.
    Density,
    /// Force: a bare number is in N.
    Force,
    /// A pure number (ratios, exponents, factors), or a coefficient in the SI unit its field
    /// names.
    Number,
}

impl Dimension {
    /// (unit, factor to SI) pairs; the first is the unit of a bare number. Temperatures also
    /// have an offset, see [`Dimension::offset`].
    fn units(self) -> &'static [(&'static str, f64)] {
        match self {
            Dimension::Length => &[
                ("m", 1.0),
                ("mm", 1e-3),
                ("cm", 1e-2),
                ("um", 1e-6),
                ("µm", 1e-6),
            ],
            Dimension::Angle => &[("deg", PI / 180.0), ("°", PI / 180.0), ("rad", 1.0)],
            Dimension::AngularSpeed => &[
                ("rad/s", 1.0),
                ("rpm", 2.0 * PI / 60.0),
                ("r/min", 2.0 * PI / 60.0),
            ],
            Dimension::AngularAcceleration => &[
                ("rad/s^2", 1.0),
                ("rad/s²", 1.0),
                ("rpm/s", 2.0 * PI / 60.0),
            ],
            Dimension::Mass => &[("kg", 1.0), ("g", 1e-3)],
            Dimension::Inertia => &[
                ("kg*m^2", 1.0),
                ("kg·m²", 1.0),
                ("kg m^2", 1.0),
                ("g*cm^2", 1e-7),
            ],
            Dimension::Pressure => &[
                ("Pa", 1.0),
                ("kPa", 1e3),
                ("MPa", 1e6),
                ("GPa", 1e9),
                ("bar", 1e5),
                ("atm", 101_325.0),
            ],
            Dimension::Temperature => &[("K", 1.0), ("°C", 1.0), ("degC", 1.0)],
            Dimension::SpecificEnergy => &[("J/kg", 1.0), ("kJ/kg", 1e3), ("MJ/kg", 1e6)],
            Dimension::GasConstant => &[("J/(kg*K)", 1.0), ("J/(kg·K)", 1.0), ("J/kgK", 1.0)],
            Dimension::AnglePerSpeed => &[("s", 1.0), ("deg/rpm", 1.0 / 6.0)],
            Dimension::KinematicViscosity => &[
                ("m^2/s", 1.0),
                ("m²/s", 1.0),
                ("mm^2/s", 1e-6),
                ("mm²/s", 1e-6),
                ("cSt", 1e-6),
            ],
            Dimension::Density => &[("kg/m^3", 1.0), ("kg/m³", 1.0), ("g/cm^3", 1e3)],
            Dimension::Force => &[("N", 1.0), ("kN", 1e3), ("MN", 1e6)],
            Dimension::Number => &[("", 1.0)],
        }
    }

    /// What a unit adds after scaling: 273.15 K for Celsius, 0 otherwise.
    fn offset(unit: &str) -> f64 {
        match unit {
            "°C" | "degC" => 273.15,
            _ => 0.0,
        }
    }

    /// The unit of a bare number.
    pub fn default_unit(self) -> &'static str {
        self.units()[0].0
    }
}

/// Converts a TOML value to SI. Errors say what was expected.
pub fn to_si(value: &toml::Value, dim: Dimension) -> Result<f64, String> {
    let number = match value {
        toml::Value::Float(x) => Some((*x, dim.units()[0].1, 0.0)),
        toml::Value::Integer(i) => Some((*i as f64, dim.units()[0].1, 0.0)),
        toml::Value::String(s) => parse(s, dim)?,
        _ => None,
    };
    let (x, factor, offset) = number.ok_or_else(|| match dim.default_unit() {
        "" => format!("expected a number, got {value}"),
        unit => format!("expected a number in {unit} or a string with a unit, got {value}"),
    })?;
    if !x.is_finite() {
        return Err(format!("must be a finite number, got {value}"));
    }
    Ok(x * factor + offset)
}

/// "12.5 MPa" → (12.5, "MPa"); "0.5" → (0.5, "").
pub fn split_number(s: &str) -> Result<(f64, &str), String> {
    let s = s.trim();
    let split = s
        .find(|c: char| !(c.is_ascii_digit() || "+-.eE".contains(c)))
        .unwrap_or(s.len());
    let (num, unit) = s.split_at(split);
    let x: f64 = num
        .parse()
        .map_err(|_| format!("cannot read a number in \"{s}\""))?;
    Ok((x, unit.trim()))
}

/// Whether `name` can be an output folder: letters, digits, '-', '_' and '.', not empty and
/// not starting with '.' (no hidden or parent folders).
pub fn is_folder_name(name: &str) -> bool {
    !name.is_empty()
        && !name.starts_with('.')
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "-_.".contains(c))
}

fn parse(s: &str, dim: Dimension) -> Result<Option<(f64, f64, f64)>, String> {
    let s = s.trim();
    let (x, unit) = split_number(s)?;
    let unit = if unit.is_empty() {
        dim.default_unit()
    } else {
        unit
    };
    let known = dim.units();
    match known.iter().find(|(u, _)| *u == unit) {
        Some((u, f)) => Ok(Some((x, *f, Dimension::offset(u)))),
        None => Err(format!(
            "unknown unit \"{unit}\" in \"{s}\"; accepted: {}",
            known.iter().map(|(u, _)| *u).collect::<Vec<_>>().join(", ")
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn units_convert_to_si() {
        let v = |s: &str| toml::Value::String(s.into());
        assert_relative_eq!(to_si(&v("60 mm"), Dimension::Length).unwrap(), 0.06);
        assert_relative_eq!(
            to_si(&v("3000 rpm"), Dimension::AngularSpeed).unwrap(),
            100.0 * PI
        );
        assert_relative_eq!(
            to_si(&toml::Value::Float(90.0), Dimension::Angle).unwrap(),
            PI / 2.0
        );
        assert_relative_eq!(to_si(&v("1.5rad"), Dimension::Angle).unwrap(), 1.5);
        assert_relative_eq!(
            to_si(&toml::Value::Integer(2), Dimension::Mass).unwrap(),
            2.0
        );
        assert!(to_si(&v("60 furlongs"), Dimension::Length)
            .unwrap_err()
            .contains("furlongs"));
        assert!(to_si(&toml::Value::Float(f64::NAN), Dimension::Length).is_err());
        assert_relative_eq!(to_si(&v("12 MPa"), Dimension::Pressure).unwrap(), 12e6);
        assert_relative_eq!(to_si(&v("1.5 bar"), Dimension::Pressure).unwrap(), 1.5e5);
        assert_relative_eq!(to_si(&v("20 °C"), Dimension::Temperature).unwrap(), 293.15);
        assert_relative_eq!(
            to_si(&v("44 MJ/kg"), Dimension::SpecificEnergy).unwrap(),
            44e6
        );
        assert_relative_eq!(
            to_si(&toml::Value::Float(1.4), Dimension::Number).unwrap(),
            1.4
        );
        assert!(to_si(&v("1.4 bar"), Dimension::Number).is_err());
        // 1°/rpm = (π/180 rad)/(π/30 rad/s) = 1/6 s.
        assert_relative_eq!(
            to_si(&v("-0.0004 deg/rpm"), Dimension::AnglePerSpeed).unwrap(),
            -0.0004 / 6.0
        );
        assert!(to_si(&toml::Value::Boolean(true), Dimension::Length).is_err());
    }
}
