//! A forward-mode dual number with `N` derivative components, [`Dual`], that
//! implements [`Real`], so every generated function and every primitive runs
//! on it and returns, beside each value, its exact partial derivatives with
//! respect to `N` chosen seeds (parameters, inputs, anything the caller
//! builds the arguments from).
//!
//! A value is `re + sum_k eps[k] e_k` with `e_j e_k = 0`: the arithmetic and
//! every elementary function carry the first-order Taylor term, so
//! `f(x + e) = f(x) + f'(x) e` exactly (to rounding). Seeding: a variable is
//! [`Dual::var`]`(value, k)` (its derivative along seed `k` is 1), a constant
//! is [`Dual::cst`] or [`Real::lit`].
//!
//! Comparisons (`<`, `==`, `min`, `max`, `clamp`) look at the real part only,
//! so a branch (an assembly mode, a wrap of an angle) takes the branch the
//! `f64` evaluation takes and the derivative is that branch's one. At a
//! branch point (`abs` at 0, a square root of 0) the derivative is the one-
//! sided or infinite value the formula gives; the generated code returns a
//! typed error there anyway (a square root of a negative discriminant).
//!
//! Why a type of our own rather than `num-dual`'s: [`Real`] needs
//! `core::fmt::LowerExp` (errors print their numbers from generic code),
//! which `num-dual`'s types do not implement and which the orphan rule keeps
//! this crate from adding; its types also need `std`. This one is `no_std`,
//! `Copy`, a fixed array (no allocation), and its transcendental functions
//! take the real part through the `f64` kernels of [`Real`] for `f64`.

use core::fmt;
use core::ops::{
    Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Rem, RemAssign, Sub, SubAssign,
};

use nalgebra::{ComplexField, RealField, SimdValue};
use num_traits::{FromPrimitive, Num, One, Signed, Zero};

use crate::scalar::Real;

/// `re + sum_k eps[k] e_k`: a value (`re`) and its derivatives with respect
/// to `N` seeds (`eps[k]` = d value / d seed k), in the caller's units.
#[derive(Clone, Copy, Debug)]
pub struct Dual<const N: usize> {
    /// The value.
    pub re: f64,
    /// The partial derivatives of the value along the `N` seeds.
    pub eps: [f64; N],
}

impl<const N: usize> Dual<N> {
    /// A constant: every derivative zero.
    #[inline(always)]
    pub const fn cst(re: f64) -> Self {
        Dual { re, eps: [0.0; N] }
    }

    /// The seed `k` itself at `re`: derivative 1 along seed `k`, 0 along the
    /// others. `k >= N` gives a constant (no seed).
    #[inline(always)]
    pub fn var(re: f64, k: usize) -> Self {
        let mut eps = [0.0; N];
        if let Some(e) = eps.get_mut(k) {
            *e = 1.0;
        }
        Dual { re, eps }
    }

    /// `f(self)` given `f(re)` and `f'(re)` (the chain rule).
    #[inline(always)]
    fn chain(self, value: f64, slope: f64) -> Self {
        let mut eps = self.eps;
        for e in eps.iter_mut() {
            *e *= slope;
        }
        Dual { re: value, eps }
    }

    /// `a * self + b * other` on the derivative parts, with value `re`.
    #[inline(always)]
    fn combine(self, a: f64, other: Self, b: f64, re: f64) -> Self {
        let mut eps = self.eps;
        for (e, o) in eps.iter_mut().zip(other.eps.iter()) {
            *e = a * *e + b * *o;
        }
        Dual { re, eps }
    }
}

// The f64 functions of the real part, in this crate's no_std setting
// (nalgebra's libm-backed implementations for f64).
fn sqrt64(x: f64) -> f64 {
    <f64 as ComplexField>::sqrt(x)
}

impl<const N: usize> Default for Dual<N> {
    fn default() -> Self {
        Self::cst(0.0)
    }
}

impl<const N: usize> PartialEq for Dual<N> {
    /// Compares the values only (see the module's note on comparisons).
    fn eq(&self, other: &Self) -> bool {
        self.re == other.re
    }
}

impl<const N: usize> PartialOrd for Dual<N> {
    /// Orders by value only (see the module's note on comparisons).
    fn partial_cmp(&self, other: &Self) -> Option<core::cmp::Ordering> {
        self.re.partial_cmp(&other.re)
    }
}

