//! Pictures and tables of any mechanism `mechanism!` generates, from its
//! description of itself (`mechanism::structure`): no drawing code per
//! mechanism.
//!
//! The caller solves the poses (one `position()` per input value, `None` where
//! it fails) and hands them over with the input; everything else comes from
//! the structure: which points are ground pivots, which link joins which
//! points, which blocks slide on which guides.
//!
//! ```ignore
//! let poses: Vec<(f64, Option<FourBarPosition>)> = thetas
//!     .iter()
//!     .map(|&t| (t, fb.position(&FourBarInput { theta2: t }).ok()))
//!     .collect();
//! let sketch = mechanism_plot::any::sketch::<FourBar, _>("Four-bar", "mm", &poses, &["P"])?;
//! sketch.write_animation(4.0, "fourbar.svg")?;
//! std::fs::write("fourbar.csv", mechanism_plot::any::csv("theta2", "rad", &poses))?;
//! ```

use crate::{Frame, PlotError, Sketch, Xy};
use mechanism_core::structure::{Describe, Fields, Guide, LinkKind, PointKind, Structure, Value};
use std::fmt::Write;

/// One solved pose: the input value and the position (`None`: the mechanism
/// cannot be assembled there; drawn as a gap, not as a jump).
pub type Pose<P> = (f64, Option<P>);

fn point_of<P: Fields<f64>>(pos: &P, name: &str) -> Option<Xy> {
    match pos.get(name) {
        Some(Value::Point(p)) if p.x.is_finite() && p.y.is_finite() => Some([p.x, p.y]),
        _ => None,
    }
}

/// The direction (rad) a block slides along at one pose: a fixed guide's own
/// angle; a carried guide's angle from its carrier's axis (the carrier's
/// first two points); an RPR block's from the other link's origin.
fn block_angle<P: Fields<f64>>(s: &Structure, link: usize, pos: &P) -> f64 {
    let axis = |points: &[&str]| -> Option<f64> {
        let a = point_of(pos, points.first()?)?;
        let b = point_of(pos, points.get(1)?)?;
        Some((b[1] - a[1]).atan2(b[0] - a[0]))
    };
    let l = &s.links[link];
    match l.guide.and_then(|g| s.guide(g)) {
        Some(Guide {
            carrier: None,
            angle,
            ..
        }) => angle.unwrap_or(0.0),
        Some(Guide {
            carrier: Some(c),
            angle,
            ..
        }) => {
            let carrier = s.link(c).map(|c| axis(c.points)).unwrap_or(None);
            carrier.unwrap_or(0.0) + angle.unwrap_or(0.0)
        }
        None => {
            // An RPR's block slides along the next link, through its origin.
            let other = s.links.get(link + 1).and_then(|o| o.points.first());
            match (other, l.points.first()) {
                (Some(o), Some(p)) => axis(&[o, p]).unwrap_or(0.0),
                _ => 0.0,
            }
        }
    }
}

/// One pose as a frame: links (bars and plates through their points), blocks
/// on their guides, revolute joints, and the traced points.
fn frame<P: Fields<f64>>(s: &Structure, caption: &str, pos: &P, traced: &[&str]) -> Frame {
    let mut f = Frame::new(caption);
    for (k, l) in s.links.iter().enumerate() {
        let pts: Vec<Xy> = l.points.iter().filter_map(|p| point_of(pos, p)).collect();
        match l.kind {
            LinkKind::Block => {
                if let Some(p) = pts.first() {
                    f = f.slider(l.name, *p, block_angle(s, k, pos));
                }
            }
            _ if pts.len() >= 2 => f = f.link(l.name, &pts),
            _ => {}
        }
    }
    for p in s.points {
        let Some(xy) = point_of(pos, p.name) else {
            continue;
        };
        match p.kind {
            PointKind::Joint => f = f.joint(p.name, xy),
            PointKind::OnLink if traced.contains(&p.name) => f = f.point(p.name, xy),
            _ => {}
        }
    }
    f
}

