//! The methods compared per scene: the generated code (f64, f32; the
//! four-bar also without angle outputs) and, for the four-bar, the baselines
//! of `benches/common/baselines.rs` and numpy.

use crate::baselines::{self, FourBarOut, SliderCrankOut, COUPLER, CRANK};
use crate::generated::{self, Sample};
use crate::reference::Scene;
use crate::scenes::*;
use crate::timing::Sweep;
use crate::variants::{FourBarPoints, FourBarPointsInput};
use crate::Errors;
use std::hint::black_box;
use std::path::Path;

/// Scalar type of a method.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Precision {
    F64,
    F32,
}

/// One compared method.
pub struct Method<'a> {
    pub family: String,
    pub name: String,
    pub precision: Precision,
    /// Its answer at every grid point (in grid order, warm starts sequential).
    pub samples: Vec<Option<Sample>>,
    /// The timed sweep (`None`: timed elsewhere, e.g. numpy).
    pub sweep: Option<Sweep<'a>>,
    /// ns per evaluation, one per round.
    pub ns: Vec<f64>,
    pub errors: Errors,
}

pub fn method<'a>(
    family: &str,
    name: &str,
    precision: Precision,
    samples: Vec<Option<Sample>>,
    sweep: Option<Sweep<'a>>,
) -> Method<'a> {
    Method {
        family: family.into(),
        name: name.into(),
        precision,
        samples,
        sweep,
        ns: Vec::new(),
        errors: Errors::default(),
    }
}

/// Sweep of a generated scene: `solve` at every grid point, summing the
/// compared outputs (the same consumer for every method).
macro_rules! gen_method {
    ($scene:expr, $ty:ident, $in:ident { $($f:ident),* }, $t:ty, $prec:expr, $sample:path, $family:expr, $name:expr, |$s:ident| $sum:expr) => {{
        let m = $ty::<$t>::default();
        let grid: Vec<Vec<f64>> = $scene.grid.clone();
        let (w, a) = ($scene.rates.clone(), $scene.accels.clone());
        let samples: Vec<Option<Sample>> = grid.iter().map(|q| $sample(&m, q, &w, &a)).collect();
        let mk = |x: &[f64]| {
            let mut k = 0;
            $(let $f = x[k] as $t; k += 1;)*
            let _ = k;
            $in { $($f),* }
        };
        let inputs: Vec<$in<$t>> = grid.iter().map(|q| mk(q)).collect();
        let (wi, ai) = (mk(&w), mk(&a));
        let sweep: Sweep = Box::new(move || {
            let mut acc: $t = 0.0;
            for i in &inputs {
                if let Ok($s) = m.solve(i, &wi, &ai) {
                    acc += $sum;
                }
            }
            black_box(acc) as f64
        });
        method($family, $name, $prec, samples, Some(sweep))
    }};
}

/// [`gen_method!`] in `f64` and in `f32` (families and names given per
/// precision), pushed onto `$v`: the two share the definition, the sample
/// function and the summed outputs.
macro_rules! gen_pair {
    ($v:expr, $scene:expr, $ty:ident, $in:ident { $($f:ident),* }, $sample:path, [$fam64:expr, $name64:expr], [$fam32:expr, $name32:expr], |$s:ident| $sum:expr) => {
        $v.push(gen_method!($scene, $ty, $in { $($f),* }, f64, F64, $sample, $fam64, $name64, |$s| $sum));
        $v.push(gen_method!($scene, $ty, $in { $($f),* }, f32, F32, $sample, $fam32, $name32, |$s| $sum));
    };
}

fn fourbar_out_sample(q: f64, o: &FourBarOut<f64>) -> Sample {
    let a = (CRANK * q.cos(), CRANK * q.sin());
    let b = (a.0 + COUPLER * o.t3.cos(), a.1 + COUPLER * o.t3.sin());
    Sample {
        cols: vec![
            None,
            None,
            Some(o.t3),
            Some(o.t4),
            None,
            None,
            Some(o.w3),
            Some(o.w4),
            None,
            None,
            Some(o.al3),
            Some(o.al4),
        ],
        points: vec![(0.0, 0.0), (baselines::GROUND, 0.0), a, b],
    }
}

