// Error: a per-evaluation load value used as a dimension.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
        loads { cut = 1.0 }
        let P = point(link3, from A, cut, 0 deg);
        force at P = (cut, 0.0);
    }
}

fn main() {}
