//! The design checks of a gear pair ([`GearPair::checks`]): each check's margin, whether it
//! passes and, when it fails, the remedies; the one text of a check's outcome.

use std::fmt;

use super::{GearPair, ROUNDING};
use crate::error::GearError;

/// Which geometry check.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CheckKind {
    /// The mate's tip reaches the pinion flank below its base circle (beyond the interference
    /// point T1). Internal pairs: the KHK criterion `z1/z2 ≥ 1 − tan αa2/tan αw`; margin
    /// `z1/|z2| − 1 + tan αa2/tan α_op`. External pairs: margin `1 + z1/z2 − tan αa2/tan α_op`.
    /// Both are the distance from T1 to the mate-tip contact point divided by `rb2 tan α_op`.
    InvoluteInterferencePinion,
    /// External pairs only: the pinion tip reaches the gear flank below its base circle;
    /// margin `1 + z2/z1 − tan αa1/tan α_op`.
    InvoluteInterferenceGear,
    /// Internal pairs only: tip/trochoid interference while the pinion leaves the mesh
    /// (KHK: `θ1 z1/z2 ≥ θ2`); margin `z1/|z2| − θ2/θ1` (`θ2/θ1` taken as 0 when the tip
    /// circles do not intersect).
    TrochoidInterference,
    /// Internal pairs only: the ring tip circle lies inside the ring base circle, so the ring
    /// tooth has no involute near its tip; margin `(|da2| − |db2|) / (2 m)` \[modules\].
    RingTipInsideBaseCircle,
    /// Internal pairs only: `|z2| − z1 ≥ min_teeth_difference`; margin = the surplus \[teeth\].
    TeethDifference,
    /// `εα ≥ 1`; margin `εα − 1`.
    ContactRatio,
    /// Rack-generated pinion without undercut (ISO 53 rack, straight-flank addendum 1 m):
    /// `x1 ≥ 1 − z1 sin²α / 2`; margin `x1 − (1 − z1 sin²α/2)`.
    PinionUndercut,
    /// Backlash must not be negative; margin `jt / m` \[modules\].
    Backlash,
}

/// What to change when a check fails.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Remedy {
    /// Shorten the ring (internal gear) addendum to at most `max_addendum` \[m\] measured from
    /// its reference circle (e.g. by a tip-diameter change or ISO shift `x2 < 0`).
    ShortenRingAddendum {
        /// Largest admissible ring addendum \[m\].
        max_addendum: f64,
    },
    /// Shorten the mating gear's addendum to at most `max_addendum` \[m\].
    ShortenGearAddendum {
        /// Largest admissible addendum \[m\].
        max_addendum: f64,
    },
    /// Shorten the pinion addendum.
    ShortenPinionAddendum,
    /// Apply a profile shift (positive on the pinion) to move contact away from the base circle.
    ProfileShift,
    /// Give the pinion a shift of at least `min_shift` \[-\].
    PinionShiftAtLeast {
        /// Smallest shift coefficient without undercut.
        min_shift: f64,
    },
    /// Use a larger pressure angle (e.g. 25° instead of 20°).
    LargerPressureAngle,
    /// Increase the ring-minus-pinion tooth count difference to at least `minimum`.
    MoreTeethDifference {
        /// Required difference.
        minimum: u32,
    },
    /// Lengthen the addenda or use a smaller pressure angle to raise the contact ratio.
    LongerAddendaOrSmallerPressureAngle,
    /// Increase the centre distance or thin the teeth.
    IncreaseCentreDistanceOrThinTeeth,
}

