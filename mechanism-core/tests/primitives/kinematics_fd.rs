//! Rates are the time derivatives of positions, and positions close their
//! loops: for every primitive (crank, slider, actuator, link point, and the
//! groups RRR, RRP, RPR, PRP, RPP, in both modes where a mode exists), with
//! moving known points (`p(t) = p0 + v0 t + a0 t^2 / 2`) and guides carried by
//! translating and rotating bodies.
//!
//! - velocity vs the central finite difference of position in time;
//! - acceleration vs the central finite difference of velocity;
//! - loop-closure residuals of positions to a few rounding units.
//!
//! Samples are built from a known closed configuration (so they assemble) and
//! ill-conditioned ones (relative determinant < 0.1) are rejected with
//! `prop_assume!`. Sizes are of order 1 (lengths 0.2..3 L, speeds <= 1 L/s,
//! angular speeds <= 2 rad/s), so one absolute-plus-relative scale per family,
//! `1 + max |analytic value|`, is the natural yardstick.
//!
//! Tolerances (per family, relative to that scale), and why:
//!
//! - f64, central differences, `h = 1e-5`: truncation is `h^2 / 6 |x'''|`;
//!   with relative determinants >= 0.1 and rates <= 10/s (see `RATE_MAX`),
//!   `|x'''| <~ 1e3` and truncation `<~ 2e-8`; rounding of the positions is
//!   amplified by `1 / h`: `~1e-16 * 10 / 1e-5 = 1e-10`. Observed worst case
//!   over these samples: ~1.5e-8. Tolerance `1e-6`: 60x above that, and still
//!   1e6 below a real formula mistake (a missing Coriolis term, a sign, a factor
//!   2 are errors of order 1; `finite_differences_catch_a_missing_coriolis_term`
//!   shows one caught).
//! - f32, five-point differences, `h = 2.5e-3`: with only ~7 digits, the
//!   central difference's best step leaves ~1e-2 (truncation and rounding
//!   balance near `h ~ 5e-3`; measured: up to 1e-2), too coarse to be a useful
//!   test, so f32 uses the fourth-order stencil: truncation `h^4 / 30 |x^(5)|
//!   ~ 1e-7`, rounding `1.5 eps_f32 |x| / h ~ 1.5 * 1.2e-7 * 3 / 2.5e-3 = 2e-4`.
//!   Observed worst case: ~2e-4. Tolerance `2e-3` (10x margin), looser than f64
//!   only because f32 rounding divided by `h` dominates.
//! - f32 against f64 at the same instant: `1e-4` (eps_f32 1.2e-7, times the
//!   condition number <= 10, times ~10 roundings is ~1e-5; observed < 1e-5).
//! - loop closure: `16 eps * scale` (scale = the largest coordinate, length or
//!   displacement involved): each closed form is a handful of roundings;
//!   observed residuals are at most ~4 eps * scale in both precisions.

use mechanism_core::driver::{actuator, crank, slider};
use mechanism_core::dyad::{prp, rpp, rpr, rrp, rrr};
use mechanism_core::guide::{Line, LineAcceleration, LineVelocity};
use mechanism_core::{link, Error, Mode, Point2, Real, Vector2};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

type V = Vector2<f64>;

// ---------------------------------------------------------------- inputs --

fn lit<T: Real>(x: f64) -> T {
    T::lit(x)
}
fn vec_t<T: Real>(v: V) -> Vector2<T> {
    Vector2::new(T::lit(v.x), T::lit(v.y))
}
fn pt_t<T: Real>(v: V) -> Point2<T> {
    Point2::new(T::lit(v.x), T::lit(v.y))
}
fn wide_v<T: Real>(v: &Vector2<T>) -> V {
    V::new(v.x.as_f64(), v.y.as_f64())
}
fn wide_p<T: Real>(p: &Point2<T>) -> V {
    wide_v(&p.coords)
}
fn unit(theta: f64) -> V {
    V::new(theta.cos(), theta.sin())
}
fn perp(v: V) -> V {
    V::new(-v.y, v.x)
}
fn cross(a: V, b: V) -> f64 {
    a.x * b.y - a.y * b.x
}

/// Motion of a known point: `p(t) = p0 + v0 t + a0 t^2 / 2`; `fixed` points are
/// passed as `None` (and then have `v0 = a0 = 0`).
#[derive(Clone, Copy, Debug)]
struct Motion {
    v0: V,
    a0: V,
    fixed: bool,
}

impl Motion {
    fn at(&self, p0: V, t: f64) -> V {
        p0 + self.v0 * t + self.a0 * (0.5 * t * t)
    }
    fn vel<T: Real>(&self, t: f64) -> Option<Vector2<T>> {
        (!self.fixed).then(|| vec_t(self.v0 + self.a0 * t))
    }
    fn acc<T: Real>(&self) -> Option<Vector2<T>> {
        (!self.fixed).then(|| vec_t(self.a0))
    }
}

fn coord() -> impl Strategy<Value = f64> {
    -1.0..1.0f64
}
fn vector(r: f64) -> impl Strategy<Value = V> {
    (-r..r, -r..r).prop_map(|(x, y)| V::new(x, y))
}
fn angle() -> impl Strategy<Value = f64> {
    -std::f64::consts::PI..std::f64::consts::PI
}
fn mode() -> impl Strategy<Value = Mode> {
    prop_oneof![Just(Mode::Plus), Just(Mode::Minus)]
}
fn motion() -> impl Strategy<Value = Motion> {
    (0..4u8, vector(1.0), vector(1.0)).prop_map(|(k, v0, a0)| {
        if k == 0 {
            Motion {
                v0: V::zeros(),
                a0: V::zeros(),
                fixed: true,
            }
        } else {
            Motion {
                v0,
                a0,
                fixed: false,
            }
        }
    })
}

