//! The generic kinetostatic system of a class II (two-link) group: three
//! joints, each revolute or prismatic, each joining the outside to link 1, the
//! outside to link 2, or link 1 to link 2; six unknowns; six equations.
//!
//! Unknowns, two per joint, in joint order (columns `2k`, `2k + 1` for joint
//! `k`), each the action on the receiving body named by [`Connection`]:
//! - revolute at `point`: the force components `Fx`, `Fy` acting through
//!   `point`;
//! - prismatic at `point` with direction `dir`: the normal force `N` (the force
//!   is `N perp(dir)`, through `point`) and the couple `M` (the moment of the
//!   contact about `point`). In the matrix the couple's column holds `M / L`,
//!   with `L` = [`GroupSystem::couple_scale`], so that its entries (`L`) are
//!   comparable to the lever arms in the same moment rows; the solver's row
//!   scaling cannot fix column scales, this does.
//!
//! Equations (rows), with all moments about the caller's point `about`:
//! link 1 `Fx`, `Fy`, moment; then link 2 likewise. Each reads
//! `sum of unknown reactions on the link = -(known load on the link)`. A
//! `Link1ToLink2` reaction enters link 2's rows with `+` and link 1's with `-`
//! (Newton's third law). Taking moments about a joint of the group (the caller
//! chooses) keeps lever arms at the group's size and puts zeros where the
//! joint's own unknowns would be.
//!
//! This is the textbook formulation (Artobolevsky; seed 003 writes the same
//! equations for an RRR group, though it eliminates the inner joint by hand and
//! keeps four); here the elimination is left to [`crate::linsolve`] in
//! [`solve`]. The five groups of [`crate::force`] solve the same equations in
//! closed form (each group's file derives it); [`solve`] is the general path,
//! for any three joints, and the independent check of those closed forms in
//! the tests.

use crate::error::{Error, Fault, Primitive};
use crate::force::body::Wrench;
use crate::geometry::{abs, cross, length, perp};
use crate::linsolve;
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

/// Which two bodies a joint connects, in the order "giver -> receiver": the
/// unknowns of the joint are the action of the first on the second.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Connection {
    /// The outside body (ground or an earlier group's link) acts on link 1.
    OutsideToLink1,
    /// The outside body acts on link 2.
    OutsideToLink2,
    /// Link 1 acts on link 2 (link 1 receives the opposite).
    Link1ToLink2,
}

/// The kind and geometry of a kinematic pair.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Pair<T: Real> {
    /// A revolute through `point` (L).
    Revolute {
        /// The joint centre (L).
        point: Point2<T>,
    },
    /// A frictionless prismatic pair sliding along `dir`, whose reaction is
    /// stated about `point`.
    Prismatic {
        /// The reference point of the reaction (L): the normal force acts
        /// through it and the couple is about it.
        point: Point2<T>,
        /// The sliding direction; unit, so that the unknown `N` is the normal
        /// force in force units (otherwise `N` is the multiplier of
        /// `perp(dir)`). See [`unit_direction`].
        dir: Vector2<T>,
    },
}

/// One joint of a group.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Joint<T: Real> {
    /// The pair and its geometry.
    pub pair: Pair<T>,
    /// Which bodies it connects (giver -> receiver).
    pub connection: Connection,
}

/// The assembled 6x6 system (see the module documentation for the layout).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GroupSystem<T: Real> {
    /// `matrix[i][j]`: row `i` (link `i / 3`, equation `Fx`, `Fy`, moment),
    /// column `j` (joint `j / 2`, unknown `j % 2`).
    pub matrix: [[T; 6]; 6],
    /// The right-hand side: minus the known loads, `-(F1x, F1y, M1, F2x, F2y,
    /// M2)`.
    pub rhs: [T; 6],
    /// `L`: the largest distance from `about` to a joint's point, or 1 when all
    /// coincide with it (then no moment row holds a lever arm and any `L` does).
    /// A prismatic pair's couple column holds `M / L`.
    pub couple_scale: T,
}

