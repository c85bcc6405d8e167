//! Criterion benchmarks of the scalar f64 kernels against glibc's (through
//! `std`) and the lane versions, in scalar use. `atan2`: throughput over a
//! sweep of 4096 link-vector-like pairs (directions spread evenly around the
//! circle, lengths 20 .. 200), and a dependent chain (each angle feeds the
//! next `y`). `sin_cos`: a sweep of 4096 crank angles over a turn (summing
//! `r cos + r sin`, as a crank's tip uses both), and a dependent chain.
//! `RUSTFLAGS="-C target-cpu=native" cargo bench --bench kernels`.

use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};
use mechanism::sincos64::sin_cos_f64;
use mechanism::trig64::atan2_f64;

const N: usize = 4096;

/// The sweep: golden-ratio steps in angle and a second irrational step in
/// length, so consecutive pairs fall in different octants.
fn pairs() -> Vec<(f64, f64)> {
    (0..N)
        .map(|k| {
            let th = std::f64::consts::TAU * (k as f64 * 0.618_033_988_749_895).fract()
                - std::f64::consts::PI;
            let r = 20.0 + 180.0 * (k as f64 * 0.414_213_562_373_095).fract();
            (r * th.sin(), r * th.cos())
        })
        .collect()
}

fn atan2(c: &mut Criterion) {
    let p = pairs();
    let mut g = c.benchmark_group("atan2 f64");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("sweep/glibc", |b| {
        b.iter(|| black_box(&p).iter().map(|&(y, x)| y.atan2(x)).sum::<f64>())
    });
    g.bench_function("sweep/trig64", |b| {
        b.iter(|| {
            black_box(&p)
                .iter()
                .map(|&(y, x)| atan2_f64(y, x))
                .sum::<f64>()
        })
    });
    g.bench_function("sweep/lane", |b| {
        b.iter(|| {
            black_box(&p)
                .iter()
                .map(|&(y, x)| mechanism::__private::lane::atan2(y, x))
                .sum::<f64>()
        })
    });
    g.bench_function("chain/glibc", |b| {
        b.iter(|| {
            black_box(&p)
                .iter()
                .fold(0.5, |z, &(y, x)| (y + z).atan2(x))
        })
    });
    g.bench_function("chain/trig64", |b| {
        b.iter(|| {
            black_box(&p)
                .iter()
                .fold(0.5, |z, &(y, x)| atan2_f64(y + z, x))
        })
    });
    g.finish();
}

fn sin_cos(c: &mut Criterion) {
    let angles: Vec<f64> = (0..N)
        .map(|k| std::f64::consts::TAU * k as f64 / N as f64)
        .collect();
    let mut g = c.benchmark_group("sin_cos f64");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("sweep/glibc", |b| {
        b.iter(|| {
            black_box(&angles)
                .iter()
                .map(|&x| {
                    let (s, c) = x.sin_cos();
                    s + c
                })
                .sum::<f64>()
        })
    });
    g.bench_function("sweep/sincos64", |b| {
        b.iter(|| {
            black_box(&angles)
                .iter()
                .map(|&x| {
                    let (s, c) = sin_cos_f64(x);
                    s + c
                })
                .sum::<f64>()
        })
    });
    g.bench_function("sweep/lane", |b| {
        b.iter(|| {
            black_box(&angles)
                .iter()
                .map(|&x| {
                    let (s, c, _) = mechanism::__private::lane::sin_cos(x);
                    s + c
                })
                .sum::<f64>()
        })
    });
    g.bench_function("chain/glibc", |b| {
        b.iter(|| {
            black_box(&angles).iter().fold(0.5, |z, &x| {
                let (s, c) = (x + z).sin_cos();
                s * c
            })
        })
    });
    g.bench_function("chain/sincos64", |b| {
        b.iter(|| {
            black_box(&angles).iter().fold(0.5, |z, &x| {
                let (s, c) = sin_cos_f64(x + z);
                s * c
            })
        })
    });
    g.finish();
}

criterion_group!(benches, atan2, sin_cos);
criterion_main!(benches);
