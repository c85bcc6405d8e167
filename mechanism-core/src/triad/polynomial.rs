//! The closed form: the assembly polynomial of degree six in the half-angle
//! tangent of the ternary link's angle, its real roots, and the joint `A`
//! each root gives.
//!
//! # The polynomial
//!
//! In the normalized frame (origin `K1`), with the ternary's angle `phi`
//! written as the unit complex number `z = e^(i phi)`, `B - A = c z` and
//! `P - A = w z` (`w = u + i v`). Subtracting leg 1's equation `|A|^2 = l1^2`
//! from the others leaves two equations linear in `A`:
//! `A . d2 = h2`, `A . d3 = h3`, with `d2 = c z - k2`, `d3 = w z - k3`,
//! `h_j = (l_j^2 - l1^2 - |d_j|^2) / 2`. On `|z| = 1` each of `d_j`, `h_j`
//! and `D = d2 x d3` is a Laurent polynomial of order one in `z` (the `z
//! conj(z)` products are 1), and Cramer's rule gives `A D = i Q` with
//! `Q = h3 d2 - h2 d3 = z (c h3 - w h2) - (k2 h3 - k3 h2)`, whose powers of `z`
//! run from -1 to 2. Leg 1's equation then reads
//!
//! `F(phi) = |Q|^2 - l1^2 D^2 = 0`,
//!
//! a real trigonometric polynomial of order 3 (in `|Q|^2 = Q conj(Q)` the
//! powers run from `-1 - 2` to `2 + 1`): six roots at most, so a triad has
//! at most six assemblies. Its coefficients `F_m` (`m = 0..=3`, `F_-m =
//! conj(F_m)`) are products of the dimensions, computed here in a few dozen
//! multiplications, without heap.
//!
//! With `t = tan(phi / 2)`, `e^(i m phi) (1 + t^2)^3 = (1 + i t)^(2m) (1 +
//! t^2)^(3 - m)`, so `P(t) = (1 + t^2)^3 F` is a real polynomial of degree 6
//! whose leading coefficient is `F(pi)`. Rather than rotating the frame to
//! keep `phi = pi` away from a root, the circle is covered in two halves:
//! the roots of `P` in `[-1, 1]` (`phi` in `[-pi/2, pi/2]`) and those of the
//! reversed polynomial `s^6 P(1/s)` in `[-1, 1]` (`s = cot(phi / 2)`, the other
//! half), so no root is at infinity in either and a vanishing leading
//! coefficient is no special case. A root on the boundary (`|t| = 1`) may be
//! found twice; the assemblies are merged afterwards.
//!
//! # The real roots
//!
//! By the derivatives: the critical points of a polynomial (roots of its
//! derivative, found the same way, down to the quadratic fourth derivative,
//! whose roots are in closed form) split `[-1, 1]` into intervals on which
//! it is monotone, so each holds at most one root, bracketed where the
//! signs at the ends differ and found by Halley's method kept inside the
//! bracket (bisection when a step leaves it), stopped on its predicted
//! error. No root is missed for want of a sample, there are no Sturm
//! sequences whose remainders lose precision, and every root comes with a
//! bracket. Chosen over the eigenvalues of the 6x6 companion matrix (a
//! Hessenberg QR of about 10 n^3 = 2000 flops, complex pairs included,
//! against at most 18 bracketed solves of polynomials of degree three to
//! six per half, about 5 on the Stephenson swing, and no complex
//! arithmetic) and over Descartes' rule with bisection (many more
//! evaluations to isolate close roots). On the report's Stephenson swing
//! Halley's method (third order, its Taylor coefficients evaluated side by
//! side) takes about 3.7 steps a bracket, Newton's stopped on its own
//! predicted error 4.1, and Newton's stopped after a step below the
//! tolerance 7. The critical points that only split intervals need only
//! be accurate to `sqrt(eps) / 64`; the roots and extrema that start a
//! polish by Newton on the three leg equations ([`Frame::newton`], two
//! steps from there) are found to rounding, so that near a branch point,
//! where that Newton converges slowly, its start adds nothing to the
//! polynomial's own error.
//!
//! **Double roots.** Where two assemblies meet (a branch point, the end of a
//! swing), `P` touches zero without changing sign, or the rounding of its
//! coefficients makes two close roots a near-miss. Every local extremum of
//! `P` whose value is within rounding of zero ([`TANGENCY`] ulps of the sum
//! of the terms' magnitudes) is kept as a candidate too: the polish on the
//! loop then decides (it converges on the real assembly or fails, and then
//! nothing is added). Two real roots are told apart by the polynomial
//! whenever their separation exceeds about `sqrt(eps)` of the scale, that
//! is, everywhere but within about `eps` (relative) of an input's branch
//! point.
//!
//! **Degenerate triads.** When `F` vanishes identically (all coefficients
//! within rounding of zero: three legs from one point, or legs 1 and 3 both
//! ending at `A` from `K1`), every angle solves the reduced equation and the
//! polynomial says nothing: [`RootsOf::Degenerate`], and the caller falls
//! back on the sampled scan. Where `D` is small at a root (`d2`, `d3`
//! parallel), Cramer's rule is ill-conditioned and `A` comes instead from
//! leg 1's circle and the longer of the two lines, both intersections tried.

