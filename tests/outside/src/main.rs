//! A user's crate outside the repository's workspace (`.ci/run` builds and
//! runs it), depending on the facade by path with the features `serde` and
//! `rayon`. It checks what the issue's "done when" asks of such a crate:
//!
//! 1. the docs.rs quick start is `src/bin/quick_start.rs` verbatim (compared
//!    here with the crate page's sample, hidden lines dropped; `.ci/run` runs
//!    that binary too). Do not run `cargo fmt` here: it would reformat that
//!    copy (the root's `cargo fmt --all` does not reach this crate);
//! 2. a solution serializes to JSON holding the user's names only, and the
//!    parameters read back;
//! 3. a 10^5-element owned batch, on one thread (`solve_columns`) and over
//!    rayon's pool (`par_solve`), gives the same bits; the times of both are
//!    printed (not asserted: a loaded machine must not fail CI);
//! 4. a four-bar's circuit switched at run time closes its loop in both
//!    circuits, which are mirror images across the line from A to O4.
//!
//! Exits non-zero (a failed `assert!`) when a check fails.

use mechanism::{mechanism, Mode};
use std::time::Instant;

mechanism! {
    /// Seed 002's crank-rocker (mm), circuit chosen at run time, with a
    /// coupler mass for the force analysis; serializable.
    #[derive(serde::Serialize, serde::Deserialize)]
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8, circuit = left }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, circuit) as (link3, link4);
        let P = point(link3, from A, 120.0, 30 deg);
        mass link3 { m = 0.5, at = P };
    }
}

/// The crate page's quick start (the facade's `src/lib.rs`), as a reader of
/// docs.rs sees it: the doc comment's first Rust sample without its hidden
/// (`# `) lines.
fn quick_start_of_the_crate_page() -> String {
    let page = include_str!("../../../src/lib.rs");
    let doc: Vec<&str> = page
        .lines()
        .filter_map(|l| l.strip_prefix("//!"))
        .map(|l| l.strip_prefix(' ').unwrap_or(l))
        .collect();
    let start = doc
        .windows(2)
        .position(|w| w[0] == "```" && w[1] == "use mechanism::mechanism;")
        .expect("the quick start sample");
    let end = start + 1 + doc[start + 1..].iter().position(|l| *l == "```").unwrap();
    let shown = doc[start + 1..end]
        .iter()
        .filter(|l| !(l.trim_start().starts_with("# ") || l.trim() == "#"));
    shown.map(|l| format!("{l}\n")).collect()
}

fn check_quick_start() {
    assert_eq!(
        include_str!("bin/quick_start.rs"),
        quick_start_of_the_crate_page(),
        "src/bin/quick_start.rs is not the crate page's quick start"
    );
    println!("quick start: src/bin/quick_start.rs is the crate page's sample");
}

fn check_json() {
    let fb = FourBar::<f64>::default();
    let i = |theta2| FourBarInput { theta2 };
    let s = fb.solve(&i(0.5), &i(250.0), &i(0.0)).expect("assembles");
    let json = serde_json::to_string(&s).expect("serializes");
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    for part in ["position", "velocity", "acceleration", "forces"] {
        assert!(v[part].is_object(), "{part} missing: {json}");
    }
    assert!(!json.contains("grp_"), "hidden fields in {json}");
    assert_eq!(v["position"]["B"][0].as_f64(), Some(s.position.B.x));
    let back: FourBar =
        serde_json::from_str(&serde_json::to_string(&fb).unwrap()).expect("reads back");
    assert_eq!(back, fb);
    println!(
        "json: {} bytes, e.g. \"position\": {}",
        json.len(),
        v["position"]
    );
}

fn check_batch() {
    let n = 100_000;
    let fb = FourBar::<f64>::default();
    let fill = || {
        let mut b = FourBar::<f64>::batch(n);
        b.in_theta2 = (0..n)
            .map(|k| k as f64 * (std::f64::consts::TAU / n as f64))
            .collect();
        b.rate_theta2 = vec![250.0; n];
        b
    };
    let (mut serial, mut parallel) = (fill(), fill());
    // Best of five, each over the whole batch.
    let (mut t1, mut tp) = (f64::INFINITY, f64::INFINITY);
    for _ in 0..5 {
        let t = Instant::now();
        // The kinematics alone, as the parallel run below: `solve_columns`
        // of a definition with masses fills the force columns too.
        assert_eq!(fb.solve_batch(&mut serial.as_batch()).unwrap(), 0);
        t1 = t1.min(t.elapsed().as_secs_f64());
        let t = Instant::now();
        let failed = mechanism::par_solve(parallel.as_batch(), 0, &|mut piece| {
            fb.solve_batch(&mut piece)
        });
        assert_eq!(failed.unwrap(), 0);
        tp = tp.min(t.elapsed().as_secs_f64());
    }
    assert_eq!(serial, parallel, "par_solve wrote other values");
    println!(
        "batch of {n}: one thread {:.2} ns/element, rayon ({} threads) {:.2} ns/element",
        t1 * 1e9 / n as f64,
        rayon_threads(),
        tp * 1e9 / n as f64
    );
}

fn rayon_threads() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

fn check_circuits() {
    let mut fb = FourBar::<f64>::default();
    for k in 0..360 {
        let input = FourBarInput {
            theta2: (k as f64).to_radians(),
        };
        fb.circuit = Mode::Plus;
        let left = fb.position(&input).expect("left assembles");
        fb.circuit = Mode::Minus;
        let right = fb.position(&input).expect("right assembles");
        for p in [&left, &right] {
            assert!(((p.B - p.A).norm() - fb.coupler).abs() < 1e-9);
            assert!(((p.B - p.O4).norm() - fb.rocker).abs() < 1e-9);
        }
        // Mirror images across A -> O4: B's sides are opposite.
        let side = |b: &mechanism::Point2<f64>| {
            let (d, r) = (left.O4 - left.A, b - left.A);
            d.x * r.y - d.y * r.x
        };
        assert!(side(&left.B) > 0.0 && side(&right.B) < 0.0, "at {k} deg");
    }
    println!("circuits: both close the loop at 360 crank angles, on opposite sides of A -> O4");
}

fn main() {
    check_quick_start();
    check_json();
    check_batch();
    check_circuits();
}
