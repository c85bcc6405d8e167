//! `synthesize_path`: four-bar path synthesis from Python
//! ([`mechanism_synthesis::cases::solve`]: multi-start Levenberg-Marquardt
//! on exact dual-number Jacobians, in both assembly modes), returning the
//! design, its objective and the definition's text, which
//! `planar_mechanism.Mechanism` reads to sweep or draw the result.

use mechanism_synthesis::cases::{self, Case};
use mechanism_synthesis::fourbar::Timing;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::f64::consts::TAU;

/// The names of a design's first nine numbers, in `Design`'s order.
const DESIGN: [&str; 9] = ["r1", "r2", "r3", "r4", "rcx", "rcy", "theta0", "x0", "y0"];

/// Checks the arguments; the case to solve.
fn case(
    targets: Vec<(f64, f64)>,
    angles: Option<Vec<f64>>,
    frame: Option<(f64, f64, f64)>,
    links: (f64, f64),
    coords: (f64, f64),
) -> Result<Case, String> {
    if targets.len() < 3 {
        return Err(format!(
            "{} target points: a path needs at least 3",
            targets.len()
        ));
    }
    let finite = |x: f64| x.is_finite();
    if !targets.iter().all(|t| finite(t.0) && finite(t.1)) {
        return Err("a target point is not finite".into());
    }
    let timing = match angles {
        None => Timing::Free,
        Some(a) if a.len() != targets.len() => {
            return Err(format!(
            "{} angles for {} target points: give one crank angle per point, or none (free timing)",
            a.len(),
            targets.len()
        ))
        }
        Some(a) if !a.iter().all(|&x| (0.0..=TAU).contains(&x)) => {
            return Err("every crank angle is in [0, 2 pi] (rad, from the ground link)".into())
        }
        Some(a) => Timing::Prescribed(a),
    };
    if let Some((t, x, y)) = frame {
        if !(finite(t) && finite(x) && finite(y)) {
            return Err("the frame (theta0, x0, y0) is not finite".into());
        }
    }
    for (name, (lo, hi)) in [("links", links), ("coords", coords)] {
        if !(finite(lo) && finite(hi) && lo < hi) {
            return Err(format!(
                "{name} = ({lo}, {hi}): bounds need lo < hi, both finite"
            ));
        }
    }
    if links.0 < 0.0 {
        return Err(format!("links = {links:?}: lengths are not negative"));
    }
    Ok(Case {
        id: "python",
        targets: targets.into_iter().map(|(x, y)| [x, y]).collect(),
        timing,
        frame: frame.map(|(t, x, y)| [t, x, y]),
        links,
        coords,
    })
}

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
    let case = case(targets, angles, frame, links, coords).map_err(PyValueError::new_err)?;
    if starts == 0 {
        return Err(PyValueError::new_err(
            "starts = 0: the search needs a start",
        ));
    }
    // The budget of the benchmark cases with free timing
    // (`mechanism-synthesis/examples/synthesis`): 20 candidates screened per
    // start, 30 iterations per local solve.
    let found = py.detach(|| cases::solve(&case, starts, 20, 30, hops, seed));
    if !found.objective.is_finite() {
        return Err(PyValueError::new_err(
            "no design assembled at every target: widen the bounds or move the targets",
        ));
    }
    let out = PyDict::new(py);
    out.set_item("objective", found.objective)?;
    let mode = match found.mode {
        mechanism_core::Mode::Plus => "left",
        mechanism_core::Mode::Minus => "right",
    };
    out.set_item("mode", mode)?;
    let design = PyDict::new(py);
    for (name, value) in DESIGN.iter().zip(&found.design.0) {
        design.set_item(*name, *value)?;
    }
    out.set_item("design", design)?;
    out.set_item("angles", found.design.angles().to_vec())?;
    out.set_item("definition", found.design.definition(found.mode))?;
    out.set_item("evaluations", found.evaluations)?;
    out.set_item("jacobians", found.jacobians)?;
    Ok(out)
}
