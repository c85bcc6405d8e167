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

pub use names::{symbols, Category, RESERVED, RESERVED_PREFIXES};

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
    // An RPP's slot crosses its guide.
    structure::rpp_slot_crosses_guide(model, errors);
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
    if model.level == Level::Forces {
        kinetics::nothing_on_a_cylinder(model, plan, errors);
    }
    // `analysis forces` has loads to carry, and loads are not left out by a
    // lower `analysis`.
    kinetics::level_matches_loads(model, errors);
    // `gravity` acts through at least one mass.
    kinetics::gravity_has_masses(model, errors);
    // A mass sits on a loadable link, once per link, at a point of it.
    kinetics::masses_on_their_links(model, plan, errors);
    // A force acts at a point of one loadable link; `along` names a guide.
    kinetics::forces_at_points_of_links(model, plan, errors);
    // A torque acts on a loadable link.
    kinetics::torques_on_links(model, plan, errors);
    // A load value's name is its own.
    kinetics::load_names_unique(model, plan, errors);
}
