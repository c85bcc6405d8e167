//! A two-input five-bar robot (m): the end point P over a grid of both crank
//! angles. With these dimensions every grid pose assembles; a pose that cannot
//! (shorter distal links, a run-time parameter) prints the typed error instead.
//!
//! Run: `cargo run --release --example five_bar` (table) or with `-- --csv`.
//!
//! Also writes SVG pictures (kinematics, a drawing, an animation) to
//! `target/plots/five_bar/` and says where on stderr (`docs/plots.md`).
#[macro_use]
#[path = "common/cli.rs"]
mod cli;
mod common;
use common::plots::{grid, positions, save};
use mechanism::mechanism;
use mechanism_plot::any;
use mechanism_plot::PlotError;
use std::path::{Path, PathBuf};

mechanism! {
    /// Two-input five-bar robot (m): cranks of 0.1 about O1 = (0, 0) and
    /// O2 = (0.08, 0), distal links of 0.16 meeting at the end point P above
    /// the base (`left` of the directed line A -> C).
    #[self_test]
    pub FiveBar {
        params { base = 0.08, proximal = 0.1, distal = 0.16 }
        units { length = "m" }
        dof 2;
        let O1 = ground(0.0, 0.0);
        let O2 = ground(base, 0.0);
        let A = crank(O1, proximal, q1) as arm1;
        let C = crank(O2, proximal, q2) as arm2;
        let P = rrr(A, distal, C, distal, left) as (forearm1, forearm2);
        range q1 = (60 deg, 150 deg);
        range q2 = (0 deg, 90 deg);
        outputs { P, O1, O2, A, C }
    }
}

fn main() {
    let args = cli::parse(
        "five_bar",
        "A two-input five-bar robot (m): the end point over a grid of both crank angles.",
        &[cli::CSV],
    );
    let csv = args.flag("--csv");
    let m = FiveBar::<f64>::default();
    let names = ["q1_deg", "q2_deg", "p_x", "p_y", "vp_x", "vp_y"];
    if csv {
        outln!("{}", names.join(","));
    } else {
        outln!("Five-bar: base 0.08 m, proximal 0.1 m, distal 0.16 m; both cranks at 1 rad/s");
        outln!("{}", common::header(&names, 12));
    }
    for i in 0..=6 {
        for j in 0..=6 {
            let q1 = 60.0 + 15.0 * i as f64;
            let q2 = 0.0 + 15.0 * j as f64;
            let input = FiveBarInput {
                q1: q1.to_radians(),
                q2: q2.to_radians(),
            };
            let rates = FiveBarInput { q1: 1.0, q2: 1.0 };
            let result = m
                .position(&input)
                .and_then(|p| m.velocity(&p, &rates).map(|v| (p, v)));
            match result {
                Ok((p, v)) => {
                    let row = [q1, q2, p.P.x, p.P.y, v.P.x, v.P.y];
                    if csv {
                        outln!("{}", common::csv_row(&row));
                    } else {
                        outln!("{}", common::table_row(&row, 12, 5));
                    }
                }
                Err(e) if !csv => outln!("{q1:>12.1} {q2:>12.1}   {e}"),
                Err(_) => {}
            }
        }
    }
    common::plots::write_and_report("five_bar", pictures);
}

/// Two-input five-bar along a closed loop of both inputs round the centre of the
/// example's grid, q1 = 105° + 40° cos t, q2 = 45° + 40° sin t: the end point P against
/// t, a drawing and an animation with the path of P.
pub fn pictures(dir: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let m = FiveBar::<f64>::default();
    let inputs = |t: f64| {
        let t = t.to_radians();
        (105.0 + 40.0 * t.cos(), 45.0 + 40.0 * t.sin())
    };
    let rows: Vec<_> = grid(0.0, 360.0, 90)
        .into_iter()
        .map(|t| {
            let (q1, q2) = inputs(t);
            let p = m.position(&FiveBarInput {
                q1: q1.to_radians(),
                q2: q2.to_radians(),
            });
            let rates = FiveBarInput { q1: 1.0, q2: 1.0 };
            let s = p.and_then(|p| {
                let v = m.velocity(&p, &rates)?;
                let a = m.acceleration(&p, &v, &FiveBarInput { q1: 0.0, q2: 0.0 })?;
                Ok((p, v, a))
            });
            (t, s.ok())
        })
        .collect();
    let title = "Five-bar robot (m): P along a loop of both inputs, both at 1 rad/s";
    let x = ("loop parameter t", "deg");
    let fig = any::kinematics_chart(title, x, &rows, &["P"])?;
    let poses = &positions(&rows, 1)[..90];
    let sk = any::sketch_with::<FiveBar<f64>, _>(title, poses, &["P"], |t| {
        let (q1, q2) = inputs(t);
        format!("q1 = {q1:.0}°, q2 = {q2:.0}°")
    })?;
    save(dir, fig, &sk, 0)
}