/// How a guide's body moves.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Carry {
    /// Fixed guide: `gv = ga = None`.
    Fixed,
    /// Constant velocity and spin: `ga = None` (zero accelerations).
    Steady,
    /// General: both given.
    Accelerating,
}

/// A guide on a body: origin `o0 + vo t + ao t^2/2`, angle
/// `theta0 + w0 t + al0 t^2/2`.
#[derive(Clone, Copy, Debug)]
struct Guide {
    o0: V,
    theta0: f64,
    carry: Carry,
    vo: V,
    ao: V,
    w0: f64,
    al0: f64,
}

impl Guide {
    fn dir0(&self) -> V {
        unit(self.theta0)
    }
    fn line<T: Real>(&self, t: f64) -> Line<T> {
        let origin = self.o0 + self.vo * t + self.ao * (0.5 * t * t);
        let theta = self.theta0 + self.w0 * t + 0.5 * self.al0 * t * t;
        Line {
            origin: pt_t(origin),
            dir: vec_t(unit(theta)),
        }
    }
    fn gv<T: Real>(&self, t: f64) -> Option<LineVelocity<T>> {
        (self.carry != Carry::Fixed).then(|| LineVelocity {
            v_origin: vec_t(self.vo + self.ao * t),
            omega: lit(self.w0 + self.al0 * t),
        })
    }
    fn ga<T: Real>(&self) -> Option<LineAcceleration<T>> {
        (self.carry == Carry::Accelerating).then(|| LineAcceleration {
            a_origin: vec_t(self.ao),
            alpha: lit(self.al0),
        })
    }
    fn omega(&self, t: f64) -> f64 {
        self.w0 + self.al0 * t
    }
}

fn guide() -> impl Strategy<Value = Guide> {
    (
        vector(2.0),
        angle(),
        prop_oneof![
            Just(Carry::Fixed),
            Just(Carry::Steady),
            Just(Carry::Accelerating)
        ],
        vector(1.0),
        vector(1.0),
        -2.0..2.0f64,
        -2.0..2.0f64,
    )
        .prop_map(|(o0, theta0, carry, vo, ao, w0, al0)| match carry {
            Carry::Fixed => Guide {
                o0,
                theta0,
                carry,
                vo: V::zeros(),
                ao: V::zeros(),
                w0: 0.0,
                al0: 0.0,
            },
            Carry::Steady => Guide {
                o0,
                theta0,
                carry,
                vo,
                ao: V::zeros(),
                w0,
                al0: 0.0,
            },
            Carry::Accelerating => Guide {
                o0,
                theta0,
                carry,
                vo,
                ao,
                w0,
                al0,
            },
        })
}

/// A scalar input `x0 + v0 t + a0 t^2 / 2` (crank angle, slider displacement,
/// actuator length).
#[derive(Clone, Copy, Debug)]
struct Input {
    x0: f64,
    v0: f64,
    a0: f64,
}

impl Input {
    fn x(&self, t: f64) -> f64 {
        self.x0 + self.v0 * t + 0.5 * self.a0 * t * t
    }
    fn v(&self, t: f64) -> f64 {
        self.v0 + self.a0 * t
    }
}

// ------------------------------------------------------------- snapshots --

/// What a primitive reports at one instant, widened to f64.
#[derive(Debug, Default)]
struct Snapshot {
    /// Position-level scalars (coordinates, displacements), differenced directly.
    lin: Vec<f64>,
    /// Directions fixed on links; their angle is differenced as
    /// `atan2(cross(d(-h), d(h)), dot(d(-h), d(h)))`, free of wrap-around.
    dirs: Vec<V>,
    /// Analytic first derivatives of `lin` then of the angles of `dirs`.
    rate: Vec<f64>,
    /// Analytic second derivatives, in the same order.
    acc: Vec<f64>,
}

impl Snapshot {
    fn lin_v(&mut self, v: V) {
        self.lin.extend([v.x, v.y]);
    }
    fn rate_v(&mut self, v: V) {
        self.rate.extend([v.x, v.y]);
    }
    fn acc_v(&mut self, v: V) {
        self.acc.extend([v.x, v.y]);
    }
}

trait Case: core::fmt::Debug {
    /// Positions and analytic rates at time `t`, computed in `T`.
    fn snapshot<T: Real>(&self, t: f64) -> Result<Snapshot, Error<T>>;
    /// Largest loop-closure residual at `t = 0` and the scale it is judged by
    /// (both L), computed in f64 from the `T` inputs and outputs.
    fn residual<T: Real>(&self) -> Result<(f64, f64), Error<T>>;
}

fn max_abs(xs: &[f64]) -> f64 {
    xs.iter().fold(0.0, |m, x| m.max(x.abs()))
}

/// Derivative estimate at 0 from samples at `-2h, -h, h, 2h`: the central
/// difference `(x(h) - x(-h)) / 2h` (error `h^2 x'''(0) / 6`), or with `fourth`
/// the five-point stencil `(8 (x(h) - x(-h)) - (x(2h) - x(-2h))) / 12h` (error
/// `h^4 x^(5)(0) / 30`).
fn stencil(m2: f64, m1: f64, p1: f64, p2: f64, h: f64, fourth: bool) -> f64 {
    if fourth {
        (8.0 * (p1 - m1) - (p2 - m2)) / (12.0 * h)
    } else {
        (p1 - m1) / (2.0 * h)
    }
}

/// Angle turned from `a` to `b` (rad), free of wrap-around.
fn turn(a: V, b: V) -> f64 {
    cross(a, b).atan2(a.dot(&b))
}

