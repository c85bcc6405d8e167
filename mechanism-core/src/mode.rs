//! Assembly modes.
//!
//! Most class II groups close in two ways for the same input (two circle
//! intersections, a circle and a line). [`Mode`] picks one; its geometric
//! meaning is stated in each group's module and drawn in `docs/assembly-modes.svg`.
//! The sign `m = +1 / -1` is the one of the lab guide (seed 001).

use crate::scalar::Real;

/// Which of the two closures of a group to take.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Mode {
    /// `m = +1` (for RRR: the joint lies to the left of the line from the first
    /// known joint to the second).
    Plus,
    /// `m = -1`.
    Minus,
}

impl Mode {
    /// The other mode: the other closure of the same group (`Plus` and
    /// `Minus` swapped).
    ///
    /// ```
    /// use mechanism_core::Mode;
    /// assert_eq!(Mode::Plus.flipped(), Mode::Minus);
    /// assert_eq!(Mode::Minus.flipped().flipped(), Mode::Minus);
    /// ```
    #[inline(always)]
    pub const fn flipped(self) -> Mode {
        match self {
            Mode::Plus => Mode::Minus,
            Mode::Minus => Mode::Plus,
        }
    }

    /// `+1` or `-1` in the scalar type.
    #[inline(always)]
    pub fn sign<T: Real>(self) -> T {
        match self {
            Mode::Plus => T::one(),
            Mode::Minus => -T::one(),
        }
    }
}
