//! Drawings and animations of a mechanism read at run time
//! (`mechanism_codegen::runtime::Mechanism`, feature `runtime`): the same
//! [`Sketch`] as the generated code's pictures ([`crate::any`]: ground
//! pivots with hatching, links as bars or plates, blocks on their guides,
//! traced paths), its shapes from `Mechanism::layout` and the solved poses
//! instead of a compile-time description. The `mechanism` command's
//! `draw` and `animate` and the Python package's `Mechanism.draw` and
//! `Mechanism.animate` are made here.

use crate::{Frame, Sketch};
use mechanism_codegen::runtime::layout::{Layout, LinkKind, PointKind};
use mechanism_codegen::runtime::{Mechanism, Position};

/// One pose: its caption and its position (`None`: it does not assemble).
pub type Pose = (String, Option<Position>);

/// A frame's caption: each input's name and value, an angle in degrees
/// (`theta = 30 deg`), a length in the length unit.
pub fn caption(m: &Mechanism, q: &[f64]) -> String {
    let unit = m.layout().length_unit;
    let parts: Vec<String> = m
        .inputs()
        .iter()
        .zip(q)
        .map(|(i, &v)| {
            if i.angle {
                format!("{} = {} deg", i.name, short(v.to_degrees()))
            } else {
                format!("{} = {} {unit}", i.name, short(v))
            }
        })
        .collect();
    parts.join(", ")
}

/// A number with at most four decimals, trailing zeros dropped.
fn short(v: f64) -> String {
    let s = format!("{v:.4}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.into()
    }
}

/// The drawing of `poses`: ground pivots and fixed guides from the poses
/// that assemble, one frame per such pose, the paths of the `traced`
/// points (broken where a pose fails). `Err`: a point to trace that does
/// not exist, or no pose assembles.
pub fn sketch(
    m: &Mechanism,
    title: &str,
    poses: &[Pose],
    traced: &[String],
) -> Result<Sketch, String> {
    let layout = m.layout();
    for t in traced {
        if !layout.points.iter().any(|p| p.name == *t) {
            let names: Vec<String> = layout
                .points
                .iter()
                .map(|p| format!("`{}`", p.name))
                .collect();
            return Err(format!(
                "--trace: no point `{t}`; the points are: {}",
                names.join(", ")
            ));
        }
    }
    let solved: Vec<(&String, &Position)> = poses
        .iter()
        .filter_map(|(c, p)| p.as_ref().map(|p| (c, p)))
        .collect();
    let Some(&(_, first)) = solved.first() else {
        return Err("no pose of the sweep assembles: nothing to draw".into());
    };
    let mut sk = Sketch::new(title, &layout.length_unit);
    for p in layout.points.iter().filter(|p| p.kind == PointKind::Ground) {
        let on_link = layout.links.iter().any(|l| l.points.contains(&p.name));
        if let (true, Some(xy)) = (on_link, first.point(&p.name)) {
            sk.ground_pivot(&p.name, xy);
        }
    }
    for l in &layout.links {
        if let Some((a, b)) = fixed_guide(&layout, l.guide.as_deref(), &l.points, &solved) {
            sk.ground_guide(a, b);
        }
    }
    for name in traced {
        let mut run: Vec<[f64; 2]> = Vec::new();
        for (_, p) in poses {
            match p.as_ref().and_then(|p| p.point(name)) {
                Some(xy) => run.push(xy),
                None if !run.is_empty() => {
                    sk.path(name, &run);
                    run.clear();
                }
                None => {}
            }
        }
        if !run.is_empty() {
            sk.path(name, &run);
        }
    }
    for (c, p) in &solved {
        sk.frame(frame(m, &layout, c, p, traced));
    }
    Ok(sk)
}

/// A fixed guide's drawn segment: the travel of its block's point over the
/// poses along the guide, with a margin of a fifth of it (at least a
/// twentieth of the drawing's size). `None` for a carried guide or a link
/// on none.
fn fixed_guide(
    layout: &Layout,
    guide: Option<&str>,
    points: &[String],
    solved: &[(&String, &Position)],
) -> Option<([f64; 2], [f64; 2])> {
    let guide = guide?;
    if carrier(layout, guide).is_some() {
        return None;
    }
    let (_, first) = solved.first()?;
    let (origin, angle) = first.guide(guide)?;
    let (c, s) = (angle.cos(), angle.sin());
    let block = points.first()?;
    let along: Vec<f64> = solved
        .iter()
        .filter_map(|(_, p)| p.point(block))
        .map(|q| (q[0] - origin[0]) * c + (q[1] - origin[1]) * s)
        .collect();
    let lo = along.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = along.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let size = layout
        .points
        .iter()
        .filter_map(|p| first.point(&p.name))
        .map(|q| q[0].abs().max(q[1].abs()))
        .fold(0.0, f64::max);
    let margin = (0.2 * (hi - lo)).max(0.05 * size);
    let at = |u: f64| [origin[0] + u * c, origin[1] + u * s];
    (lo.is_finite() && hi.is_finite()).then(|| (at(lo - margin), at(hi + margin)))
}

/// The link carrying guide `name` (`None`: fixed, or no such guide).
fn carrier<'l>(layout: &'l Layout, name: &str) -> Option<&'l str> {
    layout
        .guides
        .iter()
        .find(|g| g.name == name)
        .and_then(|g| g.carrier.as_deref())
}

/// One frame: every link (a block at its point along its direction, with a
/// carried guide from the guide's origin past the block), the joints, and
/// the traced points.
fn frame(
    m: &Mechanism,
    layout: &Layout,
    caption: &str,
    pos: &Position,
    traced: &[String],
) -> Frame {
    let mut f = Frame::new(caption);
    for l in &layout.links {
        let pts: Vec<[f64; 2]> = l.points.iter().filter_map(|p| pos.point(p)).collect();
        match l.kind {
            LinkKind::Block => {
                let (Some(p), Some(angle)) = (pts.first(), m.link_direction(pos, &l.name)) else {
                    continue;
                };
                let carried = l.guide.as_deref().filter(|g| carrier(layout, g).is_some());
                if let Some((o, _)) = carried.and_then(|g| pos.guide(g)) {
                    // From its origin on the carrier to a quarter of that
                    // distance beyond the block.
                    let far = [p[0] + 0.25 * (p[0] - o[0]), p[1] + 0.25 * (p[1] - o[1])];
                    f = f.guide(o, far);
                }
                f = f.slider(&l.name, *p, angle);
            }
            _ if pts.len() >= 2 => f = f.link(&l.name, &pts),
            _ => {}
        }
    }
    for p in &layout.points {
        let Some(xy) = pos.point(&p.name) else {
            continue;
        };
        let links = layout
            .links
            .iter()
            .filter(|l| l.points.contains(&p.name))
            .count();
        match p.kind {
            PointKind::Joint => f = f.joint(&p.name, xy),
            PointKind::OnLink if links >= 2 => f = f.joint(&p.name, xy),
            PointKind::OnLink if traced.contains(&p.name) => f = f.point(&p.name, xy),
            _ => {}
        }
    }
    f
}

/// The poses of a sweep, each with its caption.
pub fn poses(m: &Mechanism, points: &[Vec<f64>], tick: &dyn Fn()) -> Vec<Pose> {
    points
        .iter()
        .map(|q| {
            let p = m.position(q).ok();
            tick();
            (caption(m, q), p)
        })
        .collect()
}
