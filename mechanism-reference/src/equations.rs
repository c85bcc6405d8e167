//! The loop-closure equations of a [`Linkage`] and their derivatives, written
//! from the constraint definitions in [`crate::constraint`]:
//!
//! - `phi(q, inputs)`: the residuals;
//! - `J = d phi / d q`: the Jacobian in the unknown coordinates;
//! - `phi_t`: the partial time derivative through the inputs, so that the
//!   velocity equations read `J qdot = -phi_t`;
//! - `gamma = -(d^2 phi/dt^2 - J qddot)`: everything in the second time
//!   derivative except the `J qddot` term, so that `J qddot = gamma`.
//!
//! For a constraint of degree at most two in the coordinates, `gamma` is
//! `-phi_theta thetaddot` minus the quadratic form in the rates, listed per
//! constraint below.

use crate::constraint::{Constraint, Linkage, Point, V2};
use crate::Dd;

/// A point turned about its pivot by an input: `Crank` (phase 0, factor
/// 1) and `Geared`.
#[derive(Clone, Copy)]
struct Turn {
    r: f64,
    input: usize,
    phase: f64,
    factor: f64,
}

impl Turn {
    /// The turn of `c`, when it is a crank or a geared link.
    fn of(c: &Constraint) -> Option<Turn> {
        match *c {
            Constraint::Crank { r, input, .. } => Some(Turn {
                r,
                input,
                phase: 0.0,
                factor: 1.0,
            }),
            Constraint::Geared {
                r,
                input,
                phase,
                factor,
                ..
            } => Some(Turn {
                r,
                input,
                phase,
                factor,
            }),
            _ => None,
        }
    }

    /// The length, and the angle's value, rate and acceleration (rad,
    /// rad/s, rad/s^2) from one input's (`rates` and `accels` may be empty
    /// when not needed: their terms are then zero).
    fn at(self, inputs: &[Dd], rates: &[Dd], accels: &[Dd]) -> [Dd; 4] {
        let of = |v: &[Dd]| v.get(self.input).copied().unwrap_or(Dd::ZERO);
        let f = Dd::from_f64(self.factor);
        [
            Dd::from_f64(self.r),
            Dd::from_f64(self.phase) + f * of(inputs),
            f * of(rates),
            f * of(accels),
        ]
    }
}

/// Positions of every point (fixed ones included) from the unknown vector.
pub fn points(linkage: &Linkage, q: &[Dd]) -> Vec<V2> {
    linkage
        .points
        .iter()
        .zip(linkage.columns())
        .map(|(p, c)| match (p, c) {
            (Point::Fixed(v), _) => *v,
            (Point::Unknown, Some(c)) => V2 {
                x: q[c],
                y: q[c + 1],
            },
            (Point::Unknown, None) => unreachable!("unknown points have columns"),
        })
        .collect()
}

/// Residuals `phi` at positions `p` (every point) and inputs (rad).
pub fn residual(linkage: &Linkage, p: &[V2], inputs: &[Dd]) -> Vec<Dd> {
    let mut f = Vec::with_capacity(linkage.equations());
    for c in &linkage.constraints {
        if let (
            Some(turn),
            Constraint::Crank { p: tip, o, .. } | Constraint::Geared { p: tip, o, .. },
        ) = (Turn::of(c), *c)
        {
            let [r, angle, _, _] = turn.at(inputs, &[], &[]);
            let (s, co) = angle.sin_cos();
            let d = p[tip].minus(p[o]);
            f.push(d.x - r * co);
            f.push(d.y - r * s);
            continue;
        }
        match *c {
            // Pushed above, from their `Turn`.
            Constraint::Crank { .. } | Constraint::Geared { .. } => {}
            Constraint::Distance { p: a, q: b, len } => {
                let d = p[a].minus(p[b]);
                f.push(d.dot(d) - Dd::from_f64(len).sqr());
            }
            Constraint::OnFixedLine { p: a, origin, dir } => {
                f.push(dir.cross(p[a].minus(origin)));
            }
            Constraint::OnLine { p: a, q1, q2 } => {
                f.push(p[q2].minus(p[q1]).cross(p[a].minus(p[q1])));
            }
            Constraint::Affine {
                p: a,
                o,
                q,
                a: ka,
                b: kb,
            } => {
                let w = p[q].minus(p[o]);
                let rhs = p[o].plus(w.scale(ka)).plus(w.perp().scale(kb));
                let d = p[a].minus(rhs);
                f.push(d.x);
                f.push(d.y);
            }
        }
    }
    f
}

/// Adds `g` (the gradient of the current row with respect to point `id`) to
/// the row, when the point is unknown.
fn put(row: &mut [Dd], cols: &[Option<usize>], id: usize, g: V2) {
    if let Some(c) = cols[id] {
        row[c] += g.x;
        row[c + 1] += g.y;
    }
}

