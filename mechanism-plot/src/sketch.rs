//! Drawings of a mechanism: [`Sketch`] (the fixed parts and the poses) and [`Frame`]
//! (one pose).
//!
//! Coordinates are world coordinates (the mechanism's length unit, y up, angles in rad
//! counter-clockwise from +x); the sketch maps them to pixels with one uniform scale
//! computed from every frame, so a drawing and the animation share the same view and a
//! link keeps its length on screen. Symbols (joints, sliders, supports, hatching) have a
//! fixed size in pixels, so they read the same at any scale.

use crate::labels::{self, Obstacles, Placed};
use crate::svg::{self, num, text, text_width, PALETTE};
use crate::{write_file, PlotError, Xy};
use std::fmt::Write;
use std::path::Path;

/// Largest drawing area (px) the mechanism is scaled into.
const MAX_W: f64 = 760.0;
const MAX_H: f64 = 520.0;
/// Free space round the mechanism for symbols and labels (px).
const MARGIN: f64 = 56.0;
/// Title band above and scale-bar band below the drawing (px).
const HEAD: f64 = 34.0;
const FOOT: f64 = 34.0;
/// Slider block size (px): along the guide, across it.
const BLOCK: (f64, f64) = (36.0, 18.0);
/// Colours of coupler-point paths (distinct from the link palette's first entries).
const PATH_COLORS: [&str; 4] = ["#C0392B", "#8E44AD", "#16A085", "#2C3E50"];

#[derive(Clone, Debug)]
pub(crate) enum Shape {
    Link { name: String, points: Vec<Xy> },
    Joint { name: String, p: Xy },
    Slider { name: String, p: Xy, angle: f64 },
    Guide { a: Xy, b: Xy },
    Point { name: String, p: Xy },
}

/// One pose of the mechanism: its moving links, joints, sliders, carried guides and
/// tracer points, in world coordinates.
#[derive(Clone, Debug, Default)]
pub struct Frame {
    caption: String,
    pub(crate) shapes: Vec<Shape>,
}

impl Frame {
    /// An empty pose; `caption` (may be empty) is shown bottom right, e.g. `θ2 = 30°`.
    pub fn new(caption: &str) -> Self {
        Frame {
            caption: caption.to_string(),
            shapes: Vec::new(),
        }
    }

    /// A link through its joints: two points draw a bar, three or more a filled polygon
    /// (a ternary link, a plate). The link's colour follows its name, the same in every
    /// frame.
    pub fn link(mut self, name: &str, points: &[Xy]) -> Self {
        self.shapes.push(Shape::Link {
            name: name.to_string(),
            points: points.to_vec(),
        });
        self
    }

    /// A revolute joint at `p`, labelled `name` (empty: no label).
    pub fn joint(mut self, name: &str, p: Xy) -> Self {
        self.shapes.push(Shape::Joint {
            name: name.to_string(),
            p,
        });
        self
    }

    /// A slider block centred at `p` (its pin), aligned with a guide at `angle` (rad,
    /// counter-clockwise from +x); `name` is the block's link, which sets its colour.
    pub fn slider(mut self, name: &str, p: Xy, angle: f64) -> Self {
        self.shapes.push(Shape::Slider {
            name: name.to_string(),
            p,
            angle,
        });
        self
    }

    /// A guide carried by a moving link (a slot or a rod a block slides on), from `a` to
    /// `b`.
    pub fn guide(mut self, a: Xy, b: Xy) -> Self {
        self.shapes.push(Shape::Guide { a, b });
        self
    }

    /// A tracer point (a coupler point) at `p`, labelled `name`.
    pub fn point(mut self, name: &str, p: Xy) -> Self {
        self.shapes.push(Shape::Point {
            name: name.to_string(),
            p,
        });
        self
    }

    /// The number of revolute joints in this frame.
    pub fn joint_count(&self) -> usize {
        self.shapes
            .iter()
            .filter(|s| matches!(s, Shape::Joint { .. }))
            .count()
    }

    fn coords(&self) -> Vec<Xy> {
        let mut v = Vec::new();
        for s in &self.shapes {
            match s {
                Shape::Link { points, .. } => v.extend_from_slice(points),
                Shape::Joint { p, .. } | Shape::Point { p, .. } => v.push(*p),
                Shape::Slider { p, angle, .. } => {
                    v.push(*p);
                    v.push([*angle, 0.0]);
                }
                Shape::Guide { a, b } => {
                    v.push(*a);
                    v.push(*b);
                }
            }
        }
        v
    }
}