fn widen(o: FourBarOut<f32>) -> FourBarOut<f64> {
    FourBarOut {
        t3: o.t3 as f64,
        t4: o.t4 as f64,
        w3: o.w3 as f64,
        w4: o.w4 as f64,
        al3: o.al3 as f64,
        al4: o.al4 as f64,
    }
}

/// Newton tolerances of the work-precision curves (rad).
pub const TOLERANCES: [f64; 12] = [
    1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13, 1e-14,
];

type NewtonFn = fn(f64, f64, f64, (f64, f64), f64) -> Option<FourBarOut<f64>>;

fn newton_method<'a>(
    family: &str,
    f: NewtonFn,
    tol: f64,
    grid: &'a [Vec<f64>],
    w: f64,
    a: f64,
) -> Method<'a> {
    // Warm start: the previous grid point's answer (the first from the last
    // point's closed form: the grid wraps around with the same step).
    let first = {
        let o = baselines::closed_form(grid[grid.len() - 1][0], w, a);
        (o.t3, o.t4)
    };
    let mut guess = first;
    let samples = grid
        .iter()
        .map(|q| {
            let o = f(q[0], w, a, guess, tol)?;
            guess = (o.t3, o.t4);
            Some(fourbar_out_sample(q[0], &o))
        })
        .collect();
    let sweep: Sweep = Box::new(move || {
        let mut g = first;
        let mut acc = 0.0;
        for q in grid {
            if let Some(o) = f(q[0], w, a, g, tol) {
                g = (o.t3, o.t4);
                acc += o.t3 + o.t4 + o.w3 + o.w4 + o.al3 + o.al4;
            }
        }
        black_box(acc)
    });
    method(
        family,
        &format!("{family} tol {tol:.0e}"),
        Precision::F64,
        samples,
        Some(sweep),
    )
}

/// A sample of the hand-written slider-crank (the generated scene's columns:
/// B, the rod's angle, their rates and accelerations).
fn slider_crank_sample(q: f64, o: &SliderCrankOut<f64>) -> Sample {
    let a = (
        baselines::SLIDER_CRANK * q.cos(),
        baselines::SLIDER_CRANK * q.sin(),
    );
    let e = baselines::SLIDER_OFFSET;
    Sample {
        cols: [
            o.b.0, o.b.1, o.t3, o.vb.0, o.vb.1, o.w3, o.ab.0, o.ab.1, o.al3,
        ]
        .map(Some)
        .to_vec(),
        points: vec![(0.0, 0.0), (0.0, e), (1.0, e), a, o.b],
    }
}

/// The hand-written closed form of the slider-crank, f64 and f32
/// (`baselines::slider_crank_closed_form`); the checksum sums the same
/// outputs as the generated rows'.
fn slider_crank_closed_forms(scene: &Scene) -> Vec<Method<'_>> {
    use baselines::slider_crank_closed_form as cf;
    let (w, a) = (scene.rates[0], scene.accels[0]);
    let grid = &scene.grid;
    let samples = grid
        .iter()
        .map(|q| Some(slider_crank_sample(q[0], &cf(q[0], w, a))))
        .collect();
    let sweep: Sweep = Box::new(move || {
        let mut acc = 0.0;
        for q in grid {
            let o = cf(black_box(q[0]), w, a);
            acc += o.b.0 + o.t3 + o.vb.0 + o.w3 + o.ab.0 + o.al3;
        }
        black_box(acc)
    });
    let m64 = method(
        "hand-written closed form",
        "hand-written closed form f64",
        Precision::F64,
        samples,
        Some(sweep),
    );
    let g32: Vec<f32> = grid.iter().map(|q| q[0] as f32).collect();
    let (w32, a32) = (w as f32, a as f32);
    let samples = g32
        .iter()
        .map(|&q| {
            let o = cf(q, w32, a32);
            let f = |x: f32| x as f64;
            let o = SliderCrankOut {
                b: (f(o.b.0), f(o.b.1)),
                vb: (f(o.vb.0), f(o.vb.1)),
                ab: (f(o.ab.0), f(o.ab.1)),
                t3: f(o.t3),
                w3: f(o.w3),
                al3: f(o.al3),
            };
            Some(slider_crank_sample(q as f64, &o))
        })
        .collect();
    let sweep: Sweep = Box::new(move || {
        let mut acc = 0.0f32;
        for &q in &g32 {
            let o = cf(black_box(q), w32, a32);
            acc += o.b.0 + o.t3 + o.vb.0 + o.w3 + o.ab.0 + o.al3;
        }
        black_box(acc) as f64
    });
    let m32 = method(
        "hand-written closed form",
        "hand-written closed form f32",
        Precision::F32,
        samples,
        Some(sweep),
    );
    vec![m64, m32]
}

