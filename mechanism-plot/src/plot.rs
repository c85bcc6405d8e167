//! Line plots: [`Plot`] (one panel) and [`Figure`] (panels stacked vertically).

use crate::svg::{self, num, text, text_width, DASHES, PALETTE};
use crate::ticks::{nice_ticks, Ticks};
use crate::{write_file, PlotError};
use std::fmt::Write;
use std::path::Path;

/// Series with at most this many points get a marker on every point (by default), so
/// that a coarse table (13 rows) does not read as a smooth curve.
const MARKER_MAX_POINTS: usize = 40;
/// Font sizes (px): tick labels and legend, axis labels, titles.
const SMALL: f64 = 12.0;
const MEDIUM: f64 = 13.0;
const LARGE: f64 = 15.0;
/// Space above the plot area for a panel title, and below it for ticks and x label (px).
const TOP_TITLE: f64 = 30.0;
const TOP_PLAIN: f64 = 12.0;
const BOTTOM: f64 = 50.0;

#[derive(Clone, Debug)]
struct Series {
    name: String,
    xs: Vec<f64>,
    ys: Vec<f64>,
    /// Indices into `xs`/`ys` where a new run starts after a gap (`0` never listed):
    /// the line breaks there instead of joining across the gap.
    breaks: Vec<usize>,
}

/// One panel: several series of y against a common x, with labelled axes and a legend.
///
/// Built by chaining; nothing is checked until [`Plot::to_svg`] or [`Plot::write`], which
/// return a typed [`PlotError`] for empty, mismatched or non-finite data.
#[derive(Clone, Debug)]
pub struct Plot {
    title: String,
    x_label: String,
    x_unit: String,
    y_label: String,
    y_unit: String,
    series: Vec<Series>,
    x_range: Option<(f64, f64)>,
    y_range: Option<(f64, f64)>,
    x_step: Option<f64>,
    y_step: Option<f64>,
    width: f64,
    height: f64,
    markers: Option<bool>,
}

impl Plot {
    /// A panel titled `title` (may be empty), 760 x 340 px.
    pub fn new(title: &str) -> Self {
        Plot {
            title: title.to_string(),
            x_label: String::new(),
            x_unit: String::new(),
            y_label: String::new(),
            y_unit: String::new(),
            series: Vec::new(),
            x_range: None,
            y_range: None,
            x_step: None,
            y_step: None,
            width: 760.0,
            height: 340.0,
            markers: None,
        }
    }

    /// The x axis' quantity and unit (`"crank angle θ2", "deg"`). A unit of `deg` (or `°`)
    /// selects ticks on 15/30/45/90 deg; `^2` in a unit prints as a superscript.
    pub fn x_axis(mut self, label: &str, unit: &str) -> Self {
        self.x_label = label.to_string();
        self.x_unit = unit.to_string();
        self
    }

    /// The y axis' quantity and unit (`"angular acceleration", "rad/s^2"`).
    pub fn y_axis(mut self, label: &str, unit: &str) -> Self {
        self.y_label = label.to_string();
        self.y_unit = unit.to_string();
        self
    }

    /// Adds a series `ys` against `xs` (same length, finite values), named in the legend.
    pub fn series(mut self, name: &str, xs: &[f64], ys: &[f64]) -> Self {
        self.series.push(Series {
            name: name.to_string(),
            xs: xs.to_vec(),
            ys: ys.to_vec(),
            breaks: Vec::new(),
        });
        self
    }

    /// Adds a series with gaps: `ys[k]` is `None` where there is no value (a pose that
    /// cannot be assembled); the line stops before a gap and starts again after it,
    /// never joining across it. `xs` and `ys` have the same length; at least one value.
    pub fn gapped(mut self, name: &str, xs: &[f64], ys: &[Option<f64>]) -> Self {
        let mut series = Series {
            name: name.to_string(),
            xs: Vec::new(),
            ys: Vec::new(),
            breaks: Vec::new(),
        };
        if xs.len() != ys.len() {
            // Kept mismatched so that `layout` reports the lengths.
            series.xs = xs.to_vec();
            series.ys = ys.iter().map(|y| y.unwrap_or(0.0)).collect();
        } else {
            let mut after_gap = false;
            for (&x, y) in xs.iter().zip(ys) {
                match y {
                    Some(y) => {
                        if after_gap && !series.xs.is_empty() {
                            series.breaks.push(series.xs.len());
                        }
                        after_gap = false;
                        series.xs.push(x);
                        series.ys.push(*y);
                    }
                    None => after_gap = true,
                }
            }
        }
        self.series.push(series);
        self
    }

