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

#[cfg(feature = "rayon")]
extern crate std;

/// What handing work to the other threads of rayon's pool costs per level of
/// `rayon::join` (waking a sleeping worker, its steal and the join), in ns,
/// before `par_solve` has measured it: the latency it weighs a piece's cost
/// against on its first split.
///
/// From `benches/par_batch.rs` (`docs/performance.md`, "Over many cores"),
/// where one piece per thread loses to one thread by about this much on
/// small batches: about 10 us on a 2-core machine, 5 to 10 us on a quiet
/// 16-core Xeon (issue 35's figures). After each split `par_solve` measures
/// how late its pieces started and follows that ([`par_task_ns`]).
#[cfg(feature = "rayon")]
pub const PAR_TASK_NS: f64 = 10_000.0;

/// The range `par_solve`'s measured task latency is kept in, in ns: at
/// least 1 us (a wake-up and a steal never cost less), at most 250 us (a
/// batch of half a millisecond is always worth a try on another core, so a
/// busy spell cannot keep every later batch on one thread, and later splits
/// measure the latency again).
#[cfg(feature = "rayon")]
pub const PAR_TASK_NS_RANGE: (f64, f64) = (1_000.0, 250_000.0);

/// The task latency `par_solve` weighs the next split against, in ns per
/// level of `rayon::join`: [`PAR_TASK_NS`] until the first split, then a
/// running geometric mean (weight 1/4 for each new split) of what the
/// splits measured: the latest start of a piece after the split began, per
/// level. On a
/// machine whose other cores are busy the pieces start late (the calling
/// thread may end up running them itself, after its own), so the latency
/// grows and small batches stay on one thread; when cores are free again
/// the next splits measure short delays and it falls. Shared by every
/// `par_solve` of the process; its value only moves the split, never a
/// result (each element is solved once, the same way, whatever the split).
#[cfg(feature = "rayon")]
pub fn par_task_ns() -> f64 {
    f64::from_bits(TASK_NS.load(core::sync::atomic::Ordering::Relaxed))
}

#[cfg(feature = "rayon")]
static TASK_NS: core::sync::atomic::AtomicU64 =
    core::sync::atomic::AtomicU64::new(PAR_TASK_NS.to_bits());

/// The latency after a split whose latest piece started `delay_ns` after the
/// split began, `levels` levels of `rayon::join` deep: a quarter of the way
/// from `old` to `delay_ns / levels` in logarithm (`old (seen / old)^(1/4)`,
/// the ratio taken within 1/16 to 16, so one split moves it by at most a
/// factor 2 either way and a single outlier, such as the pool's first
/// start, cannot throw it far), kept in [`PAR_TASK_NS_RANGE`]; a
/// non-finite observation leaves `old`.
#[cfg(feature = "rayon")]
fn next_task_ns(old: f64, delay_ns: f64, levels: u32) -> f64 {
    let (lo, hi) = PAR_TASK_NS_RANGE;
    let seen = delay_ns / f64::from(levels.max(1));
    if !seen.is_finite() {
        return old;
    }
    let ratio = (seen.max(lo) / old).clamp(1.0 / 16.0, 16.0);
    (old * ratio.sqrt().sqrt()).clamp(lo, hi)
}

/// The first elements `par_solve` solves on the calling thread, timed: the
/// per-element cost its split is decided from (no wasted work: they are
/// part of the batch). 256 four-bar elements take 2 to 10 us, well above
/// the timer's resolution (tens of ns).
#[cfg(feature = "rayon")]
pub const PAR_PROBE: usize = 256;

