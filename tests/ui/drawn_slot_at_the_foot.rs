// Error: an RPR drawn with the block's joint at the foot of the slotted
// link's pivot on the slot's line (the pose where its two assemblies meet).
use mechanism::mechanism;

mechanism! {
    pub Shaper {
        joints { A = (0.0, 0.0), C = (0.0, -0.275), B = (0.125, -0.275), D = (0.0, -0.8) }
        links { ground = [A, C], link2 = [A, B], link3 = [C, D] }
        slider block at B on link3 along 90 deg;
        input crank = angle(link2);
    }
}

fn main() {}
