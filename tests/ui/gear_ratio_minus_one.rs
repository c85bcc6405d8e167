// Error: a ratio of -1 (an internal pair of equal gears) has no center
// distance; the message says what the ratio is and gives one.
use mechanism::mechanism;

mechanism! {
    pub Geared {
        let O2 = ground(0.0, 0.0);
        let O5 = ground(3.0, 0.0);
        let A = crank(O2, 1.0, theta) as link2;
        let C = gear(O5, 0.5, link2, -1.0) as link5;
    }
}

fn main() {}
