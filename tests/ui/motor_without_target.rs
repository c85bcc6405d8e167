// Error: a motor in a forward definition, where the crank is the motor and
// its torque is already the driving effort `drive_q1`.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(4.0, 0.0);
        let A = crank(O2, 1.0, q1) as crank;
        let B = rrr(A, 3.5, O4, 3.0, left) as (coupler, rocker);
        mass coupler { m = 1.0, at = A };
        motor m1 = angle(crank);
    }
}

fn main() {}
