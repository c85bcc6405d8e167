// Error: an RPR whose block pin and rocker pivot are two ground points at the
// same place (copied coordinates): the error names both points.
use mechanism::mechanism;

mechanism! {
    pub Cylinder {
        let O2 = ground(0.0, 0.0);
        let O3 = ground(0.0, 0.0);
        let A = crank(O2, 0.05, theta) as link2;
        let s = rpr(O2, O3, plus) as (block, rocker);
    }
}

fn main() {}
