// Error: a drawing rejected for one reason (a joint on no link) reports
// that once; the mass and the force on its links blame nothing more.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        joints { O2 = (0.0, 0.0), O4 = (4.0, 0.0), A = (0.5, 0.9), B = (3.2, 2.1), Q = (9.0, 9.0) }
        links { ground = [O2, O4], crank = [O2, A], coupler = [A, B], rocker = [O4, B] }
        input theta = angle(crank);
        mass coupler { m = 1.0, at = A };
        torque on rocker = 2.0;
    }
}

fn main() {}