/// The solved reactions of a group.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GroupSolution<T: Real> {
    /// Per joint, in the order given: `[Fx, Fy]` for a revolute, `[N, M]` for a
    /// prismatic pair (couple `M` about the pair's point, already multiplied
    /// back by `couple_scale`), each the action of the giver on the receiver.
    pub unknowns: [[T; 2]; 3],
    /// The conditioning indicator of [`linsolve::Solution::min_pivot_ratio`].
    pub min_pivot_ratio: T,
}

/// `dir / |dir|`. A `dir` whose computed squared length is within `4 eps`
/// of 1 (the guide, slot and link directions the kinematics hand over are
/// unit to rounding) is returned as it is: its length is then within about
/// `3 eps` of 1, as close as the square root and the division of a
/// normalization would leave it, and the two (the costliest operations of a
/// group's force analysis after its one or two divisions) are skipped.
///
/// Errors: `NonFinite` for a non-finite `dir`, `NonPositive` for a zero one
/// (both tagged with `primitive`).
#[inline(always)]
pub fn unit_direction<T: Real>(
    dir: &Vector2<T>,
    primitive: Primitive,
    what: &'static str,
) -> Result<Vector2<T>, Error<T>> {
    let dir = crate::geometry::finite_vec(*dir, primitive, what)?;
    let squared = dir.x * dir.x + dir.y * dir.y;
    if abs(squared - T::one()) <= T::lit(4.0) * T::eps() {
        return Ok(dir);
    }
    let norm = crate::geometry::positive(length(&dir), primitive, what)?;
    Ok(dir / norm)
}

/// The point of a pair.
#[inline(always)]
fn point_of<T: Real>(pair: &Pair<T>) -> Point2<T> {
    match *pair {
        Pair::Revolute { point } | Pair::Prismatic { point, .. } => point,
    }
}

/// The two unknowns' effects `(Fx, Fy, moment about `about`)` on the receiver.
#[inline(always)]
fn effects<T: Real>(pair: &Pair<T>, about: &Point2<T>, couple_scale: T) -> [[T; 3]; 2] {
    let zero = T::zero();
    let one = T::one();
    match *pair {
        Pair::Revolute { point } => {
            let r = point - about;
            // Moment of (Fx, 0) is -r.y Fx; of (0, Fy) is r.x Fy.
            [[one, zero, -r.y], [zero, one, r.x]]
        }
        Pair::Prismatic { point, dir } => {
            let n = perp(&dir);
            let r = point - about;
            [[n.x, n.y, cross(&r, &n)], [zero, zero, couple_scale]]
        }
    }
}

/// Signs with which the receiver's unknowns enter link 1's and link 2's rows.
#[inline(always)]
fn signs<T: Real>(connection: Connection) -> [T; 2] {
    let zero = T::zero();
    let one = T::one();
    match connection {
        Connection::OutsideToLink1 => [one, zero],
        Connection::OutsideToLink2 => [zero, one],
        Connection::Link1ToLink2 => [-one, one],
    }
}

/// `L` of [`GroupSystem::couple_scale`]: the largest distance from `about` to
/// one of `points`, or 1 when all coincide with it.
#[inline(always)]
fn couple_scale_of<T: Real>(points: &[Point2<T>], about: &Point2<T>) -> T {
    let reach = points.iter().fold(T::zero(), |m, p| {
        let d = length(&(p - about));
        if d > m {
            d
        } else {
            m
        }
    });
    if reach > T::zero() {
        reach
    } else {
        T::one()
    }
}

/// Builds the system; `load1`, `load2` are the known loads on links 1 and 2
/// as wrenches about `about` (the same point for both).
pub fn assemble<T: Real>(
    joints: &[Joint<T>; 3],
    about: &Point2<T>,
    load1: &Wrench<T>,
    load2: &Wrench<T>,
) -> GroupSystem<T> {
    let couple_scale = couple_scale_of(&joints.map(|j| point_of(&j.pair)), about);
    let mut matrix = [[T::zero(); 6]; 6];
    // Joint `k` fills columns `2k`, `2k + 1`; its receiver's rows get the
    // effects times the sign, the other link's rows the same with its sign.
    for (k, joint) in joints.iter().enumerate() {
        let effect = effects(&joint.pair, about, couple_scale);
        let sign = signs::<T>(joint.connection);
        for (rows, &s) in matrix.chunks_exact_mut(3).zip(sign.iter()) {
            for (row, i) in rows.iter_mut().zip(0..3) {
                for (u, e) in effect.iter().enumerate() {
                    if let Some(v) = row.get_mut(2 * k + u) {
                        *v = s * e[i];
                    }
                }
            }
        }
    }
    let rhs = [
        -load1.force.x,
        -load1.force.y,
        -load1.moment,
        -load2.force.x,
        -load2.force.y,
        -load2.moment,
    ];
    GroupSystem {
        matrix,
        rhs,
        couple_scale,
    }
}

