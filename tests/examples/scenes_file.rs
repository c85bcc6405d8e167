//! `examples/common/scenes.rs` is the examples' own definitions gathered in
//! one file, for what cannot mount an example (a `no_std` firmware, the
//! no-panic build, the benchmarks, the report and these tests): each example
//! shows its `mechanism!` where a reader copies it from, and this test fails
//! when the gathered file differs from what the examples hold now.
//!
//! Run with `MECHANISM_BLESS=1` to rewrite the file from the examples.

use std::path::Path;

/// The examples whose definitions are gathered, in the file's order.
const EXAMPLES: [&str; 9] = [
    "fourbar",
    "sixbar",
    "shaper",
    "slider_crank",
    "five_bar",
    "geared_five_bar",
    "sine_mechanism",
    "shaper_forces",
    "five_bar_ik",
];

const HEADER: &str = "//! The examples' definitions, gathered from `examples/<name>.rs` for what
//! cannot mount an example (the firmware, the no-panic build, the
//! benchmarks, the report and the tests). Generated: do not edit; change the
//! example and run `MECHANISM_BLESS=1 cargo test -p mechanism-dev --test
//! examples scenes_file` (the test fails while this file is out of date).
#![allow(dead_code)]

use mechanism::mechanism;
";

/// Every `mechanism! { .. }` item of `text` that starts a line, in order:
/// from the macro's name to its closing brace (braces counted; the
/// definitions hold no brace inside a comment or a string).
fn definitions(text: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let mut rest = 0;
    while let Some(at) = text[rest..].find("\nmechanism! {") {
        let start = rest + at + 1;
        let mut depth = 0usize;
        let mut end = None;
        for (k, c) in text[start..].char_indices() {
            match c {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if depth == 0 {
                        end = Some(start + k + 1);
                        break;
                    }
                }
                _ => {}
            }
        }
        let end = end.expect("a mechanism! item without its closing brace");
        out.push(&text[start..end]);
        rest = end;
    }
    out
}

/// The gathered file the examples give now.
fn gathered(examples: &Path) -> String {
    let mut out = String::from(HEADER);
    for name in EXAMPLES {
        let path = examples.join(format!("{name}.rs"));
        let text =
            std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let defs = definitions(&text);
        assert!(!defs.is_empty(), "{name}.rs shows no `mechanism!` item");
        for d in defs {
            out.push('\n');
            out.push_str(&format!("// examples/{name}.rs\n"));
            out.push_str(d);
            out.push('\n');
        }
    }
    out
}

#[test]
fn the_gathered_scenes_are_the_examples_definitions() {
    let examples = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples");
    let file = examples.join("common/scenes.rs");
    let want = gathered(&examples);
    if std::env::var_os("MECHANISM_BLESS").is_some() {
        std::fs::write(&file, &want).expect("write examples/common/scenes.rs");
        return;
    }
    let have = std::fs::read_to_string(&file).expect("examples/common/scenes.rs");
    assert!(
        have == want,
        "examples/common/scenes.rs is not what the examples define now: run \
         MECHANISM_BLESS=1 cargo test -p mechanism-dev --test examples scenes_file"
    );
}

#[test]
fn items_are_found_whole_and_in_order() {
    let text = "use x;\nmechanism! {\n    /// a\n    pub A { let B = c(D, { 1 }); }\n}\nfn main() {}\nmechanism! { pub E {} }\n";
    let defs = definitions(text);
    assert_eq!(
        defs,
        [
            "mechanism! {\n    /// a\n    pub A { let B = c(D, { 1 }); }\n}",
            "mechanism! { pub E {} }"
        ]
    );
}
