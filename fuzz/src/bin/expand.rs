//! Front-end fuzzer of `mechanism!`: feeds [`mechanism_codegen::expand`]
//! with definitions that are mutants of the project's own (every
//! `mechanism! { .. }` body in `examples/`, `tests/`, `docs/*.md` and
//! `README.md`, read at start), random definitions built from the grammar of
//! `docs/dsl.md`, and random token streams, and checks each expansion:
//!
//! - no panic (`catch_unwind`) and no hang (a watchdog over a per-case time
//!   limit; the expansion runs in a thread with a big stack);
//! - the output parses as Rust items (`syn::File`);
//! - every `compile_error!` points at one of the user's tokens: its span's
//!   byte range is non-empty and lies inside the input (a span at the call
//!   site, byte range `0..0`, is a failure whenever the input has a token);
//! - a sample of the successful expansions compiles (`cargo check --tests`
//!   of a scratch crate depending on the facade by path, in batches, with a
//!   target directory shared across batches).
//!
//! Run: `cargo run --release -p mechanism-fuzz --bin expand -- --seconds 600`
//! (`--seed S` replays a run; `--compile-sample K` compiles 1 in K successful
//! expansions, 0 for none; `--case-ms MS` is the time limit of one case;
//! `--repro FILE` expands one saved input and prints the verdict; `--runtime`
//! also reads each case at run time, `mechanism_codegen::runtime`: no
//! panic, no hang, every diagnostic at a place in the text, and the
//! analyses of a definition that reads run without a panic). It prints
//! the counts and exits non-zero on any failure, the failing input saved in
//! `target/fuzz-expand/`.

use proc_macro2::{Delimiter, TokenStream, TokenTree};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::mpsc;
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// `--runtime`: each case is also read by the run-time mechanism.
static RUNTIME: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// The message of the last panic of the worker (the hook keeps it quiet).
static PANIC_MESSAGE: Mutex<Option<String>> = Mutex::new(None);

/// Stack of the expansion thread: far more than rustc gives a proc macro
/// (8 MiB), so a deep recursion shows up as a slow case, not a crash of the
/// fuzzer; the macro's own depth limit is tested at 8 MiB in
/// `mechanism-codegen`.
const WORKER_STACK: usize = 512 << 20;

/// Expansions per scratch crate in the compile sample.
const COMPILE_BATCH: usize = 20;

struct Options {
    seconds: u64,
    seed: u64,
    compile_sample: u64,
    case_ms: u64,
    repro: Option<PathBuf>,
}

fn options() -> Result<Options, String> {
    let mut o = Options {
        seconds: 60,
        seed: std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map(|d| d.as_nanos() as u64 ^ u64::from(std::process::id()))
            .unwrap_or(1),
        compile_sample: 1000,
        case_ms: 5000,
        repro: None,
    };
    let mut args = std::env::args().skip(1);
    while let Some(flag) = args.next() {
        let mut value = || args.next().ok_or(format!("{flag} needs a value"));
        let number = |v: String| v.parse::<u64>().map_err(|e| format!("{flag}: {e}"));
        match flag.as_str() {
            "--seconds" => o.seconds = number(value()?)?,
            "--seed" => o.seed = number(value()?)?,
            "--compile-sample" => o.compile_sample = number(value()?)?,
            "--case-ms" => o.case_ms = number(value()?)?,
            "--repro" => o.repro = Some(PathBuf::from(value()?)),
            "--runtime" => RUNTIME.store(true, std::sync::atomic::Ordering::Relaxed),
            _ => {
                return Err(format!(
                    "unknown option {flag}; options: --seconds N, --seed S, --compile-sample K, --case-ms MS, --repro FILE, --runtime"
                ))
            }
        }
    }
    Ok(o)
}

fn repo_root() -> PathBuf {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    manifest.parent().unwrap_or(manifest).to_path_buf()
}

fn target_dir(root: &Path) -> PathBuf {
    std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| root.join("target"))
}

// ---------------------------------------------------------------- corpus ---

/// Every `.rs` and `.md` file under `dir` (recursively, skipping `target`).
fn files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let mut entries: Vec<_> = entries.flatten().map(|e| e.path()).collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            if path.file_name().is_some_and(|n| n != "target") {
                files(&path, out);
            }
        } else if path.extension().is_some_and(|e| e == "rs" || e == "md") {
            out.push(path);
        }
    }
}

/// The text between the braces of each `mechanism! { .. }` in `text`
/// (comments and strings skipped when matching braces).
fn bodies(text: &str) -> Vec<String> {
    let bytes = text.as_bytes();
    let mut out = Vec::new();
    let mut from = 0;
    while let Some(at) = text[from..].find("mechanism!") {
        let mut i = from + at + "mechanism!".len();
        from = i;
        while i < bytes.len() && bytes[i].is_ascii_whitespace() {
            i += 1;
        }
        let (open, close) = match bytes.get(i) {
            Some(b'{') => (b'{', b'}'),
            Some(b'(') => (b'(', b')'),
            _ => continue,
        };
        let start = i + 1;
        let mut depth = 0usize;
        let mut j = i;
        while j < bytes.len() {
            match bytes[j] {
                b'/' if bytes.get(j + 1) == Some(&b'/') => {
                    while j < bytes.len() && bytes[j] != b'\n' {
                        j += 1;
                    }
                }
                b'"' => {
                    j += 1;
                    while j < bytes.len() && bytes[j] != b'"' {
                        j += if bytes[j] == b'\\' { 2 } else { 1 };
                    }
                }
                b if b == open => depth += 1,
                b if b == close => {
                    depth -= 1;
                    if depth == 0 {
                        out.push(text[start..j].to_string());
                        from = j;
                        break;
                    }
                }
                _ => {}
            }
            j += 1;
        }
    }
    out
}

