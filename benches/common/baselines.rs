//! Baselines the generated code is measured against (benchmarks and report
//! only; nothing here is in the library).
//!
//! The four-bar of `scenes::FourBar`: ground `d` from O2 = (0, 0) to O4 = (d, 0),
//! crank `a` at angle `t2`, coupler `b`, rocker `c`, B on the left of A -> O4.
//! Every baseline returns the same [`FourBarOut`]: link angles `t3`, `t4`
//! (rad), angular velocities `w3`, `w4` (rad/s) and accelerations `al3`,
//! `al4` (rad/s^2), for crank speed `w2` and acceleration `al2`.
#![allow(dead_code)]

use nalgebra::{DMatrix, DVector, Matrix2, RealField, Vector2};

/// Dimensions (mm) of the four-bar of seed 002.
pub const GROUND: f64 = 304.8;
/// Crank length (mm).
pub const CRANK: f64 = 101.6;
/// Coupler length (mm).
pub const COUPLER: f64 = 254.0;
/// Rocker length (mm).
pub const ROCKER: f64 = 177.8;

/// Angles, rates and accelerations of the coupler (3) and rocker (4).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FourBarOut<T> {
    pub t3: T,
    pub t4: T,
    pub w3: T,
    pub w4: T,
    pub al3: T,
    pub al4: T,
}

/// A float for the baselines: f32 or f64 with a literal conversion.
pub trait F: RealField + Copy {
    fn c(x: f64) -> Self;
}
impl F for f64 {
    #[inline(always)]
    fn c(x: f64) -> Self {
        x
    }
}
impl F for f32 {
    #[inline(always)]
    fn c(x: f64) -> Self {
        x as f32
    }
}

/// The best hand-written closed form I can write (vector form, one sqrt for
/// the distance, one for the height, trig only for the crank and the two
/// output angles): B from the law of cosines on vectors, rates from the 2x2
/// system `w3 perp(r3) - w4 perp(r4) = -vA` in closed form (Cramer), no
/// error checks beyond what the arithmetic gives (NaN when it cannot close).
#[inline(always)]
pub fn closed_form<T: F>(t2: T, w2: T, al2: T) -> FourBarOut<T> {
    let (a, b, c, d) = (T::c(CRANK), T::c(COUPLER), T::c(ROCKER), T::c(GROUND));
    let (s2, c2) = t2.sin_cos();
    let (ax, ay) = (a * c2, a * s2);
    // d = O4 - A
    let (dx, dy) = (d - ax, -ay);
    let dist2 = dx * dx + dy * dy;
    let dist = dist2.sqrt();
    let inv = T::one() / dist;
    let along = (b * b - c * c + dist2) * T::c(0.5) * inv;
    let h = (b * b - along * along).sqrt();
    let (ex, ey) = (dx * inv, dy * inv);
    // r3 = B - A = along e + h perp(e); r4 = B - O4 = r3 - d
    let (r3x, r3y) = (along * ex - h * ey, along * ey + h * ex);
    let (r4x, r4y) = (r3x - dx, r3y - dy);
    // vA = w2 perp(A); aA = al2 perp(A) - w2^2 A
    let (vax, vay) = (-w2 * ay, w2 * ax);
    let det = r3x * r4y - r3y * r4x;
    let idet = T::one() / det;
    // w3 perp(r3) - w4 perp(r4) = -vA; dot with r4, r3.
    let w3 = -(vax * r4x + vay * r4y) * idet;
    let w4 = -(vax * r3x + vay * r3y) * idet;
    let (aax, aay) = (-al2 * ay - w2 * w2 * ax, al2 * ax - w2 * w2 * ay);
    let (wx, wy) = (
        -aax + w3 * w3 * r3x - w4 * w4 * r4x,
        -aay + w3 * w3 * r3y - w4 * w4 * r4y,
    );
    let al3 = (wx * r4x + wy * r4y) * idet;
    let al4 = (wx * r3x + wy * r3y) * idet;
    FourBarOut {
        t3: r3y.atan2(r3x),
        t4: r4y.atan2(r4x),
        w3,
        w4,
        al3,
        al4,
    }
}

/// Residual, Jacobian, (sin, cos) of t3 and of t4.
type LoopEq<T> = (Vector2<T>, Matrix2<T>, (T, T), (T, T));

