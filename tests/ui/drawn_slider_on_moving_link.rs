// Error: a block in the slot of a block that slides on a moving link (an
// RPP on a carried line) is not a shape the drawn form decomposes; the
// message names the links left and the shapes a block on a moving link takes.
use mechanism::mechanism;

mechanism! {
    pub Yoke {
        joints { O = (0.0, 0.0), P = (0.4, 0.0), A = (0.1, 0.0), B = (0.4, 0.1), Q = (0.2, 0.1) }
        links { ground = [O, P], crank = [O, A], arm = [P, B] }
        slider yoke at Q on crank along 0 deg;
        slider block at B on yoke along 90 deg;
        input theta = angle(crank);
        input phi = angle(arm);
    }
}

fn main() {}
