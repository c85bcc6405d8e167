//! The Python exceptions: `MechanismError` (a definition that does not
//! read, with its diagnostics) and `PoseError` (inputs at which the
//! mechanism cannot be assembled, with the group that failed).

use mechanism_codegen::runtime;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

pyo3::create_exception!(
    planar_mechanism,
    MechanismError,
    PyValueError,
    "A definition that does not read. `str(e)` is every diagnostic as rustc \
     shows it (`error: ...`, ` --> <definition>:LINE:COLUMN`, the line with the \
     blamed characters underlined); `e.diagnostics` is the list of \
     `Diagnostic`s, `e.text` the definition."
);

pyo3::create_exception!(
    planar_mechanism,
    PoseError,
    PyValueError,
    "The mechanism cannot be assembled (or its velocity system is singular) \
     at the given inputs. `e.group` names the definition's group that failed \
     (\"\" when none), `e.inputs` the inputs by name."
);

/// One diagnostic of a definition, where the text says it.
///
/// Lines and columns are 1-based, columns counted in characters, as the
/// ` --> <definition>:LINE:COLUMN` line of the message shows them; the
/// blamed text runs from (`line`, `column`) up to, not including,
/// (`end_line`, `end_column`). `line` is 0 for an error about the
/// definition as a whole (no place in the text).
#[pyclass(frozen, get_all, module = "planar_mechanism")]
#[derive(Clone)]
pub struct Diagnostic {
    /// The message, as the `mechanism!` macro reports it.
    message: String,
    /// Line of the first blamed character (1-based; 0: no place).
    line: usize,
    /// Column of the first blamed character (1-based).
    column: usize,
    /// Line of the last blamed character (1-based).
    end_line: usize,
    /// Column just after the last blamed character (1-based).
    end_column: usize,
}

#[pymethods]
impl Diagnostic {
    fn __repr__(&self) -> String {
        format!(
            "Diagnostic(line={}, column={}, message={:?})",
            self.line, self.column, self.message
        )
    }

    fn __str__(&self) -> String {
        format!("{}:{}: {}", self.line, self.column, self.message)
    }
}

impl From<&runtime::Diagnostic> for Diagnostic {
    fn from(d: &runtime::Diagnostic) -> Self {
        Diagnostic {
            message: d.message.clone(),
            line: d.line,
            column: d.column + 1,
            end_line: d.end_line,
            end_column: d.end_column + 1,
        }
    }
}

/// The `MechanismError` of a definition's errors, with `diagnostics` and
/// `text` set on the exception.
pub fn definition(py: Python<'_>, errors: &runtime::Errors) -> PyErr {
    let err = MechanismError::new_err(errors.to_string());
    let diagnostics: Vec<Diagnostic> = errors.diagnostics.iter().map(Diagnostic::from).collect();
    let value = err.value(py);
    // Setting attributes on a fresh exception instance does not fail; if
    // it ever did, the error raised is that failure, not a silent loss.
    if let Err(e) = value
        .setattr("diagnostics", diagnostics)
        .and_then(|()| value.setattr("text", &errors.source))
    {
        return e;
    }
    err
}

/// The `PoseError` of a failed evaluation at `inputs` (names, values).
pub fn pose(py: Python<'_>, error: &mechanism_core::Error<f64>, inputs: &[(String, f64)]) -> PyErr {
    let at: Vec<String> = inputs.iter().map(|(n, v)| format!("{n}={v}")).collect();
    let err = PoseError::new_err(format!("at {}: {error}", at.join(", ")));
    let value = err.value(py);
    let set = || -> PyResult<()> {
        let d = PyDict::new(py);
        for (n, v) in inputs {
            d.set_item(n, v)?;
        }
        value.setattr("inputs", d)?;
        value.setattr("group", error.group)
    };
    match set() {
        Ok(()) => err,
        Err(e) => e,
    }
}