/// The bodies of the project's own definitions, with the file each came
/// from; only those that are a token stream (a doc's sketch with `..` may
/// still be one).
fn corpus(root: &Path) -> Vec<(String, String)> {
    let mut paths = Vec::new();
    files(&root.join("examples"), &mut paths);
    files(&root.join("tests"), &mut paths);
    if let Ok(entries) = std::fs::read_dir(root.join("docs")) {
        let mut docs: Vec<_> = entries
            .flatten()
            .map(|e| e.path())
            .filter(|p| p.extension().is_some_and(|e| e == "md"))
            .collect();
        docs.sort();
        paths.extend(docs);
    }
    paths.push(root.join("README.md"));
    let mut out = Vec::new();
    for path in paths {
        let Ok(text) = std::fs::read_to_string(&path) else {
            continue;
        };
        let name = path
            .strip_prefix(root)
            .unwrap_or(&path)
            .display()
            .to_string();
        for body in bodies(&text) {
            if body.parse::<TokenStream>().is_ok() {
                out.push((name.clone(), body));
            }
        }
    }
    out
}

// ------------------------------------------------------------- mutation ---

/// One token of a flattened stream: a delimiter is a token of its own.
#[derive(Clone)]
struct Tok {
    text: String,
    /// A punctuation glued to the next token (`=>`, `::`).
    joint: bool,
}

fn flatten(stream: TokenStream, out: &mut Vec<Tok>) {
    for tree in stream {
        match tree {
            TokenTree::Group(g) => {
                let (open, close) = match g.delimiter() {
                    Delimiter::Parenthesis => ("(", ")"),
                    Delimiter::Brace => ("{", "}"),
                    Delimiter::Bracket => ("[", "]"),
                    Delimiter::None => ("", ""),
                };
                if !open.is_empty() {
                    out.push(tok(open));
                }
                flatten(g.stream(), out);
                if !close.is_empty() {
                    out.push(tok(close));
                }
            }
            TokenTree::Punct(p) => out.push(Tok {
                text: p.as_char().to_string(),
                joint: p.spacing() == proc_macro2::Spacing::Joint,
            }),
            other => out.push(tok(&other.to_string())),
        }
    }
}

fn tok(s: &str) -> Tok {
    Tok {
        text: s.to_string(),
        joint: false,
    }
}

fn render(toks: &[Tok]) -> String {
    let mut out = String::new();
    for t in toks {
        out.push_str(&t.text);
        if !t.joint {
            out.push(' ');
        }
    }
    out
}

fn is_number(t: &Tok) -> bool {
    t.text.starts_with(|c: char| c.is_ascii_digit())
}

fn is_word(t: &Tok) -> bool {
    t.text.starts_with(|c: char| c.is_alphabetic() || c == '_')
}

/// Numbers at the edges of `f64` and expressions that overflow or give NaN
/// when folded, literal forms the language does not take, long chains.
const EXTREME_NUMBERS: &[&str] = &[
    "0",
    "0.0",
    "-0.0",
    "1e308",
    "-1e308",
    "1e-308",
    "5e-324",
    "1e309",
    "1.7976931348623157e308",
    "(1e308 * 10.0)",
    "(1e200 * 1e200 - 1e200 * 1e200)",
    "(0.0 / 0.0)",
    "(1.0 / 0.0)",
    "(1e-300 * 1e-300)",
    "(1e308 + 1e308)",
    "(-1e308 - 1e308)",
    "1u8",
    "0x10",
    "0b1",
    "1.5f32",
    "2.0f64",
    "1_000.0",
    "18446744073709551616",
    "340282366920938463463374607431768211456",
    "1e",
    "1.",
    ".5",
    "4294967296.0",
    "3.4e38",
    "1e-45",
];

/// Names that are Rust keywords, reserved in the generated code, or
/// meaningful to the language.
const WORDS: &[&str] = &[
    "self",
    "Self",
    "super",
    "crate",
    "r#type",
    "r#fn",
    "r#match",
    "fn",
    "let",
    "const",
    "as",
    "in",
    "mod",
    "struct",
    "impl",
    "dyn",
    "async",
    "await",
    "try",
    "union",
    "_",
    "T",
    "f64",
    "pos",
    "vel",
    "acc",
    "input",
    "loads",
    "forces",
    "deg",
    "rad",
    "from",
    "left",
    "right",
    "plus",
    "minus",
    "cos_sin",
    "ground",
    "guide",
    "crank",
    "slider",
    "actuator",
    "target",
    "motor",
    "rrr",
    "rrp",
    "rpr",
    "prp",
    "rpp",
    "gear",
    "point",
    "params",
    "analysis",
    "outputs",
    "dof",
    "mass",
    "gravity",
    "force",
    "torque",
    "range",
    "allow",
    "singular",
    "slide",
    "along",
    "at",
    "on",
    "m",
    "j",
    "position",
    "velocity",
    "acceleration",
    "grp_x",
    "in_x",
    "pos_x",
    "ü",
    "é",
    "__x",
    "self_test",
    "doc",
    "pub",
];

const PUNCTS: &[&str] = &[
    ",", ";", "=", "-", "+", "*", "/", ".", "::", "#", "!", "&", "%", "^", "<", ">", "..", "=>",
    "?", "@", "$", "~", "as", "deg", "'a", "\"s\"", "'c'", "b\"x\"",
];

fn pick<'a>(rng: &mut fastrand::Rng, from: &[&'a str]) -> &'a str {
    from[rng.usize(..from.len())]
}

