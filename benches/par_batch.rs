//! `par_solve` against the single-thread batch, from 10^3 to 10^6 elements:
//! the measurement behind `mechanism::PAR_TASK_NS` (`docs/performance.md`,
//! "Over many cores"). A four-bar (outputs A, B, link3, link4 at three
//! levels: 18 output columns), f64 and f32; per size, nanoseconds per element
//! of each method, the minimum and the median over interleaved rounds of at
//! least 2 ms each (the minimum is the round least disturbed by other
//! processes: on a shared machine it is the figure to compare) of
//!
//! - `serial`: `solve_batch` on the calling thread;
//! - `halves-512`: the batch halved recursively down to pieces of at most
//!   512 elements, each half joined with `rayon::join`;
//! - `per-thread`: one piece per thread of the pool at every size;
//! - `par_solve`: the library's function (`min_len` 0);
//! - `blocks min/max`: what a sweep that wants each output's range (not
//!   every row) does: blocks of 4096 elements on rayon's pool, each solved
//!   into its thread's scratch columns (made once per thread) and reduced to
//!   every column's smallest and largest value, so that only the inputs
//!   cross the memory bus (24 bytes per `f64` element instead of 169).
//!
//! The last column is the task latency `par_solve` has measured by the end
//! of the size's rounds (`mechanism::par_task_ns`). With
//! `RAYON_NUM_THREADS` above the machine's cores it shows the rules on a
//! pool with more threads than free cores.
//!
//! `cargo bench --features rayon --bench par_batch` (prints a Markdown table;
//! `PAR_BATCH_ROUNDS` sets the rounds, 51 by default).

use mechanism::{mechanism, BatchSplit};
use std::hint::black_box;
use std::time::{Duration, Instant};

mechanism! {
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
    }
}

/// One thread's output columns for a block of elements, made once per thread
/// and reused block after block (they stay in the cache): the `blocks`
/// policy.
struct Scratch<T> {
    out: Vec<Vec<T>>,
    status: Vec<u8>,
}

/// The inputs, 18 output columns and the status of `n` elements.
struct Buffers<T> {
    theta: Vec<T>,
    w: Vec<T>,
    a: Vec<T>,
    out: Vec<Vec<T>>,
    status: Vec<u8>,
}

macro_rules! impl_buffers {
    ($t:ty) => {
        impl Buffers<$t> {
            fn new(n: usize) -> Self {
                Buffers {
                    theta: (0..n)
                        .map(|k| (k as f64 * 0.1).to_radians() as $t)
                        .collect(),
                    w: vec![250.0; n],
                    a: vec![0.0; n],
                    out: vec![vec![0.0; n]; 18],
                    status: vec![0; n],
                }
            }

            fn view(&mut self) -> FourBarBatch<'_, $t> {
                view(
                    &self.theta,
                    &self.w,
                    &self.a,
                    &mut self.out,
                    &mut self.status,
                )
            }

            /// The batch of the elements `range` of `self`'s inputs into
            /// `scratch` (18 columns and a status of at least its length).
            fn block<'a>(
                &'a self,
                range: std::ops::Range<usize>,
                scratch: &'a mut Scratch<$t>,
            ) -> FourBarBatch<'a, $t> {
                let k = range.len();
                for c in &mut scratch.out {
                    c.truncate(k);
                }
                scratch.status.truncate(k);
                view(
                    &self.theta[range.clone()],
                    &self.w[range.clone()],
                    &self.a[range],
                    &mut scratch.out,
                    &mut scratch.status,
                )
            }
        }

        impl Scratch<$t> {
            /// 18 output columns and a status of `block` elements.
            fn new(block: usize) -> Self {
                Scratch {
                    out: vec![vec![0.0; block]; 18],
                    status: vec![0; block],
                }
            }

            /// Back to `block` elements after a shorter last block.
            fn reset(&mut self, block: usize) {
                for c in &mut self.out {
                    c.resize(block, 0.0);
                }
                self.status.resize(block, 0);
            }

            /// Each column's smallest and largest value over the block, and
            /// the block's failed elements (status not 0).
            fn min_max(&self) -> ([($t, $t); 18], usize) {
                let mut r = [(<$t>::INFINITY, <$t>::NEG_INFINITY); 18];
                for (m, c) in r.iter_mut().zip(&self.out) {
                    // Eight running minima and maxima (the loop vectorizes;
                    // one accumulator would wait on each comparison).
                    let (mut lo, mut hi) = ([<$t>::INFINITY; 8], [<$t>::NEG_INFINITY; 8]);
                    let mut chunks = c.chunks_exact(8);
                    for ch in &mut chunks {
                        for j in 0..8 {
                            lo[j] = if ch[j] < lo[j] { ch[j] } else { lo[j] };
                            hi[j] = if ch[j] > hi[j] { ch[j] } else { hi[j] };
                        }
                    }
                    for &x in chunks.remainder().iter().chain(&lo).chain(&hi) {
                        *m = (m.0.min(x), m.1.max(x));
                    }
                }
                (r, self.status.iter().filter(|&&s| s != 0).count())
            }
        }
    };
}
/// The batch of the inputs `theta`, `w`, `a` into the 18 columns of
/// `out` and `status`.
fn view<'a, T: mechanism::Real>(
    theta: &'a [T],
    w: &'a [T],
    a: &'a [T],
    out: &'a mut [Vec<T>],
    status: &'a mut [u8],
) -> FourBarBatch<'a, T> {
    let mut o = out.iter_mut().map(|v| v.as_mut_slice());
    let mut nx = || o.next().expect("18 columns");
    FourBarBatch {
        in_theta2: theta,
        rate_theta2: w,
        accel_theta2: a,
        pos_A_x: nx(),
        pos_A_y: nx(),
        pos_B_x: nx(),
        pos_B_y: nx(),
        pos_link3: nx(),
        pos_link4: nx(),
        vel_A_x: nx(),
        vel_A_y: nx(),
        vel_B_x: nx(),
        vel_B_y: nx(),
        vel_link3: nx(),
        vel_link4: nx(),
        acc_A_x: nx(),
        acc_A_y: nx(),
        acc_B_x: nx(),
        acc_B_y: nx(),
        acc_link3: nx(),
        acc_link4: nx(),
        status,
    }
}

