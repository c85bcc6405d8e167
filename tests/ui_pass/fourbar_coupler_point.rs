// Valid: the four-bar with a coupler point, a const and angle units.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        const offset = 50.0;
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
        let P = point(link3, from A, offset * 2.0, 30.0 deg);
        outputs { P, link3 }
    }
}

fn main() {
    let fb = FourBar::<f64>::default();
    let p = fb.position(&FourBarInput { theta2: 0.5 }).expect("assembles");
    let _ = (p.P, p.link3);
}