/// `(((x)))` with `n` levels, or a long chain of unary minus or of sums.
fn deep(rng: &mut fastrand::Rng, inner: &str) -> String {
    let n = *rng
        .choice(&[8usize, 40, 100, 300, 800, 2000, 5000])
        .unwrap_or(&8);
    match rng.u8(..3) {
        0 => format!("{}{inner}{}", "(".repeat(n), ")".repeat(n)),
        1 => format!("{}{inner}", "- ".repeat(n)),
        _ => format!("{inner}{}", " + 1.0".repeat(n)),
    }
}

/// One to three token-level edits of `toks`; `words` are names of the
/// corpus (to swap one name for another), `donor` another definition (to
/// splice a piece of it in).
fn mutate(rng: &mut fastrand::Rng, toks: &mut Vec<Tok>, words: &[String], donor: &[Tok]) {
    for _ in 0..rng.usize(1..=3) {
        if toks.is_empty() {
            toks.push(tok(pick(rng, WORDS)));
        }
        let i = rng.usize(..toks.len());
        match rng.u8(..12) {
            0 => {
                toks.remove(i);
            }
            1 => {
                let end = (i + rng.usize(1..=8)).min(toks.len());
                let piece: Vec<Tok> = toks[i..end].to_vec();
                let at = rng.usize(..=toks.len());
                toks.splice(at..at, piece);
            }
            2 => {
                let j = rng.usize(..toks.len());
                toks.swap(i, j);
            }
            3 | 4 => {
                let numbers: Vec<usize> =
                    (0..toks.len()).filter(|&k| is_number(&toks[k])).collect();
                let k = numbers
                    .get(rng.usize(..numbers.len().max(1)))
                    .copied()
                    .unwrap_or(i);
                toks[k] = tok(pick(rng, EXTREME_NUMBERS));
            }
            5 | 6 => {
                let names: Vec<usize> = (0..toks.len()).filter(|&k| is_word(&toks[k])).collect();
                let k = names
                    .get(rng.usize(..names.len().max(1)))
                    .copied()
                    .unwrap_or(i);
                toks[k] = if rng.bool() || words.is_empty() {
                    tok(pick(rng, WORDS))
                } else {
                    tok(&words[rng.usize(..words.len())])
                };
            }
            7 => {
                let k = (0..toks.len())
                    .filter(|&k| is_number(&toks[k]) || is_word(&toks[k]))
                    .nth(rng.usize(..toks.len()))
                    .unwrap_or(i);
                let inner = toks[k].text.clone();
                toks[k] = tok(&deep(rng, &inner));
            }
            8 => {
                let puncts: Vec<usize> = (0..toks.len())
                    .filter(|&k| !is_number(&toks[k]) && !is_word(&toks[k]))
                    .collect();
                if let Some(&k) = puncts.get(rng.usize(..puncts.len().max(1))) {
                    toks.remove(k);
                }
            }
            9 => toks.insert(i, tok(pick(rng, PUNCTS))),
            10 if !donor.is_empty() => {
                let from = rng.usize(..donor.len());
                let end = (from + rng.usize(1..=16)).min(donor.len());
                toks.splice(i..i, donor[from..end].iter().cloned());
            }
            _ => {
                // Unbalance a group (most such mutants are not a token stream
                // at all: rustc's lexer rejects them before the macro runs).
                toks.insert(i, tok(pick(rng, &["(", ")", "{", "}", "[", "]"])));
            }
        }
    }
}

// -------------------------------------------------------------- grammar ---

/// A random definition from the grammar of `docs/dsl.md`: mostly plausible
/// (a crank-rocker or a slider-crank with sane numbers, so that many
/// assemble and expand), with random extra groups, points, loads, ranges
/// and values drawn anywhere from sane to absurd.
struct Gen<'r> {
    rng: &'r mut fastrand::Rng,
    params: Vec<String>,
    consts: Vec<String>,
    points: Vec<String>,
    links: Vec<String>,
    guides: Vec<String>,
    inputs: Vec<String>,
    n: usize,
    wild: bool,
}

