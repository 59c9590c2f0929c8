//! The stage registry (`STAGES`): each entry's stage is built where its table is and only
//! there, gives the entry's metrics, and the entries name real case-file tables, once each.

use cardan_case::stage_registry::{find, STAGES};
use std::path::Path;

const CASE: &str = r#"
name = "registry"
machine = "pump"
mechanisms = ["slider_crank", "cardan_gear"]
[geometry]
crank_length = "60 mm"
rod_length = "140 mm"
bore = "120 mm"
[motion]
start_angle = 90.0
end_angle = 450.0
initial_speed = "3000 rpm"
angular_acceleration = 0.0
steps = 72
[gas]
model = "karhula_pump"
compression_ratio = 12
polytropic_exponent = 1.4
filling = 1.07
"#;

#[test]
fn each_entry_builds_its_stage_where_its_table_is() {
    let names: Vec<&str> = STAGES.iter().map(|e| e.name).collect();
    for (i, name) in names.iter().enumerate() {
        assert!(!names[i + 1..].contains(name), "{name} registered twice");
        assert!(find(name).is_some());
    }
    let schema = cardan_case::json_schema::case_schema();
    let tables = &schema["properties"];
    for e in STAGES {
        if let Some(t) = e.table {
            assert!(tables.get(t).is_some(), "{}: no [{t}] table", e.name);
        }
    }
    let with = format!("{CASE}\n[friction]\n[gear]\n");
    for (text, tables) in [(CASE, &[][..]), (with.as_str(), &["friction", "gear"][..])] {
        let case = cardan_case::case::parse(Path::new("registry.toml"), text).unwrap();
        for (m, setup) in case.mechanisms.iter().zip(&case.setups) {
            for e in STAGES {
                let asked = e.table.is_none_or(|t| tables.contains(&t));
                // The slider-crank has no gear mesh to rate.
                let has_mesh = m.name() != "slider_crank";
                let expected = asked && (e.name != "gear_rating" || has_mesh);
                assert_eq!(setup.has_stage(e.name), expected, "{} {}", m.name(), e.name);
            }
            for (e, stage) in &setup.stages {
                assert_eq!(e.metrics, stage.metrics(), "{}", e.name);
            }
            let order: Vec<&str> = setup.stages.iter().map(|(e, _)| e.name).collect();
            let registered: Vec<&str> = names
                .iter()
                .copied()
                .filter(|n| order.contains(n))
                .collect();
            assert_eq!(order, registered, "a run's stages in the registry's order");
        }
    }
}
