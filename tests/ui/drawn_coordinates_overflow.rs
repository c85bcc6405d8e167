// Error: a joint drawn so far away that its distance from the next joint
// overflows an f64; the message points at the joint the length is read for.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        joints { O2 = (0.0, 0.0), O4 = (4.0, 0.0), A = (0.5, 0.9), B = (-1e308, 2.1) }
        links { ground = [O2, O4], crank = [O2, A], coupler = [A, B], rocker = [O4, B] }
        input theta = angle(crank);
    }
}

fn main() {}