/// The four-bar's methods: the generated code with and without angle
/// outputs, the hand-written closed form, the Newton baselines at every
/// tolerance and numpy (when available).
fn fourbar_methods<'a>(v: &mut Vec<Method<'a>>, scene: &'a Scene, out_dir: &Path) {
    use Precision::*;
    gen_pair!(
        v,
        scene,
        FourBar,
        FourBarInput { theta2 },
        generated::fourbar,
        ["generated f64", "generated f64"],
        ["generated f32", "generated f32"],
        |s| s.position.B.x
            + s.position.B.y
            + s.position.link3
            + s.position.link4
            + s.velocity.B.x
            + s.velocity.B.y
            + s.velocity.link3
            + s.velocity.link4
            + s.acceleration.B.x
            + s.acceleration.B.y
            + s.acceleration.link3
            + s.acceleration.link4
    );
    gen_pair!(
        v,
        scene,
        FourBarPoints,
        FourBarPointsInput { theta2 },
        generated::fourbar_points,
        ["generated, no angles", "generated f64, no angle outputs"],
        ["generated, no angles", "generated f32, no angle outputs"],
        |s| s.position.B.x
            + s.position.B.y
            + s.velocity.B.x
            + s.velocity.B.y
            + s.acceleration.B.x
            + s.acceleration.B.y
    );
    let (w, a) = (scene.rates[0], scene.accels[0]);
    let grid = &scene.grid;
    // Hand-written closed form, f64 and f32.
    let samples = grid
        .iter()
        .map(|q| {
            Some(fourbar_out_sample(
                q[0],
                &baselines::closed_form(q[0], w, a),
            ))
        })
        .collect();
    let sweep: Sweep = Box::new(move || {
        let mut acc = 0.0;
        for q in grid {
            let o = baselines::closed_form(q[0], w, a);
            acc += o.t3 + o.t4 + o.w3 + o.w4 + o.al3 + o.al4;
        }
        black_box(acc)
    });
    v.push(method(
        "hand-written closed form",
        "hand-written closed form f64",
        F64,
        samples,
        Some(sweep),
    ));
    let g32: Vec<f32> = grid.iter().map(|q| q[0] as f32).collect();
    let samples = g32
        .iter()
        .map(|&q| {
            let o = widen(baselines::closed_form(q, w as f32, a as f32));
            Some(fourbar_out_sample(q as f64, &o))
        })
        .collect();
    let (w32, a32) = (w as f32, a as f32);
    let sweep: Sweep = Box::new(move || {
        let mut acc = 0.0f32;
        for &q in &g32 {
            let o = baselines::closed_form(q, w32, a32);
            acc += o.t3 + o.t4 + o.w3 + o.w4 + o.al3 + o.al4;
        }
        black_box(acc) as f64
    });
    v.push(method(
        "hand-written closed form",
        "hand-written closed form f32",
        F32,
        samples,
        Some(sweep),
    ));
    for tol in TOLERANCES {
        v.push(newton_method(
            "Newton, nalgebra Matrix2",
            baselines::newton_fixed::<f64>,
            tol,
            grid,
            w,
            a,
        ));
    }
    for tol in TOLERANCES {
        v.push(newton_method(
            "Newton, heap DMatrix LU",
            baselines::newton_heap::<f64>,
            tol,
            grid,
            w,
            a,
        ));
    }
    let flat: Vec<f64> = grid.iter().map(|q| q[0]).collect();
    match crate::numpy::run(&flat, w, a, crate::ROUNDS, out_dir) {
        Some((ns, version, rows)) => {
            let samples = rows
                .iter()
                .zip(grid)
                .map(|(r, q)| {
                    let o = FourBarOut {
                        t3: r[0],
                        t4: r[1],
                        w3: r[2],
                        w4: r[3],
                        al3: r[4],
                        al4: r[5],
                    };
                    Some(fourbar_out_sample(q[0], &o))
                })
                .collect();
            let mut m = method(
                "numpy whole-array",
                &format!("numpy {version} whole-array closed form f64 (subprocess)"),
                F64,
                samples,
                None,
            );
            m.ns = ns;
            v.push(m);
        }
        None => eprintln!("numpy not available: skipped"),
    }
}

