// Error: the planet is named as carried by its own coupler-like link,
// which no input turns about the ground, so the carrier is not a crank on
// the ground.
use mechanism::mechanism;

mechanism! {
    pub Planet {
        joints { O = (0.0, 0.0), A = (1.0, 0.0), B = (1.5, 0.5), P = (1.8, 0.5) }
        links { ground = [O], arm = [O, A], link3 = [A, B], planet = [B, P] }
        input theta = angle(arm);
        input phi = angle(link3, arm);
        gear planet to ground ratio 1.5 on link3;
    }
}

fn main() {}
