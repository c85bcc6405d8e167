//! The problem in a normalized frame and Newton's method on the three leg
//! equations: the polish every assembly ends in.
//!
//! [`Frame::new`], [`Frame::newton`] and [`Frame::finish`] are inlined into
//! their callers (the kernels of [`super::Kernels`] and `scan::add_root`):
//! called out of line, the frame and the states pass through memory, where
//! a field written by scalar stores and read back by a vector load stalls
//! the load (no store forwarding). Inlined, `position_near` with rates took
//! about 16 % less time on x86-64 (AMD EPYC, `perf`: the stalls were most
//! of the kernel's own samples), for about 2.4 kB more code per scalar type.

use super::{Near, Triad, TriadPosition, JUMP_FRACTION, MAX_NEWTON, PRIM};
use crate::eft::{half_excess, split, Word};
use crate::error::{Error, Fault};
use crate::geometry::{abs, all_finite, cross, dot, length, max, min, perp};
use crate::scalar::{native, Real};
use nalgebra::{Point2, Vector2};

/// The problem in the normalized frame: origin `K1`, lengths divided by
/// `up` (a power of two, exact).
#[derive(Clone, Copy, Debug)]
pub(super) struct Frame<T: Real> {
    pub(super) origin: Point2<T>,
    pub(super) down: T,
    pub(super) up: T,
    pub(super) k2: Vector2<T>,
    pub(super) k3: Vector2<T>,
    pub(super) l1: T,
    pub(super) l2: T,
    pub(super) l3: T,
    pub(super) c: T,
    pub(super) u: T,
    pub(super) v: T,
    /// `R`: `1 + |K2 - K1| + |K3 - K1|` (normalized), the size of the
    /// coordinates the residuals are rounded at.
    pub(super) reach: T,
    /// `K2` and `K3` as given: [`Frame::polish`] takes their differences
    /// from `K1` exactly (`k2`, `k3` are those differences rounded).
    known: [Point2<T>; 2],
}

/// [`Frame::finish`] polishes a state whose relative determinant is below
/// this ([`Frame::polish`]). Without it, the rates' error near a branch
/// point grows like `1 / jacobian^2` (the pose's error like `1 /
/// jacobian`): on the Stephenson III's swing 8.7e-13 at `|jacobian|` 0.022
/// (docs/report.md, "Stephenson (triad)"), so about 1e-13 at 1/16 and a
/// quarter of that at 1/8, the bound taken. 70 of the swing's 3600 inputs
/// fall under it (2 %).
pub(super) const POLISH_BELOW: f64 = 0.125;

/// The most steps of [`Frame::polish`]: the first corrects the state, the
/// second (when the first was above rounding level) moves it by at most
/// about an ulp, to the rounded solution.
const POLISH_STEPS: usize = 2;

/// The geometry of a state (normalized): see [`Frame::pose`].
#[derive(Clone, Copy, Debug)]
struct Pose<T: Real> {
    a: Vector2<T>,
    e: Vector2<T>,
    ab: Vector2<T>,
    ap: Vector2<T>,
    r2: Vector2<T>,
    r3: Vector2<T>,
    jacobian: T,
}

/// A Newton state in the normalized frame: `A` and the ternary's unit axis
/// (`(cos, sin)` of its angle: no trigonometry in the iteration).
#[derive(Clone, Copy, Debug)]
pub(super) struct State<T: Real> {
    /// Joint `A` (normalized).
    pub(super) a: Vector2<T>,
    /// The ternary's axis, along `A -> B`, of unit length.
    pub(super) e: Vector2<T>,
}

fn validate<T: Real>(triad: &Triad<T>, k: &[Point2<T>; 3]) -> Result<(), Error<T>> {
    let lengths = [
        (triad.l1, "triad leg length l1"),
        (triad.l2, "triad leg length l2"),
        (triad.l3, "triad leg length l3"),
        (triad.ab, "triad side |AB|"),
    ];
    for (x, what) in lengths {
        crate::geometry::positive(x, PRIM, what)?;
    }
    if !all_finite([triad.p_local.x, triad.p_local.y]) {
        return Err(Error::new(
            PRIM,
            Fault::NonFinite {
                what: "triad P_local",
            },
        ));
    }
    if !k.iter().all(|p| all_finite([p.x, p.y])) {
        return Err(Error::new(
            PRIM,
            Fault::NonFinite {
                what: "triad known point",
            },
        ));
    }
    Ok(())
}

