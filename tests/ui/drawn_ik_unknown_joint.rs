// Error: a coordinate input of a joint the drawing does not have; the
// message names the nearest joint.
use mechanism::mechanism;

mechanism! {
    pub FiveBarIk {
        joints { O1 = (0.0, 0.0), O2 = (0.08, 0.0), A = (-0.02, 0.1), C = (0.15, 0.07), Pen = (0.09, 0.22) }
        links {
            ground = [O1, O2],
            arm1 = [O1, A],
            arm2 = [O2, C],
            fore1 = [A, Pen],
            fore2 = [C, Pen],
        }
        input x = Pem.x;
        input y = Pen.y;
    }
}

fn main() {}
