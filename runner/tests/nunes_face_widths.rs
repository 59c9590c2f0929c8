//! Nunes (2017) Table 4.11 end to end (issue "Gears"): the 24 required face widths of the
//! single cardan gear set, derived from the project's own closed-cycle OPGHE runs with no
//! calibration. Procedure of the thesis (§4.4.3, docs/validation/nunes-2017.md):
//! at every speed of the 0–8000 rpm sweep the peak gear-tooth load F_gt(N) (eq 2.75) times each
//! member's dynamic factor Kv(N) (eqs 4.25–4.29, own pitch diameter, crank rpm) sizes
//! FW_bend = F_gt Kv Km / (m σFP J) and FW_cont = F_gt Kv Km Z_E² / (d I σHP²) with d the
//! member's own pitch diameter; the table prints the maximum over speed, i.e. the maximum of
//! the product F_gt·Kv (not F_gt,max·Kv,max, which is 4 % higher). Pitch diameters 26/52 mm for
//! every row, so the 26/52-teeth rows have m = 1 mm and the 52/104-teeth rows m = 0.5 mm.

use cardan_case::case;
use cardan_gears::agma::nunes;
use cardan_gears::*;
use cardan_runner::run_case;
use std::path::Path;

/// The peak tangential gear-tooth load of the OPGHE (the shipped Nunes case, cardan gear only)
/// at `rpm`, sampled on the thesis's 1° crank-angle grid (720 steps over the 720° cycle): the
/// thesis evaluates its dynamics at the 1° steps of its gas model (extraction §5.1), and a
/// finer grid finds the peak of F_t·sin θ between them, 0.02–0.03 % higher near 2700–3000 rpm.
fn f_gt(rpm: f64) -> f64 {
    let file =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs/nunes-op-r26-l90-2000rpm.toml");
    let text = std::fs::read_to_string(&file)
        .unwrap()
        .replace(
            "initial_speed = \"2000 rpm\"",
            &format!("initial_speed = \"{rpm} rpm\""),
        )
        .replace("steps = 7200", "steps = 720")
        .replace(
            "mechanisms = [\"slider_crank\", \"cardan_gear\"]",
            "mechanisms = [\"cardan_gear\"]",
        );
    assert!(text.contains(&format!("\"{rpm} rpm\"")) && text.contains("steps = 720"));
    let runs = run_case(&case::parse(&file, &text).unwrap(), None).unwrap();
    assert_eq!(runs.len(), 1);
    runs[0]
        .summary
        .get("total_gear_mesh_tangential_max")
        .unwrap()
}

/// Table 4.8 as printed (4 decimals): (shift, zp, zg, module, I, JP, JG). Nunes sized with
/// these rounded values: the load-free ratio of each member's contact to bending width in
/// Table 4.11 gives back I = 0.11680 for the x = 0, 26/52 row, not the unrounded 0.11675.
const TABLE_4_8: [(ShiftCase, i32, i32, f64, f64, f64, f64); 6] = [
    (ShiftCase::Zero, 26, 52, 1e-3, 0.1168, 0.4385, 0.4855),
    (ShiftCase::Zero, 52, 104, 0.5e-3, 0.1190, 0.5153, 0.5382),
    (ShiftCase::Quarter, 26, 52, 1e-3, 0.1233, 0.4900, 0.4440),
    (ShiftCase::Quarter, 52, 104, 0.5e-3, 0.1222, 0.5516, 0.5043),
    (ShiftCase::Half, 26, 52, 1e-3, 0.1278, 0.5385, 0.4010),
    (ShiftCase::Half, 52, 104, 0.5e-3, 0.1246, 0.5770, 0.4704),
];

/// Table 4.11 (mm): bending pinion, bending gear, contact pinion, contact gear.
const TABLE_4_11: [[f64; 4]; 6] = [
    [62.68, 52.45, 85.18, 39.46],
    [106.68, 94.62, 83.61, 38.73],
    [56.09, 57.35, 80.69, 37.38],
    [99.66, 100.98, 81.42, 37.71],
    [51.04, 63.50, 77.85, 36.06],
    [95.27, 108.26, 79.85, 36.99],
];

