//! Prepares the language reference (`dsl.md`, the repository's `docs/dsl.md`)
//! for the macro's documentation page: every ```` ```rust ```` block that does
//! not import the macro gets the hidden line `# use mechanism::mechanism;`, so
//! that the samples run as doctests as written in the document; a picture
//! (a line `![alt](file.png)`, a file next to the document in the repository)
//! is left out, since docs.rs has no copy of the file to show.

use std::{env, fs, path::Path};

fn main() {
    println!("cargo:rerun-if-changed=dsl.md");
    let text = fs::read_to_string("dsl.md").expect("dsl.md is part of the package");
    let mut out = String::with_capacity(text.len() + 256);
    let mut lines = text.lines().peekable();
    while let Some(line) = lines.next() {
        if line.starts_with("![") {
            continue;
        }
        out.push_str(line);
        out.push('\n');
        if line.trim_end() == "```rust" {
            let block: Vec<&str> = lines
                .clone()
                .take_while(|l| !l.starts_with("```"))
                .collect();
            if !block
                .iter()
                .any(|l| l.contains("use mechanism::mechanism;"))
            {
                out.push_str("# use mechanism::mechanism;\n");
            }
        }
    }
    let dir = env::var_os("OUT_DIR").expect("cargo sets OUT_DIR");
    fs::write(Path::new(&dir).join("dsl.md"), out).expect("OUT_DIR is writable");
}
