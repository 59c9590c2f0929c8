//! The pair's checks and its AGMA rating, and what the verdict follows from.

use super::validated::*;
use cardan_gears::{
    bending_cycle_factor, bending_geometry_factor, dynamic_factor, hardness_ratio_factor,
    pitting_cycle_factor, pitting_geometry_factor, BendingJ, CheckKind, CheckReport, GearError,
    GearPair, GearSetRating, GeneratedMember, HardnessPairing, JMethod, MemberData, PairMember,
    SizeFactor,
};

/// Whether a failed check makes the pair unusable (`Error`) or only breaks a rule of thumb
/// (`Warning`: the AGMA 917 teeth difference, the rack-generation undercut limit).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Severity {
    Error,
    Warning,
}

/// The JSON name, severity and meaning of a check.
pub fn check_info(kind: CheckKind) -> (&'static str, Severity, &'static str) {
    match kind {
        CheckKind::InvoluteInterferencePinion => (
            "involute_interference_pinion",
            Severity::Error,
            "the mate's tip stays off the pinion flank below its base circle (KHK); margin in units of rb2·tan α_op",
        ),
        CheckKind::InvoluteInterferenceGear => (
            "involute_interference_gear",
            Severity::Error,
            "the pinion tip stays off the gear flank below its base circle; margin in units of rb1·tan α_op",
        ),
        CheckKind::TrochoidInterference => (
            "trochoid_interference",
            Severity::Error,
            "no tip/trochoid interference while the pinion leaves the ring (KHK θ1·z1/z2 >= θ2); margin z1/|z2| - θ2/θ1",
        ),
        CheckKind::RingTipInsideBaseCircle => (
            "ring_tip_inside_base_circle",
            Severity::Error,
            "the ring tip circle lies outside its base circle; margin (|da2| - |db2|)/(2 m) in modules",
        ),
        CheckKind::TeethDifference => (
            "teeth_difference",
            Severity::Warning,
            "|z2| - z1 >= min_teeth_difference (AGMA 917-B97 rule of thumb); margin in teeth",
        ),
        CheckKind::ContactRatio => (
            "contact_ratio",
            Severity::Error,
            "transverse contact ratio >= 1; margin εα - 1",
        ),
        CheckKind::PinionUndercut => (
            "pinion_undercut",
            Severity::Warning,
            "rack-generated pinion without undercut, x1 >= 1 - z1 sin²α/2 (rule of thumb); margin in shift",
        ),
        CheckKind::Backlash => (
            "backlash",
            Severity::Error,
            "backlash not negative (teeth do not jam); margin jt/m in modules",
        ),
    }
}

/// How a member's bending geometry factor J was obtained.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum JSource {
    /// Given in `[rating.<member>] j`.
    Given,
    /// Computed from the tooth form (`cardan_gears::agma908`).
    Computed(BendingJ),
}

impl JSource {
    /// `"given"`, `"AGMA 908-B89"` or `"ISO 6336-3 method B"`.
    pub fn word(&self) -> &'static str {
        match self {
            JSource::Given => "given",
            JSource::Computed(b) => match b.method {
                JMethod::Agma908 => "AGMA 908-B89",
                JMethod::Iso6336MethodB => "ISO 6336-3 method B",
            },
        }
    }
}

/// J of member `k` (0 pinion, 1 gear) from the tooth form, the generating rack's tip radius
/// `tip` \[m\] (`None`: the default): AGMA 908-B89 for an external member, ISO 6336-3 method
/// B for an internal ring.
pub fn member_j(pair: &GearPair, k: usize, tip: Option<f64>) -> Result<BendingJ, GearError> {
    let which = if k == 0 {
        PairMember::Pinion
    } else {
        PairMember::Gear
    };
    bending_geometry_factor(
        pair,
        GeneratedMember {
            which,
            rack_tip_radius: tip,
        },
    )
}

