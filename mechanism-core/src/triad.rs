//! The triad: the class III Assur group of the Stephenson III six-bar. A
//! ternary rigid link with joints `A`, `B`, `P` on three binary legs: leg 1
//! from the known point `K1` to `A` (length `l1`), leg 2 from `K2` to `B`
//! (`l2`), leg 3 from `K3` to `P` (`l3`). Four moving bodies, six revolutes.
//!
//! ```text
//!                 P                  ternary link: |AB| = ab; P at (u, v) in the
//!          l3    / \                 frame with origin A, x along A -> B, y to
//!     K3 ------ /   \                its left (counter-clockwise)
//!              A --- B
//!          l1 /       \ l2
//!            K1        K2
//! ```
//!
//! # Position: every assembly, then the one asked for
//!
//! There is no closed form. The chain `K1 - A - B - K2` is a four-bar whose
//! coupler carries `P`; `P`'s path (the coupler curve, a circular sextic)
//! meets the circle of radius `l3` about `K3` in at most 6 points, so a triad
//! has at most 6 real assemblies ([`MAX_ASSEMBLIES`]). [`assemblies`] finds
//! them all without heap:
//!
//! 1. the angle `theta` of leg 1 parametrizes the four-bar; where `|A - K2|`
//!    lies in `[|ab - l2|, ab + l2]` (closed form: up to two intervals of
//!    `theta`, or the whole turn) `B` follows by the circle-circle step on one
//!    of its two branches. Each interval is traversed as one closed loop,
//!    `theta = mid - half cos t` for `t` in `[0, 2 pi)`, branch `+` while
//!    `sin t > 0` and `-` after: at the interval's ends (where the step stops
//!    assembling) the two branches meet, the height of `B` goes as `sin t`,
//!    and the loop is a smooth closed curve, so no root hides at a branch
//!    end. A whole turn gives two loops, one per branch;
//! 2. along each loop the residual `f(t) = |P - K3| - l3` is sampled at
//!    [`SAMPLES`] points; every sign change is bracketed and narrowed by the
//!    Illinois method. A pair of roots closer than the sample spacing (near
//!    a branch point) shows no sign change between samples but a local
//!    minimum of `|f|`: wherever the parabola through the three samples
//!    comes near zero, the extremum of `f` between the neighbours is located
//!    by golden-section search, and if `f` changes sign there both sides are
//!    bracketed (a tangency, `f` within `sqrt(eps)` of zero, starts Newton
//!    directly);
//! 3. each start is polished by Newton's method on the full 3x3 system in
//!    the unknowns `(A, phi)` (`phi` the angle of `A -> B`), equations
//!    `(|A - Ki|^2 - li^2) / 2 = 0` for the three legs, solved by
//!    [`crate::linsolve`], and kept when it converges (residuals at rounding
//!    level); assemblies whose joints agree to `sqrt(eps) / 8` of the
//!    group's scale are merged.
//!
//! Why [`SAMPLES`] = 720 per loop: `f` has at most 6 zeros on all loops
//! together, so a sign change between two samples is a root and the only
//! roots a scan can miss are pairs (or quadruples) closer than the spacing,
//! which the local-minimum step recovers; what the count must resolve is the
//! separation of `f`'s extrema. Measured on the 600 random triads of
//! `tests/triad.rs` (checked against a double-double scan of the ternary's
//! angle): 90 samples found every assembly, 45 missed one; 720 keeps a
//! factor 8. Cost: about 1 500 residual evaluations (one or two `sin_cos`,
//! two square roots each), 0.1 ms per search in f64 on an x86-64 core; the
//! tracking form is a few Newton steps (under 1 us).
//!
//! Everything is computed in a frame moved to `K1` and scaled by the power
//! of two at or below the longest dimension (exact), so results scale exactly
//! with powers of two and no square of a length overflows.
//!
//! **Which assembly.** [`position`] takes a [`Near`]: the approximate
//! positions of `A`, `B` and `P` ("at this input the joints are about
//! here"), and returns the assembly nearest to it (root-sum-square distance
//! over the three joints). It never returns a different one silently: no
//! assembly is `CannotAssemble`, and a nearest one farther than
//! [`JUMP_FRACTION`] of the shortest dimension, or not at most half as far
//! ([`NEAR_FACTOR`]) as the next, is `NotNear`. [`position_near`]
//! tracks an assembly from a previous pose: Newton from it, accepted when it
//! converges, the Jacobian's determinant keeps its sign (no branch point was
//! crossed) and the joints moved at most [`JUMP_FRACTION`] of the shortest
//! dimension; else the full search, the nearest assembly on the same side
//! of the branch points, with the same limits (`NotNear` when the followed
//! assembly has vanished).
//!
//! # Rates
//!
//! Differentiating the three leg equations: `r1 . vA = r1 . vK1`,
//! `r2 . (vA + w perp(ab)) = r2 . vK2`, `r3 . (vA + w perp(ap)) = r3 . vK3`
//! (`ri` the leg vectors `A - K1`, `B - K2`, `P - K3`; `w` the ternary's
//! angular velocity): the position Newton's 3x3 Jacobian, solved by
//! [`crate::linsolve`] after its determinant is checked against its bound
//! `l1 l2 l3 (ab + |ap|)` (expanding along the ternary's column: `|r2 x ab|
//! <= l2 ab`, `|r3 x ap| <= l3 |ap|`, each minor `<= l1 l3` or `l1 l2`). The legs' rates follow as
//! `omega_i = cross(ri, v_joint - vKi) / li^2`. Accelerations: the same
//! matrix, right-hand side with the centripetal terms.
//!
//! # Forces
//!
//! Four bodies, six revolutes, twelve unknowns, the 12x12 system of
//! [`reactions`] through [`crate::linsolve::solve`] (row equilibration and
//! partial pivoting). Convention (as in [`crate::force`]): at `K1`, `K2`,
//! `K3` the force of the outside body on the leg; at `A`, `B`, `P` the force
//! of the leg on the ternary link (the leg receives the opposite).
//!
//! Units: lengths in the user's unit L, angles in radians counter-clockwise,
//! rates per second.

