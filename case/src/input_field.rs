//! The case-file field of each physics input an error names (issue 37): the mechanisms'
//! [`cardan_mechanism::Input`], the stages' [`cardan_dynamics::SetupInput`] (a loss model's
//! parameter and attachment, a gear pair's input, an engine's pressures), the balancing
//! devices' [`cardan_balance::Device`]. The physics crates
//! name the input; this module alone knows where a case file gives it, one exhaustive match
//! per kind of input, so that a field renamed in the case file is renamed here.

use cardan_balance::Device;
use cardan_dynamics::loss_models::Attachment;
use cardan_dynamics::{EngineInput, GearInput, LossParameter, SetupInput};
use cardan_mechanism::Input;

/// The field of the mechanism input `input`, as a case file's path: a mechanism's option is
/// in the table named after the mechanism.
pub(crate) fn mechanism_field(input: Input) -> String {
    match input {
        Input::CrankLength => "geometry.crank_length".into(),
        Input::RodLength => "geometry.rod_length".into(),
        Input::PinOffset => "geometry.pin_offset".into(),
        Input::RodCg => "masses.rod_cg".into(),
        Input::Steps => "motion.steps".into(),
        Input::Option { mechanism, name } => format!("{mechanism}.{name}"),
    }
}

/// The field of the stage input `input`, as a case file's path.
pub(crate) fn setup_field(input: SetupInput) -> String {
    match input {
        SetupInput::Bore => "geometry.bore".into(),
        SetupInput::Parameter(p) => format!("friction.{}", parameter_field(p)),
        SetupInput::Model(a) => format!("friction.{}", attachment_field(a)),
        SetupInput::Gear(g) => gear_field(g).into(),
        SetupInput::Engine(e) => engine_field(e).into(),
    }
}

/// The field of the engine input `input`.
fn engine_field(input: EngineInput) -> &'static str {
    match input {
        // No case sets these two (the engine takes the standard atmosphere and Bishop's
        // full-load back pressure, `EngineLosses::off`), and `[friction]` has no field of
        // them: the table whose engine components read them.
        EngineInput::AmbientPressure | EngineInput::ExhaustBackPressure => "friction",
        EngineInput::IntakePressure => "friction.intake_pressure",
        EngineInput::CompressionRatio => "gas.compression_ratio",
    }
}

/// The field of the balancing device `device`.
pub(crate) fn device_field(device: Device) -> &'static str {
    match device {
        Device::Counterweight => "balance.counterweight",
        Device::CardanCounterweights => "balance.cardan_counterweights",
    }
}

/// The field of `[friction]` that sets the loss-model parameter `parameter`.
pub(crate) fn parameter_field(parameter: LossParameter) -> &'static str {
    match parameter {
        LossParameter::RingFrictionCoefficient => "ring_friction_coefficient",
        LossParameter::RingCrownHeight => "ring_crown_height",
        LossParameter::SkirtFrictionCoefficient => "skirt_friction_coefficient",
        LossParameter::SkirtLength => "skirt_length",
        LossParameter::SkirtClearance => "skirt_clearance",
        LossParameter::LubricationFactor => "lubrication_factor",
        LossParameter::BearingLoadConstant => "bearing_load_constant",
        LossParameter::JournalLengthRatio => "journal_length_ratio",
        LossParameter::JournalClearanceRatio => "journal_clearance_ratio",
        LossParameter::CamFrictionCoefficient => "cam_friction_coefficient",
    }
}

/// The field of `[friction]` that chooses the model of the attachment `attachment`.
pub(crate) fn attachment_field(attachment: Attachment) -> &'static str {
    match attachment {
        Attachment::Rings => "rings",
        Attachment::Skirt => "skirt",
        Attachment::Bearing => "bearings",
        Attachment::GearMesh => "gear_mesh",
        Attachment::ValveTrain => "valve_train",
    }
}

/// The field of the gear input `input` (`[gear]` itself for the pair as a whole).
fn gear_field(input: GearInput) -> &'static str {
    match input {
        GearInput::Pair => "gear",
        GearInput::Teeth => "gear.teeth",
        GearInput::RingAddendum => "gear.ring_addendum",
        GearInput::FaceWidth => "gear.face_width",
        GearInput::Hardness => "gear.hardness",
        GearInput::YoungsModulus => "gear.youngs_modulus",
        GearInput::ToothLoad => "gear.tooth_load",
        GearInput::J => "gear.j",
        GearInput::AccuracyGrade => "gear.accuracy_grade",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::Value;

    /// The node of the case's JSON Schema at the dotted `path`, following `$ref`s, the
    /// `anyOf` of an optional table and the `allOf` of `if`/`then` of a table by model (`[gas]`).
    fn node<'a>(schema: &'a Value, path: &str) -> Option<&'a Value> {
        fn resolve<'a>(root: &'a Value, mut v: &'a Value) -> Vec<&'a Value> {
            while let Some(r) = v.get("$ref").and_then(Value::as_str) {
                match root.pointer(r.trim_start_matches('#')) {
                    Some(target) => v = target,
                    None => return Vec::new(),
                }
            }
            let mut out = vec![v];
            for key in ["anyOf", "oneOf", "allOf"] {
                for alt in v.get(key).and_then(Value::as_array).into_iter().flatten() {
                    out.extend(resolve(root, alt));
                }
            }
            for key in ["then", "else"] {
                if let Some(branch) = v.get(key) {
                    out.extend(resolve(root, branch));
                }
            }
            out
        }
        let mut here = vec![schema];
        for segment in path.split('.') {
            here = here
                .into_iter()
                .flat_map(|v| resolve(schema, v))
                .filter_map(|v| v.get("properties")?.get(segment))
                .collect();
        }
        here.first().copied()
    }

    /// Every physics input maps to a field the case file has: a field renamed in the case
    /// cannot leave a stale mapping.
    #[test]
    fn every_input_maps_to_a_field_of_the_schema() {
        let schema = crate::json_schema::case_schema();
        let fields = (Input::all().into_iter().map(mechanism_field))
            .chain(SetupInput::all().into_iter().map(setup_field))
            .chain(Device::ALL.into_iter().map(|d| device_field(d).to_string()));
        let mut n = 0;
        for field in fields {
            assert!(
                node(&schema, &field).is_some(),
                "{field} is not in the case's schema"
            );
            n += 1;
        }
        assert!(n > 30, "{n} inputs");
        // The resolver is not blind: a missing field is missing.
        assert!(node(&schema, "geometry.crank_lenght").is_none());
        assert!(node(&schema, "gear.face_width").is_some());
    }

    /// The mapping is the one the case file's messages always used.
    #[test]
    fn fields_are_the_case_files_paths() {
        assert_eq!(mechanism_field(Input::RodCg), "masses.rod_cg");
        // A mechanism's option is in the table named after the mechanism.
        for entry in cardan_mechanism::MECHANISMS {
            for option in entry.options {
                let input = Input::Option {
                    mechanism: entry.name,
                    name: option.name,
                };
                let field = format!("{}.{}", entry.name, option.name);
                assert_eq!(mechanism_field(input), field);
            }
        }
        let crown = SetupInput::Parameter(LossParameter::RingCrownHeight);
        assert_eq!(setup_field(crown), "friction.ring_crown_height");
        let bearings = SetupInput::Model(Attachment::Bearing);
        assert_eq!(setup_field(bearings), "friction.bearings");
        let j = SetupInput::Gear(GearInput::J);
        assert_eq!(setup_field(j), "gear.j");
    }
}
