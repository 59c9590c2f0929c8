//! The ISO 6336 rating of a case run (`[gear] standard = "both"`) against `cardan gear`'s for the
//! same pair at the same tooth load and speed: two paths to one figure, the run's per-step
//! rating (`cardan_dynamics::GearRatings`, its ISO part prepared once per mesh) and the gear
//! file's (`cardan_gear_file`, from a torque and a pinion speed, its factors read from the
//! gear file's own fields: the material table, `enclosure`, `youngs_modulus`).

use std::path::Path;

/// Karhula's pump (docs/validation/karhula-2008.md), 720 steps of a turn and a half, its cardan
/// gear rated by AGMA and ISO 6336 side by side.
fn pump_case(iso: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../configs/karhula-pump-r60-l140-a0-w30pi.toml");
    let text = std::fs::read_to_string(path).unwrap();
    let text = text.replace("steps = 7200", "steps = 720");
    format!("{text}\n[gear]\nstandard = \"both\"\n{iso}\n")
}

/// The ISO fields of the default comparison: the accuracy grade alone (every factor and
/// limit computed).
const GRADE: Iso = Iso {
    case: "accuracy_grade = 7",
    rating: "accuracy_grade = 7",
    member: "",
};

/// Every override a case file takes (K_v, K_Hα, K_Hβ, σ_Hlim, σ_Flim per member), which
/// replace the accuracy grade's factors and the material's limits: the gear file's fields of
/// the same names.
const OVERRIDES: Iso = Iso {
    case: "iso_dynamic_factor = 1.15\ntransverse_load_factor = 1.1\nface_load_factor = 1.3\n\
           sigma_hlim = \"1200 MPa\"\nsigma_flim = [\"400 MPa\", \"380 MPa\"]",
    rating: "iso_dynamic_factor = 1.15\ntransverse_load_factor = 1.1\nface_load_factor = 1.3",
    member: "sigma_hlim = \"1200 MPa\"\n",
};

/// The ISO fields of one comparison: the case's `[gear]` lines, the gear file's `[rating]`
/// lines and each member's (its `sigma_flim` added by [`gear_file`]).
struct Iso {
    case: &'static str,
    rating: &'static str,
    member: &'static str,
}

/// The gear file of the case's pair (Karhula's 20/40 internal pair of a 30 mm cardan crank,
/// ring addendum 0.8 m, the case's default face width d1/3 = 20 mm, 300 HB through-hardened
/// steel MQ, E = 210 GPa and ν = 0.3 as the case's, AGMA's precision enclosure as the run's
/// Km) carrying `torque` (N·m) at `pinion_speed` (rad/s), rated on the ISO basis.
fn gear_file(torque: f64, pinion_speed: f64, iso: &Iso) -> String {
    let member = format!(
        "material = \"steel-through-hardened\"\nhardness = 300\n\
         youngs_modulus = \"210 GPa\"\npoisson_ratio = 0.3\n{}",
        iso.member
    );
    let sigma_flim = |s: &str| match iso.member {
        "" => String::new(),
        _ => format!("sigma_flim = \"{s}\"\n"),
    };
    format!(
        "name = \"pair\"\ncardan_crank_length = \"30 mm\"\npressure_angle = \"20 deg\"\n\
         teeth = [20, -40]\naddendum_coefficient = [1.0, 0.8]\nface_width = \"20 mm\"\n\
         [rating]\ntorque = {torque:e}\npinion_speed = {pinion_speed:e}\nquality = 8\n\
         enclosure = \"precision\"\npinion_cycles = 1e7\nbasis = \"iso6336\"\n{}\n\
         [rating.pinion]\n{member}{}[rating.gear]\n{member}{}",
        iso.rating,
        sigma_flim("400 MPa"),
        sigma_flim("380 MPa")
    )
}

/// A number of summary.json's metrics of the one mechanism that has it.
fn summary_metric(json: &str, name: &str) -> f64 {
    let key = format!("\"{name}\":");
    let at = json
        .find(&key)
        .unwrap_or_else(|| panic!("summary lacks {name}"))
        + key.len();
    let rest = &json[at..];
    let end = rest.find([',', '\n', '}']).unwrap();
    rest[..end].trim().parse().unwrap()
}