/// Checks velocity and acceleration against finite differences with step `h`
/// (central, or five-point with `fourth`); `tol` relative to
/// `1 + max |analytic|` of each family.
fn check_fd<T: Real, C: Case>(
    case: &C,
    h: f64,
    fourth: bool,
    tol: f64,
) -> Result<(), TestCaseError> {
    let run = |t| {
        case.snapshot::<T>(t)
            .map_err(|e| TestCaseError::fail(format!("{case:?} at t = {t}: {e}")))
    };
    let (m1, s0, p1) = (run(-h)?, run(0.0)?, run(h)?);
    let (m2, p2) = if fourth {
        (run(-2.0 * h)?, run(2.0 * h)?)
    } else {
        (Snapshot::default(), Snapshot::default())
    };
    let get = |v: &[f64], i: usize| v.get(i).copied().unwrap_or(0.0);
    let mut fd_rate: Vec<f64> = (0..s0.lin.len())
        .map(|i| {
            stencil(
                get(&m2.lin, i),
                m1.lin[i],
                p1.lin[i],
                get(&p2.lin, i),
                h,
                fourth,
            )
        })
        .collect();
    fd_rate.extend((0..s0.dirs.len()).map(|i| {
        // Angles measured from the direction at t = 0.
        let ang = |s: &Snapshot| s.dirs.get(i).map_or(0.0, |d| turn(s0.dirs[i], *d));
        stencil(ang(&m2), ang(&m1), ang(&p1), ang(&p2), h, fourth)
    }));
    let fd_acc: Vec<f64> = (0..s0.acc.len())
        .map(|i| {
            stencil(
                get(&m2.rate, i),
                m1.rate[i],
                p1.rate[i],
                get(&p2.rate, i),
                h,
                fourth,
            )
        })
        .collect();
    let compare = |what: &str, fd: &[f64], exact: &[f64]| -> Result<(), TestCaseError> {
        prop_assert_eq!(fd.len(), exact.len());
        let scale = 1.0 + max_abs(exact);
        for (i, (f, e)) in fd.iter().zip(exact).enumerate() {
            prop_assert!(
                (f - e).abs() <= tol * scale,
                "{} {}: finite difference {} vs analytic {} (error {:e}, allowed {:e}) for {:?}",
                what,
                i,
                f,
                e,
                (f - e).abs(),
                tol * scale,
                case
            );
        }
        Ok(())
    };
    compare("velocity", &fd_rate, &s0.rate)?;
    compare("acceleration", &fd_acc, &s0.acc)
}

/// Checks that the f32 results agree with the f64 ones to `tol` (relative to
/// `1 + max |value|` of each family).
fn check_f32_vs_f64<C: Case>(case: &C, tol: f64) -> Result<(), TestCaseError> {
    let a = case
        .snapshot::<f64>(0.0)
        .map_err(|e| TestCaseError::fail(format!("f64: {e}")))?;
    let b = case
        .snapshot::<f32>(0.0)
        .map_err(|e| TestCaseError::fail(format!("f32: {e}")))?;
    let mut a_lin = a.lin.clone();
    let mut b_lin = b.lin.clone();
    for (x, y) in a.dirs.iter().zip(&b.dirs) {
        a_lin.extend([x.x, x.y]);
        b_lin.extend([y.x, y.y]);
    }
    for (what, x, y) in [
        ("position", &a_lin, &b_lin),
        ("velocity", &a.rate, &b.rate),
        ("acceleration", &a.acc, &b.acc),
    ] {
        let scale = 1.0 + max_abs(x);
        for (i, (p, q)) in x.iter().zip(y.iter()).enumerate() {
            prop_assert!(
                (p - q).abs() <= tol * scale,
                "{} {}: f64 {} vs f32 {} for {:?}",
                what,
                i,
                p,
                q,
                case
            );
        }
    }
    Ok(())
}

/// Loop closure to `CLOSURE_EPS eps * scale` in both precisions.
fn check_closure<C: Case>(case: &C) -> Result<(), TestCaseError> {
    for (name, eps, got) in [
        ("f64", f64::EPSILON, case.residual::<f64>()),
        (
            "f32",
            f32::EPSILON as f64,
            case.residual::<f32>().map_err(Error::from),
        ),
    ] {
        let (res, scale) = got.map_err(|e| TestCaseError::fail(format!("{name}: {e}")))?;
        prop_assert!(
            res <= CLOSURE_EPS * eps * scale,
            "{}: residual {:e} > {} eps * {} for {:?}",
            name,
            res,
            CLOSURE_EPS,
            scale,
            case
        );
    }
    Ok(())
}

/// Loop-closure tolerance, in units of the scalar's epsilon times the scale.
const CLOSURE_EPS: f64 = 16.0;
const H64: f64 = 1e-5;
const TOL64: f64 = 1e-6;
const H32: f64 = 2.5e-3;
const TOL32: f64 = 2e-3;
const TOL_32_64: f64 = 1e-4;

/// Rates above `RATE_MAX` (1/s) or accelerations above `ACC_MAX` (1/s^2), for
/// sizes of order 1, mean the configuration changes within ~0.1 s (a guide
/// swinging a far point past a short link, nearly parallel guides turning
/// against each other): ill-conditioned in time, so the FD error estimates
/// above would not hold. Such samples are rejected like small determinants.
const RATE_MAX: f64 = 10.0;
const ACC_MAX: f64 = 100.0;

fn check_all<C: Case>(case: &C) -> Result<(), TestCaseError> {
    let s = case
        .snapshot::<f64>(0.0)
        .map_err(|e| TestCaseError::fail(format!("{case:?}: {e}")))?;
    if max_abs(&s.rate) > RATE_MAX || max_abs(&s.acc) > ACC_MAX {
        return Err(TestCaseError::reject("fast-changing configuration"));
    }
    check_fd::<f64, C>(case, H64, false, TOL64)?;
    check_fd::<f32, C>(case, H32, true, TOL32)?;
    check_f32_vs_f64(case, TOL_32_64)?;
    check_closure(case)
}

