// Error: a link name given twice, in two statements: the error is on the
// second and names the statement that defines the first.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(304.8, 0.0);
        let A = crank(O2, 101.6, theta2) as link2;
        let B = rrr(A, 254.0, O4, 177.8, left) as (link3, link4);
        let O6 = ground(500.0, 0.0);
        let C = rrr(B, 200.0, O6, 150.0, left) as (link3, link6);
    }
}

fn main() {}