/// Stresses, factors and safety factors of a rated pair; arrays are `[pinion, gear]`, SI.
#[derive(Debug, Clone, PartialEq)]
pub struct RatingResult {
    /// The bending geometry factors used.
    pub j: [f64; 2],
    /// How each was obtained.
    pub j_source: [JSource; 2],
    pub power: f64,
    pub pinion_torque: f64,
    pub pitch_line_velocity: f64,
    pub tangential_load: f64,
    pub kv: f64,
    /// Pitch-line velocity limit of the Kv curve, m/s (`None` for a given Kv).
    pub kv_velocity_limit: Option<f64>,
    pub km: f64,
    pub i: f64,
    pub cycles: [f64; 2],
    pub ks: [f64; 2],
    pub yn: [f64; 2],
    pub zn: [f64; 2],
    pub ch: [f64; 2],
    pub bending_stress: [f64; 2],
    pub contact_stress: [f64; 2],
    pub bending_safety: [f64; 2],
    pub contact_safety: [f64; 2],
    /// The face width at which every safety factor reaches the required one, m, when one falls
    /// short and a face width up to 40 in is enough ([`GearSetRating::required_face_width`]).
    pub face_width_for_required: Option<f64>,
    pub warnings: Vec<String>,
}

/// Everything computed for one gear file.
#[derive(Debug, Clone)]
pub struct GearReport {
    pub input: GearFile,
    pub pair: GearPair,
    pub checks: Vec<CheckReport>,
    /// `None` without a `[rating]` table; `Some(Err)` when the pair cannot be rated.
    pub rating: Option<Result<RatingResult, String>>,
    /// The ISO 6336 rating: `None` without its inputs; `Some(Err)` when it cannot be computed.
    pub iso: Option<Result<cardan_gears::iso6336::IsoRating, String>>,
}

impl GearReport {
    /// Why the pair cannot work, each with its remedy; empty when the pair works. The verdict
    /// (docs/gear-calculator.md):
    ///
    /// * every blocking check passes: involute and trochoid interference, ring tip outside its
    ///   base circle, contact ratio >= 1, backlash >= 0 ([`check_info`]; the rules of thumb,
    ///   teeth difference and undercut, are [`warnings`](Self::warnings));
    /// * every geometry figure written is a finite number;
    /// * with `[rating]`: the rating is computed with every figure finite, and each member's
    ///   bending safety factor `SF` and pitting safety factor `SH` is at least
    ///   `required_safety_factor` (default 1). Both are compared directly, as the design
    ///   factors of the allowable-stress equations `σ_all = St YN / (SF KT KR)` and
    ///   `σc_all = Sc ZN CH / (SH KT KR)` (Shigley, Budynas & Nisbett, eqs. 14-17 and 14-18;
    ///   AGMA 2001-D04 clause 4), with `SF`, `SH` from Shigley eqs. 14-41 and 14-42.
    pub fn failures(&self) -> Vec<String> {
        let mut out: Vec<String> = self
            .checks
            .iter()
            .filter(|c| !c.passed && check_info(c.kind).1 == Severity::Error)
            .map(|c| format!("{}: {}", check_info(c.kind).0, remedy_text(c)))
            .collect();
        for (quantity, value) in self.geometry_figures() {
            if !value.is_finite() {
                out.push(format!(
                    "geometry: {quantity} = {value} is not a finite number; check module, teeth, profile_shift and center_distance"
                ));
            }
        }
        let basis = self
            .input
            .rating
            .as_ref()
            .map_or(Basis::Agma2001, |r| r.basis);
        match (&self.rating, basis, &self.iso) {
            (None, _, _) => {}
            (Some(Err(e)), _, _) => out.push(format!("rating: {e}")),
            (Some(Ok(r)), Basis::Agma2001, _) => out.extend(self.safety_failures(r)),
            (Some(Ok(_)), Basis::Iso6336, Some(Err(e))) => out.push(format!("rating: {e}")),
            (Some(Ok(r)), Basis::Iso6336, Some(Ok(iso))) => {
                out.extend(self.iso_safety_failures(r, iso))
            }
            (Some(Ok(_)), Basis::Iso6336, None) => {
                out.push("rating: the ISO 6336 rating was not computed".to_string())
            }
        }
        out
    }

