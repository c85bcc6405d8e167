//! The triad section: the Stephenson III six-bar of
//! `examples/common/stephenson.rs` (a class III group driven by link 6's
//! angle) over its declared range, 3600 inputs.
//!
//! Methods, timed in the same interleaved rounds over the same inputs:
//! the generated `position()` (stateless: Newton from the tracked table's
//! pose with a radius of isolation, else the full search) and
//! `position_near` (warm-started from the previous input's pose), each
//! followed by the generated `velocity` and `acceleration`; and Newton on
//! the whole loop closure with nalgebra (`benches/common/baselines.rs`),
//! fixed-size `SMatrix` and heap `DMatrix` LU, warm-started from the
//! previous input's angles, with their velocity and acceleration solves.
//!
//! The reference is `mechanism_reference::triad` (double-double, its own
//! Newton on the loop closure in the four link angles, rates from its
//! Jacobian), followed along the inputs by its own continuation from the
//! definition's stated approximate pose at the stated input, so it depends on
//! no method's answer.

use crate::baselines::{self, StephensonOut};
use crate::stephenson::{
    stated_phi, Stephenson, StephensonAcceleration, StephensonInput, StephensonPosition,
    StephensonVelocity, PHI_DDOT, PHI_DOT,
};
use crate::timing::{self, Sweep};
use mechanism::Real;
use mechanism_reference::groups::{add, perp, scale, sub, V};
use mechanism_reference::triad::{self as rt, TriadRef};
use mechanism_reference::Dd;
use std::fmt::Write as _;
use std::hint::black_box;
use std::path::Path;

/// Inputs: the midpoints of `N` equal parts of the declared range.
const N: usize = 3600;
/// The definition's `range phi` (deg).
const RANGE_DEG: (f64, f64) = (-50.43, -2.64);
/// Columns per derivative order: the joints, then the link angles in the
/// reference's order (leg 1, leg 2, leg 3, ternary).
const NAMES: [&str; 10] = [
    "A.x", "A.y", "B.x", "B.y", "P.x", "P.y", "crank2", "rocker", "link5", "coupler",
];
/// Number of compared columns (three orders).
const COLS: usize = 30;

/// Link 6's angle at every input (rad).
fn grid() -> Vec<f64> {
    let (lo, hi) = RANGE_DEG;
    (0..N)
        .map(|k| (lo + (hi - lo) * (k as f64 + 0.5) / N as f64).to_radians())
        .collect()
}

/// A link angle column at order 0 (its errors are absolute, rad).
fn is_angle(k: usize) -> bool {
    (6..10).contains(&k)
}

/// The generated results flattened to the columns.
fn gen_row<T: Real>(
    p: &StephensonPosition<T>,
    v: &StephensonVelocity<T>,
    a: &StephensonAcceleration<T>,
) -> [f64; COLS] {
    [
        p.A.x, p.A.y, p.B.x, p.B.y, p.P.x, p.P.y, p.crank2, p.rocker, p.link5, p.coupler, v.A.x,
        v.A.y, v.B.x, v.B.y, v.P.x, v.P.y, v.crank2, v.rocker, v.link5, v.coupler, a.A.x, a.A.y,
        a.B.x, a.B.y, a.P.x, a.P.y, a.crank2, a.rocker, a.link5, a.coupler,
    ]
    .map(T::as_f64)
}

/// A baseline's angles, rates and accelerations flattened to the columns:
/// the joints and their rates follow from the angles along leg 1 and the
/// coupler (rigid-body kinematics, outside the timed loop).
fn base_row(o: &StephensonOut<f64>) -> [f64; COLS] {
    let [a, b, p] = baselines::stephenson_joints(&o.q);
    let o2 = baselines::ST_O2;
    let ra = (a.0 - o2.0, a.1 - o2.1);
    let (rb, rp) = ((b.0 - a.0, b.1 - a.1), (p.0 - a.0, p.1 - a.1));
    let vel = |w: f64, r: (f64, f64)| (-w * r.1, w * r.0);
    let acc = |w: f64, al: f64, r: (f64, f64)| (-al * r.1 - w * w * r.0, al * r.0 - w * w * r.1);
    let plus = |u: (f64, f64), v: (f64, f64)| (u.0 + v.0, u.1 + v.1);
    let va = vel(o.w[0], ra);
    let (vb, vp) = (plus(va, vel(o.w[3], rb)), plus(va, vel(o.w[3], rp)));
    let aa = acc(o.w[0], o.al[0], ra);
    let ab = plus(aa, acc(o.w[3], o.al[3], rb));
    let ap = plus(aa, acc(o.w[3], o.al[3], rp));
    let mut r = [0.0; COLS];
    let pts = [[a, b, p], [va, vb, vp], [aa, ab, ap]];
    let angs = [o.q, o.w, o.al];
    for order in 0..3 {
        for (i, pt) in pts[order].iter().enumerate() {
            r[10 * order + 2 * i] = pt.0;
            r[10 * order + 2 * i + 1] = pt.1;
        }
        r[10 * order + 6..10 * order + 10].copy_from_slice(&angs[order]);
    }
    r
}