// ------------------------------------------------------------------ RRR --

#[derive(Clone, Copy, Debug)]
struct RrrCase {
    a0: V,
    ma: Motion,
    b0: V,
    mb: Motion,
    l1: f64,
    l2: f64,
    mode: Mode,
}

/// Two known points at distance `d` and lengths that close a triangle with a
/// margin: `l2` strictly inside `(|d - l1|, d + l1)`.
fn triangle() -> impl Strategy<Value = (V, V, f64, f64)> {
    (vector(2.0), 0.5..3.0f64, angle(), 0.5..3.0f64, 0.1..0.9f64).prop_map(|(a0, d, psi, l1, u)| {
        let lo = (d - l1).abs();
        let l2 = lo + u * (d + l1 - lo);
        (a0, a0 + unit(psi) * d, l1, l2)
    })
}

prop_compose! {
    fn rrr_case()((a0, b0, l1, l2) in triangle(), ma in motion(), mb in motion(), mode in mode())
        -> RrrCase {
        RrrCase { a0, ma, b0, mb, l1, l2, mode }
    }
}

/// `|cross(r1, r2)| / (|r1| |r2|)` of a closed RRR-like triangle, in f64.
fn rrr_conditioning(a: V, l1: f64, b: V, l2: f64, mode: Mode) -> f64 {
    match rrr::position(&Point2::from(a), l1, &Point2::from(b), l2, mode) {
        Ok(p) => cross(p.r1, p.r2).abs() / (p.r1.norm() * p.r2.norm()),
        Err(_) => 0.0,
    }
}

impl Case for RrrCase {
    fn snapshot<T: Real>(&self, t: f64) -> Result<Snapshot, Error<T>> {
        let a = pt_t::<T>(self.ma.at(self.a0, t));
        let b = pt_t::<T>(self.mb.at(self.b0, t));
        let pos = rrr::position(&a, lit(self.l1), &b, lit(self.l2), self.mode)?;
        let (va, vb) = (self.ma.vel::<T>(t), self.mb.vel::<T>(t));
        let vel = rrr::velocity(&pos, va.as_ref(), vb.as_ref())?;
        let (aa, ab) = (self.ma.acc::<T>(), self.mb.acc::<T>());
        let acc = rrr::acceleration(&pos, &vel, aa.as_ref(), ab.as_ref())?;
        let mut s = Snapshot::default();
        s.lin_v(wide_p(&pos.c));
        s.dirs.extend([wide_v(&pos.r1), wide_v(&pos.r2)]);
        s.rate_v(wide_v(&vel.vc));
        s.rate.extend([vel.omega1.as_f64(), vel.omega2.as_f64()]);
        s.acc_v(wide_v(&acc.ac));
        s.acc.extend([acc.alpha1.as_f64(), acc.alpha2.as_f64()]);
        Ok(s)
    }
    fn residual<T: Real>(&self) -> Result<(f64, f64), Error<T>> {
        let (a, b) = (pt_t::<T>(self.a0), pt_t::<T>(self.b0));
        let (l1, l2) = (lit::<T>(self.l1), lit::<T>(self.l2));
        let pos = rrr::position(&a, l1, &b, l2, self.mode)?;
        let c = wide_p(&pos.c);
        let (a, b) = (wide_p(&a), wide_p(&b));
        let res = [
            ((c - a).norm() - l1.as_f64()).abs(),
            ((c - b).norm() - l2.as_f64()).abs(),
            (wide_v(&pos.r1) - (c - a)).norm(),
            (wide_v(&pos.r2) - (c - b)).norm(),
        ];
        let scale = max_abs(&[a.x, a.y, b.x, b.y, l1.as_f64(), l2.as_f64()]);
        Ok((max_abs(&res), scale))
    }
}

// ------------------------------------------------------------------ RRP --

#[derive(Clone, Copy, Debug)]
struct RrpCase {
    a0: V,
    ma: Motion,
    l: f64,
    g: Guide,
    offset: f64,
    mode: Mode,
}

prop_compose! {
    /// `A` at signed distance `k = u l` (|u| <= 0.9, so the relative determinant
    /// `sqrt(1 - u^2) >= 0.43`) from the offset line, `t` along it.
    fn rrp_case()(l in 0.3..3.0f64, u in -0.9..0.9f64, t in -2.0..2.0f64, offset in coord(),
                  g in guide(), ma in motion(), mode in mode()) -> RrpCase {
        let d = g.dir0();
        let a0 = g.o0 + d * t + perp(d) * (offset + u * l);
        RrpCase { a0, ma, l, g, offset, mode }
    }
}

