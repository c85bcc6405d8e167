//! The five example mechanisms of `examples/common/scenes.rs`, checked over the
//! examples' whole input ranges without trusting any number the code prints:
//!
//! 1. loop closure: every constraint of the definition (link lengths, points on
//!    guides, points on links at their local offsets, link angles, assembly
//!    branches) holds, in f64 and in f32;
//! 2. velocities equal central finite differences of positions along an input
//!    trajectory `q(t) = q0 + w t + a t^2 / 2`, and accelerations equal central
//!    finite differences of velocities along it (with zero and nonzero input
//!    accelerations `a`);
//! 3. the f32 instantiation agrees with the f64 one;
//! 4. the source documents' printed values, where the documents are right
//!    (`docs/seeds.md`), and an independent closed form for the slider-crank;
//! 5. the five-bar's typed errors: an unreachable pose is `CannotAssemble` in
//!    group `P`, never NaN.
//!
//! Every check prints its worst observed error (`cargo test --test examples kinematics --
//! --nocapture`) and states in the assertion message what it observed.

use crate::scenes::*;
use mechanism::{Error, Fault, Point2, Primitive, Real, Vector2};
use std::f64::consts::PI;

// ---------------------------------------------------------------------------
// Plain f64 planar helpers, independent of the crate's geometry module.

type V2 = [f64; 2];

fn pt<T: Real>(p: &Point2<T>) -> V2 {
    [p.x.as_f64(), p.y.as_f64()]
}

fn vc<T: Real>(v: &Vector2<T>) -> V2 {
    [v.x.as_f64(), v.y.as_f64()]
}

fn sub(a: V2, b: V2) -> V2 {
    [a[0] - b[0], a[1] - b[1]]
}

fn add(a: V2, b: V2) -> V2 {
    [a[0] + b[0], a[1] + b[1]]
}

fn scale(k: f64, a: V2) -> V2 {
    [k * a[0], k * a[1]]
}

fn norm(a: V2) -> f64 {
    a[0].hypot(a[1])
}

fn cross(a: V2, b: V2) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

fn dot(a: V2, b: V2) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

/// Unit vector at `angle` (rad).
fn unit(angle: f64) -> V2 {
    [angle.cos(), angle.sin()]
}

/// Angle of `a` from +x (rad).
fn angle_of(a: V2) -> f64 {
    a[1].atan2(a[0])
}

/// `x` wrapped into (-pi, pi]: unwraps angle differences.
fn wrap(x: f64) -> f64 {
    let y = x.rem_euclid(2.0 * PI);
    if y > PI {
        y - 2.0 * PI
    } else {
        y
    }
}

/// Angle (rad) in degrees in [0, 360), the convention of the documents' tables.
fn deg_0_360(angle: f64) -> f64 {
    angle.to_degrees().rem_euclid(360.0)
}

/// Residual of a link-angle output against the direction of the link's points,
/// as a length: the angle error times the link's length `l`.
fn angle_residual(link_angle: f64, along: V2, l: f64) -> f64 {
    wrap(link_angle - angle_of(along)) * l
}

/// `x` rounded to f32 and widened back: an input both scalars represent exactly.
fn through_f32(x: f64) -> f64 {
    x as f32 as f64
}

// ---------------------------------------------------------------------------
// One analysed pose, widened to f64, and the description of a scene.

/// What a column holds; columns of the same kind share a unit (length units or
/// radians) and so a scale for columns that are identically zero.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    /// A point coordinate or a slide (length units).
    Length,
    /// A link angle (rad); differences are unwrapped.
    Angle,
}

/// One pose: `pos[i]` (a coordinate, link angle or slide), `vel[i]` its time
/// derivative and `acc[i]` the derivative of `vel[i]`, all widened to f64.
struct Sample {
    pos: Vec<f64>,
    vel: Vec<f64>,
    acc: Vec<f64>,
    /// Constraint residuals in length units (zero for an exact solution).
    residuals: Vec<(&'static str, f64)>,
    /// The definition's assembly branches (`left`, `plus`), which must hold.
    branches: Vec<(&'static str, bool)>,
}

type Eval = fn(&[f64], &[f64], &[f64]) -> Result<Sample, Error>;

struct Scene {
    name: &'static str,
    columns: &'static [(&'static str, Kind)],
    /// Size of the mechanism (length units): the largest distance of a point
    /// from the origin or link length over the motion, the scale of rounding
    /// errors in coordinates and lengths.
    size: f64,
    eval64: Eval,
    eval32: Eval,
    /// Input poses (rad) of the example's whole range.
    poses: Vec<Vec<f64>>,
    /// Input rates and accelerations for the derivative and f32 checks.
    motions: Vec<(Vec<f64>, Vec<f64>)>,
    /// Poses may legitimately fail (the five-bar's grid); skipped there and
    /// checked against an independent reachability test elsewhere.
    may_fail: bool,
}

fn lit<T: Real>(x: f64) -> T {
    T::lit(x)
}

// ---------------------------------------------------------------------------
// The five scenes, with their constraints written from the definitions in
// examples/common/scenes.rs (not from the generated code).

const FOURBAR_COLUMNS: &[(&str, Kind)] = &[
    ("A.x", Kind::Length),
    ("A.y", Kind::Length),
    ("B.x", Kind::Length),
    ("B.y", Kind::Length),
    ("link2", Kind::Angle),
    ("link3", Kind::Angle),
    ("link4", Kind::Angle),
];

fn fourbar<T: Real>(q: &[f64], w: &[f64], a: &[f64]) -> Result<Sample, Error> {
    let m = FourBar::<T>::default();
    let s = m
        .solve(
            &FourBarInput { theta2: lit(q[0]) },
            &FourBarInput { theta2: lit(w[0]) },
            &FourBarInput { theta2: lit(a[0]) },
        )
        .map_err(Error::to_f64)?;
    let (p, v, ac) = (&s.position, &s.velocity, &s.acceleration);
    let (o2, o4, pa, pb) = (pt(&p.O2), pt(&p.O4), pt(&p.A), pt(&p.B));
    let (l2, l3, l4) = (p.link2.as_f64(), p.link3.as_f64(), p.link4.as_f64());
    Ok(Sample {
        pos: vec![pa[0], pa[1], pb[0], pb[1], l2, l3, l4],
        vel: [vc(&v.A), vc(&v.B)]
            .concat()
            .into_iter()
            .chain([v.link2, v.link3, v.link4].map(|x| x.as_f64()))
            .collect(),
        acc: [vc(&ac.A), vc(&ac.B)]
            .concat()
            .into_iter()
            .chain([ac.link2, ac.link3, ac.link4].map(|x| x.as_f64()))
            .collect(),
        residuals: vec![
            ("O2 = (0, 0)", norm(o2)),
            ("O4 = (304.8, 0)", norm(sub(o4, [304.8, 0.0]))),
            (
                "A = O2 + 101.6 u(theta2)",
                norm(sub(sub(pa, o2), scale(101.6, unit(q[0])))),
            ),
            ("|B - A| = 254", norm(sub(pb, pa)) - 254.0),
            ("|B - O4| = 177.8", norm(sub(pb, o4)) - 177.8),
            (
                "link2 = angle(A - O2)",
                angle_residual(l2, sub(pa, o2), 101.6),
            ),
            (
                "link3 = angle(B - A)",
                angle_residual(l3, sub(pb, pa), 254.0),
            ),
            (
                "link4 = angle(B - O4)",
                angle_residual(l4, sub(pb, o4), 177.8),
            ),
        ],
        branches: vec![("B left of A -> O4", cross(sub(o4, pa), sub(pb, pa)) > 0.0)],
    })
}

