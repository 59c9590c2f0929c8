//! Case-file text that several test files start from, so that a change of the schema is made
//! once. Each is the thesis air pump (Karhula 2008, ch. 11: crank 60 mm, rod 140 mm, bore
//! 120 mm, both mechanisms, one pump cycle from 90° to 810°); tests edit the text with
//! `replace` and append tables to it.

/// The pump at 628.3185307 rad/s (6000 rpm) over 720 steps, inertial loads only, every value a
/// bare SI number; named "good".
pub const THESIS_PUMP: &str = r#"
name = "good"
machine = "pump"
mechanisms = ["slider_crank", "cardan_gear"]
[geometry]
crank_length = 0.06
rod_length = 0.14
bore = 0.12
[motion]
start_angle = 90.0
end_angle = 810.0
initial_speed = 628.3185307
angular_acceleration = 0.0
steps = 720
"#;

/// The pump named `name` at 900 rpm over 1441 steps (an odd count, so that decimation leaves a
/// remainder) with its gas (`karhula_pump`, ε = 12, n = 1.4), the default loss models and
/// gear rating, every value with its unit; ends inside no table, so that tests may append
/// `[output]`.
pub fn loaded_thesis_pump(name: &str) -> String {
    format!(
        r#"
name = "{name}"
machine = "pump"
mechanisms = ["slider_crank", "cardan_gear"]
[geometry]
crank_length = "60 mm"
rod_length = "140 mm"
bore = "120 mm"
[motion]
start_angle = "90 deg"
end_angle = "810 deg"
initial_speed = "94.24777960769379 rad/s"
angular_acceleration = 0.0
steps = 1441
[gas]
model = "karhula_pump"
compression_ratio = 12
polytropic_exponent = 1.4
[friction]
[gear]
"#
    )
}
