//! The `mechanism` command end to end: `table --csv` against an independent
//! closed form of the four-bar, a failing pose as a comment and an empty
//! row, `check`'s rustc-style diagnostics and exit status, `emit`.

use std::path::PathBuf;
use std::process::{Command, Output};

/// A four-bar (O4 at (3, 0), crank 1, coupler 3, rocker 2.5, `B` left of
/// `A -> O4`), declared over theta in [0, 90] deg.
const FOUR_BAR: &str = "// a test four-bar
let O = ground(0.0, 0.0);
let O4 = ground(3.0, 0.0);
let A = crank(O, 1.0, theta) as link2;
let B = rrr(A, 3.0, O4, 2.5, left) as (link3, link4);
range theta = (0 deg, 90 deg);
";

/// Writes `text` to a fresh file named `name` under the target directory.
fn file(name: &str, text: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_mechanism"))
        .args(args)
        .output()
        .unwrap()
}

/// `B` by the law of cosines (not the core's formulation): from `A`
/// towards `O4`, turned by the angle at `A` of the triangle `A B O4`, to
/// the left.
fn closed_form_b(theta: f64) -> (f64, f64) {
    let (ax, ay) = (theta.cos(), theta.sin());
    let (dx, dy) = (3.0 - ax, -ay);
    let d = dx.hypot(dy);
    let cos_a = (9.0 + d * d - 6.25) / (2.0 * 3.0 * d);
    let turn = cos_a.acos();
    let base = dy.atan2(dx);
    (
        ax + 3.0 * (base + turn).cos(),
        ay + 3.0 * (base + turn).sin(),
    )
}

