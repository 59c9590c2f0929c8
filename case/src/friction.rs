//! The `[friction]` table of a case: which loss model at which piston and joint, read into
//! [`FrictionTable`] (units, signs and words checked by the schema) and built into a
//! [`Friction`] by [`build`]. Without `[friction]` a case has no losses; an empty `[friction]`
//! table is Karhula's (2008) App. 9.1 set ([`Friction::karhula`]). The models' words come from
//! the registry [`cardan_dynamics::LOSS_MODELS`], their parameters' defaults from
//! [`cardan_dynamics::LossParameter::default`]; a parameter no chosen model reads is refused.
//! An engine's `[friction]` also reads the engine
//! components (valve train, accessories, pumping; all off by default) and the settings of the
//! fmep cross-check ([`cardan_dynamics::EngineLosses`]).

use crate::error::{CaseError, Invalid, Machine};
use crate::gas::{Clearance, GasCase};
use crate::input_field::{attachment_field, parameter_field};
use crate::plausible::{
    BearingLoadConstant, FrictionCoefficient, JournalClearanceRatio, JournalLengthRatio,
    LubricationFactor,
};
use crate::quantity::{
    broken, AngularSpeed, Density, Force, KinematicViscosity, Length, Positive, Pressure, Quantity,
    Ranged,
};
use crate::units::{to_si, Dimension};
use cardan_dynamics::loss_models::{self, words, Attachment, Bind, NONE};
use cardan_dynamics::{
    BearingSize, EngineLosses, FmepModel, Friction, GearSpec, LossModel, ValveTrain,
};
use cardan_dynamics::{LossParameter, ParameterValues};
use cardan_mechanism::{JointKind, Mechanism};
use schemars::{json_schema, JsonSchema, Schema, SchemaGenerator};
use serde::de::{Error as _, MapAccess, Visitor};
use serde::{Deserialize, Deserializer};
use std::borrow::Cow;
use std::marker::PhantomData;
use std::sync::Arc;

/// The `[friction]` table: each model's word and parameters, the oil, per-joint bearings, and
/// an engine's components. Every field is optional; a parameter's default is the model's
/// ([`cardan_dynamics::LossParameter::default`]).
#[derive(Debug, Clone, Default, Deserialize, JsonSchema, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct FrictionTable {
    /// Piston-ring model of every piston in a cylinder (default "karhula").
    pub rings: Option<Model<Rings>>,
    /// μ_ring of the "karhula" ring pack (default 0.07, Karhula A9.1.4 after Andersson et al.
    /// 2002).
    pub ring_friction_coefficient: Option<Ranged<FrictionCoefficient>>,
    /// Crown height of the "film" rings' barrel faces, m (default 5 µm).
    pub ring_crown_height: Option<Positive<Length>>,
    /// Model of a piston's slide on the frame (default "karhula").
    pub skirt: Option<Model<Skirt>>,
    /// μ_skirt of the "karhula" skirt (default 0.09, Karhula A9.1.5).
    pub skirt_friction_coefficient: Option<Ranged<FrictionCoefficient>>,
    /// Length of the "viscous" skirt, m (default 0.6 × bore, the Thai thesis's proportions).
    pub skirt_length: Option<Positive<Length>>,
    /// Radial clearance of the "viscous" skirt, m (default 20 µm, the Thai thesis's example).
    pub skirt_clearance: Option<Positive<Length>>,
    /// Coulomb μ of every other slide, a Scotch-yoke slot (default 0.09, Karhula's skirt).
    pub slide_friction_coefficient: Option<Ranged<FrictionCoefficient>>,
    /// Bearing model of every revolute joint (default "karhula").
    pub bearings: Option<Model<Bearings>>,
    /// Lubrication factor f0 of the "karhula" and "palmgren" bearings (default 2, Karhula).
    pub lubrication_factor: Option<Ranged<LubricationFactor>>,
    /// Constant of the "karhula" bearings' load term (default 0.0009, which reproduces the
    /// thesis's tables; 0.009 as printed in A9.1.26-27).
    pub bearing_load_constant: Option<Ranged<BearingLoadConstant>>,
    /// L/D of the "petroff" and "short_bearing" journals (default 0.5).
    pub journal_length_ratio: Option<Ranged<JournalLengthRatio>>,
    /// c/R of the "petroff" and "short_bearing" journals (default 0.001).
    pub journal_clearance_ratio: Option<Ranged<JournalClearanceRatio>>,
    /// Gear-mesh loss model on the pair of `[gear]` (default "karhula").
    pub gear_mesh: Option<Model<GearMesh>>,
    /// Kinematic viscosity of the oil at running temperature, m²/s (default 5 mm²/s, Karhula).
    pub oil_viscosity: Option<Positive<KinematicViscosity>>,
    /// Density of the oil, kg/m³ (default 900, Karhula).
    pub oil_density: Option<Positive<Density>>,
    /// Per named revolute joint: another bearing model, or a table of a model and catalogue
    /// values replacing the mechanism's sizing rules (Karhula A9.1.10-13).
    pub joints: Option<Joints>,
    /// Engine only: valve-train model (default "none").
    pub valve_train: Option<Model<ValveTrainModels>>,
    /// Engine only, valve_train = "flat": μ at the cam contact (default 0.08).
    pub cam_friction_coefficient: Option<Ranged<FrictionCoefficient>>,
    /// Engine only, with a valve train: crank speed the springs are sized for, rad/s (default
    /// 6000 rpm).
    pub valve_spring_speed: Option<Positive<AngularSpeed>>,
    /// Engine only: Bishop's pumps and accessories (default false).
    pub accessories: Option<bool>,
    /// Engine only: Bishop's throttling loss at intake_pressure (default false).
    pub pumping: Option<bool>,
    /// Engine only: absolute intake-manifold pressure, Pa, above 0.1 × ambient and at most
    /// ambient (default ambient, 101 325 Pa: wide-open throttle).
    pub intake_pressure: Option<Positive<Pressure>>,
    /// Engine only: the whole-engine fmep cross-check (default "sandoval_heywood").
    pub fmep_model: Option<FmepWord>,
}