/// A mechanism drawing: the fixed parts (ground pivots, ground guides), the paths of
/// tracer points, and one [`Frame`] per pose.
#[derive(Clone, Debug, Default)]
pub struct Sketch {
    title: String,
    pub(crate) unit: String,
    pub(crate) pivots: Vec<(String, Xy)>,
    ground_guides: Vec<(Xy, Xy)>,
    paths: Vec<(String, Vec<Xy>)>,
    faint: Vec<Vec<Xy>>,
    pub(crate) frames: Vec<Frame>,
}

/// World-to-pixel mapping: uniform scale, y flipped.
struct View {
    /// The px column of `xmin`: the margin, plus half the extra width when the
    /// title is wider than the drawing (the drawing stays centred).
    left: f64,
    xmin: f64,
    ymax: f64,
    scale: f64,
    width: f64,
    height: f64,
}

impl View {
    fn px(&self, p: Xy) -> [f64; 2] {
        [
            self.left + (p[0] - self.xmin) * self.scale,
            HEAD + MARGIN + (self.ymax - p[1]) * self.scale,
        ]
    }
}

impl Sketch {
    /// An empty sketch titled `title`, lengths in `unit` (shown on the scale bar).
    pub fn new(title: &str, unit: &str) -> Self {
        Sketch {
            title: title.to_string(),
            unit: unit.to_string(),
            ..Default::default()
        }
    }

    /// A ground pivot (a fixed revolute joint) at `p`, drawn with a hatched support.
    pub fn ground_pivot(&mut self, name: &str, p: Xy) -> &mut Self {
        self.pivots.push((name.to_string(), p));
        self
    }

    /// A fixed guide from `a` to `b`, hatched on its right-hand side (looking from `a`
    /// to `b`): give the ends so that the hatching falls away from the mechanism.
    pub fn ground_guide(&mut self, a: Xy, b: Xy) -> &mut Self {
        self.ground_guides.push((a, b));
        self
    }

    /// The path of a tracer point over the input range, drawn under every frame.
    pub fn path(&mut self, name: &str, points: &[Xy]) -> &mut Self {
        self.paths.push((name.to_string(), points.to_vec()));
        self
    }

    /// A thin grey reference line (a workspace grid line, a construction line), drawn
    /// under everything else.
    pub fn faint_path(&mut self, points: &[Xy]) -> &mut Self {
        self.faint.push(points.to_vec());
        self
    }

    /// Appends a pose.
    pub fn frame(&mut self, frame: Frame) -> &mut Self {
        self.frames.push(frame);
        self
    }

    /// The number of poses.
    pub fn frame_count(&self) -> usize {
        self.frames.len()
    }

    /// The static drawing of pose `index`, with the fixed parts and the paths.
    pub fn drawing(&self, index: usize) -> Result<String, PlotError> {
        let frame = self.frames.get(index).ok_or(PlotError::NoFrame {
            index,
            frames: self.frames.len(),
        })?;
        let view = self.view()?;
        let pivots = self.pivot_labels(&view, frame);
        let mut out = self.open(&view);
        self.render_frame(&mut out, &view, frame, None, &pivots);
        self.close(&mut out, &view, &pivots);
        Ok(out)
    }

    /// An animated SVG of every pose in turn, `seconds` per cycle, repeating. Each pose is
    /// a group whose visibility a discrete SMIL `<animate>` switches on for its share of
    /// the cycle; viewers without SMIL show the first pose.
    pub fn animation(&self, seconds: f64) -> Result<String, PlotError> {
        if self.frames.is_empty() {
            return Err(PlotError::NoFrame {
                index: 0,
                frames: 0,
            });
        }
        let seconds = if seconds.is_finite() && seconds > 0.0 {
            seconds
        } else {
            4.0
        };
        let view = self.view()?;
        // The ground pivots' labels stay put: placed against the first pose.
        let pivots = self.pivot_labels(&view, &self.frames[0]);
        let mut out = self.open(&view);
        let n = self.frames.len();
        for (k, f) in self.frames.iter().enumerate() {
            self.render_frame(&mut out, &view, f, Some((k, n, seconds)), &pivots);
        }
        self.close(&mut out, &view, &pivots);
        Ok(out)
    }

    /// Writes [`Sketch::drawing`] of pose `index` to `path`.
    pub fn write_drawing(&self, index: usize, path: impl AsRef<Path>) -> Result<(), PlotError> {
        write_file(path.as_ref(), &self.drawing(index)?)
    }

