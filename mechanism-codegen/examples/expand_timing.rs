//! Expansion-time cost of `mechanism!` for each example scene: the whole
//! `expand` (parse to tokens, with the expansion-time check when the scene's
//! dimensions are literal), median of 5 runs.
//!
//! Run: `cargo run --release -p mechanism-dev --example expand_timing`
//! (rustc runs proc macros built in the dev profile unless the profile says
//! otherwise: run without `--release` for what a user's build sees).

use std::str::FromStr;
use std::time::Instant;

fn main() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../examples/common/scenes.rs");
    let source = std::fs::read_to_string(path).expect("examples/common/scenes.rs");
    let mut rest = source.as_str();
    while let Some(start) = rest.find("mechanism! {\n") {
        let body_start = start + "mechanism! {".len();
        let end = rest[body_start..].find("\n}\n").expect("closing brace") + body_start;
        let body = &rest[body_start..end];
        rest = &rest[end..];
        let name = body
            .split("pub ")
            .nth(1)
            .and_then(|s| s.split_whitespace().next())
            .unwrap_or("?");
        let tokens = proc_macro2::TokenStream::from_str(body).expect("tokens");
        let mut times = Vec::new();
        let mut size = 0;
        for _ in 0..5 {
            let t = Instant::now();
            let out = mechanism_codegen::expand(tokens.clone());
            times.push(t.elapsed().as_secs_f64() * 1e3);
            size = out.to_string().len();
        }
        times.sort_by(f64::total_cmp);
        println!(
            "{name:>14}: expand {:8.2} ms (median of 5), {size} bytes of tokens",
            times[2]
        );
    }
}
