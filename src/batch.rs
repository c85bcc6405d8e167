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
