//! Lane version of the RRR group ([`crate::dyad::rrr`]), also the position
//! of the linear actuator (an RRR with the input as second length).

use super::{abs, select, sqrt};
use crate::geometry::{normal_range, SINGULAR_RELATIVE};
use crate::scalar::Real;

/// A closed RRR group: the lane version of [`crate::dyad::rrr::position`],
/// with the reciprocal of the rate system's determinant for the rates.
#[derive(Clone, Copy, Debug)]
pub struct Rrr<T> {
    /// The inner joint `C` (L).
    pub x: T,
    /// The inner joint `C` (L).
    pub y: T,
    /// `C - A` (L).
    pub r1x: T,
    /// `C - A` (L).
    pub r1y: T,
    /// `C - B` (L).
    pub r2x: T,
    /// `C - B` (L).
    pub r2y: T,
    /// `1 / cross(r1, r2)` (1 where the rate check failed).
    pub inv_det: T,
    /// Assembled, strictly inside the rounding band of the scalar check.
    pub ok: bool,
    /// The rate system passed `det^2 > 4 (16 eps)^2 |r1|^2 |r2|^2`: four times
    /// the scalar threshold, so that an element passing here passes the scalar
    /// check whatever the rounding differences between the two paths.
    pub ok_rate: bool,
}

/// Closes the group `|C - A| = l1`, `|C - B| = l2`; `sign` is `+1` for
/// `C` left of `A -> B` (`Mode::Plus`), `-1` for right. The formulas are those
/// of the scalar primitive (Heron's factors, foot of `C` on `AB`); `ok` is
/// false unless every factor exceeds the rounding band `4 eps (l1 + l2)`,
/// the lengths are positive and `A != B` (elements in the band go to the
/// scalar path, which puts `C` on the line).
#[inline(always)]
pub fn rrr<T: Real>(ax: T, ay: T, l1: T, bx: T, by: T, l2: T, sign: T) -> Rrr<T> {
    // The scalar primitive's formula (Heron on squared lengths, one square
    // root, one reciprocal; see `dyad::rrr`), with its failures as flags.
    let (dx, dy) = (bx - ax, by - ay);
    let dsq = dx * dx + dy * dy;
    let (lo, hi) = normal_range::<T>();
    // `|B - A|^2` a normal number (a subnormal one has lost bits; with a
    // normal `prod` below, the third powers are then normal too).
    let spread = dsq >= lo;
    let sum = l1 + l2;
    let diff = l1 - l2;
    let outer = sum * sum - dsq;
    let inner = dsq - diff * diff;
    // Strictly inside the scalar's rounding band (which it accepts down to
    // minus the band): an element accepted here is accepted there.
    let band = T::lit(8.0) * T::eps() * sum;
    let adiff = select(diff < T::zero(), -diff, diff);
    let clamp = |x: T| select(x < T::zero(), T::zero(), x);
    // The product is a fourth power of the lengths: outside the normal range
    // (f32 lengths below about 1e-10 or above about 4e9) it loses bits or
    // overflows, and the element goes to the scalar path, which solves in
    // first powers of the lengths there (`dyad::rrr::position`).
    let prod = clamp(outer) * clamp(inner);
    let ok = spread
        & (l1 > T::zero())
        & (l2 > T::zero())
        & (outer > band * sum)
        & (inner > band * adiff)
        & (prod >= lo)
        & (prod <= hi);
    let height = sign * sqrt(prod);
    let along = diff * sum + dsq;
    let inv_2dsq = T::one() / (T::lit(2.0) * select(spread, dsq, T::one()));
    let (r1x, r1y) = (
        (dx * along - dy * height) * inv_2dsq,
        (dy * along + dx * height) * inv_2dsq,
    );
    let (x, y) = (ax + r1x, ay + r1y);
    let (r2x, r2y) = (x - bx, y - by);
    let det = r1x * r2y - r1y * r2x;
    let scale_sq = (r1x * r1x + r1y * r1y) * (r2x * r2x + r2y * r2y);
    let k = T::lit(2.0 * SINGULAR_RELATIVE) * T::eps();
    let ok_rate = det * det > k * k * scale_sq;
    // cross(r1, r2) = cross(B - A, r1) = height / 2 exactly (substitute r1
    // above): the reciprocal from `height` starts right after the square
    // root instead of waiting for r1, C, r2 and the cross product. It
    // differs from `1 / det` by rounding only (a few ulp, relative to the
    // rates' conditioning), and the check above stays on `det`.
    // The select keeps the reciprocal finite (|r1| |r2| = l1 l2 up to
    // rounding) without waiting for the check.
    let half_h = T::lit(0.5) * height;
    let h_ok = abs(half_h) > k * l1 * l2;
    Rrr {
        x,
        y,
        r1x,
        r1y,
        r2x,
        r2y,
        inv_det: T::one() / select(h_ok, half_h, T::one()),
        ok,
        ok_rate,
    }
}

