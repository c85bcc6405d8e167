// Error: a mass on a two-name actuator's cylinder (a massless two-force
// member); the message points to the third name (barrel and rod).
use mechanism::mechanism;

mechanism! {
    pub Boom {
        dof 1;
        let A = ground(0.0, 0.0);
        let B = ground(0.8, -0.9);
        let C = actuator(A, 2.2, B, len, left) as (boom, cyl);
        let G1 = point(cyl, from B, 0.6, 0 deg);
        mass cyl { m = 220.0, at = G1 };
        gravity (0.0, -9.81);
        range len = (1.9, 3.0);
    }
}

fn main() {}
