// Error: an actuator names two links or three (arm, barrel, rod), not four.
use mechanism::mechanism;

mechanism! {
    pub Boom {
        dof 1;
        let A = ground(0.0, 0.0);
        let B = ground(0.8, -0.9);
        let C = actuator(A, 2.2, B, len, left) as (boom, barrel, rod, piston);
        range len = (1.9, 3.0);
    }
}

fn main() {}
