//! Pictures, charts and tables of any mechanism `mechanism!` generates, from
//! its description of itself (`mechanism::structure`): no drawing code per
//! mechanism.
//!
//! The caller solves the poses (one `position()` per input value, `None` where
//! it fails) and hands them over with the input; everything else comes from
//! the structure and the result structs' fields: which points are ground
//! pivots, which link joins which points, which blocks slide on which guides,
//! what each output measures and in which unit. [`sketch`] draws and animates,
//! [`chart`], [`kinematics_chart`] and [`force_chart`] plot outputs against
//! the input (failed poses as gaps), [`csv`] tabulates.
//!
//! ```ignore
//! let poses: Vec<(f64, Option<FourBarPosition>)> = thetas
//!     .iter()
//!     .map(|&t| (t, fb.position(&FourBarInput { theta2: t }).ok()))
//!     .collect();
//! let sketch = mechanism_plot::any::sketch::<FourBar<f64>, _>("Four-bar", &poses, &["P"])?;
//! sketch.write_animation(4.0, "fourbar.svg")?;
//! std::fs::write("fourbar.csv", mechanism_plot::any::csv("theta2", "rad", &poses))?;
//! ```

use crate::{Figure, Frame, Plot, PlotError, Sketch, Xy};
use mechanism_core::structure::{
    Describe, Field, Fields, Guide, LinkKind, PointKind, Quantity, Structure, Units, Value,
};
use mechanism_core::{Point2, Real, Vector2};
use std::fmt::Write;

/// One solved pose: the input value and the position (`None`: the mechanism
/// cannot be assembled there; drawn as a gap, not as a jump). The results
/// may be `f32` or `f64` (`FourBarPosition<f32>`); the input is an `f64`
/// either way (widen an `f32` input with `f64::from`).
pub type Pose<P> = (f64, Option<P>);

/// The field `name` of a result of either precision, as `f64` (an `f32`
/// widens exactly).
fn value<T: Real, P: Fields<T>>(pos: &P, name: &str) -> Option<Value<f64>> {
    Some(match pos.get(name)? {
        Value::Point(p) => Value::Point(Point2::new(p.x.as_f64(), p.y.as_f64())),
        Value::Vector(v) => Value::Vector(Vector2::new(v.x.as_f64(), v.y.as_f64())),
        Value::Scalar(x) => Value::Scalar(x.as_f64()),
    })
}

fn point_of<T: Real, P: Fields<T>>(pos: &P, name: &str) -> Option<Xy> {
    match value(pos, name) {
        Some(Value::Point(p)) if p.x.is_finite() && p.y.is_finite() => Some([p.x, p.y]),
        _ => None,
    }
}

