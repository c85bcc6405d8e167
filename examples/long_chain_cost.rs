//! Long chains of Assur groups: the definitions of `tests/long_chain.rs` and
//! what they cost the macro (a measurement, not a test).
//!
//! - `cargo run --release --example long_chain_cost -- --defs` prints the
//!   definitions that `tests/long_chain.rs` holds (they were pasted from this
//!   output; the generator is the functions below);
//! - `cargo run --example long_chain_cost` (dev profile: the profile rustc
//!   builds proc macros in) or with `--release`: for chains of 5 to 160
//!   groups, the time of `mechanism_codegen::expand` (median of 5), the size
//!   of its output (token bytes and lines after `prettyplease`), the deepest
//!   nesting of delimited groups in the output, and the sizes per group.
//!
//! Two families:
//!
//! - the zigzag ladder: a crank of radius 0.5 about `G0 = (0, 0)`, then `n`
//!   RRR groups, each a parallelogram on the last point and the other ground
//!   pivot (`G1 = (1, 0)` or `G0`), coupler 1 and rocker 0.5, so every point
//!   `X_k` is `G_(k mod 2) + 0.5 (cos theta, sin theta)` exactly (the test's
//!   reference) and every group's condition is `|sin theta|`;
//! - the mixed chain: blocks of five groups (RRR, RPP, PRP on a guide carried
//!   by the RPP's yoke, RRP, RPR) with a point on the RPR's rocker starting
//!   the next block, every link with a mass (at a point on the link), gravity,
//!   a couple, a fixed force and a per-call load along a guide.
//!
//! Ladder with a faulty group: as the ladder, but group `X<k>`'s coupler is
//! 0.9, so that group alone cannot be assembled for `theta` above about
//! 135.2 deg (the range declared stops at 120 deg).

#[macro_use]
#[path = "common/cli.rs"]
mod cli;

use std::fmt::Write as _;
use std::str::FromStr;
use std::time::Instant;

/// The zigzag ladder of `n` RRR groups; `forces` adds masses on every link,
/// gravity and a per-call brake couple on the last rocker; `short` makes
/// group `X<short>`'s coupler 0.9 and the range (10, 120) deg.
pub fn ladder(name: &str, n: usize, forces: bool, short: Option<usize>) -> String {
    let mut s = String::new();
    let hi = if short.is_some() { 120 } else { 170 };
    writeln!(s, "    pub {name} {{").unwrap();
    if forces {
        writeln!(s, "        loads {{ brake = 0.0 }}").unwrap();
    }
    writeln!(s, "        let G0 = ground(0.0, 0.0);").unwrap();
    writeln!(s, "        let G1 = ground(1.0, 0.0);").unwrap();
    writeln!(s, "        let X0 = crank(G0, 0.5, theta) as k0;").unwrap();
    for k in 1..=n {
        let mode = if k % 2 == 1 { "left" } else { "right" };
        let l = if short == Some(k) { "0.9" } else { "1.0" };
        writeln!(
            s,
            "        let X{k} = rrr(X{}, {l}, G{}, 0.5, {mode}) as (c{k}, r{k});",
            k - 1,
            k % 2
        )
        .unwrap();
        if forces {
            writeln!(
                s,
                "        let M{k} = point(c{k}, from X{}, 0.5, 0 deg);",
                k - 1
            )
            .unwrap();
        }
    }
    writeln!(s, "        range theta = (10 deg, {hi} deg);").unwrap();
    if forces {
        writeln!(s, "        mass k0 {{ m = 0.7, at = X0, j = 0.02 }};").unwrap();
        for k in 1..=n {
            let m = 1.0 + 0.125 * (k % 5) as f64;
            let mr = 0.5 + 0.25 * (k % 3) as f64;
            writeln!(s, "        mass c{k} {{ m = {m:?}, at = M{k}, j = 0.08 }};").unwrap();
            writeln!(
                s,
                "        mass r{k} {{ m = {mr:?}, at = X{k}, j = 0.01 }};"
            )
            .unwrap();
        }
        writeln!(s, "        gravity (0.0, -9.81);").unwrap();
        writeln!(s, "        torque on r{n} = brake;").unwrap();
    }
    writeln!(s, "    }}").unwrap();
    s
}

/// Block `b`'s pivot `H_b = (b (5 + DX), -b (2 + H))`.
pub const DX: f64 = 3.38;
/// See [`DX`].
pub const H: f64 = 0.45;