use super::frame::{Frame, State};
use crate::geometry::{abs, cross, dot, max, perp};
use crate::scalar::Real;
use nalgebra::{Complex, Vector2};

/// Degree of the assembly polynomial.
const DEGREE: usize = 6;

/// Coefficients of a polynomial of degree at most [`DEGREE`], ascending.
type Poly<T> = [T; DEGREE + 1];

/// A local extremum of `P` counts as a double-root candidate when its value
/// is within this many ulps of the sum of the magnitudes of its terms (the
/// rounding of the coefficients, a few dozen products each, with margin).
const TANGENCY: f64 = 256.0;

/// The polynomial is taken as identically zero when every coefficient is
/// within this many ulps of the largest product that formed it.
const VANISH: f64 = 4096.0;

/// Steps on one bracket of the root isolation (a step that does not at
/// least halve the bracket is followed by a bisection, so 60 reach any
/// precision).
const MAX_STEPS: usize = 60;

/// The largest Newton step `|p / p'|` (in the half-angle tangent, on
/// `[-1, 1]`) after which a root's step may be the last (see
/// [`bracketed`]): `2^-10`.
const SETTLE: f64 = 1.0 / 1024.0;

/// `Re` and `Im` of `(1 + i t)^(2m) (1 + t^2)^(3 - m)`, ascending powers of `t`,
/// for `m = 0..=3`: `P(t) = sum_m (2 - [m = 0]) Re(F_m basis_m)`.
const BASIS_RE: [[f64; 7]; 4] = [
    [1.0, 0.0, 3.0, 0.0, 3.0, 0.0, 1.0],
    [1.0, 0.0, 1.0, 0.0, -1.0, 0.0, -1.0],
    [1.0, 0.0, -5.0, 0.0, -5.0, 0.0, 1.0],
    [1.0, 0.0, -15.0, 0.0, 15.0, 0.0, -1.0],
];
/// See [`BASIS_RE`].
const BASIS_IM: [[f64; 7]; 4] = [
    [0.0; 7],
    [0.0, 2.0, 0.0, 4.0, 0.0, 2.0, 0.0],
    [0.0, 4.0, 0.0, 0.0, 0.0, -4.0, 0.0],
    [0.0, 6.0, 0.0, -20.0, 0.0, 6.0, 0.0],
];

/// A Laurent polynomial of order one, `x[0] / z + x[1] + x[2] z`.
type Order1<T> = [Complex<T>; 3];

