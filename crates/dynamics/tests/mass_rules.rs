//! The default mass rules of `cardan_mechanism::mass` (no override: `MassInputs::default()`
//! plus the rod material) against Karhula (2008): the published inertial values of the
//! shortest-rod machine (docs/validation/karhula-2008.md, appendices 11.2.1-11.2.2), and
//! for other rods and bores the reductions the thesis states (ch. 11.2: mean inertial torque
//! "10...30 %" smaller in the cardan gear, mean inertial power "12...40 %", "the longer is the
//! rod and the bigger is the displacement, the better is the cardan gear machine", "the mass of
//! the rod (steel or titanium) affects the results very little"; ch. 11.7: the 5·crank rod
//! machine, "≤ 28 %" and "≲ 37 %"; ch. 13: "almost 30 %", "almost 40 %"). The derivation of
//! the rules and the table these tests print (`--nocapture`) are in docs/mass-rules.md.
//!
//! The wheel's sign. The thesis adds the cardan wheel's inertial torque with the sign opposite
//! to the crankshaft's (A5.2.1.43-46); this project adds J_wheel·α to the drive torque (see
//! `cardan_gear.rs`). The cardan gear's values are compared with the thesis's in the thesis's
//! sign: the drive torque less 2·J_wheel·α, exactly, and the crank-angle mean power less
//! 2·J_wheel·α·ω̄, ω̄ the crank-angle mean of ω. In this project's sign every reduction is
//! 0.6-0.9 percentage point smaller.
//!
//! Nothing here is copied from the program's output: the expected values are the thesis's,
//! the bounds its stated ranges, or relations between runs (trends).

mod common;
use cardan_dynamics::Summary;
use cardan_mechanism::mass::{self, cardan_wheel_inertia, crankshaft_inertia};
use cardan_mechanism::{
    entry, MachineGeometry, MassInputs, MassRules, Material, Mechanism, Options,
};
use cardan_testing::within;
use common::cycle;
use std::f64::consts::PI;

const S: &str = "slider_crank";
const C: &str = "cardan_gear";
const STEEL: Material = Material::Steel;
const TITANIUM: Material = Material::Titanium;
const DEFAULT: MassRules = MassRules::RodLength;
const OVERALL: MassRules = MassRules::OverallLength;
const READINGS: [MassRules; 2] = [DEFAULT, OVERALL];

/// The rod lengths of the thesis's rod-to-crank ratios 2.33, 3, 4 and 5 on its largest crank,
/// 0.06 m (ZBA = 2.33, 3, 4, 5·ZAA0).
const RODS: [f64; 4] = [0.14, 0.18, 0.24, 0.30];
/// Bores on the 0.06 m crank: 1.5·crank (the thesis's "thin piston", ch. 11.7), 2·crank (its
/// tables), 3·crank (within its 1...3.4·crank, ch. 11).
const BORES: [f64; 3] = [0.09, 0.12, 0.18];
/// The longest rod among the thesis's computations, m (ch. 11: rod lengths 0.08...0.24 m).
const THESIS_LONGEST_ROD: f64 = 0.24;

/// `mechanism` on crank `crank`, rod `rod`, bore `bore` (m) with the masses of the reading
/// `rules` (`None`: no `rules` field, the default) and the rod in `material`.
fn machine_in(
    rules: Option<MassRules>,
    mechanism: &str,
    crank: f64,
    rod: f64,
    bore: f64,
    material: Material,
) -> Box<dyn Mechanism> {
    let geometry = MachineGeometry {
        crank_length: crank,
        rod_length: rod,
        bore,
        pin_offset: 0.0,
    };
    let masses = MassInputs {
        rod_material: Some(material),
        rules,
        ..MassInputs::default()
    };
    (entry(mechanism).unwrap().build)(&geometry, &masses, &Options::new()).unwrap()
}

/// The thesis cycle (90° → 810°) at ω0 = `w0`·π rad/s, α = `alpha`·π rad/s².
fn run(mech: &dyn Mechanism, w0: f64, alpha: f64) -> Summary {
    cycle(mech, w0 * PI, alpha * PI, 7200).1
}

fn get(summary: &Summary, name: &str) -> f64 {
    summary.get(name).unwrap()
}