#[test]
fn nunes_table_4_11_face_widths_from_the_closed_cycle() {
    let (dp, dg) = (0.026, 0.052);
    // Speed points bracketing the maxima of F_gt·Kv (pinion 2740 rpm, gear 3040 rpm on the
    // thesis's 10 rpm grid over 10–8000 rpm; this 100 rpm grid loses 0.001 %).
    let mut best = [(0.0, 0.0); 2];
    for rpm in (24..=32).map(|k| 100.0 * k as f64) {
        let f = f_gt(rpm);
        for (b, d) in best.iter_mut().zip([dp, dg]) {
            let p = f * nunes::dynamic_factor_member(6.0, d, rpm).unwrap().kv;
            if p > b.0 {
                *b = (p, rpm);
            }
        }
    }
    let [(pp, np), (pg, ng)] = best;
    // The thesis's peak gear-tooth load, 9368.4 N at 2360 rpm (0.1 %, the for peaks).
    cardan_testing::within("F_gt at 2360 rpm", f_gt(2360.0), 9368.4, 1e-3);
    assert!(
        2400.0 < np && np < 3200.0 && 2400.0 < ng && ng < 3200.0,
        "{np} {ng}"
    );

    let kmp = nunes::load_distribution_factor(0.052, dp, 1.1, 0.8).unwrap();
    let kmg = nunes::load_distribution_factor(0.052, dg, 1.0, 0.8).unwrap();
    let sfp = nunes::nitralloy_grade2_bending_allowable(415.0).unwrap();
    let shp = 1300e6;
    let ze = elastic_coefficient(200e9, 0.3, 200e9, 0.3).unwrap();
    eprintln!("max F_gt·Kv: pinion {pp:.2} N at {np} rpm, gear {pg:.2} N at {ng} rpm");
    eprintln!("row         bend P       bend G       cont P       cont G   | internal cont P/G");
    let mut worst: f64 = 0.0;
    for ((case, zp, zg, m, i, jp, jg), printed) in TABLE_4_8.into_iter().zip(TABLE_4_11) {
        let e = agma908_table(case, zp as u32, zg as u32).unwrap();
        // The interpolation reproduces the printed Table 4.8 to one unit of its last digit
        // (0.470456 is printed 0.4704; the table cells need 0.4704, 0.470456 would put the
        // x = 0.5, 52/104 gear bending width 0.03 mm higher).
        for (a, b) in [(e.i, i), (e.jp, jp), (e.jg, jg)] {
            assert!((a - b).abs() <= 1e-4, "{case:?} {zp}: {a} vs {b}");
        }
        let got = [
            nunes::bending_face_width(pp, 1.0, kmp, m, sfp, jp),
            nunes::bending_face_width(pg, 1.0, kmg, m, sfp, jg),
            nunes::contact_face_width(pp, 1.0, kmp, ze, dp, i, shp),
            nunes::contact_face_width(pg, 1.0, kmg, ze, dg, i, shp),
        ];
        // Correct internal reading of the contact widths: internal LPSTC I of the pair
        // zp / −zg and the pinion pitch diameter for both members (same loads, Kv, Km).
        let x = match case {
            ShiftCase::Zero => 0.0,
            ShiftCase::Quarter => 0.25,
            ShiftCase::Half => 0.5,
        };
        let pair = GearPair::new(PairSpec::standard(m, zp, -zg, 25f64.to_radians(), x, -x));
        let i_int = pitting_geometry_factor(&pair.unwrap(), IForm::Lpstc).unwrap();
        let internal = [
            nunes::contact_face_width(pp, 1.0, kmp, ze, dp, i_int, shp),
            nunes::contact_face_width(pg, 1.0, kmg, ze, dp, i_int, shp),
        ];
        let mut line = format!("{x:.2} {zp:>3}/{zg:<3}");
        for (g, p) in got.iter().zip(printed) {
            let mm = g * 1e3;
            line += &format!(" {mm:7.3}({:+.3})", mm - p);
            worst = worst.max((mm - p).abs());
        }
        line += &format!(
            " | I {i_int:.4}: {:.2} {:.2}",
            internal[0] * 1e3,
            internal[1] * 1e3
        );
        eprintln!("{line}");
        assert!(internal[0] < got[2] && internal[1] < got[3]);
    }
    eprintln!("worst |difference| {worst:.4} mm");
    // Tolerance 0.05 mm (the issue's): the thesis prints to ±0.005 mm, and all 24 printed
    // cells admit one load per member within ±0.003 % (pinion 9968.3–9969.0 N, gear
    // 10201.4–10202.0 N); ours is 0.012 % / 0.015 % above, the level of our F_gt against the
    // thesis's at its published speeds (+0.013 % at 2360 rpm, +0.015 % at 2000 rpm), i.e.
    // ≤ 0.02 mm on the widest cell (108 mm; observed worst 0.016 mm). The shipped 0.1° grid
    // gives 0.034 mm; the unrounded interpolated I/J instead of Table 4.8 gives 0.048 mm.
    assert!(worst <= 0.05, "{worst}");
}