const SIXBAR_COLUMNS: &[(&str, Kind)] = &[
    ("C.x", Kind::Length),
    ("C.y", Kind::Length),
    ("F.x", Kind::Length),
    ("F.y", Kind::Length),
    ("link2", Kind::Angle),
    ("link3", Kind::Angle),
    ("link4", Kind::Angle),
    ("af", Kind::Length),
];

fn sixbar<T: Real>(q: &[f64], w: &[f64], a: &[f64]) -> Result<Sample, Error> {
    let m = SixBar::<T>::default();
    let s = m
        .solve(
            &SixBarInput { phi1: lit(q[0]) },
            &SixBarInput { phi1: lit(w[0]) },
            &SixBarInput { phi1: lit(a[0]) },
        )
        .map_err(Error::to_f64)?;
    let (p, v, ac) = (&s.position, &s.velocity, &s.acceleration);
    let (pa, pe, pk, pb) = (pt(&p.A), pt(&p.E), pt(&p.K), pt(&p.B));
    let (pf, pd, pc) = (pt(&p.F), pt(&p.D), pt(&p.C));
    let (l2, l3, l4, af) = (
        p.link2.as_f64(),
        p.link3.as_f64(),
        p.link4.as_f64(),
        p.af.as_f64(),
    );
    let u1 = unit(q[0]);
    let ef = sub(pf, pe);
    Ok(Sample {
        pos: vec![pc[0], pc[1], pf[0], pf[1], l2, l3, l4, af],
        vel: [vc(&v.C), vc(&v.F)]
            .concat()
            .into_iter()
            .chain([v.link2, v.link3, v.link4, v.af].map(|x| x.as_f64()))
            .collect(),
        acc: [vc(&ac.C), vc(&ac.F)]
            .concat()
            .into_iter()
            .chain([ac.link2, ac.link3, ac.link4, ac.af].map(|x| x.as_f64()))
            .collect(),
        residuals: vec![
            ("A = (0, 0)", norm(pa)),
            ("E = (70, 0)", norm(sub(pe, [70.0, 0.0]))),
            (
                "K = A + 40 u(phi1)",
                norm(sub(sub(pk, pa), scale(40.0, u1))),
            ),
            (
                "B = A + 40 u(phi1 + 180 deg)",
                norm(sub(sub(pb, pa), scale(-40.0, u1))),
            ),
            (
                "F = A + af u(phi1) (on the crank line)",
                norm(sub(sub(pf, pa), scale(af, u1))),
            ),
            ("|F - E| = 60", norm(ef) - 60.0),
            (
                "D = E + 35 u(angle(F - E) + 180 deg)",
                norm(sub(sub(pd, pe), scale(-35.0 / norm(ef), ef))),
            ),
            ("|C - B| = 50", norm(sub(pc, pb)) - 50.0),
            ("|C - D| = 75", norm(sub(pc, pd)) - 75.0),
            (
                "link2 = angle(C - B)",
                angle_residual(l2, sub(pc, pb), 50.0),
            ),
            (
                "link3 = angle(C - D)",
                angle_residual(l3, sub(pc, pd), 75.0),
            ),
            ("link4 = angle(F - E)", angle_residual(l4, ef, 60.0)),
        ],
        branches: vec![
            (
                "F ahead of the foot from E along the crank line (plus)",
                dot(ef, u1) > 0.0,
            ),
            ("C left of B -> D", cross(sub(pd, pb), sub(pc, pb)) > 0.0),
        ],
    })
}

const SHAPER_COLUMNS: &[(&str, Kind)] = &[
    ("E.x", Kind::Length),
    ("E.y", Kind::Length),
    ("link3", Kind::Angle),
    ("link4", Kind::Angle),
];

fn shaper<T: Real>(q: &[f64], w: &[f64], a: &[f64]) -> Result<Sample, Error> {
    let m = Shaper::<T>::default();
    let s = m
        .solve(
            &ShaperInput { crank: lit(q[0]) },
            &ShaperInput { crank: lit(w[0]) },
            &ShaperInput { crank: lit(a[0]) },
        )
        .map_err(Error::to_f64)?;
    let (p, v, ac) = (&s.position, &s.velocity, &s.acceleration);
    let (pa, pc, pb, pd, pe) = (pt(&p.A), pt(&p.C), pt(&p.B), pt(&p.D), pt(&p.E));
    let (l3, l4) = (p.link3.as_f64(), p.link4.as_f64());
    let u3 = unit(l3);
    Ok(Sample {
        pos: vec![pe[0], pe[1], l3, l4],
        vel: vc(&v.E)
            .into_iter()
            .chain([v.link3, v.link4].map(|x| x.as_f64()))
            .collect(),
        acc: vc(&ac.E)
            .into_iter()
            .chain([ac.link3, ac.link4].map(|x| x.as_f64()))
            .collect(),
        residuals: vec![
            ("A = (0, 0)", norm(pa)),
            ("C = (0, -0.275)", norm(sub(pc, [0.0, -0.275]))),
            (
                "B = A + 0.125 u(crank)",
                norm(sub(sub(pb, pa), scale(0.125, unit(q[0])))),
            ),
            ("B on link3's line through C", cross(u3, sub(pb, pc))),
            (
                "D = C + 0.6 u(link3)",
                norm(sub(sub(pd, pc), scale(0.6, u3))),
            ),
            ("E on the ram guide y = 0.3", pe[1] - 0.3),
            ("|E - D| = 0.15", norm(sub(pe, pd)) - 0.15),
            (
                "link4 = angle(E - D)",
                angle_residual(l4, sub(pe, pd), 0.15),
            ),
        ],
        branches: vec![
            (
                "block B ahead of C along link3 (plus)",
                dot(sub(pb, pc), u3) > 0.0,
            ),
            (
                "E ahead of the foot from D along the ram's 180 deg (plus)",
                pe[0] < pd[0],
            ),
        ],
    })
}