/// The slider-crank (steel rod) and the cardan gear (rod in `cardan_rod`, the thesis's pairing:
/// only the cardan gear gets the titanium rod, appendix 11.2.1) on one geometry, one motion.
struct Pair {
    s: Summary,
    c: Summary,
    /// The cardan wheel's inertia, kg·m², and the motion, for the wheel's sign.
    wheel: f64,
    alpha: f64,
    mean_speed: f64,
}

impl Pair {
    fn new_in(
        rules: Option<MassRules>,
        crank: f64,
        rod: f64,
        bore: f64,
        cardan_rod: Material,
        w0: f64,
        alpha: f64,
    ) -> Self {
        let s = run(
            machine_in(rules, S, crank, rod, bore, STEEL).as_ref(),
            w0,
            alpha,
        );
        let cardan = machine_in(rules, C, crank, rod, bore, cardan_rod);
        let c = run(cardan.as_ref(), w0, alpha);
        // ω̄ = (1/4π)·∫ω dθ with ω² = ω0² + 2α(θ − θ0): (ω_end³ − ω0³)/(3α·4π).
        let (w0, alpha) = (w0 * PI, alpha * PI);
        let end = (w0 * w0 + 2.0 * alpha * 4.0 * PI).sqrt();
        let mean_speed = if alpha > 0.0 {
            (end.powi(3) - w0.powi(3)) / (3.0 * alpha * 4.0 * PI)
        } else {
            w0
        };
        Pair {
            s,
            c,
            wheel: cardan.masses().wheel_inertia,
            alpha,
            mean_speed,
        }
    }

    /// The cardan gear's mean inertial torque, N·m, in the thesis's sign (module note).
    fn c_torque(&self) -> f64 {
        get(&self.c, "inertial_torque_mean") - 2.0 * self.wheel * self.alpha
    }

    /// The cardan gear's mean inertial power, W, in the thesis's sign (module note).
    fn c_power(&self) -> f64 {
        get(&self.c, "inertial_power_mean") - 2.0 * self.wheel * self.alpha * self.mean_speed
    }

    /// The cardan gear's reductions against the slider-crank in mean inertial torque and mean
    /// inertial power, percent, in the thesis's sign.
    fn reductions(&self) -> (f64, f64) {
        (
            100.0 * (1.0 - self.c_torque() / get(&self.s, "inertial_torque_mean")),
            100.0 * (1.0 - self.c_power() / get(&self.s, "inertial_power_mean")),
        )
    }

    /// The same in this project's sign.
    fn project_reductions(&self) -> (f64, f64) {
        let r = |name: &str| 100.0 * (1.0 - get(&self.c, name) / get(&self.s, name));
        (r("inertial_torque_mean"), r("inertial_power_mean"))
    }
}

/// The reductions the thesis's tables are quoted at: α = 100π rad/s², ω0 = 200π rad/s, in the
/// reading `rules`.
fn reductions_in(
    rules: MassRules,
    crank: f64,
    rod: f64,
    bore: f64,
    cardan_rod: Material,
) -> (f64, f64) {
    Pair::new_in(Some(rules), crank, rod, bore, cardan_rod, 200.0, 100.0).reductions()
}

/// (a) The shortest-rod machine (r = 0.06 m, l = 0.14 m, bore 0.12 m) with the default masses
/// (no override, no `rules`: the rod_length reading) and with the overall_length reading,
/// against the thesis's published inertial values. Tolerances:
/// - values a rule constant was fixed by: the cardan crank-pin force (60740 N → the piston
///   constant) and the slider-crank mean torque (15.03 N·m → κ of the rod's inertia), 0.1 %,
///   the constants being rounded to four digits; the cardan mean torque (13.51 N·m → the
///   flywheel margin, found 30.06 mm, used 30 mm), 0.3 %;
/// - the titanium crank-pin force: in the rod_length reading it fixes the rod's volume (with
///   the steel one), 0.1 %; in the overall_length reading it checks the rod rule ℓ³/50, whose
///   volume is 0.8 % above the one the thesis's two forces imply, 1 %; both cardan peak
///   torques follow from the rod, 1 %;
/// - the cardan gear's mean powers follow from the masses fixed above and the cycle: 0.5 %,
///   the thesis printing three to four digits;
/// - the slider-crank's mean powers also depend on the rod's inertia away from top dead
///   centre, which the published mean torque does not fix: 1 %;
/// - the slider-crank's crank-pin force maximum depends on how the rod's mass is distributed,
///   which the thesis does not give (with the centre of gravity at mid-rod, as its rod
///   kinematics require, the top-dead-centre value is 37.0 kN and the maximum lies where the
///   rod's inertia couple is largest): 5 %;
/// - the slider-crank's peak inertial torque, 556 N·m, is the thesis's least consistent value:
///   with the rod inertia its mean torque fixes, a rod centred at mid-length peaks about 16 %
///   lower: 20 %;
/// - the reductions are quoted in whole percent (−10 %, −13 %): ±0.5 percentage point.
#[test]
fn shortest_rod_reproduces_the_published_values() {
    for rules in [None, Some(OVERALL)] {
        shortest_rod_in(rules);
    }
}

