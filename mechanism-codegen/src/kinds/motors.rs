//! The motors of an inverse-kinematics definition (`motors { .. }`): the
//! one `target` statement they hold, and their torque fields of the forces
//! struct (`drive_NAME`), which the generated `forces()`, the stubs and the
//! run-time forces read.

use super::forces::{Held, Reaction};
use crate::model::{Kind, Model, Stmt};
use crate::names::Family;
use quote::{format_ident, quote};
use syn::Ident;

/// The local holding the motors' torques (`mechanism::force::target::MotorTorques`).
pub fn local() -> Ident {
    format_ident!("rx_motors")
}

/// The target statements of `model`, each with its `x` and `y` inputs.
pub fn targets(model: &Model) -> Vec<(&Stmt, &Ident, &Ident)> {
    model
        .stmts
        .iter()
        .filter_map(|s| match &s.kind {
            Kind::Target { x, y } => Some((s, x, y)),
            _ => None,
        })
        .collect()
}

/// The one target statement the motors of `model` hold, with its inputs
/// (`None` unless there is exactly one).
pub fn held_target(model: &Model) -> Option<(&Stmt, &Ident, &Ident)> {
    match targets(model)[..] {
        [one] => Some(one),
        _ => None,
    }
}

/// The motors' torque fields of the forces struct (`drive_NAME`), read from
/// [`local`]; none unless the definition has one target and two
/// motors.
pub fn reactions(model: &Model) -> Vec<Reaction> {
    let motors = &model.kinetics.motors;
    let Some((target, _, _)) = held_target(model) else {
        return Vec::new();
    };
    if motors.len() != 2 {
        return Vec::new();
    }
    let local = local();
    motors
        .iter()
        .enumerate()
        .map(|(k, m)| {
            let on = m.carrier.as_ref().map_or("the ground".to_string(), |c| format!("`{c}`"));
            Reaction {
                name: Family::Drive.of(&m.name),
                ty: quote!(T),
                value: quote!(#local.torque[#k]),
                doc: format!("Torque of the motor `{}` on `{}` (reacting on {on}; force x length units, counter-clockwise positive) that holds `{}` on its path: the target's driving force mapped to the motors by virtual work, `tau = J^T D`.", m.name, m.link, target.name),
                held: Held::Torque,
            }
        })
        .collect()
}
