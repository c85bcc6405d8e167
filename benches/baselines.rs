//! Criterion benchmarks of the four-bar baselines next to the generated code,
//! in one run: the hand-written closed form (f64, f32), Newton-Raphson with
//! nalgebra `Matrix2` and with heap `DMatrix` LU (warm-started from the
//! previous crank angle, tolerances 1e-3 .. 1e-14). `cargo bench --bench baselines`.
//!
//! The Stephenson III six-bar (a triad), group `stephenson`: the generated
//! `position()` (full search) and `position_near` (warm start), each with
//! `velocity` and `acceleration`, against Newton on the whole loop closure
//! with nalgebra `SMatrix` and heap `DMatrix` LU, warm-started from the
//! previous input (`cargo bench --bench baselines -- stephenson`).
//!
//! The five-bar robot given its end point, group `five_bar_ik`: the
//! generated `solve` (motor angles, rates, accelerations), and with `forces`
//! (the motors' torques), against Newton on the arms' loop closure with
//! nalgebra `SMatrix` LU, warm-started from the answer at a nearby end point
//! (`cargo bench --bench baselines -- five_bar_ik`).

#[path = "common/baselines.rs"]
mod baselines;
#[path = "../examples/common/scenes.rs"]
mod scenes;
#[path = "../examples/common/stephenson.rs"]
mod stephenson;

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use scenes::{FourBar, FourBarInput};

const N: usize = 3600;
const W: f64 = 250.0;
const A: f64 = 2.0e4;
const TOLS: [f64; 12] = [
    1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13, 1e-14,
];

fn grid() -> Vec<f64> {
    (0..N)
        .map(|k| (360.0 * k as f64 / N as f64).to_radians())
        .collect()
}

fn fourbar(c: &mut Criterion) {
    let g64 = grid();
    let g32: Vec<f32> = g64.iter().map(|&x| x as f32).collect();
    let mut g = c.benchmark_group("FourBar baselines");
    // One evaluation at 120 deg (warm start for Newton: the answer at 119.9 deg).
    let q = 120f64.to_radians();
    let prev = baselines::closed_form(q - 0.1f64.to_radians(), W, A);
    g.throughput(Throughput::Elements(1));
    let m = FourBar::<f64>::default();
    let (wi, ai) = (FourBarInput { theta2: W }, FourBarInput { theta2: A });
    g.bench_function("one/generated f64", |b| {
        b.iter(|| {
            m.solve(
                &FourBarInput {
                    theta2: black_box(q),
                },
                &wi,
                &ai,
            )
        })
    });
    g.bench_function("one/closed form f64", |b| {
        b.iter(|| baselines::closed_form(black_box(q), W, A))
    });
    g.bench_function("one/closed form f32", |b| {
        b.iter(|| baselines::closed_form(black_box(q as f32), W as f32, A as f32))
    });
    for tol in [1e-6, 1e-12] {
        g.bench_function(BenchmarkId::new("one/newton Matrix2", tol), |b| {
            b.iter(|| baselines::newton_fixed(black_box(q), W, A, (prev.t3, prev.t4), tol))
        });
        g.bench_function(BenchmarkId::new("one/newton DMatrix", tol), |b| {
            b.iter(|| baselines::newton_heap(black_box(q), W, A, (prev.t3, prev.t4), tol))
        });
    }
    // Sweeps of 3600 points.
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("sweep3600/closed form f64", |b| {
        b.iter(|| {
            for &q in &g64 {
                black_box(baselines::closed_form(black_box(q), W, A));
            }
        })
    });
    g.bench_function("sweep3600/closed form f32", |b| {
        b.iter(|| {
            for &q in &g32 {
                black_box(baselines::closed_form(black_box(q), W as f32, A as f32));
            }
        })
    });
    let start = baselines::closed_form(g64[N - 1], W, A);
    for tol in TOLS {
        g.bench_function(BenchmarkId::new("sweep3600/newton Matrix2", tol), |b| {
            b.iter(|| {
                let mut guess = (start.t3, start.t4);
                for &q in &g64 {
                    if let Some(o) = baselines::newton_fixed(black_box(q), W, A, guess, tol) {
                        guess = (o.t3, o.t4);
                        black_box(o);
                    }
                }
            })
        });
        g.bench_function(BenchmarkId::new("sweep3600/newton DMatrix", tol), |b| {
            b.iter(|| {
                let mut guess = (start.t3, start.t4);
                for &q in &g64 {
                    if let Some(o) = baselines::newton_heap(black_box(q), W, A, guess, tol) {
                        guess = (o.t3, o.t4);
                        black_box(o);
                    }
                }
            })
        });
    }
    g.finish();
}

/// Link 6's angles of the report's Stephenson section (rad): the midpoints
/// of `N` equal parts of the definition's range, -50.43 .. -2.64 deg.
fn stephenson_grid() -> Vec<f64> {
    let (lo, hi) = (-50.43, -2.64);
    (0..N)
        .map(|k| (lo + (hi - lo) * (k as f64 + 0.5) / N as f64).to_radians())
        .collect()
}

