//! Any bytes as a case file: read and validated, each case of a sweep expanded; an error or a
//! validated case, never a panic or a hang (docs/fuzzing.md).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let dir = std::env::temp_dir().join(format!("cardan-fuzz-{}", std::process::id()));
    let _ = std::fs::create_dir_all(&dir);
    let file = dir.join("case.toml");
    if std::fs::write(&file, text).is_ok() {
        // Sweeps expanded, every point validated.
        let _ = cardan_case::case::load_file(&file);
    }
});
