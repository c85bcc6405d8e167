// Error: a mass on a link name that does not exist, where the statements
// that create links have no `as`: they are named, never an internal name.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(3.0, 0.0);
        let A = crank(O2, 1.0, th);
        let B = rrr(A, 3.5, O4, 2.0, left);
        mass link3 { m = 1.0, at = B };
    }
}

fn main() {}