fn shortest_rod_in(rules: Option<MassRules>) {
    let (r, l, d) = (0.06, 0.14, 0.12);
    // Appendix 11.2.1, α = 0, ω0 = 200π.
    let steady = Pair::new_in(rules, r, l, d, STEEL, 200.0, 0.0);
    let titanium = Pair::new_in(rules, r, l, d, TITANIUM, 200.0, 0.0);
    let f = |x: &Summary| get(x, "inertial_crank_pin_force_max");
    let t = |x: &Summary| get(x, "inertial_torque_max");
    within("C crank pin force", f(&steady.c), 60_740.0, 0.001);
    let fixed_by_titanium = rules.unwrap_or_default() == DEFAULT;
    let tol = if fixed_by_titanium { 0.001 } else { 0.01 };
    within("C titanium crank pin force", f(&titanium.c), 37_960.0, tol);
    within("C peak torque", t(&steady.c), 911.0, 0.01);
    within("C titanium peak torque", t(&titanium.c), 569.0, 0.01);
    within("S crank pin force", f(&steady.s), 38_510.0, 0.05);
    within("S peak torque", t(&steady.s), 556.0, 0.20);
    // Appendix 11.2.2: mean inertial torques at α = 100π and 200π (independent of ω0).
    for (alpha, ts, tc) in [(100.0, 15.03, 13.51), (200.0, 30.05, 27.03)] {
        for w0 in [3.0, 200.0] {
            let p = Pair::new_in(rules, r, l, d, STEEL, w0, alpha);
            within(
                "S mean torque",
                get(&p.s, "inertial_torque_mean"),
                ts,
                0.001,
            );
            within("C mean torque", p.c_torque(), tc, 0.003);
        }
    }
    // Mean inertial powers at α = 100π.
    for (w0, ps, pc) in [
        (3.0, 908.0, 790.0),
        (30.0, 1705.0, 1484.0),
        (200.0, 9547.0, 8309.0),
    ] {
        let p = Pair::new_in(rules, r, l, d, STEEL, w0, 100.0);
        within("S mean power", get(&p.s, "inertial_power_mean"), ps, 0.01);
        within("C mean power", p.c_power(), pc, 0.005);
    }
    let (torque, power) = Pair::new_in(rules, r, l, d, STEEL, 200.0, 100.0).reductions();
    assert!(
        (torque - 10.0).abs() <= 0.5,
        "torque reduction {torque} %, thesis 10 %"
    );
    assert!(
        (power - 13.0).abs() <= 0.5,
        "power reduction {power} %, thesis 13 %"
    );
}

