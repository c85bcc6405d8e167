//! Compile-time diagnostics of `mechanism!`: each `tests/ui/*.rs` must fail
//! with exactly the snapshot in its `.stderr`; each `tests/ui_pass/*.rs` must
//! compile. Regenerate snapshots with `TRYBUILD=overwrite cargo test --test ui`
//! and read them: every error must point at the offending user token and say
//! how to fix it.

#[test]
fn ui() {
    // trybuild builds the cases against the crate whose manifest is in
    // CARGO_MANIFEST_DIR: the facade at the workspace's root, not
    // `mechanism-dev` which holds this test (the snapshots' paths stay
    // `tests/ui/...`). The only test in this binary: nothing reads the
    // environment concurrently.
    // The case globs are relative to the working directory, which cargo sets
    // to `mechanism-dev/`: without this they match nothing and trybuild
    // passes with no case run.
    // Canonical (no `mechanism-dev/..`): trybuild shortens the paths in
    // its messages by this prefix.
    let root = mechanism_dev::workspace_root()
        .canonicalize()
        .expect("the workspace root exists");
    std::env::set_var("CARGO_MANIFEST_DIR", &root);
    std::env::set_current_dir(&root).expect("the workspace root exists");
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/*.rs");
    t.pass("tests/ui_pass/*.rs");
}