/// The mixed chain of `blocks` blocks (5 groups each), with a force analysis.
pub fn mixed(name: &str, blocks: usize) -> String {
    let mut s = String::new();
    let f = |x: f64| format!("{x:?}");
    writeln!(s, "    pub {name} {{").unwrap();
    writeln!(s, "        loads {{ push = 0.0 }}").unwrap();
    writeln!(s, "        let H0 = ground(0.0, 0.0);").unwrap();
    writeln!(s, "        let E0 = crank(H0, 1.0, theta) as crank;").unwrap();
    writeln!(s, "        let K0 = point(crank, from H0, 0.5, 0 deg);").unwrap();
    let mut masses = vec!["crank { m = 0.6, at = K0, j = 0.02 }".to_string()];
    for b in 0..blocks {
        let hx = b as f64 * (5.0 + DX);
        let hy = -(b as f64) * (2.0 + H);
        let (nx, ny) = (hx + 5.0 + DX, hy - 2.0 - H);
        let n = b + 1;
        let lines = [
            format!("let R{b} = ground({}, {});", f(hx + 2.0), f(hy)),
            format!("let C{b} = rrr(E{b}, 2.0, R{b}, 1.0, left) as (cpl{b}, rock{b});"),
            format!(
                "let gh{b} = guide(({}, {}), 0 deg);",
                f(hx + 2.0),
                f(hy - 3.0)
            ),
            format!(
                "let Q{b} = rpp(C{b}, gh{b}, 90 deg) as (blkq{b}, yoke{b}) slide (sq{b}, tq{b});"
            ),
            format!("let gq{b} = guide(Q{b}, yoke{b}, 45 deg);"),
            format!("let gv{b} = guide(({}, {}), 90 deg);", f(hx + 5.0), f(hy)),
            format!("let F{b} = prp(gq{b}, gv{b}) as (pa{b}, pb{b}) slide (u{b}, v{b});"),
            format!(
                "let gs{b} = guide(({}, {}), 0 deg);",
                f(hx + 5.0),
                f(hy - 2.0)
            ),
            format!("let S{b} = rrp(F{b}, 4.0, gs{b}, plus) as (rod{b}, sl{b}) slide w{b};"),
            format!("let H{n} = ground({}, {});", f(nx), f(ny)),
            format!("let z{b} = rpr(S{b}, H{n}, plus) as (blks{b}, lout{b});"),
            format!("let E{n} = point(lout{b}, from H{n}, 1.0, 0 deg);"),
            // centres of mass: a point on every link
            format!("let Mc{b} = point(cpl{b}, from E{b}, 1.0, 0 deg);"),
            format!("let Mr{b} = point(rock{b}, from R{b}, 0.5, 0 deg);"),
            format!("let Mq{b} = point(blkq{b}, from C{b}, (0.1, 0.05));"),
            format!("let My{b} = point(yoke{b}, from Q{b}, (0.3, 0.2));"),
            format!("let Ma{b} = point(pa{b}, from F{b}, (0.1, 0.0));"),
            format!("let Mb{b} = point(pb{b}, from F{b}, (0.0, 0.1));"),
            format!("let Md{b} = point(rod{b}, from F{b}, 2.0, 0 deg);"),
            format!("let Ms{b} = point(sl{b}, from S{b}, (0.2, -0.1));"),
            format!("let Mk{b} = point(blks{b}, from S{b}, (0.1, 0.1));"),
            format!("let Mo{b} = point(lout{b}, from H{n}, 0.6, 10 deg);"),
        ];
        for l in lines {
            writeln!(s, "        {l}").unwrap();
        }
        let m = |i: usize| f(0.5 + 0.125 * ((b * 11 + i) % 7) as f64);
        masses.extend([
            format!("cpl{b} {{ m = {}, at = Mc{b}, j = 0.3 }}", m(0)),
            format!("rock{b} {{ m = {}, at = Mr{b}, j = 0.05 }}", m(1)),
            format!("blkq{b} {{ m = {}, at = Mq{b} }}", m(2)),
            format!("yoke{b} {{ m = {}, at = My{b} }}", m(3)),
            format!("pa{b} {{ m = {}, at = Ma{b} }}", m(4)),
            format!("pb{b} {{ m = {}, at = Mb{b} }}", m(5)),
            format!("rod{b} {{ m = {}, at = Md{b}, j = 1.2 }}", m(6)),
            format!("sl{b} {{ m = {}, at = Ms{b} }}", m(7)),
            format!("blks{b} {{ m = {}, at = Mk{b}, j = 0.004 }}", m(8)),
            format!("lout{b} {{ m = {}, at = Mo{b}, j = 0.09 }}", m(9)),
        ]);
    }
    writeln!(s, "        range theta = (50 deg, 130 deg);").unwrap();
    for m in masses {
        writeln!(s, "        mass {m};").unwrap();
    }
    let last = blocks - 1;
    writeln!(s, "        gravity (0.0, -9.81);").unwrap();
    writeln!(s, "        torque on rock0 = 0.3;").unwrap();
    writeln!(s, "        force at My0 = (0.5, -0.2);").unwrap();
    writeln!(
        s,
        "        force at S{last} on sl{last} along gs{last} = -push;"
    )
    .unwrap();
    writeln!(s, "    }}").unwrap();
    s
}