/// The coefficients `F_0 ..= F_3` of `F(phi) = sum_m F_m z^m` (see the
/// module documentation) and the size of the products that formed them.
pub(super) fn closure_coefficients<T: Real>(f: &Frame<T>) -> ([Complex<T>; 4], T) {
    let cx = |x: T, y: T| Complex::new(x, y);
    let half = T::lit(0.5);
    let c = cx(f.c, T::zero());
    let w = cx(f.u, f.v);
    let k2 = cx(f.k2.x, f.k2.y);
    let k3 = cx(f.k3.x, f.k3.y);
    let l1s = f.l1 * f.l1;
    // h2 = (l2^2 - l1^2 - c^2 - |k2|^2) / 2 + (c k2 / 2) / z + (c conj(k2) / 2) z.
    let a2 = half * (f.l2 * f.l2 - l1s - f.c * f.c - k2.norm_sqr());
    let h2: Order1<T> = [
        k2 * (half * f.c),
        cx(a2, T::zero()),
        k2.conj() * (half * f.c),
    ];
    // h3 = (l3^2 - l1^2 - |w|^2 - |k3|^2) / 2 + conj(w) k3 / 2 / z + w conj(k3) / 2 z.
    let a3 = half * (f.l3 * f.l3 - l1s - w.norm_sqr() - k3.norm_sqr());
    let h3: Order1<T> = [
        w.conj() * k3 * half,
        cx(a3, T::zero()),
        w * k3.conj() * half,
    ];
    // s = c h3 - w h2 (times z below), r = k2 h3 - k3 h2.
    let s: Order1<T> = core::array::from_fn(|j| c * h3[j] - w * h2[j]);
    let r: Order1<T> = core::array::from_fn(|j| k2 * h3[j] - k3 * h2[j]);
    // Q = z s - r: powers -1 ..= 2.
    let q = [-r[0], s[0] - r[1], s[1] - r[2], s[2]];
    // conj(d2) d3 = (c w + conj(k2) k3) - c k3 / z - conj(k2) w z; D = its Im.
    let p: Order1<T> = [-(c * k3), c * w + k2.conj() * k3, -(k2.conj() * w)];
    let i2 = cx(T::zero(), half);
    // D_m = (p_m - conj(p_-m)) / (2 i), m = -1 ..= 1.
    let d: Order1<T> = core::array::from_fn(|j| (p[j] - p[2 - j].conj()) * (-i2));
    let mut out = [cx(T::zero(), T::zero()); 4];
    // |Q|^2: sum over j - k = m of q_j conj(q_k).
    for (m, o) in out.iter_mut().enumerate() {
        for k in 0..4 - m {
            *o += q[k + m] * q[k].conj();
        }
    }
    // - l1^2 D^2: sum over j + k = m of D_j D_k (D indexed -1 ..= 1).
    for (m, o) in out.iter_mut().enumerate().take(3) {
        for j in 0..3 {
            let k = m + 2 - j;
            if k <= 2 {
                *o -= d[j] * d[k] * l1s;
            }
        }
    }
    // The size of the products: |Q|'s and l1 |D|'s largest terms squared.
    let big = |v: &[Complex<T>]| v.iter().fold(T::zero(), |m, x| max(m, x.norm_sqr()));
    let scale = max(big(&q), l1s * big(&d));
    (out, scale)
}

/// `F(phi)` at the unit vector `e = (cos phi, sin phi)` from its
/// coefficients (the tests' check of the expansion).
#[cfg(test)]
pub(super) fn closure_at<T: Real>(fm: &[Complex<T>; 4], e: &Vector2<T>) -> T {
    let z = Complex::new(e.x, e.y);
    let mut zm = z;
    let mut sum = fm[0].re;
    for f in &fm[1..] {
        sum += T::lit(2.0) * (*f * zm).re;
        zm *= z;
    }
    sum
}

/// `P(t) = (1 + t^2)^3 F(phi)`, `t = tan(phi / 2)`, ascending powers.
fn tangent_polynomial<T: Real>(fm: &[Complex<T>; 4]) -> Poly<T> {
    let mut p = [T::zero(); DEGREE + 1];
    for (m, f) in fm.iter().enumerate() {
        let w = if m == 0 { T::one() } else { T::lit(2.0) };
        for (k, pk) in p.iter_mut().enumerate() {
            *pk += w * (f.re * T::lit(BASIS_RE[m][k]) - f.im * T::lit(BASIS_IM[m][k]));
        }
    }
    p
}

