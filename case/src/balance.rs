//! `[layout]` and `[balance]` (issue 24): the machine's cylinders on one crankshaft and the
//! devices that balance it, read into [`cardan_balance::MachineBalance`].
//!
//! A layout's cylinders each run the case's mechanism at their throw and axis (a radial
//! engine's rods all on the one crank pin: no master and articulated rods), with the gas of
//! cylinder 1 delayed by their place in the firing order. Defaults: one cylinder; an inline
//! machine's usual even-firing crankshaft from its firing order
//! ([`cardan_balance::throws_from_firing_order`]).

use crate::error::{CaseError, Invalid};
use crate::quantity::{Angle, Length, NonNegative, Quantity, Whole};
use cardan_balance::{throws_from_firing_order, Cylinder, Layout, MachineBalance};
use schemars::JsonSchema;
use serde::Deserialize;
use std::f64::consts::{PI, TAU};

/// `[balance]`: the balancing devices of every cylinder (what each cancels follows from the
/// mechanism's masses, `cardan-balance`).
#[derive(Debug, Default, Deserialize, JsonSchema, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct BalanceTable {
    /// A counterweight on the crank of every cylinder balancing all its rotating mass and
    /// this fraction of its reciprocating mass (0 to 1; 1 = all of the first order along the
    /// cylinder); left out: no counterweight (today's balanced crankshaft, the rod's rotating
    /// part unbalanced). It loads the main bearing with its m·ω², turning with the crank.
    pub counterweight: Option<Quantity<crate::quantity::Number>>,
    /// "none" (default) or "lanchester": two shafts at twice the crank speed cancelling the
    /// machine's second-order shaking force.
    #[serde(default)]
    pub balance_shafts: BalanceShafts,
    /// The counterweight pair on the crank and the cardan wheel of every cylinder that cancels
    /// the mechanism's first-order shaking force; default false. It applies to the mechanisms
    /// with a body turning against the crank (the cardan wheel); the others ignore it, with a
    /// warning in the summary (a case of none of them is refused).
    #[serde(default)]
    pub cardan_counterweights: bool,
}

/// Balance shafts.
#[derive(Debug, Default, Clone, Copy, PartialEq, Eq, Deserialize, JsonSchema, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum BalanceShafts {
    #[default]
    None,
    Lanchester,
}

/// A layout's kind.
#[derive(Debug, Default, Clone, Copy, PartialEq, Eq, Deserialize, JsonSchema, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LayoutKind {
    /// Cylinders in a row, one throw each.
    #[default]
    Inline,
    /// Two banks `bank_angle` apart, a pair of cylinders (one per bank) on each crank pin, the
    /// pair in one plane (no axial offset: docs/validation/balance.md; an offset pair is a
    /// "custom" layout); cylinders 1, 3, 5, ... on the first bank.
    Vee,
    /// Opposed cylinders (axes 180° apart, cylinders 1, 3, ... on the first side), each on its
    /// own throw, each opposed pair at its top dead centres together, the pairs' throws evenly
    /// apart.
    Boxer,
    /// Cylinders equally spaced round the crank axis in one plane, every rod on the one crank
    /// pin.
    Radial,
    /// Each cylinder's axis and axial position given.
    Custom,
}

impl LayoutKind {
    /// Its word in case files.
    pub fn name(self) -> &'static str {
        match self {
            LayoutKind::Inline => "inline",
            LayoutKind::Vee => "vee",
            LayoutKind::Boxer => "boxer",
            LayoutKind::Radial => "radial",
            LayoutKind::Custom => "custom",
        }
    }
}

/// The engine's cycle, for the firing intervals.
#[derive(Debug, Default, Clone, Copy, PartialEq, Eq, Deserialize, JsonSchema, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Cycle {
    /// Cylinders fire 720°/N apart.
    #[default]
    FourStroke,
    /// Cylinders fire 360°/N apart.
    TwoStroke,
}

