// Error: `along` names a point, not a guide.
use mechanism::mechanism;

mechanism! {
    pub SliderCrank {
        let O = ground(0.0, 0.0);
        let line = guide((0.0, 0.0), 0 deg);
        let A = crank(O, 0.1, theta) as link2;
        let B = rrp(A, 0.4, line, plus) as (rod, ram) slide x;
        mass ram { m = 5.0, at = B };
        force at B on ram along A = -100.0;
    }
}

fn main() {}