    /// Writes [`Sketch::animation`] to `path`.
    pub fn write_animation(&self, seconds: f64, path: impl AsRef<Path>) -> Result<(), PlotError> {
        write_file(path.as_ref(), &self.animation(seconds)?)
    }

    /// Checks every coordinate and fits the bounding box of everything into the page.
    fn view(&self) -> Result<View, PlotError> {
        let mut all: Vec<Xy> = Vec::new();
        let check = |what: String, pts: &[Xy], all: &mut Vec<Xy>, bbox: bool| {
            for (i, p) in pts.iter().enumerate() {
                if !(p[0].is_finite() && p[1].is_finite()) {
                    return Err(PlotError::NonFinite { what, index: i });
                }
                if bbox {
                    all.push(*p);
                }
            }
            Ok(())
        };
        for (name, p) in &self.pivots {
            check(format!("ground pivot `{name}`"), &[*p], &mut all, true)?;
        }
        for (k, (a, b)) in self.ground_guides.iter().enumerate() {
            check(format!("ground guide {k}"), &[*a, *b], &mut all, true)?;
        }
        for (name, pts) in &self.paths {
            check(format!("path `{name}`"), pts, &mut all, true)?;
        }
        for (k, pts) in self.faint.iter().enumerate() {
            check(format!("faint path {k}"), pts, &mut all, true)?;
        }
        for (k, f) in self.frames.iter().enumerate() {
            check(format!("frame {k}"), &f.coords(), &mut Vec::new(), false)?;
            for s in &f.shapes {
                match s {
                    Shape::Link { points, .. } => all.extend_from_slice(points),
                    Shape::Joint { p, .. } | Shape::Point { p, .. } | Shape::Slider { p, .. } => {
                        all.push(*p)
                    }
                    Shape::Guide { a, b } => {
                        all.push(*a);
                        all.push(*b);
                    }
                }
            }
        }
        if all.is_empty() {
            return Err(PlotError::NothingToDraw);
        }
        let (mut xmin, mut xmax, mut ymin, mut ymax) = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for p in &all {
            xmin = xmin.min(p[0]);
            xmax = xmax.max(p[0]);
            ymin = ymin.min(p[1]);
            ymax = ymax.max(p[1]);
        }
        // A single point (or a line) still gets a square view.
        let extent = (xmax - xmin).max(ymax - ymin);
        let extent = if extent > 0.0 {
            extent
        } else {
            xmin.abs().max(ymin.abs()).max(1.0)
        };
        if xmax - xmin < 1e-3 * extent {
            xmin -= extent / 2.0;
            xmax += extent / 2.0;
        }
        if ymax - ymin < 1e-3 * extent {
            ymin -= extent / 2.0;
            ymax += extent / 2.0;
        }
        let scale = (MAX_W / (xmax - xmin)).min(MAX_H / (ymax - ymin));
        let drawing = 2.0 * MARGIN + (xmax - xmin) * scale;
        // The bold title (about 10 % wider than regular text) with 14 px each side.
        let title = 28.0 + 1.1 * text_width(&self.title, 15.0);
        let width = drawing.max(title);
        Ok(View {
            left: MARGIN + (width - drawing) / 2.0,
            xmin,
            ymax,
            scale,
            width,
            height: HEAD + FOOT + 2.0 * MARGIN + (ymax - ymin) * scale,
        })
    }

