// `analysis dynamics` on a four-bar whose only mass sits at the crank's
// ground pivot without a moment of inertia: nothing moves with the input.
use mechanism::mechanism;

mechanism! {
    pub NoInertia {
        analysis dynamics;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.30, 0.0);
        let A = crank(O2, 0.10, phi) as crank;
        let B = rrr(A, 0.25, O4, 0.18, left) as (coupler, rocker);
        mass crank { m = 2.0, at = O2 };
    }
}

fn main() {}
