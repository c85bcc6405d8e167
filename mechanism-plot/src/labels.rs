//! Where a drawing's labels go: beside their joint, on the side where they
//! cover the least (other labels, joints, blocks, links), inside the canvas.

use crate::svg::text_width;

/// A box in px: left, top, right, bottom (SVG coordinates, y down).
pub type Rect = [f64; 4];

/// Label font size (px).
pub const SIZE: f64 = 13.0;

/// Candidate places of a label round its point `(x, y)`: the text's anchor
/// point offset `(dx, dy)` (px, baseline) and its `text-anchor`, in order of
/// preference (up and right first, as a reader expects).
const PLACES: [(f64, f64, &str); 8] = [
    (9.0, -9.0, "start"),
    (-9.0, -9.0, "end"),
    (9.0, 20.0, "start"),
    (-9.0, 20.0, "end"),
    (11.0, 5.0, "start"),
    (-11.0, 5.0, "end"),
    (0.0, -12.0, "middle"),
    (0.0, 23.0, "middle"),
];

/// What a label should not cover.
#[derive(Default)]
pub struct Obstacles {
    /// Discs: centre and radius (joints, blocks).
    pub discs: Vec<([f64; 2], f64)>,
    /// Thick segments: ends and half width (links, guides).
    pub segments: Vec<([f64; 2], [f64; 2], f64)>,
    /// Boxes (labels already placed, ground supports).
    pub boxes: Vec<Rect>,
    /// The canvas: labels stay inside it.
    pub canvas: Rect,
}

/// A label placed: its anchor point, `text-anchor` and box.
pub struct Placed {
    pub x: f64,
    pub y: f64,
    pub anchor: &'static str,
    pub rect: Rect,
}

/// The box of `name` at anchor point `(x, y)`: the width estimated at 0.7 em
/// a character (wider than the margins' 0.6: a label's capitals and digits),
/// 10 px above the baseline and 3 below.
fn rect(name: &str, x: f64, y: f64, anchor: &str) -> Rect {
    let w = text_width(name, SIZE) * 7.0 / 6.0;
    let left = match anchor {
        "end" => x - w,
        "middle" => x - w / 2.0,
        _ => x,
    };
    [left, y - 10.0, left + w, y + 3.0]
}

fn overlap(a: &Rect, b: &Rect) -> bool {
    a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]
}

/// Distance from `p` to the box `r` (0 inside).
fn distance(r: &Rect, p: [f64; 2]) -> f64 {
    let dx = (r[0] - p[0]).max(p[0] - r[2]).max(0.0);
    let dy = (r[1] - p[1]).max(p[1] - r[3]).max(0.0);
    dx.hypot(dy)
}

/// Whether the thick segment `a`-`b` (half width `h`) touches the box `r`:
/// sampled every 2 px along it.
fn crosses(r: &Rect, a: [f64; 2], b: [f64; 2], h: f64) -> bool {
    let n = ((b[0] - a[0]).hypot(b[1] - a[1]) / 2.0).ceil().max(1.0) as usize;
    (0..=n).any(|k| {
        let t = k as f64 / n as f64;
        distance(r, [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]) < h
    })
}

impl Obstacles {
    /// How much a label at `r` covers: 100 outside the canvas, 10 for each
    /// label, support, joint or block it covers, 3 for each link or guide.
    fn cost(&self, r: &Rect) -> u32 {
        let c = &self.canvas;
        let outside = r[0] < c[0] || r[1] < c[1] || r[2] > c[2] || r[3] > c[3];
        let boxes = self.boxes.iter().filter(|b| overlap(r, b)).count();
        let discs = self
            .discs
            .iter()
            .filter(|(p, radius)| distance(r, *p) < *radius)
            .count();
        let segments = self
            .segments
            .iter()
            .filter(|(a, b, h)| crosses(r, *a, *b, *h))
            .count();
        100 * u32::from(outside) + 10 * (boxes + discs) as u32 + 3 * segments as u32
    }

    /// Places `name` next to the point `(x, y)` where it covers least (the
    /// first such place in order of preference) and keeps its box as an
    /// obstacle for the labels placed after it.
    pub fn place(&mut self, name: &str, x: f64, y: f64) -> Placed {
        let (mut best, mut best_cost) = (None, u32::MAX);
        for (dx, dy, anchor) in PLACES {
            let r = rect(name, x + dx, y + dy, anchor);
            let cost = self.cost(&r);
            if cost < best_cost {
                best = Some(Placed {
                    x: x + dx,
                    y: y + dy,
                    anchor,
                    rect: r,
                });
                best_cost = cost;
            }
            if cost == 0 {
                break;
            }
        }
        let placed = best.unwrap_or(Placed {
            x: x + 9.0,
            y: y - 9.0,
            anchor: "start",
            rect: rect(name, x + 9.0, y - 9.0, "start"),
        });
        self.boxes.push(placed.rect);
        placed
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The preferred place (up and right) when it is free; another side when a
    /// joint or a label is there, or when it would leave the canvas.
    #[test]
    fn a_label_moves_off_what_it_would_cover() {
        let canvas = [0.0, 0.0, 400.0, 300.0];
        let mut free = Obstacles {
            canvas,
            ..Default::default()
        };
        let p = free.place("B", 100.0, 100.0);
        assert_eq!((p.x, p.y, p.anchor), (109.0, 91.0, "start"));
        let mut busy = Obstacles {
            canvas,
            discs: vec![([115.0, 88.0], 7.0)],
            ..Default::default()
        };
        let p = busy.place("B", 100.0, 100.0);
        assert_eq!(p.anchor, "end", "up-left, clear of the joint up-right");
        let second = busy.place("C", 100.0, 100.0);
        assert!(!overlap(&second.rect, &p.rect), "labels do not overlap");
        let mut edge = Obstacles {
            canvas,
            ..Default::default()
        };
        let p = edge.place("long name", 395.0, 100.0);
        assert!(p.rect[2] <= 400.0, "kept inside the canvas: {:?}", p.rect);
    }
}
