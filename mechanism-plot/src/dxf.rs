//! DXF of a drawing at one pose, for laser or water-jet cutting (feature
//! `dxf`): every moving link's outline and a hole at each of its points,
//! each slider block's outline and pin hole, and a hole at each ground pivot,
//! in the drawing's place and the definition's length unit. Written with the
//! [`dxf`](https://docs.rs/dxf) crate (ixmilia's reader and writer), so the
//! file is what CAD programs read, not text assembled here.
//!
//! A link's outline is the convex hull of its points grown by half the link
//! width, with round ends: for a bar (two joints) the usual slot shape, two
//! straight sides and a half circle about each joint; for a plate the hull's
//! sides moved out and arcs about its corners. Layers: `OUTLINE` (lines and
//! arcs) and `HOLES` (circles).

use crate::sketch::Shape;
use crate::{PlotError, Sketch, Xy};
use ::dxf::entities::{Arc, Circle, Entity, EntityType, Line};
use ::dxf::enums::{AcadVersion, Units};
use ::dxf::{Drawing, Point};
use std::path::Path;

/// The layer of the parts' outlines.
pub const OUTLINE: &str = "OUTLINE";
/// The layer of the holes (circles).
pub const HOLES: &str = "HOLES";

/// Sizes of the cut parts, in the drawing's length unit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cut {
    /// Width of a link (twice the radius of its round ends), > 0.
    pub width: f64,
    /// Diameter of a hole, > 0 and < `width` (the hole stays inside the link).
    pub hole: f64,
}

impl Sketch {
    /// The pose `index` as a DXF drawing (see the module `dxf`): link
    /// outlines, slider blocks and holes, sized by `cut`. An index without a
    /// frame is [`PlotError::NoFrame`]; a width or hole that is not finite and
    /// positive, or a hole as wide as the link, is [`PlotError::BadRange`]; a
    /// link point that is not finite is [`PlotError::NonFinite`].
    pub fn dxf(&self, index: usize, cut: Cut) -> Result<Drawing, PlotError> {
        let frame = self.frames.get(index).ok_or(PlotError::NoFrame {
            index,
            frames: self.frames.len(),
        })?;
        let ok = |v: f64| v.is_finite() && v > 0.0;
        if !(ok(cut.width) && ok(cut.hole) && cut.hole < cut.width) {
            return Err(PlotError::BadRange {
                axis: "dxf cut (width, hole)",
                lo: cut.width,
                hi: cut.hole,
            });
        }
        let mut d = Drawing::new();
        // $INSUNITS (the unit) needs R2000 or later.
        d.header.version = AcadVersion::R2000;
        d.header.default_drawing_units = units(&self.unit);
        let (r, hole) = (0.5 * cut.width, 0.5 * cut.hole);
        for (k, shape) in frame.shapes.iter().enumerate() {
            match shape {
                Shape::Link { points, .. } => {
                    finite(points, k)?;
                    outline(&mut d, &hull(points), r);
                    for p in points {
                        add(&mut d, HOLES, EntityType::Circle(Circle::new(at(*p), hole)));
                    }
                }
                Shape::Slider { p, angle, .. } => {
                    finite(&[*p, [*angle, 0.0]], k)?;
                    block(&mut d, *p, *angle, cut.width);
                    add(&mut d, HOLES, EntityType::Circle(Circle::new(at(*p), hole)));
                }
                _ => {}
            }
        }
        for (_, p) in &self.pivots {
            add(&mut d, HOLES, EntityType::Circle(Circle::new(at(*p), hole)));
        }
        Ok(d)
    }

    /// Writes [`Sketch::dxf`] of the pose `index` to `path` (ASCII DXF),
    /// creating the parent directories.
    pub fn write_dxf(
        &self,
        index: usize,
        cut: Cut,
        path: impl AsRef<Path>,
    ) -> Result<(), PlotError> {
        let d = self.dxf(index, cut)?;
        let mut text = Vec::new();
        d.save(&mut text)
            .map_err(|e| PlotError::Io(std::io::Error::other(e.to_string())))?;
        let text = String::from_utf8(text)
            .map_err(|e| PlotError::Io(std::io::Error::other(e.to_string())))?;
        crate::write_file(path.as_ref(), &text)
    }
}