impl Case for RrpCase {
    fn snapshot<T: Real>(&self, t: f64) -> Result<Snapshot, Error<T>> {
        let a = pt_t::<T>(self.ma.at(self.a0, t));
        let g = self.g.line::<T>(t);
        let pos = rrp::position(&a, lit(self.l), &g, lit(self.offset), self.mode)?;
        let (va, gv) = (self.ma.vel::<T>(t), self.g.gv::<T>(t));
        let vel = rrp::velocity(&pos, &g, va.as_ref(), gv.as_ref())?;
        let (aa, ga) = (self.ma.acc::<T>(), self.g.ga::<T>());
        let acc = rrp::acceleration(&pos, &g, &vel, aa.as_ref(), gv.as_ref(), ga.as_ref())?;
        let mut s = Snapshot::default();
        s.lin_v(wide_p(&pos.c));
        s.lin.push(pos.s.as_f64());
        s.dirs.push(wide_v(&pos.r1));
        s.rate_v(wide_v(&vel.vc));
        s.rate.extend([vel.s_dot.as_f64(), vel.omega1.as_f64()]);
        s.acc_v(wide_v(&acc.ac));
        s.acc.extend([acc.s_ddot.as_f64(), acc.alpha1.as_f64()]);
        Ok(s)
    }
    fn residual<T: Real>(&self) -> Result<(f64, f64), Error<T>> {
        let a = pt_t::<T>(self.a0);
        let g = self.g.line::<T>(0.0);
        let (l, e) = (lit::<T>(self.l), lit::<T>(self.offset));
        let pos = rrp::position(&a, l, &g, e, self.mode)?;
        let (c, a) = (wide_p(&pos.c), wide_p(&a));
        let (o, d) = (wide_p(&g.origin), wide_v(&g.dir));
        let on_line = o + d * pos.s.as_f64() + perp(d) * e.as_f64();
        let res = [
            ((c - a).norm() - l.as_f64()).abs(),
            (c - on_line).norm(),
            (wide_v(&pos.r1) - (c - a)).norm(),
        ];
        let scale = max_abs(&[a.x, a.y, o.x, o.y, l.as_f64(), e.as_f64(), c.x, c.y]);
        Ok((max_abs(&res), scale))
    }
}

// ------------------------------------------------------------------ RPR --

#[derive(Clone, Copy, Debug)]
struct RprCase {
    a0: V,
    ma: Motion,
    b0: V,
    mb: Motion,
    offset: f64,
    mode: Mode,
}

prop_compose! {
    /// `A = B + s u + e perp(u)` with `0.3 <= |s| <= 2.5`, `|e| <= 1`: relative
    /// determinant `|s| / |A - B| >= 0.28`.
    fn rpr_case()(b0 in vector(2.0), s in 0.3..2.5f64, offset in coord(), phi in angle(),
                  ma in motion(), mb in motion(), mode in mode()) -> RprCase {
        let u = unit(phi);
        let a0 = b0 + u * (mode.sign::<f64>() * s) + perp(u) * offset;
        RprCase { a0, ma, b0, mb, offset, mode }
    }
}

impl Case for RprCase {
    fn snapshot<T: Real>(&self, t: f64) -> Result<Snapshot, Error<T>> {
        let a = pt_t::<T>(self.ma.at(self.a0, t));
        let b = pt_t::<T>(self.mb.at(self.b0, t));
        let pos = rpr::position(&a, &b, lit(self.offset), self.mode)?;
        let (va, vb) = (self.ma.vel::<T>(t), self.mb.vel::<T>(t));
        let vel = rpr::velocity(&pos, &a, &b, va.as_ref(), vb.as_ref())?;
        let (aa, ab) = (self.ma.acc::<T>(), self.mb.acc::<T>());
        let acc = rpr::acceleration(&pos, &a, &b, &vel, aa.as_ref(), ab.as_ref())?;
        let mut s = Snapshot::default();
        s.lin.push(pos.s.as_f64());
        s.dirs.push(wide_v(&pos.axis));
        s.rate.extend([vel.s_dot.as_f64(), vel.omega.as_f64()]);
        s.acc.extend([acc.s_ddot.as_f64(), acc.alpha.as_f64()]);
        Ok(s)
    }
    fn residual<T: Real>(&self) -> Result<(f64, f64), Error<T>> {
        let (a, b) = (pt_t::<T>(self.a0), pt_t::<T>(self.b0));
        let e = lit::<T>(self.offset);
        let pos = rpr::position(&a, &b, e, self.mode)?;
        let (a, b, u) = (wide_p(&a), wide_p(&b), wide_v(&pos.axis));
        let closed = b + u * pos.s.as_f64() + perp(u) * e.as_f64();
        let res = [(a - closed).norm(), (u.norm() - 1.0).abs() * (a - b).norm()];
        let scale = max_abs(&[a.x, a.y, b.x, b.y, e.as_f64()]);
        Ok((max_abs(&res), scale))
    }
}

// ------------------------------------------------------------------ PRP --

#[derive(Clone, Copy, Debug)]
struct PrpCase {
    g1: Guide,
    offset1: f64,
    g2: Guide,
    offset2: f64,
}

prop_compose! {
    fn prp_case()(g1 in guide(), offset1 in coord(), g2 in guide(), offset2 in coord())
        -> PrpCase {
        PrpCase { g1, offset1, g2, offset2 }
    }
}

impl PrpCase {
    /// `|sin|` of the angle between the guides (the relative determinant).
    fn conditioning(&self) -> f64 {
        cross(self.g1.dir0(), self.g2.dir0()).abs()
    }
}