/// The fmep correlation of an engine's cross-check.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, JsonSchema, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FmepWord {
    /// Sandoval & Heywood (2003): PNH with the oil's viscosity scaling.
    SandovalHeywood,
    /// Patton, Nitschke & Heywood (1989).
    Pnh,
}

/// An attachment of loss models, as a type: the field type [`Model`] takes its words from the
/// registry.
pub trait AttachmentType {
    const ATTACHMENT: Attachment;
    /// The name used in the JSON Schema's definitions.
    const NAME: &'static str;
}

macro_rules! attachment_types {
    ($($(#[$doc:meta])* $name:ident => $attachment:ident),* $(,)?) => {$(
        $(#[$doc])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq)]
        pub struct $name;
        impl AttachmentType for $name {
            const ATTACHMENT: Attachment = Attachment::$attachment;
            const NAME: &'static str = concat!(stringify!($name), "Model");
        }
    )*};
}

attachment_types!(
    /// The rings of the pistons.
    Rings => Rings,
    /// A piston's slide on the frame.
    Skirt => Skirt,
    /// A revolute joint's bearings.
    Bearings => Bearing,
    /// A gear mesh.
    GearMesh => GearMesh,
    /// An engine's valve train.
    ValveTrainModels => ValveTrain,
);

/// A loss model's word, checked against the registry: `model` is `None` for "none".
#[derive(Debug, Clone, Copy)]
pub struct Model<S> {
    pub model: Option<&'static LossModel>,
    attachment: PhantomData<S>,
}

impl<S: AttachmentType> Model<S> {
    /// The word as written.
    pub fn word(&self) -> &'static str {
        self.model.map_or(NONE, |m| m.name)
    }
}

impl<'de, S: AttachmentType> Deserialize<'de> for Model<S> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let word = String::deserialize(deserializer)?;
        let model = loss_models::find(S::ATTACHMENT, &word);
        if model.is_none() && word != NONE {
            let words = words(S::ATTACHMENT);
            return Err(D::Error::custom(crate::schema::suggest(
                "word", &word, &words,
            )));
        }
        Ok(Self {
            model,
            attachment: PhantomData,
        })
    }
}