/// Up to this many starts: six roots and five extrema.
const MAX_STARTS: usize = 12;

/// The half-angle tangents that start a polish, in one half of the circle.
#[derive(Clone, Copy, Debug)]
pub(super) struct Starts<T: Real> {
    /// Roots and double-root candidates, in `[-1, 1]`.
    pub(super) list: [T; MAX_STARTS],
    /// How many of `list` are set.
    pub(super) count: usize,
}

impl<T: Real> Starts<T> {
    fn new() -> Self {
        Starts {
            list: [T::zero(); MAX_STARTS],
            count: 0,
        }
    }

    fn push(&mut self, x: T) {
        if let Some(slot) = self.list.get_mut(self.count) {
            *slot = x;
            self.count += 1;
        }
    }

    /// The starts found.
    pub(super) fn iter(&self) -> impl Iterator<Item = &T> {
        self.list.iter().take(self.count)
    }
}

/// What the polynomial gives for the two halves of the circle.
#[derive(Clone, Copy, Debug)]
pub(super) enum RootsOf<T: Real> {
    /// `t = tan(phi / 2)` in `[-1, 1]` and `s = cot(phi / 2)` in `[-1, 1]`.
    Halves(Starts<T>, Starts<T>),
    /// `F` vanishes identically: the polynomial decides nothing.
    Degenerate,
}

/// The real roots of the assembly polynomial (see the module documentation).
pub(super) fn roots<T: Real>(f: &Frame<T>) -> RootsOf<T> {
    let (fm, scale) = closure_coefficients(f);
    let p = tangent_polynomial(&fm);
    let size = p.iter().fold(T::zero(), |m, x| max(m, abs(*x)));
    // NaN (overflowed products) counts as vanishing too.
    let live = size > T::lit(VANISH) * T::eps() * scale;
    if !live {
        return RootsOf::Degenerate;
    }
    let mut rev = p;
    rev.reverse();
    RootsOf::Halves(roots_in_unit(&p), roots_in_unit(&rev))
}

/// `p(x)` and its Taylor coefficients at `x`, `p'(x)`, `p''(x) / 2` and
/// `p'''(x) / 6`, by Horner's rule (repeated synthetic division), for the
/// `n + 1` first coefficients: four chains side by side, about the latency
/// of `p(x)` alone.
#[inline(always)]
fn eval<T: Real>(p: &Poly<T>, n: usize, x: T) -> (T, T, T, T) {
    let mut v = p[n];
    let mut d = T::zero();
    let mut h = T::zero();
    let mut g = T::zero();
    for k in (0..n).rev() {
        g = g * x + h;
        h = h * x + d;
        d = d * x + v;
        v = v * x + p[k];
    }
    (v, d, h, g)
}

/// The sum of the magnitudes of `p`'s terms at `x` (rounding's scale).
fn magnitude<T: Real>(p: &Poly<T>, x: T) -> T {
    let ax = abs(x);
    p.iter().rev().fold(T::zero(), |m, c| m * ax + abs(*c))
}

