//! A press's torque curve over 10^5 crank angles: the batch form of the
//! force analysis (`solve_columns`, i.e. `solve_batch_forces`) against a
//! scalar loop of `solve` with forces writing the same torque, and the
//! kinematic batch alone (`solve_batch`, the vectorized kernel) for scale.
//! f64 and f32, one run: `cargo bench -p mechanism-dev --bench batch_forces` (criterion's
//! medians; `docs/performance.md`, "The force analysis in a batch").

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use mechanism::mechanism;
use std::time::Duration;

mechanism! {
    /// A mechanical press (m, kg, N): crank 0.1 about O, connecting rod
    /// 0.4 to the ram on a slide line 0.02 below O; masses on every link,
    /// gravity, and the process force on the ram as a run-time load.
    pub Press {
        loads { force = 0.0 }
        let O = ground(0.0, 0.0);
        let line = guide((0.0, -0.02), 0 deg);
        let A = crank(O, 0.1, theta) as link2;
        let B = rrp(A, 0.4, line, plus) as (link3, ram) slide x;
        let G3 = point(link3, from A, 0.2, 0 deg);
        mass link2 { m = 0.5, at = A, j = 0.001 };
        mass link3 { m = 2.0, at = G3, j = 0.03 };
        mass ram { m = 5.0, at = B };
        gravity (0.0, -9.81);
        force at B on ram along line = -force;
    }
}

const N: usize = 100_000;

/// The process force at crank angle `theta`: 20 kN over the last 30 deg
/// before bottom dead centre, 0 elsewhere.
fn process(theta: f64) -> f64 {
    let bdc = 0.0;
    let d = (theta - bdc).rem_euclid(std::f64::consts::TAU);
    if d > std::f64::consts::TAU - 30f64.to_radians() {
        20_000.0
    } else {
        0.0
    }
}

macro_rules! press_bench {
    ($c:expr, $t:ty, $label:literal) => {{
        let m = Press::<$t>::default();
        let theta: Vec<$t> = (0..N)
            .map(|k| (k as f64 * std::f64::consts::TAU / N as f64) as $t)
            .collect();
        let force: Vec<$t> = theta.iter().map(|q| process(*q as f64) as $t).collect();
        let w = 10.0 as $t;
        let mut cols = Press::<$t>::batch(N);
        cols.in_theta = theta.clone();
        cols.rate_theta = vec![w; N];
        cols.load_force = force.clone();
        let mut torque = vec![0.0 as $t; N];
        let mut g = $c.benchmark_group(concat!("press torque curve ", $label));
        g.throughput(Throughput::Elements(N as u64));
        g.sample_size(20);
        g.warm_up_time(Duration::from_secs(1));
        g.measurement_time(Duration::from_secs(4));
        g.bench_function(BenchmarkId::new("scalar solve loop", N), |b| {
            b.iter(|| {
                let zero = 0.0 as $t;
                for k in 0..N {
                    let i = |x: $t| PressInput { theta: x };
                    torque[k] = match black_box(&m).solve(
                        &i(theta[k]),
                        &i(w),
                        &i(zero),
                        &PressLoads { force: force[k] },
                    ) {
                        Ok(s) => s.forces.drive_theta,
                        Err(_) => zero,
                    };
                }
                black_box(&torque);
            })
        });
        g.bench_function(BenchmarkId::new("batch with forces", N), |b| {
            b.iter(|| black_box(black_box(&m).solve_columns(&mut cols)))
        });
        g.bench_function(BenchmarkId::new("kinematic batch (lane kernel)", N), |b| {
            b.iter(|| black_box(black_box(&m).solve_batch(&mut cols.as_batch())))
        });
        g.finish();
        // The same torque curve both ways, bit for bit.
        m.solve_columns(&mut cols).expect("one length");
        assert!(cols
            .drive_theta
            .iter()
            .zip(&torque)
            .all(|(a, b)| a.to_bits() == b.to_bits()));
    }};
}

fn press(c: &mut Criterion) {
    press_bench!(c, f64, "f64");
    press_bench!(c, f32, "f32");
}

criterion_group!(benches, press);
criterion_main!(benches);
