// Error: a gear meshes with a crank's link on the ground (it reads that
// crank's input as the link's angle), and `link3` is a group's link; the fix
// names the crank to write first, or gearing to `ground`.
use mechanism::mechanism;

mechanism! {
    pub Geared {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(3.0, 0.0);
        let O5 = ground(5.0, 0.0);
        let A = crank(O2, 1.0, theta) as link2;
        let B = rrr(A, 3.0, O4, 2.5, left) as (link3, link4);
        let C = gear(O5, 0.5, link3, 2.0) as link5;
    }
}

fn main() {}
