// Valid: the seed four-bar, position analysis only; a mechanism with
// `params` can be written out in full (no hidden field to fill).
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
        analysis position;
    }
}

fn main() {
    let fb = FourBar::<f64>::default();
    let p = fb.position(&FourBarInput { theta2: 0.5 }).expect("assembles");
    let _ = (p.A, p.B, p.link3, p.link4);
    let written = FourBar::<f32> {
        ground: 0.3,
        crank: 0.1,
        coupler: 0.25,
        rocker: 0.18,
    };
    let _ = written.position(&FourBarInput { theta2: 0.5 });
}