    /// Adds a series from `(x, y)` pairs.
    pub fn points(mut self, name: &str, xy: impl IntoIterator<Item = (f64, f64)>) -> Self {
        let (xs, ys) = xy.into_iter().unzip();
        self.series.push(Series {
            name: name.to_string(),
            xs,
            ys,
            breaks: Vec::new(),
        });
        self
    }

    /// Fixes the x axis to `[lo, hi]` (data outside is clipped). Default: the data's range.
    pub fn x_range(mut self, lo: f64, hi: f64) -> Self {
        self.x_range = Some((lo, hi));
        self
    }

    /// Fixes the y axis to `[lo, hi]`. Default: the data's range widened to whole ticks.
    pub fn y_range(mut self, lo: f64, hi: f64) -> Self {
        self.y_range = Some((lo, hi));
        self
    }

    /// Distance between x ticks, in x units. Default: automatic.
    pub fn x_step(mut self, step: f64) -> Self {
        self.x_step = Some(step);
        self
    }

    /// Distance between y ticks, in y units. Default: automatic.
    pub fn y_step(mut self, step: f64) -> Self {
        self.y_step = Some(step);
        self
    }

    /// Panel size in px (at least 200 x 150).
    pub fn size(mut self, width: f64, height: f64) -> Self {
        self.width = if width.is_finite() {
            width.max(200.0)
        } else {
            760.0
        };
        self.height = if height.is_finite() {
            height.max(150.0)
        } else {
            340.0
        };
        self
    }

    /// Markers on every point (`true`), never (`false`). Default: when every series has at
    /// most 40 points.
    pub fn markers(mut self, on: bool) -> Self {
        self.markers = Some(on);
        self
    }

    /// The standalone SVG document of this panel.
    pub fn to_svg(&self) -> Result<String, PlotError> {
        Figure::new("").panel(self.clone()).to_svg()
    }

    /// Writes [`Plot::to_svg`] to `path`, creating its directory.
    pub fn write(&self, path: impl AsRef<Path>) -> Result<(), PlotError> {
        write_file(path.as_ref(), &self.to_svg()?)
    }

    /// Checks the data and computes both axes and the margins it needs.
    fn layout(&self) -> Result<Layout, PlotError> {
        if self.series.is_empty() {
            return Err(PlotError::NoSeries {
                plot: self.title.clone(),
            });
        }
        let (mut xlo, mut xhi, mut ylo, mut yhi) = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for s in &self.series {
            if s.xs.len() != s.ys.len() {
                return Err(PlotError::LengthMismatch {
                    series: s.name.clone(),
                    xs: s.xs.len(),
                    ys: s.ys.len(),
                });
            }
            if s.xs.is_empty() {
                return Err(PlotError::EmptySeries {
                    series: s.name.clone(),
                });
            }
            for (i, (&x, &y)) in s.xs.iter().zip(&s.ys).enumerate() {
                if !x.is_finite() || !y.is_finite() {
                    return Err(PlotError::NonFinite {
                        what: format!("series `{}`", s.name),
                        index: i,
                    });
                }
                xlo = xlo.min(x);
                xhi = xhi.max(x);
                ylo = ylo.min(y);
                yhi = yhi.max(y);
            }
        }
        let deg = |u: &str| u == "deg" || u == "°";
        let x = axis(
            "x",
            self.x_range,
            self.x_step,
            (xlo, xhi),
            deg(&self.x_unit),
            false,
        )?;
        let y = axis(
            "y",
            self.y_range,
            self.y_step,
            (ylo, yhi),
            deg(&self.y_unit),
            true,
        )?;
        let widest_tick = y
            .values
            .iter()
            .map(|&v| text_width(&y.label(v), SMALL))
            .fold(0.0, f64::max);
        let widest_name = self
            .series
            .iter()
            .map(|s| text_width(&s.name, SMALL))
            .fold(0.0, f64::max);
        Ok(Layout {
            left: 36.0 + widest_tick,
            right: 16.0 + 28.0 + widest_name + 14.0,
            x,
            y,
        })
    }

