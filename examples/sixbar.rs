//! Seed 000, problem 3-28: a six-bar whose block F slides along the crank's own
//! line (mm), crank at 10 rad/s, crank angle 40..55 deg at 15 equally spaced values (both ends
//! included, as the document's `linspace`), on
//! the document's branch (theta2 = 41.04, theta3 = 145.85, theta4 = 88.58 deg,
//! af = 93.31 at phi1 = 40 deg).
//!
//! Run: `cargo run --release --example sixbar` (table) or with `-- --csv`.
//!
//! Also writes SVG pictures (kinematics, a drawing, an animation) to
//! `target/plots/sixbar/` and says where on stderr (`docs/plots.md`).
#[macro_use]
#[path = "common/cli.rs"]
mod cli;
mod common;
use common::plots::{degrees, grid, positions, save};
use mechanism::geometry::angle_deg_0_360;
use mechanism::mechanism;
use mechanism_plot::any;
use mechanism_plot::PlotError;
use std::path::{Path, PathBuf};

/// Crank speed (rad/s).
const OMEGA1: f64 = 10.0;

mechanism! {
    /// Six-bar of seed 000, problem 3-28 (mm): the crank turns about A; B is on
    /// the crank opposite its slide line; the block F slides along the crank's
    /// line and is pinned to the rocker E-F (60) whose other arm E-D is 35; the
    /// RRR group B-C-D (50, 75) closes the loop.
    #[self_test]
    pub SixBar {
        units { length = "mm" }
        dof 1;
        let A = ground(0.0, 0.0);
        let E = ground(70.0, 0.0);
        let K = crank(A, 40.0, phi1) as link1;
        let B = point(link1, from A, 40.0, 180 deg);
        let crank_line = guide(A, link1);
        let F = rrp(E, 60.0, crank_line, plus) as (link4, block5) slide af;
        let D = point(link4, from E, 35.0, 180 deg);
        let C = rrr(B, 50.0, D, 75.0, left) as (link2, link3);
        // F assembles only while the crank line passes within 60 of E
        // (|sin phi1| <= 6/7): the document's 40..55 deg.
        range phi1 = (40 deg, 55 deg);
        outputs { C, F, link2, link3, link4, af, A, E, K, B, D, link1 }
    }
}

fn main() {
    let args = cli::parse(
        "sixbar",
        "Seed 000, problem 3-28: the six-bar whose block slides along the crank, crank 40..55 deg.",
        &[cli::CSV],
    );
    let csv = args.flag("--csv");
    let m = SixBar::<f64>::default();
    let names = [
        "phi1_deg",
        "theta2_deg",
        "theta3_deg",
        "theta4_deg",
        "af",
        "omega2",
        "omega3",
        "omega4",
        "v_f",
        "alpha2",
        "alpha3",
        "alpha4",
        "a_f",
        "vc_x",
        "vc_y",
        "ac_x",
        "ac_y",
    ];
    if csv {
        outln!("{}", names.join(","));
    } else {
        outln!("Six-bar of seed 000 (problem 3-28), mm; crank 10 rad/s");
        outln!("angles deg, rates rad/s, rad/s^2; af mm, v_f mm/s, a_f mm/s^2; C in mm/s, mm/s^2");
        outln!("{}", common::header(&names, 11));
    }
    // The document's grid: linspace(40, 55, 15), both ends included.
    for step in 0..15 {
        let deg = 40.0 + 15.0 * step as f64 / 14.0;
        let s = m
            .solve(
                &SixBarInput {
                    phi1: deg.to_radians(),
                },
                &SixBarInput { phi1: OMEGA1 },
                &SixBarInput { phi1: 0.0 },
            )
            .expect("the seed 000 six-bar assembles for 40..55 deg");
        let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
        let row = [
            deg,
            angle_deg_0_360(&mechanism::geometry::unit(p.link2)),
            angle_deg_0_360(&mechanism::geometry::unit(p.link3)),
            angle_deg_0_360(&mechanism::geometry::unit(p.link4)),
            p.af,
            v.link2,
            v.link3,
            v.link4,
            v.af,
            a.link2,
            a.link3,
            a.link4,
            a.af,
            v.C.x,
            v.C.y,
            a.C.x,
            a.C.y,
        ];
        if csv {
            outln!("{}", common::csv_row(&row));
        } else {
            outln!("{}", common::table_row(&row, 11, 3));
        }
    }
    common::plots::write_and_report("sixbar", pictures);
}

/// Six-bar of seed 000 at 10 rad/s over the document's range 40..55 deg (its `range`);
/// the animation goes there and back.
pub fn pictures(dir: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let m = SixBar::<f64>::default();
    let solve = |d: f64| {
        let s = m.solve(
            &SixBarInput {
                phi1: d.to_radians(),
            },
            &SixBarInput { phi1: 10.0 },
            &SixBarInput { phi1: 0.0 },
        );
        (d, s.ok().map(|s| (s.position, s.velocity, s.acceleration)))
    };
    let rows: Vec<_> = grid(40.0, 55.0, 60).into_iter().map(solve).collect();
    let title = "Six-bar of seed 000 (problem 3-28), crank at 10 rad/s";
    let x = ("crank angle φ1", "deg");
    let fig = any::kinematics_chart(title, x, &rows, &["link2", "link3", "link4", "af"])?;
    let there = positions(&rows, 2);
    let back = there.iter().rev().skip(1).take(there.len() - 2).cloned();
    let poses: Vec<_> = there.iter().cloned().chain(back).collect();
    let sk = any::sketch_with::<SixBar<f64>, _>(title, &poses, &["C"], degrees("φ1"))?;
    save(dir, fig, &sk, 0)
}