/// The Jacobian `d phi / d q` (rows: equations; columns: unknown coordinates).
pub fn jacobian(linkage: &Linkage, p: &[V2]) -> Vec<Vec<Dd>> {
    let n = linkage.unknowns();
    let cols = linkage.columns();
    let one = Dd::ONE;
    let zero = Dd::ZERO;
    let mut rows = Vec::with_capacity(linkage.equations());
    for c in &linkage.constraints {
        match *c {
            Constraint::Crank { p: tip, o, .. } | Constraint::Geared { p: tip, o, .. } => {
                let mut rx = vec![zero; n];
                put(&mut rx, &cols, tip, V2 { x: one, y: zero });
                put(&mut rx, &cols, o, V2 { x: -one, y: zero });
                let mut ry = vec![zero; n];
                put(&mut ry, &cols, tip, V2 { x: zero, y: one });
                put(&mut ry, &cols, o, V2 { x: zero, y: -one });
                rows.push(rx);
                rows.push(ry);
            }
            Constraint::Distance { p: a, q: b, .. } => {
                let d = p[a].minus(p[b]).scale(Dd::from_f64(2.0));
                let mut r = vec![zero; n];
                put(&mut r, &cols, a, d);
                put(&mut r, &cols, b, d.scale(-one));
                rows.push(r);
            }
            Constraint::OnFixedLine { p: a, dir, .. } => {
                // cross(u, P - o) = u.x Py - u.y Px.
                let mut r = vec![zero; n];
                put(
                    &mut r,
                    &cols,
                    a,
                    V2 {
                        x: -dir.y,
                        y: dir.x,
                    },
                );
                rows.push(r);
            }
            Constraint::OnLine { p: a, q1, q2 } => {
                // cross(w, e), w = Q2 - Q1, e = P - Q1:
                // d/dw = (e.y, -e.x), d/de = (-w.y, w.x).
                let w = p[q2].minus(p[q1]);
                let e = p[a].minus(p[q1]);
                let gw = V2 { x: e.y, y: -e.x };
                let ge = V2 { x: -w.y, y: w.x };
                let mut r = vec![zero; n];
                put(&mut r, &cols, q2, gw);
                put(&mut r, &cols, a, ge);
                put(&mut r, &cols, q1, gw.plus(ge).scale(-one));
                rows.push(r);
            }
            Constraint::Affine {
                p: a,
                o,
                q,
                a: ka,
                b: kb,
            } => {
                // x: Px - Ox - a (Qx - Ox) + b (Qy - Oy)
                // y: Py - Oy - a (Qy - Oy) - b (Qx - Ox)
                let mut rx = vec![zero; n];
                put(&mut rx, &cols, a, V2 { x: one, y: zero });
                put(
                    &mut rx,
                    &cols,
                    o,
                    V2 {
                        x: ka - one,
                        y: -kb,
                    },
                );
                put(&mut rx, &cols, q, V2 { x: -ka, y: kb });
                let mut ry = vec![zero; n];
                put(&mut ry, &cols, a, V2 { x: zero, y: one });
                put(&mut ry, &cols, o, V2 { x: kb, y: ka - one });
                put(&mut ry, &cols, q, V2 { x: -kb, y: -ka });
                rows.push(rx);
                rows.push(ry);
            }
        }
    }
    rows
}

/// Right-hand side of the velocity equations `J qdot = -phi_t` for input
/// rates `rates` (rad/s).
pub fn velocity_rhs(linkage: &Linkage, inputs: &[Dd], rates: &[Dd]) -> Vec<Dd> {
    let mut b = Vec::with_capacity(linkage.equations());
    for c in &linkage.constraints {
        if let Some(turn) = Turn::of(c) {
            // phi = P - O - r (cos a, sin a): phi_a = r (sin a, -cos a).
            let [r, angle, rate, _] = turn.at(inputs, rates, &[]);
            let (s, co) = angle.sin_cos();
            let k = r * rate;
            b.push(-(k * s));
            b.push(k * co);
            continue;
        }
        match *c {
            // Pushed above, from their `Turn`.
            Constraint::Crank { .. } | Constraint::Geared { .. } => {}
            Constraint::Affine { .. } => {
                b.push(Dd::ZERO);
                b.push(Dd::ZERO);
            }
            _ => b.push(Dd::ZERO),
        }
    }
    b
}