impl Gen<'_> {
    fn fresh(&mut self, prefix: &str) -> String {
        self.n += 1;
        format!("{prefix}{}", self.n)
    }

    fn number(&mut self) -> String {
        if self.wild && self.rng.u8(..6) == 0 {
            return pick(self.rng, EXTREME_NUMBERS).to_string();
        }
        let x = self.rng.f64() * 10.0_f64.powi(self.rng.i32(-3..=3));
        format!("{x:?}")
    }

    /// A length near `sane` (or anything, when wild).
    fn length(&mut self, sane: f64) -> String {
        if self.wild && self.rng.u8(..3) == 0 {
            return self.value(2);
        }
        let x = sane * (1.0 + 0.02 * (self.rng.f64() - 0.5));
        match self.rng.u8(..6) {
            0 if !self.params.is_empty() => {
                let p = self.params[self.rng.usize(..self.params.len())].clone();
                format!("{x:?} + {p} * 0.0")
            }
            1 => format!("({:?} * 2.0)", x / 2.0),
            _ => format!("{x:?}"),
        }
    }

    /// An expression: numbers, parameters, constants, `+ - * /`, parens.
    fn value(&mut self, depth: u32) -> String {
        match self.rng.u8(..if depth == 0 { 3 } else { 7 }) {
            0 if !self.params.is_empty() => {
                self.params[self.rng.usize(..self.params.len())].clone()
            }
            1 if !self.consts.is_empty() => {
                self.consts[self.rng.usize(..self.consts.len())].clone()
            }
            3 => format!("-{}", self.value(depth - 1)),
            4 => format!("({})", self.value(depth - 1)),
            5 | 6 => {
                let op = pick(self.rng, &["+", "-", "*", "/"]);
                format!("{} {op} {}", self.value(depth - 1), self.value(depth - 1))
            }
            _ => self.number(),
        }
    }

    fn angle(&mut self) -> String {
        let unit = pick(self.rng, &["deg", "rad", "deg", ""]);
        let v = if self.rng.bool() {
            format!("{:?}", (self.rng.f64() * 360.0 - 180.0).round())
        } else {
            self.value(1)
        };
        format!("{v} {unit}")
    }

    fn any<'a>(&mut self, of: &'a [String]) -> Option<&'a String> {
        if of.is_empty() {
            None
        } else {
            Some(&of[self.rng.usize(..of.len())])
        }
    }

    fn point(&mut self) -> String {
        let points = self.points.clone();
        self.any(&points)
            .cloned()
            .unwrap_or_else(|| "O".to_string())
    }

    fn side(&mut self, a: &str, b: &str) -> String {
        pick(self.rng, &[a, b]).to_string()
    }

    /// The core: a crank-rocker four-bar or a slider-crank, sane numbers.
    fn core(&mut self, out: &mut Vec<String>) {
        let o = self.fresh("O");
        out.push(format!("let {o} = ground(0.0, 0.0);"));
        self.points.push(o.clone());
        let th = self.fresh("th");
        let a = self.fresh("A");
        let crank = self.fresh("crank");
        let r = self.length(1.0);
        out.push(format!("let {a} = crank({o}, {r}, {th}) as {crank};"));
        self.links.push(crank);
        self.inputs.push(th);
        self.points.push(a.clone());
        let b = self.fresh("B");
        if self.rng.bool() {
            let o4 = self.fresh("O");
            let g = self.length(3.5);
            out.push(format!("let {o4} = ground({g}, 0.0);"));
            let (l3, l4) = (self.fresh("coupler"), self.fresh("rocker"));
            let (c, k) = (self.length(3.0), self.length(3.0));
            let mode = self.side("left", "right");
            out.push(format!(
                "let {b} = rrr({a}, {c}, {o4}, {k}, {mode}) as ({l3}, {l4});"
            ));
            self.points.push(o4);
            self.links.push(l3);
            self.links.push(l4);
        } else {
            let line = self.fresh("line");
            let angle = if self.rng.bool() {
                "0 deg".to_string()
            } else {
                self.angle()
            };
            out.push(format!("let {line} = guide((0.0, 0.0), {angle});"));
            let (rod, block, s) = (self.fresh("rod"), self.fresh("block"), self.fresh("s"));
            let l = self.length(3.0);
            let mode = self.side("plus", "minus");
            out.push(format!(
                "let {b} = rrp({a}, {l}, {line}, {mode}) as ({rod}, {block}) slide {s};"
            ));
            self.guides.push(line);
            self.links.push(rod);
            self.links.push(block);
        }
        self.points.push(b);
    }

    /// One extra statement of any kind.
    fn extra(&mut self, out: &mut Vec<String>) {
        let name = self.fresh("P");
        let link = self
            .any(&self.links.clone())
            .cloned()
            .unwrap_or_else(|| "link".into());
        let (p, q) = (self.point(), self.point());
        let stmt = match self.rng.u8(..18) {
            0 => format!(
                "let {name} = point({link}, from {p}, {}, {});",
                self.length(0.5),
                self.angle()
            ),
            1 => format!(
                "let {name} = point({link}, from {p}, ({}, {}));",
                self.value(1),
                self.value(1)
            ),
            2 => {
                let (l1, l2) = (self.fresh("l"), self.fresh("l"));
                let mode = self.side("left", "right");
                format!(
                    "let {name} = rrr({p}, {}, {q}, {}, {mode}) as ({l1}, {l2});",
                    self.length(3.0),
                    self.length(3.0)
                )
            }
            3 => {
                let g = self.fresh("g");
                let angle = self.angle();
                out.push(format!("let {g} = guide({p}, {angle});"));
                self.guides.push(g.clone());
                let (l1, l2, s) = (self.fresh("l"), self.fresh("l"), self.fresh("s"));
                format!(
                    "let {name} = rrp({q}, {}, {g}, plus) as ({l1}, {l2}) slide {s};",
                    self.length(2.0)
                )
            }
            4 => format!(
                "let {name} = rpr({p}, {q}, {}) as ({}, {});",
                self.side("plus", "minus"),
                self.fresh("b"),
                self.fresh("l")
            ),
            5 => format!("let {name} = ground({}, {});", self.value(2), self.value(2)),
            6 => format!(
                "mass {link} {{ m = {}, at = {p}, j = {} }}",
                self.value(1),
                self.value(1)
            ),
            7 => format!("gravity ({}, {});", self.value(2), self.value(2)),
            8 => {
                let load = self.fresh("f");
                out.push(format!("loads {{ {load} = {} }}", self.number()));
                format!(
                    "force at {p} = ({load} * {}, {});",
                    self.value(2),
                    self.value(1)
                )
            }
            9 => format!("torque on {link} = {} * {};", self.value(2), self.value(1)),
            10 => {
                let input = self
                    .any(&self.inputs.clone())
                    .cloned()
                    .unwrap_or_else(|| "th".into());
                let (lo, hi) = (self.angle(), self.angle());
                format!("range {input} = ({lo}, {hi});")
            }
            11 => format!(
                "analysis {};",
                pick(
                    self.rng,
                    &["position", "velocity", "acceleration", "forces"]
                )
            ),
            12 => format!("outputs {{ {p}, {link} }}"),
            13 => format!("dof {};", self.rng.u8(..4)),
            14 => "allow singular;".to_string(),
            15 => {
                let (x, y, e) = (self.fresh("x"), self.fresh("y"), self.fresh("e"));
                self.inputs.push(x.clone());
                self.links.push(e.clone());
                format!("let {name} = target({x}, {y}) as {e};")
            }
            16 => format!("motor {} = angle({link});", self.fresh("q")),
            _ => {
                let c = self.fresh("k");
                let v = self.value(2);
                self.consts.push(c.clone());
                format!("const {c} = {v};")
            }
        };
        self.points.push(name);
        out.push(stmt);
    }
}

