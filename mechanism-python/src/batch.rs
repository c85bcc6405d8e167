//! The evaluation behind `solve` and `sweep`, in plain Rust: one row of
//! every asked analysis, and a sweep of rows into columns (one `Vec<f64>`
//! per output), with a per-row error instead of numbers for a pose that
//! fails. No Python object is touched here.

use mechanism_codegen::runtime::{Analysis, Forces, Mechanism, Position, Rates};
use mechanism_core::Error;

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
    pub fn new(m: &Mechanism) -> Self {
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
    m: &Mechanism,
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

/// Every row `i < n` of a sweep: inputs `inputs[j][i]` (one column per
/// input, in `Mechanism::inputs` order, each at least `n` long), rates and
/// accelerations likewise (empty when `depth` does not need them).
pub fn sweep(
    m: &Mechanism,
    inputs: &[Column<'_>],
    rates: &[Column<'_>],
    accels: &[Column<'_>],
    depth: Depth,
    n: usize,
) -> Batch {
    let width = keys(m, depth).len();
    let mut columns: Vec<Vec<f64>> = (0..width).map(|_| Vec::with_capacity(n)).collect();
    let mut errors = Vec::with_capacity(n);
    let (mut q, mut r, mut a) = (Vec::new(), Vec::new(), Vec::new());
    let mut block = Vec::with_capacity(BLOCK * width);
    let mut store = Store::new(m);
    let at = |cols: &[Column<'_>], i: usize, into: &mut Vec<f64>| {
        into.clear();
        into.extend(cols.iter().map(|c| c[i]));
    };
    for start in (0..n).step_by(BLOCK) {
        let rows = start..n.min(start + BLOCK);
        block.clear();
        for i in rows.clone() {
            at(inputs, i, &mut q);
            at(rates, i, &mut r);
            at(accels, i, &mut a);
            match row(m, &q, &r, &a, depth, &mut store, &mut block) {
                Ok(()) => errors.push(None),
                Err(e) => {
                    block.resize(block.len() + width, f64::NAN);
                    errors.push(Some(e.to_string()));
                }
            }
        }
        for (k, col) in columns.iter_mut().enumerate() {
            col.extend(block.iter().skip(k).step_by(width.max(1)).take(rows.len()));
        }
    }
    Batch { columns, errors }
}
