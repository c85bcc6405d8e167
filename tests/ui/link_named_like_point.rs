// Error: a link named like a point: one error on the name, none at the uses of `A`, and main compiles.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (A, link4);
    }
}

fn main() {
    let fb = FourBar::<f64>::default();
    let _ = fb.position(&FourBarInput { theta2: 0.0 }).map(|p| (p.A, p.B));
}
