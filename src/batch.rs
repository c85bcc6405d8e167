//! Batches: the generated `solve_batch` works on a structure of arrays
//! (`<Name>Batch`), which implements [`BatchSplit`] so that a sweep can be
//! cut into pieces, e.g. over cores with `par_solve` (feature `rayon`).

/// A batch of independent evaluations that can be split in two.
pub trait BatchSplit: Sized + Send {
    /// Number of elements.
    fn len(&self) -> usize;
    /// `true` when there is no element.
    fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// The first `mid` elements and the rest (`mid` is clamped to the length).
    fn split_at(self, mid: usize) -> (Self, Self);
}

/// The smallest piece `par_solve` hands to a thread, in elements.
///
/// Chosen from `benches/par_batch.rs` (`docs/performance.md`, "Over many
/// cores"): handing a piece to another thread costs a few microseconds
/// (waking a worker, joining), about what the four-bar's batch does in 2000
/// to 4000 elements; with pieces of at least 16384 elements rayon was at
/// least as fast as one thread at every size measured, in `f32` (the cheapest
/// elements, 2 to 4 ns) as in `f64`.
#[cfg(feature = "rayon")]
pub const PAR_MIN_PIECE: usize = 16384;

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
/// ```ignore
/// let failed = mechanism::par_solve(batch, 0, &|mut b| model.solve_batch(&mut b));
/// ```
#[cfg(feature = "rayon")]
pub fn par_solve<B, F>(batch: B, min_len: usize, solve: &F) -> usize
where
    B: BatchSplit,
    F: Fn(B) -> usize + Sync,
{
    let piece = min_len.max(PAR_MIN_PIECE);
    let pieces = (batch.len() / piece).min(rayon::current_num_threads());
    solve_in_pieces(batch, pieces.max(1), solve)
}

/// Solves `batch` in `pieces` pieces of equal size (to one element), in
/// parallel: halves the pieces at each level of `rayon::join`.
#[cfg(feature = "rayon")]
fn solve_in_pieces<B, F>(batch: B, pieces: usize, solve: &F) -> usize
where
    B: BatchSplit,
    F: Fn(B) -> usize + Sync,
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
    a + b
}
