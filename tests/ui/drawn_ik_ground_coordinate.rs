// Error: the coordinates of a ground joint as inputs: a coordinate input
// places a moving joint.
use mechanism::mechanism;

mechanism! {
    pub FiveBarIk {
        joints { O1 = (0.0, 0.0), O2 = (0.08, 0.0), A = (-0.02, 0.1), C = (0.15, 0.07), P = (0.09, 0.22) }
        links {
            ground = [O1, O2],
            arm1 = [O1, A],
            arm2 = [O2, C],
            fore1 = [A, P],
            fore2 = [C, P],
        }
        input x = O2.x;
        input y = O2.y;
    }
}

fn main() {}
