//! Baselines the generated code is measured against (benchmarks and report
//! only; nothing here is in the library).
//!
//! The four-bar of `scenes::FourBar`: ground `d` from O2 = (0, 0) to O4 = (d, 0),
//! crank `a` at angle `t2`, coupler `b`, rocker `c`, B on the left of A -> O4.
//! Every baseline returns the same [`FourBarOut`]: link angles `t3`, `t4`
//! (rad), angular velocities `w3`, `w4` (rad/s) and accelerations `al3`,
//! `al4` (rad/s^2), for crank speed `w2` and acceleration `al2`.
//!
//! The Stephenson III six-bar of `examples/common/stephenson.rs` (a triad
//! driven by link 6): Newton-Raphson on its whole loop closure in the four
//! unknown link angles, with nalgebra's fixed-size and heap LU
//! ([`stephenson_newton_fixed`], [`stephenson_newton_heap`]).
//!
//! The five-bar robot given its end point (`scenes::FiveBarIk`): Newton on
//! the two arms' loop closure in the motor and distal angles, with
//! nalgebra's fixed-size LU ([`five_bar_ik_newton`]), the usual numerical
//! inverse kinematics.
#![allow(dead_code)]

use nalgebra::{DMatrix, DVector, Matrix2, RealField, SMatrix, SVector, Vector2};

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

/// Dimensions (m) of the offset slider-crank of `scenes::SliderCrank`: crank
/// about O = (0, 0), connecting rod, slide line `y = SLIDER_OFFSET` along +x.
pub const SLIDER_CRANK: f64 = 0.1;
/// Connecting rod length (m).
pub const SLIDER_ROD: f64 = 0.4;
/// Height of the slide line (m).
pub const SLIDER_OFFSET: f64 = 0.02;

/// The offset slider-crank's outputs: the slider pin B (m), its velocity
/// (m/s) and acceleration (m/s^2), the rod's angle `t3` (rad, from +x,
/// counter-clockwise), rate `w3` (rad/s) and acceleration `al3` (rad/s^2).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SliderCrankOut<T> {
    pub b: (T, T),
    pub vb: (T, T),
    pub ab: (T, T),
    pub t3: T,
    pub w3: T,
    pub al3: T,
}

