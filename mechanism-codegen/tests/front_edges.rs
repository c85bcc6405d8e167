//! The front end at its edges, fed straight to `expand` (no rustc): each
//! case once panicked the macro, produced output that does not parse, let a
//! bad definition through, or put an error at the whole invocation. Every
//! case must now give `compile_error!`s only (no panic), each starting at the
//! user's token named in the case, with a message that says what to write.
//! Positions come from `proc-macro2`'s `span-locations` (tests only).

use proc_macro2::{TokenStream, TokenTree};
use std::panic::{catch_unwind, AssertUnwindSafe};

/// `(message, line, column)` of each `compile_error!` in `out`.
fn errors(out: TokenStream, found: &mut Vec<(String, usize, usize)>) {
    let trees: Vec<TokenTree> = out.into_iter().collect();
    for (k, t) in trees.iter().enumerate() {
        match t {
            TokenTree::Ident(i) if i == "compile_error" => {
                let message = trees.get(k + 2).map(|g| g.to_string()).unwrap_or_default();
                let at = i.span().start();
                found.push((message, at.line, at.column));
            }
            TokenTree::Group(g) => errors(g.stream(), found),
            _ => {}
        }
    }
}

/// Expands `src` (in a thread with `stack` bytes) and returns its errors.
fn expand_in(src: &str, stack: usize) -> Vec<(String, usize, usize)> {
    let src = src.to_string();
    std::thread::Builder::new()
        .stack_size(stack)
        .spawn(move || {
            let input: TokenStream = src.parse().expect("a token stream");
            let out = catch_unwind(AssertUnwindSafe(|| mechanism_codegen::expand(input)))
                .unwrap_or_else(|_| panic!("the macro panicked on:\n{src}"));
            syn::parse2::<syn::File>(out.clone()).expect("the output parses as Rust items");
            let mut found = Vec::new();
            errors(out, &mut found);
            found
        })
        .expect("spawn")
        .join()
        .expect("no panic")
}

fn expand(src: &str) -> Vec<(String, usize, usize)> {
    expand_in(src, 64 << 20)
}

/// Asserts exactly one error, starting at the first occurrence of `at` in
/// `src`, whose message contains each of `says`.
fn one_error_at(src: &str, at: &str, says: &[&str]) {
    let found = expand(src);
    assert_eq!(
        found.len(),
        1,
        "expected one error for\n{src}\ngot {found:#?}"
    );
    let (message, line, column) = &found[0];
    let offset = src
        .find(at)
        .unwrap_or_else(|| panic!("`{at}` not in the source"));
    let before = &src[..offset];
    let want = (
        before.matches('\n').count() + 1,
        before.rsplit('\n').next().unwrap_or("").chars().count(),
    );
    assert_eq!(
        (*line, *column),
        want,
        "error {message} not at `{at}` in\n{src}"
    );
    for s in says {
        assert!(message.contains(s), "message {message} lacks {s:?}");
    }
}

/// A slider-crank with one parameter `r` and a load `f`, with `extra`
/// statements and the crank's radius `radius`.
fn slider_crank(radius: &str, extra: &str) -> String {
    format!(
        "pub S {{
    params {{ r = 1.0, g = 9.81, rot = 0.0 }}
    loads {{ f = 0.0 }}
    let O = ground(0.0, 0.0);
    let A = crank(O, {radius}, th) as link2;
    let line = guide((0.0, 0.0), 0 deg);
    let B = rrp(A, 3.0, line, plus) as (link3, block) slide s;
    mass link3 {{ m = 1.0, at = B, j = 0.1 }}
    {extra}
}}"
    )
}