impl Case for PrpCase {
    fn snapshot<T: Real>(&self, t: f64) -> Result<Snapshot, Error<T>> {
        let (g1, g2) = (self.g1.line::<T>(t), self.g2.line::<T>(t));
        let (e1, e2) = (lit::<T>(self.offset1), lit::<T>(self.offset2));
        let pos = prp::position(&g1, e1, &g2, e2)?;
        let (gv1, gv2) = (self.g1.gv::<T>(t), self.g2.gv::<T>(t));
        let vel = prp::velocity(&pos, &g1, &g2, gv1.as_ref(), gv2.as_ref())?;
        let (ga1, ga2) = (self.g1.ga::<T>(), self.g2.ga::<T>());
        let acc = prp::acceleration(
            &pos,
            &g1,
            &g2,
            &vel,
            gv1.as_ref(),
            ga1.as_ref(),
            gv2.as_ref(),
            ga2.as_ref(),
        )?;
        let mut s = Snapshot::default();
        s.lin_v(wide_p(&pos.c));
        s.lin.extend([pos.s1.as_f64(), pos.s2.as_f64()]);
        s.rate_v(wide_v(&vel.vc));
        s.rate.extend([vel.s1_dot.as_f64(), vel.s2_dot.as_f64()]);
        s.acc_v(wide_v(&acc.ac));
        s.acc.extend([acc.s1_ddot.as_f64(), acc.s2_ddot.as_f64()]);
        Ok(s)
    }
    fn residual<T: Real>(&self) -> Result<(f64, f64), Error<T>> {
        let (g1, g2) = (self.g1.line::<T>(0.0), self.g2.line::<T>(0.0));
        let (e1, e2) = (lit::<T>(self.offset1), lit::<T>(self.offset2));
        let pos = prp::position(&g1, e1, &g2, e2)?;
        let c = wide_p(&pos.c);
        let at = |g: &Line<T>, s: T, e: T| {
            wide_p(&g.origin) + wide_v(&g.dir) * s.as_f64() + perp(wide_v(&g.dir)) * e.as_f64()
        };
        let res = [
            (c - at(&g1, pos.s1, e1)).norm(),
            (c - at(&g2, pos.s2, e2)).norm(),
        ];
        let scale = max_abs(&[
            c.x,
            c.y,
            g1.origin.x.as_f64(),
            g1.origin.y.as_f64(),
            g2.origin.x.as_f64(),
            g2.origin.y.as_f64(),
            pos.s1.as_f64(),
            pos.s2.as_f64(),
            e1.as_f64(),
            e2.as_f64(),
        ]);
        // The solve divides by the determinant: rounding is amplified by 1/|det|.
        Ok((max_abs(&res) * self.conditioning(), scale))
    }
}

// ------------------------------------------------------------------ RPP --

#[derive(Clone, Copy, Debug)]
struct RppCase {
    a0: V,
    ma: Motion,
    g: Guide,
    offset: f64,
    beta: f64,
}

prop_compose! {
    /// `A = Q + s1 w`, `Q = g.at(s2, offset)`, with `|s1|, |s2| <= 2`.
    fn rpp_case()(g in guide(), offset in coord(), beta in angle(), s1 in -2.0..2.0f64,
                  s2 in -2.0..2.0f64, ma in motion()) -> RppCase {
        let d = g.dir0();
        let n = perp(d);
        let w = d * beta.cos() + n * beta.sin();
        let a0 = g.o0 + d * s2 + n * offset + w * s1;
        RppCase { a0, ma, g, offset, beta }
    }
}

impl Case for RppCase {
    fn snapshot<T: Real>(&self, t: f64) -> Result<Snapshot, Error<T>> {
        let a = pt_t::<T>(self.ma.at(self.a0, t));
        let g = self.g.line::<T>(t);
        let local = vec_t::<T>(unit(self.beta));
        let pos = rpp::position(&a, &g, lit(self.offset), &local)?;
        let (va, gv) = (self.ma.vel::<T>(t), self.g.gv::<T>(t));
        let vel = rpp::velocity(&pos, &a, &g, va.as_ref(), gv.as_ref())?;
        let (aa, ga) = (self.ma.acc::<T>(), self.g.ga::<T>());
        let acc = rpp::acceleration(&pos, &a, &g, &vel, aa.as_ref(), gv.as_ref(), ga.as_ref())?;
        let mut s = Snapshot::default();
        s.lin_v(wide_p(&pos.q));
        s.lin.extend([pos.s1.as_f64(), pos.s2.as_f64()]);
        // The slot turns with the guide's body.
        s.dirs.push(wide_v(&pos.slot));
        s.rate_v(wide_v(&vel.vq));
        s.rate.extend([vel.s1_dot.as_f64(), vel.s2_dot.as_f64()]);
        s.rate.push(self.g.omega(t));
        s.acc_v(wide_v(&acc.aq));
        s.acc.extend([acc.s1_ddot.as_f64(), acc.s2_ddot.as_f64()]);
        s.acc.push(self.g.al0);
        Ok(s)
    }
    fn residual<T: Real>(&self) -> Result<(f64, f64), Error<T>> {
        let a = pt_t::<T>(self.a0);
        let g = self.g.line::<T>(0.0);
        let e = lit::<T>(self.offset);
        let pos = rpp::position(&a, &g, e, &vec_t::<T>(unit(self.beta)))?;
        let (a, q, w) = (wide_p(&a), wide_p(&pos.q), wide_v(&pos.slot));
        let (o, d) = (wide_p(&g.origin), wide_v(&g.dir));
        let res = [
            (a - (q + w * pos.s1.as_f64())).norm(),
            (q - (o + d * pos.s2.as_f64() + perp(d) * e.as_f64())).norm(),
        ];
        let scale = max_abs(&[
            a.x,
            a.y,
            o.x,
            o.y,
            q.x,
            q.y,
            pos.s1.as_f64(),
            pos.s2.as_f64(),
        ]);
        Ok((max_abs(&res) * self.beta.sin().abs(), scale))
    }
}

// ---------------------------------------------------------------- crank --

#[derive(Clone, Copy, Debug)]
struct CrankCase {
    o0: V,
    mo: Motion,
    r: f64,
    theta: Input,
}

prop_compose! {
    fn crank_case()(o0 in vector(2.0), mo in motion(), r in 0.2..3.0f64, x0 in angle(),
                    v0 in -2.0..2.0f64, a0 in -2.0..2.0f64) -> CrankCase {
        CrankCase { o0, mo, r, theta: Input { x0, v0, a0 } }
    }
}

