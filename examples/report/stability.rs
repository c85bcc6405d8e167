//! The report's stability section: error against distance to the singularity
//! for each group, against the double-double reference
//! (`mechanism_reference::groups`), with the bound `c eps / d`, run time per
//! evaluation, and log-log SVG plots written next to the report.
//!
//! `section(out_dir)` returns the markdown and writes
//! `stability-positions.svg`, `stability-rates.svg` and
//! `stability-stiff.svg` into `out_dir`. The tests of the same cases, with
//! their assertions, are in `tests/stability/`; the constants are documented
//! in `docs/stability.md`.
#![allow(dead_code)]

use mechanism::dyad::{rpr, rrp, rrr};
use mechanism::force::{self, group, inertia_and_gravity, Wrench};
use mechanism::guide::Line;
use mechanism::{Mode, Point2, Vector2};
use mechanism_reference::groups as refg;
use mechanism_reference::naive::solve_unpivoted_unscaled;
use mechanism_reference::Dd;
use std::fmt::Write as _;
use std::hint::black_box;
use std::path::Path;
use std::time::Instant;

const EPS: f64 = f64::EPSILON;

/// One series of a plot: `(x, y)` points, positive values only.
struct Series {
    name: String,
    points: Vec<(f64, f64)>,
    dashed: bool,
}

/// Relative distances 1e-2 .. 1e-14, four per decade.
fn deltas() -> Vec<f64> {
    let mut out = vec![];
    for k in 2..=14 {
        for m in [1.0, 1.7, 3.1, 5.3] {
            let d = m * 10f64.powi(-k);
            if d >= 0.99e-14 {
                out.push(d);
            }
        }
    }
    out
}

fn p(x: f64, y: f64) -> Point2<f64> {
    Point2::new(x, y)
}

fn dv(q: &Point2<f64>) -> refg::V {
    refg::v(q.x, q.y)
}

fn dist(q: &Point2<f64>, r: refg::V) -> f64 {
    refg::norm(refg::sub(dv(q), r)).to_f64()
}

/// Median of `rounds` timings (ns per call) of `f` over `n` calls, the cases
/// interleaved round by round so that they see the same machine state.
fn time_interleaved(cases: &mut [&mut dyn FnMut() -> f64], n: usize, rounds: usize) -> Vec<f64> {
    let mut samples = vec![vec![]; cases.len()];
    for _ in 0..rounds {
        for (i, f) in cases.iter_mut().enumerate() {
            let t = Instant::now();
            let mut acc = 0.0;
            for _ in 0..n {
                acc += f();
            }
            black_box(acc);
            samples[i].push(t.elapsed().as_nanos() as f64 / n as f64);
        }
    }
    samples
        .into_iter()
        .map(|mut s| {
            s.sort_by(f64::total_cmp);
            s[s.len() / 2]
        })
        .collect()
}

/// RRR near the outer (`outer`) or inner limit: `(delta, err / L)` pairs,
/// worst over three directions and both modes at each delta.
fn rrr_edge(outer: bool) -> Vec<(f64, f64)> {
    let (a, l1, l2) = (p(0.31, -0.72), 1.3, 0.9);
    deltas()
        .into_iter()
        .map(|delta| {
            let mut worst: f64 = 0.0;
            let mut real = delta;
            for phi in [0.4f64, 2.2, -2.9] {
                let d = if outer {
                    (l1 + l2) * (1.0 - delta)
                } else {
                    f64::abs(l1 - l2) + (l1 + l2) * delta
                };
                let b = p(a.x + d * phi.cos(), a.y + d * phi.sin());
                let dd = refg::norm(refg::sub(dv(&b), dv(&a)));
                let (l1d, l2d) = (Dd::from(l1), Dd::from(l2));
                let gap = if outer {
                    l1d + l2d - dd
                } else {
                    dd - (l1d - l2d).abs()
                };
                real = (gap / (l1d + l2d)).to_f64();
                for (mode, left) in [(Mode::Plus, true), (Mode::Minus, false)] {
                    let c = rrr::position(&a, l1, &b, l2, mode).map(|q| q.c);
                    let r = refg::rrr_position(dv(&a), l1, dv(&b), l2, left);
                    if let (Ok(c), Some(r)) = (c, r) {
                        worst = worst.max(dist(&c, r) / (l1 + l2));
                    }
                }
            }
            (real, worst)
        })
        .collect()
}

