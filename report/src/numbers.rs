//! Metric values as the reports show and compare them: whether higher or lower is better (the
//! metric registry's), the difference to the reference in % ([`Delta`]) with the round-off
//! floor of a signed mean or work, the legends of the tables, and the number formats.

/// Whether a larger or a smaller value of a metric is better (the registry's).
pub(crate) use cardan_metrics::Better;

/// The phrase of a direction in a report's sentences.
pub(crate) fn phrase(direction: Better) -> &'static str {
    match direction {
        Better::Lower => "lower is better",
        Better::Higher => "higher is better",
        Better::Neither => "neither is better",
    }
}

/// The direction of a metric, from its definition in the registry
/// (`cardan_metrics`): none for an unknown metric or one whose direction is neither
/// (kinematics, mean drive power, energy checks).
pub(crate) fn better(metric: &str) -> Option<Better> {
    cardan_metrics::find(metric)
        .map(|d| d.better)
        .filter(|b| *b != Better::Neither)
}

/// `(value − reference) / |reference|` in %, if defined.
pub(crate) fn pct_diff(value: f64, reference: f64) -> Option<f64> {
    let d = (value - reference) / reference.abs() * 100.0;
    (reference != 0.0 && d.is_finite()).then_some(d)
}

/// The round-off floor of a signed mean or work, relative to its scale: the largest the
/// drive could make of it in the run (peak drive torque of its family, × peak crank speed for a
/// power, × peak speed × cycle time, at least the crank angle turned, for a work). Such a
/// metric is a sum over the steps whose terms cancel (a whole-turn inertial work at constant
/// speed is 0 up to a few ulp of its terms), and its round-off grows with the steps to about
/// steps·ε of the scale: 1e-9 is above it up to 1e7 steps, and below any difference a report
/// shows to a tenth of a percent of a result.
pub(crate) const ROUND_OFF: f64 = 1e-9;

/// The value below which `metric` is round-off ([`ROUND_OFF`] of its scale), for the signed
/// means and works, and the energy balance's relative error; None for the others (maxima,
/// ratios: no cancelling sum) or without the scale's metrics. `get` reads a metric of the same mechanism (and sweep point).
pub(crate) fn round_off_floor(metric: &str, get: impl Fn(&str) -> Option<f64>) -> Option<f64> {
    // A relative error (issue 38: no Δ of 4e-17 to 2e-16): [`ROUND_OFF`] itself.
    if metric == "energy_balance_error" {
        return Some(ROUND_OFF);
    }
    let (family, kind) = if metric == "kinetic_energy_change" {
        ("inertial", "_work")
    } else {
        ["_work", "_torque_mean", "_power_mean"]
            .iter()
            .find_map(|k| metric.strip_suffix(k).map(|f| (f, *k)))?
    };
    // The machine's peak torque is signed (`machine_torque_max`, `machine_torque_min`): its
    // scale is the larger magnitude.
    let torque = if family == "machine" {
        get("machine_torque_max")?
            .abs()
            .max(get("machine_torque_min")?.abs())
    } else {
        get(&format!("{family}_torque_max"))?
    };
    let speed = || get("crankshaft_angular_velocity_max");
    let scale = match kind {
        "_torque_mean" => torque,
        "_power_mean" => torque * speed()?,
        _ => torque * speed()? * get("cycle_time")?,
    };
    (scale.is_finite() && scale > 0.0).then_some(ROUND_OFF * scale.abs())
}

/// The difference of a value to the reference's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Delta {
    /// In %, if defined.
    Percent(Option<f64>),
    /// Both within their round-off floor: both 0.
    BothRoundOff,
    /// One within its floor, the other not: no % of a round-off.
    OneRoundOff,
}

/// The [`Delta`] of `value` to `reference`, with their round-off floors.
pub(crate) fn delta(
    value: f64,
    value_floor: Option<f64>,
    reference: f64,
    reference_floor: Option<f64>,
) -> Delta {
    let below = |v: f64, floor: Option<f64>| floor.is_some_and(|f| v.abs() < f);
    match (below(value, value_floor), below(reference, reference_floor)) {
        (true, true) => Delta::BothRoundOff,
        (false, false) => Delta::Percent(pct_diff(value, reference)),
        _ => Delta::OneRoundOff,
    }
}

/// A [`Delta`] as a table shows it: [`fmt_pct`], `≈ 0` where both values are round-off, `—`
/// where one is.
pub(crate) fn fmt_delta(d: Delta) -> String {
    match d {
        Delta::Percent(d) => fmt_pct(d),
        Delta::BothRoundOff => "≈ 0".into(),
        Delta::OneRoundOff => "—".into(),
    }
}

