//! Result files: `summary.json` (the per-step files are [`crate::per_step`]'s). A case's
//! files are written into a fresh temporary folder that then replaces the case's folder as a
//! whole, so no file of an earlier run survives beside the new ones.

use crate::run::MechanismResult;
use anyhow::Context;
use cardan_case::case::Case;
use cardan_mechanism::JointKind;
use serde_json::{json, Map, Value};
use std::fs::File;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Version of the layout of `summary.json`; raised when a name or the shape changes.
pub const SCHEMA_VERSION: u32 = 2;

/// The summary of a case as JSON (see docs/results.md).
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

/// Writes `contents` to `path` through a temporary file beside it that is then renamed onto
/// it: a reader sees the old file or the new one, never half of one, and a symbolic link at
/// `path` is replaced by the file, not followed.
pub fn write_file_replacing(path: &Path, contents: &[u8]) -> anyhow::Result<()> {
    let name = path.file_name().context("no file name")?.to_string_lossy();
    let tmp = path.with_file_name(format!(".{name}.tmp-{}", std::process::id()));
    write_file(&tmp, contents)?;
    std::fs::rename(&tmp, path).with_context(|| {
        let _ = std::fs::remove_file(&tmp);
        format!("rename to {}", path.display())
    })
}

/// Moves the finished folder `tmp` onto `dir`, replacing whatever was there as a whole. A
/// concurrent run replacing the same folder (moving it aside, or putting its own in place
/// between our two renames) is retried: the last run to finish wins, whole.
pub fn replace_dir(tmp: &Path, dir: &Path) -> anyhow::Result<()> {
    let name = dir.file_name().context("no folder name")?.to_string_lossy();
    let old = dir.with_file_name(format!(".{name}.old-{}", std::process::id()));
    for _ in 0..20 {
        if old.symlink_metadata().is_ok() {
            std::fs::remove_dir_all(&old).with_context(|| format!("remove {}", old.display()))?;
        }
        match std::fs::rename(dir, &old) {
            Ok(()) => {}
            // Nothing there, or another run has just moved it aside.
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {}
            Err(e) => {
                return Err(e).with_context(|| format!("move {} aside", dir.display()));
            }
        }
        match std::fs::rename(tmp, dir) {
            Ok(()) => {
                if old.symlink_metadata().is_ok() {
                    std::fs::remove_dir_all(&old)
                        .with_context(|| format!("remove {}", old.display()))?;
                }
                return Ok(());
            }
            // Another run put its folder in place between the two renames (and may since
            // have moved it aside again): again, while ours is still there to move.
            Err(_) if tmp.is_dir() => continue,
            Err(e) => return Err(e).with_context(|| format!("rename to {}", dir.display())),
        }
    }
    anyhow::bail!(
        "another run keeps replacing {} at the same time; run one at a time on one output folder",
        dir.display()
    )
}

/// The process id in the name of a temporary entry this crate makes (`.NAME.tmp-PID`,
/// `.NAME.old-PID`), if `name` is one.
fn temporary_owner(name: &str) -> Option<u32> {
    let rest = name.strip_prefix('.')?;
    let (stem, pid) = rest.rsplit_once('-')?;
    if !(stem.ends_with(".tmp") || stem.ends_with(".old")) {
        return None;
    }
    pid.parse().ok()
}

/// Whether process `pid` is alive; `None` where this cannot be told (no `/proc`).
fn alive(pid: u32) -> Option<bool> {
    if !Path::new("/proc/self").exists() {
        return None;
    }
    Some(Path::new("/proc").join(pid.to_string()).exists())
}

/// Removes from `dir` the temporary folders and files (`.NAME.tmp-PID`, `.NAME.old-PID`) left
/// by runs that ended without cleaning up (killed): those whose process is no longer alive.
/// Those of a live process (another run at work) are left alone, and so is everything where
/// the liveness of a process cannot be told. Returns what was removed.
pub fn remove_stale_temporaries(dir: &Path) -> Vec<PathBuf> {
    let mut removed = Vec::new();
    let Ok(entries) = std::fs::read_dir(dir) else {
        return removed;
    };
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let Some(pid) = temporary_owner(&name) else {
            continue;
        };
        if pid == std::process::id() || alive(pid) != Some(false) {
            continue;
        }
        let path = entry.path();
        let gone = match entry.file_type() {
            Ok(t) if t.is_dir() => std::fs::remove_dir_all(&path),
            _ => std::fs::remove_file(&path),
        };
        match gone {
            Ok(()) => {
                tracing::info!(path = %path.display(), pid, "removed the leftover of an ended run");
                removed.push(path);
            }
            Err(e) => {
                tracing::warn!(path = %path.display(), "cannot remove the leftover of an ended run: {e}")
            }
        }
    }
    removed
}

#[cfg(test)]
mod tests {
    use super::temporary_owner;

    #[test]
    fn temporary_names_are_told_apart() {
        assert_eq!(temporary_owner(".k.tmp-123"), Some(123));
        assert_eq!(temporary_owner(".my-case.old-9"), Some(9));
        assert_eq!(temporary_owner(".index.html.tmp-77"), Some(77));
        assert_eq!(temporary_owner("k.tmp-123"), None);
        assert_eq!(temporary_owner(".k-123"), None);
        assert_eq!(temporary_owner(".k.tmp-x"), None);
    }
}
