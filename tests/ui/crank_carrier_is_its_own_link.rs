// Error: a crank carried by the link it creates.
use mechanism::mechanism;

mechanism! {
    pub Leg {
        dof 2;
        let H = ground(0.0, 0.0);
        let K = crank(H, 0.4, q1) as thigh;
        let F = crank(K, 0.35, q2, shank) as shank;
    }
}

fn main() {}
