//! The typed errors. Every fallible function in the core returns
//! `Result<_, Error<T>>`; no function panics, and no `Ok` carries NaN or infinity.
//!
//! An [`Error`] says which primitive failed (and, once the generated code has
//! named it with [`Error::in_group`], which group of the user's mechanism), and
//! by how much ([`Fault`]). The numbers are in the scene's own scalar `T`
//! (`f32` or `f64`, the default): an `f32` scene on a single-precision FPU
//! builds its errors without software conversions to `f64`. Code that mixes
//! precisions widens with `From<Error<f32>> for Error<f64>` (exact), so `?`
//! works from an `f32` call inside a function returning `Error<f64>`.

use core::fmt;

use crate::scalar::Real;

/// The kind of primitive that reported an error.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Primitive {
    /// A crank driver (link turning about a known point).
    Crank,
    /// A slider driver (translation along a known guide).
    Slider,
    /// A linear-actuator driver (a length between two points is the input).
    Actuator,
    /// A point fixed on a link.
    LinkPoint,
    /// Class II group revolute-revolute-revolute.
    Rrr,
    /// Class II group revolute-revolute-prismatic.
    Rrp,
    /// Class II group revolute-prismatic-revolute.
    Rpr,
    /// Class II group prismatic-revolute-prismatic.
    Prp,
    /// Class II group revolute-prismatic-prismatic.
    Rpp,
    /// The linear solver ([`crate::linsolve`]).
    LinearSystem,
}

impl Primitive {
    /// Short upper-case name, as in the textbooks ("RRR", "crank", ...).
    pub const fn name(self) -> &'static str {
        match self {
            Primitive::Crank => "crank",
            Primitive::Slider => "slider",
            Primitive::Actuator => "actuator",
            Primitive::LinkPoint => "link point",
            Primitive::Rrr => "RRR",
            Primitive::Rrp => "RRP",
            Primitive::Rpr => "RPR",
            Primitive::Prp => "PRP",
            Primitive::Rpp => "RPP",
            Primitive::LinearSystem => "linear system",
        }
    }
}

/// What went wrong, with the numbers that show by how much, in the scalar
/// type `T` of the computation that failed (`f32` or `f64`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Fault<T = f64> {
    /// The group cannot close at this pose. `miss` (> 0, length units) is how far
    /// the distance between the known joints lies outside the reachable range;
    /// `reach` is the range's nearer bound, for scale.
    CannotAssemble {
        /// Distance outside the reachable range, > 0.
        miss: T,
        /// The bound that was missed (for example `l1 + l2`).
        reach: T,
    },
    /// A rate or force system is singular at this pose (toggle, dead centre,
    /// parallel guides). `det` is the determinant (or smallest pivot) and
    /// `scale` what it is compared against; `|det| / scale` is the relative
    /// conditioning, below `16 * eps` here.
    Singular {
        /// The determinant or pivot found.
        det: T,
        /// Its natural scale (product of the column lengths or row scales).
        scale: T,
    },
    /// An input or an intermediate result was NaN or infinite.
    NonFinite {
        /// Which quantity.
        what: &'static str,
    },
    /// A length or other input that must be positive was not.
    NonPositive {
        /// Which quantity.
        what: &'static str,
        /// The value given.
        value: T,
    },
    /// An input that must be zero or positive (a moment of inertia) was
    /// negative.
    Negative {
        /// Which quantity.
        what: &'static str,
        /// The value given, < 0.
        value: T,
    },
}

/// A typed error: which primitive, which group of the user's mechanism (when
/// known), and the [`Fault`] with its numbers in the scalar type `T` (`f32` or
/// `f64`, the default).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Error<T = f64> {
    /// The user's name for the group or driver (for example `"B"`), or `""` when
    /// a primitive was called directly.
    pub group: &'static str,
    /// The primitive that failed.
    pub primitive: Primitive,
    /// What went wrong.
    pub fault: Fault<T>,
}

impl<T> Error<T> {
    /// An error from `primitive`, not yet attributed to a named group.
    #[inline]
    pub const fn new(primitive: Primitive, fault: Fault<T>) -> Self {
        Error {
            group: "",
            primitive,
            fault,
        }
    }

    /// Attributes the error to the user's group `name` (generated code calls this).
    #[inline]
    pub const fn in_group(mut self, name: &'static str) -> Self {
        self.group = name;
        self
    }
}

impl<T: Real> Fault<T> {
    /// The same fault with its numbers widened to `f64` (exact for `f32` and
    /// `f64`), for code that collects faults of either precision (the sweep
    /// of [`crate::sweep`], the generated `check`).
    #[inline]
    pub fn to_f64(self) -> Fault<f64> {
        match self {
            Fault::CannotAssemble { miss, reach } => Fault::CannotAssemble {
                miss: miss.as_f64(),
                reach: reach.as_f64(),
            },
            Fault::Singular { det, scale } => Fault::Singular {
                det: det.as_f64(),
                scale: scale.as_f64(),
            },
            Fault::NonFinite { what } => Fault::NonFinite { what },
            Fault::NonPositive { what, value } => Fault::NonPositive {
                what,
                value: value.as_f64(),
            },
            Fault::Negative { what, value } => Fault::Negative {
                what,
                value: value.as_f64(),
            },
        }
    }
}