/// The reference triad at `phi` (rad) and link 6's tip's velocity and
/// acceleration: `C` in double-double from the exact `f64` input, `P`'s
/// place in the coupler's frame as the definition folds it.
fn ref_triad(phi: f64) -> (TriadRef, V, V) {
    let d = baselines::ST_AP.1.to_radians();
    let [l1, l2, l3, ab, l6] = baselines::ST_L;
    let (o2, o4, o6) = (baselines::ST_O2, baselines::ST_O4, baselines::ST_O6);
    let mut t = TriadRef::new(
        [[o2.0, o2.1], [o4.0, o4.1], [0.0, 0.0]],
        [l1, l2, l3],
        ab,
        [baselines::ST_AP.0 * d.cos(), baselines::ST_AP.0 * d.sin()],
    );
    let (s, c) = Dd::from(phi).sin_cos();
    let r = [Dd::from(l6) * c, Dd::from(l6) * s];
    t.k[2] = add([Dd::from(o6.0), Dd::from(o6.1)], r);
    let (w, al) = (Dd::from(PHI_DOT), Dd::from(PHI_DDOT));
    let vc = scale(w, perp(r));
    let ac = sub(scale(al, perp(r)), scale(w * w, r));
    (t, vc, ac)
}

/// The reference's columns at `phi` from the angles `start`, and its
/// converged angles (`None`: its Newton or a rate solve failed).
fn ref_row(phi: f64, start: [Dd; 4]) -> Option<([Dd; COLS], [Dd; 4])> {
    let (t, _, _) = ref_triad(phi);
    let pose = rt::newton(&t, start)?;
    Some((columns(phi, &pose)?, pose.q))
}

/// The columns at `phi` of the assembly `pose`: its joints and angles, and
/// the rates and accelerations the reference solves from them (`None`: a
/// rate solve failed).
fn columns(phi: f64, pose: &rt::Pose) -> Option<[Dd; COLS]> {
    let (t, vc, ac) = ref_triad(phi);
    columns_of(&t, vc, ac, pose)
}

/// [`columns`] for the triad `t` with `K3`'s velocity `vc` and acceleration
/// `ac`.
fn columns_of(t: &TriadRef, vc: V, ac: V, pose: &rt::Pose) -> Option<[Dd; COLS]> {
    let z = [Dd::ZERO; 2];
    let (w, vj) = rt::rates(t, pose, [z, z, vc])?;
    let (al, aj) = rt::accelerations(t, pose, &w, [z, z, ac])?;
    let mut r = [Dd::ZERO; COLS];
    let pts = [pose.joints, vj, aj];
    let angs = [pose.q, w, al];
    for order in 0..3 {
        for i in 0..3 {
            r[10 * order + 2 * i] = pts[order][i][0];
            r[10 * order + 2 * i + 1] = pts[order][i][1];
        }
        r[10 * order + 6..10 * order + 10].copy_from_slice(&angs[order]);
    }
    Some(r)
}

/// The floor of any method that forms the velocity and acceleration
/// systems in `f64`: the link angles' rates and accelerations (in the order
/// of the columns 16..20 and 26..30) solved in double-double from the
/// reference's Jacobian at its own angles `q` and right-hand sides (`J x`
/// of its exact `x`) with every entry rounded to `f64` once, as `f64`.
fn system_floor(phi: f64, q: [Dd; 4], exact: &[Dd; COLS]) -> Option<[f64; 8]> {
    let (t, _, _) = ref_triad(phi);
    let jac = t.jacobian(&q);
    let round = |x: Dd| Dd::from(x.to_f64());
    let rows: Vec<Vec<Dd>> = jac
        .iter()
        .map(|r| r.iter().map(|&x| round(x)).collect())
        .collect();
    let mut out = [0.0; 8];
    for (order, base) in [(0, 16), (1, 26)] {
        let x = &exact[base..base + 4];
        let rhs = jac
            .iter()
            .map(|r| round(r.iter().zip(x).fold(Dd::ZERO, |s, (&a, &b)| s + a * b)))
            .collect();
        let y = mechanism_reference::linear::solve(rows.clone(), rhs).ok()?;
        for i in 0..4 {
            out[4 * order + i] = y[i].to_f64();
        }
    }
    Some(out)
}

