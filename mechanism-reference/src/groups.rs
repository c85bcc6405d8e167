//! Double-double references for the class II groups, written from their
//! defining equations (not from `mechanism-core`'s formulas): circle-circle
//! and line-circle intersections for the positions, Cramer's rule on the
//! differentiated loop-closure equations for the rates, and the six
//! Newton-Euler equations of an RRR group for its reactions.
//!
//! Inputs are `f64` values taken as exact; every intermediate is a [`Dd`]
//! (about 106 bits). Where a formula here cancels (for example
//! `h^2 = l1^2 - a^2` near the edge of assembly) it still keeps about
//! `106 - log2(1 / delta)` bits, far more than an `f64` result can be checked
//! against; the stability tests state where that matters.
//!
//! Conventions as in `mechanism-core`: angles counter-clockwise from +x,
//! `perp(v) = (-v.y, v.x)`, "left" of a directed line is `+perp`.

use crate::linear;
use crate::Dd;

/// A planar vector in double-double.
pub type V = [Dd; 2];

/// `(x, y)` exactly.
pub fn v(x: f64, y: f64) -> V {
    [Dd::from(x), Dd::from(y)]
}

/// `a + b`.
pub fn add(a: V, b: V) -> V {
    [a[0] + b[0], a[1] + b[1]]
}

/// `a - b`.
pub fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1]]
}

/// `k a`.
pub fn scale(k: Dd, a: V) -> V {
    [k * a[0], k * a[1]]
}

/// `a . b`.
pub fn dot(a: V, b: V) -> Dd {
    a[0] * b[0] + a[1] * b[1]
}

/// `a x b` (z component).
pub fn cross(a: V, b: V) -> Dd {
    a[0] * b[1] - a[1] * b[0]
}

/// `a` turned +90 degrees.
pub fn perp(a: V) -> V {
    [-a[1], a[0]]
}

/// Euclidean length.
pub fn norm(a: V) -> Dd {
    dot(a, a).sqrt()
}

/// Rounds to `f64`.
pub fn to_f64(a: V) -> [f64; 2] {
    [a[0].to_f64(), a[1].to_f64()]
}

/// Solves `x c0 + y c1 = r` for `(x, y)` by Cramer's rule (the 2x2 rate
/// systems of every group). `None` when the determinant is exactly zero.
pub fn solve2(c0: V, c1: V, r: V) -> Option<(Dd, Dd)> {
    let det = cross(c0, c1);
    if det.hi == 0.0 {
        return None;
    }
    Some((cross(r, c1) / det, cross(c0, r) / det))
}

/// RRR closure: the point `C` with `|C - A| = l1`, `|C - B| = l2`, on the
/// left of `A -> B` when `left`. Circle-circle intersection: the foot of `C`
/// on `AB` at `a = (l1^2 - l2^2 + d^2) / (2 d)` from `A`, height
/// `h = sqrt(l1^2 - a^2)`. `None` when `h^2 < 0` (no intersection) or `A = B`.
pub fn rrr_position(a: V, l1: f64, b: V, l2: f64, left: bool) -> Option<V> {
    let (l1, l2) = (Dd::from(l1), Dd::from(l2));
    let d = sub(b, a);
    let dist2 = dot(d, d);
    if dist2.hi == 0.0 {
        return None;
    }
    let dist = dist2.sqrt();
    let along = (l1.sqr() - l2.sqr() + dist2) / dist.scale_pow2(1);
    let h2 = l1.sqr() - along.sqr();
    if h2.hi < 0.0 {
        return None;
    }
    let h = if left { h2.sqrt() } else { -h2.sqrt() };
    let e = scale(Dd::ONE / dist, d);
    Some(add(a, add(scale(along, e), scale(h, perp(e)))))
}