/// Loop-closure equations in angle form: `a u(t2) + b u(t3) - c u(t4) - d x = 0`,
/// with Jacobian in `(t3, t4)`: `[[-b s3, c s4], [b c3, -c c4]]`.
#[inline(always)]
fn loop_eq<T: F>(t2: (T, T), t3: T, t4: T) -> LoopEq<T> {
    let (a, b, c, d) = (T::c(CRANK), T::c(COUPLER), T::c(ROCKER), T::c(GROUND));
    let (s3, c3) = t3.sin_cos();
    let (s4, c4) = t4.sin_cos();
    let f = Vector2::new(a * t2.1 + b * c3 - c * c4 - d, a * t2.0 + b * s3 - c * s4);
    let j = Matrix2::new(-b * s3, c * s4, b * c3, -c * c4);
    (f, j, (s3, c3), (s4, c4))
}

/// Rates and accelerations once the angles are known (same for both Newton
/// baselines): `J w = -a w2 (-s2, c2)`, `J al = -(a al2 (-s2, c2) - a w2^2
/// (c2, s2) - b w3^2 (c3, s3) + c w4^2 (c4, s4))`.
#[inline(always)]
fn rates_from_j<T: F>(
    solve: impl Fn(&Matrix2<T>, Vector2<T>) -> Option<Vector2<T>>,
    j: &Matrix2<T>,
    t2: (T, T),
    s3c3: (T, T),
    s4c4: (T, T),
    w2: T,
    al2: T,
) -> Option<(T, T, T, T)> {
    let (a, b, c) = (T::c(CRANK), T::c(COUPLER), T::c(ROCKER));
    let (s2, c2) = t2;
    let w = solve(j, Vector2::new(a * w2 * s2, -a * w2 * c2))?;
    let (w3, w4) = (w.x, w.y);
    let rhs = Vector2::new(
        a * al2 * s2 + a * w2 * w2 * c2 + b * w3 * w3 * s3c3.1 - c * w4 * w4 * s4c4.1,
        -a * al2 * c2 + a * w2 * w2 * s2 + b * w3 * w3 * s3c3.0 - c * w4 * w4 * s4c4.0,
    );
    let al = solve(j, rhs)?;
    Some((w3, w4, al.x, al.y))
}

/// Generic Newton-Raphson on the loop-closure equations with nalgebra's
/// fixed-size `Matrix2` LU, warm-started from `guess` (the previous pose),
/// until the step is below `tol` (rad) or 50 iterations.
#[inline(always)]
pub fn newton_fixed<T: F>(t2: T, w2: T, al2: T, guess: (T, T), tol: T) -> Option<FourBarOut<T>> {
    let sc2 = t2.sin_cos();
    let (mut t3, mut t4) = guess;
    let solve = |j: &Matrix2<T>, b: Vector2<T>| j.lu().solve(&b);
    for _ in 0..50 {
        let (f, j, _, _) = loop_eq(sc2, t3, t4);
        let dx = solve(&j, -f)?;
        t3 += dx.x;
        t4 += dx.y;
        if dx.x.abs() < tol && dx.y.abs() < tol {
            let (_, j, s3, s4) = loop_eq(sc2, t3, t4);
            let (w3, w4, al3, al4) = rates_from_j(solve, &j, sc2, s3, s4, w2, al2)?;
            return Some(FourBarOut {
                t3,
                t4,
                w3,
                w4,
                al3,
                al4,
            });
        }
    }
    None
}

/// The same Newton-Raphson with heap `DMatrix` / `DVector` and their LU, as a
/// run-time multibody solver (sized at run time) does it.
#[inline(never)]
pub fn newton_heap<T: F>(t2: T, w2: T, al2: T, guess: (T, T), tol: T) -> Option<FourBarOut<T>> {
    let sc2 = t2.sin_cos();
    let (mut t3, mut t4) = guess;
    let solve = |j: &Matrix2<T>, b: Vector2<T>| {
        let m = DMatrix::from_column_slice(2, 2, j.as_slice());
        let v = DVector::from_column_slice(b.as_slice());
        m.lu().solve(&v).map(|x| Vector2::new(x[0], x[1]))
    };
    for _ in 0..50 {
        let (f, j, _, _) = loop_eq(sc2, t3, t4);
        let dx = solve(&j, -f)?;
        t3 += dx.x;
        t4 += dx.y;
        if dx.x.abs() < tol && dx.y.abs() < tol {
            let (_, j, s3, s4) = loop_eq(sc2, t3, t4);
            let (w3, w4, al3, al4) = rates_from_j(solve, &j, sc2, s3, s4, w2, al2)?;
            return Some(FourBarOut {
                t3,
                t4,
                w3,
                w4,
                al3,
                al4,
            });
        }
    }
    None
}