/// Solves `batch` with `solve` over rayon's thread pool and returns the sum
/// of what `solve` returns (with `solve_batch`: the number of failed
/// elements). Feature `rayon` (needs `std`).
///
/// The split is decided by what a piece costs against what a task costs:
/// the first [`PAR_PROBE`] elements are solved on the calling thread and
/// timed, which gives the cost `c` of one element of this mechanism on
/// this machine; the rest, `m` elements, goes in `p` pieces of equal size
/// (to one element), `p` the number up to the pool's threads that
/// minimizes `m c / p + L * ceil(log2 p)` (the work of one piece plus one
/// task latency `L` per level of `rayon::join`; `L` is [`par_task_ns`],
/// measured on the previous splits), each of at least
/// `min_len` elements (pass 0 for no floor). A batch whose rest is cheaper
/// than about two task latencies, or a pool of one thread, stays on the
/// calling thread, so the call is never much slower than `solve(batch)`;
/// a batch worth splitting at all is usually split one piece per thread.
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
    let n = batch.check()?;
    let threads = rayon::current_num_threads();
    if threads <= 1 || n <= PAR_PROBE {
        return solve(batch);
    }
    let (probe, rest) = batch.split_at(PAR_PROBE);
    let start = std::time::Instant::now();
    let failed = solve(probe)?;
    let per_element = start.elapsed().as_nanos() as f64 / PAR_PROBE as f64;
    let pieces = pieces_for(rest.len(), per_element, min_len, threads, par_task_ns());
    if pieces <= 1 {
        return Ok(failed + solve(rest)?);
    }
    let latest = core::sync::atomic::AtomicU64::new(0);
    let split = Split {
        began: std::time::Instant::now(),
        latest: &latest,
    };
    let rest_failed = solve_in_pieces(rest, pieces, solve, &split)?;
    let delay = latest.load(core::sync::atomic::Ordering::Relaxed) as f64;
    let new = next_task_ns(par_task_ns(), delay, levels(pieces));
    TASK_NS.store(new.to_bits(), core::sync::atomic::Ordering::Relaxed);
    Ok(failed + rest_failed)
}

/// `ceil(log2 p)`: the levels of `rayon::join` that `p` pieces take.
#[cfg(feature = "rayon")]
fn levels(p: usize) -> u32 {
    usize::BITS - p.saturating_sub(1).leading_zeros()
}

/// When a split began and the latest start of one of its pieces after that
/// (ns), what [`par_task_ns`] learns from.
#[cfg(feature = "rayon")]
struct Split<'a> {
    began: std::time::Instant,
    latest: &'a core::sync::atomic::AtomicU64,
}

/// The number of pieces, 1 to `threads`, that minimizes the estimated time
/// of `m` elements at `per_element` ns each: the work of one piece plus
/// `task_ns` per level of `rayon::join` (`ceil(log2 p)` levels), each piece
/// at least `min_len` elements.
#[cfg(feature = "rayon")]
fn pieces_for(m: usize, per_element: f64, min_len: usize, threads: usize, task_ns: f64) -> usize {
    let work = m as f64 * per_element;
    let most = (m / min_len.max(1)).clamp(1, threads);
    let cost = |p: usize| work / p as f64 + task_ns * f64::from(levels(p));
    (1..=most).fold(1, |best, p| if cost(p) < cost(best) { p } else { best })
}