/// RRP near tangency: `(delta, err / l)`.
fn rrp_edge() -> Vec<(f64, f64)> {
    let (l, offset, psi) = (0.37, 0.055, 1.9f64);
    let g = Line {
        origin: p(0.2, -0.1),
        dir: Vector2::new(psi.cos(), psi.sin()),
    };
    let gr = refg::Line::new([0.2, -0.1], [g.dir.x, g.dir.y]);
    deltas()
        .into_iter()
        .map(|delta| {
            let k = offset + l * (1.0 - delta);
            let a = g.origin + g.dir * 0.123 + Vector2::new(-g.dir.y, g.dir.x) * k;
            let kr = refg::cross(gr.dir, refg::sub(dv(&a), gr.origin)) - Dd::from(offset);
            let real = ((Dd::from(l) - kr.abs()) / Dd::from(l)).to_f64();
            let mut worst: f64 = 0.0;
            for (mode, ahead) in [(Mode::Plus, true), (Mode::Minus, false)] {
                if let (Ok(pos), Some((cr, _))) = (
                    rrp::position(&a, l, &g, offset, mode),
                    refg::rrp_position(dv(&a), l, &gr, offset, ahead),
                ) {
                    worst = worst.max(dist(&pos.c, cr) / l);
                }
            }
            (real, worst)
        })
        .collect()
}

/// RPR near `|A - B| = |offset|`: `(delta, max(axis error, s error / e))`.
fn rpr_edge() -> Vec<(f64, f64)> {
    let (b, e, phi) = (p(0.4, 0.1), 0.35, 2.2f64);
    deltas()
        .into_iter()
        .map(|delta| {
            let r = e * (1.0 + delta);
            let a = p(b.x + r * phi.cos(), b.y + r * phi.sin());
            let dd = refg::norm(refg::sub(dv(&a), dv(&b)));
            let real = ((dd - Dd::from(e)) / Dd::from(e)).to_f64();
            let mut worst: f64 = 0.0;
            for (mode, pos_s) in [(Mode::Plus, true), (Mode::Minus, false)] {
                if let (Ok(pos), Some((u, s))) = (
                    rpr::position(&a, &b, e, mode),
                    refg::rpr_position(dv(&a), dv(&b), e, pos_s),
                ) {
                    let eu = refg::norm(refg::sub(refg::v(pos.axis.x, pos.axis.y), u)).to_f64();
                    let es = (Dd::from(pos.s) - s).abs().to_f64() / e;
                    worst = worst.max(eu.max(es));
                }
            }
            (real, worst)
        })
        .collect()
}

/// The textbook height `sqrt(l1^2 - a^2)` against ours (clamped Heron on
/// squared lengths), `B` at `2 (1 - delta)` in the direction 0.3 rad from `A`
/// (`l1 + l2 = 2`): `(delta, ours, naive)` relative errors of the height (the
/// naive one `inf` when it returned NaN).
fn naive_height() -> Vec<(f64, f64, f64)> {
    let (l1, l2, phi) = (1.25, 0.75, 0.3f64);
    let height =
        |b: &Point2<f64>, c: &Point2<f64>| (b.x * c.y - b.y * c.x) / (b.x * b.x + b.y * b.y).sqrt();
    deltas()
        .into_iter()
        .map(|delta| {
            let r = 2.0 * (1.0 - delta);
            let b = p(r * phi.cos(), r * phi.sin());
            let c = refg::rrr_position(refg::v(0.0, 0.0), l1, dv(&b), l2, true).unwrap();
            let (bx, by) = (Dd::from(b.x), Dd::from(b.y));
            let h = (bx * c[1] - by * c[0]) / refg::norm(dv(&b));
            let ours = rrr::position(&p(0.0, 0.0), l1, &b, l2, Mode::Plus)
                .map(|q| height(&b, &q.c))
                .unwrap_or(f64::NAN);
            let dist = (b.x * b.x + b.y * b.y).sqrt();
            let along = (l1 * l1 - l2 * l2 + dist * dist) / (2.0 * dist);
            let naive = (l1 * l1 - along * along).sqrt();
            let rel = |x: f64| {
                if x.is_finite() {
                    (Dd::from(x) - h).abs().to_f64() / h.to_f64()
                } else {
                    f64::INFINITY
                }
            };
            (delta, rel(ours), rel(naive))
        })
        .collect()
}