/// The floor of any method that holds the pose in `f64`: the columns at
/// `phi` solved in double-double from the reference's link angles `q`
/// rounded to `f64` (the joints from those angles), as `f64`. Where the
/// velocity system is nearly singular (the swing's ends) the rounding of
/// the angles alone moves the rates and accelerations by far more than an
/// ulp; this measures how far.
fn floor_row(phi: f64, q: [Dd; 4]) -> Option<[f64; COLS]> {
    let (t, _, _) = ref_triad(phi);
    let q = q.map(|x| Dd::from(x.to_f64()));
    let pose = rt::Pose {
        q,
        joints: t.joints(&q),
    };
    Some(columns(phi, &pose)?.map(|x| x.to_f64()))
}

/// The floor of any method that receives the triad's moving pivot `K3`
/// (link 6's tip) in `f64`: per input, the largest error of the rates and
/// accelerations (columns 10..30, relative to `scale`) of the exact
/// solution (the reference's Newton, from its own angles) at `K3`, its
/// velocity and its acceleration rounded once from the reference's
/// double-double values. Near the swing's ends the half-ulp rounding of
/// `K3` alone moves the assembly by the velocity system's amplification, as
/// the rounding of the angles does in [`floor_row`]; `NaN` where the
/// reference failed.
fn input_floor(g: &[f64], refs: &[Option<([Dd; COLS], [Dd; 4])>], scale: &[f64; COLS]) -> Vec<f64> {
    let round = |v: V| v.map(|c| Dd::from(c.to_f64()));
    let at = |x: f64, f: &[Dd; COLS], q: [Dd; 4]| -> Option<f64> {
        let (mut t, vc, ac) = ref_triad(x);
        t.k[2] = round(t.k[2]);
        let pose = rt::newton(&t, q)?;
        let row = columns_of(&t, round(vc), round(ac), &pose)?;
        Some((10..30).fold(0.0f64, |m, k| {
            m.max((row[k] - f[k]).to_f64().abs() / scale[k])
        }))
    };
    g.iter()
        .zip(refs)
        .map(|(&x, r)| {
            r.as_ref()
                .and_then(|(f, q)| at(x, f, *q))
                .unwrap_or(f64::NAN)
        })
        .collect()
}

/// The reference at every input, by continuation: Newton from the stated
/// approximate pose (angles of the stated joints) at the stated input, then
/// in steps of at most 0.01 deg to the first input and along the inputs, each
/// solve started from the previous one's angles.
fn references(g: &[f64]) -> Vec<Option<([Dd; COLS], [Dd; 4])>> {
    let ang = |from: (f64, f64), to: (f64, f64)| Dd::from((to.1 - from.1).atan2(to.0 - from.0));
    let (a, b, p) = ((-0.061, -0.052), (0.137, 0.116), (-0.036, 0.096));
    let q0 = stated_phi();
    let c = (
        baselines::ST_O6.0 + baselines::ST_L[4] * q0.cos(),
        baselines::ST_O6.1 + baselines::ST_L[4] * q0.sin(),
    );
    let mut q = [
        ang(baselines::ST_O2, a),
        ang(baselines::ST_O4, b),
        ang(c, p),
        ang(a, b),
    ];
    let steps = ((g[0] - q0).abs() / 0.01f64.to_radians()).ceil() as usize;
    for k in 0..=steps {
        let x = q0 + (g[0] - q0) * k as f64 / steps.max(1) as f64;
        q = ref_row(x, q)
            .expect("the reference follows its stated assembly")
            .1;
    }
    g.iter()
        .map(|&x| {
            let (r, nq) = ref_row(x, q)?;
            q = nq;
            Some((r, nq))
        })
        .collect()
}

/// One method: its columns at every input, iterations (baselines), its
/// timed sweeps (position + velocity + acceleration; position alone for the
/// generated code).
struct Method<'a> {
    name: &'static str,
    family: &'static str,
    /// Evaluated in `f32` at the inputs rounded to `f32` (compared with the
    /// reference there).
    f32: bool,
    rows: Vec<Option<[f64; COLS]>>,
    iterations: Vec<u32>,
    sweep: Sweep<'a>,
    ns: Vec<f64>,
}

/// Link 6's rate and acceleration as inputs of the generated code.
fn rates<T: Real>() -> (StephensonInput<T>, StephensonInput<T>) {
    (
        StephensonInput {
            phi: T::lit(PHI_DOT),
        },
        StephensonInput {
            phi: T::lit(PHI_DDOT),
        },
    )
}

fn input<T: Real>(phi: f64) -> StephensonInput<T> {
    StephensonInput { phi: T::lit(phi) }
}

/// The generated velocity and acceleration at `p`, flattened with it.
fn gen_rates<T: Real>(m: &Stephenson<T>, p: &StephensonPosition<T>) -> Option<[f64; COLS]> {
    let (w, al) = rates();
    let v = m.velocity(p, &w).ok()?;
    let a = m.acceleration(p, &v, &al).ok()?;
    Some(gen_row(p, &v, &a))
}