const SLIDER_COLUMNS: &[(&str, Kind)] = &[
    ("B.x", Kind::Length),
    ("B.y", Kind::Length),
    ("link3", Kind::Angle),
    ("x", Kind::Length),
];

fn slider_crank<T: Real>(q: &[f64], w: &[f64], a: &[f64]) -> Result<Sample, Error> {
    let m = SliderCrank::<T>::default();
    let s = m
        .solve(
            &SliderCrankInput { theta: lit(q[0]) },
            &SliderCrankInput { theta: lit(w[0]) },
            &SliderCrankInput { theta: lit(a[0]) },
        )
        .map_err(Error::to_f64)?;
    let (p, v, ac) = (&s.position, &s.velocity, &s.acceleration);
    let (po, pa, pb) = (pt(&p.O), pt(&p.A), pt(&p.B));
    let (l3, x) = (p.link3.as_f64(), p.x.as_f64());
    Ok(Sample {
        pos: vec![pb[0], pb[1], l3, x],
        vel: vc(&v.B)
            .into_iter()
            .chain([v.link3, v.x].map(|x| x.as_f64()))
            .collect(),
        acc: vc(&ac.B)
            .into_iter()
            .chain([ac.link3, ac.x].map(|x| x.as_f64()))
            .collect(),
        residuals: vec![
            ("O = (0, 0)", norm(po)),
            (
                "A = O + 0.1 u(theta)",
                norm(sub(sub(pa, po), scale(0.1, unit(q[0])))),
            ),
            ("B on the line y = 0.02", pb[1] - 0.02),
            ("B = (0, 0.02) + x (1, 0)", norm(sub(pb, [x, 0.02]))),
            ("|B - A| = 0.4", norm(sub(pb, pa)) - 0.4),
            ("link3 = angle(B - A)", angle_residual(l3, sub(pb, pa), 0.4)),
        ],
        branches: vec![("B ahead of the foot from A along +x (plus)", pb[0] > pa[0])],
    })
}

const FIVEBAR_COLUMNS: &[(&str, Kind)] = &[("P.x", Kind::Length), ("P.y", Kind::Length)];

fn five_bar<T: Real>(q: &[f64], w: &[f64], a: &[f64]) -> Result<Sample, Error> {
    let m = FiveBar::<T>::default();
    let input = |x: &[f64]| FiveBarInput {
        q1: lit(x[0]),
        q2: lit(x[1]),
    };
    let s = m
        .solve(&input(q), &input(w), &input(a))
        .map_err(Error::to_f64)?;
    let (p, v, ac) = (&s.position, &s.velocity, &s.acceleration);
    let (o1, o2, pa, pc, pp) = (pt(&p.O1), pt(&p.O2), pt(&p.A), pt(&p.C), pt(&p.P));
    Ok(Sample {
        pos: pp.to_vec(),
        vel: vc(&v.P).to_vec(),
        acc: vc(&ac.P).to_vec(),
        residuals: vec![
            ("O1 = (0, 0)", norm(o1)),
            ("O2 = (0.08, 0)", norm(sub(o2, [0.08, 0.0]))),
            (
                "A = O1 + 0.1 u(q1)",
                norm(sub(sub(pa, o1), scale(0.1, unit(q[0])))),
            ),
            (
                "C = O2 + 0.1 u(q2)",
                norm(sub(sub(pc, o2), scale(0.1, unit(q[1])))),
            ),
            ("|P - A| = 0.16", norm(sub(pp, pa)) - 0.16),
            ("|P - C| = 0.16", norm(sub(pp, pc)) - 0.16),
        ],
        branches: vec![("P left of A -> C", cross(sub(pc, pa), sub(pp, pa)) > 0.0)],
    })
}

fn deg_range(from: f64, to_inclusive: f64, step: f64) -> Vec<Vec<f64>> {
    let n = ((to_inclusive - from) / step).round() as usize;
    (0..=n)
        .map(|k| vec![(from + step * k as f64).to_radians()])
        .collect()
}

/// The six-bar document's `linspace(40, 55, 15)` (deg, in rad).
fn sixbar_linspace() -> Vec<f64> {
    (0..15)
        .map(|k| (40.0 + 15.0 * k as f64 / 14.0).to_radians())
        .collect()
}

const RPM_3000: f64 = 3000.0 * 2.0 * PI / 60.0;

fn scenes() -> Vec<Scene> {
    let mut sixbar_poses = deg_range(40.0, 55.0, 1.0);
    sixbar_poses.extend(sixbar_linspace().into_iter().map(|q| vec![q]));
    let mut five_bar_poses = Vec::new();
    for i in 0..=6 {
        for j in 0..=6 {
            let q1 = 60.0 + 15.0 * i as f64;
            let q2 = 15.0 * j as f64;
            five_bar_poses.push(vec![q1.to_radians(), q2.to_radians()]);
        }
    }
    vec![
        Scene {
            name: "fourbar",
            columns: FOURBAR_COLUMNS,
            // Points within 304.8 + 177.8 of the origin; links up to 304.8 mm.
            size: 482.6,
            eval64: fourbar::<f64>,
            eval32: fourbar::<f32>,
            poses: deg_range(0.0, 355.0, 5.0),
            // The example's 250 rad/s, then with an input acceleration whose
            // term alpha * d/dq is comparable to the omega^2 term.
            motions: vec![(vec![250.0], vec![0.0]), (vec![250.0], vec![2.0e4])],
            may_fail: false,
        },
        Scene {
            name: "sixbar",
            columns: SIXBAR_COLUMNS,
            // C, F, D within about 150 mm of A; links up to 75 mm.
            size: 150.0,
            eval64: sixbar::<f64>,
            eval32: sixbar::<f32>,
            poses: sixbar_poses,
            motions: vec![(vec![10.0], vec![0.0]), (vec![10.0], vec![-60.0])],
            may_fail: false,
        },
        Scene {
            name: "shaper",
            columns: SHAPER_COLUMNS,
            // D at 0.6 m from C = (0, -0.275); E within 0.35 m of the origin.
            size: 0.6,
            eval64: shaper::<f64>,
            eval32: shaper::<f32>,
            poses: deg_range(0.0, 360.0, 30.0)
                .into_iter()
                .chain(deg_range(0.0, 360.0, 1.0))
                .collect(),
            motions: vec![(vec![1.0], vec![0.0]), (vec![1.0], vec![0.7])],
            may_fail: false,
        },
        Scene {
            name: "slider_crank",
            columns: SLIDER_COLUMNS,
            // B within 0.5 m of the origin.
            size: 0.5,
            eval64: slider_crank::<f64>,
            eval32: slider_crank::<f32>,
            poses: deg_range(0.0, 350.0, 10.0),
            motions: vec![(vec![RPM_3000], vec![0.0]), (vec![RPM_3000], vec![5.0e4])],
            may_fail: false,
        },
        Scene {
            name: "five_bar",
            columns: FIVEBAR_COLUMNS,
            // P within about 0.26 m of the origin; links 0.16 m.
            size: 0.3,
            eval64: five_bar::<f64>,
            eval32: five_bar::<f32>,
            poses: five_bar_poses,
            // The example's (1, 1) rad/s; each input alone; then two different
            // rates with nonzero input accelerations.
            motions: vec![
                (vec![1.0, 1.0], vec![0.0, 0.0]),
                (vec![1.0, 0.0], vec![0.0, 0.0]),
                (vec![0.0, 1.0], vec![0.0, 0.0]),
                (vec![0.8, -1.3], vec![2.0, -0.5]),
            ],
            may_fail: true,
        },
    ]
}

