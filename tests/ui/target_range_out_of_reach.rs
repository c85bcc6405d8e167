// Error: the end point's declared range reaches beyond the arms (0.26 m
// from each base pivot): the expansion-time check names the arm's group
// and the end points where it cannot close.
use mechanism::mechanism;

mechanism! {
    pub Robot {
        let O1 = ground(0.0, 0.0);
        let O2 = ground(0.08, 0.0);
        let P = target(x, y) as effector;
        let A = rrr(O1, 0.1, P, 0.16, left) as (arm1, fore1);
        let C = rrr(O2, 0.1, P, 0.16, right) as (arm2, fore2);
        range x = (0.0, 0.08);
        range y = (0.16, 0.30);
    }
}

fn main() {}