/// RRR rates: `omega1 perp(C - A) - omega2 perp(C - B) = vB - vA`, solved for
/// `(omega1, omega2)`.
pub fn rrr_rates(a: V, b: V, c: V, va: V, vb: V) -> Option<(Dd, Dd)> {
    let r1 = sub(c, a);
    let r2 = sub(c, b);
    solve2(perp(r1), scale(-Dd::ONE, perp(r2)), sub(vb, va))
}

/// RRR accelerations: `alpha1 perp(r1) - alpha2 perp(r2) = aB - aA +
/// omega1^2 r1 - omega2^2 r2` (the rates' equation differentiated once more).
#[allow(clippy::too_many_arguments)]
pub fn rrr_accelerations(
    a: V,
    b: V,
    c: V,
    aa: V,
    ab: V,
    omega1: Dd,
    omega2: Dd,
) -> Option<(Dd, Dd)> {
    let r1 = sub(c, a);
    let r2 = sub(c, b);
    let rhs = add(
        sub(ab, aa),
        sub(scale(omega1.sqr(), r1), scale(omega2.sqr(), r2)),
    );
    solve2(perp(r1), scale(-Dd::ONE, perp(r2)), rhs)
}

/// A straight guide through `origin` along `dir` (normalized here in
/// double-double, so an `f64` direction that is unit only to rounding is
/// taken as the exact line it names).
#[derive(Clone, Copy, Debug)]
pub struct Line {
    /// A point of the line.
    pub origin: V,
    /// Unit direction.
    pub dir: V,
}

impl Line {
    /// The line through `origin` along `dir` (any nonzero length).
    pub fn new(origin: [f64; 2], dir: [f64; 2]) -> Line {
        let d = v(dir[0], dir[1]);
        Line {
            origin: v(origin[0], origin[1]),
            dir: scale(Dd::ONE / norm(d), d),
        }
    }

    /// The point at displacement `s` along the line and `offset` to its left.
    pub fn at(&self, s: Dd, offset: Dd) -> V {
        add(
            self.origin,
            add(scale(s, self.dir), scale(offset, perp(self.dir))),
        )
    }
}

/// RRP closure: the point `C` on the line `g` shifted left by `offset` with
/// `|C - A| = l`, ahead of the foot of the perpendicular from `A` (along
/// `dir`) when `ahead`. Returns `(C, s)` with `C = g.at(s, offset)`.
/// Line-circle intersection: with `t = (A - origin) . dir`, the chord's half
/// length is `sqrt(l^2 - k^2)`, `k` the distance of `A` from the shifted line.
/// `None` when the circle misses the line.
pub fn rrp_position(a: V, l: f64, g: &Line, offset: f64, ahead: bool) -> Option<(V, Dd)> {
    let p = sub(a, g.origin);
    let t = dot(p, g.dir);
    let k = dot(p, perp(g.dir)) - Dd::from(offset);
    let half2 = Dd::from(l).sqr() - k.sqr();
    if half2.hi < 0.0 {
        return None;
    }
    let half = if ahead { half2.sqrt() } else { -half2.sqrt() };
    let s = t + half;
    Some((g.at(s, Dd::from(offset)), s))
}

/// RRP rates on a fixed guide: `omega1 perp(C - A) - s_dot dir = -vA`, solved
/// for `(omega1, s_dot)`.
pub fn rrp_rates(a: V, c: V, g: &Line, va: V) -> Option<(Dd, Dd)> {
    solve2(perp(sub(c, a)), scale(-Dd::ONE, g.dir), scale(-Dd::ONE, va))
}

/// RRP accelerations on a fixed guide: `alpha1 perp(r1) - s_ddot dir =
/// -aA + omega1^2 r1`.
pub fn rrp_accelerations(a: V, c: V, g: &Line, aa: V, omega1: Dd) -> Option<(Dd, Dd)> {
    let r1 = sub(c, a);
    solve2(
        perp(r1),
        scale(-Dd::ONE, g.dir),
        sub(scale(omega1.sqr(), r1), aa),
    )
}

