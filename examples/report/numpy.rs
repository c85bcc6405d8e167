//! numpy's whole-array closed form of the four-bar (position, velocity,
//! acceleration, angle outputs), run as a subprocess in the same run; skipped
//! when `python3` or numpy is missing.

use std::path::Path;
use std::process::Command;

/// The numpy program: the same vector-form equations as the hand-written
/// closed form, on whole arrays; times `rounds` interleaved repetitions and
/// writes t3, t4, w3, w4, al3, al4 per grid point to `out`.
const SCRIPT: &str = r#"
import sys, time, numpy as np
grid, w2, al2, rounds, out = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4]), sys.argv[5]
a, b, c, d = 101.6, 254.0, 177.8, 304.8
t2 = np.loadtxt(grid, dtype=np.float64)
n = t2.size
def solve(t2):
    s2, c2 = np.sin(t2), np.cos(t2)
    ax, ay = a * c2, a * s2
    dx, dy = d - ax, -ay
    dist2 = dx * dx + dy * dy
    dist = np.sqrt(dist2)
    along = (b * b - c * c + dist2) / (2.0 * dist)
    h = np.sqrt(b * b - along * along)
    ex, ey = dx / dist, dy / dist
    r3x, r3y = along * ex - h * ey, along * ey + h * ex
    r4x, r4y = r3x - dx, r3y - dy
    vax, vay = -w2 * ay, w2 * ax
    det = r3x * r4y - r3y * r4x
    w3 = -(vax * r4x + vay * r4y) / det
    w4 = -(vax * r3x + vay * r3y) / det
    aax, aay = -al2 * ay - w2 * w2 * ax, al2 * ax - w2 * w2 * ay
    wx = -aax + w3 * w3 * r3x - w4 * w4 * r4x
    wy = -aay + w3 * w3 * r3y - w4 * w4 * r4y
    al3 = (wx * r4x + wy * r4y) / det
    al4 = (wx * r3x + wy * r3y) / det
    return np.arctan2(r3y, r3x), np.arctan2(r4y, r4x), w3, w4, al3, al4
res = solve(t2)
reps = 200
samples = []
for _ in range(rounds):
    t = time.perf_counter_ns()
    for _ in range(reps):
        solve(t2)
    samples.append((time.perf_counter_ns() - t) / (reps * n))
np.savetxt(out, np.column_stack(res), fmt="%.17e", delimiter=",")
print(" ".join(repr(s) for s in samples))
print(np.__version__)
"#;

/// ns per evaluation per round, numpy's version, and its outputs per grid
/// point (t3, t4, w3, w4, al3, al4), or `None` when numpy is unavailable.
pub fn run(
    grid: &[f64],
    w2: f64,
    al2: f64,
    rounds: usize,
    dir: &Path,
) -> Option<(Vec<f64>, String, Vec<[f64; 6]>)> {
    let out = dir.join("numpy_fourbar.csv");
    let grid_path = dir.join("numpy_grid.csv");
    let text: Vec<String> = grid.iter().map(|x| format!("{x:.17e}")).collect();
    std::fs::write(&grid_path, text.join("\n")).ok()?;
    let o = Command::new("python3")
        .arg("-c")
        .arg(SCRIPT)
        .args([
            grid_path.display().to_string(),
            w2.to_string(),
            al2.to_string(),
            rounds.to_string(),
            out.display().to_string(),
        ])
        .output()
        .ok()?;
    if !o.status.success() {
        return None;
    }
    let text = String::from_utf8(o.stdout).ok()?;
    let mut lines = text.lines();
    let samples: Vec<f64> = lines
        .next()?
        .split_whitespace()
        .filter_map(|s| s.parse().ok())
        .collect();
    let version = lines.next().unwrap_or("?").to_string();
    let rows = std::fs::read_to_string(&out)
        .ok()?
        .lines()
        .map(|l| {
            let v: Vec<f64> = l.split(',').filter_map(|s| s.parse().ok()).collect();
            [v[0], v[1], v[2], v[3], v[4], v[5]]
        })
        .collect();
    Some((samples, version, rows))
}
