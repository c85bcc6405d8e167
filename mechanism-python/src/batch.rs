//! The evaluation behind `solve` and `sweep`, in plain Rust: one row of
//! every asked analysis, and a sweep of rows into columns (one `Vec<f64>`
//! per output), with a per-row error instead of numbers for a pose that
//! fails. No Python object is touched here.

use mechanism_codegen::runtime::{Analysis, Forces, Mechanism, Position, Rates, Solver};
use mechanism_core::Error;
use std::ops::Range;

/// How deep a solve goes: position always, velocity and acceleration
/// when asked (acceleration needs the velocity).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Depth {
    /// Velocity analysis (needs input rates).
    pub velocity: bool,
    /// Acceleration analysis (needs input rates and accelerations).
    pub acceleration: bool,
    /// Force analysis (needs the acceleration; the definition's masses and
    /// loads at their current values).
    pub forces: bool,
}

/// The key of the velocity's condition number in a combined result.
pub const CONDITION: &str = "velocity.condition";

/// The keys of one row's values, in order: the position columns by their
/// names in the generated structs (`B.x`, `link3`, `s`), then
/// `velocity.NAME` for each velocity column and [`CONDITION`], then
/// `acceleration.NAME`, then `forces.NAME` (the fields of the generated
/// `Solution`).
pub fn keys(m: &Mechanism, depth: Depth) -> Vec<(String, &'static str)> {
    let mut keys: Vec<(String, &'static str)> = m
        .columns(Analysis::Position)
        .into_iter()
        .map(|c| (c.name, c.unit))
        .collect();
    if depth.velocity {
        let cols = m.columns(Analysis::Velocity).into_iter();
        keys.extend(cols.map(|c| (format!("velocity.{}", c.name), c.unit)));
        keys.push((CONDITION.to_string(), "1"));
    }
    if depth.acceleration {
        let cols = m.columns(Analysis::Acceleration).into_iter();
        keys.extend(cols.map(|c| (format!("acceleration.{}", c.name), c.unit)));
    }
    if depth.forces {
        let cols = m.force_columns().into_iter();
        keys.extend(cols.map(|c| (format!("forces.{}", c.name), c.unit)));
    }
    keys
}

/// The storage one row is solved in, made once per sweep (the run-time
/// mechanism's `*_into` methods then allocate nothing per row).
pub struct Store {
    pos: Position,
    vel: Rates,
    acc: Rates,
    forces: Forces,
}

impl Store {
    /// Storage for `m`'s rows.
    pub fn new(m: &Solver) -> Self {
        Store {
            pos: m.new_position(),
            vel: m.new_rates(),
            acc: m.new_rates(),
            forces: m.new_forces(),
        }
    }
}

/// Appends one row's values (in [`keys`] order) to `out` for inputs `q`,
/// input rates `rates` and accelerations `accels` (each one value per
/// input, in the order of `Mechanism::inputs`; unused by a shallower
/// `depth`), solved in `store` (from [`Store::new`] of the same `m`). On
/// an error nothing is appended.
pub fn row(
    m: &Solver,
    q: &[f64],
    rates: &[f64],
    accels: &[f64],
    depth: Depth,
    store: &mut Store,
    out: &mut Vec<f64>,
) -> Result<(), Error<f64>> {
    let Store {
        pos,
        vel,
        acc,
        forces,
    } = store;
    m.position_into(q, pos)?;
    if !depth.velocity {
        out.extend(&pos.values);
        return Ok(());
    }
    m.velocity_into(pos, rates, vel)?;
    if depth.acceleration {
        m.acceleration_into(pos, vel, accels, acc)?;
        if depth.forces {
            m.forces_into(pos, vel, acc, forces)?;
        }
    }
    out.extend(&pos.values);
    out.extend(&vel.values);
    out.push(vel.condition);
    if depth.acceleration {
        out.extend(&acc.values);
        if depth.forces {
            out.extend(&forces.values);
        }
    }
    Ok(())
}

/// A sweep's results: one column per key, one entry per row.
pub struct Batch {
    /// `columns[k][i]`: key `k` at row `i`; NaN where row `i` failed.
    pub columns: Vec<Vec<f64>>,
    /// `errors[i]`: why row `i` failed (the typed error's message, naming
    /// its group), `None` where it was solved.
    pub errors: Vec<Option<String>>,
}

/// The values of one input (or rate, or acceleration) at every row.
pub type Column<'a> = &'a [f64];

/// Rows solved into a row-major block before the block is written out
/// column by column: writing each row's values straight into the columns
/// stores to one stream per output (28 for a four-bar's three analyses),
/// more than the hardware prefetches, and cost more than the solve itself
/// (a four-bar's full sweep took 3.3 times the walk alone); a block of 256
/// rows (56 KiB at that width) stays in the cache and each column then
/// gets a run of 256 values.
const BLOCK: usize = 256;

/// The fewest rows a worker thread of [`par_sweep`] is given. The workers
/// share the definition's compiled [`Solver`], so a worker costs its
/// start and join (tens of microseconds) and its storage; 8192 rows of a
/// four-bar's position sweep take about 2 ms. Measured on 2 logical cores
/// (docs/python.md).
pub const ROWS_PER_THREAD: usize = 8_192;

/// The inputs of a sweep's rows: one column per input, rate and
/// acceleration (in `Mechanism::inputs` order; rates and accelerations
/// empty when the depth does not need them), each at least as long as the
/// sweep.
#[derive(Clone, Copy)]
pub struct Given<'a> {
    /// The inputs' values.
    pub inputs: &'a [Column<'a>],
    /// The inputs' rates.
    pub rates: &'a [Column<'a>],
    /// The inputs' accelerations.
    pub accels: &'a [Column<'a>],
}

