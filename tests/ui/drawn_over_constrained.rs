// Error: a drawn four-bar with a fifth link from A to O4 makes it a rigid
// structure with one input too many.
use mechanism::mechanism;

mechanism! {
    pub Braced {
        joints { O2 = (0.0, 0.0), O4 = (4.0, 0.0), A = (0.5, 0.9), B = (3.2, 2.1) }
        links {
            ground = [O2, O4],
            crank = [O2, A],
            coupler = [A, B],
            rocker = [O4, B],
            brace = [A, O4],
        }
        input theta = angle(crank);
    }
}

fn main() {}