/// Right-hand side `gamma` of the acceleration equations `J qddot = gamma`,
/// at positions `p`, point velocities `v` (every point; zero for fixed ones),
/// input rates and input accelerations.
///
/// Per constraint: crank (and geared, with its angle `a = phase + factor
/// theta`, `adot = factor thetadot`, `addot = factor thetaddot`) `r
/// thetaddot (-sin, cos) - r thetadot^2 (cos, sin)`;
/// distance `-2 |Pdot - Qdot|^2`; moving line `-2 cross(Q2dot - Q1dot, Pdot -
/// Q1dot)`; fixed line and affine: zero (linear in the coordinates).
pub fn acceleration_rhs(
    linkage: &Linkage,
    v: &[V2],
    inputs: &[Dd],
    rates: &[Dd],
    accels: &[Dd],
) -> Vec<Dd> {
    let two = Dd::from_f64(2.0);
    let mut b = Vec::with_capacity(linkage.equations());
    for c in &linkage.constraints {
        if let Some(turn) = Turn::of(c) {
            let [r, angle, w, al] = turn.at(inputs, rates, accels);
            let (s, co) = angle.sin_cos();
            let w2 = w.sqr();
            b.push(-(r * al * s) - r * w2 * co);
            b.push(r * al * co - r * w2 * s);
            continue;
        }
        match *c {
            // Pushed above, from their `Turn`.
            Constraint::Crank { .. } | Constraint::Geared { .. } => {}
            Constraint::Distance { p: a, q: bb, .. } => {
                let dv = v[a].minus(v[bb]);
                b.push(-(two * dv.dot(dv)));
            }
            Constraint::OnLine { p: a, q1, q2 } => {
                let wd = v[q2].minus(v[q1]);
                let ed = v[a].minus(v[q1]);
                b.push(-(two * wd.cross(ed)));
            }
            Constraint::OnFixedLine { .. } => b.push(Dd::ZERO),
            Constraint::Affine { .. } => {
                b.push(Dd::ZERO);
                b.push(Dd::ZERO);
            }
        }
    }
    b
}

/// Largest residual, each divided by `scale^degree` of its constraint
/// (dimensionless).
pub fn relative_residual(linkage: &Linkage, f: &[Dd]) -> f64 {
    let mut worst = 0.0f64;
    let mut i = 0;
    for c in &linkage.constraints {
        let s = linkage.scale.powi(c.degree());
        for _ in 0..c.rows() {
            worst = worst.max(f[i].to_f64().abs() / s);
            i += 1;
        }
    }
    worst
}

#[cfg(test)]
mod tests {
    use crate::constraint::{Constraint, Linkage, Point, V2};
    use crate::loop_closure::{acceleration, position, velocity};
    use crate::Dd;

    /// One point turned about the origin by `c`.
    fn turned(c: Constraint) -> Linkage {
        Linkage {
            points: vec![Point::Fixed(V2::new(0.0, 0.0)), Point::Unknown],
            constraints: vec![c],
            sides: vec![],
            scale: 1.0,
        }
    }

    /// A geared point turns at `phase + factor q`: its pose, velocity and
    /// acceleration are the circle's at that angle (`r e`, `r a' perp(e)`,
    /// `r a'' perp(e) - r a'^2 e`, written out here), and a geared point of
    /// phase 0 and factor 1 is the crank's, bit for bit.
    #[test]
    fn a_geared_point_turns_in_proportion_to_its_input() {
        let (q, w, al) = (0.7, 3.0, -20.0);
        let (r, phase, factor) = (0.08, 30f64.to_radians(), -2.0);
        let geared = turned(Constraint::Geared {
            p: 1,
            o: 0,
            r,
            input: 0,
            phase,
            factor,
        });
        let d = Dd::from_f64;
        let (qs, ws, als) = ([d(q)], [d(w)], [d(al)]);
        let pose = position(&geared, &qs, &[(0.0, 0.0), (0.05, -0.05)]).expect("solves");
        let v = velocity(&geared, &pose, &qs, &ws).expect("rates");
        let a = acceleration(&geared, &pose, &v, &qs, &ws, &als).expect("accelerations");
        let angle = phase + factor * q;
        let (s, c) = angle.sin_cos();
        let (aw, aal) = (factor * w, factor * al);
        let want = [
            (pose.points[1], r * c, r * s),
            (v[1], -r * aw * s, r * aw * c),
            (
                a[1],
                -r * aal * s - r * aw * aw * c,
                r * aal * c - r * aw * aw * s,
            ),
        ];
        for (got, x, y) in want {
            // f64 arithmetic on the expected side: a few ulp of the largest term.
            let tol = 1e-15 * (1.0 + (r * aw * aw).abs() + (r * aal).abs());
            assert!(
                (got.x.to_f64() - x).abs() <= tol,
                "{} vs {x}",
                got.x.to_f64()
            );
            assert!(
                (got.y.to_f64() - y).abs() <= tol,
                "{} vs {y}",
                got.y.to_f64()
            );
        }
        let crank = turned(Constraint::Crank {
            p: 1,
            o: 0,
            r,
            input: 0,
        });
        let as_crank = turned(Constraint::Geared {
            p: 1,
            o: 0,
            r,
            input: 0,
            phase: 0.0,
            factor: 1.0,
        });
        let pts = [V2::new(0.0, 0.0), V2::new(0.05, 0.06)];
        let vs = [V2::new(0.0, 0.0), V2::new(0.3, -0.2)];
        assert_eq!(
            super::residual(&crank, &pts, &qs),
            super::residual(&as_crank, &pts, &qs)
        );
        assert_eq!(
            super::velocity_rhs(&crank, &qs, &ws),
            super::velocity_rhs(&as_crank, &qs, &ws)
        );
        assert_eq!(
            super::acceleration_rhs(&crank, &vs, &qs, &ws, &als),
            super::acceleration_rhs(&as_crank, &vs, &qs, &ws, &als)
        );
    }
}
