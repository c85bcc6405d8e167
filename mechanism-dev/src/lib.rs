//! The development side of `planar-mechanism`, never published: it owns the
//! workspace's integration tests (`tests/`), the benchmarks (`benches/`) and
//! the heavier examples (`report`, `stability_report`, `long_chain_cost`),
//! so that their dependencies (criterion, trybuild, resvg, proptest, ...) are
//! not the facade's dev-dependencies and a user's
//! `cargo run --release --example fourbar` builds only the library, the
//! plotting crate and the example.
//!
//! The targets keep their files where they are: this manifest names them by
//! path (`../tests/...`). The features forward to the facade's, so
//! `cfg(feature = "...")` in a test reads the same as before.
//! [`workspace_root`] is where the tests find the repository's files.

use std::path::Path;

/// The repository's root (the facade's manifest directory), where `docs/`,
/// `tests/` and `target/` are.
pub fn workspace_root() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
}
