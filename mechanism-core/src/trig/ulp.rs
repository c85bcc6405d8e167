//! The error measure of the `f32` kernels' tests: ulps of `f32` against an
//! exact (`f64`) value, and the bound the kernels state.

/// Error of `got` against the exact value `want` (f64), in units of the
/// f32 spacing at `|want|` (floored at the smallest subnormal spacing).
pub(super) fn ulps(got: f32, want: f64) -> f64 {
    let w32 = (want as f32).abs();
    let spacing = if w32 == 0.0 || w32 < f32::MIN_POSITIVE {
        2f64.powi(-149)
    } else {
        // Spacing of f32 at |want|: 2^(exponent - 23); when |want| rounds
        // up to a power of two, use the smaller spacing below it.
        let e = ((w32.to_bits() >> 23) & 0xFF) as i32 - 127;
        let s = 2f64.powi(e - 23);
        if (w32 as f64) > want.abs() && w32.to_bits() & 0x007F_FFFF == 0 {
            s / 2.0
        } else {
            s
        }
    };
    ((got as f64) - want).abs() / spacing
}

/// The stated bound.
pub(super) const BOUND_ULP: f64 = 2.0;
