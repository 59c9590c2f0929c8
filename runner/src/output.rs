//! Result files: `summary.json` (the per-step files are [`crate::per_step`]'s). A case's
//! files are written into a fresh temporary folder that then replaces the case's folder as a
//! whole, so no file of an earlier run survives beside the new ones.

use crate::case::Case;
use crate::run::MechanismResult;
use anyhow::Context;
use cardan_mechanism::JointKind;
use serde_json::{json, Map, Value};
use std::fs::File;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Version of the layout of `summary.json`; raised when a name or the shape changes.
pub const SCHEMA_VERSION: u32 = 2;

/// The summary of a case as JSON (see README.md, "Results").
pub fn summary_json(case: &Case, results: &[MechanismResult]) -> Value {
    let mut mechanisms = Map::new();
    for r in results {
        let m = r.mechanism.as_ref();
        let mut metrics = Map::new();
        let mut units = Map::new();
        for metric in &r.summary.metrics {
            metrics.insert(metric.name.clone(), json!(metric.value));
            units.insert(metric.name.clone(), json!(metric.unit));
        }
        let masses = m.masses();
        let mut mass_properties: Map<String, Value> = masses
            .fields()
            .iter()
            .map(|(name, value, _)| (name.to_string(), json!(value)))
            .collect();
        mass_properties.insert("rod_material".into(), json!(masses.rod_material.name()));
        let t = m.topology();
        let bodies: Map<String, Value> = t
            .bodies
            .iter()
            .map(|b| {
                (
                    b.name.to_string(),
                    json!({"mass_kg": b.mass, "inertia_kg_m2": b.inertia}),
                )
            })
            .collect();
        let joints: Map<String, Value> = t
            .joints
            .iter()
            .map(|j| {
                let between = json!([
                    t.bodies[j.body].name,
                    j.other.map_or("frame", |o| t.bodies[o].name)
                ]);
                let v = match j.kind {
                    JointKind::Revolute(b) => {
                        json!({"kind": "revolute", "bodies": between, "journal_radius_m": b.radius,
                            "bearings": b.count, "static_load_rating_N": b.static_load_rating})
                    }
                    JointKind::Prismatic => json!({"kind": "prismatic", "bodies": between}),
                    JointKind::GearMesh {
                        ratio,
                        pitch_radius,
                        internal,
                        pressure_angle,
                        ..
                    } => json!({
                        "kind": "gear_mesh",
                        "bodies": between,
                        "ratio": ratio,
                        "pitch_radius_m": pitch_radius,
                        "internal": internal,
                        "pressure_angle_deg": pressure_angle.to_degrees()
                    }),
                };
                (j.name.to_string(), v)
            })
            .collect();
        // The maps moved in: `json!` would serialise each into a copy.
        let mechanism: Map<String, Value> = [
            ("metrics", metrics),
            ("units", units),
            ("mass_properties", mass_properties),
            ("bodies", bodies),
            ("joints", joints),
        ]
        .into_iter()
        .map(|(k, v)| (k.to_string(), Value::Object(v)))
        .collect();
        mechanisms.insert(r.label.clone(), Value::Object(mechanism));
    }
    let mut summary = json!({
        "schema_version": SCHEMA_VERSION,
        "case": case.name,
        "machine": case.machine.name(),
        "gas_model": case.gas.as_ref().map(|g| g.name()),
    });
    summary["mechanisms"] = Value::Object(mechanisms);
    let warnings: Vec<String> = results
        .iter()
        .flat_map(|r| r.warnings.iter().map(move |w| format!("{}: {w}", r.label)))
        .collect();
    if !warnings.is_empty() {
        summary["warnings"] = json!(warnings);
    }
    summary
}

/// Writes `contents` to `path`. No fsync: a case folder appears whole by a rename, and waiting
/// for the disk would cost more than the computation of a small case (10 000 pump cases of
/// 720 steps: 13.4 s with one fsync per case, 6.7 s without); durability across a power cut is not promised.
pub fn write_file(path: &Path, contents: &[u8]) -> anyhow::Result<()> {
    let mut f = File::create(path).with_context(|| format!("create {}", path.display()))?;
    f.write_all(contents)?;
    Ok(())
}

/// A fresh, empty temporary folder beside `dir`, to be moved onto it by [`replace_dir`].
pub fn temporary_dir(dir: &Path) -> anyhow::Result<PathBuf> {
    let parent = dir.parent().context("no parent folder")?;
    std::fs::create_dir_all(parent).with_context(|| format!("create {}", parent.display()))?;
    let name = dir.file_name().context("no folder name")?.to_string_lossy();
    let tmp = parent.join(format!(".{name}.tmp-{}", std::process::id()));
    if tmp.exists() {
        std::fs::remove_dir_all(&tmp)?;
    }
    std::fs::create_dir(&tmp).with_context(|| format!("create {}", tmp.display()))?;
    Ok(tmp)
}

/// Moves the finished folder `tmp` onto `dir`, replacing whatever was there as a whole.
pub fn replace_dir(tmp: &Path, dir: &Path) -> anyhow::Result<()> {
    if dir.exists() {
        let name = dir.file_name().context("no folder name")?.to_string_lossy();
        let old = dir.with_file_name(format!(".{name}.old-{}", std::process::id()));
        if old.exists() {
            std::fs::remove_dir_all(&old)?;
        }
        std::fs::rename(dir, &old).with_context(|| format!("move {} aside", dir.display()))?;
        std::fs::rename(tmp, dir).with_context(|| format!("rename to {}", dir.display()))?;
        std::fs::remove_dir_all(&old).with_context(|| format!("remove {}", old.display()))?;
    } else {
        std::fs::rename(tmp, dir).with_context(|| format!("rename to {}", dir.display()))?;
    }
    Ok(())
}