// ---------------------------------------------------------------------------
// Column statistics.

/// Worst error of a column relative to its scale.
struct Worst {
    rel: f64,
    at: String,
}

/// For each column, the largest |reference|. A column that is zero in exact
/// arithmetic (the velocity of a point on a fixed straight guide across the
/// guide: its largest value is below 1e-6 of the largest column of the same
/// kind, only rounding noise) is measured against that largest column of its
/// kind instead, the magnitude its rounding errors come from.
fn column_scales(columns: &[(&str, Kind)], values: &[Vec<f64>]) -> Vec<f64> {
    let mut scales = vec![0.0f64; columns.len()];
    for row in values {
        for (s, x) in scales.iter_mut().zip(row) {
            *s = s.max(x.abs());
        }
    }
    let kind_max = |k: Kind| {
        columns
            .iter()
            .zip(&scales)
            .filter(|((_, kind), _)| *kind == k)
            .map(|(_, s)| *s)
            .fold(0.0, f64::max)
    };
    columns
        .iter()
        .zip(&scales)
        .map(|((_, k), s)| {
            let kind = kind_max(*k);
            if *s < 1e-6 * kind {
                kind
            } else {
                *s
            }
        })
        .collect()
}

/// Worst |a - b| / scale per column, over rows labelled by `labels`.
fn worst_per_column(
    reference: &[Vec<f64>],
    other: &[Vec<f64>],
    scales: &[f64],
    labels: &[String],
) -> Vec<Worst> {
    (0..scales.len())
        .map(|i| {
            let mut w = Worst {
                rel: 0.0,
                at: String::new(),
            };
            for ((r, o), label) in reference.iter().zip(other).zip(labels) {
                let rel = (r[i] - o[i]).abs() / scales[i];
                assert!(rel.is_finite(), "non-finite column {i} at {label}");
                if rel > w.rel {
                    w = Worst {
                        rel,
                        at: label.clone(),
                    };
                }
            }
            w
        })
        .collect()
}

fn label(q: &[f64]) -> String {
    let deg: Vec<String> = q.iter().map(|x| format!("{:.4}", x.to_degrees())).collect();
    format!("q = ({}) deg", deg.join(", "))
}

fn assert_all_finite(scene: &str, s: &Sample, at: &str) {
    for (what, v) in [
        ("position", &s.pos),
        ("velocity", &s.vel),
        ("acceleration", &s.acc),
    ] {
        assert!(
            v.iter().all(|x| x.is_finite()),
            "{scene}: non-finite {what} at {at}: {v:?}"
        );
    }
}

// ---------------------------------------------------------------------------
// 1. Loop closure.

/// Residual bound in units of `eps * size`. A point is built by at most about
/// four dependent steps (crank tip, point on a link, a group's closed form),
/// each adding a rounding error of about one or two eps times the coordinates'
/// magnitude (<= size); the test's own subtraction and `hypot` add one or two
/// more: some 4 to 10 eps * size in all. Near-singular poses do not enlarge
/// residuals (only the sensitivity of the solution to its inputs). Observed:
/// below 2 eps * size in f64 and in f32.
const CLOSURE_EPS_UNITS: f64 = 8.0;

fn check_closure(scene: &Scene, eval: Eval, eps: f64, scalar: &str) -> f64 {
    let tol = CLOSURE_EPS_UNITS * eps * scene.size;
    let mut worst = 0.0f64;
    let mut worst_at = String::new();
    let mut checked = 0;
    let zeros = vec![0.0; scene.poses[0].len()];
    for q in &scene.poses {
        // f32 inputs exactly representable, so that both scalars see the same pose.
        let q: Vec<f64> = q.iter().map(|&x| through_f32(x)).collect();
        let s = match eval(&q, &zeros, &zeros) {
            Ok(s) => s,
            Err(e) if scene.may_fail => {
                eprintln!("{}: {} skipped: {e}", scene.name, label(&q));
                continue;
            }
            Err(e) => panic!("{} ({scalar}) fails at {}: {e}", scene.name, label(&q)),
        };
        checked += 1;
        assert_all_finite(scene.name, &s, &label(&q));
        for (what, ok) in &s.branches {
            assert!(
                ok,
                "{} ({scalar}): branch `{what}` violated at {}",
                scene.name,
                label(&q)
            );
        }
        for (what, r) in &s.residuals {
            assert!(
                r.abs() <= tol,
                "{} ({scalar}): `{what}` off by {r:e} at {} (tolerance {tol:e} = {CLOSURE_EPS_UNITS} eps * {})",
                scene.name,
                label(&q),
                scene.size
            );
            if r.abs() > worst {
                worst = r.abs();
                worst_at = format!("`{what}` at {}", label(&q));
            }
        }
    }
    assert!(checked > 0, "{}: no pose checked", scene.name);
    println!(
        "closure {:>12} {scalar}: {checked} poses, worst residual {worst:.3e} = {:.2} eps * size ({worst_at})",
        scene.name,
        worst / (eps * scene.size)
    );
    worst / (eps * scene.size)
}

#[test]
fn loop_closure_f64() {
    for scene in scenes() {
        check_closure(&scene, scene.eval64, f64::EPSILON, "f64");
    }
}

#[test]
fn loop_closure_f32() {
    for scene in scenes() {
        check_closure(&scene, scene.eval32, f32::EPSILON as f64, "f32");
    }
}

// ---------------------------------------------------------------------------
// 2. Derivatives against finite differences.

/// Step of the inputs (rad) per finite-difference step: the time step is
/// `h = DQ / max |w|`, so that the pose moves by DQ rad in the fastest input.
///
/// A central difference errs by the truncation `h^2 |f'''| / 6` plus the
/// rounding of `f` at both ends, up to about `2 eps |f|` each, so
/// `2 eps |f| / h` after the division by `2 h`. In the input angle q and
/// relative to the column's largest
/// derivative `|f'|`, that is `K DQ^2 / 6 + 2 eps R / DQ` with
/// - `K`, the ratio of the third derivative to the first (rad^-2): up to about
///   2e3 for the six-bar near 55 deg (it nears its limit position, where its
///   rates change fastest), 1.5e2 for the five-bar at (60, 90) deg (A nearly on
///   C), 10 to 25 for the others (estimated from how the differences converge
///   as DQ shrinks: they fall by 4 per halving until rounding takes over);
/// - `R`, the ratio of a column's magnitude to its rate per radian: at most
///   about 10 (a link angle up to pi turning at a third of the input's rate; a
///   slider 0.5 m from the origin moving 0.1 m/rad).
///
/// `DQ = 2e-6` balances the two for the six-bar.
const DQ: f64 = 2e-6;

