//! Stage 3, validate: rules across statements, one function per rule, each
//! pushing errors with the span of the user's offending token and a hint.
//! All rules run, so several errors are reported at once.
//!
//! The rules by family: `names` (each name defined once, none reserved,
//! every reference resolved), `structure` (driver, mobility, outputs, an
//! RPP's slot, `#[self_test]`), `geometry` (joints, link points, pivots,
//! carried guides) and `kinetics` (the force analysis' masses and loads).

mod geometry;
mod kinetics;
mod names;
mod structure;

pub use names::{symbols, Category, RESERVED};

use crate::diag::Diagnostics;
use crate::model::{Level, Model};
use crate::plan::Plan;

/// The rules on the statements as written: names, references, drivers,
/// mobility, outputs, `#[self_test]`'s ranges.
pub fn model(model: &Model, errors: &mut Diagnostics) {
    // A name is defined once: points, links, slides, inputs, parameters and
    // constants share one namespace.
    names::unique_names(model, errors);
    // Names the generated code needs for itself are not available.
    names::reserved_names(model, errors);
    // A group's two known joints are two different places.
    geometry::distinct_joints(model, errors);
    // Every reference names something defined, of the right category, and
    // not the statement itself.
    names::references_resolve(model, errors);
    // At least one driver.
    structure::has_driver(model, errors);
    // A declared `dof N` matches Gruebler's count.
    structure::dof_matches(model, errors);
    // Every requested output is a point, a named link or a slide.
    structure::outputs_exist(model, errors);
    // Each kind's own rules on its arguments (an RPP's slot crosses its
    // guide).
    structure::kind_rules(model, errors);
    // Each kind's own rules on the inputs it names (a triad's pose is given
    // at a value of one of them).
    structure::kind_input_rules(model, errors);
    // `#[self_test]` has a range to sweep for every input, and at most two.
    structure::self_test_sweepable(model, errors);
}

/// The rules that need the solve order and the owner of every point: the
/// geometry of carried guides and link points, and the force analysis'
/// masses and loads.
pub fn planned(model: &Model, plan: &Plan, errors: &mut Diagnostics) {
    // A link point is measured from a point of its link; a crank turns about
    // a ground point; a guide passes through a point of what carries it.
    geometry::geometry_consistent(model, plan, errors);
    // With a force analysis, nothing is joined to an actuator's cylinder.
    if model.level >= Level::Forces {
        kinetics::nothing_on_a_cylinder(model, plan, errors);
    }
    // `analysis forces` has loads to carry, and loads are not left out by a
    // lower `analysis`.
    kinetics::level_matches_loads(model, errors);
    // `gravity` acts through at least one mass.
    kinetics::gravity_has_masses(model, errors);
    // `analysis dynamics` has inertia that moves with the inputs.
    kinetics::dynamics_has_inertia(model, plan, errors);
    // A mass sits on a loadable link, once per link, at a point of it.
    kinetics::masses_on_their_links(model, plan, errors);
    // A force acts at a point of one loadable link; `along` names a guide.
    kinetics::forces_at_points_of_links(model, plan, errors);
    // A torque acts on a loadable link.
    kinetics::torques_on_links(model, plan, errors);
    // A load value's name is its own.
    kinetics::load_names_unique(model, plan, errors);
    // Motors hold an inverse-kinematics definition's target: two, on
    // turning links, with names of their own.
    kinetics::motors_hold_the_target(model, plan, errors);
}

#[cfg(test)]
mod tests {
    use crate::diag::Diagnostics;
    use crate::{model, plan, validate};

