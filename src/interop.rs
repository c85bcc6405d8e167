//! What the generated `Display` and serde impls call (not public API):
//! number formatting that honours the formatter's precision, and, with the
//! feature `serde`, the serde crate itself and `__with_serde!`.

use crate::Real;
use core::fmt::{Formatter, Result};

/// With the feature `serde`: the serde crate the generated impls name
/// (`::mechanism::__interop::serde::Serialize`), so a user's crate needs no
/// serde dependency of its own for them.
#[cfg(feature = "serde")]
pub use serde;

/// Writes `x` with the formatter's precision when it has one (`{:.3}`),
/// else as `Display` does; a zero prints without sign (`-0.0 + 0.0` is
/// `+0.0`: a reaction that vanishes by symmetry reads `0`, not `-0`).
#[inline]
pub fn number<T: Real>(f: &mut Formatter<'_>, x: T) -> Result {
    let x = x + T::lit(0.0);
    match f.precision() {
        Some(p) => write!(f, "{x:.p$}"),
        None => write!(f, "{x}"),
    }
}

/// Writes `SEP NAME = VALUE UNIT`: `sep` before every entry but a line's
/// first, `unit` after the value (with its leading space, or empty).
#[inline]
pub fn scalar<T: Real>(f: &mut Formatter<'_>, sep: &str, name: &str, x: T, unit: &str) -> Result {
    write!(f, "{sep}{name} = ")?;
    number(f, x)?;
    f.write_str(unit)
}

/// Writes `SEP NAME = (X, Y) UNIT` (a point, a vector).
#[inline]
pub fn pair<T: Real>(
    f: &mut Formatter<'_>,
    sep: &str,
    name: &str,
    x: T,
    y: T,
    unit: &str,
) -> Result {
    write!(f, "{sep}{name} = (")?;
    number(f, x)?;
    f.write_str(", ")?;
    number(f, y)?;
    write!(f, "){unit}")
}

/// Writes a prismatic pair's reaction: `SEP NAME = (normal N F, moment M F L)`, with
/// the force and moment units given (each with its leading space: `" N"`).
#[inline]
pub fn prismatic<T: Real>(
    f: &mut Formatter<'_>,
    sep: &str,
    name: &str,
    normal: T,
    moment: T,
    force_unit: &str,
    moment_unit: &str,
) -> Result {
    write!(f, "{sep}{name} = (normal ")?;
    number(f, normal)?;
    write!(f, "{force_unit}, moment ")?;
    number(f, moment)?;
    write!(f, "{moment_unit})")
}

/// Implemented when this crate's feature `serde` is on: the generated code of
/// a definition with `#[derive(Serialize)]` or `#[derive(Deserialize)]`
/// calls [`serde_feature`] on the derive's tokens, so that without the
/// feature the compile error is there and says how to turn it on.
#[diagnostic::on_unimplemented(
    message = "`#[derive(Serialize)]` / `#[derive(Deserialize)]` on a `mechanism!` definition needs the feature `serde` of `planar-mechanism`",
    label = "the impls this asks for need the feature `serde`",
    note = "in Cargo.toml: `planar-mechanism = {{ version = \"0.1\", features = [\"serde\"] }}`"
)]
pub trait SerdeFeature {}

#[cfg(feature = "serde")]
impl SerdeFeature for () {}

/// Compiles only with the feature `serde` (see [`SerdeFeature`]).
pub const fn serde_feature<T: SerdeFeature>() {}

/// Emits its input when this crate's feature `serde` is on (the serde impls
/// a definition's `#[derive(Serialize)]` asks for), nothing otherwise (the
/// error is [`SerdeFeature`]'s). Not public API.
#[cfg(feature = "serde")]
#[doc(hidden)]
#[macro_export]
macro_rules! __with_serde {
    ($($item:tt)*) => { $($item)* };
}

/// Emits its input when this crate's feature `serde` is on (the serde impls
/// a definition's `#[derive(Serialize)]` asks for), nothing otherwise (the
/// error is [`SerdeFeature`]'s). Not public API.
#[cfg(not(feature = "serde"))]
#[doc(hidden)]
#[macro_export]
macro_rules! __with_serde {
    ($($item:tt)*) => {};
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::format;

    struct N(f64);

    impl core::fmt::Display for N {
        fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
            super::number(f, self.0)
        }
    }

    // Proves a negative zero prints unsigned with and without a precision,
    // and any other number exactly as `Display` prints it.
    #[test]
    fn negative_zero_prints_unsigned() {
        assert_eq!(format!("{:.3}", N(-0.0)), "0.000");
        assert_eq!(format!("{}", N(-0.0)), "0");
        assert_eq!(format!("{:.3}", N(-1e-9)), "-0.000");
        assert_eq!(format!("{:.2}", N(-1.005)), format!("{:.2}", -1.005f64));
        assert_eq!(format!("{}", N(0.1 + 0.2)), "0.30000000000000004");
    }
}
