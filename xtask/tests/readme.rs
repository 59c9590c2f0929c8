//! The metric, column and mechanism tables of README.md and docs/ are the registries' own:
//! regenerating them changes nothing (run `cargo xtask readme` after changing a registry).

#[test]
fn generated_tables_match_the_registries() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    for (path, text, fresh) in xtask_gen::regenerate_all(&root).unwrap() {
        assert!(
            fresh == text,
            "{}'s generated tables are stale: run `cargo xtask readme`",
            path.display()
        );
    }
}
