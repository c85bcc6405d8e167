// Error: the input is the angle of a slider's block, which does not turn.
use mechanism::mechanism;

mechanism! {
    pub SliderCrank {
        joints { O = (0.0, 0.0), A = (0.05, 0.08), B = (0.45, 0.02) }
        links { ground = [O], crank = [O, A], rod = [A, B] }
        slider block at B on ground along 0 deg;
        input s = angle(block);
    }
}

fn main() {}