/// Angular velocities `(omega1, omega2)` of the group's links from
/// `dv = vB - vA` (the scalar primitive's formulas with `1 / det`).
#[inline(always)]
pub fn rrr_rates<T: Real>(g: &Rrr<T>, dvx: T, dvy: T) -> (T, T) {
    (
        (dvx * g.r2x + dvy * g.r2y) * g.inv_det,
        (dvx * g.r1x + dvy * g.r1y) * g.inv_det,
    )
}

/// Angular accelerations `(alpha1, alpha2)` from `da = aB - aA` and the rates.
#[inline(always)]
pub fn rrr_accels<T: Real>(g: &Rrr<T>, dax: T, day: T, w1: T, w2: T) -> (T, T) {
    let (q1, q2) = (w1 * w1, w2 * w2);
    let wx = dax + g.r1x * q1 - g.r2x * q2;
    let wy = day + g.r1y * q1 - g.r2y * q2;
    (
        (wx * g.r2x + wy * g.r2y) * g.inv_det,
        (wx * g.r1x + wy * g.r1y) * g.inv_det,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::__private::lane::crank;
    use crate::mode::Mode;
    use nalgebra::Point2;

    /// The lane RRR against the scalar primitive over a sweep of a four-bar
    /// (crank 101.6 about the origin, coupler 254, rocker 177.8 about
    /// (304.8, 0)): the same joint to a few ulp of the lengths, the same
    /// verdict wherever the lane says ok, and rates that agree to the
    /// conditioning.
    #[test]
    fn rrr_matches_the_scalar_primitive() {
        use crate::dyad::rrr;
        use nalgebra::Vector2;
        let (ax0, l0, l1, l2, bx) = (0.0, 101.6, 254.0, 177.8, 304.8);
        let mut oks = 0;
        for i in 0..20_000 {
            let th = i as f64 * core::f64::consts::TAU / 20_000.0;
            for (sign, mode) in [(1.0, Mode::Plus), (-1.0, Mode::Minus)] {
                let cr = crank(ax0, 0.0, l0, th);
                let g = rrr(cr.x, cr.y, l1, bx, 0.0, l2, sign);
                let a = Point2::new(cr.x, cr.y);
                let s = rrr::position(&a, l1, &Point2::new(bx, 0.0), l2, mode);
                if !g.ok {
                    continue;
                }
                oks += 1;
                let s = s.expect("lane ok implies scalar ok");
                // Lengths ~250: a few ulp of 250 is ~1e-13; the joint comes
                // from a square root and a division chain, each within 1 ulp.
                // 4 ulp of the largest length.
                let tol = 4.0 * f64::EPSILON * 512.0;
                assert!(
                    (g.x - s.c.x).abs() < tol && (g.y - s.c.y).abs() < tol,
                    "{th}"
                );
                let va = Vector2::new(-cr.ry * 10.0, cr.rx * 10.0);
                let sv = rrr::velocity(&s, Some(&va), None).expect("rates");
                let (w1, w2) = rrr_rates(&g, -va.x, -va.y);
                // The rates' relative error is about eps / condition; the
                // transmission angle of this four-bar keeps the condition
                // above 0.3: 64 eps relative covers both paths.
                let rel = |a: f64, b: f64| (a - b).abs() / b.abs().max(1.0);
                assert!(rel(w1, sv.omega1) < 64.0 * f64::EPSILON, "{th}");
                assert!(rel(w2, sv.omega2) < 64.0 * f64::EPSILON, "{th}");
            }
        }
        assert_eq!(oks, 40_000, "this four-bar assembles everywhere");
        // Cannot assemble: too far apart, and coincident joints.
        assert!(!rrr(0.0, 0.0, 1.0, 3.0, 0.0, 1.0, 1.0).ok);
        let g = rrr(0.0f64, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0);
        assert!(!g.ok && g.x.is_finite() && g.inv_det.is_finite());
        // A toggle (links aligned): position fine, rates flagged.
        let g = rrr(0.0, 0.0, 1.0, 2.0 - 1e-9, 0.0, 1.0, 1.0);
        assert!(g.ok);
        let g = rrr(0.0, 0.0, 1.0, 2.0 - 1e-30, 0.0, 1.0, 1.0);
        assert!(!g.ok_rate);
    }

    /// f32 four-bars whose product of squared lengths leaves the normal
    /// range (lengths near 1e-10: subnormal; near 1e11: infinite) are handed
    /// to the scalar path, which takes the two square roots apart; at unit
    /// scale the same pose stays in the kernel.
    #[test]
    fn rrr_hands_back_products_outside_the_normal_range() {
        for (k, in_kernel) in [(1.0e-12f64, false), (1.0, true), (2.0e9, false)] {
            let l = |x: f64| (x * k) as f32;
            let cr = crank(0.0f32, 0.0, l(101.6), 1.0);
            let g = rrr(cr.x, cr.y, l(254.0), l(304.8), 0.0, l(177.8), 1.0);
            assert_eq!(g.ok, in_kernel, "scale {k:e}");
        }
    }
}