impl<const N: usize> fmt::Display for Dual<N> {
    fn fmt(&self, fm: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.re, fm)?;
        for (k, e) in self.eps.iter().enumerate() {
            write!(fm, " + {e}e{k}")?;
        }
        Ok(())
    }
}

impl<const N: usize> fmt::LowerExp for Dual<N> {
    fn fmt(&self, fm: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::LowerExp::fmt(&self.re, fm)?;
        for (k, e) in self.eps.iter().enumerate() {
            write!(fm, " + {e:e}e{k}")?;
        }
        Ok(())
    }
}

// ---- arithmetic ----------------------------------------------------------

impl<const N: usize> Add for Dual<N> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        self.combine(1.0, o, 1.0, self.re + o.re)
    }
}
impl<const N: usize> Sub for Dual<N> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        self.combine(1.0, o, -1.0, self.re - o.re)
    }
}
impl<const N: usize> Mul for Dual<N> {
    type Output = Self;
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        self.combine(o.re, o, self.re, self.re * o.re)
    }
}
impl<const N: usize> Div for Dual<N> {
    type Output = Self;
    #[inline(always)]
    fn div(self, o: Self) -> Self {
        let inv = 1.0 / o.re;
        let q = self.re * inv;
        self.combine(inv, o, -q * inv, q)
    }
}
impl<const N: usize> Rem for Dual<N> {
    type Output = Self;
    /// `self - trunc(self / o) * o`: derivative 1 along `self`, `-trunc(q)`
    /// along `o` (the truncated quotient is locally constant).
    fn rem(self, o: Self) -> Self {
        let t = <f64 as ComplexField>::trunc(self.re / o.re);
        self.combine(1.0, o, -t, self.re % o.re)
    }
}
impl<const N: usize> Neg for Dual<N> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        self.chain(-self.re, -1.0)
    }
}

macro_rules! assign_ops {
    ($($tr:ident $m:ident $op:tt),*) => {$(
        impl<const N: usize> $tr for Dual<N> {
            #[inline(always)]
            fn $m(&mut self, o: Self) {
                *self = *self $op o;
            }
        }
    )*};
}
assign_ops!(AddAssign add_assign +, SubAssign sub_assign -, MulAssign mul_assign *,
    DivAssign div_assign /, RemAssign rem_assign %);

// ---- num-traits ----------------------------------------------------------

impl<const N: usize> Zero for Dual<N> {
    fn zero() -> Self {
        Self::cst(0.0)
    }
    fn is_zero(&self) -> bool {
        self.re == 0.0
    }
}
impl<const N: usize> One for Dual<N> {
    fn one() -> Self {
        Self::cst(1.0)
    }
}
impl<const N: usize> Num for Dual<N> {
    type FromStrRadixErr = num_traits::ParseFloatError;
    fn from_str_radix(s: &str, radix: u32) -> Result<Self, Self::FromStrRadixErr> {
        <f64 as Num>::from_str_radix(s, radix).map(Self::cst)
    }
}
impl<const N: usize> Signed for Dual<N> {
    fn abs(&self) -> Self {
        if self.re < 0.0 {
            -*self
        } else {
            *self
        }
    }
    fn abs_sub(&self, o: &Self) -> Self {
        if self.re <= o.re {
            Self::zero()
        } else {
            *self - *o
        }
    }
    fn signum(&self) -> Self {
        Self::cst(<f64 as Signed>::signum(&self.re))
    }
    fn is_positive(&self) -> bool {
        self.re > 0.0
    }
    fn is_negative(&self) -> bool {
        self.re < 0.0
    }
}
impl<const N: usize> FromPrimitive for Dual<N> {
    fn from_i64(n: i64) -> Option<Self> {
        Some(Self::cst(n as f64))
    }
    fn from_u64(n: u64) -> Option<Self> {
        Some(Self::cst(n as f64))
    }
    fn from_f64(n: f64) -> Option<Self> {
        Some(Self::cst(n))
    }
}

// ---- approx ---------------------------------------------------------------

