//! Criterion benchmarks of the generated code of every example scene, f32 and
//! f64: one evaluation (position + velocity + acceleration) and a 3600-point
//! sweep over the input range. `cargo bench --bench scenes`.

#[path = "../examples/common/scenes.rs"]
mod scenes;
#[path = "common/variants.rs"]
mod variants;

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use scenes::*;
use variants::*;

const N: usize = 3600;

/// Angles `from + (to - from) k / N` (deg, in rad).
fn grid(from: f64, to: f64) -> Vec<f64> {
    (0..N)
        .map(|k| (from + (to - from) * k as f64 / N as f64).to_radians())
        .collect()
}

macro_rules! bench_scene {
    ($c:expr, $label:expr, $ty:ident, $in:ident, $field:ident, $lo:expr, $hi:expr, $w:expr, $a:expr) => {{
        let mut g = $c.benchmark_group($label);
        bench_scene!(@prec g, $ty, $in, $field, $lo, $hi, $w, $a, f64);
        bench_scene!(@prec g, $ty, $in, $field, $lo, $hi, $w, $a, f32);
        g.finish();
    }};
    (@prec $g:ident, $ty:ident, $in:ident, $field:ident, $lo:expr, $hi:expr, $w:expr, $a:expr, $t:ty) => {{
        let m = $ty::<$t>::default();
        let inputs: Vec<$in<$t>> = grid($lo, $hi).into_iter().map(|q| $in { $field: q as $t }).collect();
        let (w, a) = ($in { $field: $w as $t }, $in { $field: $a as $t });
        let one = inputs[N / 3];
        $g.throughput(Throughput::Elements(1));
        $g.bench_function(BenchmarkId::new("one", stringify!($t)), |b| {
            b.iter(|| m.solve(black_box(&one), &w, &a))
        });
        $g.throughput(Throughput::Elements(N as u64));
        $g.bench_function(BenchmarkId::new("sweep3600", stringify!($t)), |b| {
            b.iter(|| {
                for i in &inputs {
                    let _ = black_box(m.solve(black_box(i), &w, &a));
                }
            })
        });
    }};
}

fn scenes(c: &mut Criterion) {
    bench_scene!(
        c,
        "FourBar",
        FourBar,
        FourBarInput,
        theta2,
        0.0,
        360.0,
        250.0,
        2.0e4
    );
    bench_scene!(
        c,
        "FourBarPoints",
        FourBarPoints,
        FourBarPointsInput,
        theta2,
        0.0,
        360.0,
        250.0,
        2.0e4
    );
    bench_scene!(
        c,
        "SixBar",
        SixBar,
        SixBarInput,
        phi1,
        40.0,
        55.0,
        10.0,
        -60.0
    );
    bench_scene!(
        c,
        "Shaper",
        Shaper,
        ShaperInput,
        crank,
        0.0,
        360.0,
        1.0,
        0.7
    );
    bench_scene!(
        c,
        "SliderCrank",
        SliderCrank,
        SliderCrankInput,
        theta,
        0.0,
        360.0,
        314.159,
        5.0e4
    );
    // Five-bar: two inputs; q1 swept over [60, 150) deg at q2 = 45 deg.
    let mut g = c.benchmark_group("FiveBar");
    macro_rules! five {
        ($t:ty) => {{
            let m = FiveBar::<$t>::default();
            let q2 = 45f64.to_radians() as $t;
            let inputs: Vec<FiveBarInput<$t>> = grid(60.0, 150.0)
                .into_iter()
                .map(|q| FiveBarInput { q1: q as $t, q2 })
                .collect();
            let w = FiveBarInput { q1: 0.8, q2: -1.3 };
            let a = FiveBarInput { q1: 2.0, q2: -0.5 };
            let one = inputs[N / 3];
            g.throughput(Throughput::Elements(1));
            g.bench_function(BenchmarkId::new("one", stringify!($t)), |b| {
                b.iter(|| m.solve(black_box(&one), &w, &a))
            });
            g.throughput(Throughput::Elements(N as u64));
            g.bench_function(BenchmarkId::new("sweep3600", stringify!($t)), |b| {
                b.iter(|| {
                    for i in &inputs {
                        let _ = black_box(m.solve(black_box(i), &w, &a));
                    }
                })
            });
        }};
    }
    five!(f64);
    five!(f32);
    g.finish();
}

criterion_group!(benches, scenes);
criterion_main!(benches);
