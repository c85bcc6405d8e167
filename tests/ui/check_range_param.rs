use mechanism::mechanism;

mechanism! {
    /// A range bound must be known at compile time.
    pub ParamRange {
        params { stroke = 0.1 }
        let line = guide((0.0, 0.0), 0 deg);
        let P = slider(line, x) as block;
        range x = (0.0, stroke);
    }
}

fn main() {}