/// The root in `[a, b]` of `p` (degree `n`), monotone there with `pa`, `pb`
/// of opposite signs: Halley's method from the midpoint, kept in the
/// bracket (bisection when a step leaves it).
///
/// With `v`, `d`, `h`, `g` the Taylor coefficients of [`eval`] at `x` and
/// `s = v / d` (Newton's step), Halley's step is `v d / (d^2 - v h)`, and
/// the root is off the point it reaches by about `s^3 (h^2 - g d) / d^2`
/// (the expansion of `v + d e + h e^2 + g e^3 = 0` to third order; the
/// omitted terms are of order `s^4`). That step is the last when this
/// predicted error is at most `tol` and `|s| <= 2^-10` (so the expansion
/// holds); the iteration also ends when the bracket is below `tol`.
fn bracketed<T: Real>(p: &Poly<T>, n: usize, mut a: T, mut b: T, pa: T, tol: T) -> T {
    let neg_a = pa < T::zero();
    let mut x = T::lit(0.5) * (a + b);
    for _ in 0..MAX_STEPS {
        let (v, d, h, g) = eval(p, n, x);
        if v == T::zero() {
            return x;
        }
        if (v < T::zero()) == neg_a {
            a = x;
        } else {
            b = x;
        }
        // Outside the bracket, or NaN (`d^2 = v h`): bisection.
        let halley = x - v * d / (d * d - v * h);
        let inside = halley > a && halley < b;
        let s = v / d;
        let settled = inside
            && abs(s) <= T::lit(SETTLE)
            && abs(s * s * s) * abs(h * h - g * d) <= tol * d * d;
        x = if inside {
            halley
        } else {
            T::lit(0.5) * (a + b)
        };
        if settled || b - a <= tol {
            break;
        }
    }
    x
}

/// The real roots of the quadratic `c[0] + c[1] x + c[2] x^2` in `[-1, 1]`,
/// ascending, in closed form (the critical points of the cubic level):
/// `q = -(c1 + sign(c1) sqrt(c1^2 - 4 c0 c2)) / 2`, roots `q / c2` and `c0 /
/// q` (no cancellation). A negative discriminant gives none: where it is
/// negative by rounding only, the two roots are within about `sqrt(eps)`
/// and the cubic's wiggle between them is of order `eps^(3/2)`, below its
/// rounding (a monotone piece that is not split there loses no root the
/// rounding does not hide already). A double root is kept (an extra split
/// of a monotone piece is harmless).
fn quadratic_roots<T: Real>(c: &Poly<T>) -> Starts<T> {
    let mut out = Starts::new();
    let one = T::one();
    let mut keep = |x: T| {
        if x >= -one && x <= one {
            out.push(x);
        }
    };
    let (c0, c1, c2) = (c[0], c[1], c[2]);
    if c2 == T::zero() {
        if c1 != T::zero() {
            keep(-c0 / c1);
        }
        return out;
    }
    let disc = c1 * c1 - T::lit(4.0) * c0 * c2;
    // NaN or infinite (overflowed products) gives none, as no sign change
    // would.
    if disc < T::zero() || !disc.finite() {
        return out;
    }
    let root = disc.sqrt_kernel();
    let q = T::lit(-0.5)
        * if c1 >= T::zero() {
            c1 + root
        } else {
            c1 - root
        };
    if q == T::zero() {
        // c1 = 0 and c0 = 0: the double root 0.
        keep(T::zero());
        return out;
    }
    let (r1, r2) = (q / c2, c0 / q);
    let (lo, hi) = if r1 <= r2 { (r1, r2) } else { (r2, r1) };
    keep(lo);
    keep(hi);
    out
}

/// Roots of `p` (degree `n`) in `[-1, 1]` given its sorted critical points
/// there, each to `tol` ([`bracketed`]); with `tangent`, also the extrema
/// within rounding of zero.
fn level<T: Real>(p: &Poly<T>, n: usize, crit: &Starts<T>, tangent: bool, tol: T) -> Starts<T> {
    let mut out = Starts::new();
    let one = T::one();
    let mut a = -one;
    let (mut pa, ..) = eval(p, n, a);
    if pa == T::zero() {
        out.push(a);
    }
    let ends = crit.iter().copied().chain(core::iter::once(one));
    for b in ends {
        let (pb, ..) = eval(p, n, b);
        if pb == T::zero() {
            out.push(b);
        } else if (pa < T::zero() && pb > T::zero()) || (pa > T::zero() && pb < T::zero()) {
            out.push(bracketed(p, n, a, b, pa, tol));
        } else if tangent && b < one && abs(pb) <= T::lit(TANGENCY) * T::eps() * magnitude(p, b) {
            out.push(b);
        }
        (a, pa) = (b, pb);
    }
    out
}