/// The bound above with `K = 4e3`, `R = 10`: 2.7e-9 + 2.2e-9 = 4.9e-9, relative
/// to the column's largest analytic value. A wrong or missing term in a
/// velocity or acceleration formula errs by a fraction of the column, many
/// orders above this.
const FD_REL_TOL: f64 = 4e3 * DQ * DQ / 6.0 + 2.0 * 10.0 * f64::EPSILON / DQ;

fn check_derivatives(scene: &Scene) -> (f64, f64) {
    let mut all_worst = (0.0f64, 0.0f64);
    for (w, alpha) in &scene.motions {
        let h = DQ / w.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let at = |q0: &[f64], t: f64| {
            let q: Vec<f64> = (0..q0.len())
                .map(|i| q0[i] + w[i] * t + 0.5 * alpha[i] * t * t)
                .collect();
            let rate: Vec<f64> = (0..q0.len()).map(|i| w[i] + alpha[i] * t).collect();
            (scene.eval64)(&q, &rate, alpha)
        };
        let (mut vel, mut vel_fd, mut acc, mut acc_fd, mut labels) =
            (vec![], vec![], vec![], vec![], vec![]);
        for q0 in &scene.poses {
            let (s0, sp, sm) = match (at(q0, 0.0), at(q0, h), at(q0, -h)) {
                (Ok(a), Ok(b), Ok(c)) => (a, b, c),
                (r0, rp, rm) => {
                    let e = r0.err().or(rp.err()).or(rm.err());
                    assert!(
                        scene.may_fail,
                        "{} fails near {}: {e:?}",
                        scene.name,
                        label(q0)
                    );
                    continue;
                }
            };
            let fd_v: Vec<f64> = scene
                .columns
                .iter()
                .enumerate()
                .map(|(i, (_, kind))| {
                    let d = sp.pos[i] - sm.pos[i];
                    let d = if *kind == Kind::Angle { wrap(d) } else { d };
                    d / (2.0 * h)
                })
                .collect();
            let fd_a: Vec<f64> = (0..scene.columns.len())
                .map(|i| (sp.vel[i] - sm.vel[i]) / (2.0 * h))
                .collect();
            vel.push(s0.vel);
            vel_fd.push(fd_v);
            acc.push(s0.acc);
            acc_fd.push(fd_a);
            labels.push(label(q0));
        }
        assert!(
            labels.len() * 2 > scene.poses.len(),
            "{}: only {} of {} poses checked",
            scene.name,
            labels.len(),
            scene.poses.len()
        );
        for (what, an, fd) in [("velocity", &vel, &vel_fd), ("acceleration", &acc, &acc_fd)] {
            let scales = column_scales(scene.columns, an);
            let worst = worst_per_column(an, fd, &scales, &labels);
            for ((name, _), (wst, sc)) in scene.columns.iter().zip(worst.iter().zip(&scales)) {
                assert!(
                    wst.rel <= FD_REL_TOL,
                    "{} {what} of {name} (rates {w:?}, accelerations {alpha:?}) differs from the finite difference by {:.3e} of its largest value {sc:.4e} at {} (tolerance {FD_REL_TOL:.2e})",
                    scene.name,
                    wst.rel,
                    wst.at
                );
            }
            let (col, wmax) = scene
                .columns
                .iter()
                .zip(&worst)
                .max_by(|a, b| a.1.rel.total_cmp(&b.1.rel))
                .expect("columns");
            println!(
                "fd {:>12} {what:>12} w={w:?} a={alpha:?}: worst {:.3e} ({} at {})",
                scene.name, wmax.rel, col.0, wmax.at
            );
            if what == "velocity" {
                all_worst.0 = all_worst.0.max(wmax.rel);
            } else {
                all_worst.1 = all_worst.1.max(wmax.rel);
            }
        }
    }
    all_worst
}

#[test]
fn velocity_and_acceleration_match_finite_differences() {
    for scene in scenes() {
        check_derivatives(&scene);
    }
}

// ---------------------------------------------------------------------------
// 3. f32 against f64.

/// Tolerance of f32 against f64, relative to the f64 column's largest value,
/// for positions, velocities and accelerations (both get the same inputs, exact
/// in f32, so only the arithmetic and the f32 rounding of the definition's
/// constants differ). f32 rounds at eps = 1.2e-7; each output is a chain of a
/// few tens of operations, and the conditioning (1 / sin of the transmission
/// angle, the ratio of a link's rate to the input's, the cancellation between
/// the omega^2 and alpha terms of an acceleration) multiplies that by up to
/// about 60 here: the six-bar near 55 deg, close to its limit position, where
/// its block's acceleration is a difference of large terms (6.8e-6 observed;
/// the other mechanisms stay below 2.6e-6, most below 1e-6). 2e-5 leaves a
/// factor of 3 over the worst case.
const F32_REL_TOL: [f64; 3] = [2e-5, 2e-5, 2e-5];