impl<T: Real> Frame<T> {
    #[inline(always)]
    pub(super) fn new(triad: &Triad<T>, k: &[Point2<T>; 3]) -> Result<Self, Error<T>> {
        validate(triad, k)?;
        let big = [triad.l2, triad.l3, triad.ab, abs(triad.p_local.x)]
            .into_iter()
            .chain([abs(triad.p_local.y)])
            .fold(triad.l1, crate::geometry::max);
        let (down, up) = crate::geometry::pow2_scale(big);
        let k2 = (k[1] - k[0]) * down;
        let k3 = (k[2] - k[0]) * down;
        if !all_finite([k2.x, k2.y, k3.x, k3.y]) {
            return Err(Error::new(
                PRIM,
                Fault::NonFinite {
                    what: "triad distance between known points",
                },
            ));
        }
        let reach = T::one() + length(&k2) + length(&k3);
        Ok(Frame {
            origin: k[0],
            down,
            up,
            k2,
            k3,
            l1: triad.l1 * down,
            l2: triad.l2 * down,
            l3: triad.l3 * down,
            c: triad.ab * down,
            u: triad.p_local.x * down,
            v: triad.p_local.y * down,
            reach,
            known: [k[1], k[2]],
        })
    }

    /// `B - A` and `P - A` (normalized) for the ternary's unit axis `e`.
    pub(super) fn offsets(&self, e: &Vector2<T>) -> (Vector2<T>, Vector2<T>) {
        (e * self.c, e * self.u + perp(e) * self.v)
    }

    /// Residuals `(|ri|^2 - li^2) / 2` and their Jacobian in `(A, phi)`.
    pub(super) fn system(&self, x: &State<T>) -> ([T; 3], [[T; 3]; 3]) {
        let a = x.a;
        let (ab, ap) = self.offsets(&x.e);
        let r2 = a + ab - self.k2;
        let r3 = a + ap - self.k3;
        let half = T::lit(0.5);
        let g = [
            half * (dot(&a, &a) - self.l1 * self.l1),
            half * (dot(&r2, &r2) - self.l2 * self.l2),
            half * (dot(&r3, &r3) - self.l3 * self.l3),
        ];
        let jac = [
            [a.x, a.y, T::zero()],
            [r2.x, r2.y, cross(&ab, &r2)],
            [r3.x, r3.y, cross(&ap, &r3)],
        ];
        (g, jac)
    }

