//! The run-time mechanism (`mechanism_codegen::runtime::Mechanism`, a
//! definition read from text and evaluated by walking its plan) beside the
//! code `mechanism!` generates from the same text: ns per evaluation of the
//! position, of position + velocity + acceleration, and of those + the
//! forces, over the same grid, timed in the same interleaved rounds. The
//! outputs are the same numbers (`tests/runtime`), so only time is shown.

use crate::scenes::{FourBar, FourBarInput, ShaperForces, ShaperForcesInput, SixBar, SixBarInput};
use crate::stephenson::{Stephenson, StephensonInput};
use crate::timing::{self, Sweep};
use mechanism_codegen::runtime::Mechanism;
use std::cell::RefCell;
use std::fmt::Write as _;
use std::hint::black_box;

/// Interleaved rounds per figure.
const ROUNDS: usize = 11;
/// Shortest sample (ns).
const MIN_SAMPLE_NS: f64 = 5e6;
/// Grid points per definition.
const POINTS: usize = 360;
/// The target: run time at most this many times the generated code's.
const TARGET: f64 = 5.0;
/// Input rate (rad/s) and acceleration (rad/s^2) of every evaluation.
const RATE: f64 = 10.0;
const ACCEL: f64 = 0.0;

/// The text inside the braces of the `mechanism! {` that defines `pub
/// NAME {` in `source`.
fn definition(source: &str, name: &str) -> String {
    let mut rest = source;
    while let Some(at) = rest.find("mechanism! {") {
        let body = &rest[at + "mechanism! {".len()..];
        let mut depth = 1usize;
        let end = body.char_indices().find_map(|(i, c)| {
            match c {
                '{' => depth += 1,
                '}' => depth -= 1,
                _ => {}
            }
            (depth == 0).then_some(i)
        });
        let Some(end) = end else { break };
        if body[..end].contains(&format!("pub {name} {{")) {
            return body[..end].to_string();
        }
        rest = &body[end..];
    }
    panic!("no definition {name}")
}

/// The grid: `POINTS` values over `(lo, hi)`.
fn grid(lo: f64, hi: f64) -> Vec<f64> {
    (0..POINTS)
        .map(|k| lo + (hi - lo) * k as f64 / (POINTS - 1) as f64)
        .collect()
}

/// The run-time sweeps of one definition: position; + velocity and
/// acceleration; + forces (`None` without a force analysis). With `reuse`,
/// into storage made once (`position_into` and the like, what a caller
/// evaluating many inputs does); without, each call returns new storage
/// (`position` and the like).
fn runtime_sweeps<'a>(m: &'a Mechanism, g: &'a [f64], reuse: bool) -> [Option<Sweep<'a>>; 3] {
    if !reuse {
        return allocating_sweeps(m, g);
    }
    let pos = RefCell::new(m.new_position());
    let pos: Sweep = Box::new(move || {
        let mut s = 0.0;
        let p = &mut *pos.borrow_mut();
        for &q in g {
            if m.position_into(&[q], p).is_ok() {
                s += p.values[0];
            }
        }
        black_box(s)
    });
    let store = || {
        RefCell::new((
            m.new_position(),
            m.new_rates(),
            m.new_rates(),
            m.new_forces(),
        ))
    };
    let kin_store = store();
    let kin: Sweep = Box::new(move || {
        let mut s = 0.0;
        let (p, v, a, _) = &mut *kin_store.borrow_mut();
        for &q in g {
            let ok = m.position_into(&[q], p).is_ok()
                && m.velocity_into(p, &[RATE], v).is_ok()
                && m.acceleration_into(p, v, &[ACCEL], a).is_ok();
            if ok {
                s += a.values[0];
            }
        }
        black_box(s)
    });
    let forces_store = store();
    let forces: Option<Sweep> = m.has_forces().then(|| {
        Box::new(move || {
            let mut s = 0.0;
            let (p, v, a, f) = &mut *forces_store.borrow_mut();
            for &q in g {
                let ok = m.position_into(&[q], p).is_ok()
                    && m.velocity_into(p, &[RATE], v).is_ok()
                    && m.acceleration_into(p, v, &[ACCEL], a).is_ok()
                    && m.forces_into(p, v, a, f).is_ok();
                if ok {
                    s += f.values[0];
                }
            }
            black_box(s)
        }) as Sweep
    });
    [Some(pos), Some(kin), forces]
}