    /// The ISO 6336 safety factors below `required_safety_factor` (the verdict's basis is
    /// ISO), each with the remedy: the load scaled by `min(S_F/n, (S_H/n)²)` (ISO 6336-3
    /// eq. (1): `σ_F ∝ F_t`; ISO 6336-2 eq. (3): `σ_H ∝ √F_t`; approximate, since method B
    /// `K_v` and `K_Hα` depend on the load), a wider face, a larger module or a stronger
    /// material.
    fn iso_safety_failures(
        &self,
        r: &RatingResult,
        iso: &cardan_gears::iso6336::IsoRating,
    ) -> Vec<String> {
        let Some(inputs) = &self.input.rating else {
            return Vec::new();
        };
        let n = inputs.required_safety_factor;
        let mut short = Vec::new();
        for (k, member) in ["pinion", "gear"].iter().enumerate() {
            if iso.s_f[k] < n {
                short.push(format!(
                    "ISO bending safety factor S_F of the {member} = {:.4} < required_safety_factor {n} (ISO 6336-3:2019 §5.4)",
                    iso.s_f[k]
                ));
            }
        }
        for (k, member) in ["pinion", "gear"].iter().enumerate() {
            if iso.s_h[k] < n {
                short.push(format!(
                    "ISO pitting safety factor S_H of the {member} = {:.4} < required_safety_factor {n} (ISO 6336-2:2019 §5.4)",
                    iso.s_h[k]
                ));
            }
        }
        if short.is_empty() {
            return short;
        }
        let f = (0..2)
            .map(|k| (iso.s_f[k] / n).min((iso.s_h[k] / n).powi(2)))
            .fold(f64::INFINITY, f64::min);
        let load = match inputs.load {
            Load::Torque(t) => format!("rating.torque at most about {} N*m", sig4(t * f, false)),
            Load::Power(_) => format!(
                "rating.power at most about {} kW",
                sig4(r.power * f / 1e3, false)
            ),
        };
        let remedy = format!(
            "{load} (K_v and K_Hα change with the load), or a wider face_width, or a larger module, or a stronger material (larger σ_Hlim, σ_Flim)"
        );
        short
            .into_iter()
            .map(|s| format!("{s}; remedy: {remedy}"))
            .collect()
    }

    /// The safety factors below `required_safety_factor`, each with the pair's remedy.
    fn safety_failures(&self, r: &RatingResult) -> Vec<String> {
        let Some(inputs) = &self.input.rating else {
            return Vec::new();
        };
        let n = inputs.required_safety_factor;
        let members = ["pinion", "gear"];
        let mut short = Vec::new();
        for (k, member) in members.iter().enumerate() {
            if r.bending_safety[k] < n {
                short.push(format!(
                    "bending safety factor SF of the {member} = {:.4} < required_safety_factor {n} (Shigley eq. 14-41)",
                    r.bending_safety[k]
                ));
            }
        }
        for (k, member) in members.iter().enumerate() {
            if r.contact_safety[k] < n {
                short.push(format!(
                    "pitting safety factor SH of the {member} = {:.4} < required_safety_factor {n} (Shigley eq. 14-42)",
                    r.contact_safety[k]
                ));
            }
        }
        if short.is_empty() {
            return short;
        }
        let remedy = self.safety_remedy(r, n);
        short
            .into_iter()
            .map(|s| format!("{s}; remedy: {remedy}"))
            .collect()
    }

    /// The remedy of a pair whose safety factors fall short of `n`: the largest load, from the
    /// stresses' dependence on the tangential load at a fixed speed (bending `σ ∝ Wt`, AGMA
    /// 2001-D04 eq. 15; contact `σc ∝ √Wt`, eq. 1; `Kv` depends on the speed, `Km`, `Ks` on the
    /// face width), so the load may be scaled by `min(SF/n, (SH/n)²)`; the face width at which
    /// every factor reaches `n`; a larger module, a stronger material.
    fn safety_remedy(&self, r: &RatingResult, n: f64) -> String {
        let f = (0..2)
            .map(|k| (r.bending_safety[k] / n).min((r.contact_safety[k] / n).powi(2)))
            .fold(f64::INFINITY, f64::min);
        let load = match self.input.rating.as_ref().map(|i| i.load) {
            Some(Load::Torque(t)) => format!("rating.torque at most {} N*m", sig4(t * f, false)),
            _ => format!("rating.power at most {} kW", sig4(r.power * f / 1e3, false)),
        };
        let width = match r.face_width_for_required {
            Some(b) => format!("face_width at least {} mm", sig4(b * 1e3, true)),
            None => "no face width up to 40 in is enough".to_string(),
        };
        format!(
            "{load}, or {width}, or a larger module, or a stronger material (larger allowable stresses St, Sc)"
        )
    }

