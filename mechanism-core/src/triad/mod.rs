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
//! The assembly reduces to one polynomial equation of degree six: with the
//! ternary's angle `phi` known, legs 2 and 3 minus leg 1 are two equations
//! linear in `A`; Cramer's rule gives `A`, and leg 1's equation becomes a
//! trigonometric polynomial of order 3 in `phi`, of degree 6 in
//! `tan(phi / 2)`, so a triad has at most 6 real assemblies
//! ([`MAX_ASSEMBLIES`]). [`assemblies`] finds them all without heap:
//!
//! 1. the polynomial's coefficients from the dimensions and the known points
//!    (a few dozen products, `polynomial.rs`);
//! 2. its real roots, each half of the circle in its own variable (`tan` or
//!    `cot` of `phi / 2`, in `[-1, 1]`): isolated by the roots of its
//!    derivatives (monotone pieces), each bracketed root found by Newton's
//!    method kept in its bracket; local extrema within rounding of zero
//!    (near-double roots, where two assemblies meet) are kept as candidates;
//! 3. `A` at each root by Cramer's rule (or, where the two lines are nearly
//!    parallel, from leg 1's circle, both intersections), then Newton's
//!    method on the full 3x3 system in the unknowns `(A, phi)`, equations
//!    `(|A - Ki|^2 - li^2) / 2 = 0` for the three legs, to full precision;
//!    kept when it converges (residuals at rounding level); assemblies whose
//!    joints agree to `sqrt(eps) / 8` of the group's scale are merged;
//! 4. near a branch point (relative determinant below 1/8) one or two more
//!    Newton steps whose residuals are evaluated in double words (`f32` and
//!    `f64`; not for dual numbers): there the residuals' rounding divided by
//!    the small singular value would leave the joints dozens of ulps off,
//!    and the rates, solved through the same nearly singular matrix, that
//!    error over the determinant again; polished, the joints are the
//!    rounded solution (`Frame::polish` in `frame.rs`).
//!
//! Where the polynomial vanishes identically (a degenerate triad whose
//! reduced equation holds at every angle) and where it gives no assembly,
//! the earlier sampled search (`scan.rs`) runs instead: the chain `K1 - A -
//! B - K2` as a four-bar traversed along its closed loops, the residual
//! `|P - K3| - l3` sampled at [`SAMPLES`] points per loop, sign changes
//! bracketed and near-zero minima searched, each start polished the same
//! way; with no assembly it measures how far the triad misses closing
//! (`CannotAssemble`'s `miss`).
//!
//! Everything is computed in a frame moved to `K1` and scaled by the power
//! of two at or below the longest dimension (exact), so results scale exactly
//! with powers of two and no square of a length overflows.
//!
//! **Which assembly.** [`position`] takes a [`Near`]: the approximate
//! positions of `A`, `B` and `P` ("at this input the joints are about
//! here"), and returns the assembly nearest to it (root-sum-square distance
//! over the three joints). It answers without the search when it can prove
//! the answer: Newton on the leg equations from the pose, then a radius of
//! isolation around the assembly reached (`Frame::isolation`: the
//! uniqueness half of Newton-Kantorovich's theorem, from the Jacobian's
//! inverse there and a bound on the equations' second derivatives) that
//! puts every other assembly at least `1 + NEAR_FACTOR` times as far from
//! it as the pose is; else every assembly as above, and the rule below. It never returns a different one silently: no
//! assembly is `CannotAssemble`, and a nearest one farther than
//! [`JUMP_FRACTION`] of the shortest dimension, or not at most half as far
//! ([`NEAR_FACTOR`]) as the next, is `NotNear`. [`position_near`]
//! tracks an assembly from a previous pose: Newton on the loop from it (a
//! few steps without trigonometry, faster than the polynomial's roots and
//! their polish; measured in docs/report.md), accepted when it
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
//! angular velocity): the position Newton's 3x3 Jacobian, eliminated once
//! (row equilibration, partial pivoting: [`crate::linsolve::factor`]'s
//! arithmetic unrolled for this matrix, `elimination.rs`) for
//! the velocity and the acceleration after its determinant is checked against its bound
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

mod assembly;
mod elimination;
mod forces;
mod frame;
mod polynomial;
mod rates;
mod scan;

pub use assembly::refine;
pub use forces::{TriadLoads, TriadReactions};
pub use rates::{acceleration, velocity, TriadAcceleration, TriadVelocity};

use crate::error::{Error, Fault, Primitive};
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

/// The triad's searches and reactions compiled once, in this crate, for
/// `f32` and `f64` (a supertrait of [`Real`]): a definition's crate calls
/// them instead of instantiating the generic search, its polish and the
/// 12x12 elimination in its own code, which made a triad definition take
/// seconds longer to compile than a dyad's. Out of line (`inline(never)`),
/// so no copy is made downstream. Not for implementing elsewhere.
#[doc(hidden)]
pub trait Kernels: Sized {
    /// [`assemblies`] in this type.
    fn triad_assemblies(
        triad: &Triad<Self>,
        k: &[Point2<Self>; 3],
    ) -> Result<Assemblies<Self>, Error<Self>>
    where
        Self: Real;
    /// [`position`] in this type.
    fn triad_position(
        triad: &Triad<Self>,
        k: &[Point2<Self>; 3],
        near: &Near<Self>,
    ) -> Result<TriadPosition<Self>, Error<Self>>
    where
        Self: Real;
    /// [`position_near`] in this type.
    fn triad_position_near(
        triad: &Triad<Self>,
        k: &[Point2<Self>; 3],
        previous: &TriadPosition<Self>,
    ) -> Result<TriadPosition<Self>, Error<Self>>
    where
        Self: Real;
    /// [`reactions`] in this type.
    fn triad_reactions(
        pos: &TriadPosition<Self>,
        loads: &TriadLoads<Self>,
    ) -> Result<TriadReactions<Self>, Error<Self>>
    where
        Self: Real;
}