fn check_f32(scene: &Scene) -> [f64; 3] {
    let mut worst_all = [0.0f64; 3];
    for (w, alpha) in &scene.motions {
        // Inputs exactly representable in f32, so that only the arithmetic differs.
        let w32: Vec<f64> = w.iter().map(|&x| through_f32(x)).collect();
        let a32: Vec<f64> = alpha.iter().map(|&x| through_f32(x)).collect();
        let mut rows64: [Vec<Vec<f64>>; 3] = Default::default();
        let mut rows32: [Vec<Vec<f64>>; 3] = Default::default();
        let mut labels = vec![];
        for q in &scene.poses {
            let q: Vec<f64> = q.iter().map(|&x| through_f32(x)).collect();
            let (s64, s32) = match (
                (scene.eval64)(&q, &w32, &a32),
                (scene.eval32)(&q, &w32, &a32),
            ) {
                (Ok(a), Ok(b)) => (a, b),
                (r64, r32) => {
                    assert!(
                        scene.may_fail,
                        "{} fails at {}: f64 {:?}, f32 {:?}",
                        scene.name,
                        label(&q),
                        r64.err(),
                        r32.err()
                    );
                    continue;
                }
            };
            assert_all_finite(scene.name, &s32, &label(&q));
            // Angles: compare the f32 angle unwrapped to the f64 one.
            let pos32: Vec<f64> = scene
                .columns
                .iter()
                .enumerate()
                .map(|(i, (_, kind))| match kind {
                    Kind::Angle => s64.pos[i] + wrap(s32.pos[i] - s64.pos[i]),
                    Kind::Length => s32.pos[i],
                })
                .collect();
            rows64[0].push(s64.pos);
            rows64[1].push(s64.vel);
            rows64[2].push(s64.acc);
            rows32[0].push(pos32);
            rows32[1].push(s32.vel);
            rows32[2].push(s32.acc);
            labels.push(label(&q));
        }
        assert!(!labels.is_empty(), "{}: no pose compared", scene.name);
        for (k, what) in ["position", "velocity", "acceleration"].iter().enumerate() {
            let scales = column_scales(scene.columns, &rows64[k]);
            let worst = worst_per_column(&rows64[k], &rows32[k], &scales, &labels);
            for ((name, _), wst) in scene.columns.iter().zip(&worst) {
                assert!(
                    wst.rel <= F32_REL_TOL[k],
                    "{} f32 {what} of {name} (rates {w:?}, accelerations {alpha:?}) differs from f64 by {:.3e} of the column's largest value at {} (tolerance {:e})",
                    scene.name,
                    wst.rel,
                    wst.at,
                    F32_REL_TOL[k]
                );
                worst_all[k] = worst_all[k].max(wst.rel);
            }
            let (col, wmax) = scene
                .columns
                .iter()
                .zip(&worst)
                .max_by(|a, b| a.1.rel.total_cmp(&b.1.rel))
                .expect("columns");
            println!(
                "f32 {:>12} {what:>12} w={w:?} a={alpha:?}: worst {:.3e} ({} at {})",
                scene.name, wmax.rel, col.0, wmax.at
            );
        }
    }
    worst_all
}

#[test]
fn f32_agrees_with_f64() {
    for scene in scenes() {
        check_f32(&scene);
    }
}

// ---------------------------------------------------------------------------
// 4. The documents' values (docs/seeds.md), and a closed form.

/// Asserts `|value - printed| <= tol`, naming the quantity.
fn assert_printed(what: &str, value: f64, printed: f64, tol: f64) {
    assert!(
        (value - printed).abs() <= tol,
        "{what}: ours {value:.8}, the document prints {printed} (tolerance {tol:e}, off by {:.3e})",
        (value - printed).abs()
    );
}

/// Seed 002 at theta2 = 0: theta3 = 44.05 deg, theta4 = 96.67 deg, printed to
/// two decimals (tolerance half a unit of the last digit).
#[test]
fn seed_002_fourbar_document_values() {
    let p = FourBar::<f64>::default()
        .position(&FourBarInput { theta2: 0.0 })
        .expect("assembles at theta2 = 0");
    assert_printed("theta3 (deg)", deg_0_360(p.link3), 44.05, 0.005);
    assert_printed("theta4 (deg)", deg_0_360(p.link4), 96.67, 0.005);
    // The same from the points, the document's definition of the angles.
    assert_printed(
        "angle(B - A) (deg)",
        deg_0_360(angle_of(sub(pt(&p.B), pt(&p.A)))),
        44.05,
        0.005,
    );
    assert_printed(
        "angle(B - O4) (deg)",
        deg_0_360(angle_of(sub(pt(&p.B), pt(&p.O4)))),
        96.67,
        0.005,
    );
}

/// Seed 000, problem 3-28, at phi1 = 40 deg: theta2 = 41.04, theta3 = 145.85,
/// theta4 = 88.58 deg, af = 93.31 mm (two decimals).
#[test]
fn seed_000_sixbar_document_values_at_40_deg() {
    let p = SixBar::<f64>::default()
        .position(&SixBarInput {
            phi1: 40f64.to_radians(),
        })
        .expect("assembles at 40 deg");
    assert_printed("theta2 (deg)", deg_0_360(p.link2), 41.04, 0.005);
    assert_printed("theta3 (deg)", deg_0_360(p.link3), 145.85, 0.005);
    assert_printed("theta4 (deg)", deg_0_360(p.link4), 88.58, 0.005);
    assert_printed("af (mm)", p.af, 93.31, 0.005);
}

/// The document's whole table (seed 000, its `p` and `q` results) over its
/// `linspace(40, 55, 15)`: af (mm), theta2..4 (rad) and omega2..4 (rad/s) to
/// four decimals, the slider speed printed x1e3 to four decimals (0.1 mm/s).
/// Its accelerations are wrong (docs/seeds.md) and are not compared here; the
/// finite-difference test checks ours.
#[test]
fn seed_000_sixbar_document_table() {
    const AF: [f64; 15] = [
        93.3149, 91.3071, 89.2387, 87.1076, 84.9113, 82.6463, 80.3086, 77.8931, 75.3930, 72.7998,
        70.1019, 67.2833, 64.3217, 61.1835, 57.8153,
    ];
    const THETA2: [f64; 15] = [
        0.7163, 0.7045, 0.6929, 0.6815, 0.6703, 0.6592, 0.6482, 0.6372, 0.6263, 0.6154, 0.6043,
        0.5930, 0.5812, 0.5687, 0.5551,
    ];
    const THETA3: [f64; 15] = [
        2.5455, 2.5617, 2.5786, 2.5963, 2.6147, 2.6339, 2.6539, 2.6747, 2.6965, 2.7192, 2.7431,
        2.7683, 2.7950, 2.8237, 2.8549,
    ];
    const THETA4: [f64; 15] = [
        1.5461, 1.5902, 1.6347, 1.6796, 1.7250, 1.7709, 1.8174, 1.8646, 1.9126, 1.9616, 2.0118,
        2.0635, 2.1169, 2.1728, 2.2319,
    ];
    const OMEGA2: [f64; 15] = [
        -6.3578, -6.2487, -6.1469, -6.0541, -5.9726, -5.9054, -5.8561, -5.8299, -5.8340, -5.8786,
        -5.9789, -6.1587, -6.4572, -6.9440, -7.7555,
    ];
    const OMEGA3: [f64; 15] = [
        8.4725, 8.8575, 9.2469, 9.6433, 10.0502, 10.4720, 10.9145, 11.3856, 11.8957, 12.4601,
        13.1005, 13.8507, 14.7646, 15.9364, 17.5470,
    ];
    const OMEGA4: [f64; 15] = [
        23.5099, 23.6948, 23.9018, 24.1350, 24.3994, 24.7013, 25.0491, 25.4538, 25.9305, 26.5003,
        27.1937, 28.0569, 29.1637, 30.6408, 32.7288,
    ];
    const V_E3: [f64; 15] = [
        -1.0578, -1.0897, -1.1226, -1.1568, -1.1926, -1.2302, -1.2704, -1.3137, -1.3610, -1.4136,
        -1.4734, -1.5431, -1.6273, -1.7337, -1.8767,
    ];
    let m = SixBar::<f64>::default();
    let half = 0.5e-4;
    for (k, phi1) in sixbar_linspace().into_iter().enumerate() {
        let p = m.position(&SixBarInput { phi1 }).expect("assembles");
        let v = m
            .velocity(&p, &SixBarInput { phi1: 10.0 })
            .expect("velocity");
        let at = |what: &str| format!("{what} at phi1 = {:.4} deg (column {k})", phi1.to_degrees());
        assert_printed(&at("af (mm)"), p.af, AF[k], half);
        assert_printed(&at("theta2 (rad)"), p.link2, THETA2[k], half);
        assert_printed(&at("theta3 (rad)"), p.link3, THETA3[k], half);
        assert_printed(&at("theta4 (rad)"), p.link4, THETA4[k], half);
        assert_printed(&at("omega2 (rad/s)"), v.link2, OMEGA2[k], half);
        assert_printed(&at("omega3 (rad/s)"), v.link3, OMEGA3[k], half);
        assert_printed(&at("omega4 (rad/s)"), v.link4, OMEGA4[k], half);
        assert_printed(&at("v_f (1e3 mm/s)"), v.af / 1e3, V_E3[k], half);
    }
}