    /// Rules of thumb the pair breaks (failed `Warning` checks: teeth difference, undercut),
    /// with their remedies, and the rating's warnings.
    pub fn warnings(&self) -> Vec<String> {
        let mut out: Vec<String> = self
            .checks
            .iter()
            .filter(|c| !c.passed && check_info(c.kind).1 == Severity::Warning)
            .map(|c| format!("{}: {}", check_info(c.kind).0, remedy_text(c)))
            .collect();
        if let Some(Ok(r)) = &self.rating {
            out.extend(r.warnings.iter().map(|w| format!("rating: {w}")));
        }
        out
    }

    /// Every geometry figure written to `gear.json` and `report.md`, with its name.
    fn geometry_figures(&self) -> Vec<(String, f64)> {
        let p = &self.pair;
        let s = &p.spec;
        let mut v: Vec<(String, f64)> = vec![
            ("module".into(), s.module),
            ("pressure angle".into(), s.pressure_angle),
            ("profile shift x1".into(), s.pinion.shift),
            ("profile shift x2".into(), s.gear.shift),
            ("ratio".into(), p.ratio),
            ("working pressure angle".into(), p.working_pressure_angle),
            (
                "operating pressure angle".into(),
                p.operating_pressure_angle,
            ),
            ("working centre distance".into(), p.working_centre_distance),
            ("centre distance".into(), p.centre_distance),
            ("base pitch".into(), p.base_pitch),
            ("path of contact".into(), p.path_of_contact),
            ("contact ratio".into(), p.contact_ratio),
            (
                "circumferential backlash".into(),
                p.backlash_circumferential,
            ),
            ("normal backlash".into(), p.backlash_normal),
            ("gear addendum".into(), p.gear_addendum()),
            (
                "largest gear addendum without interference".into(),
                p.max_gear_addendum_without_interference(),
            ),
        ];
        if p.internal {
            v.push(("trochoid ratio".into(), p.trochoid_ratio()));
        }
        for (member, d) in [("pinion", &p.pinion), ("gear", &p.gear)] {
            for (name, x) in [
                ("reference diameter", d.reference),
                ("base diameter", d.base),
                ("tip diameter", d.tip),
                ("root diameter", d.root),
                ("working diameter", d.working),
            ] {
                v.push((format!("{member} {name}"), x));
            }
        }
        for c in &self.checks {
            v.push((format!("margin of {}", check_info(c.kind).0), c.margin));
        }
        v
    }
}

/// `x` to 4 significant digits, rounded up (`up`) or down, so that a remedy's bound is safe.
fn sig4(x: f64, up: bool) -> String {
    if !(x.is_finite() && x > 0.0) {
        return format!("{x}");
    }
    let e = x.log10().floor() as i32;
    let scale = 10f64.powi(e - 3);
    let y = if up {
        (x / scale * (1.0 - 1e-12)).ceil() * scale
    } else {
        (x / scale * (1.0 + 1e-12)).floor() * scale
    };
    let decimals = (3 - e).max(0) as usize;
    format!("{y:.decimals$}")
}

/// The check's outcome in the words of the case files' geometry errors
/// ([`CheckReport::verdict`]: one text for both).
fn remedy_text(c: &CheckReport) -> String {
    c.verdict()
}

/// Computes the geometry, the checks and the rating of a validated gear file.
pub fn evaluate(input: &GearFile) -> Result<GearReport, GearFileError> {
    let pair = GearPair::new(input.spec).map_err(|e| GearFileError::Invalid {
        file: input.file.clone(),
        name: input.name.clone(),
        field: "teeth".into(),
        value: format!("{:?}", [input.spec.pinion.teeth, input.spec.gear.teeth]),
        rule: e.to_string(),
    })?;
    let checks = pair.checks();
    let rating = match (&input.rating, input.face_width) {
        (Some(r), Some(b)) => Some(rate(&pair, r, b, input.rack_tip_radius)),
        _ => None,
    };
    let iso = match (&input.rating, input.face_width) {
        (Some(r), Some(b)) => super::iso_rate::rate_iso(&pair, r, b, input.rack_tip_radius),
        _ => None,
    };
    Ok(GearReport {
        input: input.clone(),
        pair,
        checks,
        rating,
        iso,
    })
}