impl fmt::Display for Remedy {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Remedy::ShortenRingAddendum { max_addendum } => write!(
                f,
                "shorter ring addendum (at most {:.4} mm from the reference circle)",
                max_addendum * 1e3
            ),
            Remedy::ShortenGearAddendum { max_addendum } => write!(
                f,
                "shorter gear addendum (at most {:.4} mm)",
                max_addendum * 1e3
            ),
            Remedy::ShortenPinionAddendum => write!(f, "shorter pinion addendum"),
            Remedy::ProfileShift => write!(f, "profile shift (positive on the pinion)"),
            Remedy::PinionShiftAtLeast { min_shift } => {
                write!(f, "pinion profile shift x1 >= {min_shift:.4}")
            }
            Remedy::LargerPressureAngle => write!(f, "larger pressure angle"),
            Remedy::MoreTeethDifference { minimum } => {
                write!(f, "ring-minus-pinion teeth difference >= {minimum}")
            }
            Remedy::LongerAddendaOrSmallerPressureAngle => {
                write!(f, "longer addenda or a smaller pressure angle")
            }
            Remedy::IncreaseCentreDistanceOrThinTeeth => {
                write!(f, "larger centre distance or thinner teeth")
            }
        }
    }
}

/// Result of one geometry check.
#[derive(Debug, Clone, PartialEq)]
pub struct CheckReport {
    /// Which check.
    pub kind: CheckKind,
    /// Margin (dimensionless, defined per [`CheckKind`]); ≥ 0 passes.
    pub margin: f64,
    /// `margin >= 0` (to a rounding allowance of 1e-12).
    pub passed: bool,
    /// Remedies, filled only on failure.
    pub remedies: Vec<Remedy>,
}

impl CheckReport {
    /// The margin to 5 decimals, a value that rounds to zero written `0.00000` whatever its sign
    /// (a zero-backlash pair computes `jt ≈ −1e-17 m`, which is no negative margin).
    pub fn margin_text(&self) -> String {
        fixed(self.margin, 5)
    }

    /// "margin M, ok" or "margin M, FAILED; remedy: R1, or R2": the one text of a check's
    /// outcome, for the case files' geometry errors ([`GearPair::verify`]) and the gear file's
    /// report alike.
    pub fn verdict(&self) -> String {
        let mut s = format!("margin {}", self.margin_text());
        if self.passed {
            s.push_str(", ok");
        } else {
            s.push_str(", FAILED");
            if !self.remedies.is_empty() {
                s.push_str("; remedy: ");
                let remedies: Vec<String> = self.remedies.iter().map(|r| r.to_string()).collect();
                s.push_str(&remedies.join(", or "));
            }
        }
        s
    }
}

/// `x` with `decimals` decimals, and `0.000…` (no sign) for a value that rounds to zero.
pub fn fixed(x: f64, decimals: usize) -> String {
    let s = format!("{x:.decimals$}");
    match s.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        _ => s,
    }
}

impl fmt::Display for CheckReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:?}: {}", self.kind, self.verdict())
    }
}

impl GearPair {
    /// Runs every check that applies to this pair type: those of its type (internal or
    /// external), then the contact ratio, the pinion's undercut and the backlash.
    pub fn checks(&self) -> Vec<CheckReport> {
        let m = self.spec.module;
        let z1 = self.spec.pinion.teeth as f64;
        let mut out = if self.internal {
            self.internal_checks()
        } else {
            self.external_checks()
        };
        out.push(report(
            CheckKind::ContactRatio,
            self.contact_ratio - 1.0,
            vec![Remedy::LongerAddendaOrSmallerPressureAngle],
        ));
        let alpha = self.spec.pressure_angle;
        let x_min = 1.0 - z1 * alpha.sin().powi(2) / 2.0;
        out.push(report(
            CheckKind::PinionUndercut,
            self.spec.pinion.shift - x_min,
            vec![
                Remedy::PinionShiftAtLeast { min_shift: x_min },
                Remedy::LargerPressureAngle,
            ],
        ));
        out.push(report(
            CheckKind::Backlash,
            self.backlash_circumferential / m,
            vec![Remedy::IncreaseCentreDistanceOrThinTeeth],
        ));
        out
    }