/// RRR rates near toggle: `(kappa, err)` for the rate system alone.
fn rrr_rates() -> Vec<(f64, f64)> {
    let (l1, l2, phi) = (1.3, 0.9, 0.7f64);
    let (va, vb) = (Vector2::new(0.3, -1.1), Vector2::new(-0.8, 0.45));
    (0..=28)
        .filter_map(|i| {
            let kappa = 10f64.powf(-0.5 * i as f64);
            let beta = kappa.asin();
            let r1 = Vector2::new(l1 * phi.cos(), l1 * phi.sin());
            let r2 = Vector2::new(l2 * (phi + beta).cos(), l2 * (phi + beta).sin());
            let pos = rrr::RrrPosition::new(p(0.0, 0.0) + r1, r1, r2);
            let v = rrr::velocity(&pos, Some(&va), Some(&vb)).ok()?;
            let (r1d, r2d) = (refg::v(r1.x, r1.y), refg::v(r2.x, r2.y));
            let kd = refg::cross(r1d, r2d).abs() / (refg::norm(r1d) * refg::norm(r2d));
            let (w1, w2) = refg::rrr_rates(
                refg::v(0.0, 0.0),
                refg::sub(r1d, r2d),
                r1d,
                refg::v(va.x, va.y),
                refg::v(vb.x, vb.y),
            )?;
            let size = w1.abs().to_f64().max(w2.abs().to_f64());
            let err = (Dd::from(v.omega1) - w1)
                .abs()
                .to_f64()
                .max((Dd::from(v.omega2) - w2).abs().to_f64())
                / size;
            Some((kd.to_f64(), err))
        })
        .collect()
}

/// The stiff RRR group (1e6 kg and 1e-6 kg links, mm): `(angle, solve,
/// naive)` normwise relative errors against the double-double Newton-Euler
/// reference (`inf` for the naive division by zero).
fn stiff() -> Vec<(f64, f64, f64)> {
    (2..=26)
        .map(|k| 10f64.powf(-0.5 * k as f64))
        .map(|angle| {
            let (a, c) = (p(0.0, 0.0), p(300.0, 400.0));
            let b = p(900.0, 400.0 + 600.0 * angle.tan());
            let g = Vector2::new(0.0, -9810.0);
            let (m1, j1, g1, ag1, al1) = (
                1e6,
                1e11,
                p(150.0, 200.0),
                Vector2::new(-2500.0, 1200.0),
                3.0,
            );
            let (m2, j2, g2, ag2, al2) = (
                1e-6,
                1e-5,
                p(600.0, 400.0),
                Vector2::new(4000.0, -700.0),
                -2.0,
            );
            let (fx, fp) = (Vector2::new(1.0, -2.0), p(800.0, 0.0));
            let load1 = inertia_and_gravity(m1, j1, &g1, &ag1, al1, Some(&g), &c);
            let load2 = inertia_and_gravity(m2, j2, &g2, &ag2, al2, Some(&g), &c)
                + Wrench::force_at(&fx, &fp, &c);
            let r = force::rrr::reactions(&a, &b, &c, &load1, &load2).unwrap();
            let ours = [r.a.x, r.a.y, r.b.x, r.b.y, r.c.x, r.c.y];
            let d = Dd::from;
            let vv = |q: Vector2<f64>| refg::v(q.x, q.y);
            let f2 = refg::add(refg::scale(d(m2), refg::sub(vv(g), vv(ag2))), vv(fx));
            let m2c = -(d(j2) * d(al2)) + refg::cross(refg::sub(dv(&fp), dv(&g2)), vv(fx));
            let exact = refg::rrr_reactions(
                dv(&a),
                dv(&b),
                dv(&c),
                refg::scale(d(m1), refg::sub(vv(g), vv(ag1))),
                dv(&g1),
                -(d(j1) * d(al1)),
                f2,
                dv(&g2),
                m2c,
            )
            .unwrap();
            let size = exact.iter().fold(0.0f64, |m, x| m.max(x.abs().to_f64()));
            let err = |x: &[f64; 6]| {
                x.iter()
                    .zip(&exact)
                    .map(|(x, e)| (Dd::from(*x) - *e).abs().to_f64())
                    .fold(0.0, f64::max)
                    / size
            };
            let joints = [
                group::Joint {
                    pair: group::Pair::Revolute { point: a },
                    connection: group::Connection::OutsideToLink1,
                },
                group::Joint {
                    pair: group::Pair::Revolute { point: b },
                    connection: group::Connection::OutsideToLink2,
                },
                group::Joint {
                    pair: group::Pair::Revolute { point: c },
                    connection: group::Connection::Link1ToLink2,
                },
            ];
            let sys = group::assemble(&joints, &c, &load1, &load2);
            let order = [0, 1, 3, 4, 5, 2];
            let naive =
                solve_unpivoted_unscaled(order.map(|i| sys.matrix[i]), order.map(|i| sys.rhs[i]))
                    .map(|x| err(&x))
                    .unwrap_or(f64::INFINITY);
            (angle, err(&ours), naive)
        })
        .collect()
}