/// The outputs every generated sweep sums (the same consumer for all).
fn gen_sum<T: Real>(
    m: &Stephenson<T>,
    p: &StephensonPosition<T>,
    w: &StephensonInput<T>,
    al: &StephensonInput<T>,
) -> f64 {
    let Ok(v) = m.velocity(p, w) else {
        return 0.0;
    };
    let Ok(a) = m.acceleration(p, &v, al) else {
        return 0.0;
    };
    (p.P.x + p.coupler + v.P.y + v.rocker + a.P.x + a.link5).as_f64()
}

/// The generated methods in `T`: `position()` at every input, and
/// `position_near` from the previous input's pose (from `first` at the
/// first input); `names`: (name, family) of each; inputs rounded to `T`.
fn generated<'a, T: Real>(
    m: &'a Stephenson<T>,
    g: &'a [f64],
    first: StephensonPosition<T>,
    names: [(&'static str, &'static str); 2],
) -> [Method<'a>; 2] {
    let f32 = core::mem::size_of::<T>() == 4;
    let inputs: Vec<StephensonInput<T>> = g.iter().map(|&x| input(x)).collect();
    let mut prev = first;
    let near_rows = inputs
        .iter()
        .map(|x| {
            let p = m.position_near(&prev, x).ok()?;
            prev = p;
            gen_rates(m, &p)
        })
        .collect();
    let full_rows = inputs
        .iter()
        .map(|x| gen_rates(m, &m.position(x).ok()?))
        .collect();
    let (xs, ys) = (inputs.clone(), inputs);
    [
        Method {
            name: names[0].0,
            family: names[0].1,
            f32,
            rows: full_rows,
            iterations: Vec::new(),
            sweep: Box::new(move || {
                let (w, al) = rates::<T>();
                let mut acc = 0.0;
                for x in &xs {
                    if let Ok(p) = m.position(x) {
                        acc += gen_sum(m, &p, &w, &al);
                    }
                }
                black_box(acc)
            }),
            ns: Vec::new(),
        },
        Method {
            name: names[1].0,
            family: names[1].1,
            f32,
            rows: near_rows,
            iterations: Vec::new(),
            sweep: Box::new(move || {
                let (w, al) = rates::<T>();
                let (mut acc, mut prev) = (0.0, first);
                for x in &ys {
                    if let Ok(p) = m.position_near(&prev, x) {
                        prev = p;
                        acc += gen_sum(m, &p, &w, &al);
                    }
                }
                black_box(acc)
            }),
            ns: Vec::new(),
        },
    ]
}

/// A Newton baseline of `benches/common/baselines.rs`.
type Newton = fn(f64, f64, f64, [f64; 4]) -> Option<StephensonOut<f64>>;

/// A Newton baseline over the inputs, each solve started from the previous
/// one's angles (from `guess0` at the first input).
fn baseline<'a>(
    g: &'a [f64],
    guess0: [f64; 4],
    name: &'static str,
    family: &'static str,
    f: Newton,
) -> Method<'a> {
    let mut guess = guess0;
    let mut iterations = Vec::new();
    let rows = g
        .iter()
        .map(|&x| {
            let o = f(x, PHI_DOT, PHI_DDOT, guess)?;
            guess = o.q;
            iterations.push(o.iterations);
            Some(base_row(&o))
        })
        .collect();
    Method {
        name,
        family,
        f32: false,
        rows,
        iterations,
        sweep: Box::new(move || {
            let (mut acc, mut guess) = (0.0, guess0);
            for &x in g {
                if let Some(o) = f(x, PHI_DOT, PHI_DDOT, guess) {
                    guess = o.q;
                    acc += o.q[2] + o.q[3] + o.w[1] + o.w[2] + o.al[0] + o.al[3];
                }
            }
            black_box(acc)
        }),
        ns: Vec::new(),
    }
}

/// The generated positions alone (timed only).
fn alone<'a>(
    m: &'a Stephenson<f64>,
    g: &'a [f64],
    first: StephensonPosition<f64>,
) -> Vec<(String, Sweep<'a>)> {
    vec![
        (
            "generated position() alone".into(),
            Box::new(move || {
                let mut acc = 0.0;
                for &x in g {
                    if let Ok(p) = m.position(&input(x)) {
                        acc += p.P.x + p.coupler;
                    }
                }
                black_box(acc)
            }),
        ),
        (
            "generated position_near alone".into(),
            Box::new(move || {
                let (mut acc, mut prev) = (0.0, first);
                for &x in g {
                    if let Ok(p) = m.position_near(&prev, &input(x)) {
                        prev = p;
                        acc += p.P.x + p.coupler;
                    }
                }
                black_box(acc)
            }),
        ),
    ]
}

