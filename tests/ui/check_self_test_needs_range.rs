use mechanism::mechanism;

mechanism! {
    /// `#[self_test]` needs a range for every input; a slider has no default.
    #[self_test]
    pub NoStroke {
        let O = ground(0.0, 0.0);
        let line = guide((0.0, 0.0), 0 deg);
        let P = slider(line, x) as block;
        let B = rrr(P, 0.12, O, 0.06, left) as (rod, rocker);
    }
}

fn main() {}
