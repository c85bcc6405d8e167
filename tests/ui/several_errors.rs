// Errors: four independent mistakes, all reported together: an unknown
// analysis, an undefined point, an unknown statement kind and an unknown
// output.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        dof 1;
        analysis jerk;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, Q4, rocker, left) as (link3, link4);
        let P = pointt(link3, from A, 50.0, 30.0 deg);
        outputs { B, link3, Z }
    }
}

fn main() {}