#[test]
fn table_csv_gives_the_closed_form_four_bar() {
    // Proves the CSV: a header with the inputs first and the generated
    // names with units, 73 rows for 0:90deg:73 with both ends exact, every
    // number round-trip (17 significant digits), `B` at the closed form
    // within 1e-13 (coordinates of size 3: a few roundings of each side).
    let path = file("fourbar.mech", FOUR_BAR);
    let out = run(&[
        "table",
        path.to_str().unwrap(),
        "--input",
        "theta=0:90deg:73",
        "--csv",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(header[0], "theta [rad]");
    let col = |n: &str| header.iter().position(|h| *h == n).unwrap();
    let (bx, by, l3) = (col("B.x [L]"), col("B.y [L]"), col("link3 [rad]"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 73);
    assert_eq!(rows[0][0], 0.0);
    assert_eq!(rows[72][0], 90f64.to_radians());
    for r in &rows {
        let (x, y) = closed_form_b(r[0]);
        assert!(
            (r[bx] - x).abs() < 1e-13 && (r[by] - y).abs() < 1e-13,
            "{r:?}"
        );
        let (ax, ay) = (r[0].cos(), r[0].sin());
        assert!((r[l3] - (y - ay).atan2(x - ax)).abs() < 1e-13);
    }
}

#[test]
fn a_failing_pose_is_a_comment_and_an_empty_row() {
    // Proves a pose where the four-bar cannot be assembled (the rocker
    // shortened at run time by `--param`) gives `# theta=...: error` and a
    // row with the input and empty outputs, the other rows their numbers.
    let text = FOUR_BAR
        .replace("2.5, left", "rocker, left")
        .replace("// a test four-bar", "params { rocker = 2.5 }");
    let path = file("param.mech", &text);
    let out = run(&[
        "table",
        path.to_str().unwrap(),
        "--input",
        "theta=90,180deg",
        "--param",
        "rocker=0.9",
        "--csv",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    // theta = 90 deg: A at (0, 1), sqrt(10) from O4, within [3 - 0.9, 3 +
    // 0.9]: assembles; theta = 180 deg: A at (-1, 0), 4 from O4 > 3.9: fails.
    assert_eq!(lines.len(), 4, "{text}");
    assert!(!lines[1].contains(",,"), "{}", lines[1]);
    assert!(
        lines[2].starts_with("# theta=") && lines[2].contains("`B`"),
        "{}",
        lines[2]
    );
    assert!(lines[3].ends_with(",,"), "{}", lines[3]);
}

#[test]
fn check_shows_errors_as_rustc_and_exits_1() {
    // Proves a misspelt point is reported with its place and underline,
    // status 1; a good definition status 0.
    let bad = FOUR_BAR.replace("3.0, O4, 2.5", "3.0, O5, 2.5");
    let path = file("bad.mech", &bad);
    let out = run(&["check", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.contains("cannot find point `O5`"), "{err}");
    assert!(err.contains("bad.mech:5:21"), "{err}");
    assert!(err.contains("|                     ^^"), "{err}");
    let good = file("good.mech", FOUR_BAR);
    assert_eq!(
        run(&["check", good.to_str().unwrap()]).status.code(),
        Some(0)
    );
}

#[test]
fn emit_writes_the_item() {
    // Proves `emit --name` wraps a body in `mechanism! { pub NAME { .. } }`.
    let path = file("emit.mech", FOUR_BAR);
    let out = run(&["emit", path.to_str().unwrap(), "--name", "Press"]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("mechanism! {\n    pub Press {\n        // a test four-bar"),
        "{text}"
    );
}

/// The coupler point of `synthesize`'s four-bar (`[r1, r2, r3, r4, rcx,
/// rcy, theta0, x0, y0]`) at crank angle `th2` from the ground link, `B`
/// left of `A -> O4`: circle intersection written here.
fn coupler_point(d: &[f64; 9], th2: f64) -> (f64, f64) {
    let [r1, r2, r3, r4, rcx, rcy, t0, x0, y0] = *d;
    let (ax, ay) = (x0 + r2 * (t0 + th2).cos(), y0 + r2 * (t0 + th2).sin());
    let (ox, oy) = (x0 + r1 * t0.cos(), y0 + r1 * t0.sin());
    let (dx, dy) = (ox - ax, oy - ay);
    let d = dx.hypot(dy);
    let a = (r3 * r3 - r4 * r4 + d * d) / (2.0 * d);
    let h = (r3 * r3 - a * a).sqrt();
    let (bx, by) = (ax + (a * dx - h * dy) / d, ay + (a * dy + h * dx) / d);
    let (ux, uy) = ((bx - ax) / r3, (by - ay) / r3);
    (ax + rcx * ux - rcy * uy, ay + rcx * uy + rcy * ux)
}

#[test]
fn synthesize_fits_a_known_crank_rocker_and_writes_a_definition_the_table_reads() {
    // Proves `synthesize`: targets from a crank-rocker (this file's circle
    // intersection) at prescribed angles are fitted exactly (objective at
    // rounding level, 1e-9 of the squared path size); the JSON's design
    // gives the same points by this file's formula (1e-9: the fit's own
    // residual); the definition written with -o, read by `table` at `phi =
    // theta0 + angle`, puts P there too. Then bad arguments: exit status 2
    // with the reason.
    let truth = [4.0, 1.2, 3.5, 4.5, 1.5, 1.0, 0.3, 0.5, -0.2];
    let angles: Vec<f64> = (0..7).map(|k| 0.4 + 0.6 * k as f64).collect();
    let mut args = vec!["synthesize".to_string()];
    for &a in &angles {
        let (x, y) = coupler_point(&truth, a);
        args.push(format!("--target={x:?},{y:?}"));
        args.push(format!("--angle={a:?}"));
    }
    let out_file = file("synthesized.mech", "");
    args.extend(
        [
            "--links=0:10",
            "--coords=-10:10",
            "--starts=100",
            "--hops=100",
            "--json",
            "-o",
        ]
        .map(String::from),
    );
    args.push(out_file.to_str().unwrap().to_string());
    let refs: Vec<&str> = args.iter().map(String::as_str).collect();
    let out = run(&refs);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let scale = 25.0;
    assert!(v["objective"].as_f64().unwrap() <= 1e-9 * scale, "{v}");
    let names = ["r1", "r2", "r3", "r4", "rcx", "rcy", "theta0", "x0", "y0"];
    let design = names.map(|n| v["design"][n].as_f64().unwrap());
    let got: Vec<f64> = v["angles"]
        .as_array()
        .unwrap()
        .iter()
        .map(|a| a.as_f64().unwrap())
        .collect();
    assert_eq!(got, angles);
    assert_eq!(v["mode"], "left");
    let written = std::fs::read_to_string(&out_file).unwrap();
    assert_eq!(v["definition"].as_str().unwrap(), written);
    let phis: Vec<String> = angles
        .iter()
        .map(|a| format!("{:?}", design[6] + a))
        .collect();
    let table = run(&[
        "table",
        out_file.to_str().unwrap(),
        "--input",
        &format!("phi={}", phis.join(",")),
        "--csv",
    ]);
    assert!(
        table.status.success(),
        "{}",
        String::from_utf8_lossy(&table.stderr)
    );
    let text = String::from_utf8(table.stdout).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| header.iter().position(|h| h.starts_with(n)).expect(n);
    let (px, py) = (col("P.x "), col("P.y "));
    for (line, &a) in lines.zip(&angles) {
        let cells: Vec<f64> = line.split(',').map(|c| c.parse().unwrap()).collect();
        let (wx, wy) = coupler_point(&truth, a);
        let (dx, dy) = coupler_point(&design, a);
        for (g, w, d) in [(cells[px], wx, dx), (cells[py], wy, dy)] {
            assert!(
                (g - w).abs() <= 1e-9 && (g - d).abs() <= 1e-9,
                "{g} {w} {d}"
            );
        }
    }
    for (bad, reason) in [
        (vec!["--target=1,2", "--target=3,4"], "at least 3"),
        (
            vec!["--target=1,2", "--target=3,4", "--target=5,x"],
            "--target `5,x`",
        ),
        (
            vec!["--target=1,2", "--target=3,4", "--target=5,6", "--angle=1"],
            "one crank angle per point",
        ),
        (
            vec![
                "--target=1,2",
                "--target=3,4",
                "--target=5,6",
                "--links=9:1",
            ],
            "lo < hi",
        ),
        (
            vec!["--target=1,2", "--target=3,4", "--target=5,6", "--starts=0"],
            "starts = 0",
        ),
    ] {
        let mut a = vec!["synthesize"];
        a.extend(bad);
        let out = run(&a);
        assert_eq!(out.status.code(), Some(2));
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(reason), "{err}");
    }
}
