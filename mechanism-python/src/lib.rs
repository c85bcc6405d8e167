//! The Python package `planar_mechanism` (its native module
//! `planar_mechanism._native`): a definition of the `mechanism!` language
//! read at run time ([`mechanism_codegen::runtime::Mechanism`]) and solved
//! in Rust, with results as Python dicts and, over a sweep, numpy arrays
//! filled without a Python call per element.
//!
//! Units: angles in rad (counter-clockwise from +x), lengths in the
//! definition's own unit `L`, rates per second. See `docs/python.md`.
#![forbid(unsafe_code)]

mod batch;
mod errors;
mod mechanism;
mod shared;
mod synthesis;

use pyo3::prelude::*;

/// The module `planar_mechanism._native`; `planar_mechanism` re-exports it.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add_class::<mechanism::Mechanism>()?;
    m.add_class::<mechanism::Input>()?;
    m.add_class::<errors::Diagnostic>()?;
    m.add_function(wrap_pyfunction!(synthesis::synthesize_path, m)?)?;
    m.add("MechanismError", py.get_type::<errors::MechanismError>())?;
    m.add("PoseError", py.get_type::<errors::PoseError>())?;
    Ok(())
}
