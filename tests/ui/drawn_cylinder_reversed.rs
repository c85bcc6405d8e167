// Error: a cylinder drawn from the boom's joint to the ground's: its barrel
// end (`from`) must be placed before it; the message says to swap the ends.
use mechanism::mechanism;

mechanism! {
    pub Boom {
        joints { A = (0.0, 0.0), B = (0.8, -0.9), C = (2.1, 0.65) }
        links { ground = [A, B], boom = [A, C] }
        cylinder lift from C to B;
        input len = length(lift);
    }
}

fn main() {}