/// Rates the pair; an error names the quantity that could not be computed or is not finite.
fn rate(
    pair: &GearPair,
    r: &RatingInputs,
    face_width: f64,
    tips: [Option<f64>; 2],
) -> Result<RatingResult, String> {
    let mut j = [0.0; 2];
    let mut j_source = [JSource::Given; 2];
    for (k, member) in ["pinion", "gear"].into_iter().enumerate() {
        (j[k], j_source[k]) = match r.members[k].j {
            Some(given) => (given, JSource::Given),
            None => {
                let b = member_j(pair, k, tips[k]).map_err(|e| {
                    format!("the {member}'s bending geometry factor J cannot be computed from the tooth form: {e}; give rating.{member}.j")
                })?;
                (b.j, JSource::Computed(b))
            }
        };
    }
    let mut result = rate_figures(pair, r, face_width, j).map_err(|e| e.to_string())?;
    result.j_source = j_source;
    let figures = rating_figures(&result);
    if let Some((quantity, value, unit)) = figures.iter().find(|(_, v, _)| !v.is_finite()) {
        return Err(format!(
            "{quantity} = {value} {unit} is not a finite number (pinion torque {:e} N·m at pinion speed {:e} rad/s): check rating.power or rating.torque, rating.pinion_speed and the factors",
            result.pinion_torque, r.pinion_speed
        ));
    }
    let n = r.required_safety_factor;
    if result
        .bending_safety
        .iter()
        .chain(&result.contact_safety)
        .any(|&x| x < n)
    {
        result.face_width_for_required = rating_set(pair, r, &result)
            .required_face_width(result.tangential_load, result.kv, n, n, 1)
            .ok()
            .map(|w| w.governing);
    }
    Ok(result)
}