/// The direction (rad) a block slides along at one pose: a fixed guide's own
/// angle; a carried guide's angle from its carrier's axis (the carrier's
/// first two points); an RPR block's from the other link's origin.
fn block_angle<T: Real, P: Fields<T>>(s: &Structure, link: usize, pos: &P) -> f64 {
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

/// Where a guide carried by a link starts at one pose: the named point it
/// passes through, else its carrier's first point (`None` for a fixed guide).
fn carried_guide_origin<T: Real, P: Fields<T>>(
    s: &Structure,
    guide: Option<&str>,
    pos: &P,
) -> Option<Xy> {
    let g = s.guide(guide?)?;
    let carrier = s.link(g.carrier?)?;
    point_of(pos, g.through.or(carrier.points.first().copied())?)
}

/// One pose as a frame: links (bars and plates through their points), blocks
/// on their guides, revolute joints, and the traced points.
fn frame<T: Real, P: Fields<T>>(s: &Structure, caption: &str, pos: &P, traced: &[&str]) -> Frame {
    let mut f = Frame::new(caption);
    for (k, l) in s.links.iter().enumerate() {
        let pts: Vec<Xy> = l.points.iter().filter_map(|p| point_of(pos, p)).collect();
        match l.kind {
            LinkKind::Block => {
                if let Some(p) = pts.first() {
                    if let Some(o) = carried_guide_origin(s, l.guide, pos) {
                        // The carried guide, from its origin on the carrier to a
                        // quarter of that distance beyond the block.
                        let far = [p[0] + 0.25 * (p[0] - o[0]), p[1] + 0.25 * (p[1] - o[1])];
                        f = f.guide(o, far);
                    }
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
        // A point fixed on one link where another is pinned is a joint too.
        let links = s
            .links
            .iter()
            .filter(|l| l.points.contains(&p.name))
            .count();
        match p.kind {
            PointKind::Joint => f = f.joint(p.name, xy),
            PointKind::OnLink if links >= 2 => f = f.joint(p.name, xy),
            PointKind::OnLink if traced.contains(&p.name) => f = f.point(p.name, xy),
            _ => {}
        }
    }
    f
}

/// A drawing of mechanism `M` over its poses: ground pivots with hatching,
/// fixed guides as long as the blocks travel on them, one frame per pose that
/// assembles (captioned with its input: `theta = 30 deg` for a crank, whose
/// pose holds radians; `s = 12.5 mm` for a slider), and the paths of the `traced`
/// points, broken where a pose fails. The scale bar is in the definition's
/// length unit (its `units` statement; `L` without one). The results may be
/// `f32` or `f64`. [`Sketch::drawing`] draws one frame, [`Sketch::animation`] all.
pub fn sketch<M: Describe, T: Real>(
    title: &str,
    poses: &[Pose<impl Fields<T>>],
    traced: &[&str],
) -> Result<Sketch, PlotError> {
    let input = M::STRUCTURE.inputs.first();
    let name = input.map_or("input", |i| i.name);
    let angle = input.is_some_and(|i| i.quantity == Quantity::Angle);
    let unit = M::STRUCTURE.units.length;
    sketch_with::<M, T>(title, poses, traced, |q| caption(name, q, angle, unit))
}

/// [`sketch`] with each frame's caption made by `caption` from the pose's
/// input value (for several inputs, or an input in other units than the
/// structure's).
pub fn sketch_with<M: Describe, T: Real>(
    title: &str,
    poses: &[Pose<impl Fields<T>>],
    traced: &[&str],
    caption: impl Fn(f64) -> String,
) -> Result<Sketch, PlotError> {
    draw(&M::STRUCTURE, title, poses, traced, caption)
}

/// [`sketch_with`] for the structure `s` (the result type named).
fn draw<T: Real, P: Fields<T>>(
    s: &Structure,
    title: &str,
    poses: &[Pose<P>],
    traced: &[&str],
    caption: impl Fn(f64) -> String,
) -> Result<Sketch, PlotError> {
    let mut sketch = Sketch::new(title, s.units.length);
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
            if let Some((a, b)) = travel(&along, block_angle(s, k, first)) {
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
        sketch.frame(frame(s, &caption(*q), *p, traced));
    }
    Ok(sketch)
}

/// A frame's caption: the input's name and value, an angle (rad in the pose)
/// in degrees (`theta = 30 deg`), a length in `unit` (`s = 0.12 mm`).
fn caption(name: &str, q: f64, angle: bool, unit: &str) -> String {
    if angle {
        format!("{name} = {} deg", short(q.to_degrees()))
    } else if unit.is_empty() {
        format!("{name} = {}", short(q))
    } else {
        format!("{name} = {} {unit}", short(q))
    }
}

/// A number with at most four decimals, trailing zeros dropped (`60`, `1.0472`).
fn short(v: f64) -> String {
    let s = format!("{v:.4}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".to_string()
    } else {
        s.to_string()
    }
}

/// The segment a guide is drawn as: the blocks' travel along `angle`, with a
/// margin of a fifth of it (at least one unit of the block positions' scale).
/// `None` when the points do not lie on one line along `angle` (1e-9 of their
/// scale): a block that does not travel along its guide gets no ground line
/// drawn where the guide is not.
fn travel(points: &[Xy], angle: f64) -> Option<(Xy, Xy)> {
    let first = *points.first()?;
    let (c, s) = (angle.cos(), angle.sin());
    let t = |p: &Xy| (p[0] - first[0]) * c + (p[1] - first[1]) * s;
    let lo = points.iter().map(t).fold(f64::INFINITY, f64::min);
    let hi = points.iter().map(t).fold(f64::NEG_INFINITY, f64::max);
    let scale = first[0].abs().max(first[1].abs()).max(hi - lo);
    let off = |p: &Xy| ((p[1] - first[1]) * c - (p[0] - first[0]) * s).abs();
    if points.iter().map(off).fold(0.0, f64::max) > 1e-9 * scale {
        return None;
    }
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
/// each point as two columns (`B.x`, `B.y`) and each scalar as one, the
/// definition's units in the headers (`B.x [mm]`, `link3 [rad]`, `B.x [L]`
/// for a definition without a `units` statement). A pose that fails is a row with empty fields, so the gap
/// shows in a spreadsheet. Values with 17 significant digits (round-trip).
pub fn csv<T: Real, P: Fields<T>>(input: &str, input_unit: &str, poses: &[Pose<P>]) -> String {
    let mut out = format!("{input} [{input_unit}]");
    for f in P::FIELDS {
        let unit = display_unit(f.quantity, &P::UNITS, false);
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
            let cells = match p.as_ref().and_then(|p| value(p, f.name)) {
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

/// The unit of `q` in the definition's `units` (`mm/s^2`; `L/s^2` without a
/// `units` statement), angles in degrees (`deg`) when `degrees` (the charts
/// show them so; rates stay in rad per time unit).
fn display_unit(q: Quantity, units: &Units, degrees: bool) -> String {
    if degrees && q == Quantity::Angle {
        return "deg".to_string();
    }
    units.parts(q).concat()
}

/// A panel's title and its y axis' quantity, for fields of quantity `q`.
fn quantity_words(q: Quantity) -> (&'static str, &'static str) {
    match q {
        Quantity::Length => ("Positions", "position"),
        Quantity::Angle => ("Angles", "angle"),
        Quantity::Velocity => ("Velocities", "velocity"),
        Quantity::AngularVelocity => ("Angular velocities", "angular velocity"),
        Quantity::Acceleration => ("Accelerations", "acceleration"),
        Quantity::AngularAcceleration => ("Angular accelerations", "angular acceleration"),
        Quantity::Force => ("Forces", "force"),
        Quantity::Moment => ("Moments", "moment"),
        Quantity::Ratio => ("Ratios", "ratio"),
    }
}

/// The columns one field makes over the rows: one for a scalar, `.x` and
/// `.y` for a point or a vector; `None` where the row failed or the value is
/// not finite. Angles in degrees, unwrapped: each value moved by whole turns
/// to within half a turn of the previous value (across gaps too), the whole
/// series by whole turns so that it starts in [0, 360).
fn columns<T: Real, P: Fields<T>>(
    f: &Field,
    rows: &[Pose<P>],
    magnitude: bool,
) -> Vec<(String, Vec<Option<f64>>)> {
    let finite = |v: f64| v.is_finite().then_some(v);
    if magnitude && f.planar {
        let norm = |pos: &Option<P>| match value(pos.as_ref()?, f.name)? {
            Value::Point(p) => finite(p.coords.norm()),
            Value::Vector(v) => finite(v.norm()),
            Value::Scalar(x) => finite(x.abs()),
        };
        let ys = rows.iter().map(|(_, p)| norm(p)).collect();
        return vec![(format!("|{}|", f.name), ys)];
    }
    let read = |pos: &Option<P>, k: usize| -> Option<f64> {
        match value(pos.as_ref()?, f.name)? {
            Value::Point(p) => finite([p.x, p.y][k]),
            Value::Vector(v) => finite([v.x, v.y][k]),
            Value::Scalar(x) => finite(x),
        }
    };
    let parts: &[(usize, &str)] = if f.planar {
        &[(0, ".x"), (1, ".y")]
    } else {
        &[(0, "")]
    };
    parts
        .iter()
        .map(|&(k, suffix)| {
            let mut ys: Vec<Option<f64>> = rows.iter().map(|(_, p)| read(p, k)).collect();
            if f.quantity == Quantity::Angle {
                unwrap_degrees(&mut ys);
            }
            (format!("{}{suffix}", f.name), ys)
        })
        .collect()
}

/// Radians to continuous degrees (see [`columns`]).
fn unwrap_degrees(ys: &mut [Option<f64>]) {
    let mut prev: Option<f64> = None;
    for y in ys.iter_mut().flatten() {
        let d = y.to_degrees();
        *y = match prev {
            Some(p) => d + 360.0 * ((p - d) / 360.0).round(),
            None => d,
        };
        prev = Some(*y);
    }
    if let Some(first) = ys.iter().flatten().next() {
        let shift = 360.0 * (first / 360.0).floor();
        for y in ys.iter_mut().flatten() {
            *y -= shift;
        }
    }
}

/// One panel titled `title` with every column of `fields` (all of one
/// quantity) against the rows' input.
fn panel<T: Real, P: Fields<T>>(
    title: &str,
    input: (&str, &str),
    rows: &[Pose<P>],
    fields: &[&Field],
    magnitude: bool,
) -> Plot {
    let xs: Vec<f64> = rows.iter().map(|(x, _)| *x).collect();
    let q = fields.first().map_or(Quantity::Ratio, |f| f.quantity);
    let mut plot = Plot::new(title)
        .x_axis(input.0, input.1)
        .y_axis(quantity_words(q).1, &display_unit(q, &P::UNITS, true));
    for f in fields {
        for (name, ys) in columns(f, rows, magnitude) {
            plot = plot.gapped(&name, &xs, &ys);
        }
    }
    plot
}

/// The fields of `P` named in `names`, in that order (every field but the
/// pure ratios when `names` is empty).
fn chosen<T: Real, P: Fields<T>>(names: &[&str]) -> Result<Vec<&'static Field>, PlotError> {
    if names.is_empty() {
        return Ok(P::FIELDS
            .iter()
            .filter(|f| f.quantity != Quantity::Ratio)
            .collect());
    }
    names
        .iter()
        .map(|n| {
            P::FIELDS
                .iter()
                .find(|f| f.name == *n)
                .ok_or_else(|| PlotError::NoField {
                    name: n.to_string(),
                    known: P::FIELDS.iter().map(|f| f.name).collect(),
                })
        })
        .collect()
}

/// Panels of the outputs `fields` of `P` (a position, velocity, acceleration
/// or forces struct; every field but ratios when `fields` is empty) against
/// the input: one panel per quantity, in the order the quantities first
/// appear, one series per scalar and two (`.x`, `.y`) per point or vector.
/// `input` is the x axis' label and unit as the rows hold it (`("crank angle
/// θ2", "deg")`); lengths, forces and rates are labelled in the definition's
/// units (its `units` statement; `L` and `F` without one), angles are
/// shown in degrees (continuous), angular rates in rad per time unit. A row whose result is
/// `None` (the mechanism cannot be assembled there) is a gap in every series,
/// not a line across it. An unknown field name is [`PlotError::NoField`].
pub fn panels<T: Real, P: Fields<T>>(
    input: (&str, &str),
    rows: &[Pose<P>],
    fields: &[&str],
) -> Result<Vec<Plot>, PlotError> {
    let fields = chosen::<T, P>(fields)?;
    let mut groups: Vec<(Quantity, Vec<&Field>)> = Vec::new();
    for f in fields {
        match groups.iter_mut().find(|(q, _)| *q == f.quantity) {
            Some((_, g)) => g.push(f),
            None => groups.push((f.quantity, vec![f])),
        }
    }
    Ok(groups
        .iter()
        .map(|(q, g)| panel(quantity_words(*q).0, input, rows, g, false))
        .collect())
}

/// A figure titled `title` of [`panels`]: the chart of any outputs against
/// the input in one call.
///
/// ```ignore
/// let rows: Vec<(f64, Option<FourBarPosition<f64>>)> = degrees
///     .iter()
///     .map(|&d| (d, fb.position(&FourBarInput { theta2: d.to_radians() }).ok()))
///     .collect();
/// chart("Four-bar", ("θ2", "deg"), &rows, &["link3", "B"])?.write("angles.svg")?;
/// ```
pub fn chart<T: Real, P: Fields<T>>(
    title: &str,
    input: (&str, &str),
    rows: &[Pose<P>],
    fields: &[&str],
) -> Result<Figure, PlotError> {
    Ok(panels(input, rows, fields)?
        .into_iter()
        .fold(Figure::new(title), Figure::panel))
}

/// A figure titled `title` of the forces against the input, from the forces
/// struct's fields alone: the driving efforts (`drive_*`: a torque for a
/// crank, a force for a slider or a cylinder), then the magnitude of every
/// joint reaction (`|r_ground_link2|`, the bearing load; a prismatic pair's
/// force too), then the prismatic pairs' couples, one panel per quantity in
/// each group; the power balance residual is left out. Signs follow the
/// forces struct (moments counter-clockwise positive). Failed rows are gaps.
pub fn force_chart<T: Real, F: Fields<T>>(
    title: &str,
    input: (&str, &str),
    rows: &[Pose<F>],
) -> Result<Figure, PlotError> {
    let drive = |f: &&Field| f.name.starts_with("drive_");
    let mut fig = Figure::new(title);
    let groups: [(&str, Vec<&Field>); 3] = [
        ("Driving effort", F::FIELDS.iter().filter(drive).collect()),
        (
            "Joint reactions",
            F::FIELDS
                .iter()
                .filter(|f| !drive(f) && f.quantity == Quantity::Force)
                .collect(),
        ),
        (
            "Couples of the prismatic pairs",
            F::FIELDS
                .iter()
                .filter(|f| !drive(f) && f.quantity == Quantity::Moment)
                .collect(),
        ),
    ];
    for (title, fields) in &groups {
        for q in [Quantity::Moment, Quantity::Force] {
            let these: Vec<&Field> = fields.iter().copied().filter(|f| f.quantity == q).collect();
            if !these.is_empty() {
                fig = fig.panel(panel(title, input, rows, &these, true));
            }
        }
    }
    Ok(fig)
}

/// Splits rows of `(position, velocity, acceleration)` into one row list per
/// result struct.
type Split<P, V, A> = (Vec<Pose<P>>, Vec<Pose<V>>, Vec<Pose<A>>);

fn split<P: Clone, V: Clone, A: Clone>(rows: &[Pose<(P, V, A)>]) -> Split<P, V, A> {
    let mut out: Split<P, V, A> = (Vec::new(), Vec::new(), Vec::new());
    for (x, r) in rows {
        out.0.push((*x, r.as_ref().map(|r| r.0.clone())));
        out.1.push((*x, r.as_ref().map(|r| r.1.clone())));
        out.2.push((*x, r.as_ref().map(|r| r.2.clone())));
    }
    out
}

/// A figure titled `title` of the outputs `fields` at the three levels: their
/// positions, then their velocities, then their accelerations against the
/// input, the panels of [`panels`] for each (`fields` names the outputs, the
/// same names in the three structs; all of them when empty). The rows hold
/// the three results of one input (`None` where it fails: a gap).
pub fn kinematics_chart<T, P, V, A>(
    title: &str,
    input: (&str, &str),
    rows: &[Pose<(P, V, A)>],
    fields: &[&str],
) -> Result<Figure, PlotError>
where
    T: Real,
    P: Fields<T> + Clone,
    V: Fields<T> + Clone,
    A: Fields<T> + Clone,
{
    let (p, v, a) = split(rows);
    let all = [
        panels(input, &p, fields)?,
        panels(input, &v, fields)?,
        panels(input, &a, fields)?,
    ];
    Ok(all
        .into_iter()
        .flatten()
        .fold(Figure::new(title), Figure::panel))
}
