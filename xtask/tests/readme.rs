//! README.md's metric, column and mechanism tables are the registries' own: regenerating them
//! changes nothing (run `cargo xtask readme` after changing a registry).

#[test]
fn readme_tables_match_the_registries() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../README.md");
    let readme = std::fs::read_to_string(path).unwrap();
    let fresh = xtask::regenerate(&readme).unwrap();
    assert!(
        fresh == readme,
        "README.md's generated tables are stale: run `cargo xtask readme`"
    );
}