use crate::error::{Error, Fault, Primitive};
use crate::force::body::Wrench;
use crate::geometry::{abs, all_finite, angle, check_det, cross, dot, length, min, perp, unit};
use crate::linsolve;
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

const PRIM: Primitive = Primitive::Triad;

/// The most real assemblies a triad has (the coupler sextic meets a circle
/// in at most 6 real points).
pub const MAX_ASSEMBLIES: usize = 6;

/// Residual samples per loop of the search (see the module documentation).
pub const SAMPLES: usize = 720;

/// The nearest assembly is taken only when the next one is at least this
/// many times as far from the given pose.
pub const NEAR_FACTOR: f64 = 2.0;

/// Largest joint displacement (root-sum-square over `A`, `B`, `P`) that
/// [`position_near`] accepts as the same assembly, as a fraction of the
/// shortest of `l1`, `l2`, `l3`, `ab`.
pub const JUMP_FRACTION: f64 = 0.5;

/// Newton iterations of the polish and the warm start.
const MAX_NEWTON: usize = 16;

/// The triad's dimensions (L).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Triad<T: Real> {
    /// Leg 1, `|A - K1|` (> 0).
    pub l1: T,
    /// Leg 2, `|B - K2|` (> 0).
    pub l2: T,
    /// Leg 3, `|P - K3|` (> 0).
    pub l3: T,
    /// The ternary link's side `|B - A|` (> 0).
    pub ab: T,
    /// `P` in the ternary's frame: origin `A`, x along `A -> B`, y 90 degrees
    /// counter-clockwise from it (any finite value; `P` may coincide with `A`
    /// or `B`).
    pub p_local: Vector2<T>,
}

/// One assembly of the triad.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriadPosition<T: Real> {
    /// Joint `A` (L).
    pub a: Point2<T>,
    /// Joint `B` (L).
    pub b: Point2<T>,
    /// Joint `P` (L).
    pub p: Point2<T>,
    /// Leg 1 as a vector, `A - K1` (L).
    pub r1: Vector2<T>,
    /// Leg 2, `B - K2` (L).
    pub r2: Vector2<T>,
    /// Leg 3, `P - K3` (L).
    pub r3: Vector2<T>,
    /// `B - A` (L).
    pub ab: Vector2<T>,
    /// `P - A` (L).
    pub ap: Vector2<T>,
    /// The ternary's unit axis, along `A -> B`: `(cos, sin)` of its angle.
    pub axis: Vector2<T>,
    /// The Jacobian's determinant of the three leg equations in `(A, phi)`
    /// relative to its bound `l1 l2 l3 (ab + |ap|)`, in `[-1, 1]`:
    /// its sign tells the assemblies on either side of a branch point apart;
    /// its magnitude is the conditioning (0 at a branch point, where two
    /// assemblies meet and the rates are undefined).
    pub jacobian: T,
}

/// The approximate positions of the joints (L) that select an assembly.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Near<T: Real> {
    /// About where `A` is.
    pub a: Point2<T>,
    /// About where `B` is.
    pub b: Point2<T>,
    /// About where `P` is.
    pub p: Point2<T>,
}

impl<T: Real> Near<T> {
    /// A pose from the three joints.
    pub fn new(a: Point2<T>, b: Point2<T>, p: Point2<T>) -> Self {
        Near { a, b, p }
    }

    /// The joints of an assembly.
    pub fn of(pos: &TriadPosition<T>) -> Self {
        Near {
            a: pos.a,
            b: pos.b,
            p: pos.p,
        }
    }
}

