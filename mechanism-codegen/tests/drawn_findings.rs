//! The expansion-time checks find the same things in a drawn definition as
//! in the grouped definition of the same mechanism: a four-bar that cannot
//! close over part of the crank's turn, drawn at a crank angle where it
//! closes, and written with its lengths, give the same message (the group,
//! the input interval where it fails, the reason); the drawn Grashof
//! variant, like the grouped one, gives none. The same for a slotted link
//! (an RPR) whose offset slot loses the block over part of the turn, and a
//! boom cylinder whose declared stroke starts below the boom's reach. Each
//! is fed straight to `expand` (no rustc).

use proc_macro2::{TokenStream, TokenTree};
use std::str::FromStr;

/// The messages of every `compile_error!` in an expansion.
fn errors(stream: TokenStream, out: &mut Vec<String>) {
    let tokens: Vec<TokenTree> = stream.into_iter().collect();
    for (i, t) in tokens.iter().enumerate() {
        match t {
            TokenTree::Ident(id) if id == "compile_error" => {
                if let Some(TokenTree::Group(g)) = tokens.get(i + 2) {
                    let lit = g.stream().to_string();
                    let message = syn::parse_str::<syn::LitStr>(&lit)
                        .map(|l| l.value())
                        .unwrap_or(lit);
                    out.push(message);
                }
            }
            TokenTree::Group(g) => errors(g.stream(), out),
            _ => {}
        }
    }
}

fn messages(body: &str) -> Vec<String> {
    let mut out = Vec::new();
    errors(
        mechanism_codegen::expand(TokenStream::from_str(body).unwrap()),
        &mut out,
    );
    out
}

/// B of the four-bar O2 = (0, 0), O4 = (4, 0), crank 1 at `theta`, coupler
/// `l3`, rocker `l4`, on the left of A -> O4 (f64 closed form).
fn joint_b(theta: f64, l3: f64, l4: f64) -> (f64, f64, f64, f64) {
    let (ax, ay) = (theta.cos(), theta.sin());
    let (dx, dy) = (4.0 - ax, -ay);
    let d = dx.hypot(dy);
    let along = (l3 * l3 - l4 * l4 + d * d) / (2.0 * d);
    let h = (l3 * l3 - along * along).sqrt();
    let (ux, uy) = (dx / d, dy / d);
    (ax, ay, ax + along * ux - h * uy, ay + along * uy + h * ux)
}

/// The four-bar written both ways: drawn at `theta`, and grouped.
fn both(theta: f64, l3: f64, l4: f64) -> (String, String) {
    let (ax, ay, bx, by) = joint_b(theta, l3, l4);
    let drawn = format!(
        "pub M {{
            joints {{ O2 = (0.0, 0.0), O4 = (4.0, 0.0), A = ({ax:e}, {ay:e}), B = ({bx:e}, {by:e}) }}
            links {{ ground = [O2, O4], crank = [O2, A], coupler = [A, B], rocker = [O4, B] }}
            input theta = angle(crank);
        }}"
    );
    let grouped = format!(
        "pub M {{
            let O2 = ground(0.0, 0.0);
            let O4 = ground(4.0, 0.0);
            let A = crank(O2, 1.0, theta) as crank;
            let B = rrr(A, {l3:e}, O4, {l4:e}, left) as (coupler, rocker);
        }}"
    );
    (drawn, grouped)
}

#[test]
fn a_drawn_four_bar_gets_the_grouped_findings() {
    // Proves: coupler 2.5 and rocker 1.2 cannot reach O4 when |A - O4| > 3.7
    // (crank angles around 180 deg); both forms report that one failure, in
    // the same words and numbers. The Grashof variant (coupler 4.2, rocker
    // 1.5) compiles clean both ways.
    let (drawn, grouped) = both(0.3, 2.5, 1.2);
    let (d, g) = (messages(&drawn), messages(&grouped));
    assert_eq!(g.len(), 1, "{g:?}");
    assert!(g[0].contains("cannot assemble group `B`"), "{g:?}");
    eprintln!("{}", g[0]);
    assert_eq!(d, g);
    let (drawn, grouped) = both(0.3, 4.2, 1.5);
    assert_eq!(messages(&grouped), Vec::<String>::new());
    assert_eq!(messages(&drawn), Vec::<String>::new());
}

