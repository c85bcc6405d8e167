// Error: a link lists a joint that is not drawn (a typo of `B`).
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        joints { O2 = (0.0, 0.0), O4 = (4.0, 0.0), A = (0.5, 0.9), B = (3.2, 2.1) }
        links { ground = [O2, O4], crank = [O2, A], coupler = [A, Bb], rocker = [O4, B] }
        input theta = angle(crank);
    }
}

fn main() {}
