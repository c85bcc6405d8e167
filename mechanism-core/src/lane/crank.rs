//! Lane version of the crank driver ([`crate::driver::crank`]).

use super::sin_cos;
use crate::scalar::Real;

/// A crank at one angle: the lane version of
/// [`crate::driver::crank::position`].
#[derive(Clone, Copy, Debug)]
pub struct Crank<T> {
    /// The tip (L).
    pub x: T,
    /// The tip (L).
    pub y: T,
    /// `tip - pivot` (L).
    pub rx: T,
    /// `tip - pivot` (L).
    pub ry: T,
    /// Unit axis `(cos, sin)`.
    pub ux: T,
    /// Unit axis `(cos, sin)`.
    pub uy: T,
    /// The angle was in range and the length positive.
    pub ok: bool,
}

/// Crank of `length` about `(px, py)` at `theta` (rad).
#[inline(always)]
pub fn crank<T: Real>(px: T, py: T, length: T, theta: T) -> Crank<T> {
    let (s, c, ok) = sin_cos(theta);
    let (rx, ry) = (c * length, s * length);
    Crank {
        x: px + rx,
        y: py + ry,
        rx,
        ry,
        ux: c,
        uy: s,
        ok: ok & (length > T::zero()),
    }
}