/// Every method of a scene.
pub fn for_scene<'a>(scene: &'a Scene, out_dir: &Path) -> Vec<Method<'a>> {
    use Precision::*;
    let mut v = Vec::new();
    match scene.name {
        "FourBar" => fourbar_methods(&mut v, scene, out_dir),
        "SixBar" => {
            gen_pair!(
                v,
                scene,
                SixBar,
                SixBarInput { phi1 },
                generated::sixbar,
                ["generated f64", "generated f64"],
                ["generated f32", "generated f32"],
                |s| s.position.C.x
                    + s.position.F.y
                    + s.position.link2
                    + s.velocity.C.x
                    + s.velocity.link3
                    + s.acceleration.C.y
                    + s.acceleration.af
            );
        }
        "Shaper" => {
            gen_pair!(
                v,
                scene,
                Shaper,
                ShaperInput { crank },
                generated::shaper,
                ["generated f64", "generated f64"],
                ["generated f32", "generated f32"],
                |s| s.position.E.x
                    + s.position.link3
                    + s.position.link4
                    + s.velocity.E.x
                    + s.velocity.link3
                    + s.acceleration.E.x
                    + s.acceleration.link4
            );
        }
        "SliderCrank" => {
            gen_pair!(
                v,
                scene,
                SliderCrank,
                SliderCrankInput { theta },
                generated::slider_crank,
                ["generated f64", "generated f64"],
                ["generated f32", "generated f32"],
                |s| s.position.B.x
                    + s.position.link3
                    + s.velocity.B.x
                    + s.velocity.link3
                    + s.acceleration.B.x
                    + s.acceleration.link3
            );
            v.extend(slider_crank_closed_forms(scene));
        }
        "FiveBar" => {
            gen_pair!(
                v,
                scene,
                FiveBar,
                FiveBarInput { q1, q2 },
                generated::five_bar,
                ["generated f64", "generated f64"],
                ["generated f32", "generated f32"],
                |s| s.position.P.x
                    + s.position.P.y
                    + s.velocity.P.x
                    + s.velocity.P.y
                    + s.acceleration.P.x
                    + s.acceleration.P.y
            );
        }
        "GearedFiveBar" => {
            gen_pair!(
                v,
                scene,
                GearedFiveBar,
                GearedFiveBarInput { theta },
                generated::geared_five_bar,
                ["generated f64", "generated f64"],
                ["generated f32", "generated f32"],
                |s| s.position.B.x
                    + s.position.link4
                    + s.position.link5
                    + s.velocity.B.y
                    + s.velocity.link3
                    + s.acceleration.B.x
                    + s.acceleration.link4
            );
        }
        _ => {}
    }
    v.extend(crate::batch::for_scene(scene));
    v
}

fn median(m: &Method) -> f64 {
    if m.ns.is_empty() {
        f64::NAN
    } else {
        crate::timing::stats(&m.ns).0
    }
}

fn ok(b: bool) -> &'static str {
    if b {
        "**met**"
    } else {
        "**not met**"
    }
}