/// Seed 001 at crank 0: CT3 = 65.556 deg, CV3 = 0.171233 rad/s,
/// CA3 = 0.247701 rad/s^2, CT4 = 168.938 deg, Xe = 0.101069 m: a tolerance of
/// half a unit of the last printed digit.
#[test]
fn seed_001_shaper_document_values() {
    let s = Shaper::<f64>::default()
        .solve(
            &ShaperInput { crank: 0.0 },
            &ShaperInput { crank: 1.0 },
            &ShaperInput { crank: 0.0 },
        )
        .expect("assembles at crank 0");
    let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
    assert_printed("theta3 (deg)", deg_0_360(p.link3), 65.556, 0.0005);
    assert_printed("omega3 (rad/s)", v.link3, 0.171233, 0.5e-6);
    assert_printed("alpha3 (rad/s^2)", a.link3, 0.247701, 0.5e-6);
    assert_printed("theta4 (deg)", deg_0_360(p.link4), 168.938, 0.0005);
    assert_printed("x_e (m)", p.E.x, 0.101069, 0.5e-6);
}

/// The offset slider-crank against its closed form, written here by hand:
/// with `c = r cos(theta)`, `s = r sin(theta) - e`, `D = sqrt(l^2 - s^2)`,
/// `x = c + D`; `dx/dtheta = -r sin(theta) - s c / D`,
/// `d2x/dtheta2 = -c - (c^2 - s r sin(theta)) / D - s^2 c^2 / D^3`; the rod's
/// angle `phi = atan2(-s, D)`, `dphi/dtheta = -c / D`,
/// `d2phi/dtheta2 = r sin(theta) / D - s c^2 / D^3`; and
/// `xdot = w x'`, `xddot = a x' + w^2 x''` (likewise for phi).
/// Both sides are well conditioned here (D >= 0.28 m against l = 0.4 m) and a
/// handful of operations each, so they agree to a few eps times the column's
/// largest value: 16 eps (about 1.3 eps observed).
#[test]
fn slider_crank_closed_form() {
    let (r, l, e) = (0.1, 0.4, 0.02);
    let m = SliderCrank::<f64>::default();
    let tol = 16.0 * f64::EPSILON;
    for alpha in [0.0, 5.0e4, -3.0e5] {
        let w = RPM_3000;
        let mut ours = vec![];
        let mut hand = vec![];
        let mut labels = vec![];
        for q in deg_range(0.0, 350.0, 10.0) {
            let th = q[0];
            let s = m
                .solve(
                    &SliderCrankInput { theta: th },
                    &SliderCrankInput { theta: w },
                    &SliderCrankInput { theta: alpha },
                )
                .expect("assembles everywhere");
            let (c, sn) = (r * th.cos(), r * th.sin());
            let s_ = sn - e;
            let d = (l * l - s_ * s_).sqrt();
            let x = c + d;
            let x1 = -sn - s_ * c / d;
            let x2 = -c - (c * c - s_ * sn) / d - s_ * s_ * c * c / (d * d * d);
            let phi = (-s_).atan2(d);
            let phi1 = -c / d;
            let phi2 = sn / d - s_ * c * c / (d * d * d);
            let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
            ours.push(vec![
                p.x, p.B.x, p.link3, v.x, v.B.x, v.link3, a.x, a.B.x, a.link3,
            ]);
            hand.push(vec![
                x,
                x,
                phi,
                w * x1,
                w * x1,
                w * phi1,
                alpha * x1 + w * w * x2,
                alpha * x1 + w * w * x2,
                alpha * phi1 + w * w * phi2,
            ]);
            labels.push(label(&q));
        }
        const COLS: [(&str, Kind); 9] = [
            ("x", Kind::Length),
            ("B.x", Kind::Length),
            ("link3", Kind::Angle),
            ("v x", Kind::Length),
            ("v B.x", Kind::Length),
            ("omega3", Kind::Angle),
            ("a x", Kind::Length),
            ("a B.x", Kind::Length),
            ("alpha3", Kind::Angle),
        ];
        let scales: Vec<f64> = (0..COLS.len())
            .map(|i| hand.iter().fold(0.0f64, |m, row| m.max(row[i].abs())))
            .collect();
        let worst = worst_per_column(&hand, &ours, &scales, &labels);
        for ((name, _), wst) in COLS.iter().zip(&worst) {
            assert!(
                wst.rel <= tol,
                "slider-crank {name} (alpha = {alpha}) differs from the closed form by {:.3e} of the column's largest value at {} (tolerance {tol:e})",
                wst.rel,
                wst.at
            );
        }
        let wmax = worst.iter().map(|w| w.rel).fold(0.0, f64::max);
        println!(
            "closed form slider_crank alpha={alpha}: worst {wmax:.3e} = {:.1} eps",
            wmax / f64::EPSILON
        );
    }
}

// ---------------------------------------------------------------------------
// 5. The five-bar's typed errors.