    /// Newton's method on [`Frame::system`] from `x`: `Some` when the
    /// iteration settles and every residual ends within `64 eps l_i R`.
    /// Settled: a step below `sqrt(eps) R` whose successor, predicted from
    /// the quadratic convergence (`|d_(k+1)| ~ |d_k| (|d_k| / |d_(k-1)|)^2`,
    /// step sizes weighted as below), is under `eps c / 8`, an eighth of the
    /// rounding of the axis' angle times the side `c` (so it would move
    /// neither `A` nor the axis by more than a fraction of an ulp); when the
    /// prediction is larger (or there is no previous step), one more step is
    /// taken, and further ones while that step is above `4 eps c` and
    /// shrank at least fourfold (Newton converging slowly on a nearly
    /// singular Jacobian, near a branch point; at rounding level, or no
    /// longer shrinking, it stops). The axis turns by `atan(step)` rather
    /// than `step` (a rotation by `(1, step) / sqrt(1 + step^2)`, no sine
    /// or cosine): the difference is third order in the step, so
    /// convergence stays quadratic. Each step solves the 3x3 system by
    /// Cramer's rule (its accuracy matters only to the speed of
    /// convergence: the residuals decide the result).
    #[inline(always)]
    pub(super) fn newton(&self, mut x: State<T>) -> Option<State<T>> {
        let small = T::eps().sqrt() * self.reach;
        let tiny = T::lit(0.125) * T::eps() * self.c;
        let floor = T::lit(4.0) * T::eps() * self.c;
        let mut settled = false;
        // The previous step's size (0 before the first: no prediction).
        let mut last = T::zero();
        for _ in 0..MAX_NEWTON {
            let (g, jac) = self.system(&x);
            let step = cramer(&jac, [-g[0], -g[1], -g[2]])?;
            x.a += Vector2::new(step[0], step[1]);
            let turned = x.e + perp(&x.e) * step[2];
            x.e = turned * inv_hypot1(step[2]);
            let size = abs(step[0]) + abs(step[1]) + abs(step[2]) * self.c;
            if !(size.finite() && abs(x.a.x) + abs(x.a.y) <= T::lit(4.0) * self.reach) {
                return None;
            }
            // The step after a settled one is the last unless it is still
            // above rounding (`floor`) and shrank at least fourfold: then
            // Newton is converging slowly (a nearly singular Jacobian, near
            // a branch point) and goes on while it shrinks. Elsewhere that
            // step is at rounding level and the last, as always.
            if settled && (size <= floor || size * T::lit(4.0) > last) {
                break;
            }
            settled = settled || size <= small;
            // The predicted next step `size^3 / last^2` against `tiny`,
            // without a division (a cube below the normal range is a step
            // far below rounding: 0 passes).
            if settled && size * size * size <= tiny * last * last {
                break;
            }
            last = size;
        }
        if !settled {
            return None;
        }
        let (g, _) = self.system(&x);
        let tol = T::lit(64.0) * T::eps() * self.reach;
        let ok =
            abs(g[0]) <= tol * self.l1 && abs(g[1]) <= tol * self.l2 && abs(g[2]) <= tol * self.l3;
        ok.then_some(x)
    }

    /// The assembly at a converged state, in the user's frame. Where the
    /// Jacobian's relative determinant is below [`POLISH_BELOW`] (near a
    /// branch point) the state is first polished by [`Frame::polish`]:
    /// there the rates solved from the returned position amplify its
    /// rounding by about `1 / jacobian^2` (docs/report.md, "Stephenson
    /// (triad)"), so the position should be the rounded solution, not one
    /// a few dozen ulps off it.
    #[inline(always)]
    pub(super) fn finish(&self, x: &State<T>) -> Option<TriadPosition<T>> {
        let mut at = self.pose(x);
        if native::<T>() && abs(at.jacobian) < T::lit(POLISH_BELOW) {
            at = self.polish(x, at.jacobian);
        }
        let Pose {
            a,
            e,
            ab,
            ap,
            r2,
            r3,
            jacobian,
        } = at;
        let up = self.up;
        let pa = self.origin + a * up;
        let pos = TriadPosition {
            a: pa,
            b: pa + ab * up,
            p: pa + ap * up,
            r1: a * up,
            r2: r2 * up,
            r3: r3 * up,
            ab: ab * up,
            ap: ap * up,
            axis: e,
            jacobian: crate::geometry::max(-T::one(), min(jacobian, T::one())),
        };
        let all = [pos.a, pos.b, pos.p];
        let finite = all.iter().all(|q| all_finite([q.x, q.y])) && jacobian.finite();
        finite.then_some(pos)
    }

    /// The joints' offsets, the legs and the relative determinant at `x`
    /// (normalized).
    #[inline(always)]
    fn pose(&self, x: &State<T>) -> Pose<T> {
        let (a, e) = (x.a, x.e);
        let (ab, ap) = self.offsets(&e);
        let r2 = a + ab - self.k2;
        let r3 = a + ap - self.k3;
        self.pose_of(a, e, [ab, ap, r2, r3])
    }

    /// The [`Pose`] of `A`, the axis `e` and the vectors `B - A`, `P - A`
    /// and the legs 2 and 3: their relative determinant added.
    #[inline(always)]
    fn pose_of(&self, a: Vector2<T>, e: Vector2<T>, vectors: [Vector2<T>; 4]) -> Pose<T> {
        let [ab, ap, r2, r3] = vectors;
        let det = cross(&ap, &r3) * cross(&a, &r2) - cross(&ab, &r2) * cross(&a, &r3);
        let bound = self.l1 * self.l2 * self.l3 * (self.c + length(&ap));
        Pose {
            a,
            e,
            ab,
            ap,
            r2,
            r3,
            jacobian: det / bound,
        }
    }

