//! Tests of the kinds' force code (`kinds::*::forces`) through the force
//! emitter: reactions named by the bodies on each side, passed on negated.

#[cfg(test)]
mod tests {
    use crate::emit::test_support::{flat, four_bar, planned};

    /// The forces struct's fields of `src` as `name:value` pairs, and the
    /// `forces` method's code, without whitespace.
    fn reactions(src: &str) -> (Vec<String>, String) {
        let (model, plan) = planned(src);
        let moving = plan.moving_points(&model);
        let reads = crate::kinds::reads::Reads::default();
        let code = super::super::emit(&model, &plan, &moving, &reads);
        let methods = flat(&code.methods);
        let value = methods.split("Ok(").last().unwrap();
        let fields = value
            .split(['{', '}', ','])
            .filter(|f| f.contains(':'))
            .map(str::to_string)
            .collect();
        (fields, methods)
    }

    // Proves a four-bar's reactions, groups taken in the reverse of the solve
    // order: the RRR's three joints named after the bodies on each side (its
    // pin at A on the crank, at O4 on the ground, the inner one at B), then
    // the crank's pivot and driving torque; and the RRR's reaction at A is
    // passed, negated, onto the crank's load.
    #[test]
    fn four_bar_reactions_by_body_and_passed_on() {
        let (fields, code) = reactions(&four_bar("mass link3 { m = 2.0, at = P };"));
        assert_eq!(
            fields,
            [
                "r_link2_link3:rx_B.a",
                "r_ground_link4:rx_B.b",
                "r_link3_link4:rx_B.c",
                "r_ground_link2:rx_A.pivot",
                "drive_theta2:rx_A.torque",
            ]
        );
        assert!(
            code.contains(
                "letload_link2=::mechanism::force::Wrench::force_at(&(-rx_B.a),&pos.A,&pos.O2);"
            ),
            "{code}"
        );
    }

    // Proves an RRP on a fixed guide reports its guide's reaction as a
    // prismatic one of the ground on the block, passes nothing to the ground,
    // and takes the block's load about its point B.
    #[test]
    fn rrp_on_a_fixed_guide_reacts_on_the_ground() {
        let src = "pub SliderCrank {
            params { crank = 0.1, rod = 0.4, offset = 0.02 }
            let O = ground(0.0, 0.0);
            let line = guide((0.0, offset), 0 deg);
            let A = crank(O, crank, theta) as link2;
            let B = rrp(A, rod, line, plus) as (link3, slider) slide x;
            mass slider { m = 1.5, at = B };
        }";
        let (fields, code) = reactions(src);
        assert_eq!(
            fields,
            [
                "r_link2_link3:rx_B.a",
                "r_link3_slider:rx_B.c",
                "r_ground_slider:rx_B.guide",
                "r_ground_link2:rx_A.pivot",
                "drive_theta:rx_A.torque",
            ]
        );
        assert!(
            code.contains("rrp::reactions(&pos.A,&pos.B,&pos.line.dir,&::mechanism::force::Wrench::zero(),&load_slider)"),
            "{code}"
        );
        assert!(!code.contains("load_ground"), "{code}");
    }
}
