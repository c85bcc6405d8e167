// Error: a motor on a link that has no joint with the ground (a forearm):
// a motor sits at the joint of the two links it turns.
use mechanism::mechanism;

mechanism! {
    pub Arm {
        let O1 = ground(0.0, 0.0);
        let O2 = ground(0.08, 0.0);
        let P = target(x, y) as effector;
        let A = rrr(O1, 0.1, P, 0.16, left) as (arm1, fore1);
        let C = rrr(O2, 0.1, P, 0.16, right) as (arm2, fore2);
        motor q1 = angle(fore1);
        motor q2 = angle(arm2);
    }
}

fn main() {}
