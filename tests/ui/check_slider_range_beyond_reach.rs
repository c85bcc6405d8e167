use mechanism::mechanism;

mechanism! {
    /// A slider drives a rocker through a rod: the declared stroke goes
    /// beyond what the rod and the rocker can reach.
    pub SliderRocker {
        let O = ground(0.0, 0.0);
        let line = guide((0.0, -0.05), 0 deg);
        let P = slider(line, x) as block;
        let B = rrr(P, 0.12, O, 0.06, left) as (rod, rocker);
        range x = (-0.1, 0.2);
    }
}

fn main() {}
