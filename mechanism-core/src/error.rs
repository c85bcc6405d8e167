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
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub enum Primitive {
    /// A crank driver (link turning about a known point).
    Crank,
    /// A slider driver (translation along a known guide).
    Slider,
    /// A linear-actuator driver (a length between two points is the input).
    Actuator,
    /// A target driver (a point placed by two inputs, its coordinates).
    Target,
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
    /// Class III group: a ternary link on three revolute legs
    /// ([`crate::triad`]).
    Triad,
    /// The linear solver ([`crate::linsolve`]).
    LinearSystem,
    /// The generalized mass matrix of the forward dynamics (a definition's
    /// generated `dynamics`): no inertia moves with some input, or a dead
    /// point of the drive. The error's group lists the inputs.
    MassMatrix,
}

impl Primitive {
    /// Short upper-case name, as in the textbooks ("RRR", "crank", ...).
    pub const fn name(self) -> &'static str {
        match self {
            Primitive::Crank => "crank",
            Primitive::Slider => "slider",
            Primitive::Actuator => "actuator",
            Primitive::Target => "target",
            Primitive::LinkPoint => "link point",
            Primitive::Rrr => "RRR",
            Primitive::Rrp => "RRP",
            Primitive::Rpr => "RPR",
            Primitive::Prp => "PRP",
            Primitive::Rpp => "RPP",
            Primitive::Triad => "triad",
            Primitive::LinearSystem => "linear system",
            Primitive::MassMatrix => "mass matrix",
        }
    }
}

/// What went wrong, with the numbers that show by how much, in the scalar
/// type `T` of the computation that failed (`f32` or `f64`).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[non_exhaustive]
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
    /// A group with several assemblies (the triad) was asked for the one
    /// nearest a given pose, and no assembly is clearly that one: the nearest
    /// is `nearest` from the pose (L, root-sum-square over the joints) and
    /// either the next is `next`, less than twice as far, or `nearest`
    /// exceeds the largest distance accepted, `next` (half the group's
    /// shortest dimension). Tracking, the same when the followed assembly
    /// has met another one and vanished (a branch point): `nearest` is then
    /// the jump to the closest assembly left on the same side of the branch
    /// point (infinite when none is left).
    NotNear {
        /// Distance from the pose to the nearest assembly (L).
        nearest: T,
        /// Distance to the next one, or the largest jump accepted (L).
        next: T,
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
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
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
    #[must_use]
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
    #[must_use]
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
            Fault::NotNear { nearest, next } => Fault::NotNear {
                nearest: nearest.as_f64(),
                next: next.as_f64(),
            },
        }
    }
}

impl<T: Real> Error<T> {
    /// The same error with its numbers widened to `f64` (exact); the group
    /// and primitive are kept.
    #[inline]
    #[must_use]
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

/// A number as the messages print it: rounded to 4 significant digits,
/// in plain notation when the rounded magnitude lies in `[1e-3, 1e5)` (`2`,
/// `0.1789`, `0.9`, `12350`, `0.001`) and in scientific notation otherwise
/// (`1.234e-7`, `1e5`, `3.403e38`), trailing zeros dropped; either zero
/// prints as `0`, and NaN and the infinities as `NaN`, `inf`, `-inf`.
///
/// The rounding is `core`'s correctly rounded `{:.3e}` of the value in its
/// own type `T` (an `f32` prints from its `f32` bits: `-0.1f32` is `-0.1`,
/// not the expansion `-1.0000000149011612e-1` of the same bits in `f64`), so
/// the decimal `9.9995`, which is `9.99949999...` as an `f64`, prints as
/// `9.999`, and `9.99951` as `10`. no_std, no allocation: the digits go
/// through a 32-byte buffer on the stack. Width and alignment flags apply
/// to the whole number (`{:>8}`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rounded<T>(pub T);

/// Significant digits [`Rounded`] keeps.
const DIGITS: usize = 4;

/// A fixed stack buffer that `write!` can fill (no allocation).
struct Buf {
    bytes: [u8; 32],
    len: usize,
}

impl Buf {
    const fn new() -> Self {
        Buf {
            bytes: [0; 32],
            len: 0,
        }
    }

    fn push(&mut self, b: u8) -> fmt::Result {
        let slot = self.bytes.get_mut(self.len).ok_or(fmt::Error)?;
        *slot = b;
        self.len += 1;
        Ok(())
    }

