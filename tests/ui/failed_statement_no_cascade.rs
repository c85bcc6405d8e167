// A rejected driver statement keeps its names: no "cannot find point `A`", no
// "has no driver", no dof error, and main's use of the generated items compiles.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, 0.0, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
    }
}

fn main() {
    let fb = FourBar::<f64>::default();
    let p = fb.position(&FourBarInput { theta2: 0.0 }).unwrap();
    let _ = (p.A, p.B, p.link3);
}
