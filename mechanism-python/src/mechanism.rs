//! The class `planar_mechanism.Mechanism`: a definition read at run time,
//! its inputs, outputs, parameters and modes, and its solutions at one
//! pose (dicts of floats) or over a sweep (dicts of numpy arrays).

use crate::batch::{self, Depth};
use crate::errors;
use crate::shared::Shared;
use mechanism_codegen::runtime::{self, Analysis};
use mechanism_plot::runtime as picture;
use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::exceptions::{PyKeyError, PyRuntimeError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString, PyTuple};

/// A driver input of a definition.
#[pyclass(frozen, get_all, module = "planar_mechanism")]
#[derive(Clone)]
pub struct Input {
    /// Its name: the keyword of `position(...)` and `sweep(...)`.
    name: String,
    /// `"rad"` for an angle, `"L"` for a length (the definition's unit).
    unit: &'static str,
    /// The range the definition declares or implies (a crank's full turn,
    /// `(0, 2*pi)`), `(lo, hi)` in `unit`; `None` when it has none.
    range: Option<(f64, f64)>,
}

#[pymethods]
impl Input {
    fn __repr__(&self) -> String {
        let range = match self.range {
            Some((lo, hi)) => format!("({lo}, {hi})"),
            None => "None".into(),
        };
        format!(
            "Input(name={:?}, unit={:?}, range={range})",
            self.name, self.unit
        )
    }
}

/// A planar mechanism read from the text of a definition.
///
/// `text` is what goes between the braces of `mechanism! { ... }` (or the
/// whole `pub Name { ... }` item). Angles are in rad, counter-clockwise
/// from +x; lengths in the definition's unit `L`; rates per second.
/// A definition that does not read raises `MechanismError` with every
/// diagnostic. Usable from any thread (each keeps its own solver copy).
#[pyclass(frozen, module = "planar_mechanism")]
pub struct Mechanism {
    shared: Shared,
    /// The input names, in input order (fixed once read).
    names: Vec<String>,
    /// The columns of position, velocity and acceleration (fixed once read:
    /// parameters and modes change values, not outputs).
    columns: [Vec<runtime::Column>; 3],
}

/// The analysis named `name`.
fn analysis(name: &str) -> PyResult<Analysis> {
    match name {
        "position" => Ok(Analysis::Position),
        "velocity" => Ok(Analysis::Velocity),
        "acceleration" => Ok(Analysis::Acceleration),
        _ => Err(PyValueError::new_err(format!(
            "no analysis `{name}`; the analyses are: `position`, `velocity`, `acceleration`, `forces`"
        ))),
    }
}

/// The depth that `rates` and `accels` ask for.
fn depth(rates: bool, accels: bool, forces: bool) -> PyResult<Depth> {
    if accels && !rates {
        return Err(PyTypeError::new_err(
            "`accels` needs `rates` too (the acceleration is solved from the velocity)",
        ));
    }
    if forces && !accels {
        return Err(PyTypeError::new_err(
            "`forces=True` needs `rates` and `accels` (the force analysis is solved from the acceleration)",
        ));
    }
    Ok(Depth {
        velocity: rates,
        acceleration: accels,
        forces,
    })
}

impl Mechanism {
    /// `f` of this thread's run-time mechanism.
    fn rt<R>(&self, f: impl FnOnce(&runtime::Mechanism) -> R) -> PyResult<R> {
        self.shared.with(|m| f(m)).map_err(PyRuntimeError::new_err)
    }

    /// The input names, in the order of the generated input struct.
    fn input_names(&self) -> &[String] {
        &self.names
    }

    /// The columns of `analysis`.
    fn cols(&self, analysis: Analysis) -> &[runtime::Column] {
        let k = match analysis {
            Analysis::Position => 0,
            Analysis::Velocity => 1,
            Analysis::Acceleration => 2,
        };
        &self.columns[k]
    }

