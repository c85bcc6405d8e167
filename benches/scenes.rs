//! Criterion benchmarks of the generated code of every example scene, f32 and
//! f64: each analysis alone at one input (`position`, `velocity` at a given
//! position, `acceleration` at a given position and velocity, and `forces`
//! for the scenes with masses), one whole evaluation (`solve`) and a
//! 3600-point sweep of `solve` over the input range.
//! `cargo bench --bench scenes`.

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
    // Each analysis alone, from the previous ones' results.
    (@analyses $g:ident, $m:ident, $one:ident, $w:ident, $a:ident, $t:ty) => {{
        let pos = $m.position(&$one).expect("the bench input assembles");
        let vel = $m.velocity(&pos, &$w).expect("regular");
        $g.bench_function(BenchmarkId::new("position", stringify!($t)), |b| {
            b.iter(|| $m.position(black_box(&$one)))
        });
        $g.bench_function(BenchmarkId::new("velocity", stringify!($t)), |b| {
            b.iter(|| $m.velocity(black_box(&pos), &$w))
        });
        $g.bench_function(BenchmarkId::new("acceleration", stringify!($t)), |b| {
            b.iter(|| $m.acceleration(black_box(&pos), &vel, &$a))
        });
    }};
    (@prec $g:ident, $ty:ident, $in:ident, $field:ident, $lo:expr, $hi:expr, $w:expr, $a:expr, $t:ty) => {{
        let m = $ty::<$t>::default();
        let inputs: Vec<$in<$t>> = grid($lo, $hi).into_iter().map(|q| $in { $field: q as $t }).collect();
        let (w, a) = ($in { $field: $w as $t }, $in { $field: $a as $t });
        let one = inputs[N / 3];
        $g.throughput(Throughput::Elements(1));
        bench_scene!(@analyses $g, m, one, w, a, $t);
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
            bench_scene!(@analyses g, m, one, w, a, $t);
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
    forces(c);
}

/// The force analysis alone (at a given position, velocity and
/// acceleration) and the whole `solve` of the two scenes with masses.
fn forces(c: &mut Criterion) {
    macro_rules! with_masses {
        ($label:expr, $ty:ident, $in:ident, $field:ident, $w:expr, $a:expr, ($($loads:tt)*)) => {{
            let mut g = c.benchmark_group($label);
            g.throughput(Throughput::Elements(1));
            with_masses!(@prec g, $ty, $in, $field, $w, $a, ($($loads)*), f64);
            with_masses!(@prec g, $ty, $in, $field, $w, $a, ($($loads)*), f32);
            g.finish();
        }};
        (@prec $g:ident, $ty:ident, $in:ident, $field:ident, $w:expr, $a:expr, ($($loads:tt)*), $t:ty) => {{
            let m = $ty::<$t>::default();
            let one = $in { $field: 1.0 as $t };
            let (w, a) = ($in { $field: $w as $t }, $in { $field: $a as $t });
            let pos = m.position(&one).expect("the bench input assembles");
            let vel = m.velocity(&pos, &w).expect("regular");
            let acc = m.acceleration(&pos, &vel, &a).expect("regular");
            $g.bench_function(BenchmarkId::new("forces", stringify!($t)), |b| {
                b.iter(|| m.forces(black_box(&pos), &vel, &acc $($loads)*))
            });
            $g.bench_function(BenchmarkId::new("one", stringify!($t)), |b| {
                b.iter(|| m.solve(black_box(&one), &w, &a $($loads)*))
            });
        }};
    }
    with_masses!(
        "SineMechanism",
        SineMechanism,
        SineMechanismInput,
        phi1,
        10.0,
        0.0,
        ()
    );
    with_masses!(
        "ShaperForces",
        ShaperForces,
        ShaperForcesInput,
        crank,
        1.0,
        0.7,
        (, &ShaperForcesLoads { cut: 5000.0 })
    );
}

criterion_group!(benches, scenes);
criterion_main!(benches);