impl_buffers!(f64);
impl_buffers!(f32);

/// Halves `b` recursively until pieces have at most `leaf` elements.
fn halves<B: BatchSplit, F: Fn(B) -> usize + Sync>(b: B, leaf: usize, f: &F) -> usize {
    let n = b.len();
    if n <= leaf {
        return f(b);
    }
    let (lo, hi) = b.split_at(n / 2);
    let (x, y) = rayon::join(|| halves(lo, leaf, f), || halves(hi, leaf, f));
    x + y
}

/// `pieces` equal pieces, joined pairwise.
fn per_thread<B: BatchSplit, F: Fn(B) -> usize + Sync>(b: B, pieces: usize, f: &F) -> usize {
    if pieces <= 1 {
        return f(b);
    }
    let left = pieces / 2;
    let mid = b.len() * left / pieces;
    let (lo, hi) = b.split_at(mid);
    let (x, y) = rayon::join(
        || per_thread(lo, left, f),
        || per_thread(hi, pieces - left, f),
    );
    x + y
}

const POLICIES: [&str; 5] = [
    "serial",
    "halves-512",
    "per-thread",
    "par_solve",
    "blocks min/max",
];

/// Elements per block of the `blocks` policy: 4096 elements of 18 `f64`
/// columns are 590 kB of scratch per thread, within a core's L2.
const BLOCK: usize = 4096;