fn stephenson(c: &mut Criterion) {
    use stephenson::{Stephenson, StephensonInput, PHI_DDOT, PHI_DOT};
    let m = Stephenson::<f64>::default();
    let g = stephenson_grid();
    let (wi, ai) = (
        StephensonInput { phi: PHI_DOT },
        StephensonInput { phi: PHI_DDOT },
    );
    let pva = |p: &stephenson::StephensonPosition<f64>| {
        let v = m.velocity(p, &wi).ok()?;
        let a = m.acceleration(p, &v, &ai).ok()?;
        Some((v, a))
    };
    let mut grp = c.benchmark_group("stephenson (triad)");
    // One evaluation at -30 deg, warm starts from the previous grid input.
    let mid = (-30f64).to_radians();
    let k = (1..N)
        .min_by(|&a, &b| (g[a] - mid).abs().total_cmp(&(g[b] - mid).abs()))
        .unwrap_or(N / 2);
    let (q, prev_q) = (g[k], g[k - 1]);
    let prev = m
        .position(&StephensonInput { phi: prev_q })
        .expect("assembles mid-swing");
    let guess = [prev.crank2, prev.rocker, prev.link5, prev.coupler];
    grp.throughput(Throughput::Elements(1));
    grp.bench_function("one/generated position()", |b| {
        b.iter(|| {
            let p = m.position(&StephensonInput { phi: black_box(q) }).ok()?;
            pva(&p)
        })
    });
    grp.bench_function("one/generated position_near", |b| {
        b.iter(|| {
            let p = m
                .position_near(&prev, &StephensonInput { phi: black_box(q) })
                .ok()?;
            pva(&p)
        })
    });
    // The generated analyses alone (where the time of the two above goes).
    let (p_q, v_q) = {
        let p = m.position(&StephensonInput { phi: q }).expect("assembles");
        (p, m.velocity(&p, &wi).expect("regular"))
    };
    grp.bench_function("one/generated position_near alone", |b| {
        b.iter(|| m.position_near(&prev, &StephensonInput { phi: black_box(q) }))
    });
    grp.bench_function("one/generated velocity alone", |b| {
        b.iter(|| m.velocity(black_box(&p_q), &wi))
    });
    grp.bench_function("one/generated acceleration alone", |b| {
        b.iter(|| m.acceleration(black_box(&p_q), &v_q, &ai))
    });
    grp.bench_function("one/newton SMatrix", |b| {
        b.iter(|| baselines::stephenson_newton_fixed(black_box(q), PHI_DOT, PHI_DDOT, guess))
    });
    grp.bench_function("one/newton DMatrix", |b| {
        b.iter(|| baselines::stephenson_newton_heap(black_box(q), PHI_DOT, PHI_DDOT, guess))
    });
    // Sweeps over the 3600 inputs, warm starts from the previous input.
    let first = m
        .position(&StephensonInput { phi: g[0] })
        .expect("assembles at the first input");
    let guess0 = [first.crank2, first.rocker, first.link5, first.coupler];
    grp.throughput(Throughput::Elements(N as u64));
    grp.sample_size(10);
    grp.bench_function("sweep3600/generated position()", |b| {
        b.iter(|| {
            for &x in &g {
                if let Ok(p) = m.position(&StephensonInput { phi: black_box(x) }) {
                    black_box(pva(&p));
                }
            }
        })
    });
    grp.bench_function("sweep3600/generated position_near", |b| {
        b.iter(|| {
            let mut p = first;
            for &x in &g {
                if let Ok(n) = m.position_near(&p, &StephensonInput { phi: black_box(x) }) {
                    p = n;
                    black_box(pva(&p));
                }
            }
        })
    });
    type Newton = fn(f64, f64, f64, [f64; 4]) -> Option<baselines::StephensonOut<f64>>;
    let newtons: [(&str, Newton); 2] = [
        (
            "sweep3600/newton SMatrix",
            baselines::stephenson_newton_fixed::<f64>,
        ),
        (
            "sweep3600/newton DMatrix",
            baselines::stephenson_newton_heap::<f64>,
        ),
    ];
    for (name, f) in newtons {
        grp.bench_function(name, |b| {
            b.iter(|| {
                let mut guess = guess0;
                for &x in &g {
                    if let Some(o) = f(black_box(x), PHI_DOT, PHI_DDOT, guess) {
                        guess = o.q;
                        black_box(o);
                    }
                }
            })
        });
    }
    grp.finish();
}

/// One end point of the report's section, with its velocity and
/// acceleration: the generated inverse and the Newton baseline.
fn five_bar_ik(c: &mut Criterion) {
    use scenes::{FiveBarIk, FiveBarIkInput};
    let m = FiveBarIk::default();
    let inp = |x: f64, y: f64| FiveBarIkInput { x, y };
    let (p, v, a) = ((0.05, 0.2), (0.3, -0.2), (1.5, 2.5));
    let (vi, ai) = (inp(v.0, v.1), inp(a.0, a.1));
    // Newton's warm start: the answer at an end point 0.1 mm away.
    let near = m
        .position(&inp(p.0 - 1e-4, p.1))
        .expect("inside the workspace");
    // Newton's distal angles run from the elbows to P, the generated
    // forearms' axes from P to the elbows.
    let pi = std::f64::consts::PI;
    let guess = [near.arm1, near.forearm1 + pi, near.arm2, near.forearm2 + pi];
    let mut grp = c.benchmark_group("five_bar_ik");
    grp.throughput(Throughput::Elements(1));
    grp.bench_function("generated solve", |b| {
        b.iter(|| m.solve(&inp(black_box(p.0), black_box(p.1)), &vi, &ai))
    });
    grp.bench_function("generated solve + forces (motor torques)", |b| {
        b.iter(|| {
            let s = m
                .solve(&inp(black_box(p.0), black_box(p.1)), &vi, &ai)
                .ok()?;
            m.forces(&s.position, &s.velocity, &s.acceleration).ok()
        })
    });
    grp.bench_function("Newton SMatrix 4x4 LU (warm start)", |b| {
        b.iter(|| baselines::five_bar_ik_newton(black_box(p), v, a, guess))
    });
    grp.finish();
}

criterion_group!(benches, fourbar, stephenson, five_bar_ik);
criterion_main!(benches);