/// Solves `batch` in `pieces` pieces of equal size (to one element), in
/// parallel: halves the pieces at each level of `rayon::join`; each piece
/// records in `split` how long after the split began it started.
#[cfg(feature = "rayon")]
fn solve_in_pieces<B, F>(
    batch: B,
    pieces: usize,
    solve: &F,
    split: &Split,
) -> Result<usize, BatchError>
where
    B: BatchSplit,
    F: Fn(B) -> Result<usize, BatchError> + Sync,
{
    if pieces <= 1 {
        let delay = split.began.elapsed().as_nanos();
        let delay = u64::try_from(delay).unwrap_or(u64::MAX);
        split
            .latest
            .fetch_max(delay, core::sync::atomic::Ordering::Relaxed);
        return solve(batch);
    }
    let n = batch.len();
    let left = pieces / 2;
    // n * left / pieces without overflow (left < pieces).
    let mid = n / pieces * left + n % pieces * left / pieces;
    let (lo, hi) = batch.split_at(mid);
    let (a, b) = rayon::join(
        || solve_in_pieces(lo, left, solve, split),
        || solve_in_pieces(hi, pieces - left, solve, split),
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

#[cfg(all(test, feature = "rayon"))]
mod tests {
    use super::{levels, next_task_ns, pieces_for, PAR_TASK_NS, PAR_TASK_NS_RANGE};

    /// The split weighs the work against the task latency: a batch cheaper
    /// than about two latencies stays whole, one worth splitting goes one
    /// piece per thread, and `min_len` caps the pieces.
    #[test]
    fn pieces_follow_the_cost_of_the_work() {
        let l = PAR_TASK_NS;
        // 1000 elements of 10 ns: 10 us of work, one latency: whole.
        assert_eq!(pieces_for(1000, 10.0, 0, 16, l), 1);
        // Work of 4 latencies on 2 threads: halves (2 + 1 < 4).
        let m = (4.0 * l / 10.0) as usize;
        assert_eq!(pieces_for(m, 10.0, 0, 2, l), 2);
        // Work of 100 latencies on 16 threads: 16 pieces (6.25 + 4 levels).
        let m = (100.0 * l / 10.0) as usize;
        assert_eq!(pieces_for(m, 10.0, 0, 16, l), 16);
        // The same with pieces of at least m / 3 elements: 3.
        assert_eq!(pieces_for(m, 10.0, m / 3, 16, l), 3);
        // A zero or NaN cost (a timer that did not advance): whole.
        assert_eq!(pieces_for(m, 0.0, 0, 16, l), 1);
        assert_eq!(pieces_for(m, f64::NAN, 0, 16, l), 1);
        // The same work against a latency 10 times longer (in units of
        // the old latency: 100 / p + 10 levels(p)): 8 pieces (12.5 + 30)
        // beat 16 (6.25 + 40), 4 (25 + 20) and 2 (50 + 10).
        assert_eq!(pieces_for(m, 10.0, 0, 16, 10.0 * l), 8);
    }

    /// `ceil(log2 p)` levels of `rayon::join` for `p` pieces.
    #[test]
    fn levels_are_the_depth_of_the_halving() {
        let got = [1, 2, 3, 4, 5, 8, 9, 16].map(levels);
        assert_eq!(got, [0, 1, 2, 2, 3, 3, 4, 4]);
    }

    /// The measured latency moves a quarter of the way (in logarithm) to
    /// each split's delay per level, at most a factor 2 per split, stays in
    /// its range, and ignores a non-finite observation.
    #[test]
    fn the_latency_follows_what_the_splits_measure() {
        let (lo, hi) = PAR_TASK_NS_RANGE;
        // 320 us over 2 levels is 160 us per level, 16 times 10 us: the
        // fourth root of 16 is 2, so 20 us.
        assert_eq!(next_task_ns(10_000.0, 320_000.0, 2), 20_000.0);
        // Beyond 16 times: the same factor 2 (one outlier moves it once).
        assert_eq!(next_task_ns(10_000.0, 1e12, 1), 20_000.0);
        // 10 us seen at 10 us: unchanged.
        assert_eq!(next_task_ns(10_000.0, 10_000.0, 1), 10_000.0);
        // Late pieces repeatedly (a busy machine): it grows to the cap.
        let mut l = PAR_TASK_NS;
        for _ in 0..20 {
            l = next_task_ns(l, 1e9, 1);
        }
        assert_eq!(l, hi);
        // Pieces that start at once (free cores): it falls, halving per
        // split while 16 times the floor or more (250 to 15.6 us in 4
        // splits), then by a quarter of the remaining logarithm per split
        // (15.6^(3/4) = 7.86 us, then 4.69 us).
        assert_eq!(next_task_ns(hi, 0.0, 4), hi / 2.0);
        for _ in 0..6 {
            l = next_task_ns(l, 0.0, 4);
        }
        assert!((l - 4_694.0).abs() < 1.0, "{l}");
        for _ in 0..100 {
            l = next_task_ns(l, 0.0, 4);
        }
        assert!((l - lo).abs() < 1e-9 * lo, "{l}");
        assert_eq!(next_task_ns(l, f64::NAN, 1), l);
        assert_eq!(next_task_ns(l, f64::INFINITY, 1), l);
    }
}
