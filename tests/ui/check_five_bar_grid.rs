use mechanism::mechanism;

mechanism! {
    /// The example five-bar with distal links too short for part of the
    /// declared box of both crank angles.
    pub ShortFiveBar {
        let O1 = ground(0.0, 0.0);
        let O2 = ground(0.08, 0.0);
        let A = crank(O1, 0.1, q1) as arm1;
        let C = crank(O2, 0.1, q2) as arm2;
        let P = rrr(A, 0.1, C, 0.1, left) as (forearm1, forearm2);
        range q1 = (60 deg, 150 deg);
        range q2 = (0 deg, 90 deg);
    }
}

fn main() {}
