// Error: a drawn motor carried by a block (a pendulum on a cart): a block's
// axis is its line, and the drawn form does not measure an angle from it
// yet; the message shows the group statement to write.
use mechanism::mechanism;

mechanism! {
    pub CartPole {
        joints { O = (-1.0, 0.0), Q = (0.0, 0.0), P = (0.0, 0.5) }
        links { ground = [O], pole = [Q, P] }
        slider cart at Q on ground along 0 deg;
        input x = slide(cart);
        input q = angle(pole, cart);
    }
}

fn main() {}