    /// The value `given` holds for each input, in input order: a
    /// `TypeError` naming a missing or unknown input (`what`: "value",
    /// "rate", "acceleration").
    fn ordered<'py>(
        &self,
        what: &str,
        given: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<Vec<Bound<'py, PyAny>>> {
        let names = self.input_names();
        let list = || {
            let v: Vec<String> = names.iter().map(|n| format!("`{n}`")).collect();
            v.join(", ")
        };
        let mut out = Vec::with_capacity(names.len());
        for n in names {
            match given.map(|d| d.get_item(n)).transpose()?.flatten() {
                Some(v) => out.push(v),
                None => {
                    return Err(PyTypeError::new_err(format!(
                        "missing {what} for input `{n}`; the inputs are: {}",
                        list()
                    )))
                }
            }
        }
        if let Some(d) = given {
            for k in d.keys() {
                let k: String = k.extract()?;
                if !names.contains(&k) {
                    return Err(PyTypeError::new_err(format!(
                        "no input `{k}`; the inputs are: {}",
                        list()
                    )));
                }
            }
        }
        Ok(out)
    }

    /// The floats `given` holds for each input, in input order.
    fn floats(&self, what: &str, given: Option<&Bound<'_, PyDict>>) -> PyResult<Vec<f64>> {
        self.ordered(what, given)?
            .iter()
            .map(|v| v.extract::<f64>())
            .collect()
    }

    /// A `ValueError` when `forces` is asked of a definition without a
    /// force analysis.
    fn need_forces(&self, forces: bool) -> PyResult<()> {
        if forces && !self.rt(runtime::Mechanism::has_forces)? {
            return Err(PyValueError::new_err(
                "the definition has no force analysis: give it masses, loads or `analysis forces;`",
            ));
        }
        Ok(())
    }

    /// The error of a pose that fails at inputs `q`.
    fn pose_error(&self, py: Python<'_>, e: &mechanism_core::Error<f64>, q: &[f64]) -> PyErr {
        let names = self.input_names().iter().cloned();
        let at: Vec<(String, f64)> = names.zip(q.iter().copied()).collect();
        errors::pose(py, e, &at)
    }

    /// `{name: value}` of `analysis`' columns and `values`.
    fn named<'py>(
        &self,
        py: Python<'py>,
        analysis: Analysis,
        values: &[f64],
    ) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (c, v) in self.cols(analysis).iter().zip(values) {
            d.set_item(&c.name, v)?;
        }
        Ok(d)
    }

    /// Position, then velocity and acceleration when asked, at one pose.
    fn solve_one(
        &self,
        py: Python<'_>,
        q: &[f64],
        rates: &[f64],
        accels: &[f64],
        depth: Depth,
    ) -> PyResult<Vec<f64>> {
        let mut values = Vec::new();
        self.rt(|m| {
            let mut store = batch::Store::new(m.solver());
            batch::row(m.solver(), q, rates, accels, depth, &mut store, &mut values)
        })?
        .map_err(|e| self.pose_error(py, &e, q))?;
        Ok(values)
    }
}

#[pymethods]
impl Mechanism {
    #[new]
    fn new(py: Python<'_>, text: &str) -> PyResult<Self> {
        let shared = Shared::new(text).map_err(|e| errors::definition(py, &e))?;
        let (names, columns) = shared
            .with(|m| {
                let names = m.inputs().into_iter().map(|i| i.name).collect();
                let columns = [
                    m.columns(Analysis::Position),
                    m.columns(Analysis::Velocity),
                    m.columns(Analysis::Acceleration),
                ];
                (names, columns)
            })
            .map_err(PyRuntimeError::new_err)?;
        Ok(Mechanism {
            shared,
            names,
            columns,
        })
    }

    /// The type name of the definition (`"Mechanism"` for a body alone).
    #[getter]
    fn name(&self) -> PyResult<String> {
        self.rt(runtime::Mechanism::name)
    }

