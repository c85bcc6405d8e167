//! Criterion benchmarks of the four-bar baselines next to the generated code,
//! in one run: the hand-written closed form (f64, f32), Newton-Raphson with
//! nalgebra `Matrix2` and with heap `DMatrix` LU (warm-started from the
//! previous crank angle, tolerances 1e-3 .. 1e-14). `cargo bench --bench baselines`.

#[path = "common/baselines.rs"]
mod baselines;
#[path = "../examples/common/scenes.rs"]
mod scenes;

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

criterion_group!(benches, fourbar);
criterion_main!(benches);
