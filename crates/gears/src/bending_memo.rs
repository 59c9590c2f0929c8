//! The bending geometry factors `J` computed so far ([`crate::agma908::bending_geometry_factor`],
//! an iterative search of the tooth root for each member), kept by their exact inputs: the
//! points of a sweep over anything but the gear pair (the crank speed, the rod length) have one
//! pair, whose factors are then searched once instead of at every point (issue 37: 4 % of a
//! table point's time). A memo travels with what shares it (a sweep's points); there is no
//! global one.

use crate::agma908::{bending_geometry_factor, BendingJ};
use crate::error::GearError;
use crate::geometry::{Diameters, GearPair, GearSpec, PairSpec, Tip};
use crate::tooth_root::{GeneratedMember, PairMember};
use std::collections::HashMap;
use std::sync::Mutex;

/// At most this many factors are kept (a sweep over the gear's own fields has a pair a point):
/// past it the memo starts again, so that it holds some 100 kB whatever the number of points.
const KEPT: usize = 256;

/// The [`bending_geometry_factor`]s computed so far, by the exact pair and member: every field
/// of both, every float to the bit (`-0.0` is not `0.0`), so that a factor is only taken for
/// the very inputs it was computed from, and is the same bits as computing it again (the
/// search is a function of its inputs alone).
#[derive(Debug, Default)]
pub struct BendingJMemo {
    computed: Mutex<HashMap<Vec<u64>, Result<BendingJ, GearError>>>,
}

impl BendingJMemo {
    /// [`bending_geometry_factor`] of `pair`'s `member`: computed the first time, the kept
    /// result after (an error too: the same inputs fail the same way).
    pub fn get(&self, pair: &GearPair, member: GeneratedMember) -> Result<BendingJ, GearError> {
        let key = key(pair, member);
        // Held while computing: the points of a sweep on other threads wait for the one search
        // instead of each starting its own.
        let mut computed = self.computed.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(kept) = computed.get(&key) {
            return kept.clone();
        }
        if computed.len() >= KEPT {
            computed.clear();
        }
        let j = bending_geometry_factor(pair, member);
        computed.insert(key, j.clone());
        j
    }
}

/// Every input of a factor as bits. The structs are taken apart field by field without `..`,
/// so that a field added to any of them does not compile until it is keyed here too.
fn key(pair: &GearPair, member: GeneratedMember) -> Vec<u64> {
    let GearPair {
        spec,
        internal,
        ratio,
        pinion,
        gear,
        working_pressure_angle,
        working_centre_distance,
        centre_distance,
        operating_pressure_angle,
        base_pitch,
        path_of_contact,
        contact_ratio,
        backlash_circumferential,
        backlash_normal,
    } = pair;
    let GeneratedMember {
        which,
        rack_tip_radius,
    } = member;
    let mut key = Vec::with_capacity(48);
    key.push(u64::from(*internal));
    key.extend(
        [
            ratio,
            working_pressure_angle,
            working_centre_distance,
            centre_distance,
            operating_pressure_angle,
            base_pitch,
            path_of_contact,
            contact_ratio,
            backlash_circumferential,
            backlash_normal,
        ]
        .map(|x| x.to_bits()),
    );
    pair_spec(spec, &mut key);
    diameters(pinion, &mut key);
    diameters(gear, &mut key);
    key.push(match which {
        PairMember::Pinion => 0,
        PairMember::Gear => 1,
    });
    optional(rack_tip_radius, &mut key);
    key
}

/// The bits of `x`, or of its absence.
fn optional(x: Option<f64>, key: &mut Vec<u64>) {
    match x {
        Some(x) => key.extend([1, x.to_bits()]),
        None => key.push(0),
    }
}

fn pair_spec(spec: &PairSpec, key: &mut Vec<u64>) {
    let PairSpec {
        module,
        pressure_angle,
        pinion,
        gear,
        centre_distance,
        min_teeth_difference,
    } = spec;
    key.extend([module.to_bits(), pressure_angle.to_bits()]);
    key.push(u64::from(*min_teeth_difference));
    optional(*centre_distance, key);
    gear_spec(pinion, key);
    gear_spec(gear, key);
}