/// `[layout]`: the machine's cylinders (default: one cylinder).
#[derive(Debug, Deserialize, JsonSchema, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct LayoutTable {
    /// "inline" (default), "vee", "boxer", "radial" or "custom".
    #[serde(default)]
    pub kind: LayoutKind,
    /// Number of cylinders, 1 to 24.
    pub cylinders: Whole<1, 24>,
    /// Each cylinder's crank throw ahead of cylinder 1's (degrees or with a unit), cylinder 1
    /// first; default: the layout's usual even-firing crankshaft of the `cycle` (an inline
    /// four-stroke's throws 720°/N apart in the firing order, a two-stroke's 360°/N: 0° and
    /// 180° for a two-stroke twin).
    pub crank_angles: Option<Vec<Quantity<Angle>>>,
    /// The cylinders in firing order, a permutation of 1..N; default: the usual order of an
    /// inline machine (1-3-4-2, 1-5-3-6-2-4, ...), else the even firing the throws allow.
    pub firing_order: Option<Vec<Whole<1, 24>>>,
    /// "four_stroke" (default: cylinders fire 720°/N apart) or "two_stroke" (360°/N).
    #[serde(default)]
    pub cycle: Cycle,
    /// Axial pitch of the cylinders (of the crank pins of a vee), m; default 0.1 m.
    pub cylinder_spacing: Option<NonNegative<Length>>,
    /// Angle between the banks of a vee, in (0°, 180°]; vee only, default 90°.
    pub bank_angle: Option<Quantity<Angle>>,
    /// Each cylinder's axis angle from cylinder 1's, counter-clockwise (the crank's
    /// direction); custom only, default all 0.
    pub cylinder_axes: Option<Vec<Quantity<Angle>>>,
    /// Each cylinder's position along the crank axis, m; custom only, default one
    /// `cylinder_spacing` apart.
    pub axial_positions: Option<Vec<Quantity<Length>>>,
}

impl Cycle {
    /// The crank angle of one cycle, rad: every cylinder fires once in it.
    fn angle(self) -> f64 {
        match self {
            Cycle::FourStroke => 2.0 * TAU,
            Cycle::TwoStroke => TAU,
        }
    }
}

/// The even-firing crank of an inline machine of `count` cylinders whose cycle is
/// `cycle_angle` (rad): the usual firing order, one firing interval of `count` cylinders
/// (720°/count four-stroke, 360°/count two-stroke) between throws fired one after the other.
fn inline_throws(count: usize, cycle_angle: f64) -> Vec<f64> {
    throws_from_firing_order(&inline_firing_order(count), cycle_angle / count as f64)
}

/// The usual firing order of an inline machine of `n` cylinders (of a four-stroke; a two-stroke
/// is given the same order, its throws 360°/n apart instead of 720°/n).
fn inline_firing_order(n: usize) -> Vec<usize> {
    match n {
        3 => vec![1, 3, 2],
        4 => vec![1, 3, 4, 2],
        5 => vec![1, 2, 4, 5, 3],
        6 => vec![1, 5, 3, 6, 2, 4],
        8 => vec![1, 6, 2, 5, 8, 3, 7, 4],
        _ => (1..=n).collect(),
    }
}

/// The machine of a case: its layout, firing delays and devices.
pub(crate) fn build(
    layout: Option<&LayoutTable>,
    balance: Option<&BalanceTable>,
    invalid: &Invalid,
) -> Result<MachineBalance, CaseError> {
    let mut machine = match layout {
        Some(t) => build_layout(t, invalid)?,
        None => MachineBalance::default(),
    };
    machine.shaking_per_step = layout.is_some() || balance.is_some();
    if let Some(b) = balance {
        if let Some(c) = &b.counterweight {
            if !(0.0..=1.0).contains(&c.si) {
                return Err(invalid(
                    "balance.counterweight",
                    &c.written,
                    "must be a fraction from 0 to 1 of the reciprocating mass",
                ));
            }
            machine.counterweight = Some(c.si);
        }
        machine.lanchester = b.balance_shafts == BalanceShafts::Lanchester;
        machine.cardan_counterweights = b.cardan_counterweights;
        if machine.counterweight.is_some() && machine.cardan_counterweights {
            return Err(invalid(
                "balance.counterweight",
                &b.counterweight.as_ref().map_or("", |c| &c.written),
                "cannot be combined with cardan_counterweights = true: the pair already cancels the whole first order",
            ));
        }
    }
    Ok(machine)
}