    /// The checks of an internal pair: the pinion flank's involute interference, tip/trochoid
    /// interference, the ring's tip inside its base circle, the teeth difference.
    fn internal_checks(&self) -> Vec<CheckReport> {
        let m = self.spec.module;
        let z1 = self.spec.pinion.teeth as f64;
        let z2 = self.spec.gear.teeth.unsigned_abs() as f64;
        let t_op = self.operating_pressure_angle.tan();
        let ta2 = self.gear_tip_pressure_angle().tan();
        let max_ha2 = self.max_gear_addendum_without_interference();
        vec![
            report(
                CheckKind::InvoluteInterferencePinion,
                z1 / z2 - 1.0 + ta2 / t_op,
                vec![
                    Remedy::ShortenRingAddendum {
                        max_addendum: max_ha2,
                    },
                    Remedy::ProfileShift,
                    Remedy::LargerPressureAngle,
                ],
            ),
            report(
                CheckKind::TrochoidInterference,
                z1 / z2 - self.trochoid_ratio(),
                vec![
                    Remedy::ShortenRingAddendum {
                        max_addendum: max_ha2.min(self.gear_addendum()),
                    },
                    Remedy::MoreTeethDifference {
                        minimum: self.spec.min_teeth_difference,
                    },
                    Remedy::LargerPressureAngle,
                ],
            ),
            report(
                CheckKind::RingTipInsideBaseCircle,
                (self.gear.tip - self.gear.base) / (2.0 * m),
                vec![
                    Remedy::ShortenRingAddendum {
                        max_addendum: (self.gear.reference - self.gear.base) / 2.0,
                    },
                    Remedy::LargerPressureAngle,
                ],
            ),
            report(
                CheckKind::TeethDifference,
                (z2 - z1) - self.spec.min_teeth_difference as f64,
                vec![Remedy::MoreTeethDifference {
                    minimum: self.spec.min_teeth_difference,
                }],
            ),
        ]
    }

    /// The checks of an external pair: involute interference on either flank.
    fn external_checks(&self) -> Vec<CheckReport> {
        let z1 = self.spec.pinion.teeth as f64;
        let z2 = self.spec.gear.teeth.unsigned_abs() as f64;
        let t_op = self.operating_pressure_angle.tan();
        let ta1 = self.pinion_tip_pressure_angle().tan();
        let ta2 = self.gear_tip_pressure_angle().tan();
        vec![
            report(
                CheckKind::InvoluteInterferencePinion,
                1.0 + z1 / z2 - ta2 / t_op,
                vec![
                    Remedy::ShortenGearAddendum {
                        max_addendum: self.max_gear_addendum_without_interference(),
                    },
                    Remedy::ProfileShift,
                    Remedy::LargerPressureAngle,
                ],
            ),
            report(
                CheckKind::InvoluteInterferenceGear,
                1.0 + z2 / z1 - ta1 / t_op,
                vec![Remedy::ShortenPinionAddendum, Remedy::LargerPressureAngle],
            ),
        ]
    }

    /// Runs [`Self::checks`] and returns an error listing every failure with its remedies.
    pub fn verify(&self) -> Result<(), GearError> {
        let failed: Vec<String> = self
            .checks()
            .iter()
            .filter(|c| !c.passed)
            .map(|c| c.to_string())
            .collect();
        if failed.is_empty() {
            Ok(())
        } else {
            Err(GearError::ChecksFailed(failed.join("\n")))
        }
    }
}

/// A check's report: passed if its `margin` is not below 0 by more than the rounding allowance
/// (a zero-backlash pair computes jt ≈ ±1e-17 m); its `remedies` kept only if it failed.
fn report(kind: CheckKind, margin: f64, remedies: Vec<Remedy>) -> CheckReport {
    let passed = margin >= -ROUNDING;
    CheckReport {
        kind,
        margin,
        passed,
        remedies: if passed { Vec::new() } else { remedies },
    }
}