/// Every figure of a rating written to `gear.json` and `report.md`, in the order they are
/// computed: (quantity, value, unit).
fn rating_figures(r: &RatingResult) -> Vec<(String, f64, &'static str)> {
    let mut v: Vec<(String, f64, &'static str)> = vec![
        ("pitch-line velocity".into(), r.pitch_line_velocity, "m/s"),
        ("power".into(), r.power, "W"),
        ("pinion torque".into(), r.pinion_torque, "N·m"),
        ("tangential load Wt".into(), r.tangential_load, "N"),
        ("dynamic factor Kv".into(), r.kv, ""),
        ("load distribution factor Km".into(), r.km, ""),
        ("pitting geometry factor I".into(), r.i, ""),
        ("bending geometry factor J of the pinion".into(), r.j[0], ""),
        ("bending geometry factor J of the gear".into(), r.j[1], ""),
    ];
    if let Some(x) = r.kv_velocity_limit {
        v.push(("velocity limit of Kv".into(), x, "m/s"));
    }
    let per_member: [(&str, &[f64; 2], &'static str); 9] = [
        ("load cycles", &r.cycles, ""),
        ("size factor Ks", &r.ks, ""),
        ("stress-cycle factor YN", &r.yn, ""),
        ("stress-cycle factor ZN", &r.zn, ""),
        ("hardness-ratio factor CH", &r.ch, ""),
        ("bending stress", &r.bending_stress, "Pa"),
        ("contact stress", &r.contact_stress, "Pa"),
        ("bending safety factor SF", &r.bending_safety, ""),
        ("pitting safety factor SH", &r.contact_safety, ""),
    ];
    for (name, a, unit) in per_member {
        for (k, member) in ["pinion", "gear"].iter().enumerate() {
            v.push((format!("{name} of the {member}"), a[k], unit));
        }
    }
    v
}

/// The AGMA 2001-D04 rating set of the pair (the inputs of [`GearSetRating::rate`]).
fn gear_set(
    pair: &GearPair,
    r: &RatingInputs,
    j: [f64; 2],
    i: f64,
    yn: [f64; 2],
    zn: [f64; 2],
    ch: [f64; 2],
) -> GearSetRating {
    let d1 = pair.pinion.working;
    let m = pair.spec.module;
    let member = |k: usize| MemberData {
        j: j[k],
        rim: r.members[k].rim_factor,
        bending_allowable: r.members[k].bending_allowable,
        contact_allowable: r.members[k].contact_allowable,
        yn: yn[k],
        zn: zn[k],
        ch: ch[k],
    };
    let size = match (r.members[0].lewis_y, r.members[1].lewis_y) {
        (Some(y1), Some(y2)) => SizeFactor::Shigley { lewis_y: [y1, y2] },
        _ => SizeFactor::Given([
            r.members[0].size_factor.unwrap_or(1.0),
            r.members[1].size_factor.unwrap_or(1.0),
        ]),
    };
    GearSetRating {
        module: m,
        pinion_diameter: d1,
        overload: r.overload,
        load_distribution: r.load_distribution,
        size,
        surface_condition: r.surface_condition,
        geometry_i: i,
        elastic_coefficient: r.elastic_coefficient,
        temperature: r.temperature_factor,
        reliability: r.reliability_factor,
        pinion: member(0),
        gear: member(1),
    }
}

/// [`gear_set`] of a computed rating.
fn rating_set(pair: &GearPair, r: &RatingInputs, result: &RatingResult) -> GearSetRating {
    gear_set(pair, r, result.j, result.i, result.yn, result.zn, result.ch)
}

fn rate_figures(
    pair: &GearPair,
    r: &RatingInputs,
    face_width: f64,
    j: [f64; 2],
) -> Result<RatingResult, GearError> {
    let mut warnings = Vec::new();
    let u = pair.ratio;
    if u < 1.0 {
        warnings.push(
            "gear 1 is the larger member; AGMA's pinion is the smaller one, so its diameter and CH apply to gear 2 (not applied here: gear 1 is rated as the pinion)".to_string(),
        );
    }
    let d1 = pair.pinion.working;
    let v = r.pinion_speed * d1 / 2.0;
    let (power, torque) = match r.load {
        Load::Power(p) => (p, p / r.pinion_speed),
        Load::Torque(t) => (t * r.pinion_speed, t),
    };
    let wt = torque / (d1 / 2.0);
    let (kv, kv_limit) = match r.kv {
        KvInput::Given(k) => (k, None),
        KvInput::Quality(q) => {
            let d = dynamic_factor(q, v)?;
            if !d.within_limit {
                warnings.push(format!(
                    "pitch-line velocity {:.3} m/s exceeds the Kv curve's limit {:.3} m/s: Kv is extrapolated",
                    v, d.v_max
                ));
            }
            (d.kv, Some(d.v_max))
        }
    };
    let i = match r.i {
        IInput::Given(i) => i,
        IInput::Form(f) => pitting_geometry_factor(pair, f)?,
    };
    let cycles = [r.pinion_cycles, r.pinion_cycles / u];
    let yn = [
        bending_cycle_factor(cycles[0], r.bending_low, r.bending_high)?,
        bending_cycle_factor(cycles[1], r.bending_low, r.bending_high)?,
    ];
    let zn = [
        pitting_cycle_factor(cycles[0], r.nitrided)?,
        pitting_cycle_factor(cycles[1], r.nitrided)?,
    ];
    let ch_gear = match (
        r.hardness_ratio_factor,
        r.members[0].hardness,
        r.members[1].hardness,
    ) {
        (Some(ch), _, _) => ch,
        (None, Some(hp), Some(hg)) if u >= 1.0 => hardness_ratio_factor(
            HardnessPairing::ThroughHardened {
                pinion_hb: hp,
                gear_hb: hg,
            },
            u,
        )?,
        _ => 1.0,
    };
    let ch = [1.0, ch_gear];
    let set = gear_set(pair, r, j, i, yn, zn, ch);
    let km = r.load_distribution.factor(face_width, d1)?;
    if !km.within_validity {
        warnings.push(format!(
            "face width / pinion diameter = {:.3} > 2: outside the empirical Km method",
            face_width / d1
        ));
    }
    let out = set.rate(wt, kv, face_width)?;
    Ok(RatingResult {
        j,
        j_source: [JSource::Given; 2],
        power,
        pinion_torque: torque,
        pitch_line_velocity: v,
        tangential_load: wt,
        kv,
        kv_velocity_limit: kv_limit,
        km: out.km,
        i,
        cycles,
        ks: out.ks,
        yn,
        zn,
        ch,
        bending_stress: out.bending_stress,
        contact_stress: out.contact_stress,
        bending_safety: out.bending_safety,
        contact_safety: out.contact_safety,
        face_width_for_required: None,
        warnings,
    })
}