/// Its word.
impl<S: AttachmentType> serde::Serialize for Model<S> {
    fn serialize<Ser: serde::Serializer>(&self, serializer: Ser) -> Result<Ser::Ok, Ser::Error> {
        serializer.serialize_str(self.word())
    }
}

impl<S: AttachmentType> JsonSchema for Model<S> {
    fn schema_name() -> Cow<'static, str> {
        S::NAME.into()
    }

    fn json_schema(_: &mut SchemaGenerator) -> Schema {
        let models: Vec<String> = loss_models::LOSS_MODELS
            .iter()
            .filter(|m| m.attachment == S::ATTACHMENT)
            .map(|m| format!("\"{}\": {}", m.name, m.summary))
            .collect();
        json_schema!({
            "type": "string",
            "enum": words(S::ATTACHMENT),
            "description": format!("{}; \"none\": no loss", models.join("; "))
        })
    }
}

/// `[friction.joints]`: joint name = a bearing model, or a table; in the file's order.
#[derive(Debug, Clone, Default, serde::Serialize)]
pub struct Joints(pub Vec<(String, Joint)>);

/// One entry of `[friction.joints]`.
#[derive(Debug, Clone, serde::Serialize)]
pub enum Joint {
    /// `crank_pin = "short_bearing"`.
    Model(Model<Bearings>),
    /// `crank_pin = { model = "palmgren", pitch_diameter = "50 mm", ... }`.
    Table(JointTable),
}

/// A joint's bearing model and catalogue values; what is left out keeps the sizing rules.
#[derive(Debug, Clone, Deserialize, JsonSchema, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct JointTable {
    /// The joint's bearing model (default: `bearings`).
    pub model: Option<Model<Bearings>>,
    /// Pitch (mean) diameter of one bearing, m (of a plain bearing: the journal diameter).
    pub pitch_diameter: Option<Positive<Length>>,
    /// Basic static load rating C0 of one bearing, N.
    pub static_load_rating: Option<Positive<Force>>,
    /// Bearings side by side sharing the joint's load, 1 to 16.
    pub count: Option<Count>,
}

/// A number of bearings, a whole number from 1 to 16.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub struct Count(pub u32);

impl<'de> Deserialize<'de> for Count {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let value = toml::Value::deserialize(deserializer)?;
        let x =
            to_si(&value, Dimension::Number).map_err(|r| D::Error::custom(broken(&value, &r)))?;
        if x.fract() != 0.0 || !(1.0..=16.0).contains(&x) {
            let rule = "must be a whole number from 1 to 16";
            return Err(D::Error::custom(broken(&value, rule)));
        }
        Ok(Count(x as u32))
    }
}

impl JsonSchema for Count {
    fn schema_name() -> Cow<'static, str> {
        "BearingCount".into()
    }

    fn json_schema(_: &mut SchemaGenerator) -> Schema {
        json_schema!({ "type": "integer", "minimum": 1, "maximum": 16 })
    }
}

impl<'de> Deserialize<'de> for Joint {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Either;
        impl<'de> Visitor<'de> for Either {
            type Value = Joint;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a bearing model, or a table of model, pitch_diameter, static_load_rating, count")
            }
            fn visit_str<E: serde::de::Error>(self, word: &str) -> Result<Joint, E> {
                let word = serde::de::value::StrDeserializer::<E>::new(word);
                Model::<Bearings>::deserialize(word).map(Joint::Model)
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<Joint, A::Error> {
                // Through the reader's own map, so that a field's path goes on to the field.
                JointTable::deserialize(serde::de::value::MapAccessDeserializer::new(map))
                    .map(Joint::Table)
            }
        }
        deserializer.deserialize_any(Either)
    }
}

impl<'de> Deserialize<'de> for Joints {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Entries;
        impl<'de> Visitor<'de> for Entries {
            type Value = Joints;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a table of joint name = bearing model or table")
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Joints, A::Error> {
                let mut joints = Vec::new();
                while let Some(entry) = map.next_entry::<String, Joint>()? {
                    joints.push(entry);
                }
                Ok(Joints(joints))
            }
        }
        deserializer.deserialize_map(Entries)
    }
}

