// Error: the barrel and the rod given the same name.
use mechanism::mechanism;

mechanism! {
    pub Boom {
        dof 1;
        let A = ground(0.0, 0.0);
        let B = ground(0.8, -0.9);
        let C = actuator(A, 2.2, B, len, left) as (boom, cyl, cyl);
        let G1 = point(cyl, from B, 0.6, 0 deg);
        mass cyl { m = 220.0, at = G1 };
        range len = (1.9, 3.0);
    }
}

fn main() {}