/// (b) Over the rods and bores, in both readings: the reductions increase with the rod length
/// ("the longer is the rod ... the better is the cardan gear machine", ch. 11.2).
///
/// In the overall_length reading, also the thesis's stated ranges where the thesis computed
/// (rods up to 0.24 m, and its two other published machines). Bounds: the thesis states whole
/// percents, so ±0.5 percentage point. The 0.30 m rod on the 0.06 m crank lies beyond the
/// thesis's rod lengths (0.08...0.24 m, ch. 11); its stated maxima ("almost 30 %" and "almost
/// 40 %", ch. 13) are those of its 5·crank rod on a 0.046 m crank (ch. 11.7: 28 %, 37 %), and
/// by its own trend the same rod ratio on the bigger crank does better. There the test asks
/// for more than the 0.24 m rod and the thesis's 5·crank machine, and less than the thesis's
/// "almost 30 %"/"almost 40 %" carried to the 0.06 m crank by the chapter-10 crankshaft rule:
/// for machines of equal proportions the cardan gear's advantage ΔJ/J grows as the rod's r⁵
/// over the crankshaft's r³·(r + 30 mm)², by (0.06/0.09)²/(0.046/0.076)² = 1.2131, so 30 %
/// becomes 34.2 % and 40 % becomes 44.7 %.
///
/// The default reading (rod_length) does not meet these ranges on the long rods: its rod grows
/// as l⁵ against the crankshaft's r³·(r + 30 mm)², so the 0.24 m rod on the 0.06 m crank and
/// the 5·crank machine of ch. 11.7 come out above the thesis's "10...30 %" and "≤ 28 %"
/// (docs/mass-rules.md, "Where the readings part"; test (g) states by how much).
#[test]
fn reductions_across_rods_and_bores_follow_the_thesis() {
    println!(
        "reading, rod, bore [m]; torque and power reductions [%], thesis's sign (this project's)"
    );
    for rules in READINGS {
        for bore in BORES {
            let mut last = (f64::MIN, f64::MIN);
            for rod in RODS {
                let p = Pair::new_in(Some(rules), 0.06, rod, bore, STEEL, 200.0, 100.0);
                let (torque, power) = p.reductions();
                let (pt, pp) = p.project_reductions();
                println!(
                    "{}  {rod:.2}  {bore:.2}  {torque:5.1}  {power:5.1}  ({pt:.1}, {pp:.1})",
                    rules.name()
                );
                assert!(
                    torque > last.0 && power > last.1,
                    "{}: the longer the rod, the better the cardan gear: rod {rod} m, bore {bore} m: \
                     {torque:.2} % / {power:.2} % after {:.2} % / {:.2} %",
                    rules.name(),
                    last.0,
                    last.1
                );
                last = (torque, power);
                if rules == OVERALL && rod <= THESIS_LONGEST_ROD {
                    assert!(
                        (9.5..=30.5).contains(&torque),
                        "rod {rod} m, bore {bore} m: torque {torque:.2} % smaller, thesis 10...30 %"
                    );
                    assert!(
                        (11.5..=40.5).contains(&power),
                        "rod {rod} m, bore {bore} m: power {power:.2} % smaller, thesis 12...40 %"
                    );
                }
            }
        }
    }
    // The thesis's two other published machines, bore = 2·crank and 1.5·crank (figures
    // 11.6.7-9, 11.6.16-18): in the ranges.
    let (t4, p4) = reductions_in(OVERALL, 0.04, 0.16, 0.08, STEEL);
    let (t5, p5) = reductions_in(OVERALL, 0.046, 0.229, 0.069, STEEL);
    println!(
        "overall_length: 0.04/0.16 bore 0.08: {t4:.1} % / {p4:.1} %; 0.046/0.229 bore 0.069: {t5:.1} % / {p5:.1} %"
    );
    for (what, torque, power) in [
        ("4·crank on 0.04 m", t4, p4),
        ("5·crank on 0.046 m", t5, p5),
    ] {
        assert!(
            (9.5..=30.5).contains(&torque),
            "{what}: torque {torque:.2} %"
        );
        assert!((11.5..=40.5).contains(&power), "{what}: power {power:.2} %");
    }
    // The 0.30 m rod on the 0.06 m crank (doc comment).
    let (t30, p30) = reductions_in(OVERALL, 0.06, 0.30, 0.12, STEEL);
    let (t24, p24) = reductions_in(OVERALL, 0.06, 0.24, 0.12, STEEL);
    assert!(
        t30 > t24 && t30 > t5 && t30 < 34.2,
        "0.30 m rod: torque {t30:.2} %"
    );
    assert!(
        p30 > p24 && p30 > p5 && p30 < 44.7,
        "0.30 m rod: power {p30:.2} %"
    );
}

/// (c) The thesis's 5·crank rod machine (ch. 11.7: crank 0.046 m, rod 0.229 m, bore
/// 1.5·crank, 339 cm³), in the overall_length reading: mean inertial torque "≤ 28 %"
/// smaller, called "almost 30 %" in the conclusions (ch. 13); mean inertial power "≲ 37 %",
/// "almost 40 %". Bounds: 28 % and 37 % rounded to whole percents (≥ 27.5 %, ≥ 36.5 %), and
/// below the "almost" 30 % and 40 %. The default reading puts this machine far above (test (g)).
#[test]
fn the_five_crank_rod_machine_matches_chapter_11_7() {
    let (torque, power) = reductions_in(OVERALL, 0.046, 0.229, 0.069, STEEL);
    assert!(
        (27.5..30.0).contains(&torque),
        "torque {torque:.2} %, thesis 28 %"
    );
    assert!(
        (36.5..40.0).contains(&power),
        "power {power:.2} %, thesis 37 %"
    );
}

