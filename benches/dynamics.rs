//! One `q''` of the run-up four-bar (`examples/common/run_up.rs`): the
//! generated `position` + `dynamics` against the same definition's
//! `position` + `velocity` + `acceleration`, and against the dense global
//! formulation with multipliers a user writes with nalgebra (one 17 x 17
//! `DMatrix` LU per evaluation, `examples/report/dynamics.rs`). One run:
//! `cargo bench -p mechanism-dev --bench dynamics` (criterion's medians;
//! the report's dynamics section has the same three side by side).

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use std::time::Duration;

#[allow(dead_code)]
#[path = "../examples/report/dynamics_dense.rs"]
mod dense;
#[path = "../examples/common/run_up.rs"]
mod run_up;

use run_up::{motor, RunUp, RunUpInput};

fn dynamics(c: &mut Criterion) {
    let m = RunUp::<f64>::default();
    let (phi, omega) = (0.7, 12.0);
    let d = dense::Dense::new();
    let full = d.state(phi, omega);
    let mut g = c.benchmark_group("run-up four-bar, one evaluation");
    g.warm_up_time(Duration::from_secs(1));
    g.measurement_time(Duration::from_secs(3));
    g.bench_function("position + velocity + acceleration", |b| {
        b.iter(|| {
            let pos = m
                .position(&RunUpInput {
                    phi: black_box(phi),
                })
                .unwrap();
            let vel = m.velocity(&pos, &RunUpInput { phi: omega }).unwrap();
            black_box(
                m.acceleration(&pos, &vel, &RunUpInput { phi: 10.0 })
                    .unwrap(),
            )
        })
    });
    g.bench_function("q'' (position + dynamics)", |b| {
        b.iter(|| {
            let pos = m
                .position(&RunUpInput {
                    phi: black_box(phi),
                })
                .unwrap();
            black_box(
                m.dynamics(
                    &pos,
                    &RunUpInput { phi: omega },
                    &RunUpInput { phi: motor(omega) },
                )
                .unwrap(),
            )
        })
    });
    g.bench_function("dense global formulation q'' (nalgebra LU)", |b| {
        b.iter(|| {
            let y = black_box(&full);
            black_box(d.accel(&y[..9], &y[9..], motor(omega)))
        })
    });
    g.finish();
}

criterion_group!(benches, dynamics);
criterion_main!(benches);