/// Every real root of `p` in `[-1, 1]` and its near-double roots, by the
/// derivatives' roots (see the module documentation): the quadratic fourth
/// derivative's in closed form, then each level's from the next one's.
fn roots_in_unit<T: Real>(p: &Poly<T>) -> Starts<T> {
    // ders[k]: the k-th derivative, degree DEGREE - k.
    let mut ders = [*p; DEGREE - 1];
    for k in 1..DEGREE - 1 {
        let prev = ders[k - 1];
        let n = DEGREE - k;
        for j in 0..=n {
            ders[k][j] = prev[j + 1] * T::lit((j + 1) as f64);
        }
        for x in ders[k].iter_mut().skip(n + 1) {
            *x = T::zero();
        }
    }
    // The critical points of the third and second derivatives only split
    // intervals: `sqrt(eps) / 64` is ample (a split off by `d` changes the
    // next level's values there by about `d^2`, far below their rounding).
    // The first derivative's roots (the extrema, candidates for double
    // roots) and the polynomial's start the polish on the loop: to rounding
    // (`eps`), so the polish starts where the polynomial puts the root, as
    // accurately as its coefficients allow; near a branch point, where the
    // loop's Jacobian is nearly singular and Newton converges slowly, a
    // start off by `sqrt(eps)` would leave its mark in the rates.
    let split = T::eps().sqrt() * T::lit(1.0 / 64.0);
    let mut crit = quadratic_roots(&ders[DEGREE - 2]);
    for k in (0..DEGREE - 2).rev() {
        let tol = if k <= 1 { T::eps() } else { split };
        crit = level(&ders[k], DEGREE - k, &crit, k == 0, tol);
    }
    crit
}

/// The Newton starts (normalized `A` and the ternary's angle) at the root
/// `(cos phi, sin phi) = e`: one from Cramer's rule, or two from leg 1's
/// circle when the two lines are nearly parallel; `None` for unused slots.
pub(super) fn starts_at<T: Real>(f: &Frame<T>, e: &Vector2<T>) -> [Option<State<T>>; 2] {
    let half = T::lit(0.5);
    let (ab, ap) = f.offsets(e);
    let (d2, d3) = (ab - f.k2, ap - f.k3);
    let l1s = f.l1 * f.l1;
    let h2 = half * (f.l2 * f.l2 - l1s - dot(&d2, &d2));
    let h3 = half * (f.l3 * f.l3 - l1s - dot(&d3, &d3));
    let det = cross(&d2, &d3);
    let (n2, n3) = (dot(&d2, &d2), dot(&d3, &d3));
    // |sin| of the angle between the lines above 1/1024: Cramer's rule.
    if det * det > T::lit(1.0 / 1_048_576.0) * n2 * n3 {
        let a = (Vector2::new(d3.y, -d3.x) * h2 + Vector2::new(-d2.y, d2.x) * h3) / det;
        return [Some(State { a, e: *e }), None];
    }
    let (n, h, nn) = if n2 >= n3 { (d2, h2, n2) } else { (d3, h3, n3) };
    let usable = nn > T::zero();
    if !usable {
        return [None, None];
    }
    let foot = n * (h / nn);
    let off = max(l1s - h * h / nn, T::zero()).sqrt_kernel();
    let side = perp(&n) * (off / nn.sqrt_kernel());
    let (p, m) = (foot + side, foot - side);
    [Some(State { a: p, e: *e }), Some(State { a: m, e: *e })]
}