    /// Draws the panel into `out` with its top-left corner at `(0, y0)`, plot area from
    /// `left` to `width - right` (px): title, grid and frame, ticks, axis labels, series,
    /// legend, in this order.
    fn render(&self, out: &mut String, id: usize, y0: f64, lay: &Layout, left: f64, right: f64) {
        let top = y0
            + if self.title.is_empty() {
                TOP_PLAIN
            } else {
                TOP_TITLE
            };
        let area = Area::new(
            lay,
            left,
            self.width - right,
            top,
            y0 + self.height - BOTTOM,
        );
        if !self.title.is_empty() {
            text(
                out,
                (area.x0 + area.x1) / 2.0,
                y0 + 20.0,
                LARGE,
                "middle",
                r#" font-weight="bold""#,
                &self.title,
            );
        }
        area.grid(out);
        area.ticks(out);
        self.axis_labels(out, &area);
        let markers = self
            .markers
            .unwrap_or_else(|| self.series.iter().all(|s| s.xs.len() <= MARKER_MAX_POINTS));
        self.render_series(out, &area, id, markers);
        self.legend(out, &area, markers);
    }

    /// The axis titles: x centred below the tick labels, y rotated, centred left of them.
    fn axis_labels(&self, out: &mut String, area: &Area) {
        text(
            out,
            (area.x0 + area.x1) / 2.0,
            area.y1 + 40.0,
            MEDIUM,
            "middle",
            r#" class="x-label""#,
            &axis_title(&self.x_label, &self.x_unit, area.x.exponent),
        );
        let (lx, ly) = (16.0, (area.top + area.y1) / 2.0);
        text(
            out,
            lx,
            ly,
            MEDIUM,
            "middle",
            &format!(
                r#" class="y-label" transform="rotate(-90 {} {})""#,
                num(lx),
                num(ly)
            ),
            &axis_title(&self.y_label, &self.y_unit, area.y.exponent),
        );
    }

    /// Every series as a path (and markers on its points when `markers`), clipped to the
    /// plot area by a clip path whose id is made unique in the document by the panel
    /// index `id`.
    fn render_series(&self, out: &mut String, area: &Area, id: usize, markers: bool) {
        let _ = writeln!(
            out,
            r#"<clipPath id="mp-clip-{id}"><rect x="{}" y="{}" width="{}" height="{}"/></clipPath>"#,
            num(area.x0),
            num(area.top),
            num(area.pw),
            num(area.ph)
        );
        let _ = writeln!(
            out,
            r#"<g class="series" clip-path="url(#mp-clip-{id})" fill="none" stroke-width="2" stroke-linejoin="round" stroke-linecap="round">"#
        );
        for (k, s) in self.series.iter().enumerate() {
            let (color, dash) = style(k);
            let pts: Vec<[f64; 2]> =
                s.xs.iter()
                    .zip(&s.ys)
                    .map(|(&a, &b)| [area.px(a), area.py(b)])
                    .collect();
            let mut d = String::new();
            let mut start = 0;
            for end in s.breaks.iter().copied().chain([pts.len()]) {
                if !d.is_empty() {
                    d.push(' ');
                }
                d.push_str(&svg::path_data(&pts[start..end]));
                start = end;
            }
            let _ = writeln!(
                out,
                r#"<path data-series="{}" stroke="{color}"{dash} d="{d}"/>"#,
                svg::esc(&s.name),
            );
            if markers {
                let _ = writeln!(out, r#"<g fill="{color}" stroke="none">"#);
                for p in &pts {
                    let _ = writeln!(
                        out,
                        r#"<circle cx="{}" cy="{}" r="3"/>"#,
                        num(p[0]),
                        num(p[1])
                    );
                }
                let _ = writeln!(out, "</g>");
            }
        }
        let _ = writeln!(out, "</g>");
    }

    /// The legend right of the plot area: one row of 20 px per series, its line style
    /// (and marker when `markers`) and name.
    fn legend(&self, out: &mut String, area: &Area, markers: bool) {
        let _ = writeln!(out, r#"<g class="legend">"#);
        let lx = area.x1 + 16.0;
        for (k, s) in self.series.iter().enumerate() {
            let (color, dash) = style(k);
            let ly = area.top + 12.0 + 20.0 * k as f64;
            let _ = writeln!(
                out,
                r#"<line x1="{}" y1="{2}" x2="{}" y2="{2}" stroke="{color}" stroke-width="2"{dash}/>"#,
                num(lx),
                num(lx + 24.0),
                num(ly)
            );
            if markers {
                let _ = writeln!(
                    out,
                    r#"<circle cx="{}" cy="{}" r="3" fill="{color}"/>"#,
                    num(lx + 12.0),
                    num(ly)
                );
            }
            text(out, lx + 30.0, ly + 4.0, SMALL, "start", "", &s.name);
        }
        let _ = writeln!(out, "</g>");
    }
}

/// A panel's plot area in px (SVG coordinates, y down) and the axes mapped onto it.
struct Area<'a> {
    /// Left edge.
    x0: f64,
    /// Right edge.
    x1: f64,
    /// Top edge.
    top: f64,
    /// Bottom edge.
    y1: f64,
    /// Width, `x1 - x0`.
    pw: f64,
    /// Height, `y1 - top`.
    ph: f64,
    /// The x axis' ticks (x units).
    x: &'a Ticks,
    /// The y axis' ticks (y units).
    y: &'a Ticks,
}

impl<'a> Area<'a> {
    /// The area from `x0` to `x1` across and from `top` down to `y1` (px).
    fn new(lay: &'a Layout, x0: f64, x1: f64, top: f64, y1: f64) -> Self {
        Area {
            x0,
            x1,
            top,
            y1,
            pw: x1 - x0,
            ph: y1 - top,
            x: &lay.x,
            y: &lay.y,
        }
    }