/// The pose an assembly tracked ahead of time has at input `q`: linear
/// interpolation in a table of rows `[q, ax, ay, bx, by, px, py]` (input in
/// its unit, joints in L) whose inputs increase; the generated `position()`
/// of a definition with a triad selects the assembly nearest this pose.
///
/// Errors: `NonFinite` for a non-finite `q`; `NotNear` with `nearest`
/// infinite for a `q` outside the table's inputs (the tracked assembly is
/// not known there: it vanished, or the range ends) or a table of fewer
/// than two rows.
pub fn near_from_table<T: Real>(table: &[[f64; 7]], q: T) -> Result<Near<T>, Error<T>> {
    let x = q.as_f64();
    if !x.is_finite() {
        return Err(Error::new(
            PRIM,
            Fault::NonFinite {
                what: "triad input",
            },
        ));
    }
    let outside = Error::new(
        PRIM,
        Fault::NotNear {
            nearest: T::lit(f64::INFINITY),
            next: T::zero(),
        },
    );
    let (Some(first), Some(last)) = (table.first(), table.last()) else {
        return Err(outside);
    };
    if table.len() < 2 || !(x >= first[0] && x <= last[0]) {
        return Err(outside);
    }
    // The last row at or below x (the first row is), short of the last row.
    let i = table
        .partition_point(|r| r[0] <= x)
        .clamp(1, table.len() - 1)
        - 1;
    let (r0, r1) = (&table[i], &table[i + 1]);
    let span = r1[0] - r0[0];
    let w = if span > 0.0 { (x - r0[0]) / span } else { 0.0 };
    let v = |k: usize| T::lit(r0[k] + (r1[k] - r0[k]) * w);
    Ok(Near {
        a: Point2::new(v(1), v(2)),
        b: Point2::new(v(3), v(4)),
        p: Point2::new(v(5), v(6)),
    })
}

/// Every real assembly at one input, in no particular order, without heap.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Assemblies<T: Real> {
    list: [Option<TriadPosition<T>>; MAX_ASSEMBLIES],
    count: usize,
    /// With no assembly: how far it misses (L); see [`Fault::CannotAssemble`].
    miss: T,
    /// With no assembly: the bound missed (L).
    reach: T,
}

impl<T: Real> Assemblies<T> {
    /// The assemblies found (`0..=6`).
    pub fn len(&self) -> usize {
        self.count
    }

    /// `true` when the triad does not assemble at this input.
    pub fn is_empty(&self) -> bool {
        self.count == 0
    }

    /// The assemblies.
    pub fn iter(&self) -> impl Iterator<Item = &TriadPosition<T>> {
        self.list.iter().flatten()
    }

    /// The `CannotAssemble` error when empty: `miss` is how far the group
    /// is from closing (L), `reach` the bound it misses.
    fn none_error(&self) -> Error<T> {
        Error::new(
            PRIM,
            Fault::CannotAssemble {
                miss: self.miss,
                reach: self.reach,
            },
        )
    }

    fn push(&mut self, pos: TriadPosition<T>) {
        if let Some(slot) = self.list.get_mut(self.count) {
            *slot = Some(pos);
            self.count += 1;
        }
    }
}

/// Angular velocities of the four links and the joints' velocities.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriadVelocity<T: Real> {
    /// Leg 1 (rad/s, counter-clockwise positive).
    pub omega1: T,
    /// Leg 2 (rad/s).
    pub omega2: T,
    /// Leg 3 (rad/s).
    pub omega3: T,
    /// The ternary link (rad/s).
    pub omega: T,
    /// Velocity of `A` (L/s).
    pub va: Vector2<T>,
    /// Velocity of `B` (L/s).
    pub vb: Vector2<T>,
    /// Velocity of `P` (L/s).
    pub vp: Vector2<T>,
    /// Velocities of `K1`, `K2`, `K3` as given (zero for `None`; L/s), kept
    /// for the accelerations.
    pub vk: [Vector2<T>; 3],
    /// `|jacobian|` of the position: the conditioning, in `(16 eps, 1]`.
    pub condition: T,
}

/// Angular accelerations of the four links and the joints' accelerations.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriadAcceleration<T: Real> {
    /// Leg 1 (rad/s^2).
    pub alpha1: T,
    /// Leg 2 (rad/s^2).
    pub alpha2: T,
    /// Leg 3 (rad/s^2).
    pub alpha3: T,
    /// The ternary link (rad/s^2).
    pub alpha: T,
    /// Acceleration of `A` (L/s^2).
    pub aa: Vector2<T>,
    /// Acceleration of `B` (L/s^2).
    pub ab: Vector2<T>,
    /// Acceleration of `P` (L/s^2).
    pub ap: Vector2<T>,
}

/// The known loads on the four bodies (inertia, weight, external loads, the
/// reactions of later groups negated), each about a stated point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriadLoads<T: Real> {
    /// On leg 1, about `A`.
    pub leg1: Wrench<T>,
    /// On leg 2, about `B`.
    pub leg2: Wrench<T>,
    /// On leg 3, about `P`.
    pub leg3: Wrench<T>,
    /// On the ternary link, about `A`.
    pub ternary: Wrench<T>,
}

