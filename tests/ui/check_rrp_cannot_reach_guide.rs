use mechanism::mechanism;

mechanism! {
    /// A slider-crank whose rod (0.05) is shorter than the crank (0.1) plus
    /// the guide's offset (0.02): the rod cannot reach the guide over part of
    /// the turn.
    pub ShortRod {
        let O = ground(0.0, 0.0);
        let line = guide((0.0, 0.02), 0 deg);
        let A = crank(O, 0.1, theta) as link2;
        let B = rrp(A, 0.05, line, plus) as (link3, slider) slide x;
    }
}

fn main() {}