    /// The px column of x value `v` (x units).
    fn px(&self, v: f64) -> f64 {
        self.x0 + (v - self.x.lo) / (self.x.hi - self.x.lo) * self.pw
    }

    /// The px row of y value `v` (y units): `y.lo` at the bottom edge.
    fn py(&self, v: f64) -> f64 {
        self.y1 - (v - self.y.lo) / (self.y.hi - self.y.lo) * self.ph
    }

    /// Grid lines at every tick, a darker line at y = 0 when the y axis spans it, and the
    /// frame.
    fn grid(&self, out: &mut String) {
        let _ = writeln!(out, r##"<g stroke="#e3e3e3" stroke-width="1">"##);
        for &v in &self.x.values {
            let _ = writeln!(
                out,
                r#"<line x1="{0}" y1="{1}" x2="{0}" y2="{2}"/>"#,
                num(self.px(v)),
                num(self.top),
                num(self.y1)
            );
        }
        for &v in &self.y.values {
            let _ = writeln!(
                out,
                r#"<line x1="{1}" y1="{0}" x2="{2}" y2="{0}"/>"#,
                num(self.py(v)),
                num(self.x0),
                num(self.x1)
            );
        }
        let _ = writeln!(out, "</g>");
        if self.y.lo < 0.0 && self.y.hi > 0.0 {
            let _ = writeln!(
                out,
                r##"<line x1="{1}" y1="{0}" x2="{2}" y2="{0}" stroke="#888" stroke-width="1"/>"##,
                num(self.py(0.0)),
                num(self.x0),
                num(self.x1)
            );
        }
        let _ = writeln!(
            out,
            r##"<rect x="{}" y="{}" width="{}" height="{}" fill="none" stroke="#333" stroke-width="1"/>"##,
            num(self.x0),
            num(self.top),
            num(self.pw),
            num(self.ph)
        );
    }

    /// Tick marks (5 px, outside the frame) and their labels, x below and y left of the
    /// plot area.
    fn ticks(&self, out: &mut String) {
        let _ = writeln!(
            out,
            r##"<g class="x-ticks" stroke="#333" stroke-width="1">"##
        );
        for &v in &self.x.values {
            let _ = writeln!(
                out,
                r#"<line x1="{0}" y1="{1}" x2="{0}" y2="{2}"/>"#,
                num(self.px(v)),
                num(self.y1),
                num(self.y1 + 5.0)
            );
        }
        let _ = writeln!(out, "</g>");
        let _ = writeln!(out, r#"<g class="x-tick-labels">"#);
        for &v in &self.x.values {
            text(
                out,
                self.px(v),
                self.y1 + 19.0,
                SMALL,
                "middle",
                "",
                &self.x.label(v),
            );
        }
        let _ = writeln!(out, "</g>");
        let _ = writeln!(
            out,
            r##"<g class="y-ticks" stroke="#333" stroke-width="1">"##
        );
        for &v in &self.y.values {
            let _ = writeln!(
                out,
                r#"<line x1="{1}" y1="{0}" x2="{2}" y2="{0}"/>"#,
                num(self.py(v)),
                num(self.x0 - 5.0),
                num(self.x0)
            );
        }
        let _ = writeln!(out, "</g>");
        let _ = writeln!(out, r#"<g class="y-tick-labels">"#);
        for &v in &self.y.values {
            text(
                out,
                self.x0 - 8.0,
                self.py(v) + 4.0,
                SMALL,
                "end",
                "",
                &self.y.label(v),
            );
        }
        let _ = writeln!(out, "</g>");
    }
}

/// Colour and dash attribute of series `k`.
fn style(k: usize) -> (&'static str, String) {
    let color = PALETTE[k % PALETTE.len()];
    let dash = DASHES[(k / PALETTE.len()) % DASHES.len()];
    let dash = if dash.is_empty() {
        String::new()
    } else {
        format!(r#" stroke-dasharray="{dash}""#)
    };
    (color, dash)
}

/// `quantity (unit)`, `quantity (10³ unit)` with an exponent, `quantity` without a unit.
fn axis_title(label: &str, unit: &str, exponent: i32) -> String {
    let unit = svg::pretty_unit(unit);
    let scale = if exponent != 0 {
        svg::pow10_text(exponent)
    } else {
        String::new()
    };
    match (scale.is_empty(), unit.is_empty()) {
        (true, true) => label.to_string(),
        (true, false) => format!("{label} ({unit})"),
        (false, true) => format!("{label} ({scale})"),
        (false, false) => format!("{label} ({scale} {unit})"),
    }
}

/// The ticks of one axis: a caller's range and step if usable, else from the data.
fn axis(
    name: &'static str,
    range: Option<(f64, f64)>,
    step: Option<f64>,
    data: (f64, f64),
    degrees: bool,
    expand: bool,
) -> Result<Ticks, PlotError> {
    if let Some(s) = step {
        if !(s.is_finite() && s > 0.0) {
            return Err(PlotError::BadRange {
                axis: name,
                lo: s,
                hi: s,
            });
        }
    }
    match range {
        Some((lo, hi)) => {
            if !(lo.is_finite() && hi.is_finite() && lo < hi) {
                return Err(PlotError::BadRange { axis: name, lo, hi });
            }
            Ok(nice_ticks(lo, hi, degrees, false, step))
        }
        None => Ok(nice_ticks(data.0, data.1, degrees, expand, step)),
    }
}

struct Layout {
    left: f64,
    right: f64,
    x: Ticks,
    y: Ticks,
}

/// Panels stacked vertically under an optional title, sharing their left and right
/// margins so that the plot areas line up.
#[derive(Clone, Debug)]
pub struct Figure {
    title: String,
    panels: Vec<Plot>,
}

impl Figure {
    /// A figure titled `title` (may be empty).
    pub fn new(title: &str) -> Self {
        Figure {
            title: title.to_string(),
            panels: Vec::new(),
        }
    }

    /// Appends a panel below the previous ones.
    pub fn panel(mut self, plot: Plot) -> Self {
        self.panels.push(plot);
        self
    }

    /// The standalone SVG document.
    pub fn to_svg(&self) -> Result<String, PlotError> {
        if self.panels.is_empty() {
            return Err(PlotError::NoSeries {
                plot: self.title.clone(),
            });
        }
        let layouts = self
            .panels
            .iter()
            .map(Plot::layout)
            .collect::<Result<Vec<_>, _>>()?;
        let left = layouts.iter().map(|l| l.left).fold(0.0, f64::max);
        let right = layouts.iter().map(|l| l.right).fold(0.0, f64::max);
        let width = self.panels.iter().map(|p| p.width).fold(0.0, f64::max);
        let head = if self.title.is_empty() { 0.0 } else { 34.0 };
        // A panel grows to hold its legend (20 px a row from 12 px below the
        // plot area's top) when it has more series than its height shows.
        let panels: Vec<Plot> = self
            .panels
            .iter()
            .map(|p| {
                let mut p = p.clone();
                let top = if p.title.is_empty() {
                    TOP_PLAIN
                } else {
                    TOP_TITLE
                };
                p.height = p
                    .height
                    .max(top + 12.0 + 20.0 * p.series.len() as f64 + BOTTOM);
                p
            })
            .collect();
        let height = head + panels.iter().map(|p| p.height).sum::<f64>();
        let mut out = String::new();
        svg::open_svg(&mut out, width, height);
        if !self.title.is_empty() {
            text(
                &mut out,
                width / 2.0,
                24.0,
                LARGE + 2.0,
                "middle",
                r#" font-weight="bold""#,
                &self.title,
            );
        }
        let mut y0 = head;
        for (k, (p, lay)) in panels.iter().zip(&layouts).enumerate() {
            // Every panel spans the figure's width.
            let mut p = p.clone();
            p.width = width;
            let _ = writeln!(out, r#"<g class="panel">"#);
            p.render(&mut out, k, y0, lay, left, right);
            let _ = writeln!(out, "</g>");
            y0 += p.height;
        }
        out.push_str("</svg>\n");
        Ok(out)
    }

    /// Writes [`Figure::to_svg`] to `path`, creating its directory.
    pub fn write(&self, path: impl AsRef<Path>) -> Result<(), PlotError> {
        write_file(path.as_ref(), &self.to_svg()?)
    }
}