impl<const N: usize> approx::AbsDiffEq for Dual<N> {
    type Epsilon = Self;
    fn default_epsilon() -> Self {
        Self::cst(f64::EPSILON)
    }
    fn abs_diff_eq(&self, o: &Self, e: Self) -> bool {
        self.re.abs_diff_eq(&o.re, e.re)
    }
}
impl<const N: usize> approx::RelativeEq for Dual<N> {
    fn default_max_relative() -> Self {
        Self::cst(f64::EPSILON)
    }
    fn relative_eq(&self, o: &Self, e: Self, r: Self) -> bool {
        self.re.relative_eq(&o.re, e.re, r.re)
    }
}
impl<const N: usize> approx::UlpsEq for Dual<N> {
    fn default_max_ulps() -> u32 {
        4
    }
    fn ulps_eq(&self, o: &Self, e: Self, u: u32) -> bool {
        self.re.ulps_eq(&o.re, e.re, u)
    }
}

// ---- simba ------------------------------------------------------------------

// A scalar is a SIMD value of one lane; simba declares the unchecked lane
// accessors `unsafe`, and these bodies (the value itself) have nothing unsafe.
#[allow(unsafe_code)]
impl<const N: usize> SimdValue for Dual<N> {
    const LANES: usize = 1;
    type Element = Self;
    type SimdBool = bool;
    fn splat(v: Self) -> Self {
        v
    }
    fn extract(&self, _: usize) -> Self {
        *self
    }
    unsafe fn extract_unchecked(&self, _: usize) -> Self {
        *self
    }
    fn replace(&mut self, _: usize, v: Self) {
        *self = v;
    }
    unsafe fn replace_unchecked(&mut self, _: usize, v: Self) {
        *self = v;
    }
    fn select(self, cond: bool, other: Self) -> Self {
        if cond {
            self
        } else {
            other
        }
    }
}

impl<const N: usize> nalgebra::Field for Dual<N> {}

impl<const N: usize> simba::scalar::SubsetOf<Dual<N>> for Dual<N> {
    fn to_superset(&self) -> Self {
        *self
    }
    fn from_superset_unchecked(e: &Self) -> Self {
        *e
    }
    fn is_in_subset(_: &Self) -> bool {
        true
    }
}
impl<const N: usize> simba::scalar::SubsetOf<Dual<N>> for f64 {
    fn to_superset(&self) -> Dual<N> {
        Dual::cst(*self)
    }
    /// The value; the derivatives are dropped.
    fn from_superset_unchecked(e: &Dual<N>) -> f64 {
        e.re
    }
    fn is_in_subset(e: &Dual<N>) -> bool {
        e.eps.iter().all(|d| *d == 0.0)
    }
}
impl<const N: usize> simba::scalar::SubsetOf<Dual<N>> for f32 {
    fn to_superset(&self) -> Dual<N> {
        Dual::cst(f64::from(*self))
    }
    /// The value rounded to `f32`; the derivatives are dropped.
    fn from_superset_unchecked(e: &Dual<N>) -> f32 {
        e.re as f32
    }
    fn is_in_subset(e: &Dual<N>) -> bool {
        e.eps.iter().all(|d| *d == 0.0)
    }
}

macro_rules! consts {
    ($($name:ident = $v:expr),*) => {$(
        fn $name() -> Self {
            Self::cst($v)
        }
    )*};
}

impl<const N: usize> RealField for Dual<N> {
    fn is_sign_positive(&self) -> bool {
        self.re.is_sign_positive()
    }
    fn is_sign_negative(&self) -> bool {
        self.re.is_sign_negative()
    }
    fn copysign(self, sign: Self) -> Self {
        if self.re.is_sign_negative() == sign.re.is_sign_negative() {
            self
        } else {
            -self
        }
    }
    fn max(self, o: Self) -> Self {
        if o.re > self.re {
            o
        } else {
            self
        }
    }
    fn min(self, o: Self) -> Self {
        if o.re < self.re {
            o
        } else {
            self
        }
    }
    fn clamp(self, lo: Self, hi: Self) -> Self {
        RealField::min(RealField::max(self, lo), hi)
    }
    /// `atan2(self, x)`: the angle of `(x, self)`; derivative
    /// `(x dy - y dx) / (x^2 + y^2)`.
    fn atan2(self, x: Self) -> Self {
        let r2 = x.re * x.re + self.re * self.re;
        let v = <f64 as RealField>::atan2(self.re, x.re);
        self.combine(x.re / r2, x, -self.re / r2, v)
    }
    fn min_value() -> Option<Self> {
        Some(Self::cst(f64::MIN))
    }
    fn max_value() -> Option<Self> {
        Some(Self::cst(f64::MAX))
    }
    consts!(
        pi = core::f64::consts::PI,
        two_pi = core::f64::consts::TAU,
        frac_pi_2 = core::f64::consts::FRAC_PI_2,
        frac_pi_3 = core::f64::consts::FRAC_PI_3,
        frac_pi_4 = core::f64::consts::FRAC_PI_4,
        frac_pi_6 = core::f64::consts::FRAC_PI_6,
        frac_pi_8 = core::f64::consts::FRAC_PI_8,
        frac_1_pi = core::f64::consts::FRAC_1_PI,
        frac_2_pi = core::f64::consts::FRAC_2_PI,
        frac_2_sqrt_pi = core::f64::consts::FRAC_2_SQRT_PI,
        e = core::f64::consts::E,
        log2_e = core::f64::consts::LOG2_E,
        log10_e = core::f64::consts::LOG10_E,
        ln_2 = core::f64::consts::LN_2,
        ln_10 = core::f64::consts::LN_10
    );
}

