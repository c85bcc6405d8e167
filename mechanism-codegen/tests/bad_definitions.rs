//! Bad definitions, fed straight to the macro logic (`expand`, no rustc): each
//! must give exactly one `compile_error!` (no follow-on errors), without
//! panicking, whose message names the problem (and the fix, where there is
//! one), and whose span starts at the offending user token.
//!
//! Each case marks the token the error must start at with `^` inside its `at`
//! snippet, which must occur exactly once in the source. The source positions
//! come from `proc-macro2`'s `span-locations` (enabled for the tests only).
//!
//! `BAD_DEFS_PRINT=1 cargo test -p mechanism-codegen --test bad_definitions --
//! --nocapture` prints every message.

use proc_macro2::{TokenStream, TokenTree};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::str::FromStr;

/// One bad definition and what its error must be.
struct Case {
    name: &'static str,
    src: String,
    /// A snippet of `src` with `^` before the token the error starts at.
    at: &'static str,
    /// Substrings the message must contain.
    says: &'static [&'static str],
}

/// One `compile_error!` found in the expansion.
#[derive(Debug)]
struct Found {
    message: String,
    line: usize,
    column: usize,
}

fn find_errors(stream: TokenStream, out: &mut Vec<Found>) {
    let tokens: Vec<TokenTree> = stream.into_iter().collect();
    for (i, t) in tokens.iter().enumerate() {
        match t {
            TokenTree::Ident(id) if id == "compile_error" => {
                if let (Some(TokenTree::Punct(bang)), Some(TokenTree::Group(g))) =
                    (tokens.get(i + 1), tokens.get(i + 2))
                {
                    if bang.as_char() == '!' {
                        let lit = g.stream().to_string();
                        let message = syn::parse_str::<syn::LitStr>(&lit)
                            .map(|l| l.value())
                            .unwrap_or(lit);
                        let start = id.span().start();
                        out.push(Found {
                            message,
                            line: start.line,
                            column: start.column,
                        });
                    }
                }
            }
            TokenTree::Group(g) => find_errors(g.stream(), out),
            _ => {}
        }
    }
}

/// Line (1-based) and column (0-based, in characters) of the `^` of `at`.
fn expected_position(src: &str, at: &str) -> Result<(usize, usize), String> {
    let caret = at.find('^').ok_or("`at` has no `^`")?;
    let snippet = at.replace('^', "");
    let hits: Vec<usize> = src.match_indices(&snippet).map(|(i, _)| i).collect();
    if hits.len() != 1 {
        return Err(format!(
            "`at` snippet {snippet:?} occurs {} times",
            hits.len()
        ));
    }
    let offset = hits[0] + caret;
    let before = &src[..offset];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().unwrap_or("").chars().count();
    Ok((line, column))
}

/// The source text from a position to the end of its line (for reports).
fn text_at(src: &str, line: usize, column: usize) -> String {
    src.lines()
        .nth(line.wrapping_sub(1))
        .map(|l| l.chars().skip(column).collect())
        .unwrap_or_default()
}

/// Runs one case; `Err` describes what is wrong.
fn run(case: &Case, print: bool) -> Result<(), String> {
    let tokens = TokenStream::from_str(&case.src).map_err(|e| format!("bad test source: {e}"))?;
    let out = catch_unwind(AssertUnwindSafe(|| mechanism_codegen::expand(tokens)))
        .map_err(|_| "expand panicked".to_string())?;
    let mut found = Vec::new();
    find_errors(out, &mut found);
    if print {
        println!("--- {}", case.name);
        for f in &found {
            println!(
                "  {}:{} `{}`\n    {}",
                f.line,
                f.column,
                text_at(&case.src, f.line, f.column),
                f.message
            );
        }
    }
    let (line, column) = expected_position(&case.src, case.at)?;
    let [f] = found.as_slice() else {
        return Err(format!(
            "{} errors, want 1: {:#?}",
            found.len(),
            found.iter().map(|f| &f.message).collect::<Vec<_>>()
        ));
    };
    let mut problems = Vec::new();
    if (f.line, f.column) != (line, column) {
        problems.push(format!(
            "span at {}:{} `{}`, want {line}:{column} `{}`",
            f.line,
            f.column,
            text_at(&case.src, f.line, f.column),
            text_at(&case.src, line, column)
        ));
    }
    for s in case.says {
        if !f.message.contains(s) {
            problems.push(format!("message lacks {s:?}"));
        }
    }
    if problems.is_empty() {
        Ok(())
    } else {
        Err(format!(
            "{}\n    message: {}",
            problems.join("; "),
            f.message
        ))
    }
}

/// A four-bar, ground 130 and crank 40 long, with coupler and rocker
/// lengths `links` (as written) and `extra` lines appended.
fn four_bar_with(links: (&str, &str), extra: &str) -> String {
    let (coupler, rocker) = links;
    format!(
        "pub M {{
    let O2 = ground(0.0, 0.0);
    let O4 = ground(130.0, 0.0);
    let A = crank(O2, 40.0, theta) as link2;
    let B = rrr(A, {coupler}, O4, {rocker}, left) as (link3, link4);
{extra}
}}"
    )
}

