// `check()` exists for every definition; where the definition gives an input
// no range (a slider's travel), a call is an error that names the input and
// the `range` statement to add (not `no method named check`).
use mechanism::mechanism;

mechanism! {
    pub Press {
        let line = guide((0.0, 0.0), 0 deg);
        let O = ground(0.0, 1.0);
        let S = slider(line, s) as block;
        let C = rrr(O, 1.5, S, 1.2, left) as (arm, rod);
    }
}

fn main() {
    let report = Press::<f64>::default().check();
    let _ = report;
}