impl Case for CrankCase {
    fn snapshot<T: Real>(&self, t: f64) -> Result<Snapshot, Error<T>> {
        let o = pt_t::<T>(self.mo.at(self.o0, t));
        let pos = crank::position(&o, lit(self.r), lit(self.theta.x(t)))?;
        let omega = lit::<T>(self.theta.v(t));
        let v = crank::velocity(&pos, self.mo.vel::<T>(t).as_ref(), omega)?;
        let a = crank::acceleration(&pos, self.mo.acc::<T>().as_ref(), omega, lit(self.theta.a0))?;
        let mut s = Snapshot::default();
        s.lin_v(wide_p(&pos.tip));
        s.dirs.push(wide_v(&pos.axis));
        s.rate_v(wide_v(&v));
        s.rate.push(self.theta.v(t));
        s.acc_v(wide_v(&a));
        s.acc.push(self.theta.a0);
        Ok(s)
    }
    fn residual<T: Real>(&self) -> Result<(f64, f64), Error<T>> {
        let o = pt_t::<T>(self.o0);
        let r = lit::<T>(self.r);
        let pos = crank::position(&o, r, lit(self.theta.x0))?;
        let (tip, o) = (wide_p(&pos.tip), wide_p(&o));
        let res = [
            ((tip - o).norm() - r.as_f64()).abs(),
            (wide_v(&pos.r) - wide_v(&pos.axis) * r.as_f64()).norm(),
        ];
        Ok((max_abs(&res), max_abs(&[o.x, o.y, r.as_f64()])))
    }
}

// --------------------------------------------------------------- slider --

#[derive(Clone, Copy, Debug)]
struct SliderCase {
    g: Guide,
    offset: f64,
    s: Input,
}

prop_compose! {
    fn slider_case()(g in guide(), offset in coord(), x0 in -2.0..2.0f64, v0 in -1.0..1.0f64,
                     a0 in -1.0..1.0f64) -> SliderCase {
        SliderCase { g, offset, s: Input { x0, v0, a0 } }
    }
}

impl Case for SliderCase {
    fn snapshot<T: Real>(&self, t: f64) -> Result<Snapshot, Error<T>> {
        let g = self.g.line::<T>(t);
        let (s, sd, sdd) = (
            lit::<T>(self.s.x(t)),
            lit::<T>(self.s.v(t)),
            lit::<T>(self.s.a0),
        );
        let pos = slider::position(&g, lit(self.offset), s)?;
        let gv = self.g.gv::<T>(t);
        let v = slider::velocity(&pos, &g, s, sd, gv.as_ref())?;
        let a = slider::acceleration(&pos, &g, s, sd, sdd, gv.as_ref(), self.g.ga::<T>().as_ref())?;
        let mut snap = Snapshot::default();
        snap.lin_v(wide_p(&pos.p));
        snap.rate_v(wide_v(&v));
        snap.acc_v(wide_v(&a));
        Ok(snap)
    }
    fn residual<T: Real>(&self) -> Result<(f64, f64), Error<T>> {
        let g = self.g.line::<T>(0.0);
        let (e, s) = (lit::<T>(self.offset), lit::<T>(self.s.x0));
        let pos = slider::position(&g, e, s)?;
        let (o, d) = (wide_p(&g.origin), wide_v(&g.dir));
        let res = (wide_p(&pos.p) - (o + d * s.as_f64() + perp(d) * e.as_f64())).norm();
        Ok((res, max_abs(&[o.x, o.y, s.as_f64(), e.as_f64()])))
    }
}

// ------------------------------------------------------------- actuator --

#[derive(Clone, Copy, Debug)]
struct ActuatorCase {
    a0: V,
    ma: Motion,
    b0: V,
    mb: Motion,
    l: f64,
    len: Input,
    mode: Mode,
}

prop_compose! {
    fn actuator_case()((a0, b0, l, l2) in triangle(), ma in motion(), mb in motion(),
                       v0 in -1.0..1.0f64, acc in -1.0..1.0f64, mode in mode()) -> ActuatorCase {
        ActuatorCase { a0, ma, b0, mb, l, len: Input { x0: l2, v0, a0: acc }, mode }
    }
}

impl Case for ActuatorCase {
    fn snapshot<T: Real>(&self, t: f64) -> Result<Snapshot, Error<T>> {
        let a = pt_t::<T>(self.ma.at(self.a0, t));
        let b = pt_t::<T>(self.mb.at(self.b0, t));
        let pos = actuator::position(&a, lit(self.l), &b, lit(self.len.x(t)), self.mode)?;
        let (va, vb) = (self.ma.vel::<T>(t), self.mb.vel::<T>(t));
        let ld = lit::<T>(self.len.v(t));
        let vel = actuator::velocity(&pos, va.as_ref(), vb.as_ref(), ld)?;
        let (aa, ab) = (self.ma.acc::<T>(), self.mb.acc::<T>());
        let acc =
            actuator::acceleration(&pos, &vel, aa.as_ref(), ab.as_ref(), ld, lit(self.len.a0))?;
        let mut s = Snapshot::default();
        s.lin_v(wide_p(&pos.c));
        s.dirs.extend([wide_v(&pos.r1), wide_v(&pos.r2)]);
        s.rate_v(wide_v(&vel.vc));
        s.rate.extend([vel.omega1.as_f64(), vel.omega2.as_f64()]);
        s.acc_v(wide_v(&acc.ac));
        s.acc.extend([acc.alpha1.as_f64(), acc.alpha2.as_f64()]);
        Ok(s)
    }
    fn residual<T: Real>(&self) -> Result<(f64, f64), Error<T>> {
        let (a, b) = (pt_t::<T>(self.a0), pt_t::<T>(self.b0));
        let (l, len) = (lit::<T>(self.l), lit::<T>(self.len.x0));
        let pos = actuator::position(&a, l, &b, len, self.mode)?;
        let (c, a, b) = (wide_p(&pos.c), wide_p(&a), wide_p(&b));
        let res = [
            ((c - a).norm() - l.as_f64()).abs(),
            ((c - b).norm() - len.as_f64()).abs(),
        ];
        let scale = max_abs(&[a.x, a.y, b.x, b.y, l.as_f64(), len.as_f64()]);
        Ok((max_abs(&res), scale))
    }
}