fn generate(rng: &mut fastrand::Rng) -> String {
    let wild = rng.u8(..3) == 0;
    let mut g = Gen {
        rng,
        params: Vec::new(),
        consts: Vec::new(),
        points: Vec::new(),
        links: Vec::new(),
        guides: Vec::new(),
        inputs: Vec::new(),
        n: 0,
        wild,
    };
    let mut out = Vec::new();
    if g.rng.u8(..8) == 0 {
        out.push("#[self_test]".to_string());
    }
    let vis = pick(g.rng, &["pub", "", "pub(crate)", "pub(super)"]);
    let name = pick(g.rng, &["Gen", "FourBar", "M", "Slider"]);
    out.push(format!("{vis} {name} {{"));
    let mut body = Vec::new();
    let n_params = g.rng.usize(..4);
    if n_params > 0 {
        let entries: Vec<String> = (0..n_params)
            .map(|_| {
                let p = g.fresh("p");
                g.params.push(p.clone());
                format!("{p} = {}", g.number())
            })
            .collect();
        body.push(format!("params {{ {} }}", entries.join(", ")));
    }
    g.core(&mut body);
    for _ in 0..g.rng.usize(..5) {
        g.extra(&mut body);
    }
    if g.rng.bool() {
        g.rng.shuffle(&mut body);
    }
    out.extend(body);
    out.push("}".to_string());
    out.join("\n")
}

/// A random token stream: words, numbers, punctuation and nested groups,
/// sometimes behind a definition's head.
fn random_stream(rng: &mut fastrand::Rng, depth: u32) -> String {
    let mut out = String::new();
    if depth == 0 && rng.bool() {
        out.push_str("pub M { ");
    }
    for _ in 0..rng.usize(..24) {
        match rng.u8(..10) {
            0..=2 => out.push_str(pick(rng, WORDS)),
            3 | 4 => out.push_str(pick(rng, EXTREME_NUMBERS)),
            5 => out.push_str(&format!("{:?}", rng.f64() * 100.0)),
            6 | 7 => out.push_str(pick(rng, PUNCTS)),
            _ if depth < 6 => {
                let (o, c) = *rng
                    .choice(&[("(", ")"), ("{", "}"), ("[", "]")])
                    .unwrap_or(&("(", ")"));
                out.push_str(o);
                out.push_str(&random_stream(rng, depth + 1));
                out.push_str(c);
            }
            _ => out.push(';'),
        }
        out.push(' ');
    }
    if depth == 0 && out.starts_with("pub M") {
        out.push('}');
    }
    out
}

// -------------------------------------------------------------- verdict ---

/// What one case gave.
enum Verdict {
    /// Not a token stream (rustc's lexer would reject it first).
    Unlexable,
    /// Expanded with no error: the output, to compile in the sample.
    Ok(String),
    /// Expanded into errors, each on a user token.
    Errors,
    Panic(String),
    NotParsing(String),
    CallSiteError(String),
}

/// The byte range of the input's tokens (the fallback's spans are offsets
/// into a per-thread source map, so the input's are not at 0).
fn input_range(stream: &TokenStream) -> Option<std::ops::Range<usize>> {
    let mut lo = usize::MAX;
    let mut hi = 0;
    fn walk(s: &TokenStream, lo: &mut usize, hi: &mut usize) {
        for t in s.clone() {
            let r = t.span().byte_range();
            *lo = (*lo).min(r.start);
            *hi = (*hi).max(r.end);
            if let TokenTree::Group(g) = t {
                walk(&g.stream(), lo, hi);
            }
        }
    }
    walk(stream, &mut lo, &mut hi);
    (lo < hi).then_some(lo..hi)
}

/// Each `compile_error!` of `out` whose span is not on a user token: its
/// message.
fn misplaced_errors(out: &TokenStream, input: &std::ops::Range<usize>) -> Vec<String> {
    let mut bad = Vec::new();
    let trees: Vec<TokenTree> = out.clone().into_iter().collect();
    for (k, t) in trees.iter().enumerate() {
        match t {
            TokenTree::Ident(i) if i == "compile_error" => {
                let r = i.span().byte_range();
                let on_user = r.start < r.end && r.start >= input.start && r.end <= input.end;
                if !on_user {
                    let message = trees.get(k + 2).map(|g| g.to_string()).unwrap_or_default();
                    bad.push(format!("span {r:?} outside the input {input:?}: {message}"));
                }
            }
            TokenTree::Group(g) => bad.extend(misplaced_errors(&g.stream(), input)),
            _ => {}
        }
    }
    bad
}

