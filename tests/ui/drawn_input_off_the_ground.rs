// Error: the input is the coupler's angle, but the coupler has no joint on
// the ground, so no crank can drive it (the four-bar then cannot be placed).
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        joints { O2 = (0.0, 0.0), O4 = (4.0, 0.0), A = (0.5, 0.9), B = (3.2, 2.1) }
        links { ground = [O2, O4], crank = [O2, A], coupler = [A, B], rocker = [O4, B] }
        input theta = angle(coupler);
    }
}

fn main() {}