/// The elementary functions: value and slope of the f64 function at `re`.
macro_rules! unary {
    ($($name:ident => |$x:ident| $vd:expr),* $(,)?) => {$(
        #[inline]
        fn $name(self) -> Self {
            let $x = self.re;
            let (v, d): (f64, f64) = $vd;
            self.chain(v, d)
        }
    )*};
}

impl<const N: usize> ComplexField for Dual<N> {
    type RealField = Self;
    fn from_real(re: Self) -> Self {
        re
    }
    fn real(self) -> Self {
        self
    }
    fn imaginary(self) -> Self {
        Self::zero()
    }
    fn modulus(self) -> Self {
        Signed::abs(&self)
    }
    fn modulus_squared(self) -> Self {
        self * self
    }
    fn argument(self) -> Self {
        if self.re >= 0.0 {
            Self::zero()
        } else {
            Self::pi()
        }
    }
    fn norm1(self) -> Self {
        Signed::abs(&self)
    }
    fn scale(self, factor: Self) -> Self {
        self * factor
    }
    fn unscale(self, factor: Self) -> Self {
        self / factor
    }
    fn floor(self) -> Self {
        Self::cst(<f64 as ComplexField>::floor(self.re))
    }
    fn ceil(self) -> Self {
        Self::cst(<f64 as ComplexField>::ceil(self.re))
    }
    fn round(self) -> Self {
        Self::cst(<f64 as ComplexField>::round(self.re))
    }
    fn trunc(self) -> Self {
        Self::cst(<f64 as ComplexField>::trunc(self.re))
    }
    fn fract(self) -> Self {
        self.chain(<f64 as ComplexField>::fract(self.re), 1.0)
    }
    fn mul_add(self, a: Self, b: Self) -> Self {
        self * a + b
    }
    fn abs(self) -> Self {
        Signed::abs(&self)
    }
    fn hypot(self, o: Self) -> Self {
        let h = <f64 as ComplexField>::hypot(self.re, o.re);
        self.combine(self.re / h, o, o.re / h, h)
    }
    fn recip(self) -> Self {
        Self::one() / self
    }
    fn conjugate(self) -> Self {
        self
    }
    fn sin_cos(self) -> (Self, Self) {
        let (s, c) = <f64 as ComplexField>::sin_cos(self.re);
        (self.chain(s, c), self.chain(c, -s))
    }
    fn log(self, base: Self) -> Self {
        self.ln() / base.ln()
    }
    fn powi(self, n: i32) -> Self {
        let v = <f64 as ComplexField>::powi(self.re, n);
        let d = if n == 0 {
            0.0
        } else {
            f64::from(n) * <f64 as ComplexField>::powi(self.re, n - 1)
        };
        self.chain(v, d)
    }
    /// `self^n = exp(n ln self)`, both varying.
    fn powf(self, n: Self) -> Self {
        let v = <f64 as ComplexField>::powf(self.re, n.re);
        let ds = if n.re == 0.0 {
            0.0
        } else {
            n.re * <f64 as ComplexField>::powf(self.re, n.re - 1.0)
        };
        let dn = if v == 0.0 {
            0.0
        } else {
            v * <f64 as ComplexField>::ln(self.re)
        };
        self.combine(ds, n, dn, v)
    }
    fn powc(self, n: Self) -> Self {
        self.powf(n)
    }
    fn is_finite(&self) -> bool {
        self.re.is_finite() && self.eps.iter().all(|e| e.is_finite())
    }
    fn try_sqrt(self) -> Option<Self> {
        if self.re >= 0.0 {
            Some(ComplexField::sqrt(self))
        } else {
            None
        }
    }
    unary!(
        sin => |x| (<f64 as ComplexField>::sin(x), <f64 as ComplexField>::cos(x)),
        cos => |x| (<f64 as ComplexField>::cos(x), -<f64 as ComplexField>::sin(x)),
        tan => |x| {
            let t = <f64 as ComplexField>::tan(x);
            (t, 1.0 + t * t)
        },
        asin => |x| (<f64 as ComplexField>::asin(x), 1.0 / sqrt64(1.0 - x * x)),
        acos => |x| (<f64 as ComplexField>::acos(x), -1.0 / sqrt64(1.0 - x * x)),
        atan => |x| (<f64 as ComplexField>::atan(x), 1.0 / (1.0 + x * x)),
        sinh => |x| (<f64 as ComplexField>::sinh(x), <f64 as ComplexField>::cosh(x)),
        cosh => |x| (<f64 as ComplexField>::cosh(x), <f64 as ComplexField>::sinh(x)),
        tanh => |x| {
            let t = <f64 as ComplexField>::tanh(x);
            (t, 1.0 - t * t)
        },
        asinh => |x| (<f64 as ComplexField>::asinh(x), 1.0 / sqrt64(x * x + 1.0)),
        acosh => |x| (<f64 as ComplexField>::acosh(x), 1.0 / sqrt64(x * x - 1.0)),
        atanh => |x| (<f64 as ComplexField>::atanh(x), 1.0 / (1.0 - x * x)),
        log2 => |x| (<f64 as ComplexField>::log2(x), core::f64::consts::LOG2_E / x),
        log10 => |x| (<f64 as ComplexField>::log10(x), core::f64::consts::LOG10_E / x),
        ln => |x| (<f64 as ComplexField>::ln(x), 1.0 / x),
        ln_1p => |x| (<f64 as ComplexField>::ln_1p(x), 1.0 / (1.0 + x)),
        sqrt => |x| {
            let r = sqrt64(x);
            (r, 0.5 / r)
        },
        exp => |x| {
            let v = <f64 as ComplexField>::exp(x);
            (v, v)
        },
        exp2 => |x| {
            let v = <f64 as ComplexField>::exp2(x);
            (v, v * core::f64::consts::LN_2)
        },
        exp_m1 => |x| (<f64 as ComplexField>::exp_m1(x), <f64 as ComplexField>::exp(x)),
        cbrt => |x| {
            let r = <f64 as ComplexField>::cbrt(x);
            (r, 1.0 / (3.0 * r * r))
        },
    );
}