fn gear_spec(gear: &GearSpec, key: &mut Vec<u64>) {
    let GearSpec {
        teeth,
        shift,
        tip,
        dedendum_coefficient,
        thickness_allowance,
    } = gear;
    // The teeth as their i32 bits, sign-extended: one value each.
    key.push(i64::from(*teeth) as u64);
    key.extend([shift, dedendum_coefficient, thickness_allowance].map(|x| x.to_bits()));
    key.extend(match tip {
        Tip::Coefficient(ha) => [0, ha.to_bits()],
        Tip::Diameter(d) => [1, d.to_bits()],
    });
}

fn diameters(d: &Diameters, key: &mut Vec<u64>) {
    let Diameters {
        reference,
        base,
        tip,
        root,
        working,
    } = d;
    key.extend([reference, base, tip, root, working].map(|x| x.to_bits()));
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pair(spec: PairSpec) -> GearPair {
        GearPair::new(spec).unwrap()
    }

    /// A kept factor is the factor computed again, to the bit, for each member; another pair
    /// (one input changed, by a sign bit alone too) gets its own, not the kept one.
    #[test]
    fn a_kept_factor_is_only_that_of_its_own_inputs() {
        let memo = BendingJMemo::default();
        let ring = pair(PairSpec::standard(
            0.0025,
            20,
            -40,
            20f64.to_radians(),
            0.0,
            0.0,
        ));
        let external = pair(PairSpec::standard(
            0.003,
            18,
            36,
            20f64.to_radians(),
            0.1,
            -0.1,
        ));
        let signed = pair(PairSpec::standard(
            0.0025,
            20,
            -40,
            20f64.to_radians(),
            -0.0,
            0.0,
        ));
        assert_ne!(
            key(&ring, GeneratedMember::new(PairMember::Pinion)),
            key(&signed, GeneratedMember::new(PairMember::Pinion))
        );
        for _ in 0..2 {
            for p in [&ring, &external, &signed] {
                for which in [PairMember::Pinion, PairMember::Gear] {
                    for tip in [None, Some(0.3e-3)] {
                        let member = GeneratedMember {
                            which,
                            rack_tip_radius: tip,
                        };
                        let kept = memo.get(p, member).map(|j| j.j.to_bits());
                        let again = bending_geometry_factor(p, member).map(|j| j.j.to_bits());
                        assert_eq!(kept, again, "{which:?} of {:?}, tip {tip:?}", p.spec);
                    }
                }
            }
        }
        let ring_j = |memo: &BendingJMemo| memo.get(&ring, GeneratedMember::new(PairMember::Gear));
        let other = pair(PairSpec::standard(
            0.0025,
            22,
            -40,
            20f64.to_radians(),
            0.0,
            0.0,
        ));
        assert_ne!(
            ring_j(&memo).unwrap().j,
            memo.get(&other, GeneratedMember::new(PairMember::Gear))
                .unwrap()
                .j
        );
    }

    /// Past [`KEPT`] pairs the memo starts again, and its factors stay right.
    #[test]
    fn the_memo_holds_a_bounded_number_of_factors() {
        let memo = BendingJMemo::default();
        let pinion = GeneratedMember::new(PairMember::Pinion);
        for k in 0..KEPT + 10 {
            let module = 0.001 + k as f64 * 1e-6;
            let p = pair(PairSpec::standard(
                module,
                20,
                40,
                20f64.to_radians(),
                0.0,
                0.0,
            ));
            let again = bending_geometry_factor(&p, pinion).unwrap().j.to_bits();
            assert_eq!(memo.get(&p, pinion).unwrap().j.to_bits(), again);
            assert!(memo.computed.lock().unwrap().len() <= KEPT);
        }
    }
}
