//! Every assembly, the one nearest a given pose, and tracking.

use super::frame::{Frame, State};
use super::polynomial::{self, RootsOf};
use super::scan::{self, add_root};
use super::{Assemblies, Near, Triad, TriadPosition, MAX_ASSEMBLIES, NEAR_FACTOR, PRIM};
use crate::error::{Error, Fault};
use crate::geometry::{abs, all_finite, dot, min};
use crate::scalar::Real;
use nalgebra::Point2;

/// [`super::assemblies`], generic: instantiated in this crate for `f32` and
/// `f64` only (through [`super::Kernels`]).
pub(super) fn assemblies_in<T: Real>(
    triad: &Triad<T>,
    k: &[Point2<T>; 3],
) -> Result<Assemblies<T>, Error<T>> {
    let f = Frame::new(triad, k)?;
    Ok(search(&f))
}

/// Every assembly: the closed form's roots ([`polynomial`]), each polished
/// by Newton on the leg equations and merged when they coincide; the sampled
/// scan ([`scan::search`]) where the polynomial vanishes identically (a
/// degenerate triad) and, to measure how far the triad misses closing, where
/// it gives no assembly.
fn search<T: Real>(f: &Frame<T>) -> Assemblies<T> {
    let RootsOf::Halves(t, s) = polynomial::roots(f) else {
        return scan::search(f);
    };
    let mut found = Assemblies {
        list: [None; MAX_ASSEMBLIES],
        count: 0,
        miss: T::zero(),
        reach: f.l3 * f.up,
    };
    for (starts, flip) in [(&t, false), (&s, true)] {
        for x in starts.iter() {
            let e = polynomial::unit_of(*x, flip);
            for start in polynomial::starts_at(f, &e).into_iter().flatten() {
                add_root(f, start, &mut found);
            }
        }
    }
    if found.is_empty() {
        return scan::search(f);
    }
    found
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

/// [`super::position`], generic: instantiated in this crate for `f32` and
/// `f64` only (through [`super::Kernels`]).
pub(super) fn position_in<T: Real>(
    triad: &Triad<T>,
    k: &[Point2<T>; 3],
    near: &Near<T>,
) -> Result<TriadPosition<T>, Error<T>> {
    let f = Frame::new(triad, k)?;
    if !near_finite(near) {
        return Err(Error::new(PRIM, Fault::NonFinite { what: "triad pose" }));
    }
    if let Some(pos) = isolated(&f, near) {
        return Ok(pos);
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

/// [`super::position`]'s answer without the full search, when it can be
/// proved: Newton on the leg equations from `near` (its `A` and the axis
/// `A -> B`) converges to an assembly at distance `d` from `near` within
/// the jump limit, and [`Frame::isolation`] proves every other assembly at
/// least `(1 + NEAR_FACTOR) d` from it, so at least `NEAR_FACTOR d` from
/// `near`: that assembly is the nearest and clearly so, the one the search
/// would select (from its own polish of the same root). `None` otherwise
/// (Newton fails, the radius is too small, near a branch point or with a
/// pose far from every assembly): then the search decides, and reports its
/// errors. Measured in docs/report.md, "Stephenson (triad)": the generated
/// stateless `position()`, whose pose is the tracked table's, takes this
/// path at all but the inputs nearest the swing's ends.
#[inline(always)]
fn isolated<T: Real>(f: &Frame<T>, near: &Near<T>) -> Option<TriadPosition<T>> {
    let a = (near.a - f.origin) * f.down;
    let axis = (near.b - near.a) * f.down;
    let norm2 = dot(&axis, &axis);
    let usable = norm2 > T::zero() && norm2.finite();
    if !usable {
        return None;
    }
    let start = State {
        a,
        e: axis * (T::one() / norm2.sqrt_kernel()),
    };
    let x = f.newton(start)?;
    let pos = f.finish(&x)?;
    let d = f.distance(&pos, near);
    let radius = f.isolation(&x)?;
    let clear = d <= f.jump() && radius >= T::lit(1.0 + NEAR_FACTOR) * d;
    clear.then_some(pos)
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
    let axis = previous.axis;
    let norm2 = dot(&axis, &axis);
    if !(all_finite([x0.x, x0.y, axis.x, axis.y]) && norm2 > T::zero()) {
        return Err(Error::new(PRIM, Fault::NonFinite { what: "triad pose" }));
    }
    let start = State {
        a: x0,
        e: axis * inv_length(norm2),
    };
    let Some(pos) = f.newton(start).and_then(|x| f.finish(&x)) else {
        return Err(not_near(&f, inf, f.jump()));
    };
    // The move against the limit in squares (no square root on the way
    // that accepts).
    let moved2 = f.distance_squared(&pos, &Near::of(previous));
    let jump = f.jump();
    if same_side(&pos, previous) && moved2 <= jump * jump {
        Ok(pos)
    } else {
        Err(not_near(&f, moved2.sqrt_kernel(), jump))
    }
}

/// `1 / |axis|` from `norm2 = |axis|^2 > 0`. An axis from an earlier
/// solve is of unit length to rounding: for `|norm2 - 1| <= 2^-20` the
/// series `1 - d/2 + 3 d^2/8` (`d = norm2 - 1`; first omitted term `5 d^3 /
/// 16`, below `2^-61`, under half an ulp of 1 in `f64` and `f32`) instead
/// of a square root and a division; else `1 / sqrt(norm2)`.
#[inline(always)]
fn inv_length<T: Real>(norm2: T) -> T {
    let d = norm2 - T::one();
    if abs(d) <= T::lit(9.5367431640625e-7) {
        T::one() - d * (T::lit(0.5) - T::lit(0.375) * d)
    } else {
        T::one() / norm2.sqrt_kernel()
    }
}

/// Both determinants non-zero with the same sign (no branch point between).
fn same_side<T: Real>(p: &TriadPosition<T>, q: &TriadPosition<T>) -> bool {
    p.jacobian * q.jacobian > T::zero()
}

/// [`super::position_near`], generic: instantiated in this crate for `f32` and
/// `f64` only (through [`super::Kernels`]).
pub(super) fn position_near_in<T: Real>(
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

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector2;

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

    /// The Stephenson III's swing as a stateless `position()` from a table
    /// sees it: the assembly followed at 49 evenly spaced inputs (the
    /// macro's table crowds its rows near the ends instead, which misses
    /// by 60 times less there: `mechanism-codegen`'s `kinds/triad.rs`), the
    /// pose interpolated linearly at 3600 inputs between them. Proves that the isolated Newton
    /// ([`isolated`]) answers at all but the inputs nearest the swing's ends
    /// (3452 of 3600, 96 %: near the ends the interpolated pose is farther
    /// off and the other assembly closer; those go to the search), and that
    /// where it answers it returns the assembly the search selects.
    #[test]
    fn the_tracked_table_pose_is_answered_without_the_search() {
        let (lo, hi) = ((-50.43f64).to_radians(), (-2.64f64).to_radians());
        const ROWS: usize = 49;
        let rows = ROWS;
        let (t0, k0) = stephenson((-49.48f64).to_radians());
        let hint = Near::new(
            Point2::new(-0.061, -0.052),
            Point2::new(0.137, 0.116),
            Point2::new(-0.036, 0.096),
        );
        let mut pos = position_in(&t0, &k0, &hint).unwrap();
        // Follow to `lo` in small steps, then along the rows.
        let mut phi = (-49.48f64).to_radians();
        let mut table = [(0.0, Near::of(&pos)); ROWS];
        for (i, row) in table.iter_mut().enumerate() {
            let target = lo + (hi - lo) * i as f64 / (rows - 1) as f64;
            while phi != target {
                let step = (target - phi).clamp(-0.002, 0.002);
                phi = if (target - phi).abs() <= 0.002 {
                    target
                } else {
                    phi + step
                };
                let (t, k) = stephenson(phi);
                pos = position_near_in(&t, &k, &pos).unwrap();
            }
            *row = (phi, Near::of(&pos));
        }
        let n = 3600;
        let mut answered = 0;
        for j in 0..n {
            let x = lo + (hi - lo) * (j as f64 + 0.5) / n as f64;
            let i = (((x - lo) / (hi - lo) * (rows - 1) as f64) as usize).min(rows - 2);
            let ((x0, p0), (x1, p1)) = (table[i], table[i + 1]);
            let w = (x - x0) / (x1 - x0);
            let lerp = |a: Point2<f64>, b: Point2<f64>| a + (b - a) * w;
            let near = Near::new(lerp(p0.a, p1.a), lerp(p0.b, p1.b), lerp(p0.p, p1.p));
            let (t, k) = stephenson(x);
            let f = Frame::new(&t, &k).unwrap();
            if let Some(p) = isolated(&f, &near) {
                answered += 1;
                let all = search(&f);
                let (q, _, _) = nearest(&f, all.iter(), &near).unwrap();
                assert!(f.distance(&p, &Near::of(&q)) < 1e-14, "at {x}");
            }
        }
        assert!(answered * 100 >= 95 * n, "{answered} of {n}");
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
}
