use mechanism::mechanism;

mechanism! {
    /// Bad range statements: an unknown input, a unit on a displacement, an
    /// empty range, a parameter bound, and `#[self_test]` without a range for
    /// a slider.
    #[self_test]
    pub BadRanges {
        params { stroke = 0.1 }
        let O = ground(0.0, 0.0);
        let line = guide((0.0, 0.0), 0 deg);
        let P = slider(line, x) as block;
        let O2 = ground(0.3, 0.0);
        let A = crank(O2, 0.05, theta) as crank_link;
        range thetta = (0 deg, 90 deg);
        range x = (0.0 deg, 0.1);
        range theta = (90 deg, 10 deg);
        allow singular Q;
    }
}

fn main() {}
