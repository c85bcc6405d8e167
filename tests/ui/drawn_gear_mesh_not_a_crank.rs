// Error: the gear meshes with the coupler, which turns about no fixed
// center (it is not a crank on the ground), so the pair has no center
// distance.
use mechanism::mechanism;

mechanism! {
    pub GearedFiveBar {
        joints {
            O2 = (0.0, 0.0),
            O5 = (3.0, 0.0),
            A = (0.94, 0.34),
            C = (3.79, -0.14),
            B = (3.37, 2.43),
        }
        links {
            ground = [O2, O5],
            link2 = [O2, A],
            link5 = [O5, C],
            link3 = [A, B],
            link4 = [C, B],
        }
        input theta = angle(link2);
        gear link5 to link3 ratio 2.0;
    }
}

fn main() {}
