//! Serialization of arrays whose length is a const generic (`[T; N]` in
//! [`crate::sweep::Report`], [`crate::linsolve::Solution`]): serde implements
//! `Serialize` for arrays of the lengths 0 to 32 only, one impl per length.
//! These write any length as a sequence, without allocation
//! (`#[serde(serialize_with = "...")]` on the fields).

use serde::ser::{Serialize, Serializer};

/// A slice serialized as a sequence.
struct Seq<'a, T>(&'a [T]);

impl<T: Serialize> Serialize for Seq<'_, T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(self.0)
    }
}

/// `[T; N]` as a sequence of `N` elements.
pub(crate) fn array<T: Serialize, const N: usize, S: Serializer>(
    a: &[T; N],
    s: S,
) -> Result<S::Ok, S::Error> {
    s.collect_seq(a)
}

/// `Option<[T; N]>`: `None`, or the array as a sequence.
pub(crate) fn opt_array<T: Serialize, const N: usize, S: Serializer>(
    a: &Option<[T; N]>,
    s: S,
) -> Result<S::Ok, S::Error> {
    match a {
        None => s.serialize_none(),
        Some(a) => s.serialize_some(&Seq(a)),
    }
}

/// `Option<([T; N], [T; N])>` (an interval's corners): `None`, or a pair of
/// sequences.
pub(crate) fn opt_corners<T: Serialize, const N: usize, S: Serializer>(
    a: &Option<([T; N], [T; N])>,
    s: S,
) -> Result<S::Ok, S::Error> {
    match a {
        None => s.serialize_none(),
        Some((lo, hi)) => s.serialize_some(&(Seq(lo), Seq(hi))),
    }
}