/// The unit vector of `phi` from `t = tan(phi / 2)` (`flip`: from `s =
/// cot(phi / 2)`).
pub(super) fn unit_of<T: Real>(t: T, flip: bool) -> Vector2<T> {
    let t2 = t * t;
    let den = T::one() + t2;
    let c = (T::one() - t2) / den;
    let s = T::lit(2.0) * t / den;
    if flip {
        Vector2::new(-c, s)
    } else {
        Vector2::new(c, s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::triad::Triad;
    use nalgebra::Point2;

    /// A triad with every dimension distinct and known points in general
    /// position (normalized frame: the largest dimension 1.7 scales by 1).
    fn frame() -> Frame<f64> {
        let triad = Triad {
            l1: 0.9,
            l2: 1.3,
            l3: 1.1,
            ab: 1.7,
            p_local: Vector2::new(0.4, 0.8),
        };
        let k = [
            Point2::new(0.0, 0.0),
            Point2::new(1.9, 0.3),
            Point2::new(0.7, 1.6),
        ];
        Frame::new(&triad, &k).unwrap()
    }

    /// The direct `F(phi) = |A D|^2 - l1^2 D^2` from the two lines.
    fn direct(f: &Frame<f64>, phi: f64) -> f64 {
        let e = Vector2::new(phi.cos(), phi.sin());
        let (ab, ap) = f.offsets(&e);
        let (d2, d3) = (ab - f.k2, ap - f.k3);
        let l1s = f.l1 * f.l1;
        let h2 = 0.5 * (f.l2 * f.l2 - l1s - d2.dot(&d2));
        let h3 = 0.5 * (f.l3 * f.l3 - l1s - d3.dot(&d3));
        let det = d2.x * d3.y - d2.y * d3.x;
        let ad = Vector2::new(d3.y, -d3.x) * h2 + Vector2::new(-d2.y, d2.x) * h3;
        ad.dot(&ad) - l1s * det * det
    }

    #[test]
    fn coefficients_reproduce_the_reduced_equation() {
        // Proves the expansion into F_0..F_3 (the order-3 claim included:
        // no z^4 term is dropped that matters) and the half-angle polynomial
        // P(t) = (1 + t^2)^3 F agree with F computed directly from Cramer's
        // rule, at angles all round the circle (t from tan(phi/2)); the
        // tolerance is rounding of terms of size `scale` (a few hundred eps).
        let f = frame();
        let (fm, scale) = closure_coefficients(&f);
        let p = tangent_polynomial(&fm);
        for k in 0..72 {
            let phi = -3.1 + 0.086 * k as f64;
            let want = direct(&f, phi);
            let got = closure_at(&fm, &Vector2::new(phi.cos(), phi.sin()));
            assert!(
                (got - want).abs() <= 256.0 * f64::EPSILON * scale,
                "{phi}: {got} vs {want}"
            );
            let t = (0.5 * phi).tan();
            let (pt, ..) = eval(&p, DEGREE, t);
            let want_p = want * (1.0 + t * t).powi(3);
            assert!(
                (pt - want_p).abs() <= 256.0 * f64::EPSILON * scale * (1.0 + t * t).powi(3),
                "{phi}: {pt} vs {want_p}"
            );
        }
    }

    #[test]
    fn roots_are_the_sign_changes_of_the_polynomial() {
        // Proves the isolation by derivatives finds every sign change of a
        // polynomial with six known real roots in [-1, 1], two of them 1e-6
        // apart (an independent count: the product form), to the requested
        // sqrt(eps)/64, and none where there is none.
        let r: [f64; 6] = [-0.9, -0.31, 0.2, 0.2 + 1e-6, 0.55, 0.97];
        let mut p = [0.0; 7];
        p[0] = 1.0;
        for (n, root) in r.iter().enumerate() {
            // multiply by (x - root)
            for j in (0..=n + 1).rev() {
                let lower = if j > 0 { p[j - 1] } else { 0.0 };
                p[j] = lower - root * p[j];
            }
        }
        let got = roots_in_unit(&p);
        assert_eq!(got.count, 6, "{got:?}");
        for (g, w) in got.iter().zip(&r) {
            assert!((g - w).abs() < 1e-9, "{g} vs {w}");
        }
        // Shifted up by 1: no real root in [-1, 1] (the minimum of the
        // product there is far above -1).
        let mut q = p;
        q[0] += 1.0;
        assert_eq!(roots_in_unit(&q).count, 0);
    }
}
