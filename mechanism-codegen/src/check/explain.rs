//! What a failing or singular group means, in the user's words and numbers:
//! the distances that do not close, the links that align, the four-bar's
//! Grashof condition, and a `range` statement that would pass.

use super::eval::num;
use crate::diag::show_num;
use crate::model::{Input, Kind, Model};
use crate::plan::Plan;
use mechanism_core::Fault;
use syn::Ident;

/// A range statement for a hint: the interval shrunk inward to whole tenths
/// (deg for angles), strictly inside; `None` when nothing is left.
pub fn suggest(input: &Input, lo: f64, hi: f64) -> Option<String> {
    let (lo, hi, unit) = if input.angle {
        (lo.to_degrees(), hi.to_degrees(), " deg")
    } else {
        (lo, hi, "")
    };
    let scale = if input.angle {
        10.0
    } else {
        // Two significant digits of the width below its leading digit.
        let w = hi - lo;
        if w <= 0.0 {
            return None;
        }
        10f64.powi(2 - w.log10().ceil() as i32)
    };
    let a = (lo * scale).floor() / scale + 1.0 / scale;
    let b = (hi * scale).ceil() / scale - 1.0 / scale;
    (a < b).then(|| {
        format!(
            "`range {} = ({}{unit}, {}{unit});`",
            input.name,
            show_num(a),
            show_num(b)
        )
    })
}

/// What the failing group's fault means, in the user's words.
pub fn explain(model: &Model, stmt_index: usize, fault: &Fault, at: &str) -> String {
    let stmt = &model.stmts[stmt_index];
    match (&stmt.kind, fault) {
        (Kind::Actuator { a, b, .. }, Fault::CannotAssemble { miss, reach }) => format!(
            "at {at}, `{a}` and `{b}` are {} outside the distances the link and the cylinder can span (bound {})",
            show_num(*miss),
            show_num(*reach)
        ),
        (Kind::Rrr { a, l1, b, l2, .. }, Fault::CannotAssemble { miss, reach }) => {
            let (l1, l2) = (num(l1), num(l2));
            if (reach - (l1 + l2)).abs() <= 1e-9 * reach.abs().max(1.0) {
                format!(
                    "at {at}, `{a}` and `{b}` are {} apart, {} more than the links reach ({} + {} = {})",
                    show_num(reach + miss),
                    show_num(*miss),
                    show_num(l1),
                    show_num(l2),
                    show_num(*reach)
                )
            } else {
                format!(
                    "at {at}, `{a}` and `{b}` are {} apart, {} less than the links' difference (|{} - {}| = {})",
                    show_num(reach - miss),
                    show_num(*miss),
                    show_num(l1),
                    show_num(l2),
                    show_num(*reach)
                )
            }
        }
        (Kind::Rrp { a, guide, .. }, Fault::CannotAssemble { miss, reach }) => format!(
            "at {at}, `{a}` is {} from the line of guide `{guide}`, {} more than the link's length {} reaches",
            show_num(reach + miss),
            show_num(*miss),
            show_num(*reach)
        ),
        (Kind::Rpr { a, b, .. }, Fault::CannotAssemble { miss, reach }) => format!(
            "at {at}, `{a}` is {} from `{b}`, {} inside the offset {} of the slide line",
            show_num(reach - miss),
            show_num(*miss),
            show_num(*reach)
        ),
        (Kind::Prp { g1, g2, .. }, Fault::Singular { .. }) => format!(
            "at {at}, guides `{g1}` and `{g2}` are parallel: the joint is at infinity"
        ),
        (Kind::Rpp { guide, .. }, Fault::Singular { .. }) => format!(
            "at {at}, the slot is parallel to guide `{guide}`: the joint is at infinity"
        ),
        (_, fault) => format!("at {at}: {fault}"),
    }
}

/// Why a group is singular, in the user's words.
pub fn singular_meaning(model: &Model, stmt_index: usize) -> String {
    let stmt = &model.stmts[stmt_index];
    let l = |k: usize| stmt.links[k].to_string();
    match &stmt.kind {
        Kind::Rrr { .. } => format!("links `{}` and `{}` are aligned (toggle)", l(0), l(1)),
        Kind::Actuator { .. } => format!(
            "the cylinder `{}` is aligned with link `{}` (dead centre)",
            l(1),
            l(0)
        ),
        Kind::Rrp { guide, .. } => format!(
            "link `{}` is perpendicular to guide `{guide}` (the block cannot be pushed along it)",
            l(0)
        ),
        Kind::Rpr { a, b, .. } => {
            format!("`{a}` is at the foot of the perpendicular from `{b}` on the slide line")
        }
        Kind::Prp { g1, g2, .. } => format!("guides `{g1}` and `{g2}` are parallel"),
        Kind::Rpp { guide, .. } => format!("the slot is parallel to guide `{guide}`"),
        _ => "its rate system is singular".into(),
    }
}

/// For a crank driving an RRR group onto a ground point: the four-bar's
/// Grashof condition, in numbers.
pub fn grashof(model: &Model, plan: &Plan, stmt_index: usize) -> Option<String> {
    let stmt = &model.stmts[stmt_index];
    let Kind::Rrr { a, l1, b, l2, .. } = &stmt.kind else {
        return None;
    };
    let find = |n: &Ident| plan.defined.get(&n.to_string()).map(|&i| &model.stmts[i]);
    let ground = |n: &Ident| match find(n).map(|s| &s.kind) {
        Some(Kind::Ground { x, y }) => Some((num(x), num(y))),
        _ => None,
    };
    let (crank, other) = match (find(a).map(|s| &s.kind), find(b).map(|s| &s.kind)) {
        (Some(Kind::Crank { .. }), _) => (find(a)?, b),
        (_, Some(Kind::Crank { .. })) => (find(b)?, a),
        _ => return None,
    };
    let Kind::Crank { pivot, radius, .. } = &crank.kind else {
        return None;
    };
    let (o, g) = (ground(pivot)?, ground(other)?);
    let base = (o.0 - g.0).hypot(o.1 - g.1);
    let r = num(radius);
    let mut links = [
        (r, format!("crank {}", show_num(r))),
        (num(l1), show_num(num(l1))),
        (num(l2), show_num(num(l2))),
        (base, format!("ground {}", show_num(base))),
    ];
    links.sort_by(|x, y| x.0.total_cmp(&y.0));
    let (s, p, q, l) = (&links[0], &links[1], &links[2], &links[3]);
    let text = format!(
        "s + l = {} + {} = {}, p + q = {} + {} = {}",
        s.1,
        l.1,
        show_num(s.0 + l.0),
        p.1,
        q.1,
        show_num(p.0 + q.0)
    );
    Some(if s.0 + l.0 > p.0 + q.0 {
        format!("the four-bar `{pivot}`-`{}`-`{}`-`{other}` is not Grashof ({text}): no link turns fully", crank.name, stmt.name)
    } else if s.0 < r {
        format!("the four-bar `{pivot}`-`{}`-`{}`-`{other}` is Grashof ({text}), but the crank is not its shortest link: only the shortest link turns fully", crank.name, stmt.name)
    } else {
        return None;
    })
}