/// The generated methods (`position()`, `position_near`; f64, then f32),
/// the baselines, and the sweeps of the generated f64 positions alone.
fn methods<'a>(
    m: &'a Stephenson<f64>,
    m32: &'a Stephenson<f32>,
    g: &'a [f64],
) -> (Vec<Method<'a>>, Vec<(String, Sweep<'a>)>) {
    let first = m
        .position(&input(g[0]))
        .expect("position() assembles at the first input");
    let first32 = m32
        .position(&input(g[0]))
        .expect("the f32 position() assembles at the first input");
    let guess0 = [first.crank2, first.rocker, first.link5, first.coupler];
    let mut out: Vec<Method> = generated(
        m,
        g,
        first,
        [
            (
                "generated position() + velocity + acceleration",
                "generated, full search",
            ),
            (
                "generated position_near + velocity + acceleration",
                "generated, warm start",
            ),
        ],
    )
    .into_iter()
    .collect();
    out.push(baseline(
        g,
        guess0,
        "Newton, nalgebra SMatrix 4x4 LU (warm start)",
        "Newton, SMatrix",
        baselines::stephenson_newton_fixed::<f64>,
    ));
    out.push(baseline(
        g,
        guess0,
        "Newton, heap DMatrix LU (warm start)",
        "Newton, DMatrix",
        baselines::stephenson_newton_heap::<f64>,
    ));
    out.extend(generated(
        m32,
        g,
        first32,
        [
            (
                "generated f32 position() + velocity + acceleration",
                "generated f32, full search",
            ),
            (
                "generated f32 position_near + velocity + acceleration",
                "generated f32, warm start",
            ),
        ],
    ));
    (out, alone(m, g, first))
}

fn wrap(d: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    d - tau * (d / tau).round()
}

/// Per column, the error at every input where both answered: relative to
/// the column's largest |reference| value over the inputs (`.0`), and
/// relative to the largest |reference| value of its group (the joints'
/// coordinates, or the link angles) and derivative order at the same input
/// (`.1`: a relative error that stays meaningful where a column crosses
/// zero). Angles (order 0): absolute, rad, in both.
fn column_errors(
    rows: &[Option<[f64; COLS]>],
    refs: &[Option<[Dd; COLS]>],
    scale: &[f64; COLS],
) -> (Vec<Vec<f64>>, Vec<Vec<f64>>) {
    let mut e: Vec<Vec<f64>> = (0..COLS).map(|_| Vec::with_capacity(rows.len())).collect();
    let mut local = e.clone();
    for (r, f) in rows.iter().zip(refs) {
        let (Some(r), Some(f)) = (r, f) else { continue };
        let group_of = |k: usize| {
            let base = 10 * (k / 10);
            if k % 10 < 6 {
                base..base + 6
            } else {
                base + 6..base + 10
            }
        };
        for k in 0..COLS {
            let d = (Dd::from(r[k]) - f[k]).to_f64();
            let here = group_of(k).map(|i| f[i].to_f64().abs()).fold(0.0, f64::max);
            let (a, b) = if !d.is_finite() {
                (f64::INFINITY, f64::INFINITY)
            } else if is_angle(k) {
                (wrap(d).abs(), wrap(d).abs())
            } else {
                (d.abs() / scale[k], d.abs() / here)
            };
            e[k].push(a);
            local[k].push(b);
        }
    }
    (e, local)
}

fn max_med(v: &[f64]) -> (f64, f64) {
    if v.is_empty() {
        return (f64::NAN, f64::NAN);
    }
    let (med, _, hi) = timing::stats(v);
    (hi, med)
}

fn sci(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else {
        format!("{x:.1e}")
    }
}

/// The section's heading and description; `ref_failed`: inputs where the
/// reference failed.
fn intro(ref_failed: usize) -> String {
    let mut md = String::new();
    let (lo, hi) = RANGE_DEG;
    let _ = writeln!(
        md,
        "## Stephenson (triad)\n\n\
         The Stephenson III six-bar of `examples/stephenson.rs` (a triad driven by link 6's angle \
         `phi` at {PHI_DOT} rad/s, {PHI_DDOT} rad/s^2): {N} inputs, the midpoints of {N} equal \
         parts of its declared range [{lo}, {hi}] deg (the swing's ends, where the assembly meets \
         another, are -50.4365 and -2.6334 deg: the rates grow without bound there). Reference: \
         `mechanism_reference::triad` in double-double (its own Newton on the loop closure in the \
         four link angles, rates from its Jacobian), followed by its own continuation from the \
         stated approximate pose at phi = -49.48 deg, once at the inputs and once at the inputs \
         rounded to f32 (for the f32 methods; the dimensions are the definition's decimals in \
         f64 in both, so an f32 error includes the rounding of the dimensions); it failed at \
         {ref_failed} inputs. All methods run on the same inputs in the same {} interleaved \
         rounds; ns per evaluation \
         (position + velocity + acceleration), median and min-max. `position()` is stateless: \
         Newton from the pose interpolated in the definition's tracked table, kept when a radius \
         of isolation proves it the assembly the full search would select, else the full \
         search; `position_near` and both Newton baselines start from the previous input's \
         answer. The Newton baselines (`benches/common/baselines.rs`) solve the six-bar's whole \
         loop closure (four equations in the four unknown link angles) with nalgebra's LU, stop \
         after the first step below {:.0e} rad (at most {} iterations), then solve the velocity and \
         acceleration systems with the converged Jacobian; they return the link angles and their \
         rates (the joints compared below follow from them outside the timed loop: a few \
         products). Errors: angles absolute (rad), every other column relative to its largest \
         |reference| value over the inputs.\n",
        crate::ROUNDS,
        baselines::ST_TOL,
        baselines::ST_MAX_ITER
    );
    md
}

