// Error: a block in the slot of a link that has no placed joint when the
// block's joint is placed (the slot closes a loop of the class III kind) is
// not a shape the drawn form decomposes; the message names the links left
// and the shapes a block on a moving link takes.
use mechanism::mechanism;

mechanism! {
    pub SlottedTriad {
        joints {
            O2 = (0.0, 0.0), O6 = (0.5, 0.0), O7 = (0.2, 0.6),
            B = (0.1, 0.05), D = (0.4, 0.3), E = (0.25, 0.4),
        }
        links { ground = [O2, O6, O7], crank = [O2, B], link3 = [D, E], link5 = [O6, D], link6 = [O7, E] }
        slider block at B on link3 along 0.3;
        input theta = angle(crank);
    }
}

fn main() {}
