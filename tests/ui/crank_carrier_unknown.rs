// Error: a crank carried by a link no statement creates (a typo of `link3`).
use mechanism::mechanism;

mechanism! {
    pub Arm {
        dof 2;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.3, 0.0);
        let A = crank(O2, 0.1, theta2) as link2;
        let B = rrr(A, 0.25, O4, 0.18, left) as (link3, link4);
        let C = crank(B, 0.05, phi, lnk3) as link5;
    }
}

fn main() {}
