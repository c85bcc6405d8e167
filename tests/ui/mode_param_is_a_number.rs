// Error: a number parameter written where a mode goes.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        params { circuit = 1.0 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(304.8, 0.0);
        let A = crank(O2, 101.6, theta2) as link2;
        let B = rrr(A, 254.0, O4, 177.8, circuit) as (link3, link4);
    }
}

fn main() {}
