//! Cutting definitions out of Rust source: the text between the braces of
//! each `mechanism! { ... }`.

/// The text inside the braces of every `mechanism! {` in `source`, in order.
pub fn definitions(source: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = source;
    while let Some(at) = rest.find("mechanism! {") {
        let body = &rest[at + "mechanism! {".len()..];
        let mut depth = 1usize;
        let mut end = None;
        for (i, c) in body.char_indices() {
            match c {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if depth == 0 {
                        end = Some(i);
                        break;
                    }
                }
                _ => {}
            }
        }
        let Some(end) = end else { break };
        out.push(body[..end].to_string());
        rest = &body[end..];
    }
    out
}

/// The definition of `name` (`pub NAME {`) among those of `source`.
pub fn definition(source: &str, name: &str) -> String {
    definitions(source)
        .into_iter()
        .find(|d| d.contains(&format!("pub {name} {{")))
        .unwrap_or_else(|| panic!("no definition `{name}` in the source"))
}
