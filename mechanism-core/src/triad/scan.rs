//! The sampled search along the loops of the four-bar `K1 - A - B - K2`
//! (see the module documentation of [`super`]).

use super::frame::{Frame, State};
use super::{Assemblies, Near, MAX_ASSEMBLIES, SAMPLES};
use crate::geometry::{abs, angle, dot, length, min, perp, unit};
use crate::scalar::Real;
use nalgebra::Vector2;

/// One closed loop of the four-bar `K1 - A - B - K2` in `t` in `[0, 2 pi)`.
#[derive(Clone, Copy, Debug)]
enum Loop<T: Real> {
    /// `theta = psi + t` on one branch (sign `+1` or `-1`).
    Full { sign: T },
    /// `theta = psi + mid - half cos t`, branch `sign(sin t)`.
    Arc { mid: T, half: T },
}

/// The loops of [`loops`] and the angle `psi` of `K2 - K1` they start from.
type Loops<T> = ([Option<Loop<T>>; 2], T);

/// The loops of the four-bar `K1 - A - B - K2` (at most two), or the
/// `CannotAssemble` miss and reach (normalized) when it never closes.
fn loops<T: Real>(f: &Frame<T>) -> Result<Loops<T>, (T, T)> {
    let m = length(&f.k2);
    let psi = if m > T::zero() {
        angle(&f.k2)
    } else {
        T::zero()
    };
    let (outer, inner) = (f.c + f.l2, abs(f.c - f.l2));
    // |A - K2| ranges over [|m - l1|, m + l1] and must meet [inner, outer].
    let (near, far) = (abs(m - f.l1), m + f.l1);
    if near > outer {
        return Err((near - outer, outer));
    }
    if far < inner {
        return Err((inner - far, inner));
    }
    let two_pi = T::two_pi();
    let full = [
        Some(Loop::Full { sign: T::one() }),
        Some(Loop::Full { sign: -T::one() }),
    ];
    let denom = T::lit(2.0) * f.l1 * m;
    if denom <= T::zero() {
        // K1 = K2: |A - K2| = l1 whatever theta, inside the range (above).
        return Ok((full, psi));
    }
    // cos(theta - psi) within [lo, hi] keeps |A - K2| within [inner, outer].
    let base = m * m + f.l1 * f.l1;
    let lo = (base - outer * outer) / denom;
    let hi = (base - inner * inner) / denom;
    let clamp = |x: T| crate::geometry::max(-T::one(), min(x, T::one()));
    let (a_hi, a_lo) = (clamp(hi).acos(), clamp(lo).acos());
    let arc = |a0: T, a1: T| {
        Some(Loop::Arc {
            mid: T::lit(0.5) * (a0 + a1),
            half: T::lit(0.5) * (a1 - a0),
        })
    };
    let out = if lo <= -T::one() && hi >= T::one() {
        full
    } else if hi >= T::one() {
        [arc(-a_lo, a_lo), None]
    } else if lo <= -T::one() {
        [arc(a_hi, two_pi - a_hi), None]
    } else {
        [arc(a_hi, a_lo), arc(-a_lo, -a_hi)]
    };
    Ok((out, psi))
}

/// A point of a loop at `t`: the sample and the residual
/// `|P - K3| - l3` (normalized); `None` where `A` meets `K2`.
///
/// Out of line: the scan calls it from six places, each of which would
/// otherwise carry its own copy of the sine and cosine kernel into every
/// definition's code (compile time; the scan is the rare path).
#[inline(never)]
fn curve<T: Real>(f: &Frame<T>, lp: &Loop<T>, psi: T, t: T) -> Option<(Sample<T>, T)> {
    let (theta, sign) = match *lp {
        Loop::Full { sign } => (psi + t, sign),
        Loop::Arc { mid, half } => {
            let (s, c) = t.sin_cos_kernel();
            let sign = if s >= T::zero() { T::one() } else { -T::one() };
            (psi + mid - half * c, sign)
        }
    };
    let a = unit(theta) * f.l1;
    let g = f.k2 - a;
    let dd = dot(&g, &g);
    if dd <= T::zero() {
        return None;
    }
    let (outer, inner) = (f.c + f.l2, f.c - f.l2);
    let pos = |x: T| crate::geometry::max(x, T::zero());
    let prod = pos(outer * outer - dd) * pos(dd - inner * inner);
    let h = sign * prod.sqrt_kernel();
    let ab = (g * ((f.c - f.l2) * (f.c + f.l2) + dd) + perp(&g) * h) / (T::lit(2.0) * dd);
    let e = ab / f.c;
    let (_, ap) = f.offsets(&e);
    let res = length(&(a + ap - f.k3)) - f.l3;
    res.finite().then_some(((a, e), res))
}