/// The offset slider-crank in closed form as one would write it by hand
/// for this one mechanism (B ahead of A along +x): A from the crank angle,
/// the rod's rise `dy = e - A.y` fixed by the line, its run
/// `dx = sqrt(L^2 - dy^2)`; the line holds B's vertical velocity and
/// acceleration at zero, so `w3 = -vA.y / dx` and
/// `al3 = (w3^2 dy - aA.y) / dx`; one `sin_cos`, one `sqrt`, one `atan2`,
/// one division; no error checks (NaN when the rod cannot reach the line).
#[inline(always)]
pub fn slider_crank_closed_form<T: F>(t2: T, w2: T, al2: T) -> SliderCrankOut<T> {
    let (r, l, e) = (T::c(SLIDER_CRANK), T::c(SLIDER_ROD), T::c(SLIDER_OFFSET));
    let (s2, c2) = t2.sin_cos();
    let (ax, ay) = (r * c2, r * s2);
    let dy = e - ay;
    let dx = (l * l - dy * dy).sqrt();
    let idx = T::one() / dx;
    // vA = w2 perp(A); vB = vA + w3 perp(B - A), vB.y = 0.
    let (vax, vay) = (-w2 * ay, w2 * ax);
    let w3 = -vay * idx;
    // aA = al2 perp(A) - w2^2 A; aB = aA + al3 perp(B - A) - w3^2 (B - A), aB.y = 0.
    let w22 = w2 * w2;
    let (aax, aay) = (-al2 * ay - w22 * ax, al2 * ax - w22 * ay);
    let w32 = w3 * w3;
    let al3 = (w32 * dy - aay) * idx;
    SliderCrankOut {
        b: (ax + dx, e),
        vb: (vax - w3 * dy, T::zero()),
        ab: (aax - al3 * dy - w32 * dx, T::zero()),
        t3: dy.atan2(dx),
        w3,
        al3,
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

// ---------------------------------------------------------------------------
// The Stephenson III six-bar of `examples/common/stephenson.rs` (m): the
// triad's loop closure solved as one system, as a run-time solver would.

/// Ground pivot of crank2 (m).
pub const ST_O2: (f64, f64) = (0.0, 0.0);
/// Ground pivot of the rocker (m).
pub const ST_O4: (f64, f64) = (0.30, 0.0);
/// Ground pivot of link 6, the driven link (m).
pub const ST_O6: (f64, f64) = (0.05, 0.42);
/// Lengths (m): crank2 O2-A, rocker O4-B, link5 C-P, coupler A-B, link6 O6-C.
pub const ST_L: [f64; 5] = [0.08, 0.20, 0.28, 0.26, 0.24];
/// P on the coupler: 0.15 m from A, 40 deg counter-clockwise from A -> B.
pub const ST_AP: (f64, f64) = (0.15, 40.0);

/// Newton's stopping rule for the Stephenson baselines: the iteration stops
/// after the first step whose largest component is below this (rad); with
/// quadratic convergence the error left is then at the rounding level.
pub const ST_TOL: f64 = 1e-12;
/// Iteration limit of the Stephenson baselines (`None` beyond it).
pub const ST_MAX_ITER: u32 = 50;

/// Angles (rad), rates (rad/s) and accelerations (rad/s^2) of crank2,
/// rocker, link5 and the coupler (in that order: the legs from `O2`, `O4`,
/// `C`, then the ternary link's axis A -> B), and the Newton iterations
/// the position took.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StephensonOut<T> {
    pub q: [T; 4],
    pub w: [T; 4],
    pub al: [T; 4],
    pub iterations: u32,
}

/// The loop closure `F(q) = 0` of the six-bar at link 6's angle `phi`, as
/// two vector equations (B reached from O2 through A and from O4; P reached
/// from O2 through A and from O6 through C):
///
/// ```text
/// O2 + l1 e(q0) + ab e(q3)          - l2 e(q1) - O4 = 0
/// O2 + l1 e(q0) + u e(q3) + v perp(e(q3)) - l3 e(q2) - C(phi) = 0
/// ```
///
/// Holds the residual (rows x, y of each equation), the Jacobian `dF/dq`
/// (row-major) and the signed rotating arms `s_i r_i` of each equation (for
/// the centripetal terms).
struct StLoop<T> {
    /// Residual (m).
    f: [T; 4],
    /// Jacobian (m/rad).
    j: [[T; 4]; 4],
    /// Signed arms per equation and unknown (`[equation][unknown]`, zero
    /// where the unknown is absent).
    arm: [[(T, T); 4]; 2],
}

#[inline(always)]
fn st_loop<T: F>(c: (T, T), q: &[T; 4]) -> StLoop<T> {
    let [l1, l2, l3, ab, _] = ST_L.map(T::c);
    let d = ST_AP.1.to_radians();
    let (u, v) = (T::c(ST_AP.0 * d.cos()), T::c(ST_AP.0 * d.sin()));
    let e = |x: T| {
        let (s, c) = x.sin_cos();
        (c, s)
    };
    let (e1, e2, e3, e4) = (e(q[0]), e(q[1]), e(q[2]), e(q[3]));
    let z = (T::zero(), T::zero());
    let r1 = (l1 * e1.0, l1 * e1.1);
    let r4b = (ab * e4.0, ab * e4.1);
    let r4p = (u * e4.0 - v * e4.1, u * e4.1 + v * e4.0);
    let r2 = (-l2 * e2.0, -l2 * e2.1);
    let r3 = (-l3 * e3.0, -l3 * e3.1);
    let (o2, o4) = (
        (T::c(ST_O2.0), T::c(ST_O2.1)),
        (T::c(ST_O4.0), T::c(ST_O4.1)),
    );
    let f = [
        o2.0 + r1.0 + r4b.0 + r2.0 - o4.0,
        o2.1 + r1.1 + r4b.1 + r2.1 - o4.1,
        o2.0 + r1.0 + r4p.0 + r3.0 - c.0,
        o2.1 + r1.1 + r4p.1 + r3.1 - c.1,
    ];
    // d/dx of a rotating arm r(x) is perp(r) = (-r.y, r.x).
    let arm = [[r1, r2, z, r4b], [r1, z, r3, r4p]];
    let mut j = [[T::zero(); 4]; 4];
    for (k, row) in arm.iter().enumerate() {
        for (i, r) in row.iter().enumerate() {
            j[2 * k][i] = -r.1;
            j[2 * k + 1][i] = r.0;
        }
    }
    StLoop { f, j, arm }
}

/// Link 6's tip `C`, its velocity and its acceleration at `phi` (rad),
/// `phi'` (rad/s), `phi''` (rad/s^2).
#[inline(always)]
fn st_c<T: F>(phi: T, w6: T, al6: T) -> [(T, T); 3] {
    let l6 = T::c(ST_L[4]);
    let (s, c) = phi.sin_cos();
    let r = (l6 * c, l6 * s);
    [
        (T::c(ST_O6.0) + r.0, T::c(ST_O6.1) + r.1),
        (-w6 * r.1, w6 * r.0),
        (-al6 * r.1 - w6 * w6 * r.0, al6 * r.0 - w6 * w6 * r.1),
    ]
}

/// The right-hand sides of the velocity and acceleration systems:
/// `J w = (0, 0, vC)` and `J al = sum_i s_i w_i^2 r_i + (0, 0, aC)` (the
/// loop closure differentiated once and twice).
#[inline(always)]
fn st_rhs<T: F>(l: &StLoop<T>, vc: (T, T), ac: (T, T), w: Option<&[T; 4]>) -> [T; 4] {
    let Some(w) = w else {
        return [T::zero(), T::zero(), vc.0, vc.1];
    };
    let mut out = [T::zero(), T::zero(), ac.0, ac.1];
    for (k, row) in l.arm.iter().enumerate() {
        for (i, r) in row.iter().enumerate() {
            let w2 = w[i] * w[i];
            out[2 * k] += w2 * r.0;
            out[2 * k + 1] += w2 * r.1;
        }
    }
    out
}

/// Newton-Raphson on the six-bar's loop closure in its four unknown angles,
/// from `guess` (the previous step's angles, as a real-time loop has them),
/// until a step is below [`ST_TOL`] (at most [`ST_MAX_ITER`] iterations),
/// then the velocity and acceleration systems with the converged Jacobian;
/// every linear solve by `solve` (`None`: singular). `phi` (rad), `w6`
/// (rad/s), `al6` (rad/s^2) are link 6's angle and its derivatives.
#[inline(always)]
fn st_newton<T: F>(
    solve: impl Fn(&[[T; 4]; 4], [T; 4]) -> Option<[T; 4]>,
    phi: T,
    w6: T,
    al6: T,
    guess: [T; 4],
) -> Option<StephensonOut<T>> {
    let [c, vc, ac] = st_c(phi, w6, al6);
    let tol = T::c(ST_TOL);
    let mut q = guess;
    for it in 1..=ST_MAX_ITER {
        let l = st_loop(c, &q);
        let dx = solve(&l.j, l.f.map(|x| -x))?;
        let mut big = T::zero();
        for (qi, di) in q.iter_mut().zip(dx) {
            *qi += di;
            big = big.max(di.abs());
        }
        if !big.is_finite() {
            return None;
        }
        if big < tol {
            let l = st_loop(c, &q);
            let w = solve(&l.j, st_rhs(&l, vc, ac, None))?;
            let al = solve(&l.j, st_rhs(&l, vc, ac, Some(&w)))?;
            return Some(StephensonOut {
                q,
                w,
                al,
                iterations: it,
            });
        }
    }
    None
}

/// [`st_newton`] with nalgebra's fixed-size `SMatrix<T, 4, 4>` LU (on the
/// stack).
#[inline(always)]
pub fn stephenson_newton_fixed<T: F>(
    phi: T,
    w6: T,
    al6: T,
    guess: [T; 4],
) -> Option<StephensonOut<T>> {
    let solve = |j: &[[T; 4]; 4], b: [T; 4]| {
        let m = SMatrix::<T, 4, 4>::from_fn(|r, c| j[r][c]);
        let x = m.lu().solve(&SVector::<T, 4>::from(b))?;
        Some([x[0], x[1], x[2], x[3]])
    };
    st_newton(solve, phi, w6, al6, guess)
}

/// [`st_newton`] with heap `DMatrix` / `DVector` and their LU (sized at run
/// time, allocating at every solve), as a general multibody solver does it.
#[inline(never)]
pub fn stephenson_newton_heap<T: F>(
    phi: T,
    w6: T,
    al6: T,
    guess: [T; 4],
) -> Option<StephensonOut<T>> {
    let solve = |j: &[[T; 4]; 4], b: [T; 4]| {
        let m = DMatrix::<T>::from_fn(4, 4, |r, c| j[r][c]);
        let x = m.lu().solve(&DVector::from_column_slice(&b))?;
        Some([x[0], x[1], x[2], x[3]])
    };
    st_newton(solve, phi, w6, al6, guess)
}

/// The joints `A`, `B`, `P` (m) for the angles `q` of [`StephensonOut`].
pub fn stephenson_joints(q: &[f64; 4]) -> [(f64, f64); 3] {
    let [l1, _, _, ab, _] = ST_L;
    let d = ST_AP.1.to_radians();
    let (u, v) = (ST_AP.0 * d.cos(), ST_AP.0 * d.sin());
    let a = (ST_O2.0 + l1 * q[0].cos(), ST_O2.1 + l1 * q[0].sin());
    let (c4, s4) = (q[3].cos(), q[3].sin());
    [
        a,
        (a.0 + ab * c4, a.1 + ab * s4),
        (a.0 + u * c4 - v * s4, a.1 + u * s4 + v * c4),
    ]
}

/// The five-bar robot's base, proximal and distal lengths (m).
pub const IK_BASE: f64 = 0.08;
pub const IK_PROX: f64 = 0.1;
pub const IK_DIST: f64 = 0.16;
/// Newton's stop for the five-bar: the first step below this (rad), at
/// most `IK_MAX_ITER` steps.
pub const IK_TOL: f64 = 1e-13;
pub const IK_MAX_ITER: u32 = 20;

/// The five-bar robot's inverse kinematics by Newton: the angles `[q1, t3, q2, t4]`, their rates and
/// accelerations, and the iterations taken.
pub struct FiveBarIkOut {
    pub q: [f64; 4],
    pub w: [f64; 4],
    pub al: [f64; 4],
    pub iterations: u32,
}

/// Newton on the two arms' loop closure at end point `p` (m) from
/// `guess`, then the rates and accelerations for the end point's velocity
/// `v` (m/s) and acceleration `a` (m/s^2) with the converged Jacobian.
pub fn five_bar_ik_newton(
    p: (f64, f64),
    v: (f64, f64),
    a: (f64, f64),
    guess: [f64; 4],
) -> Option<FiveBarIkOut> {
    let r = [IK_PROX, IK_DIST, IK_PROX, IK_DIST];
    let jac = |q: &[f64; 4]| {
        let (s, c): (Vec<f64>, Vec<f64>) = q.iter().map(|a| a.sin_cos()).unzip();
        let mut j = SMatrix::<f64, 4, 4>::zeros();
        for k in 0..2 {
            j[(0, k)] = -r[k] * s[k];
            j[(1, k)] = r[k] * c[k];
            j[(2, k + 2)] = -r[k + 2] * s[k + 2];
            j[(3, k + 2)] = r[k + 2] * c[k + 2];
        }
        (j, s, c)
    };
    let mut q = guess;
    let mut iterations = 0;
    loop {
        let (j, s, c) = jac(&q);
        let f = SVector::<f64, 4>::new(
            r[0] * c[0] + r[1] * c[1] - p.0,
            r[0] * s[0] + r[1] * s[1] - p.1,
            IK_BASE + r[2] * c[2] + r[3] * c[3] - p.0,
            r[2] * s[2] + r[3] * s[3] - p.1,
        );
        let step = j.lu().solve(&f)?;
        for k in 0..4 {
            q[k] -= step[k];
        }
        iterations += 1;
        if step.amax() < IK_TOL {
            break;
        }
        if iterations >= IK_MAX_ITER {
            return None;
        }
    }
    let (j, s, c) = jac(&q);
    let lu = j.lu();
    let w = lu.solve(&SVector::<f64, 4>::new(v.0, v.1, v.0, v.1))?;
    let centripetal = |k: usize| (r[k] * c[k] * w[k] * w[k], r[k] * s[k] * w[k] * w[k]);
    let (c0, c1, c2, c3) = (
        centripetal(0),
        centripetal(1),
        centripetal(2),
        centripetal(3),
    );
    let rhs = SVector::<f64, 4>::new(
        a.0 + c0.0 + c1.0,
        a.1 + c0.1 + c1.1,
        a.0 + c2.0 + c3.0,
        a.1 + c2.1 + c3.1,
    );
    let al = lu.solve(&rhs)?;
    Some(FiveBarIkOut {
        q,
        w: [w[0], w[1], w[2], w[3]],
        al: [al[0], al[1], al[2], al[3]],
        iterations,
    })
}
