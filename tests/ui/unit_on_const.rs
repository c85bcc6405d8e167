// Error: an angle unit on a `const` (a plain number): the error is on the unit
// and says where the unit goes instead.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        const tilt = 30.0 deg;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(304.8, 0.0);
        let A = crank(O2, 101.6, theta2) as link2;
        let B = rrr(A, 254.0, O4, 177.8, left) as (link3, link4);
        let P = point(link3, from A, 50.0, tilt deg);
    }
}

fn main() {}