/// RPR closure: the slide line's unit direction `u` (link 2's axis, through
/// `B` offset by `offset`) and the block's place `s` with
/// `A = B + s u + offset perp(u)`, `s >= 0` when `positive`. From
/// `|A - B|^2 = s^2 + offset^2`, then `u` from the 2x2 system
/// `s u + offset perp(u) = A - B`. `None` when `|A - B| < |offset|`.
pub fn rpr_position(a: V, b: V, offset: f64, positive: bool) -> Option<(V, Dd)> {
    let p = sub(a, b);
    let e = Dd::from(offset);
    let s2 = dot(p, p) - e.sqr();
    if s2.hi < 0.0 {
        return None;
    }
    let s = if positive { s2.sqrt() } else { -s2.sqrt() };
    // [s  -e; e  s] (ux, uy) = p.
    let det = s.sqr() + e.sqr();
    if det.hi == 0.0 {
        return None;
    }
    let ux = (s * p[0] + e * p[1]) / det;
    let uy = (s * p[1] - e * p[0]) / det;
    Some(([ux, uy], s))
}

/// RPR rates: `s_dot u + omega perp(A - B) = vA - vB`, solved for
/// `(omega, s_dot)`.
pub fn rpr_rates(a: V, b: V, u: V, va: V, vb: V) -> Option<(Dd, Dd)> {
    solve2(perp(sub(a, b)), u, sub(va, vb))
}

/// PRP closure: `C = g1.at(s1, o1) = g2.at(s2, o2)`; returns `(C, s1, s2)`.
pub fn prp_position(g1: &Line, o1: f64, g2: &Line, o2: f64) -> Option<(V, Dd, Dd)> {
    let q = sub(
        add(g2.origin, scale(Dd::from(o2), perp(g2.dir))),
        add(g1.origin, scale(Dd::from(o1), perp(g1.dir))),
    );
    let (s1, s2m) = solve2(g1.dir, scale(-Dd::ONE, g2.dir), q)?;
    Some((g1.at(s1, Dd::from(o1)), s1, s2m))
}

/// PRP rates on fixed guides with a moving guide 2 origin velocity `w`
/// (translating guide 2): `s1_dot dir1 - s2_dot dir2 = w`.
pub fn prp_rates(g1: &Line, g2: &Line, w: V) -> Option<(Dd, Dd)> {
    solve2(g1.dir, scale(-Dd::ONE, g2.dir), w)
}

/// RPP closure: `A = g.at(s2, offset) + s1 w`, `w = c dir + s perp(dir)` for
/// the slot's local direction `(c, s)` (normalized here); returns `(s1, s2)`.
pub fn rpp_position(a: V, g: &Line, offset: f64, slot_local: [f64; 2]) -> Option<(Dd, Dd)> {
    let w = rpp_slot(g, slot_local);
    let q = sub(sub(a, g.origin), scale(Dd::from(offset), perp(g.dir)));
    solve2(w, g.dir, q)
}

/// The RPP slot's world direction for a local direction (normalized).
pub fn rpp_slot(g: &Line, slot_local: [f64; 2]) -> V {
    let l = v(slot_local[0], slot_local[1]);
    let l = scale(Dd::ONE / norm(l), l);
    add(scale(l[0], g.dir), scale(l[1], perp(g.dir)))
}

/// RPP rates on a fixed guide: `s1_dot w + s2_dot dir = vA`.
pub fn rpp_rates(g: &Line, slot_local: [f64; 2], va: V) -> Option<(Dd, Dd)> {
    solve2(rpp_slot(g, slot_local), g.dir, va)
}