/// A drawing of mechanism `M` over its poses: ground pivots with hatching,
/// fixed guides as long as the blocks travel on them, one frame per pose that
/// assembles (captioned with its input), and the paths of the `traced`
/// points, broken where a pose fails. `unit` is the length unit shown on the
/// scale bar. [`Sketch::drawing`] draws one frame, [`Sketch::animation`] all.
pub fn sketch<M: Describe, P: Fields<f64>>(
    title: &str,
    unit: &str,
    poses: &[Pose<P>],
    traced: &[&str],
) -> Result<Sketch, PlotError> {
    let s = M::STRUCTURE;
    let mut sketch = Sketch::new(title, unit);
    let input = s.inputs.first().map_or("input", |i| i.name);
    let solved: Vec<(f64, &P)> = poses
        .iter()
        .filter_map(|(q, p)| p.as_ref().map(|p| (*q, p)))
        .collect();
    let Some(&(_, first)) = solved.first() else {
        return Err(PlotError::NothingToDraw);
    };
    for p in s.points.iter().filter(|p| p.kind == PointKind::Ground) {
        let on_link = s.links.iter().any(|l| l.points.contains(&p.name));
        if let (true, Some(xy)) = (on_link, point_of(first, p.name)) {
            sketch.ground_pivot(p.name, xy);
        }
    }
    for (k, l) in s.links.iter().enumerate() {
        let fixed = l
            .guide
            .and_then(|g| s.guide(g))
            .filter(|g| g.carrier.is_none());
        if let (LinkKind::Block, Some(_)) = (l.kind, fixed) {
            let along: Vec<Xy> = solved
                .iter()
                .filter_map(|(_, p)| l.points.first().and_then(|n| point_of(*p, n)))
                .collect();
            if let Some((a, b)) = travel(&along, block_angle(&s, k, first)) {
                sketch.ground_guide(a, b);
            }
        }
    }
    for name in traced {
        for run in runs(poses, |p| point_of(p, name)) {
            sketch.path(name, &run);
        }
    }
    for (q, p) in &solved {
        sketch.frame(frame(&s, &format!("{input} = {q:.4}"), *p, traced));
    }
    Ok(sketch)
}

/// The segment a guide is drawn as: the blocks' travel along `angle`, with a
/// margin of a fifth of it (at least one unit of the block positions' scale).
fn travel(points: &[Xy], angle: f64) -> Option<(Xy, Xy)> {
    let first = *points.first()?;
    let (c, s) = (angle.cos(), angle.sin());
    let t = |p: &Xy| (p[0] - first[0]) * c + (p[1] - first[1]) * s;
    let lo = points.iter().map(t).fold(f64::INFINITY, f64::min);
    let hi = points.iter().map(t).fold(f64::NEG_INFINITY, f64::max);
    let scale = first[0].abs().max(first[1].abs()).max(hi - lo);
    let margin = (0.2 * (hi - lo)).max(0.05 * scale);
    let at = |u: f64| [first[0] + u * c, first[1] + u * s];
    Some((at(lo - margin), at(hi + margin)))
}

/// The runs of consecutive poses where `value` exists (a path breaks where
/// the mechanism cannot be assembled).
fn runs<P, V>(poses: &[Pose<P>], value: impl Fn(&P) -> Option<V>) -> Vec<Vec<V>> {
    let mut out: Vec<Vec<V>> = vec![Vec::new()];
    for (_, p) in poses {
        match p.as_ref().and_then(&value) {
            Some(v) => out.last_mut().expect("one run at least").push(v),
            None if out.last().is_some_and(|r| !r.is_empty()) => out.push(Vec::new()),
            None => {}
        }
    }
    out.retain(|r| !r.is_empty());
    out
}

/// A CSV table of every field of `P` over the poses: the input first, then
/// each point as two columns (`B.x`, `B.y`) and each scalar as one, units in
/// the headers (`L` is the definition's length unit: `B.x [L]`,
/// `link3 [rad]`). A pose that fails is a row with empty fields, so the gap
/// shows in a spreadsheet. Values with 17 significant digits (round-trip).
pub fn csv<P: Fields<f64>>(input: &str, input_unit: &str, poses: &[Pose<P>]) -> String {
    let mut out = format!("{input} [{input_unit}]");
    for f in P::FIELDS {
        let unit = f.quantity.unit();
        if f.planar {
            let _ = write!(out, ",{0}.x [{unit}],{0}.y [{unit}]", f.name);
        } else {
            let _ = write!(out, ",{} [{unit}]", f.name);
        }
    }
    out.push('\n');
    for (q, p) in poses {
        let _ = write!(out, "{q:.16e}");
        for f in P::FIELDS {
            let cells = match p.as_ref().and_then(|p| p.get(f.name)) {
                Some(Value::Point(v)) => format!("{:.16e},{:.16e}", v.x, v.y),
                Some(Value::Vector(v)) => format!("{:.16e},{:.16e}", v.x, v.y),
                Some(Value::Scalar(x)) => format!("{x:.16e}"),
                None if f.planar => ",".to_string(),
                None => String::new(),
            };
            let _ = write!(out, ",{cells}");
        }
        out.push('\n');
    }
    out
}
