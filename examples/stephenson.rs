//! The Stephenson III six-bar (m, kg, N): link 6 (O6-C) driven
//! by its angle `phi` at 1.5 rad/s and -0.5 rad/s^2 moves the triad
//! (class III group) crank2 O2-A, rocker O4-B, link5 C-P on the ternary
//! coupler A-B-P. The assembly is the one near the pose given at
//! phi = -49.48 deg (scene `Stephenson` in `examples/common/stephenson.rs`).
//!
//! Prints link 6's swing on that assembly (found by following it with
//! `position_near` and bisecting where it ends), then a table of the joints,
//! the link angles, rates and accelerations over the swing, and the driving
//! torque and joint reactions with masses, gravity and a 20 N load at P.
//!
//! Run: `cargo run --release --example stephenson` (table) or with
//! `-- --csv` (the 16 kinematic columns first, 17 significant digits, then
//! the forces). Pictures: `target/plots/stephenson/`.
#[macro_use]
#[path = "common/cli.rs"]
mod cli;
mod common;
use common::stephenson::{self as st, Stephenson, StephensonLoads};

/// Rows of the table.
const ROWS: usize = 64;
/// The load at P (N, along +y: downward is negative).
const LOAD: f64 = -20.0;

fn main() {
    let args = cli::parse(
        "stephenson",
        "The Stephenson III six-bar driven by link 6: its swing, the triad's motion over it, the driving torque and reactions.",
        &[cli::CSV],
    );
    let csv = args.flag("--csv");
    let m = Stephenson::<f64>::default();
    let (lo, hi) = st::swing(&m);
    let forces = [
        "torque",
        "r_ground_crank2_x",
        "r_ground_crank2_y",
        "r_ground_rocker_x",
        "r_ground_rocker_y",
        "r_link6_link5_x",
        "r_link6_link5_y",
        "r_ground_link6_x",
        "r_ground_link6_y",
        "power_residual",
    ];
    if csv {
        outln!("{},{}", st::COLUMNS.join(","), forces.join(","));
    } else {
        outln!("Stephenson III six-bar (m); link 6 at {} rad/s, {} rad/s^2; masses, gravity, {LOAD} N at P along y", st::PHI_DOT, st::PHI_DDOT);
        outln!(
            "link 6 swings over [{:.10}, {:.10}] deg on the assembly given at phi = -49.48 deg",
            lo.to_degrees(),
            hi.to_degrees()
        );
        outln!("angles deg, rates rad/s, rad/s^2; torque N m (ccw +); reactions N (ground on crank2 at O2, ground on rocker at O4, link6 on link5 at C)");
        outln!("angles: th2 crank2, th3 coupler, th4 rocker; w rates, al accelerations (same links); the CSV names every column");
        outln!(
            "{}",
            common::header(
                &[
                    "phi", "ax", "ay", "bx", "by", "px", "py", "th2", "th3", "th4", "w2", "w3",
                    "w4", "al2", "al3", "al4"
                ],
                10
            )
        );
    }
    let loads = StephensonLoads { fp: LOAD };
    let mut worst = 0.0f64;
    let mut force_rows = Vec::new();
    for row in st::rows(&m, (lo, hi), ROWS) {
        let f = m
            .forces(&row.p, &row.v, &row.a, &loads)
            .expect("regular force systems inside the swing");
        worst = worst.max(f.power_residual.abs());
        let fr = [
            f.drive_phi,
            f.r_ground_crank2.x,
            f.r_ground_crank2.y,
            f.r_ground_rocker.x,
            f.r_ground_rocker.y,
            f.r_link6_link5.x,
            f.r_link6_link5.y,
            f.r_ground_link6.x,
            f.r_ground_link6.y,
            f.power_residual,
        ];
        let cols = row.columns();
        if csv {
            outln!("{},{}", common::csv_row(&cols), common::csv_row(&fr));
        } else {
            outln!("{}", common::table_row(&cols, 10, 4));
            force_rows.push((cols[0], fr));
        }
    }
    if !csv {
        outln!();
        outln!(
            "{}",
            common::header(
                &["phi_deg", "torque", "O2_x", "O2_y", "O4_x", "O4_y", "C_x", "C_y"],
                10
            )
        );
        for (phi, fr) in &force_rows {
            let mut v = vec![*phi];
            v.extend_from_slice(&fr[..7]);
            outln!("{}", common::table_row(&v, 10, 3));
        }
        outln!("largest power residual (relative): {worst:.1e}");
    }
    common::plots::write_and_report("stephenson", st::plots);
}
