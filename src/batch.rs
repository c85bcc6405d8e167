//! Batches: the generated `solve_batch` works on a structure of arrays
//! (`<Name>Batch`, borrowed slices), which implements [`BatchSplit`] so that
//! a sweep can be cut into pieces, e.g. over cores with `par_solve`
//! (feature `rayon`). Every slice of a batch must have the same length:
//! `solve_batch`, [`BatchSplit::check`] and `par_solve` return a
//! [`BatchError`] naming the first slice that does not, before evaluating
//! anything.
//!
//! # The force analysis
//!
//! A definition with masses or loads also gets `<Name>ForcesBatch` (its
//! kinematic `<Name>Batch` as the field `batch`, the run-time loads per
//! element as `load_*` slices, one output slice per scalar of
//! `<Name>Forces`) and `<Name>::solve_batch_forces`, which evaluates every
//! element through the scalar `solve` path (status 4: the force analysis
//! failed). It implements [`BatchSplit`] too, splitting its kinematic batch
//! at the same index.
//!
//! # Columns that never change
//!
//! No slice is generated for what the caller has or what never changes:
//! ground points, crank links (their angle is the input), the angle of a
//! link that does not turn (a block on a fixed guide) and points that do
//! not move. The scalar `position` has them.
//!
//! # The owned form (feature `alloc`)
//!
//! With the feature `alloc` (on by default through `std`), `mechanism!` also
//! emits `<Name>Columns<T>`: the same fields as `Vec<T>` (and `Vec<u8>` for
//! `status`), `<Name>::batch(n)` to make one of `n` zeroed elements,
//! `as_batch()` to borrow it as a `<Name>Batch`, and
//! `<Name>::solve_columns(&mut columns)` (with the force analysis, when the
//! definition has one, and `as_forces_batch()`, `forces_at(k)`). Without `alloc` (embedded builds:
//! `default-features = false`) none of these exist and nothing allocates.
//!
//! The generated code cannot test this crate's features with `cfg` (that
//! would test the features of the crate invoking `mechanism!`), so it wraps
//! the owned items in the hidden macro `__with_alloc!`, which this crate
//! defines to emit its input when `alloc` is on and nothing otherwise; the
//! items name `Vec` through the hidden re-export `__alloc`.

use core::fmt;

/// The slices of a batch do not all have the same length: `slice` has `len`
/// elements where `reference` (the batch's first input slice, or `status`
/// for a definition without input) has `expected`. Returned before any
/// element is evaluated (no output slice is written).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub struct BatchError {
    /// The field name of the slice whose length differs, e.g. `"pos_B_x"`.
    pub slice: &'static str,
    /// Its length (elements).
    pub len: usize,
    /// The field name of the slice that sets the batch's length, e.g.
    /// `"in_theta2"`.
    pub reference: &'static str,
    /// The batch's length: the length of `reference` (elements).
    pub expected: usize,
}

impl BatchError {
    /// `slice` has `len` elements, `reference` has `expected`.
    pub const fn length_mismatch(
        slice: &'static str,
        len: usize,
        reference: &'static str,
        expected: usize,
    ) -> Self {
        BatchError {
            slice,
            len,
            reference,
            expected,
        }
    }
}

impl fmt::Display for BatchError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "batch slice `{}` has {} elements but `{}` has {}: every slice of a batch needs the same length",
            self.slice, self.len, self.reference, self.expected
        )
    }
}

impl core::error::Error for BatchError {}

/// A batch of independent evaluations that can be split in two.
pub trait BatchSplit: Sized + Send {
    /// Number of elements: the length of the slice that sets it (see
    /// [`BatchError::reference`]).
    fn len(&self) -> usize;
    /// `true` when there is no element.
    fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// The number of elements when every slice has the same length, the
    /// first slice that does not otherwise.
    fn check(&self) -> Result<usize, BatchError>;
    /// The first `mid` elements and the rest (`mid` is clamped to the
    /// shortest slice's length, so a batch that fails [`Self::check`] does
    /// not panic here; its pieces fail it too).
    fn split_at(self, mid: usize) -> (Self, Self);
}

