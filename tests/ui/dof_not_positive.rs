// Error: `dof 0` (a mechanism has at least one degree of freedom): the error
// is on the value, not a Gruebler count that cannot match.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        dof 0;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(304.8, 0.0);
        let A = crank(O2, 101.6, theta2) as link2;
        let B = rrr(A, 254.0, O4, 177.8, left) as (link3, link4);
    }
}

fn main() {}