/// A minimal log-log SVG plot.
fn svg_plot(title: &str, xlabel: &str, ylabel: &str, series: &[Series]) -> String {
    let (w, h, ml, mr, mt, mb) = (640.0, 420.0, 70.0, 190.0, 30.0, 50.0);
    let pts = series
        .iter()
        .flat_map(|s| s.points.iter())
        .filter(|(x, y)| *x > 0.0 && *y > 0.0 && y.is_finite());
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for (x, y) in pts {
        x0 = x0.min(x.log10());
        x1 = x1.max(x.log10());
        y0 = y0.min(y.log10());
        y1 = y1.max(y.log10());
    }
    let (x0, x1, y0, y1) = (x0.floor(), x1.ceil(), y0.floor(), y1.ceil());
    let sx = |x: f64| ml + (x.log10() - x0) / (x1 - x0).max(1.0) * (w - ml - mr);
    let sy = |y: f64| h - mb - (y.log10() - y0) / (y1 - y0).max(1.0) * (h - mt - mb);
    let colors = [
        "#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#17becf",
    ];
    let mut s = String::new();
    let _ = write!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="11"><rect width="100%" height="100%" fill="white"/><text x="{}" y="18" text-anchor="middle" font-size="13">{title}</text>"#,
        (w - mr + ml) / 2.0
    );
    for e in (x0 as i32)..=(x1 as i32) {
        let x = sx(10f64.powi(e));
        let _ = write!(
            s,
            r##"<line x1="{x:.1}" y1="{mt}" x2="{x:.1}" y2="{}" stroke="#ddd"/><text x="{x:.1}" y="{}" text-anchor="middle">1e{e}</text>"##,
            h - mb,
            h - mb + 14.0
        );
    }
    for e in (y0 as i32)..=(y1 as i32) {
        let y = sy(10f64.powi(e));
        let _ = write!(
            s,
            r##"<line x1="{ml}" y1="{y:.1}" x2="{}" y2="{y:.1}" stroke="#ddd"/><text x="{}" y="{:.1}" text-anchor="end">1e{e}</text>"##,
            w - mr,
            ml - 4.0,
            y + 4.0
        );
    }
    let _ = write!(
        s,
        r##"<rect x="{ml}" y="{mt}" width="{}" height="{}" fill="none" stroke="black"/><text x="{}" y="{}" text-anchor="middle">{xlabel}</text><text x="14" y="{}" text-anchor="middle" transform="rotate(-90 14 {})">{ylabel}</text>"##,
        w - ml - mr,
        h - mt - mb,
        (w - mr + ml) / 2.0,
        h - 12.0,
        (h - mb + mt) / 2.0,
        (h - mb + mt) / 2.0
    );
    for (i, se) in series.iter().enumerate() {
        let color = colors[i % colors.len()];
        let path: Vec<String> = se
            .points
            .iter()
            .filter(|(x, y)| *x > 0.0 && *y > 0.0 && y.is_finite())
            .map(|&(x, y)| format!("{:.1},{:.1}", sx(x), sy(y)))
            .collect();
        let dash = if se.dashed {
            r#" stroke-dasharray="5,3""#
        } else {
            ""
        };
        let _ = write!(
            s,
            r#"<polyline fill="none" stroke="{color}" stroke-width="1.5"{dash} points="{}"/>"#,
            path.join(" ")
        );
        if !se.dashed {
            for pt in &path {
                let (x, y) = pt.split_once(',').unwrap_or(("0", "0"));
                let _ = write!(s, r#"<circle cx="{x}" cy="{y}" r="2" fill="{color}"/>"#);
            }
        }
        let ly = mt + 14.0 + 16.0 * i as f64;
        let _ = write!(
            s,
            r#"<line x1="{}" y1="{ly}" x2="{}" y2="{ly}" stroke="{color}" stroke-width="2"{dash}/><text x="{}" y="{}">{}</text>"#,
            w - mr + 8.0,
            w - mr + 28.0,
            w - mr + 32.0,
            ly + 4.0,
            se.name
        );
    }
    s.push_str("</svg>\n");
    s
}