/// (d) "The longer is the rod and the bigger is the displacement, the better is the cardan
/// gear machine" (ch. 11.2), the displacement grown two ways:
/// - as in the thesis's tables (bore = 2·crank), with the crank: cranks 0.04, 0.05, 0.06 m at
///   the rod ratios 2.33, 3, 4, 5: both reductions strictly increase;
/// - at the 0.06 m crank, with the bore (1.5, 2, 3·crank): only the piston mass changes. It
///   cannot change either mean inertial torque (the piston is at rest at the thesis cycle's
///   ends, top dead centre), so the torque reduction must stay the same (to 0.01 percentage
///   point: the quadrature of the work), and it lowers both mean inertial powers, the
///   slider-crank's a little more, so the power reduction must strictly increase.
#[test]
fn bigger_displacement_is_better() {
    for rules in READINGS {
        bigger_displacement_is_better_in(rules);
    }
}

fn bigger_displacement_is_better_in(rules: MassRules) {
    let reductions = |crank, rod, bore, material| reductions_in(rules, crank, rod, bore, material);
    for ratio in [7.0 / 3.0, 3.0, 4.0, 5.0] {
        let mut last = (f64::MIN, f64::MIN);
        for crank in [0.04, 0.05, 0.06] {
            let (torque, power) = reductions(crank, ratio * crank, 2.0 * crank, STEEL);
            println!(
                "{}: rod {ratio:.2}·crank, crank {crank} m, bore 2·crank: {torque:.2} % / {power:.2} %",
                rules.name()
            );
            assert!(
                torque > last.0 && power > last.1,
                "rod {ratio}·crank, crank {crank} m: {torque:.2} % / {power:.2} % after {:?}",
                last
            );
            last = (torque, power);
        }
    }
    for rod in RODS {
        let runs: Vec<(f64, f64)> = BORES
            .iter()
            .map(|&bore| reductions(0.06, rod, bore, STEEL))
            .collect();
        for w in runs.windows(2) {
            assert!(
                (w[1].0 - w[0].0).abs() < 0.01,
                "rod {rod} m: torque reduction moved with the bore: {:?}",
                runs
            );
            assert!(
                w[1].1 > w[0].1,
                "rod {rod} m: power reduction fell with the bore: {:?}",
                runs
            );
        }
    }
}

/// (e) "The mass of the rod (steel or titanium) affects the results very little" (ch. 11.2),
/// with the thesis's pairing: the titanium rod in the cardan gear, the slider-crank's steel
/// (appendix 11.2.1). The cardan gear's J at top dead centre has no rod, so its mean torque,
/// and the torque reduction, must not move (0.01 percentage point, the quadrature); its mean
/// power rises by α·ω̄·Δm·r²/4, and "very little" is read as: less than a tenth of the
/// reduction, and less than the step to the next rod length (the rod length matters, its
/// material does not). Also, at the shortest rod, "the crank pin inertial joint force maximums
/// are approximately equal" (thesis: S 38510 N, C 37960 N, −1.4 %): within the sum of the
/// tolerances of the two forces above (5 % + 1 %) of −1.4 %.
#[test]
fn a_titanium_rod_changes_the_reductions_little() {
    for rules in READINGS {
        a_titanium_rod_changes_the_reductions_little_in(rules);
    }
}

