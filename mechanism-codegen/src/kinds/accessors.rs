//! What only one kind has, read from the typed statement: a ground crank's
//! arm, a ground point's place, a guide's line, an actuator's cylinder, a
//! link point's link. Matches on [`Kind`], so no kind's view is needed.

use super::group::GuideLine;
use super::pose;
use crate::model::{Kind, Stmt};
use crate::value::Value;
use syn::Ident;

/// For a crank on the ground: its pivot and radius (`None` for other
/// statements, and for a crank carried by a moving link).
pub fn crank_arm(stmt: &Stmt) -> Option<(&Ident, &Value)> {
    match &stmt.kind {
        Kind::Crank {
            pivot,
            radius,
            carrier: None,
            ..
        } => Some((pivot, radius)),
        _ => None,
    }
}

/// For a crank whose input is marked `as cos_sin`: its input.
pub fn cos_sin_input(stmt: &Stmt) -> Option<&Ident> {
    match &stmt.kind {
        Kind::Crank {
            input,
            cos_sin: true,
            ..
        } => Some(input),
        _ => None,
    }
}

/// For a ground point: its coordinates (NaN where they do not fold).
pub fn ground_at(stmt: &Stmt) -> Option<(f64, f64)> {
    match &stmt.kind {
        Kind::Ground { x, y } => Some((pose::num(x), pose::num(y))),
        _ => None,
    }
}

/// For a ground point with literal coordinates: where it is.
pub fn literal_ground(stmt: &Stmt) -> Option<(f64, f64)> {
    match &stmt.kind {
        Kind::Ground { x, y } => Some((x.fold()?, y.fold()?)),
        _ => None,
    }
}

/// For a guide: its line as written.
pub fn as_guide(stmt: &Stmt) -> Option<GuideLine<'_>> {
    match &stmt.kind {
        Kind::Guide {
            origin,
            angle,
            carrier,
        } => Some(GuideLine {
            carrier: carrier.as_ref(),
            through: match origin {
                crate::model::Origin::Point(p) => Some(p),
                crate::model::Origin::Coords(..) => None,
            },
            angle,
        }),
        _ => None,
    }
}

/// For a guide: its carrier (`None`: fixed); `None` for other statements.
pub fn guide_carrier(stmt: &Stmt) -> Option<Option<&Ident>> {
    as_guide(stmt).map(|g| g.carrier)
}

/// The link that is a massless two-force member carrying no load: an
/// actuator's cylinder named as one link (`as (LINK, CYLINDER)`; with a
/// barrel and a rod the cylinder has mass).
pub fn cylinder(stmt: &Stmt) -> Option<&Ident> {
    match (&stmt.kind, stmt.links.as_slice()) {
        (Kind::Actuator { .. }, [_, cylinder]) => Some(cylinder),
        _ => None,
    }
}

/// For a point on a link: the link.
pub fn on_link(stmt: &Stmt) -> Option<&Ident> {
    match &stmt.kind {
        Kind::Point { link, .. } => Some(link),
        _ => None,
    }
}
