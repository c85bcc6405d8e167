// Error: an elliptic trammel drawn without its frame: both blocks slide on
// the ground's lines, but no link is named `ground`. The fix, `ground = []`
// (a ground with no pin, only the blocks' lines), is in the message.
use mechanism::mechanism;

mechanism! {
    pub Trammel {
        joints { A = (0.12, 0.0), B = (0.0, 0.16), P = (-0.06, 0.24) }
        links { rod = [A, B, P] }
        slider block_a at A on ground along 0 deg;
        slider block_b at B on ground along 90 deg;
        input s = slide(block_a);
    }
}

fn main() {}