/// The DXF unit of a length unit's name (`Unitless` for one DXF does not
/// know, such as the symbol `L`).
fn units(name: &str) -> Units {
    match name {
        "mm" => Units::Millimeters,
        "cm" => Units::Centimeters,
        "m" => Units::Meters,
        "in" => Units::Inches,
        "ft" => Units::Feet,
        "um" | "µm" => Units::Microns,
        _ => Units::Unitless,
    }
}

fn finite(points: &[Xy], index: usize) -> Result<(), PlotError> {
    if points.iter().flatten().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(PlotError::NonFinite {
            what: "dxf shape".to_string(),
            index,
        })
    }
}

fn at(p: Xy) -> Point {
    Point::new(p[0], p[1], 0.0)
}

fn add(d: &mut Drawing, layer: &str, specific: EntityType) {
    let mut e = Entity::new(specific);
    e.common.layer = layer.to_string();
    d.add_entity(e);
}

/// The convex hull of `points`, counter-clockwise, without repeated or
/// collinear points (Andrew's monotone chain); two points for a bar or for
/// points on one line (its ends), one for coincident points.
fn hull(points: &[Xy]) -> Vec<Xy> {
    let mut p = points.to_vec();
    p.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let cross = |o: Xy, a: Xy, b: Xy| (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    let mut h: Vec<Xy> = Vec::with_capacity(2 * p.len());
    for pass in 0..2 {
        let start = h.len();
        let it: Box<dyn Iterator<Item = &Xy>> = if pass == 0 {
            Box::new(p.iter())
        } else {
            Box::new(p.iter().rev())
        };
        for &q in it {
            while h.len() >= start + 2 && cross(h[h.len() - 2], h[h.len() - 1], q) <= 0.0 {
                h.pop();
            }
            h.push(q);
        }
        h.pop();
    }
    h
}

/// The outline of the hull `h` grown by `r`: each side moved out by `r`
/// (to its right, outside a counter-clockwise hull) and an arc of radius `r`
/// about each corner from one side's normal to the next's. One point: a
/// circle.
fn outline(d: &mut Drawing, h: &[Xy], r: f64) {
    if h.len() == 1 {
        add(d, OUTLINE, EntityType::Circle(Circle::new(at(h[0]), r)));
        return;
    }
    let n = h.len();
    let normal = |i: usize| {
        let (a, b) = (h[i], h[(i + 1) % n]);
        let len = (b[0] - a[0]).hypot(b[1] - a[1]);
        [(b[1] - a[1]) / len, -(b[0] - a[0]) / len]
    };
    for (i, &a) in h.iter().enumerate() {
        let (b, m) = (h[(i + 1) % n], normal(i));
        let shift = |p: Xy| [p[0] + r * m[0], p[1] + r * m[1]];
        add(
            d,
            OUTLINE,
            EntityType::Line(Line::new(at(shift(a)), at(shift(b)))),
        );
        let next = normal((i + 1) % n);
        let (from, to) = (m[1].atan2(m[0]), next[1].atan2(next[0]));
        let arc = Arc::new(at(b), r, from.to_degrees(), to.to_degrees());
        add(d, OUTLINE, EntityType::Arc(arc));
    }
}

/// A slider block: a rectangle twice `width` long along the guide (`angle`,
/// rad) and `width` across, centred on its pin `p`.
fn block(d: &mut Drawing, p: Xy, angle: f64, width: f64) {
    let (c, s) = (angle.cos(), angle.sin());
    let corner = |u: f64, v: f64| [p[0] + u * c - v * s, p[1] + u * s + v * c];
    let corners = [
        corner(-width, -0.5 * width),
        corner(width, -0.5 * width),
        corner(width, 0.5 * width),
        corner(-width, 0.5 * width),
    ];
    for (i, a) in corners.iter().enumerate() {
        let line = Line::new(at(*a), at(corners[(i + 1) % 4]));
        add(d, OUTLINE, EntityType::Line(line));
    }
}
