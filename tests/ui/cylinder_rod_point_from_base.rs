// Error: a point on the rod measured from the barrel's pivot B (the rod's
// points are measured from the joint C).
use mechanism::mechanism;

mechanism! {
    pub Boom {
        dof 1;
        let A = ground(0.0, 0.0);
        let B = ground(0.8, -0.9);
        let C = actuator(A, 2.2, B, len, left) as (boom, barrel, rod);
        let G2 = point(rod, from B, 1.5, 0 deg);
        mass rod { m = 140.0, at = G2 };
        gravity (0.0, -9.81);
        range len = (1.9, 3.0);
    }
}

fn main() {}