/// A list of per-cylinder angles (rad), checked for one value per cylinder.
fn per_cylinder<T>(
    field: &str,
    values: &Option<Vec<T>>,
    n: usize,
    si: impl Fn(&T) -> f64,
    invalid: &Invalid,
) -> Result<Option<Vec<f64>>, CaseError> {
    let Some(v) = values else { return Ok(None) };
    if v.len() != n {
        return Err(invalid(
            &format!("layout.{field}"),
            &format!("{} values", v.len()),
            &format!("must have one value per cylinder (cylinders = {n})"),
        ));
    }
    Ok(Some(v.iter().map(si).collect()))
}

/// A field given to a layout kind that has no use for it.
fn refuse_without(
    given: bool,
    field: &str,
    kind: &str,
    invalid: &Invalid,
) -> Result<(), CaseError> {
    if given {
        return Err(invalid(
            &format!("layout.{field}"),
            &"(given)",
            &format!("applies to kind = \"{kind}\" only"),
        ));
    }
    Ok(())
}

/// The layout table's fields checked against its kind before any is used: fields the kind has
/// no use for, and the cylinder count the kind needs.
fn check_layout_kind(t: &LayoutTable, n: usize, invalid: &Invalid) -> Result<(), CaseError> {
    let kind = t.kind;
    refuse_without(
        t.bank_angle.is_some() && kind != LayoutKind::Vee,
        "bank_angle",
        "vee",
        invalid,
    )?;
    refuse_without(
        t.cylinder_axes.is_some() && kind != LayoutKind::Custom,
        "cylinder_axes",
        "custom",
        invalid,
    )?;
    refuse_without(
        t.axial_positions.is_some() && kind != LayoutKind::Custom,
        "axial_positions",
        "custom",
        invalid,
    )?;
    if kind == LayoutKind::Radial && t.cylinder_spacing.is_some() {
        return Err(invalid(
            "layout.cylinder_spacing",
            &t.cylinder_spacing.as_ref().map_or("", |s| &s.written),
            "a radial engine's cylinders lie in one plane: it has no cylinder spacing",
        ));
    }
    let even = matches!(kind, LayoutKind::Vee | LayoutKind::Boxer);
    if even && n % 2 != 0 {
        return Err(invalid(
            "layout.cylinders",
            &n,
            "a vee or boxer has an even number of cylinders",
        ));
    }
    if kind == LayoutKind::Radial && n < 3 {
        return Err(invalid(
            "layout.cylinders",
            &n,
            "a radial engine has at least 3 cylinders",
        ));
    }
    Ok(())
}

/// The firing order given, if any (cylinder numbers from 1), once it names each of the `n`
/// cylinders exactly once.
fn firing_order(
    t: &LayoutTable,
    n: usize,
    invalid: &Invalid,
) -> Result<Option<Vec<usize>>, CaseError> {
    let Some(order) = &t.firing_order else {
        return Ok(None);
    };
    let order: Vec<usize> = order.iter().map(|w| w.0 as usize).collect();
    let mut sorted = order.clone();
    sorted.sort_unstable();
    if sorted != (1..=n).collect::<Vec<_>>() {
        return Err(invalid(
            "layout.firing_order",
            &format!("{order:?}"),
            &format!("must name every cylinder 1..={n} once (a permutation)"),
        ));
    }
    Ok(Some(order))
}

/// An inline engine's cylinders (default throw, axis angle, axial position): the throws from
/// the firing order if given, else the inline order's, `spacing` (m) apart on one axis.
fn inline_cylinders(
    firing: Option<&[usize]>,
    n: usize,
    (cycle_angle, interval): (f64, f64),
    spacing: f64,
) -> Vec<(f64, f64, f64)> {
    let default = match firing {
        Some(order) => throws_from_firing_order(order, interval),
        None => inline_throws(n, cycle_angle),
    };
    (0..n)
        .map(|i| (default[i], 0.0, i as f64 * spacing))
        .collect()
}

/// A vee's cylinders (default throw, axis angle, axial position): each pair on one pin of an
/// inline crank of n/2 throws, the banks `bank` (rad) apart, the pins `spacing` (m) apart.
fn vee_cylinders(n: usize, cycle_angle: f64, bank: f64, spacing: f64) -> Vec<(f64, f64, f64)> {
    let pins = inline_throws(n / 2, cycle_angle);
    (0..n)
        .map(|i| {
            let side = if i % 2 == 0 { -0.5 } else { 0.5 };
            (pins[i / 2], side * bank, (i / 2) as f64 * spacing)
        })
        .collect()
}