/// The joint reactions (force units; global frame).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriadReactions<T: Real> {
    /// Force of the body carrying `K1` on leg 1, at `K1`.
    pub k1: Vector2<T>,
    /// Force of the body carrying `K2` on leg 2, at `K2`.
    pub k2: Vector2<T>,
    /// Force of the body carrying `K3` on leg 3, at `K3`.
    pub k3: Vector2<T>,
    /// Force of leg 1 on the ternary link at `A` (leg 1 receives `-a`).
    pub a: Vector2<T>,
    /// Force of leg 2 on the ternary link at `B`.
    pub b: Vector2<T>,
    /// Force of leg 3 on the ternary link at `P`.
    pub p: Vector2<T>,
    /// [`linsolve::Solution::min_pivot_ratio`] of the 12x12 solve.
    pub min_pivot_ratio: T,
}

/// The problem in the normalized frame: origin `K1`, lengths divided by
/// `up` (a power of two, exact).
#[derive(Clone, Copy, Debug)]
struct Frame<T: Real> {
    origin: Point2<T>,
    down: T,
    up: T,
    k2: Vector2<T>,
    k3: Vector2<T>,
    l1: T,
    l2: T,
    l3: T,
    c: T,
    u: T,
    v: T,
    /// `R`: `1 + |K2 - K1| + |K3 - K1|` (normalized), the size of the
    /// coordinates the residuals are rounded at.
    reach: T,
}

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

