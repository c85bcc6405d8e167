// Error: only a crank's angle can be given as (cos, sin).
use mechanism::mechanism;

mechanism! {
    pub Press {
        let line = guide((0.0, 0.0), 0 deg);
        let P = slider(line, x as cos_sin) as block;
    }
}

fn main() {}