/// `Err(NonFinite)` (tagged with `primitive`) unless both loads, the pairs'
/// geometry and `about` are finite.
#[inline]
fn check_finite<T: Real>(
    pairs: &[&Pair<T>],
    about: &Point2<T>,
    load1: &Wrench<T>,
    load2: &Wrench<T>,
    primitive: Primitive,
) -> Result<(), Error<T>> {
    if !(load1.is_finite() && load2.is_finite()) {
        return Err(Error::new(
            primitive,
            Fault::NonFinite { what: "group load" },
        ));
    }
    let geometry_finite = pairs.iter().all(|pair| match **pair {
        Pair::Revolute { point } => point.x.finite() && point.y.finite(),
        Pair::Prismatic { point, dir } => {
            point.x.finite() && point.y.finite() && dir.x.finite() && dir.y.finite()
        }
    }) && about.x.finite()
        && about.y.finite();
    if geometry_finite {
        Ok(())
    } else {
        Err(Error::new(
            primitive,
            Fault::NonFinite {
                what: "group geometry",
            },
        ))
    }
}

/// Multiplies the couple unknown of each prismatic pair back by `L` and
/// checks that every reaction is finite.
#[inline]
fn finish<T: Real>(
    mut unknowns: [[T; 2]; 3],
    pairs: [&Pair<T>; 3],
    couple_scale: T,
    min_pivot_ratio: T,
    primitive: Primitive,
) -> Result<GroupSolution<T>, Error<T>> {
    for (u, pair) in unknowns.iter_mut().zip(pairs.iter()) {
        if let Pair::Prismatic { .. } = pair {
            u[1] *= couple_scale;
        }
    }
    if !unknowns.iter().flatten().all(|v| v.finite()) {
        return Err(Error::new(
            primitive,
            Fault::NonFinite {
                what: "group reaction",
            },
        ));
    }
    Ok(GroupSolution {
        unknowns,
        min_pivot_ratio,
    })
}

/// Solves a group: assembles with [`assemble`] and solves with
/// [`linsolve::solve_in_place`] (row equilibration and partial pivoting). The
/// general path, for any three joints; the five groups of [`crate::force`]
/// use their closed forms, a fraction of the work.
///
/// Errors, tagged with `primitive`: `NonFinite` when a load, a joint's
/// geometry or the result is not finite; `Singular` when the pose admits no
/// unique reactions (a relative pivot `<= 6 eps`, see [`linsolve::solve`]).
pub fn solve<T: Real>(
    joints: &[Joint<T>; 3],
    about: &Point2<T>,
    load1: &Wrench<T>,
    load2: &Wrench<T>,
    primitive: Primitive,
) -> Result<GroupSolution<T>, Error<T>> {
    let [j0, j1, j2] = joints;
    check_finite(
        &[&j0.pair, &j1.pair, &j2.pair],
        about,
        load1,
        load2,
        primitive,
    )?;
    let GroupSystem {
        mut matrix,
        mut rhs,
        couple_scale,
    } = assemble(joints, about, load1, load2);
    let min_pivot_ratio = linsolve::solve_in_place(&mut matrix, &mut rhs)
        .map_err(|e| Error::new(primitive, e.fault))?;
    let [x0, x1, x2, x3, x4, x5] = rhs;
    finish(
        [[x0, x1], [x2, x3], [x4, x5]],
        [&j0.pair, &j1.pair, &j2.pair],
        couple_scale,
        min_pivot_ratio,
        primitive,
    )
}