/// The per-output table: max and median of the local relative errors.
fn per_output(ms: &[Method], local: &[Vec<Vec<f64>>]) -> String {
    let mut md = String::new();
    let _ = write!(md, "| column |");
    for m in ms {
        let _ = write!(md, " {} max | median |", short(m.name));
    }
    let _ = writeln!(md);
    let _ = writeln!(md, "|---|{}", "---:|---:|".repeat(ms.len()));
    for k in 0..COLS {
        let _ = write!(md, "| {} |", col_name(k));
        for e in local {
            let (mx, med) = max_med(&e[k]);
            let _ = write!(md, " {} | {} |", sci(mx), sci(med));
        }
        let _ = writeln!(md);
    }
    md
}

/// The section (markdown); writes `stephenson.csv` and `stephenson.svg`.
pub fn section(out_dir: &Path) -> String {
    let (m, m32) = (Stephenson::<f64>::default(), Stephenson::<f32>::default());
    let g = grid();
    let with_angles = references(&g);
    let floor: Vec<Option<[f64; COLS]>> = g
        .iter()
        .zip(&with_angles)
        .map(|(&x, r)| floor_row(x, r.as_ref()?.1))
        .collect();
    let refs: Vec<Option<[Dd; COLS]>> = with_angles.iter().map(|r| r.map(|r| r.0)).collect();
    // The f32 methods' inputs and their reference.
    let g32: Vec<f64> = g.iter().map(|&x| x as f32 as f64).collect();
    let refs32: Vec<Option<[Dd; COLS]>> = references(&g32).iter().map(|r| r.map(|r| r.0)).collect();
    let (mut ms, alone) = methods(&m, &m32, &g);
    let mut scale = [0.0f64; COLS];
    for r in refs.iter().flatten() {
        for k in 0..COLS {
            scale[k] = scale[k].max(r[k].to_f64().abs());
        }
    }
    let mut sweeps: Vec<(&Sweep, usize)> = ms.iter().map(|m| (&m.sweep, N)).collect();
    sweeps.extend(alone.iter().map(|(_, s)| (s, N)));
    let ns = timing::interleaved(&sweeps, crate::ROUNDS, crate::MIN_SAMPLE_NS);
    let (ns_methods, ns_alone) = ns.split_at(ms.len());
    for (m, t) in ms.iter_mut().zip(ns_methods) {
        m.ns = t.clone();
    }
    let (errs, local): (Vec<Vec<Vec<f64>>>, Vec<_>) = ms
        .iter()
        .map(|m| column_errors(&m.rows, if m.f32 { &refs32 } else { &refs }, &scale))
        .unzip();
    let ref_failed = refs.iter().chain(&refs32).filter(|r| r.is_none()).count();
    let mut md = intro(ref_failed);
    let _ = writeln!(
        md,
        "| method | ns/eval median | min - max | x generated `position_near` | angle err max (rad) | position rel max | velocity rel max | acceleration rel max | worst column | Newton iterations mean (max) | failed |"
    );
    let _ = writeln!(md, "|---|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|");
    let near = timing::stats(&ms[1].ns).0;
    let mut csv =
        String::from("method,column,max_col_rel,median_col_rel,max_local_rel,median_local_rel\n");
    let mut pts = Vec::new();
    for ((m, e), l) in ms.iter().zip(&errs).zip(&local) {
        let (med, mn, mx) = timing::stats(&m.ns);
        let worst_of = |ks: &mut dyn Iterator<Item = usize>| {
            ks.map(|k| max_med(&e[k]).0).fold(0.0f64, f64::max)
        };
        let ang = worst_of(&mut (6..10));
        let pos = worst_of(&mut (0..6));
        let vel = worst_of(&mut (10..20));
        let acc = worst_of(&mut (20..30));
        let (mut worst, mut worst_k) = (0.0, 0);
        for k in 0..COLS {
            let x = max_med(&e[k]).0 * if is_angle(k) { 1.0 / scale[k] } else { 1.0 };
            if x > worst {
                (worst, worst_k) = (x, k);
            }
        }
        let iters = if m.iterations.is_empty() {
            "-".to_string()
        } else {
            let s: u64 = m.iterations.iter().map(|&i| i as u64).sum();
            let mx = m.iterations.iter().max().copied().unwrap_or(0);
            format!("{:.2} ({mx})", s as f64 / m.iterations.len() as f64)
        };
        let failed = m.rows.iter().filter(|r| r.is_none()).count();
        let _ = writeln!(
            md,
            "| {} | {med:.1} | {mn:.1} - {mx:.1} | {:.2} | {} | {} | {} | {} | {} | {iters} | {failed} |",
            m.name,
            med / near,
            sci(ang),
            sci(pos),
            sci(vel),
            sci(acc),
            col_name(worst_k)
        );
        for (k, (ek, lk)) in e.iter().zip(l).enumerate() {
            let (mx, md_) = max_med(ek);
            let (lmx, lmd) = max_med(lk);
            let _ = writeln!(
                csv,
                "{},{},{mx:e},{md_:e},{lmx:e},{lmd:e}",
                m.name,
                col_name(k)
            );
        }
        pts.push(crate::svg::Pt {
            family: m.family.into(),
            label: m.name.into(),
            ns: med,
            err: worst,
        });
    }
    for ((name, _), t) in alone.iter().zip(ns_alone) {
        let (med, mn, mx) = timing::stats(t);
        let _ = writeln!(
            md,
            "| {name} | {med:.1} | {mn:.1} - {mx:.1} | {:.2} | | | | | | | |",
            med / near
        );
    }
    let floor_errs = column_errors(&floor, &refs, &scale).0;
    let system = system_floor_worst(&g, &with_angles, &scale);
    // The rates solved exactly from each generated method's own angles.
    let inherited: Vec<Vec<Vec<f64>>> = ms[..2]
        .iter()
        .map(|m| {
            let rows: Vec<Option<[f64; COLS]>> = g
                .iter()
                .zip(&m.rows)
                .map(|(&x, r)| {
                    floor_row(
                        x,
                        [
                            r.as_ref()?[6],
                            r.as_ref()?[7],
                            r.as_ref()?[8],
                            r.as_ref()?[9],
                        ]
                        .map(Dd::from),
                    )
                })
                .collect();
            column_errors(&rows, &refs, &scale).0
        })
        .collect();
    let inputs = input_floor(&g, &with_angles, &scale);
    md += &targets(&ms, &errs, &floor_errs, system, &inherited, &inputs);
    let _ = writeln!(
        md,
        "\nScales above (the columns' largest |reference| values): A.x {:.3}, B.x {:.3}, P.x \
         {:.3} m; d/dt crank2 {:.1} rad/s; d2/dt2 crank2 {:.2e} rad/s^2; the rates' and \
         accelerations' are reached at the first or last input, 0.013 deg inside the swing's \
         ends, where the velocity system is nearly singular. Per output below: max and median over the {N} inputs of the error \
         relative to the largest |reference| value of the same group (joint coordinates, or link \
         angles) and order at the same input (angles: absolute, rad).\n",
        scale[0], scale[2], scale[4], scale[16], scale[26]
    );
    md += &per_output(&ms, &local);
    let _ = writeln!(md, "\nPlot: `target/report/stephenson.svg`; per-column figures: `target/report/stephenson.csv`.\n");
    std::fs::write(out_dir.join("stephenson.csv"), csv).expect("write stephenson.csv");
    std::fs::write(
        out_dir.join("stephenson.svg"),
        crate::svg::plot("Stephenson (triad): work-precision", &pts, 1e-17),
    )
    .expect("write stephenson.svg");
    md
}