/// Rows `rows` of a sweep into `out` (one slice per key of [`keys`], each
/// `rows.len()` long: row `i` at `i - rows.start`) and `errors` (likewise).
fn sweep_rows(
    m: &Solver,
    given: Given<'_>,
    depth: Depth,
    rows: Range<usize>,
    out: &mut [&mut [f64]],
    errors: &mut [Option<String>],
) {
    let width = out.len();
    let (mut q, mut r, mut a) = (Vec::new(), Vec::new(), Vec::new());
    let mut block = Vec::with_capacity(BLOCK * width);
    let mut store = Store::new(m);
    let at = |cols: &[Column<'_>], i: usize, into: &mut Vec<f64>| {
        into.clear();
        into.extend(cols.iter().map(|c| c[i]));
    };
    for start in rows.clone().step_by(BLOCK) {
        let here = start - rows.start..rows.end.min(start + BLOCK) - rows.start;
        block.clear();
        for (i, error) in (start..).zip(&mut errors[here.clone()]) {
            at(given.inputs, i, &mut q);
            at(given.rates, i, &mut r);
            at(given.accels, i, &mut a);
            *error = match row(m, &q, &r, &a, depth, &mut store, &mut block) {
                Ok(()) => None,
                Err(e) => {
                    block.resize(block.len() + width, f64::NAN);
                    Some(e.to_string())
                }
            };
        }
        for (k, col) in out.iter_mut().enumerate() {
            let values = block.iter().skip(k).step_by(width.max(1));
            for (dst, src) in col[here.clone()].iter_mut().zip(values) {
                *dst = *src;
            }
        }
    }
}

/// Columns for `n` rows of `width` keys, and their errors. Zeros, which
/// the allocator gives as untouched zeroed pages (every row is written
/// before the batch is returned).
fn columns(width: usize, n: usize) -> Batch {
    Batch {
        columns: (0..width).map(|_| vec![0.0; n]).collect(),
        errors: vec![None; n],
    }
}

/// Every row `i < n` of a sweep, on the calling thread.
pub fn sweep(m: &Mechanism, given: Given<'_>, depth: Depth, n: usize) -> Batch {
    let mut batch = columns(keys(m, depth).len(), n);
    let mut out: Vec<&mut [f64]> = batch.columns.iter_mut().map(Vec::as_mut_slice).collect();
    sweep_rows(m.solver(), given, depth, 0..n, &mut out, &mut batch.errors);
    batch
}

/// Every row `i < n` of a sweep of `m` on `threads` threads (at least one;
/// each given a contiguous run of whole blocks), started here and joined
/// before it returns: no pool outlives the call, so a process that forks
/// later (Python's multiprocessing) inherits no thread. The threads share
/// `m`'s compiled [`Solver`] (`Send + Sync`); the rows are the same numbers
/// as [`sweep`]'s, bit for bit. `Err`: a thread panicked (none does: the
/// rows' errors are values).
pub fn par_sweep(
    m: &Mechanism,
    given: Given<'_>,
    depth: Depth,
    n: usize,
    threads: usize,
) -> Result<Batch, String> {
    let (solver, width) = (m.solver(), keys(m, depth).len());
    let chunk = n.div_ceil(threads.max(1)).div_ceil(BLOCK).max(1) * BLOCK;
    let mut batch = columns(width, n);
    let pieces = n.div_ceil(chunk);
    let mut outs: Vec<Vec<&mut [f64]>> = (0..pieces).map(|_| Vec::new()).collect();
    for col in &mut batch.columns {
        for (out, piece) in outs.iter_mut().zip(col.chunks_mut(chunk)) {
            out.push(piece);
        }
    }
    let joined: Vec<bool> = std::thread::scope(|s| {
        let workers: Vec<_> = outs
            .into_iter()
            .zip(batch.errors.chunks_mut(chunk))
            .enumerate()
            .map(|(k, (mut out, errors))| {
                let rows = k * chunk..k * chunk + errors.len();
                s.spawn(move || sweep_rows(solver, given, depth, rows, &mut out, errors))
            })
            .collect();
        workers.into_iter().map(|w| w.join().is_ok()).collect()
    });
    if joined.iter().all(|&ok| ok) {
        Ok(batch)
    } else {
        Err("a sweep thread failed".into())
    }
}
