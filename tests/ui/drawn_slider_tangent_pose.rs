// Error: the rod drawn square to the block's line (the pose where the RRP's
// two assemblies meet), so the drawing does not pick one.
use mechanism::mechanism;

mechanism! {
    pub SliderCrank {
        joints { O = (0.0, 0.0), A = (0.45, 0.1), B = (0.45, -0.3) }
        links { ground = [O], crank = [O, A], rod = [A, B] }
        slider block at B on ground along 0 deg;
        input theta = angle(crank);
    }
}

fn main() {}