/// The run-time reading of `text`: `None` when it behaves (diagnostics,
/// each at a place in the text, or a mechanism whose analyses run at a few
/// inputs without a panic and without a non-finite value in `Ok`).
fn judge_runtime(text: &str) -> Option<Verdict> {
    use mechanism_codegen::runtime::Mechanism;
    let text = text.to_string();
    let result = std::panic::catch_unwind(move || match Mechanism::new(&text) {
        Err(e) => e
            .diagnostics
            .iter()
            .find(|d| d.line == 0)
            .map(|d| format!("a diagnostic at no place in the text: {}", d.message)),
        Ok(m) => {
            let n = m.inputs().len();
            let finite = |v: &[f64]| v.iter().all(|x| x.is_finite());
            for k in 0..4 {
                let q = vec![0.3 + 1.7 * f64::from(k); n];
                let Ok(p) = m.position(&q) else { continue };
                let Ok(v) = m.velocity(&p, &vec![1.0; n]) else {
                    continue;
                };
                let a = m.acceleration(&p, &v, &vec![-0.5; n]);
                if !finite(&p.values) || !finite(&v.values) || a.is_ok_and(|a| !finite(&a.values)) {
                    return Some(format!("a non-finite output in Ok at {q:?}"));
                }
            }
            None
        }
    });
    match result {
        Ok(None) => None,
        Ok(Some(bad)) => Some(Verdict::CallSiteError(format!("run time: {bad}"))),
        Err(_) => {
            let message = PANIC_MESSAGE
                .lock()
                .map(|mut m| m.take().unwrap_or_default())
                .unwrap_or_default();
            Some(Verdict::Panic(format!("run time: {message}")))
        }
    }
}

fn judge(text: &str) -> Verdict {
    proc_macro2::extra::invalidate_current_thread_spans();
    if RUNTIME.load(std::sync::atomic::Ordering::Relaxed) {
        if let Some(v) = judge_runtime(text) {
            return v;
        }
    }
    let Ok(input) = text.parse::<TokenStream>() else {
        return Verdict::Unlexable;
    };
    let range = input_range(&input);
    let result = std::panic::catch_unwind(move || mechanism_codegen::expand(input));
    let out = match result {
        Ok(out) => out,
        Err(_) => {
            let message = PANIC_MESSAGE
                .lock()
                .map(|mut m| m.take().unwrap_or_default())
                .unwrap_or_default();
            return Verdict::Panic(message);
        }
    };
    if let Err(e) = syn::parse2::<syn::File>(out.clone()) {
        return Verdict::NotParsing(format!("{e}\n--- output ---\n{out}"));
    }
    let has_error = out.to_string().contains("compile_error");
    if !has_error {
        return Verdict::Ok(out.to_string());
    }
    if let Some(range) = range {
        let bad = misplaced_errors(&out, &range);
        if !bad.is_empty() {
            return Verdict::CallSiteError(bad.join("\n"));
        }
    }
    Verdict::Errors
}

// ------------------------------------------------------- compile sample ---

/// Batches of successful expansions compiled by `cargo check`, one batch at
/// a time in the background. The scratch crate turns on the facade's feature
/// `serde` and depends on serde: a definition that derives `Serialize`
/// expands without error but only compiles with both.
struct Compiler {
    root: PathBuf,
    pending: Vec<String>,
    running: Option<(Child, PathBuf, usize)>,
    batches: usize,
    compiled: usize,
    failures: usize,
}

impl Compiler {
    fn push(&mut self, expansion: String, seed: u64) {
        self.pending.push(expansion);
        if self.pending.len() >= COMPILE_BATCH {
            self.flush(seed);
        }
    }

    /// Starts a batch of what is pending (waiting for the previous one).
    fn flush(&mut self, seed: u64) {
        if self.pending.is_empty() {
            return;
        }
        self.wait();
        let dir = std::env::temp_dir().join(format!("mechanism-fuzz-{seed}-{}", self.batches));
        self.batches += 1;
        let _ = std::fs::create_dir_all(dir.join("src"));
        let manifest = format!(
            "[package]\nname = \"fuzz-sample\"\nversion = \"0.0.0\"\nedition = \"2021\"\npublish = false\n\n[dependencies]\nmechanism = {{ package = \"planar-mechanism\", path = {:?}, features = [\"serde\"] }}\nserde = {{ version = \"1\", features = [\"derive\"] }}\n\n[workspace]\n",
            self.root.display().to_string()
        );
        let mut lib = String::from("#![allow(warnings)]\n");
        for (k, e) in self.pending.iter().enumerate() {
            lib.push_str(&format!("pub mod case{k} {{\n{e}\n}}\n"));
        }
        let written = std::fs::write(dir.join("Cargo.toml"), manifest)
            .and_then(|_| std::fs::write(dir.join("src/lib.rs"), lib))
            .and_then(|_| {
                std::fs::copy(self.root.join("Cargo.lock"), dir.join("Cargo.lock")).map(|_| ())
            });
        if let Err(e) = written {
            eprintln!("compile sample: cannot write {}: {e}", dir.display());
            self.failures += 1;
            return;
        }
        let child = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()))
            .args([
                "check",
                "--tests",
                "--offline",
                "--quiet",
                "--message-format",
                "short",
            ])
            .current_dir(&dir)
            .env(
                "CARGO_TARGET_DIR",
                target_dir(&self.root).join("fuzz-expand-check"),
            )
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn();
        match child {
            Ok(c) => self.running = Some((c, dir, self.pending.len())),
            Err(e) => {
                eprintln!("compile sample: cannot run cargo: {e}");
                self.failures += 1;
            }
        }
        self.pending.clear();
    }

    /// Waits for the running batch and records its outcome.
    fn wait(&mut self) {
        let Some((child, dir, n)) = self.running.take() else {
            return;
        };
        match child.wait_with_output() {
            Ok(out) if out.status.success() => {
                self.compiled += n;
                let _ = std::fs::remove_dir_all(&dir);
            }
            Ok(out) => {
                self.failures += 1;
                eprintln!(
                    "compile sample FAILED: {} (kept)\n{}",
                    dir.display(),
                    String::from_utf8_lossy(&out.stderr)
                );
            }
            Err(e) => {
                self.failures += 1;
                eprintln!("compile sample: {e}");
            }
        }
    }

    /// `true` when the running batch has finished (recorded).
    fn poll(&mut self) {
        if let Some((child, _, _)) = &mut self.running {
            if matches!(child.try_wait(), Ok(Some(_))) {
                self.wait();
            }
        }
    }
}

