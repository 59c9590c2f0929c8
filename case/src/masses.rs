//! `[masses]` and `[masses.<mechanism>]`: the masses a case gives, each field left out
//! estimated by the mass rules of `cardan-mechanism` (Karhula 2008 ch. 10; docs/mass-rules.md).
//! A mechanism's own table wins over the common one.

use crate::error::{CaseError, Invalid};
use crate::quantity::{Inertia, Length, Mass, MassRadius, NonNegative, Quantity};
use crate::schema::FieldError;
use cardan_mechanism::{Entry, MassInputs, MassRules, Material};
use schemars::JsonSchema;
use serde::Deserialize;

/// The mass fields of `[masses]`, and of a mechanism's `[masses.<mechanism>]` (which cannot
/// set `rules`).
#[derive(Debug, Default, Deserialize, JsonSchema, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct MassTable {
    /// Crankshaft moment of inertia about the crank axis, kg·m²; default: the mass rules.
    pub crankshaft_inertia: Option<NonNegative<Inertia>>,
    /// Cardan wheel moment of inertia about its own centre, kg·m²; default: the mass rules.
    pub wheel_inertia: Option<NonNegative<Inertia>>,
    /// Connecting-rod mass, kg; default: the mass rules.
    pub rod_mass: Option<NonNegative<Mass>>,
    /// Connecting-rod moment of inertia about its centre of gravity, kg·m²; default: the mass
    /// rules.
    pub rod_inertia: Option<NonNegative<Inertia>>,
    /// Distance of the rod's centre of gravity from its crank end, m; default: the mass rules.
    pub rod_cg: Option<NonNegative<Length>>,
    /// Piston mass (with pin and rings), kg; default: the mass rules.
    pub piston_mass: Option<NonNegative<Mass>>,
    /// Cardan wheel's mass, kg, its centre of gravity at the wheel's centre (on a circle of the
    /// cardan crank's radius, a quarter of the stroke); default 0: carried by the balanced
    /// crankshaft, as the thesis has it (ch. 11.2). It loads the crank pin, the main bearing,
    /// the drive torque and the shaking force.
    pub wheel_mass: Option<NonNegative<Mass>>,
    /// The crank's own unbalance m·e (crank pin and webs, without counterweights), kg·m,
    /// towards the crank pin; default 0: a balanced crankshaft. It shakes the frame (the
    /// shaking metrics; `[balance]` sizes the counterweights with it) and loads the main
    /// bearing (its m·ω² turning with the crank), hence the main bearing's friction.
    pub crank_unbalance: Option<NonNegative<MassRadius>>,
    /// The rod's material for the estimation rules; default "steel".
    pub rod_material: Option<RodMaterial>,
    /// The reading of the rod estimation rules (docs/mass-rules.md), for the whole machine:
    /// "rod_length" (the default) or "overall_length".
    pub rules: Option<Rules>,
}

/// A rod's material.
#[derive(Debug, Clone, Copy, Deserialize, JsonSchema, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum RodMaterial {
    Steel,
    Titanium,
}

/// The reading of the mass rules ([`MassRules`]).
#[derive(Debug, Clone, Copy, Deserialize, JsonSchema, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Rules {
    /// The section scales with the rod's centre distance l (Karhula 2008 ch. 10).
    RodLength,
    /// The section scales with l + r.
    OverallLength,
}

