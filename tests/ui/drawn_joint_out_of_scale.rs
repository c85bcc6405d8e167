// Error: a joint drawn 1e308 away, its links' lengths beyond the scale the
// groups are solved in: the expansion-time check reports the group on the
// joint (never a NaN at run time, never a message off the definition).
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        joints { O2 = (0.0, 0.0), O4 = (4.0, 0.0), A = (0.5, 0.9), B = (-1e308, 2.1) }
        links { ground = [O2, O4], crank = [O2, A], coupler = [A, B], rocker = [O4, B] }
        input theta = angle(crank);
    }
}

fn main() {}