impl JsonSchema for Joints {
    fn schema_name() -> Cow<'static, str> {
        "FrictionJoints".into()
    }

    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        let word = generator.subschema_for::<Model<Bearings>>();
        let table = generator.subschema_for::<JointTable>();
        json_schema!({
            "type": "object",
            "additionalProperties": { "anyOf": [word, table] }
        })
    }
}

/// The fields only an engine reads, with their values as written.
fn engine_fields(t: &FrictionTable) -> Vec<(&'static str, String)> {
    let mut fields = Vec::new();
    let mut field = |name, written: Option<String>| {
        if let Some(w) = written {
            fields.push((name, w));
        }
    };
    field(
        "valve_train",
        t.valve_train.map(|m| format!("\"{}\"", m.word())),
    );
    let cam = t.cam_friction_coefficient.as_ref();
    field("cam_friction_coefficient", cam.map(|q| q.written.clone()));
    let spring = t.valve_spring_speed.as_ref();
    field("valve_spring_speed", spring.map(|q| q.written.clone()));
    field("accessories", t.accessories.map(|b| b.to_string()));
    field("pumping", t.pumping.map(|b| b.to_string()));
    let intake = t.intake_pressure.as_ref();
    field("intake_pressure", intake.map(|q| q.written.clone()));
    let fmep = |w: FmepWord| match w {
        FmepWord::SandovalHeywood => "\"sandoval_heywood\"",
        FmepWord::Pnh => "\"pnh\"",
    };
    field("fmep_model", t.fmep_model.map(|w| fmep(w).to_string()));
    fields
}

/// Compression ratio of the PNH gas-loading term when the case has no gas model that gives one.
const DEFAULT_COMPRESSION_RATIO: f64 = 10.0;

/// The loss models of `[friction]` (`table`), its mesh loss on the pair of `[gear]` (`gear`),
/// for a `machine`; an engine's compression ratio (for the fmep
/// cross-check) comes from its `gas` model. Checks what the schema cannot: the engine fields
/// (refused for a pump; the valve train's own fields without one) and the intake pressure.
pub fn build(
    table: &FrictionTable,
    gear: Option<&GearSpec>,
    machine: Machine,
    gas: Option<&GasCase>,
    invalid: &Invalid,
) -> Result<Friction, CaseError> {
    // A model written (`Some(None)`: "none"), else the attachment's default.
    let model = |written: Option<Option<&'static LossModel>>, attachment| {
        written.unwrap_or_else(|| loss_models::default_model(attachment))
    };
    let mut f = Friction::karhula();
    if let Some(q) = &table.oil_viscosity {
        f.oil.kinematic_viscosity = q.si;
    }
    if let Some(q) = &table.oil_density {
        f.oil.density = q.si;
    }
    f.rings = model(table.rings.map(|m| m.model), Attachment::Rings);
    f.skirt = model(table.skirt.map(|m| m.model), Attachment::Skirt);
    if let Some(q) = &table.slide_friction_coefficient {
        f.slide_friction_coefficient = q.si;
    }
    let bearing = |m: Option<Model<Bearings>>| model(m.map(|m| m.model), Attachment::Bearing);
    f.bearings = bearing(table.bearings);
    for (name, joint) in table.joints.iter().flat_map(|j| &j.0) {
        match joint {
            Joint::Model(m) => f.joint_bearings.push((name.clone(), bearing(Some(*m)))),
            Joint::Table(t) => {
                if let Some(m) = t.model {
                    f.joint_bearings.push((name.clone(), bearing(Some(m))));
                }
                let size = BearingSize {
                    pitch_diameter: t.pitch_diameter.as_ref().map(|q| q.si),
                    static_load_rating: t.static_load_rating.as_ref().map(|q| q.si),
                    count: t.count.map(|c| c.0),
                };
                f.joint_sizes.push((name.clone(), size));
            }
        }
    }
    f.gear_mesh = model(table.gear_mesh.map(|m| m.model), Attachment::GearMesh);
    if machine == Machine::Pump {
        if let Some((field, written)) = engine_fields(table).into_iter().next() {
            return Err(invalid(
                &format!("friction.{field}"),
                &written,
                "only an engine has a valve train, accessories and pumping losses (and an fmep): this case has machine = \"pump\"",
            ));
        }
    }
    let joints = f.joint_bearings.iter().map(|(_, m)| *m);
    let train = table.valve_train.and_then(|m| m.model);
    let chosen: Vec<&'static LossModel> = [f.rings, f.skirt, f.bearings, f.gear_mesh, train]
        .into_iter()
        .chain(joints)
        .flatten()
        .collect();
    f.parameters = parameters(table, &chosen, invalid)?;
    f.engine = match machine {
        Machine::Engine => Some(engine(table, &f.parameters, gas, invalid)?),
        Machine::Pump => None,
    };
    f.pair = gear.copied().unwrap_or_default();
    Ok(f)
}

