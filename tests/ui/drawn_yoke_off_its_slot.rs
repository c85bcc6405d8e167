// Error: the yoke's joint of a drawn sine mechanism is not where its slot
// crosses the line it slides on (the RPP's reference point).
use mechanism::mechanism;

mechanism! {
    pub Sine {
        joints { A = (0.0, 0.0), B = (0.06, 0.08), Q = (0.0, 0.05) }
        links { ground = [A], link1 = [A, B] }
        slider block at B on yoke along 0 deg;
        slider yoke at Q on ground along 90 deg;
        input phi = angle(link1);
    }
}

fn main() {}