fn worst_ratio(v: &[(f64, f64)], f: impl Fn(f64, f64) -> f64) -> f64 {
    v.iter().map(|&(d, e)| f(d, e)).fold(0.0, f64::max)
}

/// The markdown section; writes the SVG plots into `out_dir`.
/// One evaluation of each primitive at a pose 1e-8 from its edge and at a
/// comfortable pose, ns (medians of 31 interleaved rounds): RRR at the
/// edge and in the middle, RRP and RPR at the edge, the RRR's velocity.
fn primitive_times() -> Vec<f64> {
    let (a, b_edge, b_mid) = (
        p(0.31, -0.72),
        p(0.31 + 2.2 * (1.0 - 1e-8), -0.72),
        p(0.31 + 1.5, -0.72),
    );
    let g = Line {
        origin: p(0.0, 0.0),
        dir: Vector2::new(1.0, 0.0),
    };
    let mut t_rrr_edge = || {
        rrr::position(black_box(&a), 1.3, black_box(&b_edge), 0.9, Mode::Plus)
            .map_or(0.0, |q| q.c.y)
    };
    let mut t_rrr_mid = || {
        rrr::position(black_box(&a), 1.3, black_box(&b_mid), 0.9, Mode::Plus).map_or(0.0, |q| q.c.y)
    };
    let a_rrp = p(0.1, 0.37 * (1.0 - 1e-8));
    let mut t_rrp = || {
        rrp::position(black_box(&a_rrp), 0.37, black_box(&g), 0.0, Mode::Plus).map_or(0.0, |q| q.s)
    };
    let a_rpr = p(0.35 * (1.0 + 1e-8), 0.0);
    let mut t_rpr = || {
        rpr::position(black_box(&a_rpr), black_box(&p(0.0, 0.0)), 0.35, Mode::Plus)
            .map_or(0.0, |q| q.s)
    };
    let pos = rrr::position(&a, 1.3, &b_edge, 0.9, Mode::Plus).unwrap();
    let va = Vector2::new(0.3, -1.1);
    let mut t_vel =
        || rrr::velocity(black_box(&pos), Some(black_box(&va)), None).map_or(0.0, |v| v.omega1);
    time_interleaved(
        &mut [
            &mut t_rrr_edge,
            &mut t_rrr_mid,
            &mut t_rrp,
            &mut t_rpr,
            &mut t_vel,
        ],
        20_000,
        31,
    )
}

