//! Case-file text that several test files start from, so that a change of the schema is made
//! once. Most are the thesis air pump (Karhula 2008, ch. 11: crank 60 mm, rod 140 mm, bore
//! 120 mm, both mechanisms, one pump cycle from 90° to 810°); tests edit the text with
//! `replace` and append tables to it. [`kinematic_optimization`] is the optimisation with a
//! closed-form optimum (issue 40) that the runner's and the command line's tests run.

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

/// The kinematic optimisation (`[optimize]`, issue 40), named "kinematic": a slider-crank of
/// crank r = 50 mm at ω = 100 rad/s, no gas, one revolution in 360 steps; the peak piston
/// acceleration minimised over the rod length l ∈ [150, 400] mm subject to `constraint`, with
/// `extra` lines appended to its `[optimize]` table. For a centred slider-crank with
/// λ = r/l ≤ 1/4 the peak piston acceleration is rω²(1 + λ) and the peak rod angular speed
/// λω, both at top dead centre (Karhula 2008, A4.1.1): with "rod_angular_velocity_max >= 20
/// rad/s" (λω ≥ ω/5, l ≤ 5r) the optimum is l* = 250 mm, a_max* = 600 m/s².
pub fn kinematic_optimization(extra: &str, constraint: &str) -> String {
    format!(
        r#"
name = "kinematic"
machine = "pump"
mechanisms = ["slider_crank"]
[geometry]
crank_length = "50 mm"
rod_length = "200 mm"
bore = "80 mm"
[motion]
start_angle = "0 deg"
end_angle = "360 deg"
initial_speed = "100 rad/s"
angular_acceleration = 0
steps = 360
[optimize]
objective = "piston_acceleration_max"
sense = "min"
variables = {{ "geometry.rod_length" = ["150 mm", "400 mm"] }}
constraints = ["{constraint}"]
{extra}
"#
    )
}
