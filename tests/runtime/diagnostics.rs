//! Every UI failure case read at run time gives the errors rustc shows for
//! it: the same messages at the same lines and columns of the case's file.

use mechanism_codegen::runtime::Mechanism;
use std::path::Path;

/// One error as shown: its message, line and column (1-based) in the file.
type Shown = (String, usize, usize);

/// A message as compared: each line without its indentation (rustc indents
/// the `= note:` lines of a message under the `error` word), and no space
/// before `(` (a call quoted from the user's tokens is printed `sqrt (..)`
/// by proc-macro2 outside a compiler, `sqrt(..)` by rustc's token printer).
fn normal(message: &str) -> String {
    let lines: Vec<&str> = message.lines().map(str::trim).collect();
    lines.join("\n").replace(" (", "(")
}

/// The macro's errors in a trybuild snapshot: `error: MESSAGE` (no rustc
/// error code) followed by ` --> FILE:LINE:COL` in the case's own file.
fn snapshot_errors(stderr: &str, file: &str) -> Vec<Shown> {
    let lines: Vec<&str> = stderr.lines().collect();
    let mut out = Vec::new();
    for (k, line) in lines.iter().enumerate() {
        let Some(message) = line.strip_prefix("error: ") else {
            continue;
        };
        // A warning of the check (a singular position) denied into an
        // error by the case: the run-time reading reports errors only.
        if message.starts_with("use of deprecated") {
            continue;
        }
        // The message may go on over several lines, up to the location.
        let mut msg = message.to_string();
        let mut j = k + 1;
        while j < lines.len() && !lines[j].trim_start().starts_with("--> ") {
            if lines[j].starts_with("error") || lines[j].trim().is_empty() {
                break;
            }
            msg.push('\n');
            msg.push_str(lines[j]);
            j += 1;
        }
        let Some(at) = lines
            .get(j)
            .and_then(|l| l.trim_start().strip_prefix("--> "))
        else {
            continue;
        };
        let mut parts = at.rsplitn(3, ':');
        let (col, line_no, path) = (parts.next(), parts.next(), parts.next());
        if path != Some(file) {
            continue;
        }
        if let (Some(Ok(c)), Some(Ok(l))) = (col.map(str::parse), line_no.map(str::parse)) {
            out.push((normal(&msg), l, c));
        }
    }
    out
}

/// The run-time errors of the definition at byte `start` of `source`, with
/// their places in the whole file.
fn runtime_errors(source: &str, start: usize, text: &str) -> Vec<Shown> {
    let before = &source[..start];
    let line0 = before.matches('\n').count() + 1;
    let col0 = before.len() - before.rfind('\n').map_or(0, |i| i + 1);
    let col0 = source[start - col0..start].chars().count();
    match Mechanism::new(text) {
        Ok(_) => Vec::new(),
        Err(e) => e
            .diagnostics
            .iter()
            .map(|d| {
                let line = line0 + d.line - 1;
                let col = if d.line == 1 {
                    col0 + d.column
                } else {
                    d.column
                };
                (normal(&d.message), line, col + 1)
            })
            .collect(),
    }
}

#[test]
fn every_ui_failure_gives_the_same_errors_at_run_time() {
    // Proves, for each tests/ui case with one definition, that the
    // run-time reading reports exactly the macro's errors of the snapshot
    // (messages, lines and columns), and at least one.
    // The repository root: the manifest's directory (`mechanism-dev/`)'s parent.
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = [manifest, manifest.parent().unwrap_or(manifest)]
        .iter()
        .map(|d| d.join("tests/ui"))
        .find(|d| d.is_dir())
        .expect("tests/ui");
    let mut cases: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "rs"))
        .collect();
    cases.sort();
    let (mut compared, mut skipped, mut mismatches) = (0, Vec::new(), Vec::new());
    for case in &cases {
        let source = std::fs::read_to_string(case).unwrap();
        let Ok(stderr) = std::fs::read_to_string(case.with_extension("stderr")) else {
            continue;
        };
        let file = format!("tests/ui/{}", case.file_name().unwrap().to_string_lossy());
        let want = snapshot_errors(&stderr, &file);
        let opens: Vec<usize> = source
            .match_indices("mechanism! {")
            .map(|(i, _)| i)
            .collect();
        if opens.len() != 1 || want.is_empty() {
            skipped.push(file);
            continue;
        }
        let start = opens[0] + "mechanism! {".len();
        let text = &super::text::definitions(&source[opens[0]..])[0];
        let got = runtime_errors(&source, start, text);
        compared += 1;
        if got != want {
            mismatches.push(format!(
                "{file}:\n  macro:    {want:?}\n  run time: {got:?}"
            ));
        }
    }
    eprintln!(
        "compared {compared} UI cases; skipped {}: {skipped:?}",
        skipped.len()
    );
    assert!(compared > 100, "only {compared} cases compared");
    assert!(
        mismatches.is_empty(),
        "{} of {compared} differ:\n{}",
        mismatches.len(),
        mismatches.join("\n")
    );
}