fn a_titanium_rod_changes_the_reductions_little_in(rules: MassRules) {
    let reductions = |crank, rod, bore, material| reductions_in(rules, crank, rod, bore, material);
    let machine = |mechanism, crank, rod, bore, material| {
        machine_in(Some(rules), mechanism, crank, rod, bore, material)
    };
    let mut steps = Vec::new();
    for rod in RODS {
        let steel = reductions(0.06, rod, 0.12, STEEL);
        let titanium = reductions(0.06, rod, 0.12, TITANIUM);
        println!(
            "rod {rod} m: steel {:.2} % / {:.2} %, titanium {:.2} % / {:.2} %",
            steel.0, steel.1, titanium.0, titanium.1
        );
        assert!(
            (titanium.0 - steel.0).abs() < 0.01,
            "rod {rod} m: torque reduction steel {steel:?}, titanium {titanium:?}"
        );
        assert!(
            (steel.1 - titanium.1).abs() < 0.1 * steel.1,
            "rod {rod} m: power reduction steel {steel:?}, titanium {titanium:?}"
        );
        steps.push((steel.1, steel.1 - titanium.1));
    }
    for w in steps.windows(2) {
        let rod_step = w[1].0 - w[0].0;
        assert!(
            w[0].1.abs() < rod_step && w[1].1.abs() < rod_step,
            "titanium moves the power reduction {:.2} and {:.2} points, a rod step {rod_step:.2}",
            w[0].1,
            w[1].1
        );
    }
    let s = run(machine(S, 0.06, 0.14, 0.12, STEEL).as_ref(), 200.0, 0.0);
    let c = run(machine(C, 0.06, 0.14, 0.12, TITANIUM).as_ref(), 200.0, 0.0);
    let ratio =
        get(&c, "inertial_crank_pin_force_max") / get(&s, "inertial_crank_pin_force_max") - 1.0;
    assert!(
        (ratio + 0.014).abs() <= 0.06,
        "titanium cardan gear vs slider-crank crank-pin force {:+.1} %, thesis −1.4 %",
        100.0 * ratio
    );
}

/// The rod's scale length, the rod-volume coefficient and κ of `rules` (the constants of
/// `cardan_mechanism::mass`), and its piston per displacement.
fn constants(rules: MassRules, crank: f64, rod: f64) -> (f64, f64, f64, f64) {
    match rules {
        MassRules::RodLength => (
            rod,
            mass::ROD_VOLUME_COEFFICIENT,
            mass::ROD_LENGTH_INERTIA_COEFFICIENT,
            mass::ROD_LENGTH_PISTON_PER_DISPLACEMENT,
        ),
        MassRules::OverallLength => (
            rod + crank,
            1.0 / mass::ROD_SECTION_DIVISOR,
            mass::ROD_INERTIA_COEFFICIENT,
            mass::PISTON_MASS_PER_DISPLACEMENT,
        ),
    }
}

/// (f) How each reading scales with crank, rod and bore, in both mechanisms, in closed form
/// against the run (the cycle's quadrature: 10⁻⁴ relative):
/// - slider-crank: J(TDC) = J_crankshaft(r) + (κ·m·L² + m·(l/2)²)·(r/l)², m = ρ·c·L³, L = l
///   (rod_length) or l + r (overall_length), J_crankshaft = ½·ρ·π·r²·2r·(r + 30 mm)²; the mean
///   inertial torque is α·J(TDC). In the rod_length reading the rod's share is
///   (κ + ¼)·ρ·c·l³·r²: at a given crank it grows as l³, where the overall_length one grows
///   as (l + r)³·(κ·(l + r)² + l²/4)/l²;
/// - cardan gear: J(TDC) = J_crankshaft(r) + J_wheel(r) (this project's sign), no rod, no bore;
///   the crank-pin force at α = 0 is 2·(m + k·π/4·d²·2r)·r·ω²: with the bore it grows by the
///   piston only, with the rod as L³;
/// - the bore changes neither mean torque (the piston is at rest at top dead centre).
#[test]
fn the_readings_scale_with_rod_and_bore_as_stated() {
    let alpha = 100.0 * PI;
    let w: f64 = 200.0 * PI;
    let machines = [
        (0.06, 0.14, 0.12),
        (0.06, 0.14, 0.09),
        (0.05, 0.15, 0.10),
        (0.04, 0.16, 0.08),
        (0.04, 0.16, 0.12),
        (0.06, 0.24, 0.12),
        (0.046, 0.229, 0.069),
    ];
    for rules in READINGS {
        for (r, l, d) in machines {
            let (length, c, kappa, k) = constants(rules, r, l);
            let m = STEEL.density() * c * length.powi(3);
            let rod_share = (kappa * m * length * length + m * (l / 2.0).powi(2)) * (r / l).powi(2);
            if rules == DEFAULT {
                let closed = (kappa + 0.25) * STEEL.density() * c * l.powi(3) * r * r;
                assert!((rod_share / closed - 1.0).abs() < 1e-12);
            }
            let j_s = crankshaft_inertia(r) + rod_share;
            let j_c = crankshaft_inertia(r) + cardan_wheel_inertia(r);
            let piston = k * PI / 4.0 * d * d * 2.0 * r;
            let moving = Pair::new_in(Some(rules), r, l, d, STEEL, 3.0, 100.0);
            let steady = Pair::new_in(Some(rules), r, l, d, STEEL, 200.0, 0.0);
            let what = format!("{} r {r} l {l} d {d}", rules.name());
            within(
                &format!("{what}: S mean torque"),
                get(&moving.s, "inertial_torque_mean"),
                alpha * j_s,
                1e-4,
            );
            within(
                &format!("{what}: C mean torque"),
                get(&moving.c, "inertial_torque_mean"),
                alpha * j_c,
                1e-4,
            );
            within(
                &format!("{what}: C crank-pin force"),
                get(&steady.c, "inertial_crank_pin_force_max"),
                2.0 * (m + piston) * r * w * w,
                1e-4,
            );
        }
        // The rod's share of the slider-crank's J(TDC) from the 0.06/0.14 m machine to the
        // 0.04/0.16 m one (l + r the same): as l³·r² in rod_length; in overall_length the same
        // rod, so only (r/l)² and the centre-of-gravity term (l/2)² change.
        let share = |r: f64, l: f64| {
            let p = Pair::new_in(Some(rules), r, l, 2.0 * r, STEEL, 3.0, 100.0);
            get(&p.s, "inertial_torque_mean") / alpha - crankshaft_inertia(r)
        };
        let ratio = share(0.04, 0.16) / share(0.06, 0.14);
        let expected = match rules {
            MassRules::RodLength => (0.16f64 / 0.14).powi(3) * (0.04f64 / 0.06).powi(2),
            MassRules::OverallLength => {
                let (kappa, ell) = (mass::ROD_INERTIA_COEFFICIENT, 0.2f64);
                (kappa * ell * ell + 0.08f64.powi(2)) / (kappa * ell * ell + 0.07f64.powi(2))
                    * ((0.04f64 / 0.16) / (0.06f64 / 0.14)).powi(2)
            }
        };
        within(
            &format!("{}: rod share ratio", rules.name()),
            ratio,
            expected,
            2e-4,
        );
    }
}

