//! `[gear]` in a case: every gear mesh rated at every step (summary metrics, CSV columns), and
//! bad gear fields named with their rule.

use cardan_case::case::parse;
use cardan_runner::run_case;
use std::path::Path;

fn pump(extra: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../configs/karhula-pump-r60-l140-a0-w30pi.toml");
    format!("{}\n{extra}", std::fs::read_to_string(path).unwrap())
}

#[test]
fn the_cardan_mesh_is_rated_at_every_step() {
    let case = parse(Path::new("pump.toml"), &pump("[gear]\nj = [0.32, 0.45]\n")).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let results = run_case(&case, Some(dir.path())).unwrap();
    let cardan = results
        .iter()
        .find(|r| r.summary.get("dynamic_tooth_load_max").is_some())
        .expect("the mechanism with a gear mesh is rated");
    let get = |k: &str| cardan.summary.get(k).unwrap();
    // Karhula's pair, ring addendum 0.8 modules: εα = 1.765 (configs-gears/karhula-cardan-20-40).
    assert!((get("contact_ratio") - 1.765).abs() < 5e-4);
    // The rated load is the tangential mesh load the loads summary already reports.
    assert_eq!(
        get("mesh_tangential_load_max"),
        get("total_gear_mesh_tangential_max")
    );
    assert!(get("dynamic_tooth_load_max") > get("mesh_tangential_load_max"));
    for k in [
        "contact_stress_max",
        "contact_safety_factor",
        "bending_stress_max",
        "bending_safety_factor",
        "gear_mesh_power_loss_mean",
    ] {
        assert!(get(k).is_finite() && get(k) > 0.0, "{k} = {}", get(k));
    }
    // A mechanism without a mesh gets no gear metrics.
    assert!(results
        .iter()
        .any(|r| r.summary.get("contact_ratio").is_none()));
    let name = cardan.mechanism.name();
    let text = std::fs::read_to_string(dir.path().join(format!("{name}.csv"))).unwrap();
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    for c in [
        "gear_mesh_dynamic_tooth_load_n",
        "gear_mesh_contact_stress_pa",
        "gear_mesh_bending_stress_pa",
    ] {
        assert!(header.contains(&c), "{c}");
    }
    let k = header
        .iter()
        .position(|c| *c == "gear_mesh_dynamic_tooth_load_n")
        .unwrap();
    let peak = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(k).unwrap().parse::<f64>().unwrap())
        .fold(0.0, f64::max);
    assert!((peak - get("dynamic_tooth_load_max")).abs() <= 1e-9 * peak);
}

#[test]
fn bad_gear_fields_are_named() {
    for (extra, field, rule) in [
        (
            "[gear]\ntooth_load = \"peak\"\n",
            "gear.tooth_load",
            "ring_force",
        ),
        ("[gear]\nhardness = 500\n", "gear.hardness", "140 to 400"),
        (
            "[gear]\nring_addendum = 1.0\n",
            "gear.ring_addendum",
            "shorten the ring addendum",
        ),
        ("[gear]\nteeth = 20.5\n", "gear.teeth", "whole number"),
        ("[gear]\nmodule = 3\n", "gear.module", "unknown field"),
        // Karhula's reading needs his mesh force, which the involute reading does not have.
        (
            "[gear]\ntooth_load = \"thesis\"\n[cardan_gear]\ngear_mesh_model = \"involute\"\n",
            "gear.tooth_load",
            "rate it with \"tangential\"",
        ),
    ] {
        let e = parse(Path::new("pump.toml"), &pump(extra))
            .unwrap_err()
            .to_string();
        assert!(e.contains(field) && e.contains(rule), "{extra}: {e}");
    }
    // A case whose mechanisms have no gear mesh cannot rate one.
    let text = pump("[gear]\n").replace(
        "mechanisms = [\"slider_crank\", \"cardan_gear\"]",
        "mechanisms = [\"slider_crank\"]",
    );
    let e = parse(Path::new("pump.toml"), &text)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("no mechanism of the case has a gear mesh"),
        "{e}"
    );
}

#[test]
fn carburized_gears_raise_the_safety_factors_by_their_allowables() {
    // Same loads and stresses; the pitting safety factor scales with Sc: carburized grade 2
    // 225 000 psi against through-hardened grade 2 at 300 HB, 349·300 + 34 300 = 139 000 psi
    // (AGMA 2001-D04 Table 4, Fig. 8).
    let safety = |extra: &str| {
        let case = parse(Path::new("pump.toml"), &pump(extra)).unwrap();
        run_case(&case, None)
            .unwrap()
            .iter()
            .find_map(|r| r.summary.get("contact_safety_factor"))
            .unwrap()
    };
    let through = safety("[gear]\n");
    let carburized = safety("[gear]\nmaterial = \"carburized\"\n");
    let ratio = carburized / through;
    assert!((ratio - 225_000.0 / 139_000.0).abs() < 1e-9, "{ratio}");
    let e = parse(
        Path::new("pump.toml"),
        &pump("[gear]\nmaterial = \"cast iron\"\n"),
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.contains("gear.material") && e.contains("carburized"),
        "{e}"
    );
}

/// With `[friction]` and `[gear]`, the loss budget's mesh component and the rating's mesh loss
/// are one figure (computed once, by the rating) in every tooth-load reading and for single and
/// twin sets: the loss is charged on the tangential load, shared by the sets; and the budget
/// alone gives the same figure for the same pair (issue "Gears", review finding).
#[test]
fn the_mesh_loss_of_the_budget_and_of_the_rating_agree() {
    let mut losses = Vec::new();
    for gear in [
        "[gear]\n",
        "[gear]\ntwin = true\n",
        "[gear]\ntwin = true\ntooth_load = \"ring_force\"\n",
        "[gear]\ntooth_load = \"thesis\"\n",
    ] {
        let text = pump(&format!("[friction]\n{gear}"));
        let case = parse(Path::new("pump.toml"), &text).unwrap();
        let results = run_case(&case, None).unwrap();
        let cardan = results
            .iter()
            .find(|r| r.summary.get("gear_mesh_power_loss_mean").is_some())
            .unwrap();
        let rating = cardan.summary.get("gear_mesh_power_loss_mean").unwrap();
        let budget = cardan.summary.get("power_loss_mean_gear_mesh").unwrap();
        assert!(rating > 0.0);
        assert!(
            (rating / budget - 1.0).abs() < 1e-12,
            "{gear}: rating {rating} W, budget {budget} W"
        );
        losses.push(rating);
    }
    // The budget takes a rated mesh's loss from the rating; on its own (no [gear]) it computes
    // the same figure for the same single pair: the two are one model.
    let alone = parse(Path::new("pump.toml"), &pump("[friction]\n")).unwrap();
    let budget_alone = run_case(&alone, None)
        .unwrap()
        .iter()
        .find_map(|r| r.summary.get("power_loss_mean_gear_mesh"))
        .unwrap();
    assert!(
        (budget_alone / losses[0] - 1.0).abs() < 1e-12,
        "budget alone {budget_alone} W, rating {} W",
        losses[0]
    );
    // The twin sets are charged as two sets at half the load each, not as one set.
    eprintln!("mesh loss: single {} W, twin {} W", losses[0], losses[1]);
    assert!((losses[1] / losses[0] - 1.0).abs() > 1e-3);
    // The rated load does not change the loss: ring-force rating, same loss as tangential.
    assert_eq!(losses[1], losses[2]);
    assert_eq!(losses[0], losses[3]);
}