    /// The driver inputs, in the order of the generated input struct.
    #[getter]
    fn inputs(&self) -> PyResult<Vec<Input>> {
        let inputs = self.rt(runtime::Mechanism::inputs)?;
        Ok(inputs
            .into_iter()
            .map(|i| Input {
                name: i.name,
                unit: if i.angle { "rad" } else { "L" },
                range: i.range,
            })
            .collect())
    }

    /// The position outputs `{name: unit}`, in the order of the generated
    /// struct's fields: points (`"B.x"`, `"B.y"`, unit `"L"`), link angles
    /// (`"link3"`, `"rad"`), slides (`"s"`, `"L"`).
    #[getter]
    fn outputs<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        self.columns(py, "position")
    }

    /// The outputs `{name: unit}` of `analysis` (`"position"`,
    /// `"velocity"`: `"L/s"`, `"rad/s"`, or `"acceleration"`: `"L/s^2"`,
    /// `"rad/s^2"`), names as in the generated structs.
    fn columns<'py>(&self, py: Python<'py>, analysis: &str) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        if analysis == "forces" {
            for c in self.rt(runtime::Mechanism::force_columns)? {
                d.set_item(c.name, c.unit)?;
            }
            return Ok(d);
        }
        let analysis = self::analysis(analysis)?;
        for c in self.cols(analysis) {
            d.set_item(&c.name, c.unit)?;
        }
        Ok(d)
    }

    /// The run-time parameters `{name: value}` (a copy; change them with
    /// `set_param`).
    #[getter]
    fn params<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        number_dict(py, self.rt(runtime::Mechanism::params)?)
    }

    /// Sets the parameter `name` to `value` (finite; in the unit the
    /// definition uses it in). `KeyError` for an unknown name,
    /// `ValueError` for a value that is not finite.
    fn set_param(&self, name: &str, value: f64) -> PyResult<()> {
        let known = self.rt(|m| m.params().iter().any(|(n, _)| n == name))?;
        self.shared
            .set_param(name, value)
            .map_err(|msg| value_or_key_error(known, msg))
    }

    /// The run-time assembly modes `{name: "plus" | "minus"}` (`"plus"`
    /// is `left`, `"minus"` is `right`; see docs/assembly-modes.md).
    #[getter]
    fn modes<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (n, plus) in self.rt(runtime::Mechanism::modes)? {
            d.set_item(n, if plus { "plus" } else { "minus" })?;
        }
        Ok(d)
    }

    /// Sets the run-time mode `name` to `"left"`/`"plus"` or
    /// `"right"`/`"minus"`. `KeyError` for an unknown name, `ValueError`
    /// for another word.
    fn set_mode(&self, name: &str, mode: &str) -> PyResult<()> {
        let plus = match mode {
            "left" | "plus" => true,
            "right" | "minus" => false,
            _ => {
                return Err(PyValueError::new_err(format!(
                "`{mode}` is not a mode; the modes are `left` (= `plus`) and `right` (= `minus`)"
            )))
            }
        };
        self.shared
            .set_mode(name, plus)
            .map_err(PyKeyError::new_err)
    }

    /// `True` when the definition has a force analysis (masses, loads or
    /// `analysis forces;`): `forces`, `solve(forces=True)`,
    /// `sweep(forces=True)`.
    #[getter]
    fn has_forces(&self) -> PyResult<bool> {
        self.rt(runtime::Mechanism::has_forces)
    }

    /// The loads `{name: value}` of the definition's `loads { .. }` (a
    /// copy; change them with `set_load`).
    #[getter]
    fn loads<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        number_dict(py, self.rt(runtime::Mechanism::loads)?)
    }

    /// Sets the load `name` to `value` (finite; in the units the definition
    /// uses it in). `KeyError` for an unknown name, `ValueError` for a value
    /// that is not finite.
    fn set_load(&self, name: &str, value: f64) -> PyResult<()> {
        let known = self.rt(|m| m.loads().iter().any(|(n, _)| n == name))?;
        self.shared
            .set_load(name, value)
            .map_err(|msg| value_or_key_error(known, msg))
    }

    /// The force analysis at the inputs given by name, for the input rates
    /// `rates` and accelerations `accels` (one per input each), with the
    /// current loads: `{name: value}` as `columns("forces")`: each joint
    /// reaction `r_FROM_TO.x`, `.y` (force on TO from FROM), prismatic ones
    /// `.force.x`, `.force.y`, `.moment`, each driving torque or force by
    /// its name, `condition` and `power_residual`. Signs and units:
    /// docs/dynamics.md. `ValueError` without a force analysis.
    #[pyo3(signature = (*, rates, accels, **inputs))]
    fn forces<'py>(
        &self,
        py: Python<'py>,
        rates: &Bound<'py, PyDict>,
        accels: &Bound<'py, PyDict>,
        inputs: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        self.need_forces(true)?;
        let q = self.floats("value", inputs)?;
        let r = self.floats("rate", Some(rates))?;
        let a = self.floats("acceleration", Some(accels))?;
        let d = depth(true, true, true)?;
        let values = self.solve_one(py, &q, &r, &a, d)?;
        let skip = self.cols(Analysis::Position).len()
            + self.cols(Analysis::Velocity).len()
            + 1
            + self.cols(Analysis::Acceleration).len();
        let out = PyDict::new(py);
        let cols = self.rt(runtime::Mechanism::force_columns)?;
        for (c, v) in cols.iter().zip(&values[skip..]) {
            out.set_item(&c.name, v)?;
        }
        Ok(out)
    }

    /// The position at the inputs given by name (`theta=0.5`; rad or L):
    /// `{name: value}` as `outputs`. `PoseError` where it cannot be
    /// assembled; `TypeError` for a missing or unknown input.
    #[pyo3(signature = (**inputs))]
    fn position<'py>(
        &self,
        py: Python<'py>,
        inputs: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let q = self.floats("value", inputs)?;
        let pos = self
            .rt(|m| m.position(&q).map(|p| p.values))?
            .map_err(|e| self.pose_error(py, &e, &q))?;
        self.named(py, Analysis::Position, &pos)
    }

    /// The drawing of the pose at the inputs given by name (`theta=0.5`;
    /// rad or L), as SVG text: ground pivots with hatching, links as bars
    /// or plates, blocks on their guides, joints as circles, in the
    /// definition's length unit with y up. `title`: its title (default the
    /// definition's name); `trace`: points to mark. `PoseError` where the
    /// pose cannot be assembled; `TypeError` for a missing or unknown input;
    /// `ValueError` for a point to trace that does not exist.
    #[pyo3(signature = (*, title = None, trace = Vec::new(), **inputs))]
    fn draw<'py>(
        &self,
        py: Python<'py>,
        title: Option<String>,
        trace: Vec<String>,
        inputs: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<String> {
        let q = self.floats("value", inputs)?;
        self.rt(|m| {
            let pos = m.position(&q).map_err(|e| self.pose_error(py, &e, &q))?;
            let title = title.unwrap_or_else(|| m.name());
            let poses = vec![(picture::caption(m, &q), Some(pos))];
            let sketch =
                picture::sketch(m, &title, &poses, &trace).map_err(PyValueError::new_err)?;
            sketch
                .drawing(0)
                .map_err(|e| PyValueError::new_err(e.to_string()))
        })?
    }

    /// The animation of the poses at the inputs given by name, each a
    /// number or a 1-d array (broadcast together as numpy does), as SVG
    /// text that plays once in `seconds` and repeats: the drawing of
    /// `draw` at each pose that assembles (the others are left out), the
    /// `trace`d points' paths. `ValueError` when no pose assembles or a
    /// point to trace does not exist.
    #[pyo3(signature = (*, seconds = 4.0, title = None, trace = Vec::new(), **inputs))]
    fn animate<'py>(
        &self,
        py: Python<'py>,
        seconds: f64,
        title: Option<String>,
        trace: Vec<String>,
        inputs: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<String> {
        let given = self.ordered("values", inputs)?;
        let (_, flat) = broadcast(py, &given)?;
        let columns: Vec<&[f64]> = flat
            .iter()
            .map(|a| a.as_slice())
            .collect::<Result<_, _>>()?;
        let n = columns.first().map_or(1, |c| c.len());
        let points: Vec<Vec<f64>> = (0..n)
            .map(|i| columns.iter().map(|c| c[i]).collect())
            .collect();
        self.rt(|m| {
            let poses = picture::poses(m, &points, &|| {});
            let title = title.unwrap_or_else(|| m.name());
            let sketch =
                picture::sketch(m, &title, &poses, &trace).map_err(PyValueError::new_err)?;
            sketch
                .animation(seconds)
                .map_err(|e| PyValueError::new_err(e.to_string()))
        })?
    }

    /// The velocity at the inputs given by name, for the input rates
    /// `rates` (`{name: rate}`, rad/s or L/s, one per input):
    /// `{name: value}` as `columns("velocity")`, and `"condition"`: the
    /// smallest scaled determinant of the groups' velocity systems, in
    /// (0, 1] (near 0: near a singular pose).
    #[pyo3(signature = (*, rates, **inputs))]
    fn velocity<'py>(
        &self,
        py: Python<'py>,
        rates: &Bound<'py, PyDict>,
        inputs: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let q = self.floats("value", inputs)?;
        let r = self.floats("rate", Some(rates))?;
        let d = Depth {
            velocity: true,
            acceleration: false,
            forces: false,
        };
        let values = self.solve_one(py, &q, &r, &[], d)?;
        let skip = self.cols(Analysis::Position).len();
        let width = self.cols(Analysis::Velocity).len();
        let d = self.named(py, Analysis::Velocity, &values[skip..skip + width])?;
        d.set_item("condition", values[skip + width])?;
        Ok(d)
    }

    /// The acceleration at the inputs given by name, for the input rates
    /// `rates` and accelerations `accels` (rad/s^2 or L/s^2), each a
    /// `{name: value}` with one entry per input: `{name: value}` as
    /// `columns("acceleration")`.
    #[pyo3(signature = (*, rates, accels, **inputs))]
    fn acceleration<'py>(
        &self,
        py: Python<'py>,
        rates: &Bound<'py, PyDict>,
        accels: &Bound<'py, PyDict>,
        inputs: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let q = self.floats("value", inputs)?;
        let r = self.floats("rate", Some(rates))?;
        let a = self.floats("acceleration", Some(accels))?;
        let d = Depth {
            velocity: true,
            acceleration: true,
            forces: false,
        };
        let values = self.solve_one(py, &q, &r, &a, d)?;
        let skip = self.cols(Analysis::Position).len() + self.cols(Analysis::Velocity).len() + 1;
        self.named(py, Analysis::Acceleration, &values[skip..])
    }

    /// Every analysis asked for at one pose, as one flat dict with the
    /// keys of `sweep` (without the inputs, `ok` and `error`): position
    /// names, then with `rates` `velocity.NAME` and `velocity.condition`,
    /// then with `accels` `acceleration.NAME`, then with `forces=True`
    /// `forces.NAME` (the keys of `columns("forces")`).
    #[pyo3(signature = (*, rates=None, accels=None, forces=false, **inputs))]
    fn solve<'py>(
        &self,
        py: Python<'py>,
        rates: Option<&Bound<'py, PyDict>>,
        accels: Option<&Bound<'py, PyDict>>,
        forces: bool,
        inputs: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let depth = depth(rates.is_some(), accels.is_some(), forces)?;
        self.need_forces(forces)?;
        let q = self.floats("value", inputs)?;
        let r = match rates {
            Some(_) => self.floats("rate", rates)?,
            None => Vec::new(),
        };
        let a = match accels {
            Some(_) => self.floats("acceleration", accels)?,
            None => Vec::new(),
        };
        let values = self.solve_one(py, &q, &r, &a, depth)?;
        let d = PyDict::new(py);
        for ((k, _), v) in self.rt(|m| batch::keys(m, depth))?.iter().zip(&values) {
            d.set_item(k, v)?;
        }
        Ok(d)
    }

    /// Solves every pose of a sweep in Rust (no Python call per pose) and
    /// returns numpy arrays.
    ///
    /// Every input by name, each a number or an array (rad or L); with
    /// `rates` (`{name: rate}`, rad/s or L/s) the velocity, with `accels`
    /// (needs `rates`) the acceleration too. Inputs, rates and accelerations
    /// broadcast together as numpy broadcasts (`np.meshgrid` for a grid);
    /// every returned array has that shape: each input (a copy), each
    /// position output, `velocity.NAME` and `velocity.condition`,
    /// `acceleration.NAME`, with `forces=True` (needs `accels`)
    /// `forces.NAME`, and `ok` (bool, False where the pose failed)
    /// and `error` (object: None, or the message naming the failed group).
    /// A failed pose has NaN in every output of its row and only there; a
    /// solved pose never holds NaN. The GIL is released while it solves.
    /// `threads`: how many threads solve it (`None`: one per core, each
    /// given at least `batch::ROWS_PER_THREAD` rows; 1: the calling thread
    /// only); the threads end with the call. The numbers do not depend on
    /// it.
    #[pyo3(signature = (*, rates=None, accels=None, forces=false, threads=None, **inputs))]
    fn sweep<'py>(
        &self,
        py: Python<'py>,
        rates: Option<&Bound<'py, PyDict>>,
        accels: Option<&Bound<'py, PyDict>>,
        forces: bool,
        threads: Option<usize>,
        inputs: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        if threads == Some(0) {
            return Err(PyValueError::new_err(
                "threads must be at least 1 (or None: one per core)",
            ));
        }
        let depth = depth(rates.is_some(), accels.is_some(), forces)?;
        self.need_forces(forces)?;
        let mut given = self.ordered("values", inputs)?;
        let k = given.len();
        if let Some(r) = rates {
            given.extend(self.ordered("rate", Some(r))?);
        }
        if let Some(a) = accels {
            given.extend(self.ordered("acceleration", Some(a))?);
        }
        let (shape, flat) = broadcast(py, &given)?;
        // Owned copies: another Python thread may write the caller's arrays
        // (`ravel` can return a view of them) while this one solves.
        let owned: Vec<Vec<f64>> = flat
            .iter()
            .map(|a| a.as_slice().map(<[f64]>::to_vec))
            .collect::<Result<_, _>>()?;
        let slices: Vec<&[f64]> = owned.iter().map(Vec::as_slice).collect();
        let n = shape.iter().product();
        let (q, rest) = slices.split_at(k);
        let (r, a) = rest.split_at(if depth.velocity { k } else { 0 });
        let given = batch::Given {
            inputs: q,
            rates: r,
            accels: a,
        };
        let threads = threads.unwrap_or_else(|| {
            let cores = std::thread::available_parallelism().map_or(1, usize::from);
            cores.min(n / batch::ROWS_PER_THREAD).max(1)
        });
        // The solve needs no Python object: other Python threads run meanwhile.
        let batch = py
            .detach(|| {
                self.rt(|m| {
                    if threads == 1 {
                        Ok(batch::sweep(m, given, depth, n))
                    } else {
                        batch::par_sweep(m, given, depth, n, threads)
                    }
                })
            })?
            .map_err(PyRuntimeError::new_err)?;
        self.sweep_dict(py, &shape, &flat[..k], batch, depth)
    }

    fn __repr__(&self) -> PyResult<String> {
        self.rt(|m| {
            let names: Vec<String> = m.inputs().into_iter().map(|i| i.name).collect();
            format!(
                "<planar_mechanism.Mechanism {} inputs=[{}], {} outputs>",
                m.name(),
                names.join(", "),
                m.columns(Analysis::Position).len()
            )
        })
    }
}