/// A value of `[friction]` where the table sets it: SI, and as written.
type Set<'a> = Option<(f64, &'a str)>;

/// Each loss-model parameter of `[friction]`, and its value where the table sets it.
fn parameter_fields(t: &FrictionTable) -> Vec<(LossParameter, Set<'_>)> {
    fn set<D, const RULE: u8>(q: &Option<Quantity<D, RULE>>) -> Set<'_> {
        q.as_ref().map(|q| (q.si, q.written.as_str()))
    }
    fn ranged<R, D>(q: &Option<Ranged<R, D>>) -> Set<'_> {
        q.as_ref().map(|q| (q.si, q.written.as_str()))
    }
    use LossParameter::*;
    vec![
        (
            RingFrictionCoefficient,
            ranged(&t.ring_friction_coefficient),
        ),
        (RingCrownHeight, set(&t.ring_crown_height)),
        (
            SkirtFrictionCoefficient,
            ranged(&t.skirt_friction_coefficient),
        ),
        (SkirtLength, set(&t.skirt_length)),
        (SkirtClearance, set(&t.skirt_clearance)),
        (LubricationFactor, ranged(&t.lubrication_factor)),
        (BearingLoadConstant, ranged(&t.bearing_load_constant)),
        (JournalLengthRatio, ranged(&t.journal_length_ratio)),
        (JournalClearanceRatio, ranged(&t.journal_clearance_ratio)),
        (CamFrictionCoefficient, ranged(&t.cam_friction_coefficient)),
    ]
}

