//! Compile-time diagnostics of `mechanism!`: each `tests/ui/*.rs` must fail
//! with exactly the snapshot in its `.stderr`; each `tests/ui_pass/*.rs` must
//! compile. Regenerate snapshots with `TRYBUILD=overwrite cargo test --test ui`
//! and read them: every error must point at the offending user token and say
//! how to fix it.

#[test]
fn ui() {
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/*.rs");
    t.pass("tests/ui_pass/*.rs");
}