    /// Newton steps on the leg equations whose residuals are evaluated in
    /// double words ([`Frame::words`]; the Jacobian and the step in the
    /// working precision), from a state [`Frame::newton`] converged to.
    /// Near a branch point the residuals' own rounding (a few `eps R`)
    /// divided by the small singular value is the error that solve leaves,
    /// a few dozen ulps along the direction in which the two assemblies
    /// meet; with the residuals exact to about `eps^2` at the state's own
    /// numbers, a step is the state's error itself (to first order) and
    /// moves it to within rounding of the solution. The residuals cannot
    /// judge the step: at a state rounded to the working precision they are
    /// about `eps R` in the well-conditioned directions whatever the error
    /// along the singular one. So a step is taken when it is small against
    /// the distance to the branch point (`|jacobian| c / 64`, where the
    /// linearization's error, about `step^2 / (|jacobian| c)`, is a small
    /// fraction of the step), at most [`POLISH_STEPS`] of them, the last
    /// one when it is at rounding level (`4 eps c`). Within about `eps` of
    /// the branch point, where no step is that small, the state is kept as
    /// it came. The pose returned is the one [`Frame::words`] rounded once
    /// from double words (the axis at unit length), not recomputed in the
    /// working precision: the rate matrix built from it is then within
    /// rounding of the exact one at that state. Out of line: it runs only
    /// near branch points.
    #[inline(never)]
    #[cold]
    fn polish(&self, x: &State<T>, jacobian: T) -> Pose<T> {
        let limit = abs(jacobian) * self.c * T::lit(1.0 / 64.0);
        let floor = T::lit(4.0) * T::eps() * self.c;
        let mut x = *x;
        let (mut g, mut pose) = self.words(&x);
        for _ in 0..POLISH_STEPS {
            let (_, jac) = self.system(&x);
            let Some(step) = cramer(&jac, [-g[0], -g[1], -g[2]]) else {
                break;
            };
            let size = abs(step[0]) + abs(step[1]) + abs(step[2]) * self.c;
            // A NaN step fails the comparison too.
            let small = size <= limit;
            if !small {
                break;
            }
            x = State {
                a: x.a + Vector2::new(step[0], step[1]),
                e: x.e + perp(&x.e) * step[2],
            };
            (g, pose) = self.words(&x);
            if size <= floor {
                break;
            }
        }
        // Double words overflow sooner (Veltkamp's split): then the state
        // as it came.
        let parts = [pose.a, pose.e, pose.ab, pose.ap, pose.r2, pose.r3];
        if parts.iter().all(|v| all_finite([v.x, v.y])) && pose.jacobian.finite() {
            pose
        } else {
            self.pose(&x)
        }
    }

    /// The residuals of [`Frame::system`] at `x` with the axis taken at unit
    /// length (`x.e` is within a few ulps of it; its excess is measured
    /// exactly and divided out to first order, `e (1 - (|e|^2 - 1) / 2)`,
    /// the next term about `eps^2`), every product and sum in double words
    /// ([`Word`]), the known points' offsets from `K1` included (the frame's
    /// `k2`, `k3` are rounded), and rounded once at the end: each residual within a few
    /// `eps^2 R^2` of its exact value at the state's own numbers; with the
    /// state's [`Pose`], each vector rounded once from its double words.
    fn words(&self, x: &State<T>) -> ([T; 3], Pose<T>) {
        let (a, e) = (x.a, x.e);
        let (xh, xl) = split(e.x);
        let (yh, yl) = split(e.y);
        let excess = half_excess(e.x, xh, xl, e.y, yh, yl);
        let ex = Word::new(e.x, -e.x * excess);
        let ey = Word::new(e.y, -e.y * excess);
        let (ax, ay) = (Word::of(a.x), Word::of(a.y));
        // `(K - K1) down` exactly: a two-sum, then a power of two.
        let from_origin = |p: T, o: T| {
            let w = Word::of(p).sub(Word::of(o));
            Word {
                hi: w.hi * self.down,
                lo: w.lo * self.down,
            }
        };
        let [k2, k3] = self.known;
        let o = self.origin;
        let r2 = [
            ax.add(ex.scale(self.c)).sub(from_origin(k2.x, o.x)),
            ay.add(ey.scale(self.c)).sub(from_origin(k2.y, o.y)),
        ];
        let apx = ex.scale(self.u).sub(ey.scale(self.v));
        let apy = ey.scale(self.u).add(ex.scale(self.v));
        let r3 = [
            ax.add(apx).sub(from_origin(k3.x, o.x)),
            ay.add(apy).sub(from_origin(k3.y, o.y)),
        ];
        let half = |r: &[Word<T>; 2], l: T| {
            let d = r[0].square().add(r[1].square()).sub(Word::of(l).square());
            d.value() * T::lit(0.5)
        };
        let g = [
            half(&[ax, ay], self.l1),
            half(&r2, self.l2),
            half(&r3, self.l3),
        ];
        let round = |w: [Word<T>; 2]| Vector2::new(w[0].value(), w[1].value());
        let e = round([ex, ey]);
        let ab = round([ex.scale(self.c), ey.scale(self.c)]);
        let ap = round([apx, apy]);
        let (r2, r3) = (round(r2), round(r3));
        (g, self.pose_of(a, e, [ab, ap, r2, r3]))
    }