// ----------------------------------------------------------------- main ---

#[derive(Default)]
struct Counts {
    by_source: BTreeMap<&'static str, u64>,
    unlexable: u64,
    ok: u64,
    errors: u64,
    panics: u64,
    hangs: u64,
    not_parsing: u64,
    call_site: u64,
}

fn save(out_dir: &Path, kind: &str, seed: u64, n: u64, text: &str, detail: &str) -> PathBuf {
    let _ = std::fs::create_dir_all(out_dir);
    let path = out_dir.join(format!("{kind}-{seed}-{n}.txt"));
    let body = format!(
        "{text}\n/* ---- {kind} ----\n{}\n*/\n",
        detail.replace("*/", "* /")
    );
    let _ = std::fs::write(&path, body);
    path
}

fn spawn_worker() -> (mpsc::Sender<String>, mpsc::Receiver<Verdict>) {
    let (job_tx, job_rx) = mpsc::channel::<String>();
    let (res_tx, res_rx) = mpsc::channel::<Verdict>();
    std::thread::Builder::new()
        .name("expand".into())
        .stack_size(WORKER_STACK)
        .spawn(move || {
            for text in job_rx {
                if res_tx.send(judge(&text)).is_err() {
                    break;
                }
            }
        })
        .expect("spawn the expansion thread");
    (job_tx, res_rx)
}

fn quiet_panics() {
    std::panic::set_hook(Box::new(|info| {
        let message = format!("{info}");
        if let Ok(mut m) = PANIC_MESSAGE.lock() {
            *m = Some(message);
        }
    }));
}

/// The message of each `compile_error!` in `out`.
fn error_messages(out: &TokenStream, into: &mut Vec<String>) {
    let trees: Vec<TokenTree> = out.clone().into_iter().collect();
    for (k, t) in trees.iter().enumerate() {
        match t {
            TokenTree::Ident(i) if i == "compile_error" => {
                into.push(trees.get(k + 2).map(|g| g.to_string()).unwrap_or_default())
            }
            TokenTree::Group(g) => error_messages(&g.stream(), into),
            _ => {}
        }
    }
}

fn repro(path: &Path) -> i32 {
    let Ok(text) = std::fs::read_to_string(path) else {
        eprintln!("cannot read {}", path.display());
        return 2;
    };
    // A saved case ends with a comment block: tokens only matter.
    quiet_panics();
    let (tx, rx) = spawn_worker();
    let _ = tx.send(text.clone());
    match rx.recv() {
        Ok(Verdict::Ok(out)) => println!(
            "ok, {} bytes:\n{}",
            out.len(),
            out.chars().take(2000).collect::<String>()
        ),
        Ok(Verdict::Errors) => {
            println!("errors, each on a user token:");
            if let Ok(input) = text.parse::<TokenStream>() {
                let mut messages = Vec::new();
                error_messages(&mechanism_codegen::expand(input), &mut messages);
                for m in messages {
                    println!("  {m}");
                }
            }
        }
        Ok(Verdict::Unlexable) => println!("not a token stream"),
        Ok(Verdict::Panic(m)) => println!("PANIC: {m}"),
        Ok(Verdict::NotParsing(m)) => println!("OUTPUT DOES NOT PARSE: {m}"),
        Ok(Verdict::CallSiteError(m)) => println!("ERROR NOT ON A USER TOKEN: {m}"),
        Err(_) => println!("worker died"),
    }
    0
}

/// Each definition of the corpus as a flat token list (empty where it does
/// not lex).
fn flattened(corpus: &[(String, String)]) -> Vec<Vec<Tok>> {
    corpus
        .iter()
        .map(|(_, body)| {
            let mut v = Vec::new();
            if let Ok(s) = body.parse::<TokenStream>() {
                flatten(s, &mut v);
            }
            v
        })
        .collect()
}

/// The distinct words of the corpus (the mutations' vocabulary), sorted.
fn word_list(flat: &[Vec<Tok>]) -> Vec<String> {
    let mut words: Vec<String> = flat
        .iter()
        .flatten()
        .filter(|t| is_word(t))
        .map(|t| t.text.clone())
        .collect();
    words.sort();
    words.dedup();
    words
}

/// The next case and its source: six in ten a mutant of a corpus
/// definition (with a donor's tokens), three in ten from the grammar, one
/// in ten random tokens.
fn next_case(
    rng: &mut fastrand::Rng,
    flat: &[Vec<Tok>],
    words: &[String],
) -> (&'static str, String) {
    match rng.u8(..10) {
        0..=5 => {
            let k = rng.usize(..flat.len());
            let donor = &flat[rng.usize(..flat.len())];
            let mut toks = flat[k].clone();
            mutate(rng, &mut toks, words, donor);
            ("mutant", render(&toks))
        }
        6..=8 => ("grammar", generate(rng)),
        _ => ("tokens", random_stream(rng, 0)),
    }
}

/// The run's one-line summary.
fn print_summary(n: u64, seconds: f64, counts: &Counts, compiler: &Compiler) {
    let sources: Vec<String> = counts
        .by_source
        .iter()
        .map(|(k, v)| format!("{k} {v}"))
        .collect();
    println!(
        "{n} cases in {seconds:.0} s ({}): not a token stream {}, ok {}, errors {}, panics {}, hangs {}, non-parsing {}, errors off the user's tokens {}; compiled {} expansions in {} batches, compile failures {}",
        sources.join(", "),
        counts.unlexable,
        counts.ok,
        counts.errors,
        counts.panics,
        counts.hangs,
        counts.not_parsing,
        counts.call_site,
        compiler.compiled,
        compiler.batches,
        compiler.failures,
    );
}