/// The tip of a crank of length `r` about `pivot` at angle `theta` (rad), with
/// its velocity and acceleration for the angular speed `omega` and angular
/// acceleration `alpha`: `(A, vA, aA)`.
pub fn crank(pivot: V, r: f64, theta: f64, omega: f64, alpha: f64) -> (V, V, V) {
    let (s, c) = Dd::from(theta).sin_cos();
    let rv = [Dd::from(r) * c, Dd::from(r) * s];
    let (w, al) = (Dd::from(omega), Dd::from(alpha));
    (
        add(pivot, rv),
        scale(w, perp(rv)),
        sub(scale(al, perp(rv)), scale(w.sqr(), rv)),
    )
}

/// Reactions of an RRR group (joints `A`, `B` outer, `C` inner) from the
/// Newton-Euler (d'Alembert) equations of its two links, each link's moment
/// taken about its own outer joint (a different point from the one
/// `mechanism-core` uses). Each link `i` carries a known force `f_i` through
/// the point `p_i` and a couple `m_i` (which include inertia and weight).
/// Unknowns: `F_A` (outside on link 1), `F_B` (outside on link 2), `F_C`
/// (link 1 on link 2). Returns `[F_A.x, F_A.y, F_B.x, F_B.y, F_C.x, F_C.y]`.
#[allow(clippy::too_many_arguments)]
pub fn rrr_reactions(
    a: V,
    b: V,
    c: V,
    f1: V,
    p1: V,
    m1: Dd,
    f2: V,
    p2: V,
    m2: Dd,
) -> Option<[Dd; 6]> {
    let z = Dd::ZERO;
    let one = Dd::ONE;
    let ca = sub(c, a);
    let cb = sub(c, b);
    // Link 1: F_A - F_C + f1 = 0; moment about A: (C - A) x (-F_C) +
    // (p1 - A) x f1 + m1 = 0.
    // Link 2: F_B + F_C + f2 = 0; about B: (C - B) x F_C + (p2 - B) x f2 + m2 = 0.
    let rows = vec![
        vec![one, z, z, z, -one, z],
        vec![z, one, z, z, z, -one],
        vec![z, z, z, z, ca[1], -ca[0]],
        vec![z, z, one, z, one, z],
        vec![z, z, z, one, z, one],
        vec![z, z, z, z, -cb[1], cb[0]],
    ];
    let rhs = vec![
        -f1[0],
        -f1[1],
        -(cross(sub(p1, a), f1) + m1),
        -f2[0],
        -f2[1],
        -(cross(sub(p2, b), f2) + m2),
    ];
    let x = linear::solve(rows, rhs).ok()?;
    Some([x[0], x[1], x[2], x[3], x[4], x[5]])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn three_four_five() {
        // A = 0, B = (5, 0), l1 = 3, l2 = 4: C = (1.8, 2.4) exactly.
        let c = rrr_position(v(0.0, 0.0), 3.0, v(5.0, 0.0), 4.0, true).unwrap();
        // 1.8 and 2.4 are not binary fractions: compare 5 C with (9, 12).
        assert!((c[0] * Dd::from(5.0) - Dd::from(9.0)).abs().hi < 1e-30);
        assert!((c[1] * Dd::from(5.0) - Dd::from(12.0)).abs().hi < 1e-30);
    }

    #[test]
    fn line_circle() {
        // Circle of radius 5 about (0, 3) on the x axis: C = (4, 0).
        let g = Line::new([0.0, 0.0], [1.0, 0.0]);
        let (c, s) = rrp_position(v(0.0, 3.0), 5.0, &g, 0.0, true).unwrap();
        assert!((s - Dd::from(4.0)).abs().hi < 1e-30);
        assert!(c[1].abs().hi < 1e-30);
    }

    #[test]
    fn rpr_axis() {
        // A = (3, 4), B = 0, offset 0: u = (0.6, 0.8), s = 5.
        let (u, s) = rpr_position(v(3.0, 4.0), v(0.0, 0.0), 0.0, true).unwrap();
        assert!((s - Dd::from(5.0)).abs().hi < 1e-30);
        assert!((u[0] * Dd::from(5.0) - Dd::from(3.0)).abs().hi < 1e-30);
    }
}
