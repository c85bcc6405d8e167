// Errors: three independent typos (an assembly mode, a range's input, a
// mass's link), each found by a different stage (lowering, the input ranges,
// the force-analysis rules after planning), all reported in one compile, in
// the order they are written.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(3.0, 0.0);
        let A = crank(O2, 1.0, theta2) as link2;
        let B = rrr(A, 2.5, O4, 1.8, lfet) as (link3, link4);
        mass link33 { m = 1.0, at = B };
        range theta = (0.0, 1.0);
        gravity (0.0, -9.81);
    }
}

fn main() {}