/// The smallest piece `par_solve` hands to a thread, in elements.
///
/// Chosen from `benches/par_batch.rs` (the table is in
/// `docs/performance.md`, "Over many cores"): on the four-bar's batch (18
/// output columns) two pieces beat one thread from about 2000 elements per
/// piece in `f64` and 2000 to 4000 in `f32` (the cheaper elements), and
/// smaller pieces lose up to 25 % to waking and joining a worker. 4096 is
/// twice the `f32` break-even piece: below 8192 elements `par_solve` runs on
/// the calling thread. A mechanism whose elements are cheaper than the
/// four-bar's (fewer groups or outputs) passes a larger `min_len`.
#[cfg(feature = "rayon")]
pub const PAR_MIN_PIECE: usize = 4096;

/// Solves `batch` with `solve` over rayon's thread pool and returns the sum
/// of what `solve` returns (with `solve_batch`: the number of failed
/// elements). Feature `rayon` (needs `std`).
///
/// The batch is cut into at most one piece per thread of the pool, each of
/// at least `max(min_len, PAR_MIN_PIECE)` elements, and of equal size (to
/// one element); a batch too small for two such pieces, or a pool of one
/// thread, is solved on the calling thread, so that the call is never much
/// slower than `solve(batch)` (see [`PAR_MIN_PIECE`]). `min_len` can only
/// raise the piece size (for a mechanism whose elements are cheaper than
/// the four-bar's); pass 0 for the default.
///
/// # Errors
///
/// The [`BatchError`] of [`BatchSplit::check`] when the slices of `batch`
/// differ in length, before `solve` is called on any piece; otherwise the
/// first error `solve` returns.
///
/// ```
/// use mechanism::mechanism;
///
/// mechanism! {
///     pub FourBar {
///         params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
///         analysis position;
///         outputs { B }
///         let O2 = ground(0.0, 0.0);
///         let O4 = ground(ground, 0.0);
///         let A = crank(O2, crank, theta2) as link2;
///         let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
///     }
/// }
///
/// let n = 100_000;
/// let theta: Vec<f64> = (0..n).map(|k| k as f64 * 1e-4).collect(); // rad
/// let (mut bx, mut by, mut status) = (vec![0.0; n], vec![0.0; n], vec![0u8; n]);
/// let batch = FourBarBatch {
///     in_theta2: &theta,
///     pos_B_x: &mut bx,
///     pos_B_y: &mut by,
///     status: &mut status,
/// };
/// let fb = FourBar::<f64>::default();
/// let failed = mechanism::par_solve(batch, 0, &|mut piece| fb.solve_batch(&mut piece))?;
/// assert_eq!(failed, 0);
/// // Every element was solved: B lies right of the crank pivot (x >= 127 mm).
/// assert!(bx.iter().all(|&x| x > 100.0));
/// # Ok::<(), mechanism::BatchError>(())
/// ```
#[cfg(feature = "rayon")]
pub fn par_solve<B, F>(batch: B, min_len: usize, solve: &F) -> Result<usize, BatchError>
where
    B: BatchSplit,
    F: Fn(B) -> Result<usize, BatchError> + Sync,
{
    batch.check()?;
    let piece = min_len.max(PAR_MIN_PIECE);
    let pieces = (batch.len() / piece).min(rayon::current_num_threads());
    solve_in_pieces(batch, pieces.max(1), solve)
}

/// Solves `batch` in `pieces` pieces of equal size (to one element), in
/// parallel: halves the pieces at each level of `rayon::join`.
#[cfg(feature = "rayon")]
fn solve_in_pieces<B, F>(batch: B, pieces: usize, solve: &F) -> Result<usize, BatchError>
where
    B: BatchSplit,
    F: Fn(B) -> Result<usize, BatchError> + Sync,
{
    if pieces <= 1 {
        return solve(batch);
    }
    let n = batch.len();
    let left = pieces / 2;
    // n * left / pieces without overflow (left < pieces).
    let mid = n / pieces * left + n % pieces * left / pieces;
    let (lo, hi) = batch.split_at(mid);
    let (a, b) = rayon::join(
        || solve_in_pieces(lo, left, solve),
        || solve_in_pieces(hi, pieces - left, solve),
    );
    Ok(a? + b?)
}

/// Emits its input when this crate's feature `alloc` is on (the owned batch
/// form of the generated code), nothing otherwise. Not public API.
#[cfg(feature = "alloc")]
#[doc(hidden)]
#[macro_export]
macro_rules! __with_alloc {
    ($($item:tt)*) => { $($item)* };
}

/// Emits its input when this crate's feature `alloc` is on (the owned batch
/// form of the generated code), nothing otherwise. Not public API.
#[cfg(not(feature = "alloc"))]
#[doc(hidden)]
#[macro_export]
macro_rules! __with_alloc {
    ($($item:tt)*) => {};
}
