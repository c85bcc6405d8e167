//! `synthesize_path`: four-bar path synthesis from Python
//! ([`mechanism_synthesis::cases::solve`]: multi-start Levenberg-Marquardt
//! on exact dual-number Jacobians, in both assembly modes), returning the
//! design, its objective and the definition's text, which
//! `planar_mechanism.Mechanism` reads to sweep or draw the result.

use mechanism_synthesis::cases::{self, Case};
use mechanism_synthesis::fourbar::{circuit_word, Design};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// Synthesizes a four-bar whose coupler point passes through `targets`
/// (least squares: the sum of squared distances from the coupler point at
/// each target's crank angle to the target).
///
/// The four-bar: ground pivot `O2 = (x0, y0)`, the other ground pivot at
/// `r1` from it at angle `theta0`, crank `r2` at angle `th2` from the
/// ground link, coupler `r3`, rocker `r4`, the coupler point at `(rcx,
/// rcy)` in the frame of `A -> B`; always a Grashof crank-rocker with the
/// crank shortest (it turns fully), in the assembly mode that fits better.
///
/// - `targets`: the points, `(x, y)` each (at least 3; lengths in any unit,
///   the design's are the same).
/// - `angles`: the crank angle from the ground link at each target (rad, in
///   `[0, 2 pi]`), or `None` for free timing (the angles are then design
///   variables, ascending).
/// - `frame`: `(theta0, x0, y0)` fixed, or `None` for free.
/// - `links`: bounds of `r1 .. r4`; `coords`: bounds of `rcx, rcy, x0, y0`.
/// - `starts`, `hops`, `seed`: the search's budget (local solves per
///   assembly mode, basin hops from the best) and its seed; the result
///   depends only on the arguments.
///
/// Returns a dict: `objective`, `mode` (`"left"` or `"right"`), `design`
/// (the nine numbers above by name), `angles` (the crank angles from the
/// ground link, rad), `definition` (the text of the four-bar, whose input
/// `phi` is the crank's absolute angle `theta0 + th2`: give it to
/// `Mechanism`), `evaluations` and `jacobians`. Runs without the GIL.
#[pyfunction]
#[pyo3(
    signature = (targets, *, angles = None, frame = None, links = (0.0, 60.0), coords = (-60.0, 60.0), starts = 300, hops = 300, seed = 0),
    text_signature = "(targets, *, angles=None, frame=None, links=(0.0, 60.0), coords=(-60.0, 60.0), starts=300, hops=300, seed=0)"
)]
#[allow(clippy::too_many_arguments)] // Python's keyword arguments.
pub fn synthesize_path<'py>(
    py: Python<'py>,
    targets: Vec<(f64, f64)>,
    angles: Option<Vec<f64>>,
    frame: Option<(f64, f64, f64)>,
    links: (f64, f64),
    coords: (f64, f64),
    starts: usize,
    hops: usize,
    seed: u64,
) -> PyResult<Bound<'py, PyDict>> {
    let targets = targets.into_iter().map(|(x, y)| [x, y]).collect();
    let frame = frame.map(|(t, x, y)| [t, x, y]);
    let case = Case::path(targets, angles, frame, links, coords).map_err(PyValueError::new_err)?;
    let found = py
        .detach(|| cases::solve_user(&case, starts, hops, seed))
        .map_err(PyValueError::new_err)?;
    let out = PyDict::new(py);
    out.set_item("objective", found.objective)?;
    out.set_item("mode", circuit_word(found.mode))?;
    let design = PyDict::new(py);
    for (name, value) in Design::NAMES.iter().zip(&found.design.0) {
        design.set_item(*name, *value)?;
    }
    out.set_item("design", design)?;
    out.set_item("angles", found.design.angles().to_vec())?;
    out.set_item("definition", found.design.definition(found.mode))?;
    out.set_item("evaluations", found.evaluations)?;
    out.set_item("jacobians", found.jacobians)?;
    Ok(out)
}