/// The run-time sweeps with new storage at each call.
fn allocating_sweeps<'a>(m: &'a Mechanism, g: &'a [f64]) -> [Option<Sweep<'a>>; 3] {
    let pos: Sweep = Box::new(move || {
        let mut s = 0.0;
        for &q in g {
            if let Ok(p) = m.position(&[q]) {
                s += p.values[0];
            }
        }
        black_box(s)
    });
    let kin: Sweep = Box::new(move || {
        let mut s = 0.0;
        for &q in g {
            let Ok(p) = m.position(&[q]) else { continue };
            let Ok(v) = m.velocity(&p, &[RATE]) else {
                continue;
            };
            if let Ok(a) = m.acceleration(&p, &v, &[ACCEL]) {
                s += a.values[0];
            }
        }
        black_box(s)
    });
    let forces: Option<Sweep> = m.has_forces().then(|| {
        Box::new(move || {
            let mut s = 0.0;
            for &q in g {
                let Ok(p) = m.position(&[q]) else { continue };
                let Ok(v) = m.velocity(&p, &[RATE]) else {
                    continue;
                };
                let Ok(a) = m.acceleration(&p, &v, &[ACCEL]) else {
                    continue;
                };
                if let Ok(f) = m.forces(&p, &v, &a) {
                    s += f.values[0];
                }
            }
            black_box(s)
        }) as Sweep
    });
    [Some(pos), Some(kin), forces]
}

/// The generated sweeps of `$ty` (input struct `$input { $i }`); with
/// `forces($($loads)*)` the forces too, called with those extra arguments.
macro_rules! generated {
    ($g:expr, $grid:expr, $input:ident { $i:ident } $(, forces($($loads:tt)*))?) => {{
        let (g, grid) = ($g, $grid);
        let inp = |x: f64| $input { $i: x };
        let pos: Sweep = Box::new(move || {
            let mut s = 0.0;
            for &q in grid {
                if let Ok(p) = g.position(&inp(q)) {
                    black_box(&p);
                    s += 1.0;
                }
            }
            black_box(s)
        });
        let kin: Sweep = Box::new(move || {
            let mut s = 0.0;
            for &q in grid {
                let Ok(p) = g.position(&inp(q)) else { continue };
                let Ok(v) = g.velocity(&p, &inp(RATE)) else { continue };
                if let Ok(a) = g.acceleration(&p, &v, &inp(ACCEL)) {
                    black_box(&a);
                    s += 1.0;
                }
            }
            black_box(s)
        });
        #[allow(unused_mut, unused_assignments)]
        let mut forces: Option<Sweep> = None;
        $(
            forces = Some(Box::new(move || {
                let mut s = 0.0;
                for &q in grid {
                    let Ok(p) = g.position(&inp(q)) else { continue };
                    let Ok(v) = g.velocity(&p, &inp(RATE)) else { continue };
                    let Ok(a) = g.acceleration(&p, &v, &inp(ACCEL)) else { continue };
                    if let Ok(f) = g.forces(&p, &v, &a $($loads)*) {
                        s += f.condition;
                    }
                }
                black_box(s)
            }));
        )?
        [Some(pos), Some(kin), forces]
    }};
}

/// One definition's row group: for each evaluation, generated ns, run
/// time ns into reused storage and with new storage each call (median,
/// min - max), the ratios, and whether the target (at most 5 times the
/// generated code, storage reused) is met.
fn rows(
    md: &mut String,
    name: &str,
    gen: [Option<Sweep>; 3],
    run: [Option<Sweep>; 3],
    fresh: [Option<Sweep>; 3],
) {
    let labels = [
        "position",
        "position + velocity + acceleration",
        "position + velocity + acceleration + forces",
    ];
    let mut sweeps: Vec<(&Sweep, usize)> = Vec::new();
    let mut which = Vec::new();
    for (k, ((g, r), f)) in gen.iter().zip(&run).zip(&fresh).enumerate() {
        if let (Some(g), Some(r), Some(f)) = (g, r, f) {
            sweeps.extend([(g, POINTS), (r, POINTS), (f, POINTS)]);
            which.push(k);
        }
    }
    let ns = timing::interleaved(&sweeps, ROUNDS, MIN_SAMPLE_NS);
    for (j, &k) in which.iter().enumerate() {
        let g = timing::stats(&ns[3 * j]);
        let r = timing::stats(&ns[3 * j + 1]);
        let f = timing::stats(&ns[3 * j + 2]);
        let ratio = r.0 / g.0;
        let _ = writeln!(
            md,
            "| {name} | {} | {:.1} ({:.1} - {:.1}) | {:.1} ({:.1} - {:.1}) | {ratio:.1} | {} | {:.1} ({:.1} - {:.1}) | {:.1} |",
            labels[k],
            g.0,
            g.1,
            g.2,
            r.0,
            r.1,
            r.2,
            if ratio <= TARGET { "met" } else { "not met" },
            f.0,
            f.1,
            f.2,
            f.0 / g.0
        );
    }
}

