// Error: a drawn slider on a moving link (the drawn form has sliders on the
// ground only; the message says which group statements to write).
use mechanism::mechanism;

mechanism! {
    pub Yoke {
        joints { O = (0.0, 0.0), A = (0.1, 0.0), B = (0.3, 0.0) }
        links { ground = [O], crank = [O, A], rod = [A, B] }
        slider block at B on crank along 0 deg;
        input theta = angle(crank);
    }
}

fn main() {}