// A constant sub-expression that overflows or is NaN beside a parameter or a
// load: an error on that sub-expression, in every context (it panicked in
// proc-macro2's `Literal::f64_suffixed`).
#[test]
fn non_finite_sub_expressions_are_errors_on_their_tokens() {
    one_error_at(
        &slider_crank("r + 1e308 * 10.0", ""),
        "1e308 * 10.0",
        &["evaluates to inf", "finite"],
    );
    one_error_at(
        &slider_crank("1.0", "torque on link3 = f * (1e308 * 10.0) - f;"),
        "1e308 * 10.0",
        &["evaluates to inf"],
    );
    one_error_at(
        &slider_crank("1.0", "gravity (g * (1e308 * 10.0), -g);"),
        "1e308 * 10.0",
        &["evaluates to inf"],
    );
    // NaN comes from an infinity (or a division by zero) below it: the error
    // is on the first sub-expression that is not finite.
    one_error_at(
        &slider_crank("1.0", "gravity (0.0, g * (1e200 * 1e200 - 1e200 * 1e200));"),
        "1e200 * 1e200",
        &["evaluates to inf"],
    );
    one_error_at(
        &slider_crank("1.0", "let g2 = guide(A, link2, (1e308 * 10.0) + rot);"),
        "1e308 * 10.0",
        &["evaluates to inf"],
    );
    one_error_at(
        &slider_crank("1.0", "force at B = (f + (-1e308 - 1e308), 0.0);"),
        "-1e308 - 1e308",
        &["evaluates to -inf"],
    );
}

// `self`, `Self`, `super` and `crate` as a name: an error on the keyword
// with a name to use instead (the output did not parse).
#[test]
fn path_keywords_are_not_names() {
    for word in ["self", "Self", "super", "crate"] {
        let src = format!(
            "pub K {{ let O = ground(0.0, 0.0); let O4 = ground(3.5, 0.0);
    let A = crank(O, 1.0, {word}) as link2;
    let B = rrr(A, 3.0, O4, 3.0, left) as (link3, link4); }}"
        );
        let suggestion = format!("`{}_`", word.to_lowercase());
        one_error_at(&src, word, &["Rust keyword", &suggestion]);
    }
    // The head's visibility may name them.
    for vis in ["pub(crate)", "pub(super)", "pub(in crate)", "pub(self)"] {
        let src = format!(
            "{vis} V {{ let O = ground(0.0, 0.0); let O4 = ground(3.5, 0.0);
    let A = crank(O, 1.0, th) as link2;
    let B = rrr(A, 3.0, O4, 3.0, left) as (link3, link4); }}"
        );
        assert_eq!(expand(&src), vec![], "{vis}");
    }
}

// A raw identifier as a name (a link, a point, an input, a parameter): an
// error on it with a plain name to use (a link `r#type` in a force analysis
// made the macro panic building `r_r#type_link4`; expand fuzzer).
#[test]
fn raw_identifiers_are_not_names() {
    let cases = [
        "pub R { let O = ground(0.0, 0.0); let line = guide((0.0, -0.3), 0 deg);
    let P = slider(line, s) as r#type; let A = crank(O, 0.1, theta) as link2;
    let B = rrr(A, 0.4, P, 0.35, left) as (link3, link4);
    mass link3 { m = 1.0, at = B }; torque on link4 = 0.5; }",
        "pub R { let O = ground(0.0, 0.0); let O4 = ground(3.5, 0.0);
    let r#loop = crank(O, 1.0, th) as link2;
    let B = rrr(r#loop, 3.0, O4, 3.0, left) as (link3, link4); }",
        "pub R { params { r#fn = 1.0 } let O = ground(0.0, 0.0); let O4 = ground(3.5, 0.0);
    let A = crank(O, r#fn, r#in) as link2;
    let B = rrr(A, 3.0, O4, 3.0, left) as (link3, link4); }",
    ];
    for src in cases {
        let errors = expand(src);
        assert!(!errors.is_empty(), "accepted: {src}");
        for e in &errors {
            assert!(e.0.contains("raw identifier"), "{e:?}");
        }
    }
    one_error_at(cases[0], "r#type", &["raw identifier", "`type_`"]);
}