/// Deepest nesting of delimited groups (`()`, `[]`, `{}`) in `ts`.
fn depth(ts: proc_macro2::TokenStream) -> usize {
    ts.into_iter()
        .map(|t| match t {
            proc_macro2::TokenTree::Group(g) => 1 + depth(g.stream()),
            _ => 0,
        })
        .max()
        .unwrap_or(0)
}

fn measure(label: &str, groups: usize, body: &str) {
    let tokens = proc_macro2::TokenStream::from_str(body).expect("tokens");
    let mut times = Vec::new();
    let mut out = proc_macro2::TokenStream::new();
    for _ in 0..5 {
        let t = Instant::now();
        out = mechanism_codegen::expand(tokens.clone());
        times.push(t.elapsed().as_secs_f64() * 1e3);
    }
    times.sort_by(f64::total_cmp);
    let bytes = out.to_string().len();
    let nest = depth(out.clone());
    let file: syn::File = syn::parse2(out).expect("expansion is valid Rust");
    let text = prettyplease::unparse(&file);
    let lines = text.lines().count();
    let compile_errors = text.matches("compile_error").count();
    outln!(
        "{label:>8} {groups:>4} groups: expand {:9.2} ms ({:6.3} ms/group), {bytes:>8} B ({:6} B/group), {lines:>6} lines ({:5} lines/group), nesting {nest}, compile_error! {compile_errors}",
        times[2],
        times[2] / groups as f64,
        bytes / groups,
        lines / groups
    );
}

fn main() {
    let args = cli::parse(
        "long_chain_cost",
        "What long chains of Assur groups cost the macro: expansion time, output size and nesting for 5 to 160 groups.",
        &[
            cli::flag("--defs", "print the definitions of tests/long_chain.rs instead"),
            cli::Opt {
                name: "--show",
                value: Some("N"),
                help: "print the expansion of a ladder of N groups instead",
            },
        ],
    );
    if args.flag("--defs") {
        for (name, n) in [("Ladder10", 10), ("Ladder20", 20), ("Ladder40", 40)] {
            outln!("mechanism! {{\n{}}}\n", ladder(name, n, true, None));
        }
        outln!(
            "mechanism! {{\n{}}}\n",
            ladder("Faulty20", 20, false, Some(13))
        );
        for (name, b) in [("Mixed10", 2), ("Mixed20", 4), ("Mixed40", 8)] {
            outln!("mechanism! {{\n{}}}\n", mixed(name, b));
        }
        return;
    }
    if let Some(n) = args.value("--show") {
        let Ok(n) = n.parse::<usize>() else {
            eprintln!("error: `--show N` needs a number of groups, got `{n}`");
            std::process::exit(2);
        };
        let out = mechanism_codegen::expand(
            proc_macro2::TokenStream::from_str(&ladder("L", n, true, None)).expect("tokens"),
        );
        let file: syn::File = syn::parse2(out).expect("expansion is valid Rust");
        out!("{}", prettyplease::unparse(&file));
        return;
    }
    outln!(
        "profile: {}",
        if cfg!(debug_assertions) {
            "dev"
        } else {
            "release"
        }
    );
    for n in [5, 10, 20, 40, 80, 160] {
        measure("ladder", n, &ladder("L", n, false, None));
    }
    for n in [5, 10, 20, 40, 80, 160] {
        measure("ladder+F", n, &ladder("L", n, true, None));
    }
    for b in [1, 2, 4, 8, 16, 32] {
        measure("mixed+F", 5 * b, &mixed("M", b));
    }
}