/// (g) Where the readings part, against the thesis (docs/mass-rules.md). Both readings are
/// fixed to the same published values of the 0.06/0.14 m machine, so there they agree (0.1
/// percentage point, the rounding of their constants). Elsewhere the rod_length reading's rod
/// grows with l alone: on the thesis's smaller machines with longer rods (0.05/0.15 m and
/// 0.04/0.16 m, where l + r, and so the overall_length rod, is the same as on the 0.06/0.14 m
/// machine) it gives the larger reductions, the direction the thesis's own tables for those
/// machines take; on the long rods of the big cranks it passes the thesis's stated bounds:
/// the 0.24 m rod on the 0.06 m crank above "10...30 %" (ch. 11.2), the 5·crank machine of
/// ch. 11.7 above "≤ 28 %". The overall_length reading meets those bounds (tests (b), (c)).
#[test]
fn where_the_readings_part() {
    let both = |r, l, d| {
        (
            reductions_in(DEFAULT, r, l, d, STEEL),
            reductions_in(OVERALL, r, l, d, STEEL),
        )
    };
    let (a, b) = both(0.06, 0.14, 0.12);
    println!("0.06/0.14/0.12: rod_length {a:.1?}, overall_length {b:.1?}");
    assert!((a.0 - b.0).abs() < 0.1 && (a.1 - b.1).abs() < 0.1);
    for (r, l, d) in [(0.05, 0.15, 0.10), (0.04, 0.16, 0.08)] {
        let (a, b) = both(r, l, d);
        println!("{r}/{l}/{d}: rod_length {a:.1?}, overall_length {b:.1?}");
        assert!(a.0 > b.0 && a.1 > b.1, "{r}/{l}: {a:?} {b:?}");
    }
    let (a, b) = both(0.06, 0.24, 0.12);
    println!("0.06/0.24/0.12: rod_length {a:.1?}, overall_length {b:.1?}");
    assert!(a.0 > 30.5 && b.0 <= 30.5);
    let (a, b) = both(0.046, 0.229, 0.069);
    println!("0.046/0.229/0.069: rod_length {a:.1?}, overall_length {b:.1?}");
    assert!(a.0 > 30.0 && b.0 < 30.0);
}