/// With the defaults (proximal 0.1, distal 0.16, base 0.08) every pose
/// assembles: |A - C| <= 0.1 + 0.08 + 0.1 = 0.28 < 2 * 0.16, and
/// |l1 - l2| = 0. The only failure is A on C (the circles about O1 and O2 meet),
/// where the direction A -> C is undefined. So the grid of the example must be
/// all `Ok`, and over the whole plane of inputs every result is `Ok` with
/// finite values or a typed error of group `P`.
#[test]
fn five_bar_grid_all_assemble_and_no_nan_anywhere() {
    let m = FiveBar::<f64>::default();
    let rates = FiveBarInput { q1: 1.0, q2: -0.5 };
    let accels = FiveBarInput { q1: 3.0, q2: 2.0 };
    for i in 0..=6 {
        for j in 0..=6 {
            let input = FiveBarInput {
                q1: (60.0 + 15.0 * i as f64).to_radians(),
                q2: (15.0 * j as f64).to_radians(),
            };
            let s = m.solve(&input, &rates, &accels);
            assert!(s.is_ok(), "grid pose {input:?}: {:?}", s.err());
        }
    }
    let mut errors = 0;
    for i in 0..360 {
        for j in 0..360 {
            let input = FiveBarInput {
                q1: (i as f64).to_radians(),
                q2: (j as f64).to_radians(),
            };
            match m.solve(&input, &rates, &accels) {
                Ok(s) => {
                    let p = &s.position.P;
                    let (v, a) = (&s.velocity.P, &s.acceleration.P);
                    assert!(
                        [p.x, p.y, v.x, v.y, a.x, a.y].iter().all(|x| x.is_finite()),
                        "non-finite Ok at {input:?}: {s:?}"
                    );
                }
                Err(e) => {
                    errors += 1;
                    assert_eq!(e.group, "P", "{input:?}: {e}");
                    assert!(
                        matches!(e.fault, Fault::Singular { .. }),
                        "{input:?}: only the A-on-C pose may fail, got {e}"
                    );
                }
            }
        }
    }
    println!("five_bar: {errors} of 129600 whole-degree poses are Singular (A on C)");
}

/// An unreachable pose: with the run-time parameter `distal` shortened to 0.1,
/// q1 = 180 deg, q2 = 0 puts A = (-0.1, 0) and C = (0.18, 0), 0.28 apart,
/// beyond 2 * 0.1: `CannotAssemble` in group `P` by 0.08, bound 0.2, in f64 and
/// in f32. Over the whole plane of inputs, a pose is `Ok` exactly when
/// |A - C| <= 0.2 (independently computed; poses within 1e-9 of the bound are
/// left out), and no `Ok` holds NaN.
#[test]
fn five_bar_unreachable_pose_is_a_typed_error() {
    let m = FiveBar::<f64> {
        distal: 0.1,
        ..FiveBar::default()
    };
    let pose = FiveBarInput { q1: PI, q2: 0.0 };
    let e = m.position(&pose).expect_err("0.28 apart, reach 0.2");
    assert_eq!(e.group, "P", "{e}");
    assert_eq!(e.primitive, Primitive::Rrr, "{e}");
    match e.fault {
        Fault::CannotAssemble { miss, reach } => {
            assert!((miss - 0.08).abs() <= 1e-15, "miss {miss}");
            assert!((reach - 0.2).abs() <= 1e-15, "reach {reach}");
        }
        f => panic!("expected CannotAssemble, got {f:?}"),
    }
    let rendered = e.to_string();
    assert!(
        rendered.contains("`P`"),
        "the message names the group: {rendered}"
    );

    let m32 = FiveBar::<f32> {
        distal: 0.1,
        ..FiveBar::default()
    };
    let e32 = m32
        .position(&FiveBarInput {
            q1: std::f32::consts::PI,
            q2: 0.0,
        })
        .expect_err("unreachable in f32 too");
    assert_eq!((e32.group, e32.primitive), ("P", Primitive::Rrr));
    assert!(matches!(e32.fault, Fault::CannotAssemble { miss, .. } if (miss - 0.08).abs() < 1e-6));

    let (mut ok, mut err) = (0, 0);
    for i in 0..360 {
        for j in 0..360 {
            let (q1, q2) = ((i as f64).to_radians(), (j as f64).to_radians());
            let dist = norm(sub(
                add([0.08, 0.0], scale(0.1, unit(q2))),
                scale(0.1, unit(q1)),
            ));
            let result = m.solve(
                &FiveBarInput { q1, q2 },
                &FiveBarInput { q1: 1.0, q2: 1.0 },
                &FiveBarInput { q1: 0.5, q2: -0.5 },
            );
            if (dist - 0.2).abs() < 1e-9 {
                continue;
            }
            match result {
                Ok(s) => {
                    ok += 1;
                    assert!(dist < 0.2, "Ok at {i}, {j} deg with |A - C| = {dist}");
                    let p = &s.position.P;
                    assert!(p.x.is_finite() && p.y.is_finite());
                    assert!((norm(sub(pt(p), pt(&s.position.A))) - 0.1).abs() < 1e-14);
                }
                Err(e) => {
                    err += 1;
                    assert_eq!(e.group, "P", "{e}");
                    match e.fault {
                        Fault::CannotAssemble { miss, reach } => {
                            assert!(
                                dist > 0.2,
                                "CannotAssemble at {i}, {j} deg with |A - C| = {dist}"
                            );
                            assert!(
                                (miss - (dist - 0.2)).abs() < 1e-14,
                                "miss {miss} for {dist}"
                            );
                            assert!((reach - 0.2).abs() < 1e-15);
                        }
                        f => panic!("unexpected fault {f:?} at {i}, {j} deg"),
                    }
                }
            }
        }
    }
    assert!(ok > 0 && err > 0, "both outcomes occur: {ok} Ok, {err} Err");
    println!("five_bar (distal 0.1): {ok} Ok, {err} Err over whole degrees");
}

/// The generated `condition` of the seed 002 four-bar's velocity is the RRR
/// group's scaled determinant, `|sin|` of the transmission angle between
/// coupler and rocker, computed here from the positions alone. Both are
/// products of a few roundings of unit-size quantities: 1e-14 leaves 50 ulp.
/// The crank-rocker never reaches toggle, so the indicator stays away from 0:
/// its minimum is at theta2 = 180 deg (in the grid), where the diagonal
/// A-O4 is d + a and the law of cosines gives the transmission angle.
#[test]
fn velocity_condition_is_the_transmission_angle_sine() {
    let fb = FourBar::<f64>::default();
    let mut lowest = f64::MAX;
    for step in 0..360 {
        let theta2 = (step as f64).to_radians();
        let p = fb.position(&FourBarInput { theta2 }).unwrap();
        let v = fb.velocity(&p, &FourBarInput { theta2: 250.0 }).unwrap();
        let (coupler, rocker) = (p.B - p.A, p.B - p.O4);
        let sine =
            (coupler.x * rocker.y - coupler.y * rocker.x).abs() / (coupler.norm() * rocker.norm());
        assert!(
            (v.condition - sine).abs() < 1e-14,
            "{step}: {} vs {sine}",
            v.condition
        );
        lowest = lowest.min(v.condition);
    }
    let (a, b, c, d) = (101.6f64, 254.0f64, 177.8f64, 304.8f64);
    let cos_mu = (b * b + c * c - (d + a) * (d + a)) / (2.0 * b * c);
    let worst = (1.0 - cos_mu * cos_mu).sqrt();
    assert!((lowest - worst).abs() < 1e-14, "lowest {lowest} vs {worst}");
}