/// A crank-rocker four-bar (Grashof: 40 + 130 < 120 + 100, so the crank turns
/// fully and the expansion-time check passes) with `extra` lines appended.
fn four_bar(extra: &str) -> String {
    four_bar_with(("120.0", "100.0"), extra)
}

/// A four-bar that is not Grashof (crank 40 + ground 130 > 90 + 70): it
/// assembles for `theta` in [-133.05, 133.05] deg.
fn non_grashof(extra: &str) -> String {
    four_bar_with(("90.0", "70.0"), extra)
}

/// The four-bar with a slider-crank beside it: a fixed guide `line`, a coupler
/// point `P` on `link3` and masses, for the force-analysis cases.
fn loaded(extra: &str) -> String {
    four_bar(&format!(
        "    let line = guide((0.0, -50.0), 0 deg);
    let C = rrp(A, 150.0, line, plus) as (rod, ram) slide x;
    let P = point(link3, from A, 60.0, 20 deg);
    mass link3 {{ m = 2.0, at = P, j = 0.1 }};
{extra}"
    ))
}

fn body(text: &str) -> String {
    format!("pub M {{\n{text}\n}}")
}

fn cases() -> Vec<Case> {
    vec![
        // ---- syntax ----
        Case {
            name: "missing semicolon after a let",
            src: body(
                "    let O2 = ground(0.0, 0.0)
    let O4 = ground(130.0, 0.0);
    let A = crank(O2, 40.0, theta) as link2;
    let B = rrr(A, 120.0, O4, 100.0, left) as (link3, link4);",
            ),
            at: "0.0, 0.0^)\n    let O4",
            says: &["expected `;` after the `let O2 = ground(..)` statement"],
        },
        Case {
            name: "missing comma between arguments",
            src: four_bar("    let C = rrr(A 120.0, O4, 100.0, left) as (link5, link6);"),
            at: "rrr(^A 120.0",
            says: &["expected `,` after `A`", "`let C = rrr(..)`"],
        },
        Case {
            name: "comma instead of semicolon",
            src: four_bar("    let Q = ground(1.0, 2.0),"),
            at: "ground(1.0, 2.0)^,",
            says: &["`;`"],
        },
        Case {
            name: "trailing name after the link names",
            src: four_bar("    let D = rrr(B, 50.0, O4, 90.0, left) as (link5, link6) link7;"),
            at: "link6) ^link7",
            says: &["`;`"],
        },
        Case {
            name: "a number where the point name goes",
            src: four_bar("    let 5 = ground(1.0, 2.0);"),
            at: "let ^5 =",
            says: &["name"],
        },
        Case {
            name: "`==` in a let",
            src: four_bar("    let Q == ground(1.0, 2.0);"),
            at: "let Q =^= ground",
            says: &["statement kind", "`let Q =`"],
        },
        Case {
            name: "brackets instead of parentheses",
            src: four_bar("    let Q = ground[1.0, 2.0];"),
            at: "ground^[",
            says: &["(", ")"],
        },
        Case {
            name: "no parentheses",
            src: four_bar("    let Q = ground 1.0, 2.0;"),
            at: "ground ^1.0",
            says: &["("],
        },
        Case {
            name: "statement kind capitalized",
            src: four_bar("    let D = Crank(O4, 30.0, phi) as link5;"),
            at: "let D = ^Crank",
            says: &["unknown statement kind `Crank`", "did you mean `crank`?"],
        },
        Case {
            name: "statement kind misspelled",
            src: four_bar("    let D = rpp_(A, line, 0 deg);"),
            at: "let D = ^rpp_",
            says: &["unknown statement kind", "did you mean `rpp`?"],
        },
        Case {
            name: "unknown item keyword",
            src: four_bar("    joint A;"),
            at: "^joint A",
            says: &["unknown statement `joint`"],
        },
        Case {
            name: "item keyword misspelled",
            src: four_bar("    output { B }"),
            at: "^output {",
            says: &["unknown statement `output`", "did you mean `outputs`?"],
        },
        Case {
            name: "a Rust item inside the definition",
            src: four_bar("    fn helper() {}"),
            at: "^fn helper",
            says: &["expected a statement"],
        },
        Case {
            name: "`deg` on a link length",
            src: four_bar("    let D = rrr(B, 50.0 deg, O4, 90.0, left) as (link5, link6);"),
            at: "50.0 ^deg",
            says: &["length", "no unit"],
        },
        Case {
            name: "unknown unit on a length",
            src: four_bar("    let D = rrr(B, 50.0 mm, O4, 90.0, left) as (link5, link6);"),
            at: "50.0 ^mm",
            says: &["length", "no unit"],
        },
        Case {
            name: "unknown angle unit",
            src: four_bar("    let P = point(link3, from A, 10.0, 30 grad);"),
            at: "30 ^grad",
            says: &["`deg` or `rad`"],
        },
        Case {
            name: "param without a default",
            src: four_bar("    params { a = 1.0, b }"),
            at: "a = 1.0, b ^}",
            says: &["`b`", "default", "`b = "],
        },
        Case {
            name: "params separated by semicolons",
            src: four_bar("    params { a = 1.0; b = 2.0 }"),
            at: "a = 1.0^;",
            says: &["`,`"],
        },
        Case {
            name: "const with a type",
            src: four_bar("    const k: f64 = 1.0;"),
            at: "const k^:",
            says: &["no type", "`const k = value;`"],
        },
        Case {
            name: "const using a later const",
            src: four_bar("    const a = b * 2.0;\n    const b = 1.0;"),
            at: "const a = ^b",
            says: &["`b`", "before"],
        },
        Case {
            name: "division by a zero const",
            src: four_bar("    const zero = 0.0;\n    const k = 10.0 / zero;"),
            at: "const k = ^10.0",
            says: &["finite", "zero"],
        },
        Case {
            name: "NaN from 0/0 as a coordinate",
            src: four_bar("    let Q = ground(0.0 / 0.0, 1.0);"),
            at: "ground(^0.0 / 0.0",
            says: &["finite"],
        },
        Case {
            name: "huge literal (overflows to infinity) as a coordinate",
            src: four_bar("    let Q = ground(1e400, 1.0);"),
            at: "ground(^1e400",
            says: &["finite"],
        },
        Case {
            name: "huge literal as a length",
            src: four_bar("    let D = rrr(B, 1e999, O4, 90.0, left) as (link5, link6);"),
            at: "(B, ^1e999",
            says: &["finite"],
        },
        Case {
            name: "huge literal as a parameter default",
            src: four_bar("    params { a = 1e400 }"),
            at: "a = ^1e400",
            says: &["finite"],
        },
        Case {
            name: "outputs without braces",
            src: four_bar("    outputs B, A;"),
            at: "outputs ^B",
            says: &["{"],
        },
        Case {
            name: "gravity with three components",
            src: loaded("    gravity (0.0, -9.81, 0.0);"),
            at: "-9.81^, 0.0)",
            says: &["(gx, gy)"],
        },
        Case {
            name: "force with three components",
            src: loaded("    force at P = (1.0, 2.0, 3.0);"),
            at: "2.0^, 3.0)",
            says: &["(fx, fy)"],
        },
        Case {
            name: "point with three coordinates",
            src: four_bar("    let P = point(link3, from A, (1.0, 2.0, 3.0));"),
            at: "from A, ^(1.0",
            says: &["(x, y)"],
        },
        Case {
            name: "guide origin with three coordinates",
            src: four_bar("    let g = guide((1.0, 2.0, 3.0), 0 deg);"),
            at: "guide(^(1.0",
            says: &["(x, y)"],
        },
        Case {
            name: "dof negative",
            src: four_bar("    dof -1;"),
            at: "dof ^-1",
            says: &["positive integer", "not `-1`"],
        },
        Case {
            name: "unknown attribute",
            src: "#[selftest]\n".to_string() + &four_bar(""),
            at: "^#[selftest]",
            says: &["selftest", "did you mean `self_test`?"],
        },
        Case {
            name: "missing type name",
            src: "pub { let O = ground(0.0, 0.0); }".to_string(),
            at: "pub ^{",
            says: &["type name"],
        },
        // ---- a missing `;` or `,`: on the end of what lacks it ----
        Case {
            name: "missing semicolon after the last statement",
            src: four_bar("    let Q = ground(1.0, 2.0)"),
            at: "ground(1.0, 2.0^)",
            says: &["expected `;` after the `let Q = ground(..)` statement"],
        },
        Case {
            name: "missing semicolon after the link names",
            src: four_bar("    let D = rrr(B, 50.0, O4, 90.0, left) as (link5, link6)\n    let E = ground(1.0, 2.0);"),
            at: "(link5, link6^)",
            says: &["expected `;` after the `let D = rrr(..)` statement"],
        },
        Case {
            name: "missing semicolon after a const",
            src: four_bar("    const k = 2.0\n    let Q = ground(k, 1.0);"),
            at: "k = ^2.0\n",
            says: &["expected `;` after the `const k = ..` statement"],
        },
        Case {
            name: "missing semicolon after a torque",
            src: loaded("    torque on link3 = 5.0\n    gravity (0.0, -9.81);"),
            at: "link3 = ^5.0",
            says: &["expected `;` after the `torque on link3 = ..` statement"],
        },
        Case {
            name: "missing comma between parameters",
            src: four_bar("    params { a = 1.0 b = 2.0 }"),
            at: "a = ^1.0 b",
            says: &["expected `,` after `a = 1.0`", "`params { .. }`"],
        },
        Case {
            name: "missing comma between outputs",
            src: four_bar("    outputs { B A }"),
            at: "{ ^B A }",
            says: &["expected `,` after `B`", "`outputs { .. }`"],
        },
        Case {
            name: "missing comma between mass fields",
            src: loaded("    mass link4 { m = 1.0 at = B };"),
            at: "m = ^1.0 at",
            says: &["expected `,` after `m = 1.0`", "`mass link4 { .. }`"],
        },
        Case {
            name: "missing comma between link names",
            src: four_bar("    let D = rrr(B, 50.0, O4, 90.0, left) as (link5 link6);"),
            at: "(^link5 link6)",
            says: &["expected `,` after `link5`", "`as`"],
        },
        Case {
            name: "missing comma between force components",
            src: loaded("    force at P = (1.0 2.0);"),
            at: "(^1.0 2.0)",
            says: &["expected `,` after `1.0`", "(fx, fy)"],
        },
        Case {
            name: "missing comma between the ends of a range",
            src: four_bar("    range theta = (0 deg 90 deg);"),
            at: "(0 ^deg 90",
            says: &["expected `,` after `0 deg`"],
        },
        Case {
            name: "semicolon between arguments",
            src: four_bar("    let Q = ground(1.0; 2.0);"),
            at: "1.0^; 2.0",
            says: &["expected `,`", "found `;`"],
        },
        Case {
            name: "link name without `as`",
            src: four_bar("    let D = crank(O4, 30.0, phi) link5;"),
            at: "phi) ^link5",
            says: &["`;`", "write `as link5`"],
        },
        Case {
            name: "let without `=`",
            src: four_bar("    let Q ground(1.0, 2.0);"),
            at: "let Q ^ground",
            says: &["expected `=` after `let Q`", "`let Q = KIND(args);`"],
        },
        Case {
            name: "torque without `=`",
            src: loaded("    torque on link3 5.0;"),
            at: "link3 ^5.0",
            says: &["expected `=` after `torque on link3`", "`torque on LINK = value;`"],
        },
        Case {
            name: "analysis without what",
            src: four_bar("    analysis;"),
            at: "analysis^;",
            says: &["after `analysis`", "`velocity`"],
        },
        Case {
            name: "mass without braces",
            src: loaded("    mass link4 m = 1.0;"),
            at: "link4 ^m",
            says: &["expected `{` after `mass link4`"],
        },
        Case {
            name: "statements without braces",
            src: "pub M let O = ground(0.0, 0.0);".to_string(),
            at: "M ^let",
            says: &["expected `{` after `M`"],
        },
        Case {
            name: "a second definition in one macro",
            src: four_bar("") + "\npub N { }",
            at: "^pub N",
            says: &["one definition"],
        },
        // ---- a unit where none is taken ----
        Case {
            name: "unit after a torque other than an angle's",
            src: loaded("    torque on link3 = 5.0 Nm;"),
            at: "5.0 ^Nm",
            says: &["`Nm`", "a torque takes no unit", "N m"],
        },
        Case {
            name: "unit after a force along a guide",
            src: loaded("    force at C on ram along line = 5.0 N;"),
            at: "5.0 ^N;",
            says: &["`N`", "a force takes no unit"],
        },
        Case {
            name: "unit on a force component",
            src: loaded("    force at P = (10.0 N, 0.0);"),
            at: "10.0 ^N,",
            says: &["`N`", "a force component takes no unit"],
        },
        Case {
            name: "unit on a gravity component",
            src: loaded("    gravity (0.0, -9.81 m);"),
            at: "-9.81 ^m)",
            says: &["`m`", "a gravity component takes no unit"],
        },
        Case {
            name: "angle unit on a const",
            src: four_bar("    const a = 30.0 deg;"),
            at: "30.0 ^deg",
            says: &["a constant takes no unit", "`a deg`"],
        },
        Case {
            name: "angle unit on a parameter",
            src: four_bar("    params { a = 30.0 deg, b = 1.0 }"),
            at: "30.0 ^deg",
            says: &["a parameter takes no unit", "`a deg`"],
        },
        Case {
            name: "unit on a load value",
            src: loaded("    loads { cut = 5.0 N }\n    force at P = (cut, 0.0);"),
            at: "5.0 ^N }",
            says: &["a load value takes no unit"],
        },
        Case {
            name: "unit after a range's parentheses",
            src: four_bar("    range theta = (0, 90) deg;"),
            at: "90) ^deg",
            says: &["each end takes its own unit"],
        },
        // ---- dof ----
        Case {
            name: "dof zero",
            src: four_bar("    dof 0;"),
            at: "dof ^0",
            says: &["positive integer", "not `0`"],
        },
        Case {
            name: "dof fractional",
            src: four_bar("    dof 1.5;"),
            at: "dof ^1.5",
            says: &["positive integer", "not `1.5`"],
        },
        Case {
            name: "dof a name",
            src: four_bar("    dof x;"),
            at: "dof ^x",
            says: &["positive integer", "not `x`"],
        },
        Case {
            name: "dof missing its semicolon",
            src: four_bar("    dof 1\n    range theta = (0 deg, 90 deg);"),
            at: "dof ^1\n",
            says: &["expected `;` after the `dof 1` statement"],
        },
        // ---- defined twice: where the first one is ----
        Case {
            name: "a point defined twice",
            src: four_bar("    let B = ground(1.0, 2.0);"),
            at: "let ^B = ground(1.0",
            says: &["`B` is already defined by the `let B = rrr(..)` statement above"],
        },
        Case {
            name: "a link named twice in two statements",
            src: four_bar("    let D = crank(O4, 30.0, phi) as link3;"),
            at: "as ^link3;",
            says: &["`link3` is already defined as a link of the `let B = rrr(..)` statement above"],
        },
        Case {
            name: "a point named like a parameter",
            src: four_bar("    params { O2 = 1.0 }"),
            at: "let ^O2 = ground",
            says: &["`O2` is already defined as a parameter"],
        },
        Case {
            name: "a load named like a point",
            src: loaded("    loads { P = 0.0 }"),
            at: "loads { ^P",
            says: &["`P` is already defined by the `let P = point(..)` statement"],
        },
        // ---- statements given twice ----
        Case {
            name: "duplicate outputs entry",
            src: four_bar("    outputs { B, A, B }"),
            at: "A, ^B }",
            says: &["`B`", "twice"],
        },
        Case {
            name: "two outputs statements",
            src: four_bar("    outputs { B }\n    outputs { A }"),
            at: "^outputs { A }",
            says: &["outputs", "once", "the first is `outputs { B }`"],
        },
        Case {
            name: "two analysis statements",
            src: four_bar("    analysis position;\n    analysis velocity;"),
            at: "^analysis velocity",
            says: &["analysis", "once", "the first is `analysis position;`"],
        },
        Case {
            name: "two dof statements",
            src: four_bar("    dof 1;\n    dof 1;"),
            at: "^dof 1;\n}",
            says: &["dof", "once"],
        },
        Case {
            name: "two dof statements, the second wrong",
            src: four_bar("    dof 1;\n    dof 2;"),
            at: "^dof 2",
            says: &["dof", "once", "the first is `dof 1;`"],
        },
        Case {
            name: "a group's own link named like its known joint",
            src: four_bar("    let D = rrr(A, 50.0, O4, 90.0, left) as (A, link6);"),
            at: "as (^A, link6)",
            says: &["`A` is already defined by the `let A = crank(..)` statement above"],
        },
        Case {
            name: "gravity twice",
            src: loaded("    gravity (0.0, -9.81);\n    gravity (0.0, -9.80);"),
            at: "^gravity (0.0, -9.80)",
            says: &["gravity", "once", "the first is `gravity (0.0, -9.81);`"],
        },
        Case {
            name: "mass field given twice",
            src: four_bar("    mass link4 { m = 1.0, at = B, m = 2.0 }"),
            at: "at = B, ^m = 2.0",
            says: &["`m`", "twice"],
        },
        // ---- names and categories ----
        Case {
            name: "empty definition",
            src: "pub M {}".to_string(),
            at: "pub ^M",
            says: &["no driver"],
        },
        Case {
            name: "outputs naming a guide",
            src: loaded("    outputs { line }"),
            at: "outputs { ^line",
            says: &["guide"],
        },
        Case {
            name: "outputs naming an undefined point",
            src: four_bar("    outputs { Bb }"),
            at: "outputs { ^Bb",
            says: &["`Bb`", "did you mean `B`?"],
        },
        Case {
            name: "driver input used as a dimension",
            src: four_bar("    let D = rrr(B, theta, O4, 90.0, left) as (link5, link6);"),
            at: "rrr(B, ^theta",
            says: &["`theta`", "input"],
        },
        Case {
            name: "slide used as a dimension",
            src: loaded("    let D = rrr(B, x, O4, 90.0, left) as (link5, link6);"),
            at: "rrr(B, ^x",
            says: &["`x`", "slide"],
        },
        Case {
            name: "crank pivot is a moving point",
            src: four_bar("    let D = crank(B, 30.0, phi) as link5;"),
            at: "crank(^B",
            says: &["ground"],
        },
        Case {
            name: "point from a point not on the link",
            src: four_bar("    let P = point(link2, from B, 10.0, 0 deg);"),
            at: "from ^B, 10.0",
            says: &["not a point of `link2`"],
        },
        Case {
            name: "guide carried by an undefined link",
            src: four_bar("    let g = guide(A, link9);"),
            at: "guide(A, ^link9",
            says: &["link9"],
        },
        Case {
            name: "link named after a point",
            src: four_bar("    let D = crank(O4, 30.0, phi) as A;"),
            at: "as ^A;",
            says: &["`A` is already defined by the `let A = crank(..)` statement above"],
        },
        Case {
            name: "same link named twice in one statement",
            src: four_bar("    let D = rrr(B, 50.0, O4, 90.0, left) as (link5, link5);"),
            at: "(link5, ^link5)",
            says: &["`link5` is already defined as a link of this statement"],
        },
        Case {
            name: "input named like a parameter",
            src: four_bar("    params { theta = 1.0 }"),
            at: "crank(O2, 40.0, ^theta)",
            says: &["`theta` is already defined as a parameter"],
        },
        // ---- force analysis ----
        Case {
            name: "mass on an undefined link",
            src: loaded("    mass lnk4 { m = 1.0, at = B };"),
            at: "mass ^lnk4",
            says: &["`lnk4`", "did you mean `link4`?"],
        },
        Case {
            name: "mass at a point not on the link",
            src: loaded("    mass link4 { m = 1.0, at = A };"),
            at: "at = ^A };",
            says: &["not", "`B`"],
        },
        Case {
            name: "force along a point",
            src: loaded("    force at C on ram along P = 1.0;"),
            at: "along ^P",
            says: &["`P` is a point", "guide"],
        },
        Case {
            name: "force along the drawn block's line by its short name",
            src: body(
                "    joints { O = (0.0, 0.0), A = (1.0, 0.0), B = (4.0, 0.5) }
    links { ground = [O], crank = [O, A], rod = [A, B] }
    slider ram at B on ground along 0 deg;
    input theta = angle(crank);
    mass rod { m = 1.0, at = B };
    force at B on ram along line = 1.0;",
            ),
            at: "along ^line",
            says: &["cannot find guide `line`", "did you mean `ram_line`?"],
        },
        Case {
            name: "force along an unknown guide lists the guides",
            src: loaded("    force at C on ram along slideway = 1.0;"),
            at: "along ^slideway",
            says: &["cannot find guide `slideway`", "the guides are `line`"],
        },
        Case {
            name: "a drawn mode on a joint a crank places",
            src: body(
                "    joints { O2 = (0.0, 0.0), O4 = (4.0, 0.0), A = (0.5, 0.9), B = (3.2, 2.1) }
    links { ground = [O2, O4], crank = [O2, A], coupler = [A, B], rocker = [O4, B] }
    input theta = angle(crank);
    mode m = assembly(A);",
            ),
            at: "assembly(^A)",
            says: &["`A` is placed by a `crank`", "single assembly"],
        },
        Case {
            name: "a drawn mode on an unknown joint",
            src: body(
                "    joints { O2 = (0.0, 0.0), O4 = (4.0, 0.0), A = (0.5, 0.9), B = (3.2, 2.1) }
    links { ground = [O2, O4], crank = [O2, A], coupler = [A, B], rocker = [O4, B] }
    input theta = angle(crank);
    mode m = assembly(Bx);",
            ),
            at: "assembly(^Bx)",
            says: &["`Bx` is no joint or block of the drawing", "did you mean `B`?"],
        },
        Case {
            name: "a drawn mode without a drawing",
            src: four_bar("    mode m = assembly(B);"),
            at: "mode ^m",
            says: &["belongs to the drawn form", "params { m = left }"],
        },
        Case {
            name: "two drawn modes on one joint",
            src: body(
                "    joints { O2 = (0.0, 0.0), O4 = (4.0, 0.0), A = (0.5, 0.9), B = (3.2, 2.1) }
    links { ground = [O2, O4], crank = [O2, A], coupler = [A, B], rocker = [O4, B] }
    input theta = angle(crank);
    mode m = assembly(B);
    mode n = assembly(B);",
            ),
            at: "n = assembly(^B)",
            says: &["already the mode parameter of another `mode` statement"],
        },
        Case {
            name: "torque on the ground",
            src: loaded("    torque on ground = 1.0;"),
            at: "torque on ^ground",
            says: &["ground"],
        },
        Case {
            name: "torque on a point",
            src: loaded("    torque on O4 = 1.0;"),
            at: "torque on ^O4",
            says: &["`O4` is not a link"],
        },
        Case {
            name: "force at an undefined point",
            src: loaded("    force at Pp = (1.0, 0.0);"),
            at: "force at ^Pp",
            says: &["`Pp`", "did you mean `P`?"],
        },
        Case {
            name: "load used as a dimension",
            src: loaded("    loads { cut = 0.0 }\n    let D = rrr(B, cut, O4, 90.0, left) as (link5, link6);"),
            at: "rrr(B, ^cut",
            says: &["load"],
        },
        // ---- checks ----
        Case {
            name: "range for a non-input",
            src: four_bar("    range B = (0 deg, 90 deg);"),
            at: "range ^B",
            says: &["not a driver input"],
        },
        Case {
            name: "range with lo > hi",
            src: four_bar("    range theta = (90 deg, 10 deg);"),
            at: "90 deg, ^10 deg",
            says: &["empty"],
        },
        Case {
            name: "range with lo == hi",
            src: four_bar("    range theta = (10 deg, 10 deg);"),
            at: "10 deg, ^10 deg",
            says: &["empty"],
        },
        // A declared range the non-Grashof four-bar (assembles for theta in
        // [-133.05, 133.05] deg) cannot follow: the error points at the end
        // it fails at, at the input when it fails inside, at the group when
        // it assembles nowhere in the range.
        Case {
            name: "declared range past the upper limit",
            src: non_grashof("    range theta = (90 deg, 150 deg);"),
            at: "(90 deg, ^150 deg)",
            says: &["cannot assemble group `B`", "narrow the declared range"],
        },
        Case {
            name: "declared range past the lower limit",
            src: non_grashof("    range theta = (-150 deg, 0 deg);"),
            at: "(-^150 deg, 0 deg)",
            says: &["cannot assemble group `B`", "narrow the declared range"],
        },
        Case {
            name: "declared range failing inside",
            src: non_grashof("    range theta = (90 deg, 270 deg);"),
            at: "range ^theta",
            says: &["cannot assemble group `B`", "narrow the declared range"],
        },
        Case {
            name: "declared range where the group assembles nowhere",
            src: non_grashof("    range theta = (140 deg, 220 deg);"),
            at: "let ^B = rrr",
            says: &["cannot assemble group `B`", "nowhere"],
        },
        Case {
            name: "allow singular of an unknown group",
            src: four_bar("    allow singular Bx;"),
            at: "singular ^Bx",
            says: &["`Bx`", "did you mean `B`?"],
        },
        Case {
            name: "dof mismatch",
            src: four_bar("    dof 2;"),
            at: "dof ^2",
            says: &["Gruebler"],
        },
        Case {
            name: "zero-length link",
            src: four_bar("    let D = rrr(B, 0.0, O4, 90.0, left) as (link5, link6);"),
            at: "rrr(B, ^0.0",
            says: &["positive"],
        },
        Case {
            name: "rpr whose two points coincide",
            src: four_bar("    let O5 = ground(0.0, 0.0);\n    let s = rpr(O2, O5, plus) as (blk, rocker);"),
            at: "rpr(O2, ^O5",
            says: &["`O2`", "`O5`"],
        },
        Case {
            name: "rrr with one point twice",
            src: four_bar("    let D = rrr(B, 50.0, B, 90.0, left) as (link5, link6);"),
            at: "50.0, ^B, 90.0",
            says: &["`B`", "twice"],
        },
        Case {
            name: "prp on one guide twice",
            src: four_bar("    let g = guide(O4, 90 deg);\n    let D = prp(g, g) as (b1, b2) slide (s1, s2);"),
            at: "prp(g, ^g)",
            says: &["`g`", "twice"],
        },
        // ---- more ----
        Case {
            name: "range bound too large",
            src: four_bar("    range theta = (0 deg, 1e400 deg);"),
            at: "0 deg, ^1e400",
            says: &["finite"],
        },
        Case {
            name: "gravity divided by zero",
            src: loaded("    gravity (0.0, 1.0 / 0.0);"),
            at: "gravity (0.0, ^1.0 / 0.0)",
            says: &["division by zero"],
        },
        Case {
            name: "force too large",
            src: loaded("    force at P = (1e400, 0.0);"),
            at: "(^1e400, 0.0)",
            says: &["finite"],
        },
        Case {
            name: "link name on a point statement",
            src: four_bar("    let P = point(link3, from A, 1.0, 0 deg) as link9;"),
            at: "as ^link9",
            says: &["`point`", "no link"],
        },
        Case {
            name: "unit after a torque",
            src: loaded("    torque on link3 = 5.0 deg;"),
            at: "5.0 ^deg",
            says: &["`deg`", "a torque takes no unit", "angles"],
        },
        Case {
            name: "guide with an extra argument",
            src: four_bar("    let g = guide(O4, 90 deg, 10.0);"),
            at: "90 deg, ^10.0",
            says: &["too many arguments", "guide("],
        },
        Case {
            name: "load named like a parameter",
            src: loaded("    params { cut = 1.0 }\n    loads { cut = 0.0 }\n    force at P = (cut, 0.0);"),
            at: "loads { ^cut",
            says: &["`cut` is already defined as a parameter"],
        },
        Case {
            name: "slider on a misspelled guide",
            src: loaded("    let S = slider(lin, y) as blk;"),
            at: "slider(^lin",
            says: &["did you mean `line`?"],
        },
        Case {
            name: "force on a misspelled link",
            src: loaded("    force at P on lnk3 = (1.0, 0.0);"),
            at: "on ^lnk3",
            says: &["did you mean `link3`?"],
        },
        Case {
            name: "self_test twice",
            src: "#[self_test]\n#[self_test]\n".to_string() + &four_bar(""),
            at: "#[self_test]\n^#[self_test]",
            says: &["self_test", "once"],
        },
        Case {
            name: "range more than a turn",
            src: four_bar("    range theta = (0 deg, 400 deg);"),
            at: "0 deg, ^400 deg",
            says: &["turn"],
        },
        Case {
            name: "raw identifier as a point",
            src: four_bar("    let r#type = point(link3, from A, 10.0, 0 deg);"),
            at: "let ^r#type",
            says: &["raw identifiers", "type_"],
        },
        Case {
            name: "raw identifier as a link",
            src: four_bar("    let D = crank(O4, 30.0, phi) as r#struct;"),
            at: "as ^r#struct",
            says: &["raw identifiers", "struct_"],
        },
        Case {
            name: "a point named T",
            src: four_bar("    let T = point(link3, from A, 10.0, 0 deg);"),
            at: "let ^T",
            says: &["scalar parameter"],
        },
        Case {
            name: "empty outputs",
            src: four_bar("    outputs { }"),
            at: "^outputs { }",
            says: &["lists nothing", "no force analysis"],
        },
        Case {
            name: "crank radius with a unit of angle",
            src: four_bar("    let D = crank(O4, 30.0 deg, phi) as link5;"),
            at: "30.0 ^deg",
            says: &["length", "no unit"],
        },
        Case {
            name: "two cranks with one input",
            src: four_bar("    let D = crank(O4, 30.0, theta) as link5;"),
            at: "crank(O4, 30.0, ^theta)",
            says: &["`theta` is already defined as the input of the `let A = crank(..)` statement above"],
        },
        // ---- arity and link names (review 9) ----
        Case {
            name: "rrr without its second length",
            src: four_bar("    let C = rrr(B, 50.0, O4, left) as (link5, link6);"),
            at: "rrr^(B, 50.0, O4, left)",
            says: &[
                "missing argument(s) for `rrr`: 4 given, it takes 5",
                "usage: `rrr(A, l1, B, l2, left|right)",
            ],
        },
        Case {
            name: "crank without its radius",
            src: four_bar("    let D = crank(O4, phi) as link5;"),
            at: "crank^(O4, phi)",
            says: &["missing argument(s) for `crank`: 2 given, it takes at least 3"],
        },
        Case {
            name: "point without its angle",
            src: four_bar("    let P = point(link3, from A, 10.0);"),
            at: "point^(link3, from A, 10.0)",
            says: &["missing argument(s) for `point`", "(x, y)"],
        },
        Case {
            name: "rrp without its mode",
            src: four_bar("    let g = guide(O2, 0 deg);\n    let C = rrp(B, 50.0, g) as (rod, ram);"),
            at: "rrp^(B, 50.0, g)",
            says: &["missing argument(s) for `rrp`: 3 given, it takes at least 4"],
        },
        Case {
            name: "rrr named by one name",
            src: four_bar("    let C = rrr(B, 50.0, O4, 90.0, left) as link5;"),
            at: "as ^link5",
            says: &["`rrr` creates two links (L1 from A, L2 from B): name both, `as (link5, link6)`"],
        },
        Case {
            name: "rpp named by one name",
            src: four_bar("    let g = guide(O2, 0 deg);\n    let C = rpp(B, g, 90 deg) as (blk);"),
            at: "as (^blk)",
            says: &["`rpp` creates two links", "`as (blk, blk2)`"],
        },
        Case {
            name: "rrr named by three names",
            src: four_bar("    let C = rrr(B, 50.0, O4, 90.0, left) as (link5, link6, link7);"),
            at: "link6, ^link7",
            says: &["creates two links", "3 names are given", "`as (link5, link6)`"],
        },
        Case {
            name: "mass on a link of a statement without `as`",
            src: body(
                "    let O2 = ground(0.0, 0.0);
    let O4 = ground(130.0, 0.0);
    let A = crank(O2, 40.0, theta);
    let B = rrr(A, 120.0, O4, 100.0, left);
    mass link3 { m = 1.0, at = B };",
            ),
            at: "mass ^link3",
            says: &[
                "cannot find link `link3`",
                "`let A = crank(..)` and `let B = rrr(..)` have no `as`",
                "`let B = rrr(..) as (LINK1, LINK2)`",
            ],
        },
        Case {
            name: "point on a link of a statement without `as`",
            src: body(
                "    let O2 = ground(0.0, 0.0);
    let O4 = ground(130.0, 0.0);
    let A = crank(O2, 40.0, theta) as link2;
    let B = rrr(A, 120.0, O4, 100.0, left);
    let P = point(link3, from A, 10.0, 0 deg);",
            ),
            at: "point(^link3",
            says: &[
                "no link named `link3`; did you mean `link2`? Or",
                "`let B = rrr(..)` has no `as`",
            ],
        },
        Case {
            name: "mass at an undefined point",
            src: loaded("    mass link4 { m = 1.0, at = Bb };"),
            at: "at = ^Bb",
            says: &["cannot find point `Bb`; did you mean `B`?"],
        },
        Case {
            name: "force at a guide",
            src: loaded("    force at line = (1.0, 0.0);"),
            at: "force at ^line",
            says: &["`line` is a guide, not a point"],
        },
        Case {
            name: "misspelled load value in a force",
            src: loaded("    loads { cut = 0.0 }\n    force at P = (cutt, 0.0);"),
            at: "(^cutt, 0.0)",
            says: &["`cutt`", "did you mean `cut`?"],
        },
        Case {
            name: "rpp slot parallel to its guide",
            src: four_bar("    let g = guide(O2, 0 deg);\n    let C = rpp(B, g, 180 deg) as (blk, body) slide (s1, s2);"),
            at: "g, ^180 deg",
            says: &["at 180 deg to guide `g`", "parallel at every pose", "`90 deg`"],
        },
        Case {
            name: "prp whose guides are parallel at every pose",
            src: body(
                "    let O = ground(0.0, 0.0);
    let g = guide(O, 0 deg);
    let S = slider(g, x) as blk;
    let g2 = guide(S, blk, 0 deg);
    let h = guide((0.0, 1.0), 0 deg);
    let C = prp(g2, h) as (l1, l2) slide (s1, s2);
    range x = (0.0, 1.0);",
            ),
            at: "let ^C = prp",
            says: &["guides `g2` and `h` are parallel at every pose", "make the guides cross"],
        },
    ]
}

#[test]
fn bad_definitions_give_one_error_on_the_users_token() {
    let print = std::env::var_os("BAD_DEFS_PRINT").is_some();
    let cases = cases();
    let mut failures = Vec::new();
    for case in &cases {
        if let Err(e) = run(case, print) {
            failures.push(format!("{}: {e}", case.name));
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} cases fail:\n{}",
        failures.len(),
        cases.len(),
        failures.join("\n")
    );
}
