//! `[output] metrics`: the summary metrics a sweep's table holds (the metric columns of a
//! table sweep's `columns/*.npy`, of a folder sweep's `sweep.csv`), each of every mechanism;
//! checked against the metric registry (`cardan_dynamics::metrics`) and against what the case
//! computes (a gear-rating metric needs `[gear]`, a loss `[friction]`, ...).

use crate::error::{CaseError, Invalid};
use cardan_dynamics::mesh::GearStandard;
use cardan_dynamics::metrics::{self, MetricDef};
use cardan_dynamics::GearSpec;
use std::sync::Arc;

/// What a case computes besides the metrics every run has.
pub(crate) struct Computed {
    pub gas: bool,
    pub friction: bool,
    /// With `[gear]`, the standard that rates its stresses.
    pub gear: Option<GearStandard>,
    pub dynamic: bool,
    /// Whether the machine's shaking is taken step by step (`[layout]` or `[balance]`).
    pub shaking: bool,
}

impl Computed {
    /// What a case with these tables (`[gas]`, `[friction]`, `[gear]`, a solved motion, the
    /// shaking step by step) computes.
    pub fn of<G, F, D>(
        gas: &Option<G>,
        friction: &Option<F>,
        gear: &Option<GearSpec>,
        dynamics: &Option<D>,
        shaking: bool,
    ) -> Self {
        Self {
            gas: gas.is_some(),
            friction: friction.is_some(),
            gear: gear.as_ref().map(|g| g.standard),
            dynamic: dynamics.is_some(),
            shaking,
        }
    }
}

/// The table of the registry a metric needs, and the case-file table that makes it computed.
pub(crate) fn needs(def: &MetricDef, computed: &Computed) -> Option<&'static str> {
    let within = |part: &[MetricDef]| part.contains(def);
    let standard = computed.gear;
    if within(metrics::GEAR_RATING) && standard.is_none() {
        Some("a gear-rating metric: needs a [gear] table")
    } else if within(metrics::GEAR_RATING_ISO) && !standard.is_some_and(|s| s.iso()) {
        Some("an ISO 6336 gear-rating metric: needs [gear] standard = \"iso6336\" or \"both\"")
    } else if metrics::GEAR_RATING_AGMA.contains(&def.name) && !standard.is_some_and(|s| s.agma()) {
        Some("an AGMA 2001 gear-rating metric: needs [gear] standard = \"agma2001\" (the default) or \"both\"")
    } else if (within(metrics::LOSSES) || within(metrics::ENGINE_FRICTION)) && !computed.friction {
        Some("a loss metric: needs a [friction] table")
    } else if (within(metrics::GAS) || within(metrics::GAS_MODEL)) && !computed.gas {
        Some("a gas metric: needs a [gas] table")
    } else if within(metrics::MACHINE_MOTION) && !computed.dynamic {
        Some("a metric of the solved motion: needs [motion] mode = \"dynamic\"")
    } else if metrics::SHAKING_PEAKS.contains(&def.name) && !computed.shaking {
        Some("a peak of the machine's shaking over the run: needs a [layout] or [balance] table (an empty [balance] will do; the shaking's orders need neither)")
    } else {
        None
    }
}

/// The metrics `listed` in `[output] metrics` (None: every metric), each a name of the registry
/// (a fixed name, or a template's with its `{joint}`, `{body}`, ... filled in) that the case
/// computes; refused naming the field, the value and the nearest valid name.
pub(crate) fn build(
    listed: Option<&[String]>,
    computed: &Computed,
    invalid: &Invalid,
) -> Result<Option<Arc<[String]>>, CaseError> {
    let Some(listed) = listed else {
        return Ok(None);
    };
    const FIELD: &str = "output.metrics";
    if listed.is_empty() {
        return Err(invalid(
            FIELD,
            &"[]",
            "must name at least one summary metric (leave it out for every metric)",
        ));
    }
    let names: Vec<&str> = metrics::METRICS.iter().map(|d| d.name).collect();
    for (i, name) in listed.iter().enumerate() {
        let value = format!("\"{name}\"");
        let Some(def) = metrics::find(name) else {
            let rule = match crate::schema::nearest(name, &names) {
                Some(near) => format!(
                    "unknown metric: did you mean \"{near}\"? (the metrics: docs/results.md)"
                ),
                None => "unknown metric (the metrics: docs/results.md)".to_string(),
            };
            return Err(invalid(FIELD, &value, &rule));
        };
        if let Some(why) = needs(def, computed) {
            return Err(invalid(
                FIELD,
                &value,
                &format!("{why}: this case does not compute it"),
            ));
        }
        if listed[..i].contains(name) {
            return Err(invalid(FIELD, &value, "is listed twice"));
        }
    }
    Ok(Some(listed.iter().cloned().collect()))
}