impl MassTable {
    /// Each mass field's name and (SI value, value as written), where given.
    fn fields(&self) -> [(&'static str, Option<(f64, &str)>); 8] {
        [
            ("crankshaft_inertia", given(&self.crankshaft_inertia)),
            ("wheel_inertia", given(&self.wheel_inertia)),
            ("rod_mass", given(&self.rod_mass)),
            ("rod_inertia", given(&self.rod_inertia)),
            ("rod_cg", given(&self.rod_cg)),
            ("piston_mass", given(&self.piston_mass)),
            ("wheel_mass", given(&self.wheel_mass)),
            ("crank_unbalance", given(&self.crank_unbalance)),
        ]
    }
}

fn given<D, const RULE: u8>(q: &Option<Quantity<D, RULE>>) -> Option<(f64, &str)> {
    q.as_ref().map(|q| (q.si, q.written.as_str()))
}

/// Reads a mechanism's own `[masses.<mechanism>]` table.
pub(crate) fn own_table(value: toml::Value, mechanism: &str) -> Result<MassTable, FieldError> {
    let prefix = format!("masses.{mechanism}");
    let table: MassTable = crate::schema::read(value, &prefix)?;
    if table.rules.is_some() {
        let fields = [
            "crankshaft_inertia",
            "wheel_inertia",
            "rod_mass",
            "rod_inertia",
        ];
        return Err(FieldError {
            field: format!("{prefix}.rules"),
            message: format!(
                "unknown field \"rules\" in a mechanism's mass table: the reading of the rules is the machine's, set it in [masses] (the fields here: {}, rod_cg, piston_mass, rod_material)",
                fields.join(", ")
            ),
            expected: Box::default(),
        });
    }
    Ok(table)
}

/// Why a mass `field` does not apply to `entry`'s mechanism, and where it may go instead: the
/// tables of the registered mechanisms it applies to (issue 36.15: not always
/// `[masses.cardan_gear]`).
fn not_applying(entry: &Entry, field: &str, own_table: bool) -> String {
    let tables: Vec<String> = cardan_mechanism::MECHANISMS
        .iter()
        .filter(|m| m.name != entry.name && !m.unused_masses.contains(&field))
        .map(|m| format!("[masses.{}]", m.name))
        .collect();
    let instead = match tables.as_slice() {
        [] => "remove it".to_string(),
        t => format!(
            "remove it, or give it in the table of a mechanism it applies to: {}",
            t.join(", ")
        ),
    };
    match own_table {
        true => format!(
            "does not apply to the {} (it has no such body): {instead}",
            entry.name
        ),
        false => format!("does not apply to the {}: {instead}", entry.name),
    }
}

/// The mass inputs of one mechanism: its own table's fields, else the common table's.
pub(crate) fn inputs(
    common: &MassTable,
    own: Option<&MassTable>,
    entry: &Entry,
    invalid: &Invalid,
) -> Result<MassInputs, CaseError> {
    let mut inputs = MassInputs::default();
    let own_fields = own.map(MassTable::fields);
    for (i, (field, common_value)) in common.fields().into_iter().enumerate() {
        let picked = match own_fields.as_ref().and_then(|f| f[i].1) {
            Some(v) => Some((v, format!("masses.{}.{field}", entry.name))),
            None => common_value.map(|v| (v, format!("masses.{field}"))),
        };
        let own_table = own_fields.as_ref().and_then(|f| f[i].1).is_some();
        let Some(((x, written), path)) = picked else {
            continue;
        };
        if entry.unused_masses.contains(&field) {
            return Err(invalid(
                &path,
                &written,
                &not_applying(entry, field, own_table),
            ));
        }
        let slot = match field {
            "crankshaft_inertia" => &mut inputs.crankshaft_inertia,
            "wheel_inertia" => &mut inputs.wheel_inertia,
            "rod_mass" => &mut inputs.rod_mass,
            "rod_inertia" => &mut inputs.rod_inertia,
            "rod_cg" => &mut inputs.rod_cg,
            "wheel_mass" => &mut inputs.wheel_mass,
            "crank_unbalance" => &mut inputs.crank_unbalance,
            _ => &mut inputs.piston_mass,
        };
        *slot = Some(x);
    }
    inputs.rules = common.rules.map(|r| match r {
        Rules::RodLength => MassRules::RodLength,
        Rules::OverallLength => MassRules::OverallLength,
    });
    let material = own.and_then(|t| t.rod_material).or(common.rod_material);
    inputs.rod_material = material.map(|m| match m {
        RodMaterial::Steel => Material::Steel,
        RodMaterial::Titanium => Material::Titanium,
    });
    Ok(inputs)
}