/// The loss-model parameters `[friction]` sets, each refused where no model of the case
/// (`chosen`) reads it: a value that would change nothing is a mistake (a model word left
/// out or misremembered).
fn parameters(
    t: &FrictionTable,
    chosen: &[&'static LossModel],
    invalid: &Invalid,
) -> Result<ParameterValues, CaseError> {
    let mut values = ParameterValues::default();
    for (parameter, set) in parameter_fields(t) {
        let Some((si, written)) = set else { continue };
        if !chosen.iter().any(|m| m.parameters.contains(&parameter)) {
            let readers: Vec<String> = (loss_models::LOSS_MODELS.iter())
                .filter(|m| m.parameters.contains(&parameter))
                .map(|m| format!("{} = \"{}\"", attachment_field(m.attachment), m.name))
                .collect();
            let rule = format!(
                "is read only with {}: no model of this case reads it (choose that model, or leave the value out)",
                readers.join(" or ")
            );
            let field = format!("friction.{}", parameter_field(parameter));
            return Err(invalid(&field, &written, &rule));
        }
        values.set(parameter, si);
    }
    Ok(values)
}

/// The engine components of `[friction]` (every one off by default) and the settings of the
/// fmep cross-check.
fn engine(
    t: &FrictionTable,
    p: &ParameterValues,
    gas: Option<&GasCase>,
    invalid: &Invalid,
) -> Result<EngineLosses, CaseError> {
    let mut e = EngineLosses::off();
    e.compression_ratio = match gas.map(|g| g.clearance) {
        Some(Clearance::CompressionRatio(r)) => r,
        _ => DEFAULT_COMPRESSION_RATIO,
    };
    let train = t.valve_train.and_then(|m| m.model);
    // The cam's μ is a model parameter (refused where no model reads it, [`parameters`]); the
    // springs' speed is the valve train's own.
    let spring = t.valve_spring_speed.as_ref();
    e.valve_train = match train {
        None => {
            if let Some(q) = spring {
                return Err(invalid(
                    "friction.valve_spring_speed",
                    &q.written,
                    "is read only with valve_train = \"flat\" or \"roller\" (the valve train is off)",
                ));
            }
            None
        }
        Some(model) => {
            let Bind::Follower(follower) = model.bind else {
                unreachable!("a valve-train model gives a follower (the registry's test)")
            };
            let mut v = ValveTrain::new(follower(p));
            if let Some(q) = spring {
                v.spring_speed = q.si;
            }
            Some(v)
        }
    };
    e.accessories = t.accessories.unwrap_or(false);
    e.pumping = t.pumping.unwrap_or(false);
    if let Some(q) = &t.intake_pressure {
        e.intake_pressure = q.si;
        let pa = e.ambient_pressure;
        if !(e.intake_pressure > 0.1 * pa && e.intake_pressure <= pa) {
            return Err(invalid(
                "friction.intake_pressure",
                &q.written,
                &format!(
                    "must be above 0.1 × ambient ({} Pa, where Bishop's standard imep is zero) and at most ambient ({pa} Pa: wide-open throttle; Bishop's engines are not boosted)",
                    0.1 * pa
                ),
            ));
        }
    }
    e.fmep_model = match t.fmep_model {
        Some(FmepWord::Pnh) => FmepModel::Pnh1989,
        Some(FmepWord::SandovalHeywood) | None => FmepModel::SandovalHeywood2003,
    };
    Ok(e)
}

/// [`build`] (`with`: the case's gear, machine and gas), then [`check_joints`] against the
/// case's `mechanisms`: a case's friction as validation takes it.
pub(crate) fn build_checked(
    table: &FrictionTable,
    (gear, machine, gas): (Option<&GearSpec>, Machine, Option<&GasCase>),
    mechanisms: &[Arc<dyn Mechanism>],
    invalid: &Invalid,
) -> Result<Friction, CaseError> {
    let f = build(table, gear, machine, gas, invalid)?;
    check_joints(table, mechanisms, invalid)?;
    Ok(f)
}

/// Every joint `[friction.joints]` names must be a revolute joint of a mechanism of the case.
pub fn check_joints(
    table: &FrictionTable,
    mechanisms: &[Arc<dyn Mechanism>],
    invalid: &Invalid,
) -> Result<(), CaseError> {
    for (joint, entry) in table.joints.iter().flat_map(|j| &j.0) {
        let revolute = |m: &Arc<dyn Mechanism>| {
            let t = m.topology();
            t.joints
                .iter()
                .any(|j| j.name == joint && matches!(j.kind, JointKind::Revolute(_)))
        };
        if !mechanisms.iter().any(revolute) {
            let written = match entry {
                Joint::Model(m) => format!("\"{}\"", m.word()),
                Joint::Table(_) => "a table".to_string(),
            };
            return Err(invalid(
                &format!("friction.joints.{joint}"),
                &written,
                "no mechanism of the case has a revolute joint of this name (see summary.json's joints)",
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn error(text: &str) -> String {
        let value: toml::Value = toml::from_str(text).unwrap();
        crate::schema::read::<FrictionTable>(value, "friction")
            .unwrap_err()
            .to_string()
    }

    #[test]
    fn a_misspelled_field_names_its_path_and_the_nearest_field() {
        let e = error("ring_frction_coefficient = 0.1");
        assert!(
            e.starts_with("friction.ring_frction_coefficient: unknown field \"ring_frction_coefficient\": did you mean \"ring_friction_coefficient\"?"),
            "{e}"
        );
        let e = error("[joints]\ncrank_pin = { modle = \"skf\" }");
        assert!(
            e.starts_with(
                "friction.joints.crank_pin.modle: unknown field \"modle\": did you mean \"model\"?"
            ),
            "{e}"
        );
    }

    #[test]
    fn a_misspelled_model_names_its_path_and_the_nearest_model_of_the_registry() {
        let e = error("rings = \"flim\"");
        assert_eq!(
            e,
            "friction.rings: unknown word \"flim\": did you mean \"film\"? (must be \"karhula\", \"film\" or \"none\")"
        );
        let e = error("[joints]\ncrank_pin = \"palmgrn\"");
        assert!(
            e.starts_with(
                "friction.joints.crank_pin: unknown word \"palmgrn\": did you mean \"palmgren\"?"
            ),
            "{e}"
        );
        let e = error("[joints]\nmain_bearing = { model = \"short_baering\" }");
        assert!(
            e.starts_with("friction.joints.main_bearing.model: unknown word \"short_baering\": did you mean \"short_bearing\"?"),
            "{e}"
        );
    }

    /// The friction of `[friction]` `text` of a pump or an engine.
    fn built(text: &str, machine: Machine) -> Result<Friction, CaseError> {
        let value: toml::Value = toml::from_str(text).unwrap();
        let t: FrictionTable = crate::schema::read(value, "friction").unwrap();
        let invalid = |field: &str, value: &dyn std::fmt::Display, rule: &str| CaseError::Invalid {
            file: "x.toml".into(),
            case: "x".into(),
            field: field.into(),
            value: value.to_string(),
            rule: rule.into(),
        };
        build(&t, None, machine, None, &invalid)
    }

    #[test]
    fn an_empty_table_is_karhulas_set() {
        assert_eq!(built("", Machine::Pump).unwrap(), Friction::karhula());
    }

    /// A model parameter is taken where a model of the case reads it (at any attachment, a
    /// named joint's too) and refused where none does, naming the models that read it.
    #[test]
    fn a_parameter_no_chosen_model_reads_is_refused() {
        use LossParameter::*;
        let taken = [
            (
                "rings = \"film\"\nring_crown_height = \"8 um\"",
                RingCrownHeight,
                8e-6,
            ),
            (
                "ring_friction_coefficient = 0.05",
                RingFrictionCoefficient,
                0.05,
            ),
            (
                "skirt = \"viscous\"\nskirt_length = \"70 mm\"",
                SkirtLength,
                0.07,
            ),
            (
                "bearings = \"palmgren\"\nlubrication_factor = 3",
                LubricationFactor,
                3.0,
            ),
            (
                "journal_length_ratio = 0.8\n[joints]\ncrank_pin = \"petroff\"",
                JournalLengthRatio,
                0.8,
            ),
        ];
        for (text, parameter, value) in taken {
            let f = built(text, Machine::Pump).unwrap_or_else(|e| panic!("{text}: {e}"));
            assert_eq!(f.parameters.get(parameter), Some(value), "{text}");
        }
        let refused = [
            (
                "ring_crown_height = \"8 um\"",
                "ring_crown_height",
                "rings = \"film\"",
            ),
            (
                "rings = \"none\"\nring_friction_coefficient = 0.05",
                "ring_friction_coefficient",
                "rings = \"karhula\"",
            ),
            (
                "skirt_clearance = \"30 um\"",
                "skirt_clearance",
                "skirt = \"viscous\"",
            ),
            (
                "bearings = \"skf\"\nlubrication_factor = 3",
                "lubrication_factor",
                "bearings = \"karhula\" or bearings = \"palmgren\"",
            ),
            (
                "journal_clearance_ratio = 0.002",
                "journal_clearance_ratio",
                "bearings = \"petroff\" or bearings = \"short_bearing\"",
            ),
            (
                "valve_train = \"roller\"\ncam_friction_coefficient = 0.1",
                "cam_friction_coefficient",
                "valve_train = \"flat\"",
            ),
        ];
        for (text, field, readers) in refused {
            let e = built(text, Machine::Engine).unwrap_err().to_string();
            assert!(e.contains(&format!("friction.{field}")), "{e}");
            assert!(e.contains(&format!("is read only with {readers}:")), "{e}");
        }
    }

    #[test]
    fn the_schema_lists_the_registrys_words() {
        let schema = serde_json::to_string(&schemars::schema_for!(FrictionTable)).unwrap();
        for m in loss_models::LOSS_MODELS {
            assert!(schema.contains(&format!("\"{}\"", m.name)), "{}", m.name);
        }
    }
}
