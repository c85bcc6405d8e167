//! Seed 002: a crank-rocker four-bar (lengths in mm), crank at 250 rad/s.
//!
//! Run: `cargo run --release --example fourbar` (table) or with `-- --csv`
//! (CSV only, full precision).
use mechanism::geometry::angle_deg_0_360;
use mechanism::mechanism;

mechanism! {
    /// Crank-rocker four-bar of seed 002 (mm). Ground O2-O4 = 304.8, crank
    /// O2-A = 101.6, coupler A-B = 254.0, rocker O4-B = 177.8.
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
        outputs { A, B, link3, link4 }
    }
}

fn main() {
    let csv = std::env::args().any(|a| a == "--csv");
    let fb = FourBar::<f64>::default();
    let omega2 = 250.0;
    if csv {
        println!("theta2_deg,theta3_deg,theta4_deg,omega3,omega4,alpha3,alpha4");
    } else {
        println!("Four-bar (seed 002): ground 304.8, crank 101.6, coupler 254.0, rocker 177.8 mm; crank 250 rad/s");
        println!(
            "{:>8} {:>10} {:>10} {:>12} {:>12} {:>14} {:>14}",
            "theta2", "theta3", "theta4", "omega3", "omega4", "alpha3", "alpha4"
        );
        println!(
            "{:>8} {:>10} {:>10} {:>12} {:>12} {:>14} {:>14}",
            "deg", "deg", "deg", "rad/s", "rad/s", "rad/s^2", "rad/s^2"
        );
    }
    for step in 0..72 {
        let deg = 5.0 * step as f64;
        let s = fb
            .solve(
                &FourBarInput {
                    theta2: deg.to_radians(),
                },
                &FourBarInput { theta2: omega2 },
                &FourBarInput { theta2: 0.0 },
            )
            .expect("the seed 002 four-bar assembles over the whole turn");
        let (p, v, a) = (s.position, s.velocity, s.acceleration);
        let t3 = angle_deg_0_360(&(p.B - p.A));
        let t4 = angle_deg_0_360(&(p.B - fb_o4(&fb)));
        let _ = (p.link3, p.link4);
        if csv {
            println!(
                "{deg:.17e},{t3:.17e},{t4:.17e},{:.17e},{:.17e},{:.17e},{:.17e}",
                v.link3, v.link4, a.link3, a.link4
            );
        } else {
            println!(
                "{deg:>8.1} {t3:>10.4} {t4:>10.4} {:>12.5} {:>12.5} {:>14.3} {:>14.3}",
                v.link3, v.link4, a.link3, a.link4
            );
        }
    }
}

fn fb_o4(fb: &FourBar) -> mechanism::Point2<f64> {
    mechanism::Point2::new(fb.ground, 0.0)
}