/// The three figures of the section, written to `out_dir`: position error
/// near the edge (`outer`, `inner`, `rrp_e`, `rpr_e`, `naive`), rate error
/// near toggle (`rates`), the stiff group's reactions (`stiff_v`).
fn write_figures(
    out_dir: &Path,
    edges: [&[(f64, f64)]; 4],
    naive: &[(f64, f64, f64)],
    rates: &[(f64, f64)],
    stiff_v: &[(f64, f64, f64)],
) {
    let [outer, inner, rrp_e, rpr_e] = edges;
    let bound = |c: f64| -> Vec<(f64, f64)> {
        deltas()
            .into_iter()
            .map(|d| (d, c * EPS / d.sqrt()))
            .collect()
    };
    let pos_svg = svg_plot(
        "Position error near the edge of assembly (f64)",
        "relative distance to the limit, delta",
        "error / size",
        &[
            Series {
                name: "RRR outer".into(),
                points: outer.to_vec(),
                dashed: false,
            },
            Series {
                name: "RRR inner".into(),
                points: inner.to_vec(),
                dashed: false,
            },
            Series {
                name: "RRP tangency".into(),
                points: rrp_e.to_vec(),
                dashed: false,
            },
            Series {
                name: "RPR tangency".into(),
                points: rpr_e.to_vec(),
                dashed: false,
            },
            Series {
                name: "naive h (rel.)".into(),
                points: naive.iter().map(|&(d, _, n)| (d, n)).collect(),
                dashed: false,
            },
            Series {
                name: "bound 2 eps/sqrt(d)".into(),
                points: bound(2.0),
                dashed: true,
            },
            Series {
                name: "eps/d".into(),
                points: deltas().into_iter().map(|d| (d, EPS / d)).collect(),
                dashed: true,
            },
        ],
    );
    let rates_svg = svg_plot(
        "RRR rate error near toggle (f64)",
        "condition kappa = |det| / scale",
        "relative error of the rates",
        &[
            Series {
                name: "RRR rates".into(),
                points: rates.to_vec(),
                dashed: false,
            },
            Series {
                name: "bound 4 eps/kappa".into(),
                points: rates.iter().map(|&(k, _)| (k, 4.0 * EPS / k)).collect(),
                dashed: true,
            },
        ],
    );
    let stiff_svg = svg_plot(
        "Stiff RRR group (1e6 kg / 1e-6 kg, mm): reactions",
        "angle of link 2 from horizontal (rad)",
        "relative error",
        &[
            Series {
                name: "scaled pivoting".into(),
                points: stiff_v.iter().map(|&(a, e, _)| (a, e.max(1e-18))).collect(),
                dashed: false,
            },
            Series {
                name: "naive elimination".into(),
                points: stiff_v.iter().map(|&(a, _, n)| (a, n.max(1e-18))).collect(),
                dashed: false,
            },
        ],
    );
    for (name, svg) in [
        ("stability-positions.svg", &pos_svg),
        ("stability-rates.svg", &rates_svg),
        ("stability-stiff.svg", &stiff_svg),
    ] {
        if let Err(e) = std::fs::write(out_dir.join(name), svg) {
            eprintln!("stability: cannot write {name}: {e}");
        }
    }
}