    fn as_str(&self) -> &str {
        // Only ASCII is ever pushed (digits, '.', '-', 'e'), so this never
        // fails; the fallback keeps the code free of a panic path.
        core::str::from_utf8(&self.bytes[..self.len]).unwrap_or("?")
    }
}

impl fmt::Write for Buf {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        s.bytes().try_for_each(|b| self.push(b))
    }
}

impl<T: Real> fmt::Display for Rounded<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use fmt::Write as _;
        let x = self.0;
        if !x.finite() {
            #[allow(clippy::eq_op)] // NaN is the one value unequal to itself
            let text = if x != x {
                "NaN"
            } else if x > T::zero() {
                "inf"
            } else {
                "-inf"
            };
            return f.pad(text);
        }
        if x == T::zero() {
            return f.pad("0");
        }
        // `d.ddde<exp>` of |x|, correctly rounded to 4 significant digits.
        let mut sci = Buf::new();
        write!(sci, "{:.*e}", DIGITS - 1, crate::scalar::abs(x))?;
        let [d0, b'.', d1, d2, d3, b'e', exp_text @ ..] = &sci.bytes[..sci.len] else {
            return Err(fmt::Error);
        };
        let (neg_exp, exp_digits) = match exp_text {
            [b'-', rest @ ..] => (true, rest),
            rest => (false, rest),
        };
        let magnitude = exp_digits
            .iter()
            .fold(0i32, |acc, &b| acc * 10 + (i32::from(b) - i32::from(b'0')));
        let exp = if neg_exp { -magnitude } else { magnitude };
        // Significant digits without the trailing zeros (the first is 1..9).
        let all = [*d0, *d1, *d2, *d3];
        let n = DIGITS - all.iter().rev().take_while(|&&b| b == b'0').count();
        let (lead, tail) = all.split_at(1);
        let tail = tail.get(..n.saturating_sub(1)).unwrap_or(tail);

        let mut out = Buf::new();
        if x < T::zero() {
            out.push(b'-')?;
        }
        if (-3..=4).contains(&exp) {
            let mut digits = lead.iter().chain(tail);
            if exp >= 0 {
                // Integer part: the first `exp + 1` digits, zeros after the
                // last significant one; then the rest as the fraction.
                let int = exp as usize + 1;
                for i in 0..int {
                    out.push(*digits.clone().nth(i).unwrap_or(&b'0'))?;
                }
                if n > int {
                    out.push(b'.')?;
                    digits.skip(int).try_for_each(|&b| out.push(b))?;
                }
            } else {
                out.write_str("0.")?;
                for _ in 0..(-exp - 1) {
                    out.push(b'0')?;
                }
                digits.try_for_each(|&b| out.push(b))?;
            }
        } else {
            out.push(*d0)?;
            if !tail.is_empty() {
                out.push(b'.')?;
                tail.iter().try_for_each(|&b| out.push(b))?;
            }
            write!(out, "e{exp}")?;
        }
        f.pad(out.as_str())
    }
}