impl<T: Real> Error<T> {
    /// The same error with its numbers widened to `f64` (exact); the group
    /// and primitive are kept.
    #[inline]
    pub fn to_f64(self) -> Error<f64> {
        Error {
            group: self.group,
            primitive: self.primitive,
            fault: self.fault.to_f64(),
        }
    }
}

impl From<Fault<f32>> for Fault<f64> {
    /// Widens the numbers to `f64` (exact: every `f32` is an `f64`).
    #[inline]
    fn from(fault: Fault<f32>) -> Self {
        fault.to_f64()
    }
}

impl From<Error<f32>> for Error<f64> {
    /// Widens the numbers to `f64` (exact), so `?` on an `Error<f32>` works in
    /// a function returning `Error<f64>`; the group and primitive are kept.
    #[inline]
    fn from(e: Error<f32>) -> Self {
        e.to_f64()
    }
}

impl<T: Real> fmt::Display for Fault<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Fault::CannotAssemble { miss, reach } => write!(
                f,
                "cannot assemble: the known joints are {miss:e} outside the reachable range (bound {reach:e})"
            ),
            Fault::Singular { det, scale } if scale == T::zero() => write!(
                f,
                "singular position: the group's known joints coincide or a length is zero, \
                 so nothing sets its direction (determinant {det:e} against a zero scale)"
            ),
            Fault::Singular { det, scale } => write!(
                f,
                "singular position: determinant {det:e} against scale {scale:e} (relative {:e})",
                det / scale
            ),
            Fault::NonFinite { what } => write!(f, "{what} is not finite"),
            Fault::NonPositive { what, value } => {
                write!(f, "{what} must be positive, got {value:e}")
            }
            Fault::Negative { what, value } => {
                write!(f, "{what} must be zero or positive, got {value:e}")
            }
        }
    }
}

impl<T: Real> fmt::Display for Error<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.group.is_empty() {
            write!(f, "{}: {}", self.primitive.name(), self.fault)
        } else {
            write!(
                f,
                "group `{}` ({}): {}",
                self.group,
                self.primitive.name(),
                self.fault
            )
        }
    }
}

impl<T: Real> core::error::Error for Error<T> {}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::{driver::crank, dyad::rrr, Mode, Point2};
    use std::string::ToString;

    /// RRR with `|B - A| = 10` and links 2 and 3: out of reach by exactly
    /// 10 - 5 = 5 (every number exact in both precisions).
    fn too_far<T: Real>() -> Error<T> {
        let (a, b) = (
            Point2::new(T::zero(), T::zero()),
            Point2::new(T::lit(10.0), T::zero()),
        );
        match rrr::position(&a, T::lit(2.0), &b, T::lit(3.0), Mode::Plus) {
            Err(e) => e,
            Ok(_) => panic!("a joint 10 away cannot be reached by links 2 and 3"),
        }
    }

    #[test]
    fn f32_error_carries_f32_values_and_widens_exactly() {
        let e32: Error<f32> = too_far::<f32>();
        assert_eq!(
            e32.fault,
            Fault::CannotAssemble {
                miss: 5.0f32,
                reach: 5.0f32
            }
        );
        // `From` (what `?` uses) and `to_f64` agree with the f64 computation.
        let widened: Error<f64> = e32.into();
        assert_eq!(widened, too_far::<f64>());
        assert_eq!(e32.to_f64(), widened);
        // A value that is not a short decimal keeps its f32 bits when widened.
        let e = Error::new(
            Primitive::Crank,
            Fault::NonPositive {
                what: "x",
                value: -0.1f32,
            },
        )
        .in_group("A");
        let w: Error<f64> = e.into();
        assert_eq!(w.group, "A");
        assert_eq!(
            w.fault,
            Fault::NonPositive {
                what: "x",
                value: -0.1f32 as f64
            }
        );
    }

    #[test]
    fn display_says_coincident_joints_for_a_zero_scale() {
        let rrr = crate::dyad::rrr::position(
            &Point2::new(1.0, 2.0),
            3.0,
            &Point2::new(1.0, 2.0),
            4.0,
            crate::Mode::Plus,
        )
        .unwrap_err();
        let rpr = crate::dyad::rpr::position(
            &Point2::new(0.5f32, 0.5),
            &Point2::new(0.5, 0.5),
            0.0,
            crate::Mode::Plus,
        )
        .unwrap_err();
        for text in [rrr.to_string(), rpr.to_string()] {
            assert!(text.contains("known joints coincide"), "{text}");
        }
    }

    #[test]
    fn display_prints_each_precision_in_its_own_digits() {
        // Same text for both precisions when the numbers are exact.
        let want = "RRR: cannot assemble: the known joints are 5e0 outside the reachable range (bound 5e0)";
        assert_eq!(too_far::<f32>().to_string(), want);
        assert_eq!(too_far::<f64>().to_string(), want);
        // -0.1 as f32 prints as the shortest f32 decimal, not as the f64
        // expansion of its bits (-1.0000000149011612e-1).
        let e = match crank::position(&Point2::new(0.0f32, 0.0), -0.1f32, 0.5) {
            Err(e) => e.in_group("A"),
            Ok(_) => panic!("a negative crank length is an error"),
        };
        assert_eq!(
            e.to_string(),
            "group `A` (crank): crank length must be positive, got -1e-1"
        );
        assert_eq!(
            e.to_f64().to_string(),
            "group `A` (crank): crank length must be positive, got -1.0000000149011612e-1"
        );
    }
}