/// A slotted link written both ways: pivot C = (0, -0.1), crank 0.125
/// about the origin, the block at B in a slot `e` to the left of link 3's
/// axis; drawn at `theta` (the slot's direction `u` from B - C = s u +
/// e perp(u), s > 0), and grouped.
fn both_slotted(theta: f64, e: f64) -> (String, String) {
    let (bx, by) = (0.125 * theta.cos(), 0.125 * theta.sin());
    let (wx, wy) = (bx, by + 0.1);
    let l2 = wx * wx + wy * wy;
    let s = (l2 - e * e).sqrt();
    let (ux, uy) = ((s * wx + e * wy) / l2, (s * wy - e * wx) / l2);
    let (dx, dy) = (0.3 * ux, -0.1 + 0.3 * uy);
    let a = uy.atan2(ux);
    let drawn = format!(
        "pub M {{
            joints {{ A = (0.0, 0.0), C = (0.0, -0.1), B = ({bx:e}, {by:e}), D = ({dx:e}, {dy:e}) }}
            links {{ ground = [A, C], link2 = [A, B], link3 = [C, D] }}
            slider block at B on link3 along {a:e};
            input theta = angle(link2);
        }}"
    );
    let grouped = format!(
        "pub M {{
            let A = ground(0.0, 0.0);
            let C = ground(0.0, -0.1);
            let B = crank(A, 0.125, theta) as link2;
            let block_slide = rpr(B, C, plus, {e:e}) as (block, link3);
            let D = point(link3, from C, 0.3, 0 deg);
        }}"
    );
    (drawn, grouped)
}

#[test]
fn a_drawn_slotted_link_gets_the_grouped_findings() {
    // Proves: a slot 0.05 off the pivot C loses the block where B passes
    // within 0.05 of C (crank angles around 270 deg); the drawn slot (its
    // offset read from the drawing) and the grouped RPR report that one
    // failure in the same words and numbers. Without the offset, both
    // compile clean.
    let (drawn, grouped) = both_slotted(0.4, 0.05);
    let (d, g) = (messages(&drawn), messages(&grouped));
    assert_eq!(g.len(), 1, "{g:?}");
    assert!(
        g[0].contains("cannot assemble group `block_slide`"),
        "{g:?}"
    );
    eprintln!("{}", g[0]);
    assert_eq!(d, g);
    let (drawn, grouped) = both_slotted(0.4, 0.0);
    assert_eq!(messages(&grouped), Vec::<String>::new());
    assert_eq!(messages(&drawn), Vec::<String>::new());
}

#[test]
fn a_drawn_cylinder_gets_the_grouped_findings() {
    // Proves: a boom cylinder whose declared stroke (0.5 to 3.0) starts
    // below what the boom (2.2 from A, B at 1.204 from A) can reach, 0.996,
    // gets the same message drawn (the boom's length and side read from the
    // drawing) as written with `actuator`; a stroke inside the reach gets
    // none either way.
    let body = |drawn: bool, lo: f64| {
        let (c, s) = (2.2 * 0.3f64.cos(), 2.2 * 0.3f64.sin());
        if drawn {
            format!(
                "pub M {{
                    joints {{ A = (0.0, 0.0), B = (0.8, -0.9), C = ({c:e}, {s:e}) }}
                    links {{ ground = [A, B], boom = [A, C] }}
                    cylinder lift from B to C;
                    input len = length(lift);
                    range len = ({lo:e}, 3.0);
                }}"
            )
        } else {
            format!(
                "pub M {{
                    let A = ground(0.0, 0.0);
                    let B = ground(0.8, -0.9);
                    let C = actuator(A, 2.2, B, len, left) as (boom, lift);
                    range len = ({lo:e}, 3.0);
                }}"
            )
        }
    };
    let (d, g) = (messages(&body(true, 0.5)), messages(&body(false, 0.5)));
    assert_eq!(g.len(), 1, "{g:?}");
    assert!(g[0].contains("`C`"), "{g:?}");
    eprintln!("{}", g[0]);
    assert_eq!(d, g);
    assert_eq!(messages(&body(true, 1.9)), Vec::<String>::new());
    assert_eq!(messages(&body(false, 1.9)), Vec::<String>::new());
}