/// The columns of the link angles' rates and accelerations.
const ANGLE_RATES: [usize; 8] = [16, 17, 18, 19, 26, 27, 28, 29];

/// The largest error over the inputs of [`system_floor`]'s columns,
/// relative to each column's `scale`.
fn system_floor_worst(
    g: &[f64],
    refs: &[Option<([Dd; COLS], [Dd; 4])>],
    scale: &[f64; COLS],
) -> f64 {
    let at = |x: f64, r: &Option<([Dd; COLS], [Dd; 4])>| -> Option<f64> {
        let (row, q) = r.as_ref()?;
        let f = system_floor(x, *q, row)?;
        Some(ANGLE_RATES.iter().zip(f).fold(0.0f64, |m, (&k, v)| {
            m.max((Dd::from(v) - row[k]).to_f64().abs() / scale[k])
        }))
    };
    g.iter()
        .zip(refs)
        .filter_map(|(&x, r)| at(x, r))
        .fold(0.0, f64::max)
}

/// The issue-35 target lines (rows in the order of the table: `position()`,
/// `position_near`, Newton SMatrix, ...; `errs`: each method's column
/// errors; `floor`: the column errors of the reference's pose rounded to
/// `f64`, [`floor_row`]).
fn targets(
    ms: &[Method],
    errs: &[Vec<Vec<f64>>],
    floor: &[Vec<f64>],
    system: f64,
    inherited: &[Vec<Vec<f64>>],
    inputs: &[f64],
) -> String {
    let med = |k: usize| timing::stats(&ms[k].ns).0;
    let (full, near, newton) = (med(0), med(1), med(2));
    let met = |b: bool| if b { "**met**" } else { "**not met**" };
    let worst = |e: &[Vec<f64>], ks: std::ops::Range<usize>| {
        ks.map(|k| max_med(&e[k]).0).fold(0.0f64, f64::max)
    };
    // Per input, the largest error of the rates and accelerations.
    let rate_worst_at = |e: &[Vec<f64>]| -> Vec<f64> {
        (0..e[10].len())
            .map(|i| (10..30).map(|k| e[k][i]).fold(0.0f64, f64::max))
            .collect()
    };
    let mut md = format!(
        "\nTargets (issue 35, this run):\n\n\
         - `position()` with rates and accelerations {full:.1} ns = {:.2}x `position_near` \
         {near:.1} ns (target <= 5): {}\n\
         - `position_near` with rates and accelerations {near:.1} ns = {:.2}x the warm-started \
         SMatrix Newton {newton:.1} ns (target <= 0.5): {}\n",
        full / near,
        met(full / near <= 5.0),
        near / newton,
        met(near / newton <= 0.5),
    );
    let floor_rates = worst(floor, 10..30);
    for (k, name) in [(0, "`position()`"), (1, "`position_near`")] {
        let (ang, pos) = (worst(&errs[k], 6..10), worst(&errs[k], 0..6));
        let rat = worst(&errs[k], 10..30);
        let per_input = rate_worst_at(&errs[k]);
        let over: Vec<usize> = (0..per_input.len())
            .filter(|&i| per_input[i] > 1e-13)
            .collect();
        // Where it is over, the floor of the triad's input there.
        let there = over
            .iter()
            .map(|&i| inputs.get(i).copied().unwrap_or(f64::NAN))
            .fold(0.0f64, f64::max);
        let _ = writeln!(
            md,
            "- accuracy of {name} over the swing, its ends included: angles {} rad (target 1e-14): \
             {}; positions {} (target 1e-13): {}; rates and accelerations {} relative (target \
             1e-13): {}, over 1e-13 at {} of the {N} inputs{}; the rates and accelerations \
             solved exactly from its own angles are off by {} (the SMatrix Newton's: {})",
            sci(ang),
            met(ang <= 1e-14),
            sci(pos),
            met(pos <= 1e-13),
            sci(rat),
            met(rat <= 1e-13),
            over.len(),
            if over.is_empty() {
                String::new()
            } else {
                format!(
                    ", where the exact solution at `K3` and its rates rounded once to `f64` is \
                     off by {}",
                    sci(there)
                )
            },
            sci(worst(&inherited[k], 10..30)),
            sci(worst(&errs[2], 10..30)),
        );
    }
    let _ = writeln!(
        md,
        "- what the rates and accelerations inherit, over the swing: {} from the reference's \
         own angles rounded to `f64` (the rates solved exactly from them), {} from its velocity \
         and acceleration systems with every entry rounded to `f64` once (the link angles' \
         rates and accelerations solved exactly), {} from the triad's input `K3` (link 6's tip), \
         its velocity and acceleration rounded to `f64` once (the exact solution there); so where the velocity system is nearly singular the error of the rates is the \
         error of the pose, amplified by that system, not the rates' own rounding, and the \
         half-ulp rounding of the group's input alone moves the pose by as much",
        sci(floor_rates),
        sci(system),
        sci(inputs.iter().copied().fold(0.0f64, f64::max)),
    );
    md
}

fn col_name(k: usize) -> String {
    let prefix = ["", "d/dt ", "d2/dt2 "][k / 10];
    format!("{prefix}{}", NAMES[k % 10])
}

fn short(name: &str) -> &str {
    match name {
        n if n.starts_with("generated position()") => "`position()`",
        n if n.starts_with("generated position_near") => "`position_near`",
        n if n.starts_with("generated f32 position()") => "f32 `position()`",
        n if n.starts_with("generated f32 position_near") => "f32 `position_near`",
        n if n.contains("SMatrix") => "Newton SMatrix",
        _ => "Newton DMatrix",
    }
}