/// A boxer's cylinders (default throw, axis angle, axial position), `spacing` (m) apart.
fn boxer_cylinders(n: usize, spacing: f64) -> Vec<(f64, f64, f64)> {
    // Opposed pairs on throws 180° apart: both pistons at their top dead centres
    // together; the pairs' throws evenly apart (360°/pairs, in the inline order of as
    // many cylinders, whatever the cycle): the flat four's 0°, 180°, 180°, 0°, free of
    // first-order couples, its second-order couple left (docs/validation/balance.md).
    // A two-stroke boxer fires each opposed pair together, the pairs 360°/pairs apart.
    let m = n / 2;
    let pairs = throws_from_firing_order(&inline_firing_order(m), TAU / m as f64);
    (0..n)
        .map(|i| {
            let side = if i % 2 == 0 { 0.0 } else { PI };
            (pairs[i / 2] + side, side, i as f64 * spacing)
        })
        .collect()
}

/// A machine's cylinders and firing delays from its `[layout]` table, each field checked.
fn build_layout(t: &LayoutTable, invalid: &Invalid) -> Result<MachineBalance, CaseError> {
    let n = t.cylinders.0 as usize;
    let kind = t.kind;
    check_layout_kind(t, n, invalid)?;
    let firing = firing_order(t, n, invalid)?;
    let cycle_angle = t.cycle.angle();
    let interval = cycle_angle / n as f64;
    let spacing = t.cylinder_spacing.as_ref().map_or(0.1, |s| s.si);
    let throws = per_cylinder("crank_angles", &t.crank_angles, n, |q| q.si, invalid)?;
    let axes = per_cylinder("cylinder_axes", &t.cylinder_axes, n, |q| q.si, invalid)?;
    let positions = per_cylinder("axial_positions", &t.axial_positions, n, |q| q.si, invalid)?;
    let bank = match &t.bank_angle {
        Some(b) if !(b.si > 0.0 && b.si <= PI + 1e-12) => {
            return Err(invalid(
                "layout.bank_angle",
                &b.written,
                "must be in (0°, 180°]",
            ))
        }
        Some(b) => b.si,
        None => PI / 2.0,
    };
    // Each cylinder: (default throw, axis angle, axial position).
    let cylinders: Vec<(f64, f64, f64)> = match kind {
        LayoutKind::Inline => {
            inline_cylinders(firing.as_deref(), n, (cycle_angle, interval), spacing)
        }
        LayoutKind::Vee => vee_cylinders(n, cycle_angle, bank, spacing),
        LayoutKind::Boxer => boxer_cylinders(n, spacing),
        LayoutKind::Radial => (0..n)
            .map(|i| (0.0, TAU * i as f64 / n as f64, 0.0))
            .collect(),
        LayoutKind::Custom => (0..n)
            .map(|i| {
                let axis = axes.as_ref().map_or(0.0, |a| a[i]);
                let z = positions.as_ref().map_or(i as f64 * spacing, |p| p[i]);
                (0.0, axis, z)
            })
            .collect(),
    };
    let layout = Layout {
        cylinders: cylinders
            .iter()
            .enumerate()
            .map(|(i, &(throw, axis_angle, axial_position))| Cylinder {
                throw: throws.as_ref().map_or(throw, |t| t[i]).rem_euclid(TAU),
                axis_angle,
                axial_position,
            })
            .collect(),
    };
    let firing_delay = firing_delays(&layout, firing.as_deref(), t.cycle, interval);
    Ok(MachineBalance {
        kind: kind.name(),
        layout,
        firing_delay,
        ..MachineBalance::default()
    })
}

