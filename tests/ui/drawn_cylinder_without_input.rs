// Error: a drawn cylinder that no `length(..)` input drives (a free
// cylinder is not drawn yet); the message shows the input to write.
use mechanism::mechanism;

mechanism! {
    pub Boom {
        joints { A = (0.0, 0.0), B = (0.8, -0.9), C = (2.1, 0.65) }
        links { ground = [A, B], boom = [A, C] }
        cylinder lift from B to C;
        input q = angle(boom);
    }
}

fn main() {}