/// A point of a loop: `A` and the ternary's unit axis (normalized frame).
type Sample<T> = (Vector2<T>, Vector2<T>);

/// The Newton state at a sample (the axis's angle taken only here, for the
/// few samples that start a polish).
fn state<T: Real>((a, e): Sample<T>) -> State<T> {
    State { a, e }
}

/// Samples one loop, starts Newton at every bracket and near-zero minimum.
fn scan<T: Real>(f: &Frame<T>, lp: &Loop<T>, psi: T, found: &mut Assemblies<T>, least: &mut T) {
    let step = T::two_pi() / T::lit(SAMPLES as f64);
    let at = |j: usize| step * T::lit((j % SAMPLES) as f64);
    let eval = |j: usize| curve(f, lp, psi, at(j));
    // A window of three samples (j - 1, j, j + 1), wrapping around the loop.
    let mut prev = eval(SAMPLES - 1);
    let mut here = eval(0);
    for j in 0..SAMPLES {
        let next = eval(j + 1);
        if let Some((x, r)) = here {
            if abs(r) < *least {
                *least = abs(r);
            }
            if r == T::zero() {
                add_root(f, state(x), found);
            }
            if let Some((_, rn)) = next {
                if (r < T::zero() && rn > T::zero()) || (r > T::zero() && rn < T::zero()) {
                    let t = bracket(f, lp, psi, at(j), at(j) + step, r, rn);
                    if let Some((xt, _)) = curve(f, lp, psi, t) {
                        add_root(f, state(xt), found);
                    }
                }
            }
            if let (Some((_, rp)), Some((_, rn))) = (prev, next) {
                minimum(f, lp, psi, at(j), step, [rp, r, rn], found);
            }
        }
        prev = here;
        here = next;
    }
}

/// The Illinois method on `f(t)` over `[t0, t1]` with `r0`, `r1` of opposite
/// signs: up to 60 steps, until the bracket or the residual is at rounding
/// level; returns the best `t`.
fn bracket<T: Real>(f: &Frame<T>, lp: &Loop<T>, psi: T, t0: T, t1: T, r0: T, r1: T) -> T {
    let (mut a, mut b, mut fa, mut fb) = (t0, t1, r0, r1);
    let mut side = 0i8;
    for _ in 0..60 {
        let t = (a * fb - b * fa) / (fb - fa);
        let Some((_, ft)) = curve(f, lp, psi, t) else {
            return t;
        };
        if ft == T::zero() || abs(b - a) <= T::lit(4.0) * T::eps() {
            return t;
        }
        if (ft > T::zero()) == (fb > T::zero()) {
            b = t;
            fb = ft;
            if side == -1 {
                fa *= T::lit(0.5);
            }
            side = -1;
        } else {
            a = t;
            fa = ft;
            if side == 1 {
                fb *= T::lit(0.5);
            }
            side = 1;
        }
    }
    (a * fb - b * fa) / (fb - fa)
}