    /// The messages of the errors of a four-bar with a coupler point and the
    /// statements `extra`, through the stages up to validation.
    fn errors(extra: &str) -> Vec<String> {
        errors_of(&format!(
            "pub M {{
                let O2 = ground(0.0, 0.0);
                let O4 = ground(4.0, 0.0);
                let A = crank(O2, 1.0, theta) as link2;
                let B = rrr(A, 3.0, O4, 2.5, left) as (link3, link4);
                let P = point(link3, from A, 1.0, 30 deg);
                {extra}
            }}"
        ))
    }

    /// The messages of the errors of the definition `src`.
    fn errors_of(src: &str) -> Vec<String> {
        let def = syn::parse_str::<crate::parse::Definition>(src).unwrap();
        let mut diag = Diagnostics::new();
        let model = model::lower(def, &mut diag);
        validate::model(&model, &mut diag);
        if let Some(plan) = plan::plan(&model, &mut diag) {
            validate::planned(&model, &plan, &mut diag);
        }
        diag.finish().iter().map(ToString::to_string).collect()
    }

    #[test]
    fn the_four_bar_breaks_no_rule() {
        // Proves the definition the other tests break is valid as it stands,
        // with loads too, so each of their errors comes from what they add.
        assert_eq!(errors(""), Vec::<String>::new());
        let loads = "mass link3 { m = 2.0, at = P } force at P = (1.0, 0.0); gravity (0.0, -9.81);";
        assert_eq!(errors(loads), Vec::<String>::new());
    }

    #[test]
    fn name_rules() {
        // Proves the rules on names: a name defined twice, a reserved prefix,
        // and a reference to a point that does not exist each give their one
        // error.
        assert_eq!(
            errors("let A = ground(1.0, 1.0);"),
            ["`A` is already defined by the `let A = crank(..)` statement above; every point, link, guide, slide, input, parameter and constant needs its own name: rename this one, e.g. `A2`"]
        );
        assert_eq!(
            errors("let vel_x = ground(1.0, 1.0);"),
            ["names starting with `vel_` are reserved for the generated code's locals; rename `vel_x`"]
        );
        assert_eq!(
            errors("let C = rrr(B, 1.0, Q4, 1.0, left) as (link5, link6);"),
            ["cannot find point `Q4`; did you mean `O4`?"]
        );
    }

    #[test]
    fn structure_rules() {
        // Proves the rules on the whole mechanism: no driver, a declared
        // mobility that is not Gruebler's, an output nothing defines, an RPP
        // slot parallel to its guide, `#[self_test]` with an input without a
        // range each give their one error.
        assert_eq!(
            errors_of("pub M { let O = ground(0.0, 0.0); }"),
            ["`M` has no driver, so nothing moves; add one, e.g. `let A = crank(O, radius, theta) as link2;`, a `slider(...)` or an `actuator(...)`"]
        );
        assert_eq!(
            errors("dof 2;"),
            ["the mechanism has 1 degree of freedom (Gruebler: 3*(4-1) - 2*4 = 1) for 1 input [theta], but `dof 2` is declared; add or remove a driver, or correct `dof`"]
        );
        assert_eq!(
            errors("outputs { B, link9 }"),
            ["this definition cannot give `link9`: no point, link or slide has that name; did you mean `link2`?"]
        );
        assert_eq!(
            errors("let line = guide(O4, 0 deg); let K = rpp(P, line, 180 deg) as (blk, yoke);"),
            ["the slot of `K` is at 180 deg to guide `line`, parallel to it; the slotted link slides along `line` without turning, so the slot stays parallel at every pose and the block's pin is at infinity for every input: give the slot an angle across the guide (e.g. `90 deg`, a slot perpendicular to it)"]
        );
        assert_eq!(
            errors_of(
                "#[self_test] pub M {
                    let line = guide((0.0, 0.0), 0 deg);
                    let S = slider(line, s) as block;
                }"
            ),
            ["`#[self_test]` tests the mechanism over its input range, and `s` has none: declare it, e.g. `range s = (0.0, 0.1);` (sliders and actuators have no default range)"]
        );
    }

    #[test]
    fn geometry_rules() {
        // Proves the rules on geometry: a group's two joints given as one
        // point, a crank about a moving point, a link point measured from a
        // point of another link each give their one error.
        assert_eq!(
            errors("let C = rrr(O2, 1.0, O2, 1.0, left) as (link5, link6);"),
            ["`O2` is given twice: the two known joints of this `rrr` must be different"]
        );
        assert_eq!(
            errors("let C = crank(B, 1.0, phi) as link5;"),
            ["a crank without a carrier turns about a ground point, and `B` moves; for a motor on the moving link that carries `B` (an elbow, a knee), name that link: `crank(B, 1.0, phi, link3)`, the input then being the angle from `link3`'s axis; or fix the pivot with `ground(x, y)`"]
        );
        assert_eq!(
            errors("let C = crank(B, 1.0, phi, link2) as link5;"),
            ["a crank carried by `link2` turns about one of its points, and `B` is not on it; its points: `O2`, `A`"]
        );
        assert_eq!(
            errors("let Q = point(link4, from A, 1.0, 0 deg);"),
            ["`A` is not a point of `link4`; measure from one of its points: `O4`, `B`"]
        );
    }

    #[test]
    fn kinetics_rules() {
        // Proves the rules of the force analysis: gravity without a mass, a
        // centre of mass off its link, a force at a joint of two links without
        // `on`, a load value named like a point each give their one error.
        assert_eq!(
            errors("gravity (0.0, -9.81); torque on link2 = 1.0;"),
            ["`gravity` acts through masses, and no link has one: add `mass LINK { m = .., at = POINT }`"]
        );
        assert_eq!(
            errors("mass link4 { m = 1.0, at = P }"),
            ["the centre of mass must be a point of `link4`, and `P` is not; its points are `O4`, `B`; or define one: `let G = point(link4, from O4, distance, angle);`"]
        );
        assert_eq!(
            errors("force at B = (1.0, 0.0);"),
            ["`B` joins `link3` and `link4`: say which link the force acts on, e.g. `force at B on link3 = (fx, fy);`"]
        );
        assert_eq!(
            errors("loads { B = 1.0 } torque on link3 = 1.0;"),
            ["`B` is already defined by the `let B = rrr(..)` statement; a load value needs a name of its own: rename it, e.g. `B2`, here and where it is used"]
        );
    }
}
