// Error: a drawn five-bar (two degrees of freedom) with one input.
use mechanism::mechanism;

mechanism! {
    pub FiveBar {
        joints { O1 = (0.0, 0.0), O2 = (0.08, 0.0), A = (0.0, 0.1), C = (0.08, 0.1), P = (0.04, 0.22) }
        links {
            ground = [O1, O2],
            arm1 = [O1, A],
            arm2 = [O2, C],
            fore1 = [A, P],
            fore2 = [C, P],
        }
        input q1 = angle(arm1);
    }
}

fn main() {}
