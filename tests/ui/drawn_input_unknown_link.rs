// Error: the input names a link that is not in `links`.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        joints { O2 = (0.0, 0.0), O4 = (4.0, 0.0), A = (0.5, 0.9), B = (3.2, 2.1) }
        links { ground = [O2, O4], crank = [O2, A], coupler = [A, B], rocker = [O4, B] }
        input theta = angle(crnak);
    }
}

fn main() {}
