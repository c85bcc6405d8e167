// Valid: the seed four-bar with only `B` as an output.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
        outputs { B }
    }
}

fn main() {
    let fb = FourBar::<f64>::default();
    let s = fb
        .solve(
            &FourBarInput { theta2: 0.5 },
            &FourBarInput { theta2: 250.0 },
            &FourBarInput { theta2: 0.0 },
        )
        .expect("assembles");
    let _ = (s.position.B, s.velocity.B, s.acceleration.B);
}
