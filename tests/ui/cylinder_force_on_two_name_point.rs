// Error: a force at a point of a two-name actuator's cylinder only; the
// message points to the barrel and rod.
use mechanism::mechanism;

mechanism! {
    pub Boom {
        dof 1;
        let A = ground(0.0, 0.0);
        let B = ground(0.8, -0.9);
        let C = actuator(A, 2.2, B, len, left) as (boom, cyl);
        let P = point(cyl, from B, 0.6, 0 deg);
        force at P = (0.0, -500.0);
        range len = (1.9, 3.0);
    }
}

fn main() {}