// ----------------------------------------------------------- link point --

#[derive(Clone, Copy, Debug)]
struct LinkPointCase {
    o0: V,
    mo: Motion,
    theta: Input,
    local: V,
}

prop_compose! {
    fn link_point_case()(o0 in vector(2.0), mo in motion(), x0 in angle(), v0 in -2.0..2.0f64,
                         a0 in -2.0..2.0f64, local in vector(2.0)) -> LinkPointCase {
        LinkPointCase { o0, mo, theta: Input { x0, v0, a0 }, local }
    }
}

impl Case for LinkPointCase {
    fn snapshot<T: Real>(&self, t: f64) -> Result<Snapshot, Error<T>> {
        let o = pt_t::<T>(self.mo.at(self.o0, t));
        let axis = vec_t::<T>(unit(self.theta.x(t)));
        let p = link::point_position(&o, &axis, &vec_t(self.local))?;
        let omega = lit::<T>(self.theta.v(t));
        let rel_v = link::point_velocity(&(p - o), omega)?;
        let rel_a = link::point_acceleration(&(p - o), omega, lit(self.theta.a0))?;
        let v = wide_v(&rel_v) + self.mo.vel::<f64>(t).unwrap_or_else(V::zeros);
        let a = wide_v(&rel_a) + self.mo.acc::<f64>().unwrap_or_else(V::zeros);
        let mut s = Snapshot::default();
        s.lin_v(wide_p(&p));
        s.rate_v(v);
        s.acc_v(a);
        Ok(s)
    }
    fn residual<T: Real>(&self) -> Result<(f64, f64), Error<T>> {
        let o = pt_t::<T>(self.o0);
        let axis = vec_t::<T>(unit(self.theta.x0));
        let local = vec_t::<T>(self.local);
        let p = link::point_position(&o, &axis, &local)?;
        let (p, o, local) = (wide_p(&p), wide_p(&o), wide_v(&local));
        let res = ((p - o).norm() - local.norm()).abs();
        Ok((res, max_abs(&[o.x, o.y, local.x, local.y])))
    }
}

// ---------------------------------------------------------------- tests --

fn config() -> ProptestConfig {
    ProptestConfig {
        cases: 512,
        ..ProptestConfig::default()
    }
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn rrr_rates_are_derivatives(case in rrr_case()) {
        prop_assume!(rrr_conditioning(case.a0, case.l1, case.b0, case.l2, case.mode) >= 0.1);
        check_all(&case)?;
    }

    #[test]
    fn rrp_rates_are_derivatives(case in rrp_case()) {
        check_all(&case)?;
    }

    #[test]
    fn rpr_rates_are_derivatives(case in rpr_case()) {
        check_all(&case)?;
    }

    #[test]
    fn prp_rates_are_derivatives(case in prp_case()) {
        prop_assume!(case.conditioning() >= 0.1);
        check_all(&case)?;
    }

    #[test]
    fn rpp_rates_are_derivatives(case in rpp_case()) {
        prop_assume!(case.beta.sin().abs() >= 0.1);
        check_all(&case)?;
    }

    #[test]
    fn crank_rates_are_derivatives(case in crank_case()) {
        check_all(&case)?;
    }

    #[test]
    fn slider_rates_are_derivatives(case in slider_case()) {
        check_all(&case)?;
    }

    #[test]
    fn actuator_rates_are_derivatives(case in actuator_case()) {
        prop_assume!(
            rrr_conditioning(case.a0, case.l, case.b0, case.len.x0, case.mode) >= 0.1
        );
        check_all(&case)?;
    }

    #[test]
    fn link_point_rates_are_derivatives(case in link_point_case()) {
        check_all(&case)?;
    }
}

/// The finite-difference check can fail: a deliberately wrong acceleration (the
/// Coriolis term of a rotating guide dropped) is caught.
#[test]
fn finite_differences_catch_a_missing_coriolis_term() {
    #[derive(Debug)]
    struct Broken(SliderCase);
    impl Case for Broken {
        fn snapshot<T: Real>(&self, t: f64) -> Result<Snapshot, Error<T>> {
            let mut s = self.0.snapshot::<T>(t)?;
            // Remove 2 omega s_dot perp(dir) from the acceleration.
            let theta = self.0.g.theta0 + self.0.g.w0 * t + 0.5 * self.0.g.al0 * t * t;
            let cor = perp(unit(theta)) * (2.0 * self.0.g.omega(t) * self.0.s.v(t));
            s.acc[0] -= cor.x;
            s.acc[1] -= cor.y;
            Ok(s)
        }
        fn residual<T: Real>(&self) -> Result<(f64, f64), Error<T>> {
            self.0.residual::<T>()
        }
    }
    let g = Guide {
        o0: V::new(0.5, -0.2),
        theta0: 0.3,
        carry: Carry::Accelerating,
        vo: V::new(0.1, 0.2),
        ao: V::new(-0.3, 0.1),
        w0: 1.5,
        al0: 0.4,
    };
    let case = SliderCase {
        g,
        offset: 0.25,
        s: Input {
            x0: 1.0,
            v0: 0.8,
            a0: -0.2,
        },
    };
    assert!(check_fd::<f64, _>(&case, H64, false, TOL64).is_ok());
    assert!(check_fd::<f64, _>(&Broken(case), H64, false, TOL64).is_err());
    assert!(check_fd::<f32, _>(&Broken(case), H32, true, TOL32).is_err());
}
