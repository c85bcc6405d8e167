//! Seed 001: the quick-return shaper (crank + RPR + RRP, m), crank at 1 rad/s,
//! 0..360 deg in steps of 30, on the document's branch (theta3 = 65.556 deg,
//! theta4 = 168.938 deg at crank 0).
//!
//! Run: `cargo run --release --example shaper` (table) or with `-- --csv`.
//!
//! Also writes SVG pictures (kinematics, a drawing, an animation) to
//! `target/plots/shaper/` and says where on stderr (`docs/plots.md`).
#[macro_use]
#[path = "common/cli.rs"]
mod cli;
mod common;
use common::plots::{degrees, grid, positions, save};
use mechanism::geometry::{angle_deg_0_360, unit};
use mechanism::mechanism;
use mechanism_plot::any;
use mechanism_plot::PlotError;
use std::path::{Path, PathBuf};

mechanism! {
    /// Quick-return shaper of seed 001 (m): crank AB = 0.125 about A; the block
    /// at B slides on the rocker pivoted at C = (0, -0.275); D on the rocker at
    /// CD = 0.6; the connecting rod DE = 0.15 drives the ram E along y = 0.3
    /// (guide direction 180 deg, as in the document).
    #[self_test]
    pub Shaper {
        units { length = "m" }
        dof 1;
        let A = ground(0.0, 0.0);
        let C = ground(0.0, -0.275);
        let ram = guide((0.0, 0.3), 180 deg);
        let B = crank(A, 0.125, crank) as link2;
        let cb = rpr(B, C, plus) as (block, link3);
        let D = point(link3, from C, 0.6, 0 deg);
        let E = rrp(D, 0.15, ram, plus) as (link4, ram_block) slide s_ram;
        outputs { E, link3, link4, A, C, B, D }
    }
}

fn main() {
    let args = cli::parse(
        "shaper",
        "Seed 001's quick-return shaper (m), crank at 1 rad/s: angles, rates and the ram's motion over a full turn.",
        &[cli::CSV],
    );
    let csv = args.flag("--csv");
    let m = Shaper::<f64>::default();
    let names = [
        "crank_deg",
        "theta3_deg",
        "omega3",
        "alpha3",
        "theta4_deg",
        "omega4",
        "alpha4",
        "x_e",
        "v_e",
        "a_e",
    ];
    if csv {
        outln!("{}", names.join(","));
    } else {
        outln!("Quick-return shaper of seed 001 (m); crank 1 rad/s");
        outln!("angles deg, rates rad/s and rad/s^2; ram E: m, m/s, m/s^2");
        outln!("{}", common::header(&names, 11));
    }
    for step in 0..=12 {
        let deg = 30.0 * step as f64;
        let s = m
            .solve(
                &ShaperInput {
                    crank: deg.to_radians(),
                },
                &ShaperInput { crank: 1.0 },
                &ShaperInput { crank: 0.0 },
            )
            .expect("the seed 001 shaper assembles over the whole turn");
        let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
        let row = [
            deg,
            angle_deg_0_360(&unit(p.link3)),
            v.link3,
            a.link3,
            angle_deg_0_360(&unit(p.link4)),
            v.link4,
            a.link4,
            p.E.x,
            v.E.x,
            a.E.x,
        ];
        if csv {
            outln!("{}", common::csv_row(&row));
        } else {
            outln!("{}", common::table_row(&row, 11, 6));
        }
    }
    common::plots::write_and_report("shaper", pictures);
}

/// Quick-return shaper of seed 001 at 1 rad/s over a turn: the ram E, the rocker's and
/// the rod's angles, their rates and accelerations; the path of D.
pub fn pictures(dir: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let m = Shaper::<f64>::default();
    let rows: Vec<_> = grid(0.0, 360.0, 180)
        .into_iter()
        .map(|d| {
            let s = m.solve(
                &ShaperInput {
                    crank: d.to_radians(),
                },
                &ShaperInput { crank: 1.0 },
                &ShaperInput { crank: 0.0 },
            );
            (d, s.ok().map(|s| (s.position, s.velocity, s.acceleration)))
        })
        .collect();
    let title = "Quick-return shaper of seed 001, crank at 1 rad/s";
    let x = ("crank angle", "deg");
    let fig = any::kinematics_chart(title, x, &rows, &["E", "link3", "link4"])?;
    let poses = &positions(&rows, 2)[..90];
    let sk = any::sketch_with::<Shaper<f64>, _>(title, poses, &["D"], degrees("crank"))?;
    save(dir, fig, &sk, 15)
}