impl<const N: usize> Real for Dual<N> {
    #[inline(always)]
    fn lit(x: f64) -> Self {
        Self::cst(x)
    }
    /// The value; the derivatives are dropped.
    #[inline(always)]
    fn as_f64(self) -> f64 {
        self.re
    }
    #[inline(always)]
    fn eps() -> Self {
        Self::cst(f64::EPSILON)
    }
    /// The value and every derivative finite.
    #[inline(always)]
    fn finite(self) -> bool {
        ComplexField::is_finite(&self)
    }
    #[inline(always)]
    fn sin_cos_kernel(self) -> (Self, Self) {
        let (s, c) = self.re.sin_cos_kernel();
        (self.chain(s, c), self.chain(c, -s))
    }
    #[inline(always)]
    fn sqrt_kernel(self) -> Self {
        let r = self.re.sqrt_kernel();
        self.chain(r, 0.5 / r)
    }
    #[inline(always)]
    fn atan2_kernel(self, x: Self) -> Self {
        let r2 = x.re * x.re + self.re * self.re;
        let v = self.re.atan2_kernel(x.re);
        self.combine(x.re / r2, x, -self.re / r2, v)
    }
    #[inline(always)]
    fn angle_kernel(self, x: Self) -> Self {
        let r2 = x.re * x.re + self.re * self.re;
        let v = self.re.angle_kernel(x.re);
        self.combine(x.re / r2, x, -self.re / r2, v)
    }
}