/// A Newton state in the normalized frame: `A` and the ternary's angle.
type State<T> = [T; 3];

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
    fn new(triad: &Triad<T>, k: &[Point2<T>; 3]) -> Result<Self, Error<T>> {
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
        })
    }

    /// `B - A` and `P - A` (normalized) for the ternary's unit axis `e`.
    fn offsets(&self, e: &Vector2<T>) -> (Vector2<T>, Vector2<T>) {
        (e * self.c, e * self.u + perp(e) * self.v)
    }

    /// Residuals `(|ri|^2 - li^2) / 2` and their Jacobian in `(A, phi)`.
    fn system(&self, x: &State<T>) -> ([T; 3], [[T; 3]; 3]) {
        let a = Vector2::new(x[0], x[1]);
        let e = unit(x[2]);
        let (ab, ap) = self.offsets(&e);
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

    /// Newton's method on [`Frame::system`] from `x`: `Some` when the steps
    /// fall below `sqrt(eps) R` (then one more is taken) and every residual
    /// ends within `64 eps l_i R`.
    fn newton(&self, mut x: State<T>) -> Option<State<T>> {
        let small = T::eps().sqrt() * self.reach;
        let mut settled = false;
        for _ in 0..MAX_NEWTON {
            let (g, jac) = self.system(&x);
            let step = linsolve::solve(jac, [-g[0], -g[1], -g[2]]).ok()?.x;
            for (xi, si) in x.iter_mut().zip(step) {
                *xi += si;
            }
            let size = abs(step[0]) + abs(step[1]) + abs(step[2]) * self.c;
            if !(size.finite() && abs(x[0]) + abs(x[1]) <= T::lit(4.0) * self.reach) {
                return None;
            }
            if settled {
                break;
            }
            settled = size <= small;
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

    /// The assembly at a converged state, in the user's frame.
    fn finish(&self, x: &State<T>) -> Option<TriadPosition<T>> {
        let a = Vector2::new(x[0], x[1]);
        let e = unit(x[2]);
        let (ab, ap) = self.offsets(&e);
        let r2 = a + ab - self.k2;
        let r3 = a + ap - self.k3;
        let det = cross(&ap, &r3) * cross(&a, &r2) - cross(&ab, &r2) * cross(&a, &r3);
        let bound = self.l1 * self.l2 * self.l3 * (self.c + length(&ap));
        let jacobian = det / bound;
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

    /// Root-sum-square distance of the joints of `pos` from `near`, in the
    /// normalized unit (no overflow).
    fn distance(&self, pos: &TriadPosition<T>, near: &Near<T>) -> T {
        let d = |p: &Point2<T>, q: &Point2<T>| {
            let w = (p - q) * self.down;
            dot(&w, &w)
        };
        (d(&pos.a, &near.a) + d(&pos.b, &near.b) + d(&pos.p, &near.p)).sqrt_kernel()
    }

    /// The largest accepted jump, normalized.
    fn jump(&self) -> T {
        let shortest = [self.l2, self.l3, self.c].into_iter().fold(self.l1, min);
        T::lit(JUMP_FRACTION) * shortest
    }
}

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
    [a.x, a.y, angle(&e)]
}

/// Finds every assembly (see the module documentation).
///
/// Errors: `NonPositive` for a length `<= 0` (or non-finite: `NonFinite`),
/// `NonFinite` for a non-finite point or `P_local`. No assembly is not an
/// error here: the list is empty ([`position`] reports it).
pub fn assemblies<T: Real>(
    triad: &Triad<T>,
    k: &[Point2<T>; 3],
) -> Result<Assemblies<T>, Error<T>> {
    let f = Frame::new(triad, k)?;
    Ok(search(&f))
}

fn search<T: Real>(f: &Frame<T>) -> Assemblies<T> {
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
fn add_root<T: Real>(f: &Frame<T>, x: State<T>, found: &mut Assemblies<T>) {
    let Some(pos) = f.newton(x).and_then(|x| f.finish(&x)) else {
        return;
    };
    let tol = T::eps().sqrt() * T::lit(0.125);
    if found.iter().all(|q| f.distance(q, &Near::of(&pos)) > tol) {
        found.push(pos);
    }
}

/// The nearest of `candidates` to `near` and the distance to the next one
/// (normalized; infinite when there is no other).
fn nearest<'a, T: Real>(
    f: &Frame<T>,
    candidates: impl Iterator<Item = &'a TriadPosition<T>>,
    near: &Near<T>,
) -> Option<(TriadPosition<T>, T, T)> {
    let inf = T::lit(f64::INFINITY);
    let mut best: Option<(TriadPosition<T>, T)> = None;
    let mut next = inf;
    for q in candidates {
        let d = f.distance(q, near);
        match best {
            Some((_, bd)) if d >= bd => next = min(next, d),
            Some((_, bd)) => {
                next = bd;
                best = Some((*q, d));
            }
            None => best = Some((*q, d)),
        }
    }
    best.map(|(q, d)| (q, d, next))
}

/// The assembly nearest to `near` (see the module documentation).
///
/// Errors ([`Primitive::Triad`]): input errors as for [`assemblies`];
/// `CannotAssemble` when the triad does not close at this input (`miss`:
/// how far the four-bar `K1 - A - B - K2` misses closing, or, when it
/// closes, the least `| |P - K3| - l3 |` sampled; L); `NotNear` when the
/// nearest assembly is farther from `near` than [`JUMP_FRACTION`] of the
/// shortest dimension (then the intended one may not exist at this input:
/// even a single assembly is not returned), or not at most half as far as
/// the next.
pub fn position<T: Real>(
    triad: &Triad<T>,
    k: &[Point2<T>; 3],
    near: &Near<T>,
) -> Result<TriadPosition<T>, Error<T>> {
    let f = Frame::new(triad, k)?;
    if !near_finite(near) {
        return Err(Error::new(PRIM, Fault::NonFinite { what: "triad pose" }));
    }
    let all = search(&f);
    let Some((pos, d, next)) = nearest(&f, all.iter(), near) else {
        return Err(all.none_error());
    };
    if d > f.jump() {
        return Err(not_near(&f, d, f.jump()));
    }
    if next < T::lit(NEAR_FACTOR) * d {
        return Err(not_near(&f, d, next));
    }
    Ok(pos)
}

fn near_finite<T: Real>(near: &Near<T>) -> bool {
    all_finite([near.a.x, near.a.y, near.b.x, near.b.y, near.p.x, near.p.y])
}

fn not_near<T: Real>(f: &Frame<T>, nearest: T, next: T) -> Error<T> {
    Error::new(
        PRIM,
        Fault::NotNear {
            nearest: nearest * f.up,
            next: next * f.up,
        },
    )
}

/// Newton from `previous` only: the same assembly at the new input when
/// Newton converges, the Jacobian's determinant keeps its sign and the
/// joints moved at most [`JUMP_FRACTION`] of the shortest dimension.
///
/// Errors: input errors as for [`assemblies`]; `NotNear { nearest, next }`
/// otherwise (`nearest`: the joints' move, infinite when Newton failed;
/// `next`: the largest move accepted).
pub fn refine<T: Real>(
    triad: &Triad<T>,
    k: &[Point2<T>; 3],
    previous: &TriadPosition<T>,
) -> Result<TriadPosition<T>, Error<T>> {
    let f = Frame::new(triad, k)?;
    let inf = T::lit(f64::INFINITY);
    let x0 = (previous.a - f.origin) * f.down;
    let start = [x0.x, x0.y, angle(&previous.axis)];
    if !all_finite(start) {
        return Err(Error::new(PRIM, Fault::NonFinite { what: "triad pose" }));
    }
    let Some(pos) = f.newton(start).and_then(|x| f.finish(&x)) else {
        return Err(not_near(&f, inf, f.jump()));
    };
    let moved = f.distance(&pos, &Near::of(previous));
    if same_side(&pos, previous) && moved <= f.jump() {
        Ok(pos)
    } else {
        Err(not_near(&f, moved, f.jump()))
    }
}

/// Both determinants non-zero with the same sign (no branch point between).
fn same_side<T: Real>(p: &TriadPosition<T>, q: &TriadPosition<T>) -> bool {
    p.jacobian * q.jacobian > T::zero()
}

/// Tracking: [`refine`] from `previous`, falling back to the full search and
/// the nearest assembly to `previous` on the same side of the branch points
/// (sign of [`TriadPosition::jacobian`]), accepted when it moved at most
/// [`JUMP_FRACTION`] of the shortest dimension and is at most half as far
/// as the next such assembly.
///
/// Errors ([`Primitive::Triad`]): input errors as for [`assemblies`];
/// `CannotAssemble` when no assembly exists; `NotNear` when the followed
/// assembly has vanished (met another at a branch point) or the match is
/// not clear (see [`Fault::NotNear`]).
pub fn position_near<T: Real>(
    triad: &Triad<T>,
    k: &[Point2<T>; 3],
    previous: &TriadPosition<T>,
) -> Result<TriadPosition<T>, Error<T>> {
    match refine(triad, k, previous) {
        Ok(pos) => return Ok(pos),
        Err(e) if !matches!(e.fault, Fault::NotNear { .. }) => return Err(e),
        Err(_) => {}
    }
    fallback(&Frame::new(triad, k)?, previous)
}

/// [`position_near`]'s full search: the nearest assembly to `previous` on
/// its side of the branch points, within the jump and clearly nearest.
fn fallback<T: Real>(
    f: &Frame<T>,
    previous: &TriadPosition<T>,
) -> Result<TriadPosition<T>, Error<T>> {
    let all = search(f);
    if all.is_empty() {
        return Err(all.none_error());
    }
    let near = Near::of(previous);
    let side = all.iter().filter(|q| same_side(q, previous));
    let inf = T::lit(f64::INFINITY);
    let Some((pos, d, next)) = nearest(f, side, &near) else {
        return Err(not_near(f, inf, f.jump()));
    };
    if d > f.jump() {
        return Err(not_near(f, d, f.jump()));
    }
    if next < T::lit(NEAR_FACTOR) * d {
        return Err(not_near(f, d, next));
    }
    Ok(pos)
}

/// `Some(v)` or zero.
fn or_zero<T: Real>(v: Option<&Vector2<T>>) -> Vector2<T> {
    v.copied().unwrap_or_else(Vector2::zeros)
}

/// The rate matrix (rows: the three legs; columns: the joint `A`'s two
/// components and `ab` times the ternary's rate, so all are lengths), after
/// the determinant check.
fn rate_matrix<T: Real>(triad: &Triad<T>, pos: &TriadPosition<T>) -> Result<[[T; 3]; 3], Error<T>> {
    check_det(pos.jacobian, T::one(), PRIM)?;
    let (r1, r2, r3) = (pos.r1, pos.r2, pos.r3);
    let c = triad.ab;
    Ok([
        [r1.x, r1.y, T::zero()],
        [r2.x, r2.y, cross(&pos.axis, &r2)],
        [r3.x, r3.y, cross(&pos.ap, &r3) / c],
    ])
}

/// Solves the rate system and maps its error to the triad.
fn solve3<T: Real>(m: [[T; 3]; 3], rhs: [T; 3]) -> Result<[T; 3], Error<T>> {
    linsolve::solve(m, rhs)
        .map(|s| s.x)
        .map_err(|e| Error::new(PRIM, e.fault))
}

/// The rotation rate of a leg `r` of length `l` whose ends move at `v_end`
/// and `v_base`: `cross(r, v_end - v_base) / l^2`.
fn leg_rate<T: Real>(r: &Vector2<T>, l: T, dv: &Vector2<T>) -> T {
    cross(&(r / l), dv) / l
}

/// Rates of the triad from the known points' velocities (L/s; `None`: fixed).
///
/// Errors ([`Primitive::Triad`]): `Singular` when `|jacobian| <= 16 eps`
/// (a branch point: two assemblies meet) or the elimination finds a relative
/// pivot `<= 3 eps`; `NonFinite` for a non-finite input or result.
pub fn velocity<T: Real>(
    triad: &Triad<T>,
    pos: &TriadPosition<T>,
    vk1: Option<&Vector2<T>>,
    vk2: Option<&Vector2<T>>,
    vk3: Option<&Vector2<T>>,
) -> Result<TriadVelocity<T>, Error<T>> {
    let m = rate_matrix(triad, pos)?;
    let vk = [or_zero(vk1), or_zero(vk2), or_zero(vk3)];
    let rhs = [
        dot(&pos.r1, &vk[0]),
        dot(&pos.r2, &vk[1]),
        dot(&pos.r3, &vk[2]),
    ];
    let [vx, vy, w_c] = solve3(m, rhs)?;
    let omega = w_c / triad.ab;
    let va = Vector2::new(vx, vy);
    let vb = va + perp(&pos.ab) * omega;
    let vp = va + perp(&pos.ap) * omega;
    let out = TriadVelocity {
        omega1: leg_rate(&pos.r1, triad.l1, &(va - vk[0])),
        omega2: leg_rate(&pos.r2, triad.l2, &(vb - vk[1])),
        omega3: leg_rate(&pos.r3, triad.l3, &(vp - vk[2])),
        omega,
        va,
        vb,
        vp,
        vk,
        condition: abs(pos.jacobian),
    };
    let check = [out.omega1, out.omega2, out.omega3, vb.x, vb.y, vp.x, vp.y];
    if all_finite(check) {
        Ok(out)
    } else {
        Err(Error::new(
            PRIM,
            Fault::NonFinite {
                what: "triad rates",
            },
        ))
    }
}

/// Accelerations from the known points' accelerations (L/s^2; `None`:
/// fixed) and the rates `vel` at this `pos`.
///
/// Second derivatives of the leg equations: `r1 . aA = r1 . aK1 - |vA -
/// vK1|^2`, `r2 . (aA + alpha perp(ab)) = r2 . aK2 - |vB - vK2|^2 + omega^2
/// r2 . ab`, likewise for leg 3 with `ap`: the rate matrix again.
/// Errors as for [`velocity`].
pub fn acceleration<T: Real>(
    triad: &Triad<T>,
    pos: &TriadPosition<T>,
    vel: &TriadVelocity<T>,
    ak1: Option<&Vector2<T>>,
    ak2: Option<&Vector2<T>>,
    ak3: Option<&Vector2<T>>,
) -> Result<TriadAcceleration<T>, Error<T>> {
    let m = rate_matrix(triad, pos)?;
    let ak = [or_zero(ak1), or_zero(ak2), or_zero(ak3)];
    let w2 = vel.omega * vel.omega;
    let (d1, d2, d3) = (vel.va - vel.vk[0], vel.vb - vel.vk[1], vel.vp - vel.vk[2]);
    let rhs = [
        dot(&pos.r1, &ak[0]) - dot(&d1, &d1),
        dot(&pos.r2, &ak[1]) - dot(&d2, &d2) + w2 * dot(&pos.r2, &pos.ab),
        dot(&pos.r3, &ak[2]) - dot(&d3, &d3) + w2 * dot(&pos.r3, &pos.ap),
    ];
    let [ax, ay, al_c] = solve3(m, rhs)?;
    let alpha = al_c / triad.ab;
    let aa = Vector2::new(ax, ay);
    let ab = aa + perp(&pos.ab) * alpha - pos.ab * w2;
    let ap = aa + perp(&pos.ap) * alpha - pos.ap * w2;
    let out = TriadAcceleration {
        alpha1: leg_rate(&pos.r1, triad.l1, &(aa - ak[0])),
        alpha2: leg_rate(&pos.r2, triad.l2, &(ab - ak[1])),
        alpha3: leg_rate(&pos.r3, triad.l3, &(ap - ak[2])),
        alpha,
        aa,
        ab,
        ap,
    };
    let check = [out.alpha1, out.alpha2, out.alpha3, ab.x, ab.y, ap.x, ap.y];
    if all_finite(check) {
        Ok(out)
    } else {
        Err(Error::new(
            PRIM,
            Fault::NonFinite {
                what: "triad accelerations",
            },
        ))
    }
}

/// The joint reactions from the known loads (see [`TriadLoads`] for the
/// points each is about).
///
/// Unknowns (columns, two each): `K1`, `K2`, `K3` (outside on the legs),
/// `A`, `B`, `P` (legs on the ternary). Rows, three per body (`Fx`, `Fy`,
/// moment): leg 1 about `A`, leg 2 about `B`, leg 3 about `P`, the ternary
/// about `A`; so a leg's moment row holds only its outer force, and the
/// ternary's only `B`'s and `P`'s. Solved by [`linsolve::solve`] (row
/// equilibration, partial pivoting) on the 12x12 system.
///
/// Errors ([`Primitive::Triad`]): `NonFinite` for non-finite loads or
/// results; `Singular` when the pose admits no unique reactions (a branch
/// point, or a relative pivot `<= 12 eps`).
pub fn reactions<T: Real>(
    pos: &TriadPosition<T>,
    loads: &TriadLoads<T>,
) -> Result<TriadReactions<T>, Error<T>> {
    let w = [loads.leg1, loads.leg2, loads.leg3, loads.ternary];
    if !w.iter().all(Wrench::is_finite) {
        return Err(Error::new(PRIM, Fault::NonFinite { what: "triad load" }));
    }
    let (o, i) = (T::one(), T::zero());
    let mut m = [[i; 12]; 12];
    let legs = [pos.r1, pos.r2, pos.r3];
    for (k, r) in legs.iter().enumerate() {
        let (row, col) = (3 * k, 2 * k);
        // Outer force on the leg at K = joint - r; the inner joint's force
        // on the ternary, received by the leg with the opposite sign.
        m[row][col] = o;
        m[row + 1][col + 1] = o;
        m[row][6 + col] = -o;
        m[row + 1][7 + col] = -o;
        // Moment about the inner joint of a force at K: cross(-r, F).
        m[row + 2][col] = r.y;
        m[row + 2][col + 1] = -r.x;
        // The ternary's force rows hold the three inner forces.
        m[9][6 + col] = o;
        m[10][7 + col] = o;
    }
    for (col, arm) in [(8, pos.ab), (10, pos.ap)] {
        m[11][col] = -arm.y;
        m[11][col + 1] = arm.x;
    }
    let mut rhs = [i; 12];
    for (k, load) in w.iter().enumerate() {
        rhs[3 * k] = -load.force.x;
        rhs[3 * k + 1] = -load.force.y;
        rhs[3 * k + 2] = -load.moment;
    }
    let s = linsolve::solve(m, rhs).map_err(|e| Error::new(PRIM, e.fault))?;
    if !s.x.iter().all(|x| x.finite()) {
        return Err(Error::new(
            PRIM,
            Fault::NonFinite {
                what: "triad reaction",
            },
        ));
    }
    let v = |j: usize| Vector2::new(s.x[j], s.x[j + 1]);
    Ok(TriadReactions {
        k1: v(0),
        k2: v(2),
        k3: v(4),
        a: v(6),
        b: v(8),
        p: v(10),
        min_pivot_ratio: s.min_pivot_ratio,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Stephenson III triad of `examples/stephenson.rs` at link 6's angle `phi` (rad).
    fn stephenson(phi: f64) -> (Triad<f64>, [Point2<f64>; 3]) {
        let d = 40f64.to_radians();
        let triad = Triad {
            l1: 0.08,
            l2: 0.20,
            l3: 0.28,
            ab: 0.26,
            p_local: Vector2::new(0.15 * d.cos(), 0.15 * d.sin()),
        };
        let c = Point2::new(0.05 + 0.24 * phi.cos(), 0.42 + 0.24 * phi.sin());
        (triad, [Point2::new(0.0, 0.0), Point2::new(0.30, 0.0), c])
    }

    /// The search that [`position_near`] falls back on when Newton fails
    /// gives, for a small step, the assembly Newton finds (bit for bit: both
    /// end in the same polish); from a pose claimed to lie on the other
    /// side of the branch points it takes the nearest assembly there, and
    /// from a pose beyond the jump limit it refuses (`NotNear`), never
    /// returning the nearest assembly of the wrong side.
    #[test]
    fn fallback_keeps_the_side_and_the_jump_limit() {
        let phi0 = (-40.0f64).to_radians();
        let (triad, k) = stephenson(phi0);
        let f = Frame::new(&triad, &k).unwrap();
        let all = search(&f);
        assert_eq!(all.len(), 4);
        let start = *all.iter().next().unwrap();
        let (t1, k1) = stephenson(phi0 + 0.5f64.to_radians());
        let f1 = Frame::new(&t1, &k1).unwrap();
        let by_newton = refine(&t1, &k1, &start).unwrap();
        let by_search = fallback(&f1, &start).unwrap();
        assert!(f1.distance(&by_newton, &Near::of(&by_search)) < 1e-15);
        assert!(by_search.jacobian * start.jacobian > 0.0);
        // Claimed on the other side: the nearest there, or NotNear.
        let flipped = TriadPosition {
            jacobian: -start.jacobian,
            ..start
        };
        match fallback(&f1, &flipped) {
            Ok(p) => assert!(p.jacobian * start.jacobian < 0.0),
            Err(e) => assert!(matches!(e.fault, Fault::NotNear { .. })),
        }
        // Beyond the jump: a pose 0.1 m off (the limit is 0.04 m).
        let off = Vector2::new(0.1, 0.0);
        let far = TriadPosition {
            a: start.a + off,
            b: start.b + off,
            p: start.p + off,
            ..start
        };
        let e = fallback(&f1, &far).unwrap_err();
        assert!(
            matches!(e.fault, Fault::NotNear { next, .. } if next == 0.04),
            "{e:?}"
        );
    }

    #[test]
    fn near_from_table_interpolates_and_refuses_outside() {
        // Proves the tracked-pose table is read by linear interpolation
        // between the two rows around the input, with uneven spacing (a
        // pose linear in the input is reproduced to rounding), that the
        // ends are included, and that an input outside the rows, a NaN, or
        // a one-row table is a typed error, not an extrapolation.
        let row = |q: f64| [q, 1.0 + q, 2.0 - q, 3.0 * q, 4.0, -q, 0.5 * q];
        let table = [row(-1.0), row(-0.25), row(0.5), row(2.0)];
        for q in [-1.0, -0.6, -0.25, 0.1, 0.5, 1.7, 2.0] {
            let n = near_from_table(&table, q).unwrap();
            let want = row(q);
            let got = [n.a.x, n.a.y, n.b.x, n.b.y, n.p.x, n.p.y];
            for (g, w) in got.iter().zip(&want[1..]) {
                assert!(
                    (g - w).abs() <= 4.0 * f64::EPSILON * (1.0 + w.abs()),
                    "{q}: {g} vs {w}"
                );
            }
        }
        for q in [-1.000_000_1, 2.000_000_1, f64::NAN] {
            let e = near_from_table(&table, q).unwrap_err();
            assert!(
                matches!(e.fault, Fault::NotNear { nearest, .. } if nearest.is_infinite())
                    || matches!(e.fault, Fault::NonFinite { .. }),
                "{q}: {e:?}"
            );
        }
        assert!(near_from_table(&table[..1], -1.0).is_err());
        assert!(near_from_table::<f64>(&[], 0.0).is_err());
    }
}
