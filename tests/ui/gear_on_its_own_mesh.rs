// Error: a gear meshing with the ground while on the ground never turns;
// the fix meshes it with a crank's link or carries it on one.
use mechanism::mechanism;

mechanism! {
    pub Geared {
        let O2 = ground(0.0, 0.0);
        let O5 = ground(3.0, 0.0);
        let A = crank(O2, 1.0, theta) as link2;
        let C = gear(O5, 0.5, ground, 2.0) as link5;
    }
}

fn main() {}
