// Error: an assembly mode parameter written where a length goes.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        params { crank = 101.6, circuit = left }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(304.8, 0.0);
        let A = crank(O2, circuit, theta2) as link2;
        let B = rrr(A, 254.0, O4, 177.8, circuit) as (link3, link4);
    }
}

fn main() {}