/// The drawn Stephenson III (tests/examples/drawn.rs) with `extra` joints,
/// link lines `links` and the crank pivot `o6`, the input's `range` line.
fn stephenson(extra: &str, links: &str, o6: &str, range: &str) -> String {
    format!(
        "pub S {{
            const phi0 = -28.402242220599071 * pi / 180.0;
            joints {{
                O2 = (0.0, 0.0), O4 = (0.30, 0.0), O6 = {o6},
                C = (0.05 + 0.24 * cos(phi0), 0.42 + 0.24 * sin(phi0)),
                A = (-5.9201362974731851e-2, 5.3807049927811955e-2),
                B = (1.7859606664268302e-1, 1.5893736176674175e-1),
                P = (6.9064856947974249e-3, 1.8845381871298039e-1),
                {extra}
            }}
            links {{ ground = [O2, O4, O6], link6 = [O6, C], coupler = [A, B, P], {links} }}
            input phi = angle(link6);
            {range}
        }}"
    )
}

const SWING: &str = "range phi = (-50.43 deg, -2.64 deg);";
const PIVOT: &str = "(0.05, 0.42)";

#[test]
fn a_mass_centre_drawn_on_a_triad_leg_keeps_the_triad() {
    // Proves: a third joint on a triad's leg that nothing else uses (a mass
    // centre) leaves the leg a binary leg of the triad: the drawing expands
    // without error, where the same drawing with that joint also on another
    // link is not a triad (the decomposition's message), so the rule can
    // fail.
    let legs = "crank2 = [O2, A, G2], rocker = [O4, B, G4], link5 = [C, P, G5],";
    let extra = "G2 = (-0.03, 0.027), G4 = (0.24, 0.08), G5 = (0.09, 0.25),";
    let ok = messages(&stephenson(extra, legs, PIVOT, SWING));
    assert!(ok.is_empty(), "{ok:?}");
    // G2 also carries a dyad (G2 - Q - O4): then crank2 is no binary leg.
    let shared = "crank2 = [O2, A, G2], rocker = [O4, B, G4], link5 = [C, P, G5], e1 = [G2, Q], e2 = [Q, O4],";
    let extra_q = "G2 = (-0.03, 0.027), G4 = (0.24, 0.08), G5 = (0.09, 0.25), Q = (0.2, -0.1),";
    let bad = messages(&stephenson(extra_q, shared, PIVOT, SWING));
    assert!(bad.iter().any(|m| m.contains("not a triad")), "{bad:?}");
}

#[test]
fn a_crank_drawn_below_the_axis_in_front_of_a_triad_is_read_a_turn_away() {
    // Proves: a full-turn crank (default range [0, 360] deg) drawn at -120
    // deg in front of a triad expands without error (the drawn input counts
    // as 240 deg, inside the range), where before the drawing's angle was
    // outside the range checked.
    let o6 = "(0.05 + 0.24 * cos(phi0) + 0.01, 0.42 + 0.24 * sin(phi0) + 0.01 * sqrt(3.0))";
    let legs = "crank2 = [O2, A], rocker = [O4, B], link5 = [C, P],";
    let out = messages(&stephenson("", legs, o6, ""));
    assert!(out.is_empty(), "{out:?}");
}

#[test]
fn a_class_four_group_says_what_is_supported() {
    // Proves: an undecomposable loop's message names what is solved (dyads
    // and the triad) and that a class IV group is not, instead of sending
    // the user to group statements, which do not solve it either.
    let out = messages(
        "pub Class4 {
            joints {
                O1 = (0.0, 0.0), O2 = (3.0, 0.0), A = (0.3, 0.9),
                X = (1.0, 1.6), Y = (0.6, 2.4), Z = (2.4, 1.5), W = (2.2, 2.6),
            }
            links {
                ground = [O1, O2], crank = [O1, A], t1 = [A, X, Y], t2 = [O2, Z, W],
                l1 = [X, Z], l2 = [Y, W],
            }
            input theta = angle(crank);
        }",
    );
    assert_eq!(out.len(), 1, "{out:?}");
    let m = &out[0];
    assert!(
        m.contains("class IV or higher") && m.contains("are not solved"),
        "{m}"
    );
    assert!(m.contains("dyads") && m.contains("the triad"), "{m}");
    assert!(!m.contains("write it with group statements"), "{m}");
}