    /// The document head, title, and everything fixed that lies under the moving parts.
    fn open(&self, view: &View) -> String {
        let mut out = String::new();
        svg::open_svg(&mut out, view.width, view.height);
        text(
            &mut out,
            14.0,
            24.0,
            15.0,
            "start",
            r#" font-weight="bold""#,
            &self.title,
        );
        for pts in &self.faint {
            let px: Vec<[f64; 2]> = pts.iter().map(|p| view.px(*p)).collect();
            let _ = writeln!(
                out,
                r##"<path class="faint" d="{}" fill="none" stroke="#bbb" stroke-width="1"/>"##,
                svg::path_data(&px)
            );
        }
        // Ground guides: the line, hatching on its right.
        for (a, b) in &self.ground_guides {
            let (pa, pb) = (view.px(*a), view.px(*b));
            let _ = writeln!(out, r##"<g class="ground-guide" stroke="#222">"##);
            let _ = writeln!(
                out,
                r#"<line x1="{}" y1="{}" x2="{}" y2="{}" stroke-width="2"/>"#,
                num(pa[0]),
                num(pa[1]),
                num(pb[0]),
                num(pb[1])
            );
            let len = ((pb[0] - pa[0]).powi(2) + (pb[1] - pa[1]).powi(2)).sqrt();
            if len > 0.0 {
                let d = [(pb[0] - pa[0]) / len, (pb[1] - pa[1]) / len];
                // Right of a->b in world (y up) is left of it on screen (y down): the
                // screen normal is d rotated by -90 deg, (d.y, -d.x).
                let n = [d[1], -d[0]];
                let mut out_h = String::new();
                let mut t = 4.0;
                while t < len {
                    let p = [pa[0] + d[0] * t, pa[1] + d[1] * t];
                    let q = [
                        p[0] + 9.0 * n[0] - 6.0 * d[0],
                        p[1] + 9.0 * n[1] - 6.0 * d[1],
                    ];
                    let _ = write!(
                        out_h,
                        "M{} {} L{} {} ",
                        num(p[0]),
                        num(p[1]),
                        num(q[0]),
                        num(q[1])
                    );
                    t += 8.0;
                }
                let _ = writeln!(
                    out,
                    r#"<path class="hatch" stroke-width="1" d="{}"/>"#,
                    out_h.trim_end()
                );
            }
            let _ = writeln!(out, "</g>");
        }
        // Paths of tracer points.
        for (k, (name, pts)) in self.paths.iter().enumerate() {
            let px: Vec<[f64; 2]> = pts.iter().map(|p| view.px(*p)).collect();
            let _ = writeln!(
                out,
                r#"<path class="path" data-name="{}" d="{}" fill="none" stroke="{}" stroke-width="1.5" stroke-dasharray="5 3"/>"#,
                svg::esc(name),
                svg::path_data(&px),
                PATH_COLORS[k % PATH_COLORS.len()]
            );
        }
        // Supports of ground pivots: a triangle standing on hatched ground.
        for (_, p) in &self.pivots {
            let [x, y] = view.px(*p);
            let _ = writeln!(
                out,
                r##"<g class="ground-pivot" stroke="#222" stroke-width="1.5">"##
            );
            let _ = writeln!(
                out,
                r##"<path d="M{} {} L{} {} L{} {} Z" fill="#e8e8e8"/>"##,
                num(x),
                num(y),
                num(x - 11.0),
                num(y + 19.0),
                num(x + 11.0),
                num(y + 19.0)
            );
            let mut h = format!(
                "M{} {} L{} {}",
                num(x - 18.0),
                num(y + 19.0),
                num(x + 18.0),
                num(y + 19.0)
            );
            for i in 0..6 {
                let hx = x - 15.0 + 7.0 * i as f64;
                let _ = write!(
                    h,
                    " M{} {} L{} {}",
                    num(hx),
                    num(y + 19.0),
                    num(hx - 6.0),
                    num(y + 26.0)
                );
            }
            let _ = writeln!(out, r#"<path class="hatch" d="{h}" fill="none"/>"#);
            let _ = writeln!(out, "</g>");
        }
        out
    }

    /// What labels should not cover in pose `f` (px): joints, points and blocks
    /// as discs, links and guides as thick segments, ground supports as boxes,
    /// the canvas between the title band and the foot band.
    fn obstacles(&self, view: &View, f: &Frame) -> Obstacles {
        let mut o = Obstacles {
            canvas: [2.0, HEAD, view.width - 2.0, view.height - FOOT],
            ..Default::default()
        };
        for (_, p) in &self.pivots {
            let [x, y] = view.px(*p);
            o.discs.push(([x, y], 7.5));
            o.boxes.push([x - 18.0, y, x + 18.0, y + 27.0]);
        }
        for (a, b) in &self.ground_guides {
            o.segments.push((view.px(*a), view.px(*b), 6.0));
        }
        for s in &f.shapes {
            match s {
                Shape::Link { points, .. } => {
                    let px: Vec<[f64; 2]> = points.iter().map(|p| view.px(*p)).collect();
                    let closed = if px.len() >= 3 {
                        px.len()
                    } else {
                        px.len().saturating_sub(1)
                    };
                    for k in 0..closed {
                        o.segments.push((px[k], px[(k + 1) % px.len()], 5.5));
                    }
                }
                Shape::Joint { p, .. } => o.discs.push((view.px(*p), 7.5)),
                Shape::Point { p, .. } => o.discs.push((view.px(*p), 6.5)),
                // Half the block's diagonal: it may turn any way.
                Shape::Slider { p, .. } => o.discs.push((view.px(*p), 20.5)),
                Shape::Guide { a, b } => o.segments.push((view.px(*a), view.px(*b), 2.5)),
            }
        }
        o
    }

    /// The ground pivots' labels, placed against pose `f`.
    fn pivot_labels(&self, view: &View, f: &Frame) -> Vec<Placed> {
        let mut o = self.obstacles(view, f);
        self.pivots
            .iter()
            .map(|(name, p)| {
                let [x, y] = view.px(*p);
                o.place(name, x, y)
            })
            .collect()
    }

    /// Ground pivots' joints and labels (over the links), scale bar, end of document.
    fn close(&self, out: &mut String, view: &View, labels: &[Placed]) {
        for ((name, p), at) in self.pivots.iter().zip(labels) {
            let [x, y] = view.px(*p);
            joint(out, x, y, "ground-joint", name);
            label(out, at, name);
        }
        // Scale bar: the largest 1-2-5 length up to a quarter of the drawing's width.
        let world_w = (view.width - 2.0 * MARGIN) / view.scale;
        let len = nice_floor(world_w / 4.0);
        let (x0, y0) = (14.0, view.height - 14.0);
        let x1 = x0 + len * view.scale;
        let _ = writeln!(
            out,
            r##"<path class="scale-bar" d="M{0} {1} L{0} {2} L{3} {2} L{3} {1}" fill="none" stroke="#222" stroke-width="1.5"/>"##,
            num(x0),
            num(y0 - 6.0),
            num(y0),
            num(x1)
        );
        let decimals = (-len.log10()).ceil().max(0.0) as usize;
        text(
            out,
            x1 + 8.0,
            y0,
            12.0,
            "start",
            r#" class="scale-label""#,
            &format!("{len:.decimals$} {}", self.unit),
        );
        out.push_str("</svg>\n");
    }

    /// Colour of a link or block, by first appearance of its name over all frames.
    fn color(&self, name: &str) -> &'static str {
        let mut names: Vec<&str> = Vec::new();
        for f in &self.frames {
            for s in &f.shapes {
                if let Shape::Link { name: n, .. } | Shape::Slider { name: n, .. } = s {
                    if !names.contains(&n.as_str()) {
                        names.push(n);
                    }
                }
            }
        }
        let k = names.iter().position(|n| *n == name).unwrap_or(0);
        PALETTE[k % PALETTE.len()]
    }

    /// One pose; with `anim = Some((k, n, seconds))` a group visible during the k-th of
    /// n equal slices of the cycle.
    fn render_frame(
        &self,
        out: &mut String,
        view: &View,
        f: &Frame,
        anim: Option<(usize, usize, f64)>,
        pivots: &[Placed],
    ) {
        match anim {
            Some((k, n, seconds)) => {
                let vis = if k == 0 { "visible" } else { "hidden" };
                let _ = writeln!(out, r#"<g class="frame" visibility="{vis}">"#);
                // Discrete animation: the value at key time t_i holds until t_{i+1}.
                let (values, times) = if n == 1 {
                    ("visible".to_string(), "0".to_string())
                } else if k == 0 {
                    ("visible;hidden".to_string(), format!("0;{}", key(1, n)))
                } else if k + 1 == n {
                    ("hidden;visible".to_string(), format!("0;{}", key(k, n)))
                } else {
                    (
                        "hidden;visible;hidden".to_string(),
                        format!("0;{};{}", key(k, n), key(k + 1, n)),
                    )
                };
                let _ = writeln!(
                    out,
                    r#"<animate attributeName="visibility" calcMode="discrete" values="{values}" keyTimes="{times}" dur="{}s" repeatCount="indefinite"/>"#,
                    num(seconds)
                );
            }
            None => {
                let _ = writeln!(out, r#"<g class="frame">"#);
            }
        }
        // Carried guides under everything that moves on them.
        for s in &f.shapes {
            if let Shape::Guide { a, b } = s {
                let (pa, pb) = (view.px(*a), view.px(*b));
                let _ = writeln!(
                    out,
                    r##"<line class="guide" x1="{}" y1="{}" x2="{}" y2="{}" stroke="#555" stroke-width="3" stroke-linecap="round"/>"##,
                    num(pa[0]),
                    num(pa[1]),
                    num(pb[0]),
                    num(pb[1])
                );
            }
        }
        // Plates first, bars over them.
        for s in &f.shapes {
            if let Shape::Link { name, points } = s {
                if points.len() >= 3 {
                    let px: Vec<[f64; 2]> = points.iter().map(|p| view.px(*p)).collect();
                    let c = self.color(name);
                    let _ = writeln!(
                        out,
                        r#"<path class="link" data-name="{}" d="{} Z" fill="{c}" fill-opacity="0.3" stroke="{c}" stroke-width="6" stroke-linejoin="round"/>"#,
                        svg::esc(name),
                        svg::path_data(&px)
                    );
                }
            }
        }
        for s in &f.shapes {
            if let Shape::Link { name, points } = s {
                if points.len() < 3 {
                    let px: Vec<[f64; 2]> = points.iter().map(|p| view.px(*p)).collect();
                    let _ = writeln!(
                        out,
                        r#"<path class="link" data-name="{}" d="{}" fill="none" stroke="{}" stroke-width="9" stroke-linecap="round" stroke-opacity="0.9"/>"#,
                        svg::esc(name),
                        svg::path_data(&px),
                        self.color(name)
                    );
                }
            }
        }
        for s in &f.shapes {
            if let Shape::Slider { name, p, angle } = s {
                let [x, y] = view.px(*p);
                // Screen y points down: a world angle a is -a on screen.
                let _ = writeln!(
                    out,
                    r##"<rect class="slider" data-name="{}" x="{}" y="{}" width="{}" height="{}" rx="2" fill="{}" fill-opacity="0.85" stroke="#222" stroke-width="1.5" transform="rotate({} {} {})"/>"##,
                    svg::esc(name),
                    num(x - BLOCK.0 / 2.0),
                    num(y - BLOCK.1 / 2.0),
                    num(BLOCK.0),
                    num(BLOCK.1),
                    self.color(name),
                    num(-angle.to_degrees()),
                    num(x),
                    num(y)
                );
            }
        }
        for s in &f.shapes {
            match s {
                Shape::Joint { p, name } => {
                    let [x, y] = view.px(*p);
                    joint(out, x, y, "joint", name);
                }
                Shape::Point { p, .. } => {
                    let [x, y] = view.px(*p);
                    let _ = writeln!(
                        out,
                        r##"<circle class="point" cx="{}" cy="{}" r="4.5" fill="{}" stroke="#222" stroke-width="1"/>"##,
                        num(x),
                        num(y),
                        PATH_COLORS[0]
                    );
                }
                _ => {}
            }
        }
        let mut obstacles = self.obstacles(view, f);
        obstacles.boxes.extend(pivots.iter().map(|p| p.rect));
        for s in &f.shapes {
            if let Shape::Joint { name, p } | Shape::Point { name, p } = s {
                if !name.is_empty() {
                    let [x, y] = view.px(*p);
                    label(out, &obstacles.place(name, x, y), name);
                }
            }
        }
        // In the foot band, right: clear of the title and of the scale bar (left).
        if !f.caption.is_empty() {
            text(
                out,
                view.width - 14.0,
                view.height - 14.0,
                13.0,
                "end",
                r#" class="caption""#,
                &f.caption,
            );
        }
        let _ = writeln!(out, "</g>");
    }
}

/// Key time `k / n` with enough digits that neighbouring slices never coincide.
fn key(k: usize, n: usize) -> String {
    format!("{:.6}", k as f64 / n as f64)
}

/// A revolute joint: a white disc with a dark ring, its name in `data-name`.
fn joint(out: &mut String, x: f64, y: f64, class: &str, name: &str) {
    let _ = writeln!(
        out,
        r##"<circle class="{class}" data-name="{}" cx="{}" cy="{}" r="5.5" fill="white" stroke="#222" stroke-width="2"/>"##,
        svg::esc(name),
        num(x),
        num(y)
    );
}

/// A joint's name where [`Obstacles::place`] put it, on a white halo so that it
/// reads over links.
fn label(out: &mut String, at: &Placed, name: &str) {
    if name.is_empty() {
        return;
    }
    text(
        out,
        at.x,
        at.y,
        labels::SIZE,
        at.anchor,
        r##" class="label" fill="#111" stroke="white" stroke-width="3" paint-order="stroke" stroke-linejoin="round""##,
        name,
    );
}

/// The largest 1, 2 or 5 times a power of ten not above `v` (`v > 0`).
fn nice_floor(v: f64) -> f64 {
    let mag = 10f64.powf(v.log10().floor());
    [5.0, 2.0, 1.0]
        .into_iter()
        .map(|f| f * mag)
        .find(|&s| s <= v * (1.0 + 1e-9))
        .unwrap_or(mag)
}
