//! Gear files: one spur pair (external or internal, any ratio) in a TOML file → the ISO 21771
//! geometry, the interference checks with their margins and remedies and, when a `[rating]`
//! table is given, the AGMA 2001-D04 stresses and safety factors → `DIR/<name>/gear.json` and
//! `DIR/<name>/report.md`. The physics is `cardan-gears`'; this crate reads, validates and
//! writes (see docs/gear-calculator.md).
//!
//! Values take units as case files do, from the one table of [`cardan_case::units`]: a bare number
//! is in the field's SI unit (lengths m, angles deg, speeds rad/s, power W, torque N·m, stress
//! Pa), a string is "NUMBER UNIT" (inches, hp, lbf·in, psi for the US-unit textbook examples).
//!
//! Bad input is a [`GearFileError`] naming the file, the pair, the field, its value and the
//! rule, never a panic. A pair that cannot work (interference, contact ratio below 1, jammed
//! teeth, a safety factor below `required_safety_factor`, a figure that is not finite) is not
//! an input error: it is written, with the failures and their remedies, and
//! [`GearReport::failures`] lists it so the command can exit 1; [`GearReport::warnings`] lists
//! the rules of thumb it breaks.

use cardan_report::files::{replace_dir, temporary_dir, write_file};
use std::path::{Path, PathBuf};

mod input;
mod iso_input;
mod iso_rate;
mod iso_rating;
mod md_table;
mod rating;
mod report;
mod table;
mod validated;
pub use input::parse;
pub use rating::{check_info, evaluate, GearReport, JSource, RatingResult, Severity};
pub use table::gear_file_schema;
pub use validated::*;

/// Reads and validates one gear file.
pub fn load(file: &Path) -> Result<GearFile, GearFileError> {
    let text = cardan_files::read_text(file, cardan_files::GEAR_FILE).map_err(|source| {
        GearFileError::Io {
            file: file.into(),
            source,
        }
    })?;
    parse(file, &text)
}

/// What [`run`] wrote.
#[derive(Debug)]
pub struct GearRun {
    /// `DIR/<name>`.
    pub dir: PathBuf,
    pub report: GearReport,
}

/// Reads, validates and rates `file` and writes `out/<name>/gear.json` and `report.md`, the
/// folder replaced as a whole. A pair that cannot work is still written; see
/// [`GearReport::failures`].
pub fn run(file: &Path, out: &Path) -> Result<GearRun, GearFileError> {
    let input = load(file)?;
    let report = evaluate(&input)?;
    let dir = out.join(&input.name);
    let cannot_write = |e: anyhow::Error| GearFileError::Write {
        file: input.file.clone(),
        name: input.name.clone(),
        dir: dir.clone(),
        message: format!("{e:#}"),
    };
    let tmp = temporary_dir(&dir).map_err(cannot_write)?;
    let written = (|| -> anyhow::Result<()> {
        let mut json = serde_json::to_string_pretty(&report.to_json())?;
        json.push('\n');
        write_file(&tmp.join("gear.json"), json.as_bytes())?;
        write_file(&tmp.join("report.md"), report.to_markdown().as_bytes())?;
        replace_dir(&tmp, &dir)
    })();
    if let Err(e) = written {
        let _ = std::fs::remove_dir_all(&tmp);
        return Err(cannot_write(e));
    }
    Ok(GearRun { dir, report })
}