/// Implements [`Kernels`] for one scalar type.
macro_rules! kernels {
    ([$($g:tt)*] $t:ty) => {
        impl<$($g)*> Kernels for $t {
            #[inline(never)]
            fn triad_assemblies(
                triad: &Triad<Self>,
                k: &[Point2<Self>; 3],
            ) -> Result<Assemblies<Self>, Error<Self>> {
                assembly::assemblies_in(triad, k)
            }
            #[inline(never)]
            fn triad_position(
                triad: &Triad<Self>,
                k: &[Point2<Self>; 3],
                near: &Near<Self>,
            ) -> Result<TriadPosition<Self>, Error<Self>> {
                assembly::position_in(triad, k, near)
            }
            #[inline(never)]
            fn triad_position_near(
                triad: &Triad<Self>,
                k: &[Point2<Self>; 3],
                previous: &TriadPosition<Self>,
            ) -> Result<TriadPosition<Self>, Error<Self>> {
                assembly::position_near_in(triad, k, previous)
            }
            #[inline(never)]
            fn triad_reactions(
                pos: &TriadPosition<Self>,
                loads: &TriadLoads<Self>,
            ) -> Result<TriadReactions<Self>, Error<Self>> {
                forces::reactions_in(pos, loads)
            }
        }
    };
}

kernels!([] f32);
kernels!([] f64);
// The dual numbers of sensitivities: the same bodies, one copy per `N`.
#[cfg(feature = "dual")]
kernels!([const N: usize] crate::dual::Dual<N>);

/// Finds every assembly (see the module documentation).
///
/// Errors: `NonPositive` for a length `<= 0` (or non-finite: `NonFinite`),
/// `NonFinite` for a non-finite point or `P_local`. No assembly is not an
/// error here: the list is empty ([`position`] reports it).
#[inline]
pub fn assemblies<T: Real>(
    triad: &Triad<T>,
    k: &[Point2<T>; 3],
) -> Result<Assemblies<T>, Error<T>> {
    T::triad_assemblies(triad, k)
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
#[inline]
pub fn position<T: Real>(
    triad: &Triad<T>,
    k: &[Point2<T>; 3],
    near: &Near<T>,
) -> Result<TriadPosition<T>, Error<T>> {
    T::triad_position(triad, k, near)
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
#[inline]
pub fn position_near<T: Real>(
    triad: &Triad<T>,
    k: &[Point2<T>; 3],
    previous: &TriadPosition<T>,
) -> Result<TriadPosition<T>, Error<T>> {
    T::triad_position_near(triad, k, previous)
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
#[inline]
pub fn reactions<T: Real>(
    pos: &TriadPosition<T>,
    loads: &TriadLoads<T>,
) -> Result<TriadReactions<T>, Error<T>> {
    T::triad_reactions(pos, loads)
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
    lookup(table, q.as_f64())
}

/// [`near_from_table`] for an input that is an angle (rad): the pose repeats
/// every turn, so `q` is first moved by whole turns into `[q0, q0 + 2 pi)`,
/// `q0` the table's first input (a crank at `theta - 2 pi` is where it is
/// at `theta`). Errors as for [`near_from_table`], for the moved input.
pub fn near_from_table_turning<T: Real>(table: &[[f64; 7]], q: T) -> Result<Near<T>, Error<T>> {
    let x = q.as_f64();
    match table.first() {
        Some(first) if x.is_finite() => lookup(table, same_turn(x, first[0])),
        _ => lookup(table, x),
    }
}

/// The angle `x` (rad) moved by whole turns into `[from, from + 2 pi)`
/// (unchanged when the turns do not fit an `i64`: then outside any table).
pub fn same_turn(x: f64, from: f64) -> f64 {
    let tau = core::f64::consts::TAU;
    let turns = (x - from) / tau;
    let fits = turns.abs() < 9.0e18;
    if !fits {
        return x;
    }
    let mut y = x - from - (turns as i64) as f64 * tau;
    if y < 0.0 {
        y += tau;
    }
    if y >= tau {
        y -= tau;
    }
    from + y
}

/// The table's pose at input `x` (see [`near_from_table`]).
fn lookup<T: Real>(table: &[[f64; 7]], x: f64) -> Result<Near<T>, Error<T>> {
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

#[cfg(test)]
mod tests {
    use super::*;

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
        // As an angle: whole turns away is the same pose (bit for bit where
        // the turn is exact in f64 arithmetic, here within 4 ulps of 2 pi).
        let tau = core::f64::consts::TAU;
        for q in [-0.6, 0.1, 1.7] {
            let n0 = near_from_table_turning(&table, q).unwrap();
            for turns in [-3.0, -1.0, 1.0, 2.0] {
                let n = near_from_table_turning(&table, q + turns * tau).unwrap();
                assert!((n.a.x - n0.a.x).abs() <= 16.0 * f64::EPSILON, "{q} {turns}");
                assert!((n.p.y - n0.p.y).abs() <= 16.0 * f64::EPSILON, "{q} {turns}");
            }
        }
        // A table over less than a turn still refuses the rest of the turn.
        assert!(near_from_table_turning(&table, 3.0).is_err());
        assert!(near_from_table_turning(&table, f64::NAN).is_err());
        assert!(near_from_table::<f64>(&[], 0.0).is_err());
    }
}