#[cfg(test)]
mod tests {
    use super::{build, Computed, GearStandard};
    use crate::error::CaseError;

    fn check(listed: &[&str], computed: &Computed) -> Result<usize, String> {
        let invalid = |field: &str, value: &dyn std::fmt::Display, rule: &str| CaseError::Invalid {
            file: "c.toml".into(),
            case: "c".into(),
            field: field.into(),
            value: value.to_string(),
            rule: rule.into(),
        };
        let listed: Vec<String> = listed.iter().map(|s| s.to_string()).collect();
        build(Some(&listed), computed, &invalid)
            .map(|m| m.map_or(0, |m| m.len()))
            .map_err(|e| e.to_string())
    }

    #[test]
    fn metrics_are_the_registrys_and_computed_by_the_case() {
        let all = Computed {
            gas: true,
            friction: true,
            gear: Some(GearStandard::Agma2001),
            dynamic: false,
            shaking: true,
        };
        let ok = [
            "mechanical_efficiency",
            "power_loss_mean",
            "total_crank_pin_force_max",
        ];
        assert_eq!(check(&ok, &all), Ok(3));
        let e = check(&["mechanical_efficency"], &all).unwrap_err();
        assert!(
            e.contains("output.metrics = \"mechanical_efficency\"")
                && e.contains("did you mean \"mechanical_efficiency\""),
            "{e}"
        );
        let e = check(&["power_loss_men"], &all).unwrap_err();
        assert!(e.contains("did you mean \"power_loss_mean\""), "{e}");
        let bare = Computed {
            gas: false,
            friction: false,
            gear: None,
            dynamic: false,
            shaking: false,
        };
        let e = check(&["mechanical_efficiency"], &bare).unwrap_err();
        assert!(e.contains("[friction]"), "{e}");
        // The shaking's peaks need it taken step by step; its orders do not.
        let e = check(&["shaking_force_max"], &bare).unwrap_err();
        assert!(e.contains("[layout] or [balance]"), "{e}");
        assert_eq!(check(&["shaking_moment_max"], &all), Ok(1));
        assert_eq!(check(&["shaking_force_order_2"], &bare), Ok(1));
        // Each standard's gear metrics need that standard.
        let e = check(&["iso_contact_safety_factor"], &all).unwrap_err();
        assert!(e.contains("standard = \"iso6336\" or \"both\""), "{e}");
        let iso = Computed {
            gear: Some(GearStandard::Iso6336),
            ..all
        };
        assert_eq!(
            check(&["iso_contact_safety_factor", "contact_ratio"], &iso),
            Ok(2)
        );
        let e = check(&["contact_safety_factor"], &iso).unwrap_err();
        assert!(e.contains("AGMA 2001"), "{e}");
        let both = Computed {
            gear: Some(GearStandard::Both),
            ..all
        };
        assert_eq!(
            check(
                &["iso_bending_safety_factor", "bending_safety_factor"],
                &both
            ),
            Ok(2)
        );
        assert!(check(&["speed_mean"], &all)
            .unwrap_err()
            .contains("dynamic"));
        assert!(check(&["power_loss_mean", "power_loss_mean"], &all)
            .unwrap_err()
            .contains("twice"));
        assert!(check(&[], &all).unwrap_err().contains("at least one"));
    }
}