/// A sampled local minimum of `|r|` without a sign change, where the
/// parabola through the three samples comes near zero (its vertex within
/// four second differences of it): a pair of roots closer than the sample
/// spacing may hide there. The extremum of `r` in `[t - step, t + step]` is
/// located by golden-section search (48 steps: to `1e-10` of the spacing);
/// where `r` changes sign there, each side is a bracket for [`bracket`];
/// where it only comes within `sqrt(eps)` of the scale (a tangency, a double
/// root) Newton starts from it.
fn minimum<T: Real>(
    f: &Frame<T>,
    lp: &Loop<T>,
    psi: T,
    t: T,
    step: T,
    [rp, r, rn]: [T; 3],
    found: &mut Assemblies<T>,
) {
    let same = (rp > T::zero()) == (r > T::zero()) && (rn > T::zero()) == (r > T::zero());
    if !(same && abs(r) <= abs(rp) && abs(r) < abs(rn)) {
        return;
    }
    let half = T::lit(0.5);
    let slope = half * (rn - rp);
    let curv = half * (rn - T::lit(2.0) * r + rp);
    if curv == T::zero() {
        return;
    }
    let vertex = -slope / (T::lit(2.0) * curv);
    let low = r + slope * vertex + curv * vertex * vertex;
    if abs(low) > T::lit(4.0) * abs(curv) {
        return;
    }
    // Minimize `sign(r) r` (the samples' side) over `[t - step, t + step]`.
    let side = if r > T::zero() { T::one() } else { -T::one() };
    let eval = |x: T| curve(f, lp, psi, x).map(|(_, v)| side * v);
    let g = T::lit(0.381_966_011_250_105_1);
    let (mut a, mut b) = (t - step, t + step);
    let (mut x1, mut x2) = (a + g * (b - a), b - g * (b - a));
    let (Some(mut f1), Some(mut f2)) = (eval(x1), eval(x2)) else {
        return;
    };
    for _ in 0..48 {
        if f1 <= f2 {
            (b, x2, f2) = (x2, x1, f1);
            x1 = a + g * (b - a);
            let Some(v) = eval(x1) else { return };
            f1 = v;
        } else {
            (a, x1, f1) = (x1, x2, f2);
            x2 = b - g * (b - a);
            let Some(v) = eval(x2) else { return };
            f2 = v;
        }
        if f1 < T::zero() || f2 < T::zero() {
            break;
        }
    }
    let (tm, fm) = if f1 <= f2 { (x1, f1) } else { (x2, f2) };
    if fm < T::zero() {
        // Two roots: one on each side of `tm` (signed residuals again).
        let (r_lo, r_mid, r_hi) = (side * rp, side * fm, side * rn);
        for (t0, t1, r0, r1) in [(t - step, tm, r_lo, r_mid), (tm, t + step, r_mid, r_hi)] {
            let tr = bracket(f, lp, psi, t0, t1, r0, r1);
            if let Some((x, _)) = curve(f, lp, psi, tr) {
                add_root(f, state(x), found);
            }
        }
    } else if fm <= T::eps().sqrt() * f.l3 {
        if let Some((x, _)) = curve(f, lp, psi, tm) {
            add_root(f, state(x), found);
        }
    }
}

/// Polishes `x` by Newton and keeps it unless it duplicates one found.
pub(super) fn add_root<T: Real>(f: &Frame<T>, x: State<T>, found: &mut Assemblies<T>) {
    let Some(pos) = f.newton(x).and_then(|x| f.finish(&x)) else {
        return;
    };
    let tol = T::eps().sqrt() * T::lit(0.125);
    if found.iter().all(|q| f.distance(q, &Near::of(&pos)) > tol) {
        found.push(pos);
    }
}

/// Every assembly by the sampled scan of each loop.
pub(super) fn search<T: Real>(f: &Frame<T>) -> Assemblies<T> {
    let mut found = Assemblies {
        list: [None; MAX_ASSEMBLIES],
        count: 0,
        miss: T::zero(),
        reach: f.l3 * f.up,
    };
    let (loops, psi) = match loops(f) {
        Ok(l) => l,
        Err((miss, reach)) => {
            found.miss = miss * f.up;
            found.reach = reach * f.up;
            return found;
        }
    };
    let mut least = T::lit(f64::INFINITY);
    for lp in loops.iter().flatten() {
        scan(f, lp, psi, &mut found, &mut least);
    }
    if found.is_empty() {
        found.miss = if least.finite() {
            least * f.up
        } else {
            found.reach
        };
    }
    found
}