/// The legend of the round-off floor, for the reports' Δ.
pub(crate) const ROUND_OFF_LEGEND: &str =
    "No Δ of a signed mean or work (`*_work`, `*_torque_mean`, \
     `*_power_mean`, `kinetic_energy_change`) within its round-off floor, 1e-9 of what the \
     drive's peak torque of its family makes of it in the run (the torque itself, × the peak \
     crank speed for a power, × peak speed × cycle time for a work): `≈ 0` where both values \
     are within it (both 0 up to round-off, e.g. an inertial work over whole turns at constant \
     speed), `—` where one is; nor of an `energy_balance_error` below 1e-9.";

/// The sign convention of the signed quantities (`cardan_metrics::METRICS`, docs/results.md "Torque
/// sign"), under every table that holds one.
pub(crate) const SIGN_LEGEND: &str = "Signs: a drive torque, its mean, work and power are those \
     of the torque the drive applies to the crankshaft, positive in the direction of rotation: \
     positive when the drive delivers them to the machine (a pump's need), negative when the \
     machine delivers them (an engine's gas work, and its total drive power when the gas drives \
     the crank). `kinetic_energy_change` is end minus start. `torque_need_mean`, \
     `power_need_mean` (pump) and `output_torque_mean`, `output_power_mean` (engine) are \
     positive when the pump needs or the engine delivers. Maxima (`*_max`) are magnitudes, but \
     for `machine_torque_max` and `machine_torque_min`, the signed extremes of the machine's \
     drive torque.";

/// Whether a metric is signed (a table holding one gets [`SIGN_LEGEND`]).
pub(crate) fn signed(metric: &str) -> bool {
    metric == "kinetic_energy_change"
        || metric == "machine_torque_max"
        || metric == "machine_torque_min"
        || metric.ends_with("_need_mean")
        || metric.starts_with("output_")
        || ["_work", "_torque_mean", "_power_mean"]
            .iter()
            .any(|k| metric.ends_with(k))
}

/// A percentage with its sign and one decimal, e.g. `-17.2 %`; `—` if undefined.
pub(crate) fn fmt_pct(d: Option<f64>) -> String {
    match d {
        Some(d) => {
            let s = format!("{d:+.1} %");
            if s == "-0.0 %" {
                "+0.0 %".into()
            } else {
                s
            }
        }
        None => "—".into(),
    }
}

/// A value with 5 significant digits (trailing zeros dropped), scientific outside
/// [1e-3, 1e6); `—` for a missing value.
/// A value of the SI `unit` in the unit engineers think in (issue 38), written after the SI
/// value: rad/s in rpm (× 60/2π), Pa in bar (10⁵ Pa, ISO 80000-4), N in kN, W in kW; `None`
/// for other units, a value not finite, or one too small for the unit to help (below 0.1 rad/s,
/// 1000 Pa, N or W: a round-off remainder stays in SI alone).
pub(crate) fn engineering(v: f64, unit: &str) -> Option<String> {
    let (factor, name, from) = match unit {
        "rad/s" => (60.0 / (2.0 * std::f64::consts::PI), "rpm", 0.1),
        "Pa" => (1e-5, "bar", 1e3),
        "N" => (1e-3, "kN", 1e3),
        "W" => (1e-3, "kW", 1e3),
        _ => return None,
    };
    (v.is_finite() && v.abs() >= from).then(|| format!("{} {name}", fmt_num(v * factor)))
}

pub(crate) fn fmt_num(v: f64) -> String {
    if !v.is_finite() {
        return "—".into();
    }
    if v == 0.0 {
        return "0".into();
    }
    let a = v.abs();
    if !(1e-3..1e6).contains(&a) {
        let s = format!("{v:.4e}");
        // 1.2000e5 → 1.2e5
        return match s.split_once('e') {
            Some((m, e)) if m.contains('.') => {
                format!("{}e{e}", m.trim_end_matches('0').trim_end_matches('.'))
            }
            _ => s,
        };
    }
    let decimals = (4 - a.log10().floor() as i32).clamp(0, 8) as usize;
    let s = format!("{v:.decimals$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_and_percentages_are_printed_fixed() {
        assert_eq!(fmt_num(563.236980502139), "563.24");
        assert_eq!(fmt_num(80326.51054262005), "80327");
        assert_eq!(fmt_num(0.12), "0.12");
        assert_eq!(fmt_num(3611624.18), "3.6116e6");
        assert_eq!(fmt_num(-2.5e-5), "-2.5e-5");
        assert_eq!(fmt_num(f64::NAN), "—");
        assert_eq!(fmt_pct(pct_diff(563.24, 679.87)), "-17.2 %");
        assert_eq!(fmt_pct(pct_diff(1.0, 0.0)), "—");
        assert_eq!(fmt_pct(pct_diff(0.9999999, 1.0)), "+0.0 %");
        assert_eq!(better("total_crank_pin_force_max"), Some(Better::Lower));
        assert_eq!(better("mechanical_efficiency"), Some(Better::Higher));
        assert_eq!(better("total_power_mean"), None);
    }
}
