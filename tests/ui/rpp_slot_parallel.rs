// Error: an RPP whose slot is parallel to its guide, at every pose.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(3.0, 0.0);
        let A = crank(O2, 1.0, th) as link2;
        let g = guide(O4, 0 deg);
        let C = rpp(A, g, 0 deg) as (block, yoke) slide (s1, s2);
    }
}

fn main() {}
