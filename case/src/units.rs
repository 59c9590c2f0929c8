//! Quantities with units, converted to SI once, at the edge. A case-file value is either a
//! bare number in the field's documented unit or a string "NUMBER UNIT" (`"60 mm"`).

use cardan_gears::units::{FOOT, HORSEPOWER, INCH, LBF, PSI};
use std::f64::consts::PI;

/// √psi in √Pa (AGMA's elastic coefficient in US units).
const SQRT_PSI: f64 = 83.034_675_245_757_19;

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
    /// A mass times a radius (an unbalance), kg·m.
    MassRadius,
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
    /// Power: a bare number is in W.
    Power,
    /// Torque: a bare number is in N·m.
    Torque,
    /// Square root of a stress (AGMA's elastic coefficient `Cp`), √Pa.
    RootStress,
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
                ("in", INCH),
                ("ft", FOOT),
                // The Greek mu (U+03BC) of a keyboard, besides the micro sign (U+00B5) above.
                ("μm", 1e-6),
            ],
            Dimension::Angle => &[("deg", PI / 180.0), ("°", PI / 180.0), ("rad", 1.0)],
            Dimension::AngularSpeed => &[
                ("rad/s", 1.0),
                ("rpm", 2.0 * PI / 60.0),
                ("RPM", 2.0 * PI / 60.0),
                ("r/min", 2.0 * PI / 60.0),
                ("rev/min", 2.0 * PI / 60.0),
                ("rev/s", 2.0 * PI),
                ("Hz", 2.0 * PI),
            ],
            Dimension::AngularAcceleration => &[
                ("rad/s^2", 1.0),
                ("rad/s²", 1.0),
                ("rpm/s", 2.0 * PI / 60.0),
            ],
            Dimension::Mass => &[("kg", 1.0), ("g", 1e-3), ("lb", 0.453_592_37)],
            Dimension::Inertia => &[
                ("kg*m^2", 1.0),
                ("kg·m²", 1.0),
                ("kg m^2", 1.0),
                ("g*cm^2", 1e-7),
            ],
            Dimension::MassRadius => &[
                ("kg*m", 1.0),
                ("kg·m", 1.0),
                ("kg m", 1.0),
                ("g*mm", 1e-6),
                ("g*cm", 1e-5),
            ],
            Dimension::Pressure => &[
                ("Pa", 1.0),
                ("kPa", 1e3),
                ("MPa", 1e6),
                ("GPa", 1e9),
                ("bar", 1e5),
                ("atm", 101_325.0),
                ("psi", PSI),
                ("kpsi", 1e3 * PSI),
                ("Mpsi", 1e6 * PSI),
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
            Dimension::Force => &[("N", 1.0), ("kN", 1e3), ("MN", 1e6), ("lbf", LBF)],
            Dimension::Power => &[("W", 1.0), ("kW", 1e3), ("MW", 1e6), ("hp", HORSEPOWER)],
            Dimension::Torque => &[
                ("N*m", 1.0),
                ("N·m", 1.0),
                ("Nm", 1.0),
                ("N m", 1.0),
                ("kN*m", 1e3),
                ("lbf*in", LBF * INCH),
                ("lbf*ft", LBF * FOOT),
            ],
            Dimension::RootStress => &[
                ("sqrt(Pa)", 1.0),
                ("√Pa", 1.0),
                ("sqrt(MPa)", 1e3),
                ("√MPa", 1e3),
                ("sqrt(psi)", SQRT_PSI),
                ("√psi", SQRT_PSI),
            ],
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

    /// Every unit this dimension accepts, the unit of a bare number first.
    pub fn unit_names(self) -> impl Iterator<Item = &'static str> {
        self.units().iter().map(|(unit, _)| *unit)
    }

    /// The unit of a bare number.
    pub fn default_unit(self) -> &'static str {
        self.units()[0].0
    }

    /// The range of a bare number that is plausible in this dimension's default unit, and the
    /// unit a number outside it was likely meant in: a bare 60 for a crank is 60 m, most
    /// likely meant as "60 mm". A value written with a unit is taken as written. `None`: any
    /// bare number is plausible. The bounds are far outside any machine this project models
    /// (the thesis's crank speeds reach 400π rad/s, its lengths 0.3 m).
    pub(crate) fn plausible(self) -> Option<(f64, f64, &'static str, &'static str)> {
        Some(match self {
            Dimension::Length => (0.0, 10.0, "mm", "millimetres"),
            Dimension::AngularSpeed => (0.0, 2000.0, "rpm", "revolutions per minute"),
            Dimension::AngularAcceleration => (0.0, 1e5, "rpm/s", "rpm per second"),
            Dimension::Mass => (0.0, 100.0, "g", "grams"),
            Dimension::Inertia => (0.0, 100.0, "g*cm^2", "g·cm²"),
            Dimension::MassRadius => (0.0, 100.0, "g*mm", "gram-millimetres"),
            Dimension::Pressure => (1000.0, 1e12, "kPa", "kilopascals"),
            Dimension::Temperature => (100.0, 5000.0, "°C", "degrees Celsius"),
            Dimension::KinematicViscosity => (0.0, 1e-2, "cSt", "centistokes (mm²/s)"),
            Dimension::Density => (100.0, 30_000.0, "g/cm^3", "grams per cubic centimetre"),
            Dimension::Force => (0.0, 1e9, "kN", "kilonewtons"),
            _ => return None,
        })
    }
}