/// Nanoseconds per element of each policy at `n` elements: (minimum, median)
/// over `rounds`.
macro_rules! measure {
    ($t:ty, $n:expr, $rounds:expr) => {{
        let n: usize = $n;
        let m = FourBar::<$t>::default();
        let mut buf = Buffers::<$t>::new(n);
        let threads = rayon::current_num_threads();
        // The lengths are equal by construction: the batch's check cannot fail.
        let solve = |mut b: FourBarBatch<'_, $t>| m.solve_batch(&mut b).unwrap_or(usize::MAX);
        let checked =
            |b: FourBarBatch<'_, $t>| -> Result<usize, mechanism::BatchError> { Ok(solve(b)) };
        // Every column's smallest and largest value and the failed count,
        // block by block on rayon's pool, nothing stored per element.
        let blocks = |buf: &Buffers<$t>| -> usize {
            use rayon::prelude::*;
            let n = buf.theta.len();
            thread_local! {
                static SCRATCH: std::cell::RefCell<Scratch<$t>> =
                    std::cell::RefCell::new(Scratch::<$t>::new(BLOCK));
            }
            let (range, failed) = (0..n.div_ceil(BLOCK))
                .into_par_iter()
                .map(|k| {
                    SCRATCH.with_borrow_mut(|scratch| {
                        let r = k * BLOCK..((k + 1) * BLOCK).min(n);
                        scratch.reset(BLOCK);
                        let _ = m.solve_batch(&mut buf.block(r, scratch));
                        scratch.min_max()
                    })
                })
                .reduce(
                    || ([(<$t>::INFINITY, <$t>::NEG_INFINITY); 18], 0),
                    |(a, fa), (b, fb)| {
                        let mut r = a;
                        for (x, y) in r.iter_mut().zip(b) {
                            *x = (x.0.min(y.0), x.1.max(y.1));
                        }
                        (r, fa + fb)
                    },
                );
            black_box(range);
            failed
        };
        let mut run = |p: usize| -> usize {
            let b = buf.view();
            match p {
                0 => solve(b),
                1 => halves(b, 512, &solve),
                2 => per_thread(b, threads, &solve),
                3 => mechanism::par_solve(b, 0, &checked).unwrap_or(usize::MAX),
                _ => blocks(&buf),
            }
        };
        // Repetitions per timed sample: at least 2 ms of the serial batch.
        let t0 = Instant::now();
        black_box(run(0));
        let once = t0.elapsed().max(Duration::from_nanos(1));
        let reps = (Duration::from_millis(2).as_nanos() / once.as_nanos()).max(1) as u32;
        let mut ns: Vec<Vec<f64>> = vec![Vec::new(); POLICIES.len()];
        for _ in 0..$rounds {
            for (p, v) in ns.iter_mut().enumerate() {
                let t = Instant::now();
                for _ in 0..reps {
                    assert_eq!(black_box(run(p)), 0, "the four-bar assembles everywhere");
                }
                v.push(t.elapsed().as_nanos() as f64 / reps as f64 / n as f64);
            }
        }
        ns.into_iter()
            .map(|mut v| {
                v.sort_by(f64::total_cmp);
                (v[0], v[v.len() / 2])
            })
            .collect::<Vec<(f64, f64)>>()
    }};
}

fn main() {
    let rounds: usize = std::env::var("PAR_BATCH_ROUNDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(51);
    let sizes = [
        1_000, 2_000, 4_000, 8_000, 16_000, 32_000, 64_000, 100_000, 300_000, 1_000_000,
    ];
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!(
        "threads {}, load average {}",
        rayon::current_num_threads(),
        load.split_whitespace()
            .take(3)
            .collect::<Vec<_>>()
            .join(" ")
    );
    println!("\nns per element, minimum / median over {rounds} rounds");
    println!(
        "\n| elements | scalar | {} | `par_task_ns` after (us) |",
        POLICIES.join(" | ")
    );
    println!("|---:|---|{}---:|", "---:|".repeat(POLICIES.len()));
    let mut targets = Vec::new();
    for &n in &sizes {
        let r64 = measure!(f64, n, rounds);
        let r32 = measure!(f32, n, rounds);
        for (t, r) in [("f64", r64), ("f32", r32)] {
            let cells: Vec<String> = r
                .iter()
                .map(|(lo, med)| format!("{lo:.2} / {med:.2}"))
                .collect();
            let latency = mechanism::par_task_ns() / 1e3;
            println!("| {n} | {t} | {} | {latency:.1} |", cells.join(" | "));
            targets.push(target_line(n, t, &r));
        }
    }
    println!(
        "\nTargets (issue 35, item 4: `par_solve` within 0.8 of the best of serial, halves-512 \
         and per-thread, here on {} threads; ratio = best / par_solve, by the minima and by the \
         medians):\n",
        rayon::current_num_threads()
    );
    for line in targets {
        println!("{line}");
    }
}

/// The target line of one size and type: the best fixed way (`serial`,
/// `halves-512`, `per-thread`: the first three policies) over
/// `par_solve` (the fourth), by the minima and by the medians, each at
/// least 0.8 to be met.
fn target_line(n: usize, t: &str, r: &[(f64, f64)]) -> String {
    let best = |f: fn(&(f64, f64)) -> f64| r[..3].iter().map(f).fold(f64::INFINITY, f64::min);
    let (lo, med) = (best(|x| x.0) / r[3].0, best(|x| x.1) / r[3].1);
    let met = if lo >= 0.8 && med >= 0.8 {
        "**met**"
    } else {
        "**not met**"
    };
    format!(
        "- {n} elements, {t}: par_solve {:.2} / {:.2} ns, best fixed {:.2} / {:.2}: ratio {lo:.2} / {med:.2} (target >= 0.8): {met}",
        r[3].0,
        r[3].1,
        best(|x| x.0),
        best(|x| x.1)
    )
}