/// The common shape of `given` (numpy broadcasting; scalars and arrays of
/// any shape) and each one as a contiguous 1-D float64 array of that
/// shape's size.
fn broadcast<'py>(
    py: Python<'py>,
    given: &[Bound<'py, PyAny>],
) -> PyResult<(Vec<usize>, Vec<PyReadonlyArray1<'py, f64>>)> {
    let np = py.import("numpy")?;
    let float64 = np.getattr("float64")?;
    let arrays = given
        .iter()
        .map(|g| np.call_method1("asarray", (g, &float64)))
        .collect::<PyResult<Vec<_>>>()?;
    let broadcast = np.call_method1("broadcast_arrays", PyTuple::new(py, arrays)?)?;
    let mut shape: Vec<usize> = Vec::new();
    let mut flat = Vec::with_capacity(given.len());
    for (j, b) in broadcast.try_iter()?.enumerate() {
        let b = b?;
        if j == 0 {
            shape = b.getattr("shape")?.extract()?;
        }
        // `ravel` of a broadcast (strided) view copies into a new array.
        let c = np
            .call_method1("ascontiguousarray", (b,))?
            .call_method0("ravel")?;
        flat.push(c.extract::<PyReadonlyArray1<'py, f64>>()?);
    }
    Ok((shape, flat))
}

impl Mechanism {
    /// The dict `sweep` returns: each input (a copy, broadcast to
    /// `shape`), each key of [`batch::keys`], `ok` and `error`.
    fn sweep_dict<'py>(
        &self,
        py: Python<'py>,
        shape: &[usize],
        inputs: &[PyReadonlyArray1<'py, f64>],
        batch: batch::Batch,
        depth: Depth,
    ) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        let reshape = |a: Bound<'py, PyAny>| a.call_method1("reshape", (shape.to_vec(),));
        for (name, a) in self.input_names().iter().zip(inputs) {
            d.set_item(name, reshape(a.as_any().call_method0("copy")?)?)?;
        }
        let keys = self.rt(|m| batch::keys(m, depth))?;
        for ((key, _), col) in keys.into_iter().zip(batch.columns) {
            if d.contains(&key)? {
                return Err(clash(&key));
            }
            d.set_item(key, reshape(PyArray1::from_vec(py, col).into_any())?)?;
        }
        let ok: Vec<bool> = batch.errors.iter().map(Option::is_none).collect();
        let error: Vec<Py<PyAny>> = batch
            .errors
            .into_iter()
            .map(|e| match e {
                Some(msg) => PyString::new(py, &msg).into_any().unbind(),
                None => py.None(),
            })
            .collect();
        for key in ["ok", "error"] {
            if d.contains(key)? {
                return Err(clash(key));
            }
        }
        d.set_item("ok", reshape(PyArray1::from_vec(py, ok).into_any())?)?;
        d.set_item("error", reshape(PyArray1::from_vec(py, error).into_any())?)?;
        Ok(d)
    }
}

/// Two entries of a sweep's dict would have the same key.
fn clash(key: &str) -> PyErr {
    PyValueError::new_err(format!(
        "the sweep's result would hold `{key}` twice (an input or output named like \
         another, or `ok`/`error`); rename it in the definition"
    ))
}

/// `{name: value}` of named numbers (parameters, loads) as a new dict.
fn number_dict(py: Python<'_>, pairs: Vec<(String, f64)>) -> PyResult<Bound<'_, PyDict>> {
    let d = PyDict::new(py);
    for (n, v) in pairs {
        d.set_item(n, v)?;
    }
    Ok(d)
}

/// A refused setting: `ValueError` when the name is `known` (the value was
/// bad), `KeyError` when it is not.
fn value_or_key_error(known: bool, msg: String) -> PyErr {
    if known {
        PyValueError::new_err(msg)
    } else {
        PyKeyError::new_err(msg)
    }
}