#[test]
fn a_run_s_iso_rating_at_a_step_is_cardan_gear_s_at_that_load_and_speed() {
    let computed = compare(&GRADE);
    // The overrides are read: every figure moves with them.
    let given = compare(&OVERRIDES);
    for (a, b) in computed.iter().zip(&given) {
        assert!(
            (a - b).abs() > 1e-3 * a.abs(),
            "{computed:?} against {given:?}"
        );
    }
}

/// Runs the pump case with the ISO fields `iso`, and checks its ISO stresses and safety factors
/// at their peak steps against `cardan gear`'s for the same pair, load and speed; returns the
/// run's [contact, bending] safety factors.
fn compare(iso: &Iso) -> Vec<f64> {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("pump.toml");
    std::fs::write(&file, pump_case(iso.case)).unwrap();
    let out = dir.path().join("out");
    let report = cardan_runner::run_paths(&[file], &out, Default::default());
    assert!(report.failures.is_empty(), "{:#?}", report.failures);
    let case = out.join("karhula-pump-r60-l140-a0-w30pi");
    let csv = std::fs::read_to_string(case.join("cardan_gear.csv")).unwrap();
    let summary = std::fs::read_to_string(case.join("summary.json")).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| {
        header
            .iter()
            .position(|c| *c == name)
            .unwrap_or_else(|| panic!("no column {name}"))
    };
    let (load, speed) = (
        col("total_gear_mesh_tangential_n"),
        col("gear_mesh_speed_m_s"),
    );
    let (sigma_h, sigma_f) = (
        col("gear_mesh_iso_contact_stress_pa"),
        col("gear_mesh_iso_bending_stress_pa"),
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| {
            l.split(',')
                .map(|x| x.parse().unwrap_or(f64::NAN))
                .collect()
        })
        .collect();
    // The steps of the largest ISO contact and root stresses: there the run's smallest safety
    // factors are (σ_HG and σ_FG do not change with the step, the load factors are common to
    // both members).
    let peak = |c: usize| {
        (0..rows.len())
            .max_by(|&a, &b| rows[a][c].total_cmp(&rows[b][c]))
            .unwrap()
    };
    // The wheel's pitch radius: the cardan crank, half the slider-crank's 60 mm (the module
    // 2·30 mm/20 = 3 mm of the gear file, Karhula A9.1.37).
    let r = 0.03;
    let mut factors = Vec::new();
    for (row, stress, safety, what) in [
        (
            peak(sigma_h),
            sigma_h,
            "iso_contact_safety_factor",
            "contact",
        ),
        (
            peak(sigma_f),
            sigma_f,
            "iso_bending_safety_factor",
            "bending",
        ),
    ] {
        let (f, v) = (rows[row][load].abs(), rows[row][speed].abs());
        assert!(
            f > 1e3 && v > 1.0,
            "{what}: a loaded, turning step ({f} N, {v} m/s)"
        );
        let text = gear_file(f * r, v / r, iso);
        let gear = cardan_gear_file::parse(Path::new("pair.toml"), &text).unwrap();
        let rated = cardan_gear_file::evaluate(&gear).unwrap();
        let iso = rated.iso.expect("the ISO rating").unwrap();
        let (gear_stress, gear_safety) = match what {
            "contact" => (
                iso.sigma_h[0].max(iso.sigma_h[1]),
                iso.s_h[0].min(iso.s_h[1]),
            ),
            _ => (
                iso.sigma_f[0].max(iso.sigma_f[1]),
                iso.s_f[0].min(iso.s_f[1]),
            ),
        };
        // The same functions on the same inputs: the load and speed only pass through the
        // gear file's torque F·r and pinion speed v/r (and its module 2·e/z1), a few roundings
        // apart; 1e-9 relative leaves room for those and for nothing else.
        let run_stress = rows[row][stress];
        let run_safety = summary_metric(&summary, safety);
        for (q, a, b) in [
            ("stress", run_stress, gear_stress),
            ("safety factor", run_safety, gear_safety),
        ] {
            assert!(
                (a - b).abs() <= 1e-9 * b.abs(),
                "{what} {q}: run {a}, cardan gear {b}"
            );
        }
        // The ISO figures stand beside AGMA's, which the run still gives.
        let agma = match what {
            "contact" => "contact_safety_factor",
            _ => "bending_safety_factor",
        };
        assert!(summary_metric(&summary, agma) > 0.0);
        factors.push(run_safety);
    }
    factors
}