/// Each cylinder's firing delay after cylinder 1 (rad). Cylinder i reaches its top dead
/// centre δ_i = (β_i − φ_i) − (β_1 − φ_1) after cylinder 1 (mod 2π, its crank angle ψ = θ + φ − β); a
/// two-stroke fires there, a four-stroke at δ_i or δ_i + 2π: the one nearest its place j in
/// the firing order, j·interval (the firing order given, or taken greedily: at each place the
/// cylinder with a top dead centre nearest it, the lowest number first).
fn firing_delays(
    layout: &Layout,
    order: Option<&[usize]>,
    cycle: Cycle,
    interval: f64,
) -> Vec<f64> {
    let n = layout.cylinders.len();
    let delta: Vec<f64> = layout
        .cylinders
        .iter()
        .map(|c| c.axis_angle - c.throw)
        .collect();
    // Relative to cylinder 1's top dead centre.
    let delta: Vec<f64> = delta
        .iter()
        .map(|d| (d - delta[0]).rem_euclid(TAU))
        .collect();
    let candidates = |i: usize| match cycle {
        Cycle::TwoStroke => vec![delta[i]],
        Cycle::FourStroke => vec![delta[i], delta[i] + TAU],
    };
    // Distance on the cycle between a delay and a target.
    let period = match cycle {
        Cycle::TwoStroke => TAU,
        Cycle::FourStroke => 2.0 * TAU,
    };
    let distance = |d: f64, target: f64| {
        let x = (d - target).rem_euclid(period);
        x.min(period - x)
    };
    let nearest = |i: usize, target: f64| {
        candidates(i)
            .into_iter()
            .map(|d| (distance(d, target), d))
            .fold(
                (f64::INFINITY, 0.0),
                |a, b| if b.0 < a.0 - 1e-12 { b } else { a },
            )
    };
    let mut delay = vec![f64::NAN; n];
    delay[0] = 0.0;
    let mut placed = vec![false; n];
    placed[0] = true;
    for j in 1..n {
        let target = j as f64 * interval;
        let i = match order {
            Some(order) => order[j] - 1,
            None => (1..n)
                .filter(|&i| !placed[i])
                .min_by(|&a, &b| nearest(a, target).0.total_cmp(&nearest(b, target).0))
                .expect("an unplaced cylinder"),
        };
        placed[i] = true;
        delay[i] = nearest(i, target).1;
    }
    // A firing order that does not start with cylinder 1: delays relative to cylinder 1.
    if let Some(order) = order {
        if order[0] != 1 {
            let first = order.iter().position(|&c| c == 1).unwrap_or(0);
            let base = first as f64 * interval;
            let mut d = vec![0.0; n];
            for (j, &c) in order.iter().enumerate() {
                let target = (j as f64 * interval - base).rem_euclid(period);
                d[c - 1] = if c == 1 {
                    0.0
                } else {
                    nearest(c - 1, target).1
                };
            }
            return d;
        }
    }
    delay
}

#[cfg(test)]
mod tests {
    use super::*;
    use cardan_balance::Cylinder;

    fn machine(throws: &[f64], axes: &[f64]) -> Layout {
        Layout {
            cylinders: throws
                .iter()
                .zip(axes)
                .map(|(&throw, &axis_angle)| Cylinder {
                    throw: throw.to_radians(),
                    axis_angle: axis_angle.to_radians(),
                    axial_position: 0.0,
                })
                .collect(),
        }
    }

    fn degrees(d: &[f64]) -> Vec<f64> {
        d.iter()
            .map(|x| (x.to_degrees() * 1e6).round() / 1e6)
            .collect()
    }

    /// A 90° vee twin on one pin fires 450° and 270° apart; an inline four of the flat crank in
    /// 1-3-4-2 every 180°; a five-cylinder radial every 144° in 1-3-5-2-4.
    #[test]
    fn firing_delays_follow_the_throws_and_the_order() {
        let vee = machine(&[0.0, 0.0], &[-45.0, 45.0]);
        let d = firing_delays(&vee, None, Cycle::FourStroke, 2.0 * PI);
        assert_eq!(degrees(&d), [0.0, 450.0]);
        let four = machine(&[0.0, 180.0, 180.0, 0.0], &[0.0; 4]);
        let d = firing_delays(&four, Some(&[1, 3, 4, 2]), Cycle::FourStroke, PI);
        assert_eq!(degrees(&d), [0.0, 540.0, 180.0, 360.0]);
        let radial = machine(&[0.0; 5], &[0.0, 72.0, 144.0, 216.0, 288.0]);
        let d = firing_delays(&radial, None, Cycle::FourStroke, 4.0 * PI / 5.0);
        assert_eq!(degrees(&d), [0.0, 432.0, 144.0, 576.0, 288.0]);
    }
}
