// Error: the drawing has B on the line through A and O4 (a dead centre), so
// it does not say which assembly is meant.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        joints { O2 = (0.0, 0.0), O4 = (4.0, 0.0), A = (1.0, 0.0), B = (2.5, 0.0) }
        links { ground = [O2, O4], crank = [O2, A], coupler = [A, B], rocker = [O4, B] }
        input theta = angle(crank);
    }
}

fn main() {}