// Numbers with a type suffix or in another base: an error with the decimal
// to write (they were accepted by value).
#[test]
fn suffixed_and_non_decimal_numbers_are_errors() {
    for (written, fix) in [
        ("1u8", "`1.0`"),
        ("0x10", "`16.0`"),
        ("1.5f32", "`1.5`"),
        ("0b11", "`3.0`"),
        ("2e0f64", "`2e0`"),
    ] {
        let src = slider_crank(written, "");
        one_error_at(&src, written, &["write", fix]);
    }
    let src = slider_crank("1.0", "dof 1u8;");
    one_error_at(&src, "1u8", &["`1.0`"]);
}

/// `n` parentheses around `1.0` added to the crank's radius.
fn nested(n: usize) -> String {
    slider_crank(&format!("r + {}1.0{}", "(".repeat(n), ")".repeat(n)), "")
}

// Deep nesting and long chains: an error that says the limit, not a stack
// overflow of rustc; and every kind of path at the limit expands in a
// quarter of the 8 MiB that rustc gives the macro (a debug build, like a
// proc macro's).
#[test]
fn nesting_is_bounded_and_the_bound_fits_the_stack() {
    let limit = mechanism_codegen::parse::MAX_PATH;
    let too_deep = nested(800);
    let found = expand_in(&too_deep, 64 << 20);
    assert_eq!(found.len(), 1, "{found:#?}");
    assert!(
        found[0].0.contains(&format!("at most {limit}")),
        "{found:#?}"
    );
    let chain = slider_crank(&format!("r{}", " + r".repeat(2000)), "");
    let found = expand(&chain);
    assert_eq!(found.len(), 1, "{found:#?}");
    assert!(found[0].0.contains("chained too deep"), "{found:#?}");
    // At the limit (each path is counted from `pub S { .. }`, 3 tokens,
    // through `let A = crank(..) as link2`, 7, to the radius argument).
    let fits = [
        nested(limit - 13),
        slider_crank(&format!("{}1.0", "- ".repeat((limit - 11) & !1)), ""),
        slider_crank(&format!("r{}", " + r".repeat((limit - 11) / 2)), ""),
        slider_crank(
            &format!(
                "{}r{}",
                "(r + ".repeat((limit - 11) / 3),
                ")".repeat((limit - 11) / 3)
            ),
            "",
        ),
    ];
    assert_eq!(expand(&nested(limit - 12)).len(), 1, "one past the limit");
    for src in &fits {
        let found = expand_in(src, 2 << 20);
        assert!(found.is_empty(), "{found:#?}");
    }
}

// A range whose width overflows f64 is an error (the sweep returned at
// once on an infinite width and reported that every group assembles), and
// so is one whose sample step underflows.
#[test]
fn a_range_whose_width_overflows_is_an_error() {
    let src = "pub W { let line = guide((0.0, 0.0), 0 deg); let P = ground(0.0, 1.0);
    let C = slider(line, s) as block;
    let B = rrr(C, 1.2, P, 0.9, left) as (l1, l2);
    range s = (-1e308, 1e308); }";
    one_error_at(src, "1e308)", &["cannot be swept", "overflows"]);
    // A width whose sample step underflows to 0 (the sweep would sample
    // one point 3601 times).
    let src = src.replace("(-1e308, 1e308)", "(0.0, 5e-321)");
    one_error_at(
        &src,
        "5e-321",
        &["cannot be swept", "underflows to 0; widen"],
    );
}

// An error at the end of the input points at the last token, not at the
// whole invocation.
#[test]
fn end_of_input_errors_point_at_the_last_token() {
    // proc-macro2 outside rustc puts a group's closing span on the last
    // character of the span it was given: the error is on `rrp`'s last
    // character here, on all of `rrp` in rustc.
    let found = expand("pub rrp");
    assert_eq!(found.len(), 1, "{found:#?}");
    assert_eq!((found[0].1, found[0].2), (1, 6), "{found:#?}");
    assert!(found[0].0.contains("expected `{`"), "{found:#?}");
    one_error_at("#", "#", &["square brackets"]);
}