fn main() {
    let o = match options() {
        Ok(o) => o,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(2);
        }
    };
    if let Some(path) = &o.repro {
        std::process::exit(repro(path));
    }
    let root = repo_root();
    let out_dir = target_dir(&root).join("fuzz-expand");
    let corpus = corpus(&root);
    println!(
        "expand fuzzer: seed {} (replay with --seed {}), {} s, {} definitions from the repository, compile 1 in {}",
        o.seed, o.seed, o.seconds, corpus.len(), o.compile_sample
    );
    if corpus.is_empty() {
        eprintln!("no `mechanism! {{ .. }}` found under {}", root.display());
        std::process::exit(2);
    }
    let flat = flattened(&corpus);
    let words = word_list(&flat);

    quiet_panics();
    let (tx, rx) = spawn_worker();
    let mut rng = fastrand::Rng::with_seed(o.seed);
    let mut counts = Counts::default();
    let mut compiler = Compiler {
        root: root.clone(),
        pending: Vec::new(),
        running: None,
        batches: 0,
        compiled: 0,
        failures: 0,
    };
    let start = Instant::now();
    let limit = Duration::from_secs(o.seconds);
    let mut n = 0u64;
    let mut failures = Vec::new();
    let mut last_report = Instant::now();
    while start.elapsed() < limit {
        n += 1;
        let (source, text) = next_case(&mut rng, &flat, &words);
        *counts.by_source.entry(source).or_default() += 1;
        if last_report.elapsed() > Duration::from_secs(60) {
            last_report = Instant::now();
            eprintln!("{n} cases, {:.0} s", start.elapsed().as_secs_f64());
        }
        if tx.send(text.clone()).is_err() {
            eprintln!("the expansion thread died");
            std::process::exit(1);
        }
        let verdict = match rx.recv_timeout(Duration::from_millis(o.case_ms)) {
            Ok(v) => v,
            Err(_) => {
                counts.hangs += 1;
                let path = save(&out_dir, "hang", o.seed, n, &text, "over the time limit");
                failures.push(format!("hang: {}", path.display()));
                break;
            }
        };
        let (kind, detail) = match verdict {
            Verdict::Unlexable => {
                counts.unlexable += 1;
                continue;
            }
            Verdict::Errors => {
                counts.errors += 1;
                continue;
            }
            Verdict::Ok(out) => {
                counts.ok += 1;
                if o.compile_sample > 0 && rng.u64(..o.compile_sample) == 0 {
                    compiler.push(out, o.seed);
                }
                compiler.poll();
                continue;
            }
            Verdict::Panic(m) => {
                counts.panics += 1;
                ("panic", m)
            }
            Verdict::NotParsing(m) => {
                counts.not_parsing += 1;
                ("not-parsing", m)
            }
            Verdict::CallSiteError(m) => {
                counts.call_site += 1;
                ("call-site-error", m)
            }
        };
        let path = save(&out_dir, kind, o.seed, n, &text, &detail);
        let first_line = detail.lines().next().unwrap_or("").to_string();
        eprintln!("{kind}: {} ({first_line})", path.display());
        failures.push(format!("{kind}: {}", path.display()));
        if failures.len() >= 20 {
            break;
        }
    }
    if counts.hangs == 0 {
        compiler.flush(o.seed);
        compiler.wait();
    }
    print_summary(n, start.elapsed().as_secs_f64(), &counts, &compiler);
    if failures.is_empty() && compiler.failures == 0 {
        println!("no failure (seed {})", o.seed);
    } else {
        println!("FAILURES (seed {}):", o.seed);
        for f in &failures {
            println!("  {f}");
        }
        std::process::exit(1);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    // The corpus reader finds each body, skipping braces in comments and
    // strings, and both delimiters of a macro call.
    #[test]
    fn bodies_are_cut_at_their_own_braces() {
        let text = "mechanism! { a { b } // }\n c \"}\" }\nx mechanism!(d) mechanism! e";
        assert_eq!(bodies(text), vec![" a { b } // }\n c \"}\" ", "d"]);
    }

    // The span rule flags a `compile_error!` at the call site (byte range
    // 0..0) and passes one on a token of the input.
    #[test]
    fn errors_off_the_input_are_flagged() {
        proc_macro2::extra::invalidate_current_thread_spans();
        let input: TokenStream = "pub M { x }".parse().expect("tokens");
        let range = input_range(&input).expect("a range");
        let at_call_site = quote::quote!(::core::compile_error!("m"););
        assert_eq!(misplaced_errors(&at_call_site, &range).len(), 1);
        let on_input = syn::Error::new_spanned(&input, "m").to_compile_error();
        assert!(misplaced_errors(&on_input, &range).is_empty());
    }

    // Every verdict of a case the macro rejects is `Errors`, and a
    // definition of the repository expands.
    #[test]
    fn judge_tells_errors_from_expansions() {
        assert!(matches!(judge("pub M { let }"), Verdict::Errors));
        let ok = "pub M { let O = ground(0.0, 0.0); let O4 = ground(3.5, 0.0);
            let A = crank(O, 1.0, th) as l2; let B = rrr(A, 3.0, O4, 3.0, left) as (l3, l4); }";
        assert!(matches!(judge(ok), Verdict::Ok(_)));
        assert!(matches!(judge("pub M { ( }"), Verdict::Unlexable));
    }
}