impl<T: Real> Fault<T> {
    /// The message, with the primitive when known (for the wording of a
    /// zero scale, which means coincident joints in a group and an equation
    /// of zeros in the linear solver).
    fn describe(&self, f: &mut fmt::Formatter<'_>, primitive: Option<Primitive>) -> fmt::Result {
        match *self {
            Fault::CannotAssemble { miss, reach } => write!(
                f,
                "cannot assemble: the distance between the known joints is {} outside \
                 the range the group can reach (nearest reachable distance {}, in the \
                 unit of the link lengths); the input lies outside the mechanism's range \
                 of motion, or a dimension is wrong",
                Rounded(miss),
                Rounded(reach)
            ),
            Fault::Singular { det, scale } if scale == T::zero() => {
                if primitive == Some(Primitive::LinearSystem) {
                    write!(
                        f,
                        "singular position: an equation of the linear system is all zeros \
                         (determinant {}, scale 0), so it has no unique solution at this \
                         pose",
                        Rounded(det)
                    )
                } else {
                    write!(
                        f,
                        "singular position: the group's known joints coincide or a length \
                         is zero, so nothing sets its direction (determinant {}, scale 0); \
                         separate the joints or correct the dimensions",
                        Rounded(det)
                    )
                }
            }
            Fault::Singular { det, scale } => write!(
                f,
                "singular position (toggle, dead centre or parallel guides): determinant \
                 {} against its scale {} (relative {}), too small to solve for the \
                 motion or the forces; avoid this input, or handle the error there",
                Rounded(det),
                Rounded(scale),
                Rounded(det / scale)
            ),
            Fault::NonFinite { what } => write!(
                f,
                "{what} is not finite (NaN or infinite): an input or parameter is NaN or \
                 infinite, or a value overflowed the scalar type"
            ),
            Fault::NonPositive { what, value } => {
                write!(f, "{what} must be positive, got {}", Rounded(value))
            }
            Fault::Negative { what, value } => {
                write!(f, "{what} must be zero or positive, got {}", Rounded(value))
            }
            Fault::NotNear { nearest, next } => write!(
                f,
                "no assembly is clearly the one asked for: the nearest is {} from the \
                 given pose and the next {} (or the largest distance accepted; a clear \
                 match is at most half as far as the next and within half the shortest \
                 link); give the joints' approximate positions more closely, or, \
                 tracking, the followed assembly met another one and vanished here",
                Rounded(nearest),
                Rounded(next)
            ),
        }
    }
}

impl<T: Real> fmt::Display for Fault<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.describe(f, None)
    }
}

