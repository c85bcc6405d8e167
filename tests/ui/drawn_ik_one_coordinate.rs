// Error: a drawn five-bar given only its end point's x: a joint is placed
// by both coordinates; the message shows the input to add.
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
        input x = P.x;
        input q2 = angle(arm2);
    }
}

fn main() {}