    /// A radius of isolation of the assembly at `x` (normalized): every
    /// other assembly's joints are at least this far from `x`'s
    /// (root-sum-square over `A`, `B`, `P`, as [`Frame::distance`]), by the
    /// uniqueness part of Newton-Kantorovich's argument on the leg
    /// equations `G(A, phi) = 0`. For another solution `y`, `0 = G(y) -
    /// G(x) = J (y - x) + R` with `|R| <= L N(y - x)^2 / 2`, so `N(y - x)
    /// >= 2 / (beta L)`, where:
    ///
    /// - `N(da, dphi) = max(|da|, s |dphi|)` (`dphi` taken within `pi`, the
    ///   equations being `2 pi`-periodic), `s = 2 kappa / pi`, `kappa =
    ///   sqrt(c^2 + |w|^2 - |c + w|^2 / 3)` (`w = (u, v)`): the joints' moves
    ///   are at least `N`, since `|dA| <= D` and, minimizing over `dA` the
    ///   sum `|dA|^2 + |dA + c dz|^2 + |dA + w dz|^2` (`dz` the axis' move,
    ///   `|dz| = 2 |sin(dphi / 2)| >= (2 / pi) |dphi|`), `D >= kappa |dz|`;
    /// - `beta` bounds `N(J^-1 v)` for `|v|_inf <= 1` (from `J`'s adjugate at
    ///   `x`);
    /// - `L` bounds each equation's second derivative along any segment
    ///   between two assemblies in `N`'s units: `1` for leg 1, `(1 + c /
    ///   s)^2 + (l1 + c + |k2|) c / s^2` for leg 2 (`|r2'| <= |da| + c |dphi|`,
    ///   `r2'' = -c e dphi^2`, `|r2| <= l1 + c + |k2|` where `|A| <= l1`, as
    ///   on any segment between two assemblies), likewise leg 3 with `|w|`
    ///   and `k3`.
    ///
    /// `None` when `J` is singular or a bound is not finite. Rounding: `J`,
    /// `beta` and `L` are computed to about `eps` times `J`'s condition
    /// number relative; the radius is reduced by `2^-10` of itself, above
    /// that in `f64` and in `f32` wherever the radius is not already far
    /// below any pose's distance (a condition number under about 8000).
    pub(super) fn isolation(&self, x: &State<T>) -> Option<T> {
        let (_, m) = self.system(x);
        // Row i of J^-1 is (c0[i], c1[i], c2[i]) / det.
        let ([c0, c1, c2], det) = adjugate(&m);
        let det = abs(det);
        let [ra0, ra1, rphi] = [0, 1, 2].map(|i| abs(c0[i]) + abs(c1[i]) + abs(c2[i]));
        let w2 = self.u * self.u + self.v * self.v;
        let cw = (self.c + self.u) * (self.c + self.u) + self.v * self.v;
        let kappa2 = self.c * self.c + w2 - cw * T::lit(1.0 / 3.0);
        let s = T::lit(2.0 / core::f64::consts::PI) * max(kappa2, T::zero()).sqrt_kernel();
        let beta = max((ra0 * ra0 + ra1 * ra1).sqrt_kernel(), s * rphi) / det;
        let w = w2.sqrt_kernel();
        let leg = |len: T, k: &Vector2<T>| {
            let g = T::one() + len / s;
            g * g + (self.l1 + len + length(k)) * len / (s * s)
        };
        let lip = max(T::one(), max(leg(self.c, &self.k2), leg(w, &self.k3)));
        let r = T::lit(2.0) / (beta * lip) * (T::one() - T::lit(1.0 / 1024.0));
        (r.finite() && r > T::zero()).then_some(r)
    }