pub fn section(out_dir: &Path) -> String {
    let outer = rrr_edge(true);
    let inner = rrr_edge(false);
    let rrp_e = rrp_edge();
    let rpr_e = rpr_edge();
    let naive = naive_height();
    let rates = rrr_rates();
    let stiff_v = stiff();

    let times = primitive_times();
    write_figures(
        out_dir,
        [&outer, &inner, &rrp_e, &rpr_e],
        &naive,
        &rates,
        &stiff_v,
    );

    let mut md = String::new();
    let _ = writeln!(md, "## Stability\n");
    let _ = writeln!(
        md,
        "Every answer is accurate to what the conditioning allows, or a typed error. Errors are \
         measured against an independent double-double reference (about 106 bits) on the same \
         `f64` inputs; `delta` is the relative distance to the singular pose, `kappa` the \
         `condition` field of the velocity results. Details and the tests: `docs/stability.md`, \
         `tests/stability/`.\n"
    );
    let _ = writeln!(md, "### Positions at the edge of assembly\n");
    let _ = writeln!(md, "Bound: `err / size <= c eps / sqrt(delta)` (hence `<= c eps / delta`), asserted with `c = 2`.\n");
    let _ = writeln!(md, "| case | worst err sqrt(delta)/eps (= c) | err at delta 1e-8 | err at delta 1e-14 | bound at 1e-14 |");
    let _ = writeln!(md, "|---|---|---|---|---|");
    let at = |v: &[(f64, f64)], d: f64| {
        v.iter()
            .min_by(|x, y| {
                (x.0.ln() - d.ln())
                    .abs()
                    .total_cmp(&(y.0.ln() - d.ln()).abs())
            })
            .map_or(f64::NAN, |x| x.1)
    };
    for (name, v) in [
        ("RRR outer (l1+l2)", &outer),
        ("RRR inner (abs(l1-l2))", &inner),
        ("RRP tangency", &rrp_e),
        ("RPR tangency", &rpr_e),
    ] {
        let _ = writeln!(
            md,
            "| {name} | {:.2} | {:.1e} | {:.1e} | {:.1e} |",
            worst_ratio(v, |d, e| e * d.sqrt() / EPS),
            at(v, 1e-8),
            at(v, 1e-14),
            2.0 * EPS / 1e-7
        );
    }
    let scaled = |pick: fn(&(f64, f64, f64)) -> f64| {
        naive
            .iter()
            .map(|x| pick(x) * x.0 / EPS)
            .fold(0.0, f64::max)
    };
    let (ours_max, naive_max) = (scaled(|x| x.1), scaled(|x| x.2));
    let _ = writeln!(
        md,
        "\nCancellation: near the edge the height's relative error follows `eps / delta` for any \
         formula fed rounded inputs (the conditioning): ours (Heron on squared lengths, clamped) \
         at most {ours_max:.2} `eps / delta`, the textbook `sqrt(l1^2 - a^2)` {naive_max:.2} \
         `eps / delta`, and one ulp inside the edge the textbook one is 3 % off or NaN \
         (`tests/stability/assembly.rs`).\n"
    );
    let _ = writeln!(md, "![position error](stability-positions.svg)\n");
    let _ = writeln!(md, "### Rates near toggle\n");
    let _ = writeln!(
        md,
        "The RRR rate system alone: relative error against `kappa`; worst `err kappa / eps` = {:.2} \
         (bound 4). Below `kappa = 16 eps` the result is `Singular {{ det, scale }}`.\n",
        worst_ratio(&rates, |k, e| e * k / EPS)
    );
    let _ = writeln!(md, "![rate error](stability-rates.svg)\n");
    let _ = writeln!(md, "### Stiff kinetostatics\n");
    let _ = writeln!(
        md,
        "| angle (rad) | scaled pivoting | naive elimination |\n|---|---|---|"
    );
    for &(a, e, n) in stiff_v.iter().step_by(4) {
        let _ = writeln!(
            md,
            "| {a:.1e} | {e:.1e} | {} |",
            if n.is_finite() {
                format!("{n:.1e}")
            } else {
                "division by zero".into()
            }
        );
    }
    let _ = writeln!(md, "\n![stiff](stability-stiff.svg)\n");
    let _ = writeln!(
        md,
        "### Run time per evaluation (median of 31 interleaved rounds, ns)\n"
    );
    let _ = writeln!(md, "| evaluation | ns |\n|---|---|");
    for (name, t) in [
        ("rrr::position, delta 1e-8", times[0]),
        ("rrr::position, delta 0.3", times[1]),
        ("rrp::position, delta 1e-8", times[2]),
        ("rpr::position, delta 1e-8", times[3]),
        ("rrr::velocity, kappa 1e-4", times[4]),
    ] {
        let _ = writeln!(md, "| {name} | {t:.1} |");
    }
    md
}
