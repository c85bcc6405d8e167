//! Batches: the generated `solve_batch` works on a structure of arrays
//! (`<Name>Batch`), which implements [`BatchSplit`] so that a sweep can be
//! cut into pieces, e.g. over cores with [`par_solve`] (feature `rayon`).

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

/// Runs `solve` on pieces of `batch` of at least `min_len` elements in
/// parallel on rayon's thread pool and returns the sum of what it returns
/// (with `solve_batch`: the number of failed elements). Feature `rayon`
/// (needs `std`).
///
/// ```ignore
/// let failed = mechanism::par_solve(batch, 4096, &|mut b| model.solve_batch(&mut b));
/// ```
#[cfg(feature = "rayon")]
pub fn par_solve<B, F>(batch: B, min_len: usize, solve: &F) -> usize
where
    B: BatchSplit,
    F: Fn(B) -> usize + Sync,
{
    let n = batch.len();
    if n <= min_len.max(1) {
        return solve(batch);
    }
    let (lo, hi) = batch.split_at(n / 2);
    let (a, b) = rayon::join(
        || par_solve(lo, min_len, solve),
        || par_solve(hi, min_len, solve),
    );
    a + b
}
