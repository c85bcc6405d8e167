// Error: a unit after a load's value (loads are plain numbers in the
// definition's own units): the error is on the unit and says so.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.3048, 0.0);
        let A = crank(O2, 0.1016, theta2) as link2;
        let B = rrr(A, 0.254, O4, 0.1778, left) as (link3, link4);
        torque on link4 = 5.0 deg;
    }
}

fn main() {}
