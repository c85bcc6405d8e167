//! The language's vocabulary: the statement kinds, how each is written, and
//! how many arguments each takes. Parsing, lowering and the messages of every
//! stage read it from here.

use super::Arg;
use syn::Expr;

/// Every statement kind the language knows, for suggestions.
pub const KINDS: &[&str] = &[
    "ground", "guide", "crank", "slider", "actuator", "target", "rrr", "rrp", "rpr", "prp", "rpp",
    "point", "triad",
];

/// How a statement kind is written (for messages); "" for an unknown kind.
pub fn usage(kind: &str) -> &'static str {
    match kind {
        "ground" => "ground(x, y)",
        "guide" => "guide(POINT or (x, y), angle) or guide(POINT, LINK[, angle])",
        "crank" => "crank(PIVOT, radius, INPUT[, CARRIER[, zero_angle]]) as LINK",
        "slider" => "slider(GUIDE, INPUT[, offset]) as LINK",
        "actuator" => "actuator(A, radius, B, INPUT, left|right) as (LINK, CYLINDER)",
        "target" => "target(X_INPUT, Y_INPUT) as EFFECTOR",
        "rrr" => "rrr(A, l1, B, l2, left|right) as (LINK1, LINK2)",
        "rrp" => "rrp(A, l, GUIDE, plus|minus[, offset]) as (LINK, BLOCK) slide S",
        "rpr" => "let S = rpr(A, B, plus|minus[, offset]) as (BLOCK, LINK)",
        "prp" => "prp(GUIDE1, GUIDE2[, offset1, offset2]) as (LINK1, LINK2) slide (S1, S2)",
        "rpp" => "rpp(A, GUIDE, slot_angle[, offset]) as (BLOCK, LINK) slide (S1, S2)",
        "point" => "point(LINK, from POINT, distance, angle) or point(LINK, from POINT, (x, y))",
        "triad" => "let (A, B, P) = triad(K1, l1, K2, l2, K3, l3, ab, distance, angle, INPUT = value, (ax, ay), (bx, by), (px, py)) as (LEG1, LEG2, LEG3, TERNARY), P's place also `(x, y)`",
        _ => "",
    }
}

/// How many arguments a statement kind takes: the fewest (every optional
/// argument left out) and the most. A `point` takes three in its `(x, y)`
/// form (a tuple third) and four in its polar form; a `guide` two (a fixed
/// guide's origin and angle, or a carried guide's point and link) or three
/// (a carried guide's angle).
pub fn arity(kind: &str, args: &[Arg]) -> Option<(usize, usize)> {
    Some(match kind {
        "ground" => (2, 2),
        "guide" => (2, 3),
        "crank" => (3, 5),
        "slider" => (2, 3),
        "target" => (2, 2),
        "actuator" | "rrr" => (5, 5),
        "rrp" => (4, 5),
        "rpr" => (3, 4),
        "prp" => (2, 4),
        "rpp" => (3, 4),
        "point" => match args.get(2) {
            Some(Arg::Value(Expr::Tuple(_), _)) => (3, 3),
            _ => (4, 4),
        },
        "triad" => match args.get(7) {
            Some(Arg::Value(Expr::Tuple(_), _)) => (12, 12),
            _ => (13, 13),
        },
        _ => return None,
    })
}

/// Drivers other tools call differently, with the word to use here.
pub fn unsupported_driver(kind: &str) -> Option<&'static str> {
    match kind {
        "motor" | "rotary" | "revolute" | "input" | "rocker" => {
            Some("a rotary input is a `crank(PIVOT, radius, INPUT) as LINK`")
        }
        "linear" | "cylinder" | "piston" => {
            Some("a length input is an `actuator(...)`, a translation input a `slider(...)`")
        }
        _ => None,
    }
}

/// The links a statement kind creates, in the order `as` names them, in
/// words (for messages).
pub fn links_created(kind: &str) -> &'static str {
    match kind {
        "crank" => "the crank, turning about its pivot",
        "slider" => "the block, sliding on the guide",
        "actuator" => "the link from A, and the cylinder from B",
        "target" => "the effector, moving with the point and not turning",
        "rrr" => "L1 from A, L2 from B",
        "rrp" => "the link from A, and the block on the guide",
        "rpr" => "the block pinned at A, and the link pivoted at B",
        "prp" => "the block on the first guide, and the block on the second",
        "rpp" => "the block pinned at A, and the slotted link sliding on the guide",
        "triad" => {
            "leg 1 from K1 to A, leg 2 from K2 to B, leg 3 from K3 to P, and the ternary link A-B-P"
        }
        _ => "",
    }
}

/// Where a driver's input names sit among its arguments.
pub fn input_positions(kind: &str) -> &'static [usize] {
    match kind {
        "crank" => &[2],
        "slider" => &[1],
        "actuator" => &[3],
        "target" => &[0, 1],
        _ => &[],
    }
}