/// The performance and accuracy targets for one scene, as sentences with the measured figures.
/// `floor`: the f32 floor of the scene (positions, rates; `main::cos_sin_floor`).
pub fn targets(scene: &Scene, ms: &[Method], floor: (f64, f64)) -> Vec<String> {
    let mut out = Vec::new();
    let find = |name: &str| ms.iter().find(|m| m.name == name);
    for m in ms.iter().filter(|m| m.family.starts_with("generated")) {
        let e = m.errors;
        let line = match m.precision {
            Precision::F64 => format!(
                "{} {}: angles {:.1e} rad (target 1e-14), rates {:.1e} relative (target 1e-13): {}",
                scene.name,
                m.name,
                e.angle_abs,
                e.rate_rel,
                ok(e.angle_abs <= 1e-14 && e.rate_rel <= 1e-13 && e.failures == 0)
            ),
            Precision::F32 => format!(
                "{} {}: angles {:.1e} rad, positions {:.1e}, rates {:.1e} relative (target 2e-6; \
                 f32 floor from the cos/sin rounding: positions {:.1e}, rates {:.1e}): {}",
                scene.name,
                m.name,
                e.angle_abs,
                e.pos_rel,
                e.rate_rel,
                floor.0,
                floor.1,
                ok(e.angle_abs.max(e.rate_rel).max(e.pos_rel) <= 2e-6 && e.failures == 0)
            ),
        };
        out.push(line);
    }
    if scene.name == "FourBar" {
        let g = find("generated f64").map(median).unwrap_or(f64::NAN);
        let na = find("generated f64, no angle outputs")
            .map(median)
            .unwrap_or(f64::NAN);
        let bt = find("generated batch f64").map(median).unwrap_or(f64::NAN);
        let np = ms
            .iter()
            .find(|m| m.family == "numpy whole-array")
            .map(median);
        let cf = find("hand-written closed form f64")
            .map(median)
            .unwrap_or(f64::NAN);
        let nf = find("Newton, nalgebra Matrix2 tol 1e-12")
            .map(median)
            .unwrap_or(f64::NAN);
        let nh = find("Newton, heap DMatrix LU tol 1e-12")
            .map(median)
            .unwrap_or(f64::NAN);
        out.push(format!(
            "FourBar generated f64 {g:.1} ns vs hand-written closed form {cf:.1} ns (ratio {:.2}, target <= 1): {}",
            g / cf,
            ok(g <= cf)
        ));
        out.push(format!(
            "FourBar Newton Matrix2 (tol 1e-12) {nf:.1} ns = {:.1}x generated (target >= 3): {}",
            nf / g,
            ok(nf / g >= 3.0)
        ));
        out.push(format!(
            "FourBar Newton heap DMatrix (tol 1e-12) {nh:.1} ns = {:.1}x generated (target >= 8): {}",
            nh / g,
            ok(nh / g >= 8.0)
        ));
        out.push(format!(
            "FourBar batch f64 {bt:.1} ns per evaluation = {:.2}x faster than the scalar path (target >= 4 with -C target-cpu=native): {}",
            g / bt,
            ok(g / bt >= 4.0)
        ));
        match np {
            Some(np) => out.push(format!(
                "FourBar batch f64 {bt:.1} ns vs numpy whole-array {np:.1} ns (target: faster): {}",
                ok(bt < np)
            )),
            None => out.push(format!(
                "FourBar batch f64 {bt:.1} ns vs numpy whole-array (not measured: numpy missing; orientation figure about 37 ns)"
            )),
        }
        out.push(format!(
            "FourBar without angle outputs {na:.1} ns = {:.2}x with them (target <= 0.6): {}",
            na / g,
            ok(na / g <= 0.6)
        ));
    }
    if scene.name == "SliderCrank" {
        for (p, target) in [("f64", 1.2), ("f32", 1.5)] {
            let g = find(&format!("generated {p}"))
                .map(median)
                .unwrap_or(f64::NAN);
            let cf = find(&format!("hand-written closed form {p}"))
                .map(median)
                .unwrap_or(f64::NAN);
            out.push(format!(
                "SliderCrank generated {p} {g:.1} ns vs hand-written closed form {cf:.1} ns \
                 (ratio {:.2}, target <= {target}, issue 35): {}",
                g / cf,
                ok(g / cf <= target)
            ));
        }
    }
    out
}