/// The section: one table, every definition's three evaluations.
pub fn section() -> String {
    let scenes = include_str!("../common/scenes.rs");
    let stephenson = include_str!("../common/stephenson.rs");
    let read = |src: &str, name: &str| {
        Mechanism::new(&definition(src, name)).unwrap_or_else(|e| panic!("{name}: {e}"))
    };
    let turn = grid(0.0, 2.0 * std::f64::consts::PI);
    let mut md = String::new();
    let _ = writeln!(md, "## The run-time mechanism beside the generated code\n");
    let _ = writeln!(
        md,
        "`mechanism_codegen::runtime::Mechanism` (what `mechanism table` and the Python package \
         evaluate: the definition's text read at run time, its plan walked in `f64`, each step \
         calling the core primitive the generated code calls) against the `f64` code \
         `mechanism!` generates from the same text, over the same {POINTS} inputs (a full turn; \
         the Stephenson six-bar over its range), rate {RATE} rad/s, acceleration {ACCEL} \
         rad/s^2; ns per evaluation, median (min - max) of {ROUNDS} interleaved rounds. The \
         numbers they give are the same bit for bit (`tests/runtime`). Made by \
         `REPORT_RUNTIME_ONLY=1 cargo run --release -p mechanism-dev --example report` (this \
         section alone) or with the whole report. How the run-time mechanism works: when the \
         text is read its plan is compiled, every name a statement reads or writes resolved to \
         a slot of flat storage and every dimension valued with the current parameters (again \
         on `set_param`, `set_mode`, `set_load`); each statement becomes its kind's step (a \
         struct of slots and numbers, defined in the kind's file beside its emitted code) \
         whose position, rates and forces make the core call the generated code makes. An \
         evaluation walks the steps in solve order, one dynamic call each, into storage made \
         once (`new_position`, `new_rates`, `new_forces` and the `*_into` methods: the run time \
         column): no allocation, no name looked up, no state boxed. What is left beside the \
         generated code: the call per step, the slot reads and writes with their bounds \
         checks, the groups' states kept in an enum, the outputs copied into a vector and \
         checked finite, and the inlining across steps the generated code gets (its whole \
         analysis is one straight-line function). The last two columns: the same evaluations \
         returning new storage from each call (`position`, `velocity`, `acceleration`, \
         `forces`), a few allocations per call.\n"
    );
    let _ = writeln!(
        md,
        "| definition | evaluation | generated ns | run time ns | ratio | run time at most {TARGET}x generated | run time, new storage per call, ns | ratio |\n|---|---|---:|---:|---:|---|---:|---:|"
    );
    let fb = FourBar::<f64>::default();
    let m = read(scenes, "FourBar");
    rows(
        &mut md,
        "FourBar",
        generated!(&fb, &turn, FourBarInput { theta2 }),
        runtime_sweeps(&m, &turn, true),
        runtime_sweeps(&m, &turn, false),
    );
    let sb = SixBar::<f64>::default();
    let m = read(scenes, "SixBar");
    rows(
        &mut md,
        "SixBar",
        generated!(&sb, &turn, SixBarInput { phi1 }),
        runtime_sweeps(&m, &turn, true),
        runtime_sweeps(&m, &turn, false),
    );
    let sf = ShaperForces::<f64>::default();
    let loads = Default::default();
    let m = read(scenes, "ShaperForces");
    rows(
        &mut md,
        "ShaperForces",
        generated!(&sf, &turn, ShaperForcesInput { crank }, forces(, &loads)),
        runtime_sweeps(&m, &turn, true),
        runtime_sweeps(&m, &turn, false),
    );
    let st = Stephenson::<f64>::default();
    let m = read(stephenson, "Stephenson");
    let range = m.inputs()[0].range.expect("a declared range");
    let on_range = grid(range.0, range.1);
    let loads = Default::default();
    rows(
        &mut md,
        "Stephenson (triad)",
        generated!(&st, &on_range, StephensonInput { phi }, forces(, &loads)),
        runtime_sweeps(&m, &on_range, true),
        runtime_sweeps(&m, &on_range, false),
    );
    md.push('\n');
    md
}