impl<T: Real> fmt::Display for Error<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.group.is_empty() {
            write!(f, "{}: ", self.primitive.name())?;
        } else {
            write!(f, "group `{}` ({}): ", self.group, self.primitive.name())?;
        }
        self.fault.describe(f, Some(self.primitive))
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

    /// `Rounded(x)` as text.
    fn r<T: Real>(x: T) -> std::string::String {
        Rounded(x).to_string()
    }

    #[test]
    fn rounded_prints_four_significant_digits_plain_in_the_middle_range() {
        // The reviewer's numbers (f64): 2e0, 1.78889744907202e-1,
        // 8.999999999999999e-1 (0.9 less an ulp), 0e0, 4e0.
        assert_eq!(r(2.0f64), "2");
        assert_eq!(r(1.78889744907202e-1f64), "0.1789");
        assert_eq!(r(0.8999999999999999f64), "0.9");
        assert_eq!(r(0.0f64), "0");
        assert_eq!(r(4.0f64), "4");
        assert_eq!(r(1.234e-7f64), "1.234e-7");
        // Either zero is 0; the sign of a negative number is kept.
        assert_eq!(r(-0.0f64), "0");
        assert_eq!(r(-0.0f32), "0");
        assert_eq!(r(-0.1f64), "-0.1");
        assert_eq!(r(-12.5f32), "-12.5");
        assert_eq!(r(-1.5e-9f64), "-1.5e-9");
        // Digits past the fourth are rounded, trailing zeros dropped, and a
        // carry into a new digit handled: 9.99951 -> 10. The decimal 9.9995
        // is 9.99949999999999938... as an f64 (below the tie: 9.999) and
        // 9.99950027... as an f32 (above it: 10), each printed from its own
        // bits.
        assert_eq!(r(9.99951f64), "10");
        assert_eq!(r(9.9995f64), "9.999");
        assert_eq!(r(9.9995f32), "10");
        assert_eq!(r(123.456f64), "123.5");
        assert_eq!(r(12345.6f64), "12350");
        assert_eq!(r(1000.0f64), "1000");
        assert_eq!(r(0.5f64), "0.5");
        assert_eq!(r(0.012345f64), "0.01235");
    }

    #[test]
    fn rounded_switches_to_scientific_outside_1e_minus_3_to_1e5() {
        // The upper edge: 99999.5 rounds to 1.000e5, no longer below 1e5.
        assert_eq!(r(99999.5f64), "1e5");
        assert_eq!(r(99994.0f64), "99990");
        assert_eq!(r(1e5f64), "1e5");
        assert_eq!(r(1e5f32), "1e5");
        assert_eq!(r(123456.0f64), "1.235e5");
        // The lower edge: 1e-3 is plain, anything rounding below it is not.
        assert_eq!(r(1e-3f64), "0.001");
        assert_eq!(r(1e-3f32), "0.001");
        assert_eq!(r(0.00099996f64), "0.001");
        assert_eq!(r(0.0009999f64), "9.999e-4");
        // Tiny and huge, in each type's own range (subnormals included).
        assert_eq!(r(5e-324f64), "4.941e-324");
        assert_eq!(r(f64::MIN_POSITIVE), "2.225e-308");
        assert_eq!(r(f64::MAX), "1.798e308");
        assert_eq!(r(-f64::MAX), "-1.798e308");
        assert_eq!(r(1e-45f32), "1.401e-45");
        assert_eq!(r(f32::MAX), "3.403e38");
        assert_eq!(r(6.775824e-21f32), "6.776e-21");
        // Non-finite numbers (a fault built from an overflowed value).
        assert_eq!(r(f64::NAN), "NaN");
        assert_eq!(r(f32::INFINITY), "inf");
        assert_eq!(r(f64::NEG_INFINITY), "-inf");
        // Width and alignment apply to the whole number.
        assert_eq!(std::format!("[{:>7}]", Rounded(-0.25f64)), "[  -0.25]");
    }

    #[test]
    fn display_prints_each_precision_in_its_own_digits() {
        // Same text for both precisions when the numbers are exact.
        let want = "RRR: cannot assemble: the distance between the known joints is 5 \
                    outside the range the group can reach (nearest reachable distance 5, \
                    in the unit of the link lengths); the input lies outside the \
                    mechanism's range of motion, or a dimension is wrong";
        assert_eq!(too_far::<f32>().to_string(), want);
        assert_eq!(too_far::<f64>().to_string(), want);
        // -0.1 as f32 prints as 0.1, and so does its exact widening to f64
        // (-1.0000000149011612e-1 to 17 digits): 4 digits hide the difference.
        let e = match crank::position(&Point2::new(0.0f32, 0.0), -0.1f32, 0.5) {
            Err(e) => e.in_group("A"),
            Ok(_) => panic!("a negative crank length is an error"),
        };
        let want = "group `A` (crank): crank length must be positive, got -0.1";
        assert_eq!(e.to_string(), want);
        assert_eq!(e.to_f64().to_string(), want);
    }

    #[test]
    fn whole_messages_read_as_sentences() {
        // A singular RRR (links 2 and 2 folded: A 4 from B): determinant as
        // computed, relative to its scale 4.
        let singular = Error::new(
            Primitive::Rrr,
            Fault::Singular {
                det: 1.5e-17f64,
                scale: 4.0,
            },
        )
        .in_group("B");
        assert_eq!(
            singular.to_string(),
            "group `B` (RRR): singular position (toggle, dead centre or parallel guides): \
             determinant 1.5e-17 against its scale 4 (relative 3.75e-18), too small to \
             solve for the motion or the forces; avoid this input, or handle the error there"
        );
        let zero = Error::new(
            Primitive::Rrr,
            Fault::Singular {
                det: 0.0f32,
                scale: 0.0,
            },
        );
        assert_eq!(
            zero.to_string(),
            "RRR: singular position: the group's known joints coincide or a length is \
             zero, so nothing sets its direction (determinant 0, scale 0); separate the \
             joints or correct the dimensions"
        );
        let solver = Error::new(
            Primitive::LinearSystem,
            Fault::Singular {
                det: 0.0f64,
                scale: 0.0,
            },
        );
        assert_eq!(
            solver.to_string(),
            "linear system: singular position: an equation of the linear system is all \
             zeros (determinant 0, scale 0), so it has no unique solution at this pose"
        );
        let nan = Error::new(
            Primitive::Rrp,
            Fault::<f64>::NonFinite {
                what: "RRP joint C",
            },
        )
        .in_group("C");
        assert_eq!(
            nan.to_string(),
            "group `C` (RRP): RRP joint C is not finite (NaN or infinite): an input or \
             parameter is NaN or infinite, or a value overflowed the scalar type"
        );
        // The reviewer's f32 RRP miss, as the user now reads it.
        let miss = Error::new(
            Primitive::Rrp,
            Fault::CannotAssemble {
                miss: 6.775824e-21f32,
                reach: 2.5e-19,
            },
        )
        .in_group("C");
        let text = miss.to_string();
        assert!(
            text.contains("is 6.776e-21 outside") && text.contains("distance 2.5e-19,"),
            "{text}"
        );
    }
}
