// Error: a number where a crank's carrying link goes (an angle offset is not
// an argument of `crank`).
use mechanism::mechanism;

mechanism! {
    pub Leg {
        dof 2;
        let H = ground(0.0, 0.0);
        let K = crank(H, 0.4, q1) as thigh;
        let F = crank(K, 0.35, q2, 0.5) as shank;
    }
}

fn main() {}
