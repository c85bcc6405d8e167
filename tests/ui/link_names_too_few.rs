// Error: an rrr creates two links, and `as` names one.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(3.0, 0.0);
        let A = crank(O2, 1.0, th) as link2;
        let B = rrr(A, 3.5, O4, 2.0, left) as link3;
    }
}

fn main() {}
