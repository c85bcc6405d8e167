//! `mechanism draw`, `animate`, `chart` and `table --forces` end to end,
//! each against geometry or statics written here: the drawn joints where
//! the law of cosines puts them, one animation frame per pose the
//! triangle inequality lets assemble, a chart's series with a gap where the
//! four-bar breaks, and a crank holding a mass against gravity.

use std::path::PathBuf;
use std::process::{Command, Output};

/// A four-bar: ground `O` (0, 0) and `O4` (3, 0), crank 1, coupler 3,
/// rocker the parameter `rocker` (2.5 unless set: a crank-rocker), `B`
/// left of `A -> O4`.
const FOUR_BAR: &str = "params { rocker = 2.5 }
let O = ground(0.0, 0.0);
let O4 = ground(3.0, 0.0);
let A = crank(O, 1.0, theta) as link2;
let B = rrr(A, 3.0, O4, rocker, left) as (link3, link4);
";

/// Writes `text` to a fresh file named `name` under the target directory.
fn file(name: &str, text: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("pictures");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

fn run(args: &[&str]) -> Output {
    let out = Command::new(env!("CARGO_BIN_EXE_mechanism"))
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

/// The value of attribute `attr` in the SVG element text `el`.
fn attr(el: &str, attr: &str) -> f64 {
    let key = format!(" {attr}=\"");
    let at = el.find(&key).unwrap_or_else(|| panic!("no {attr} in {el}")) + key.len();
    let end = el[at..].find('"').unwrap() + at;
    el[at..end].parse().unwrap()
}

/// The screen centre of the joint circle named `name` (the first one).
fn joint(svg: &str, name: &str) -> (f64, f64) {
    let key = format!("data-name=\"{name}\" cx=");
    let at = svg.find(&key).unwrap_or_else(|| panic!("no joint {name}"));
    let start = svg[..at].rfind('<').unwrap();
    let end = svg[at..].find('>').unwrap() + at;
    let el = &svg[start..end];
    (attr(el, "cx"), attr(el, "cy"))
}

/// `B` of the four-bar by the law of cosines, from `A` towards `O4`
/// turned left by the angle at `A`; `None` when the triangle cannot close.
fn closed_form_b(theta: f64, ground: f64, coupler: f64, rocker: f64) -> Option<(f64, f64)> {
    let (ax, ay) = (theta.cos(), theta.sin());
    let (dx, dy) = (ground - ax, -ay);
    let d = dx.hypot(dy);
    let cos_a = (coupler * coupler + d * d - rocker * rocker) / (2.0 * coupler * d);
    if !(-1.0..=1.0).contains(&cos_a) {
        return None;
    }
    let turn = dy.atan2(dx) + cos_a.acos();
    Some((ax + coupler * turn.cos(), ay + coupler * turn.sin()))
}

#[test]
fn draw_puts_the_joints_where_the_law_of_cosines_does() {
    // Proves `draw --at theta=30deg`: with the screen map fixed by the two
    // ground pivots (a uniform scale, y up), `A` and `B` are drawn at the
    // closed form's places. Tolerance 0.03 px: coordinates are written with
    // two decimals (0.005 px each), and the scale taken from `O4`'s rounded
    // place errs by at most 0.01 px / 3 per unit over coordinates below 3.
    let path = file("draw.mech", FOUR_BAR);
    let svg_path = path.with_extension("svg");
    run(&[
        "draw",
        path.to_str().unwrap(),
        "--at",
        "theta=30deg",
        "-o",
        svg_path.to_str().unwrap(),
    ]);
    let svg = std::fs::read_to_string(&svg_path).unwrap();
    assert!(svg.contains("theta = 30 deg"), "the caption");
    let (o, o4) = (joint(&svg, "O"), joint(&svg, "O4"));
    assert!((o.1 - o4.1).abs() < 0.01, "the ground line is horizontal");
    let scale = (o4.0 - o.0) / 3.0;
    let screen = |x: f64, y: f64| (o.0 + scale * x, o.1 - scale * y);
    let theta = 30f64.to_radians();
    let (bx, by) = closed_form_b(theta, 3.0, 3.0, 2.5).unwrap();
    for (name, (x, y)) in [("A", (theta.cos(), theta.sin())), ("B", (bx, by))] {
        let (want, got) = (screen(x, y), joint(&svg, name));
        assert!(
            (want.0 - got.0).abs() < 0.03 && (want.1 - got.1).abs() < 0.03,
            "{name}: drawn at {got:?}, expected {want:?}"
        );
    }
}

#[test]
fn animate_has_a_frame_per_pose_that_assembles_and_breaks_the_path() {
    // Proves `animate`: with the rocker set to 0.9 at run time the
    // four-bar closes only where 2.1 <= |A O4| <= 3.9 (not around 0 and
    // 180 deg): the animation has one frame per pose the triangle
    // inequality allows, and the traced path of `A` is two runs.
    let (g, c, r) = (3.0, 3.0, 0.9);
    let path = file("animate.mech", FOUR_BAR);
    let out = run(&[
        "animate",
        path.to_str().unwrap(),
        "--input",
        "theta=0:360deg:90",
        "--param",
        "rocker=0.9",
        "--trace",
        "A",
    ]);
    let svg = String::from_utf8(out.stdout).unwrap();
    let mut expected = 0;
    for k in 0..90 {
        let theta = 360f64.to_radians() * k as f64 / 89.0;
        let d = (g - theta.cos()).hypot(theta.sin());
        // No pose within 1e-6 of a limit: the count does not hang on
        // rounding.
        assert!((d - (c + r)).abs() > 1e-6 && (d - (c - r)).abs() > 1e-6);
        expected += usize::from(c - r <= d && d <= c + r);
    }
    assert!(expected > 0 && expected < 90, "{expected}");
    assert_eq!(svg.matches("<g class=\"frame\"").count(), expected);
    assert_eq!(svg.matches("class=\"path\" data-name=\"A\"").count(), 2);
}

#[test]
fn chart_series_have_one_point_per_pose_and_a_gap() {
    // Proves `chart --outputs B,link3`: `B.x` and `B.y` together, `link3`,
    // each series a path through the poses that assemble (the rocker 0.9
    // as in `animate`'s test), broken where it fails: two runs.
    let (g, c, r) = (3.0, 3.0, 0.9);
    let path = file("chart.mech", FOUR_BAR);
    let out = run(&[
        "chart",
        path.to_str().unwrap(),
        "--input",
        "theta=0:360deg:90",
        "--param",
        "rocker=0.9",
        "--outputs",
        "B,link3",
    ]);
    let svg = String::from_utf8(out.stdout).unwrap();
    let assembled = (0..90)
        .filter(|&k| {
            let theta = 360f64.to_radians() * k as f64 / 89.0;
            closed_form_b(theta, g, c, r).is_some()
        })
        .count();
    for series in ["B.x", "B.y", "link3"] {
        let key = format!("data-series=\"{series}\"");
        let at = svg
            .find(&key)
            .unwrap_or_else(|| panic!("no series {series}"));
        let end = svg[at..].find("/>").unwrap() + at;
        let el = &svg[at..end];
        let d_at = el.find(" d=\"").unwrap() + 4;
        let d = &el[d_at..el[d_at..].find('"').unwrap() + d_at];
        let moves = d.matches('M').count();
        let points = moves + d.matches('L').count();
        assert_eq!(points, assembled, "{series}: {d}");
        assert_eq!(moves, 2, "{series}: one gap");
    }
}

#[test]
fn table_forces_of_a_crank_holding_a_mass() {
    // Proves `table --forces`: a crank of radius 0.5 with 2 kg at its tip
    // under gravity 9.81 down, at rest (no rates given): statics gives the
    // pivot's force (0, m g) on the crank and the driving torque m g r
    // cos(theta) (counter-clockwise positive), headers named as the
    // generated struct's fields with their units. 1e-12: products of a few
    // numbers of size 10 rounded once or twice each.
    let path = file(
        "hold.mech",
        "units { length = \"m\", force = \"N\", mass = \"kg\" }
let O = ground(0.0, 0.0);
let A = crank(O, 0.5, theta) as arm;
mass arm { m = 2.0, at = A };
gravity (0.0, -9.81);
",
    );
    let out = run(&[
        "table",
        path.to_str().unwrap(),
        "--input",
        "theta=0:360deg:13",
        "--forces",
        "--csv",
    ]);
    let text = String::from_utf8(out.stdout).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| {
        header
            .iter()
            .position(|h| *h == n)
            .unwrap_or_else(|| panic!("no {n} in {header:?}"))
    };
    let (fx, fy, tau) = (
        col("forces.r_ground_arm.x [N]"),
        col("forces.r_ground_arm.y [N]"),
        col("forces.drive_theta [N m]"),
    );
    col("forces.condition [1]");
    let mut rows = 0;
    for line in lines {
        let r: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        let theta = r[0];
        assert!(r[fx].abs() < 1e-12, "{line}");
        assert!((r[fy] - 2.0 * 9.81).abs() < 1e-12, "{line}");
        assert!(
            (r[tau] - 2.0 * 9.81 * 0.5 * theta.cos()).abs() < 1e-12,
            "{line}"
        );
        rows += 1;
    }
    assert_eq!(rows, 13);
}

#[test]
fn help_shows_an_example_per_command() {
    // Proves every command's --help ends with an example of itself.
    for cmd in ["check", "table", "draw", "animate", "chart", "emit"] {
        let out = run(&[cmd, "--help"]);
        let text = String::from_utf8(out.stdout).unwrap();
        assert!(text.contains(&format!("mechanism {cmd} ")), "{cmd}: {text}");
    }
}