    /// Root-sum-square distance of the joints of `pos` from `near`, in the
    /// normalized unit (no overflow).
    pub(super) fn distance(&self, pos: &TriadPosition<T>, near: &Near<T>) -> T {
        self.distance_squared(pos, near).sqrt_kernel()
    }

    /// The square of [`Frame::distance`] (no square root: for comparisons
    /// with a squared limit).
    pub(super) fn distance_squared(&self, pos: &TriadPosition<T>, near: &Near<T>) -> T {
        let d = |p: &Point2<T>, q: &Point2<T>| {
            let w = (p - q) * self.down;
            dot(&w, &w)
        };
        d(&pos.a, &near.a) + d(&pos.b, &near.b) + d(&pos.p, &near.p)
    }

    /// The largest accepted jump, normalized.
    pub(super) fn jump(&self) -> T {
        let shortest = [self.l2, self.l3, self.c].into_iter().fold(self.l1, min);
        T::lit(JUMP_FRACTION) * shortest
    }
}

/// `1 / sqrt(1 + s^2)`: the length of `e + perp(e) s` (`e` a unit vector)
/// brought back to 1. For `s^2 <= 2^-20` the series `1 - s^2/2 + 3 s^4/8`,
/// whose first omitted term (`-5 s^6 / 16`, at most `2^-61.7`) is below half
/// an ulp of 1 in `f64` and `f32`: no square root and no division on the
/// dependency chain of a Newton step near convergence, where every step is
/// that small. Else (and for a NaN `s`) the square root and the division.
#[inline(always)]
fn inv_hypot1<T: Real>(s: T) -> T {
    let s2 = s * s;
    if s2 <= T::lit(9.5367431640625e-7) {
        T::one() - s2 * (T::lit(0.5) - T::lit(0.375) * s2)
    } else {
        T::one() / (T::one() + s2).sqrt_kernel()
    }
}

/// The columns of a 3x3 `m`'s adjugate (the rows' cross products: `m^-1`
/// has `c_j[i] / det` in row `i`, column `j`) and its determinant.
#[inline(always)]
fn adjugate<T: Real>(m: &[[T; 3]; 3]) -> ([[T; 3]; 3], T) {
    let cross3 = |p: &[T; 3], q: &[T; 3]| {
        [
            p[1] * q[2] - p[2] * q[1],
            p[2] * q[0] - p[0] * q[2],
            p[0] * q[1] - p[1] * q[0],
        ]
    };
    let c0 = cross3(&m[1], &m[2]);
    let c1 = cross3(&m[2], &m[0]);
    let c2 = cross3(&m[0], &m[1]);
    let det = m[0][0] * c0[0] + m[0][1] * c0[1] + m[0][2] * c0[2];
    ([c0, c1, c2], det)
}

/// `m x = b` for a 3x3 `m` by Cramer's rule (rows' cross products); `None`
/// when the determinant is zero or the result not finite.
#[inline(always)]
fn cramer<T: Real>(m: &[[T; 3]; 3], b: [T; 3]) -> Option<[T; 3]> {
    let ([c0, c1, c2], det) = adjugate(m);
    if det == T::zero() {
        return None;
    }
    let inv = T::one() / det;
    let x: [T; 3] = core::array::from_fn(|i| (b[0] * c0[i] + b[1] * c1[i] + b[2] * c2[i]) * inv);
    all_finite(x).then_some(x)
}
