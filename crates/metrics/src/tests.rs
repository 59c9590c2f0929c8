//! The registry's tests: its lookups, its parts and its groups.

use super::*;

#[test]
fn templates_match_filled_names_only() {
    assert_eq!(find("inertial_crank_pin_force_max").unwrap().unit, "N");
    assert_eq!(find("total_piston_side_moment_max").unwrap().unit, "N*m");
    assert_eq!(
        find("rod_cg_velocity_max").unwrap().name,
        "{body}_cg_velocity_max"
    );
    assert_eq!(
        find("piston_velocity_max").unwrap().name,
        "{piston}_velocity_max"
    );
    assert_eq!(find("gas_force_max").unwrap().name, "gas_force_max");
    assert_eq!(find("gas_torque_mean").unwrap().unit, "N*m");
    assert_eq!(find("imep").unwrap().unit, "Pa");
    assert!(find("_force_max").is_none());
    assert!(find("nonsense").is_none());
    // Names are unique.
    for (k, d) in METRICS.iter().enumerate() {
        assert!(METRICS[..k].iter().all(|e| e.name != d.name), "{}", d.name);
    }
}

#[test]
fn templates_alternate_their_braces() {
    // `matches_template`'s early rejection reads the text after the last `}` as the
    // template's last fixed part: true when `{` and `}` alternate, opening first.
    for d in METRICS {
        let braces: Vec<char> = d.name.chars().filter(|c| matches!(c, '{' | '}')).collect();
        assert!(
            braces.chunks(2).all(|p| p == ['{', '}']),
            "{}: unbalanced placeholders",
            d.name
        );
    }
}

#[test]
fn the_early_rejection_changes_no_match() {
    // Every template against names filled in from every template (with the topology's
    // names and the families), and against the templates' own texts and near misses.
    let fills = [
        "inertial",
        "total",
        "gas",
        "crank_pin",
        "rod",
        "piston",
        "x",
        "a_b",
    ];
    let mut names: Vec<String> = vec!["".into(), "_".into(), "nonsense".into()];
    for d in METRICS {
        names.push(d.name.to_string());
        for f in fills {
            let mut filled = String::new();
            let mut inside = false;
            for ch in d.name.chars() {
                match ch {
                    '{' => inside = true,
                    '}' => {
                        inside = false;
                        filled.push_str(f);
                    }
                    _ if !inside => filled.push(ch),
                    _ => {}
                }
            }
            names.push(filled.clone());
            names.push(format!("{filled}_x"));
            names.push(format!("x_{filled}"));
            names.push(filled[1.min(filled.len())..].to_string());
        }
    }
    for n in &names {
        assert_eq!(
            find(n).map(|d| d.name),
            find_in(METRICS, n).map(|d| d.name),
            "{n}"
        );
    }
    let mut matched = 0;
    for d in METRICS {
        for n in &names {
            let walk = matches_by_walk(d.name, n);
            assert_eq!(matches_template(d.name, n), walk, "{} against {n}", d.name);
            matched += usize::from(walk);
        }
    }
    assert!(matched > METRICS.len(), "{matched}");
}

#[test]
fn the_iso_gear_metrics_are_the_iso_rating_s_and_the_agma_ones_are_registered() {
    assert_eq!(GEAR_RATING_ISO.len(), 4);
    for d in GEAR_RATING_ISO {
        assert!(
            d.name.starts_with("iso_") && d.meaning.contains("ISO 6336"),
            "{}",
            d.name
        );
    }
    for n in GEAR_RATING_AGMA {
        let d = find_in(GEAR_RATING, n).unwrap();
        assert!(d.meaning.contains("AGMA"), "{n}");
    }
}

#[test]
fn groups_and_directions_follow_the_meaning() {
    // Every group is used, and every metric's group and direction follow from its kind.
    for g in Group::ALL {
        assert!(METRICS.iter().any(|d| d.group == g), "{g:?} unused");
    }
    for d in METRICS {
        let n = d.name;
        let gear = d.meaning.starts_with("gear rating");
        assert_eq!(gear, d.group == Group::GearRating, "{n}");
        if d.aggregation == Aggregation::Cylinder {
            assert_eq!(d.group, Group::Gas, "{n}");
        }
        if n.starts_with("{family}_{joint}_") {
            assert_eq!(
                (d.group, d.better),
                (Group::JointLoads, Better::Lower),
                "{n}"
            );
        }
        if n.starts_with("{piston}_") || n.starts_with("{body}_") {
            assert_eq!(
                (d.group, d.better),
                (Group::Kinematics, Better::Neither),
                "{n}"
            );
        }
        if n.ends_with("efficiency")
            || n.starts_with("output_")
            || n.ends_with("_safety_factor")
            || n.starts_with("mechanical_advantage")
            || n == "contact_ratio"
        {
            assert_eq!(d.better, Better::Higher, "{n}");
        }
        if n.starts_with("power_loss")
            || n.contains("power_loss")
            || n.starts_with("fmep")
            || n.starts_with("friction_")
            || n.ends_with("_need_mean")
            || n.ends_with("_stress_max")
            || n.ends_with("_load_max")
            || n.ends_with("_torque_max") && n != "machine_torque_max"
            || n.ends_with("_error")
            || n == "loss_work"
        {
            assert_eq!(d.better, Better::Lower, "{n}");
        }
        // The whole machine's figures are its group's, whatever their kind.
        if n.starts_with("machine_") {
            assert_eq!(d.group, Group::Machine, "{n}");
        }
        if !gear
            && !n.starts_with("machine_")
            && (n.starts_with("power_loss")
                || n.starts_with("fmep")
                || n.starts_with("friction_")
                || n.ends_with("_efficiency") && d.aggregation != Aggregation::Cylinder)
        {
            assert_eq!(d.group, Group::Losses, "{n}");
        }
        // Signed sums and means of the drive are no verdict: their sign is the direction
        // of the energy flow.
        if ["_work", "_torque_mean", "_power_mean"]
            .iter()
            .any(|s| n.starts_with("{family}") && n.ends_with(s))
        {
            assert_eq!(
                (d.group, d.better),
                (Group::DriveTorque, Better::Neither),
                "{n}"
            );
        }
    }
}
