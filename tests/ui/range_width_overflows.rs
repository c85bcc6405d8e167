// Error: a range whose width overflows f64 (the sweep returned at once and the
// check reported that every group assembles; the RRR assembles for |s| <= 1.73).
use mechanism::mechanism;

mechanism! {
    pub Slide {
        let line = guide((0.0, 0.0), 0 deg);
        let P = ground(0.0, 1.0);
        let C = slider(line, s) as block;
        let B = rrr(C, 1.2, P, 0.9, left) as (l1, l2);
        range s = (-1e308, 1e308);
    }
}

fn main() {}