/// Converts a TOML value to SI. Errors say what was expected.
pub fn to_si(value: &toml::Value, dim: Dimension) -> Result<f64, String> {
    let bare = match value {
        toml::Value::Float(x) => Some(*x),
        toml::Value::Integer(i) => Some(*i as f64),
        _ => None,
    };
    if let (Some(x), Some((low, high, unit, meant))) = (bare, dim.plausible()) {
        // A pressure of 0 (no load) and any zero are plausible.
        if x.is_finite() && x != 0.0 && !(low..=high).contains(&x.abs()) {
            let (default, x) = (dim.default_unit(), short(x));
            return Err(format!(
                "a bare number is in {default}: {x} {default} is implausible here (a bare number \
                 must lie within {low}...{high} {default}); write \"{x} {unit}\" if you meant \
                 {meant}, or give the unit explicitly (\"{x} {default}\") to keep it"
            ));
        }
    }
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

/// A number as a person writes it: `60`, `0.06`, and `1e300` rather than its 301 digits.
pub fn short(x: f64) -> String {
    let plain = x.to_string();
    if plain.len() > 16 {
        format!("{x:?}")
    } else {
        plain
    }
}

/// A value as the message about it shows it: every number in it longer than 16 characters
/// (a float's 300 digits, in a list or a string with a unit too) through [`short`], the rest as
/// written.
pub fn show(text: &str) -> String {
    let mut out = String::with_capacity(text.len().min(256));
    let mut rest = text;
    while let Some(start) = rest.find(|c: char| c.is_ascii_digit()) {
        // A number's run: its digits, point, exponent and signs.
        let end = rest[start..]
            .find(|c: char| !(c.is_ascii_digit() || ".eE+-".contains(c)))
            .map_or(rest.len(), |n| start + n);
        let run = &rest[start..end];
        out.push_str(&rest[..start]);
        match run.parse::<f64>() {
            Ok(x) if run.len() > 16 => out.push_str(&short(x)),
            _ => out.push_str(run),
        }
        rest = &rest[end..];
    }
    out.push_str(rest);
    out
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

/// Longest case (and sweep point) name: a folder name, with room for the temporary folder's
/// prefix and suffix within the 255 bytes file systems allow.
pub const MAX_NAME: usize = 200;

/// Whether `name` can be an output folder: letters, digits, '-', '_' and '.', not empty, at
/// most [`MAX_NAME`] characters and not starting with '.' (no hidden or parent folders).
pub fn is_folder_name(name: &str) -> bool {
    !name.is_empty()
        && name.len() <= MAX_NAME
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
        assert_relative_eq!(to_si(&v("1.5 in"), Dimension::Length).unwrap(), 0.0381);
        assert_relative_eq!(
            to_si(&v("3000 RPM"), Dimension::AngularSpeed).unwrap(),
            100.0 * PI
        );
        assert_relative_eq!(
            to_si(&v("50 Hz"), Dimension::AngularSpeed).unwrap(),
            100.0 * PI
        );
        assert_relative_eq!(
            to_si(&v("100 psi"), Dimension::Pressure).unwrap(),
            689_475.729_316_8,
            max_relative = 1e-12
        );
    }

    /// Issue 36.15: a number is shown in a message with at most 17 significant digits, alone,
    /// in a list or with a unit; the rest as written.
    #[test]
    fn messages_show_numbers_short() {
        let huge = toml::Value::Float(1e308).to_string();
        assert!(huge.len() > 300, "{huge}");
        assert_eq!(show(&huge), "1e308");
        assert_eq!(show(&format!("[{huge}, {huge}]")), "[1e308, 1e308]");
        assert_eq!(show(&format!("\"{huge} mm\"")), "\"1e308 mm\"");
        assert_eq!(show("-1000000000000000000000000.0"), "-1e24");
        for kept in ["0.06", "\"60 mm\"", "[1, 2]", "12", "abc", "\"3000 rpm\""] {
            assert_eq!(show(kept), kept);
        }
    }

    /// Issue 36.15: "60000 μm" with the Greek mu, as keyboards type it, is the micro sign's.
    #[test]
    fn both_micro_signs_are_micrometres() {
        let v = |s: &str| toml::Value::String(s.into());
        for text in ["60000 \u{03bc}m", "60000 \u{00b5}m", "60000 um"] {
            assert_relative_eq!(to_si(&v(text), Dimension::Length).unwrap(), 0.06);
        }
    }

    /// The gear calculator's quantities take the same table: hp, lbf·in, kpsi, √psi.
    #[test]
    fn gear_units_convert_to_si() {
        let v = |s: &str| toml::Value::String(s.into());
        assert_relative_eq!(SQRT_PSI, PSI.sqrt(), max_relative = 1e-15);
        assert_relative_eq!(
            to_si(&v("4 hp"), Dimension::Power).unwrap(),
            4.0 * HORSEPOWER
        );
        assert_relative_eq!(
            to_si(&v("1 lbf*in"), Dimension::Torque).unwrap(),
            LBF * INCH
        );
        assert_relative_eq!(to_si(&v("2 kpsi"), Dimension::Pressure).unwrap(), 2e3 * PSI);
        assert_relative_eq!(
            to_si(&v("2300 sqrt(psi)"), Dimension::RootStress).unwrap(),
            2300.0 * PSI.sqrt(),
            max_relative = 1e-15
        );
    }

    /// Issue 22's r15: numbers meant in other units (a crank of 60 meant in mm, 3000 meant in
    /// rpm, an ambient pressure of 101.325 meant in kPa, a viscosity of 5 meant in cSt, a
    /// piston of 380 meant in g) are refused with the likely unit; with an explicit unit the
    /// value is taken as written; plausible bare numbers pass.
    #[test]
    fn implausible_bare_numbers_are_refused_with_the_likely_unit() {
        let bare = |x: f64| toml::Value::Float(x);
        for (x, dim, suggestion) in [
            (60.0, Dimension::Length, "\"60 mm\""),
            (3000.0, Dimension::AngularSpeed, "\"3000 rpm\""),
            (101.325, Dimension::Pressure, "\"101.325 kPa\""),
            (5.0, Dimension::KinematicViscosity, "\"5 cSt\""),
            (380.0, Dimension::Mass, "\"380 g\""),
            (20.0, Dimension::Temperature, "\"20 °C\""),
            (1e250, Dimension::AngularAcceleration, "rpm/s"),
        ] {
            let e = to_si(&bare(x), dim).unwrap_err();
            assert!(e.contains(suggestion), "{x}: {e}");
        }
        let v = |s: &str| toml::Value::String(s.into());
        assert_relative_eq!(to_si(&v("60 m"), Dimension::Length).unwrap(), 60.0);
        assert_relative_eq!(
            to_si(&v("3000 rad/s"), Dimension::AngularSpeed).unwrap(),
            3000.0
        );
        for (x, dim) in [
            (0.06, Dimension::Length),
            (628.3, Dimension::AngularSpeed),
            (101_325.0, Dimension::Pressure),
            (0.0, Dimension::Pressure),
            (5e-6, Dimension::KinematicViscosity),
            (0.45, Dimension::Mass),
            (293.15, Dimension::Temperature),
            (7850.0, Dimension::Density),
        ] {
            assert_relative_eq!(to_si(&bare(x), dim).unwrap(), x);
        }
    }
}
