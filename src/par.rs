//! A batch over rayon's thread pool (feature `rayon`, needs `std`):
//! [`par_solve`], and the task latency it learns ([`par_task_ns`]).
//!
//! # How the work is shared
//!
//! The calling thread never waits for a sleeping thread to start its work.
//! The batch is cut into pieces; the calling thread and up to one helper
//! per other thread of the pool take pieces from one shared counter until
//! none is left. The calling thread starts on the first piece at once;
//! a helper that wakes late takes what is left, and one that wakes after
//! the last piece was taken finds nothing and ends. So on a pool whose
//! threads sleep the call costs at most the later of the serial work and
//! the helpers' wake-up (the scope still waits for every helper to end),
//! and on a pool whose threads are awake the work is shared from the
//! start. Halving the batch with `rayon::join` instead would, from a
//! thread outside the pool, hand even the first piece to a pool thread:
//! every split would wait for a wake-up before any work began
//! (docs/performance.md, "Over many cores").
//!
//! Helpers are invited only when the work is longer than the task latency
//! [`par_task_ns`], measured on this machine by the earlier splits: with
//! latency `L` and work `W` on one thread, `h` helpers that all start at
//! `L` finish the batch at about `L + (W - L) / (h + 1)`, which beats `W`
//! for every `h` exactly when `W > L`. Each split's time gives the `L` it
//! implies, whatever the cause of the loss (a late wake-up, a helper taken
//! off its core, a slower core), and the estimate follows it.
//!
//! The calling thread spawns one helper, and each helper spawns up to two
//! more before it works ([`invite`]): the wake-ups of a large pool run in
//! parallel instead of one after another on the calling thread.
//!
//! `rayon::in_place_scope` runs the scope's body on the calling thread
//! whether or not it belongs to the pool, which is what lets the caller
//! work at once; the pieces sit behind a `Mutex` each (taken once, never
//! contended: the counter hands each index to one thread), so this needs no
//! `unsafe`.

extern crate std;

use crate::batch::{BatchError, BatchSplit};
use core::sync::atomic::{AtomicU64, AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Instant;
use std::vec::Vec;

/// The task latency `par_solve` assumes before it has measured one, in ns:
/// the time until a helper thread of rayon's pool takes part in a split
/// (waking a sleeping thread, its start on a core).
///
/// From `benches/par_batch.rs` (`docs/performance.md`, "Over many cores"):
/// a few microseconds for a thread that is awake, tens for one that has
/// gone to sleep, on the 2-core machine of that table. After each split
/// `par_solve` measures what the split's time implies and follows that
/// ([`par_task_ns`]).
pub const PAR_TASK_NS: f64 = 10_000.0;

/// The range `par_solve`'s measured task latency is kept in, in ns: at
/// least 1 us (a wake-up never costs less), at most 250 us (a batch of half
/// a millisecond is always shared, so a busy spell cannot keep every later
/// batch on one thread, and later splits measure the latency again).
pub const PAR_TASK_NS_RANGE: (f64, f64) = (1_000.0, 250_000.0);

/// The first elements `par_solve` solves on the calling thread, timed: the
/// per-element cost its decision is made from (no wasted work: they are
/// part of the batch). 256 four-bar elements take 2 to 10 us, well above
/// the timer's resolution (tens of ns). It is also the smallest piece the
/// rest is cut into.
pub const PAR_PROBE: usize = 256;

/// Pieces per thread of the pool that the rest of a batch is cut into (each
/// of at least [`PAR_PROBE`] elements): enough that a helper arriving late
/// still finds work and that threads running at different speeds end within
/// about a piece of each other, few enough that taking a piece (an atomic
/// increment and an uncontended lock, well under a microsecond) is nothing
/// against solving it.
pub const PAR_PIECES_PER_THREAD: usize = 4;

/// The task latency `par_solve` weighs the next split against, in ns:
/// [`PAR_TASK_NS`] until the first split, then a running mean (weight 1/4
/// for each new split) of what the splits measured: the latency that each
/// split's time implies against its work estimated from the probe (the
/// helpers' late start, or their slower progress, as one start delay). On
/// a machine whose other cores are busy, or whose pool threads often
/// sleep, the splits gain less than an even share, so the latency grows
/// and small batches stay on one thread; when cores are free again the
/// next splits gain more and it falls. Shared by every
/// `par_solve` of the process; its value only moves the split, never a
/// result (each element is solved once, the same way, whatever the split).
pub fn par_task_ns() -> f64 {
    f64::from_bits(TASK_NS.load(Ordering::Relaxed))
}

static TASK_NS: AtomicU64 = AtomicU64::new(PAR_TASK_NS.to_bits());

/// The latency after a split whose time implied `seen_ns`
/// ([`implied_task_ns`]): a quarter of the way from `old` to `seen_ns`
/// (an exponential moving average, so the latency estimates the mean
/// loss, wake-ups of sleeping threads included at the rate they occur:
/// the mean is what the expected time of a split depends on),
/// the observation first kept in [`PAR_TASK_NS_RANGE`] (so one outlier,
/// such as the pool's first start, moves it by at most a quarter of the
/// range); a non-finite observation leaves `old`.
fn next_task_ns(old: f64, seen_ns: f64) -> f64 {
    let (lo, hi) = PAR_TASK_NS_RANGE;
    if !seen_ns.is_finite() {
        return old;
    }
    old + (seen_ns.clamp(lo, hi) - old) / 4.0
}

/// How the rest of a batch is shared: its pieces and the helpers invited.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Sharing {
    /// Pieces of equal size (to one element), at least 1.
    pieces: usize,
    /// Helper tasks besides the calling thread, 0 to `pieces - 1`.
    helpers: usize,
}

impl Sharing {
    /// The sharing of `m` elements at `per_element` ns each on a pool of
    /// `threads` threads with task latency `task_ns`, every piece at least
    /// `min_len` (and [`PAR_PROBE`]) elements: helpers only when the work
    /// is longer than the latency (then one per other thread, as many as
    /// the pieces allow: a helper that comes late costs nothing but its
    /// wake-up), [`PAR_PIECES_PER_THREAD`] pieces per thread that takes
    /// part. A cost that is zero or not a number (a timer that did not
    /// advance) keeps the work on the calling thread.
    fn new(m: usize, per_element: f64, min_len: usize, threads: usize, task_ns: f64) -> Self {
        let work = m as f64 * per_element;
        let most_pieces = (m / min_len.max(PAR_PROBE)).max(1);
        // A NaN work (or latency) stays whole: `partial_cmp` gives `None`.
        let worth = work.partial_cmp(&task_ns) == Some(core::cmp::Ordering::Greater);
        if !worth || threads <= 1 || most_pieces <= 1 {
            return Sharing {
                pieces: 1,
                helpers: 0,
            };
        }
        let pieces = most_pieces.min(threads * PAR_PIECES_PER_THREAD);
        Sharing {
            pieces,
            helpers: (threads - 1).min(pieces - 1),
        }
    }
}

/// Solves `batch` with `solve` over rayon's thread pool and returns the sum
/// of what `solve` returns (with `solve_batch`: the number of failed
/// elements). Feature `rayon` (needs `std`).
///
/// The split is decided by what the work costs against what a helper
/// thread costs to start: the first [`PAR_PROBE`] elements are solved on
/// the calling thread and timed, which gives the cost `c` of one element of
/// this mechanism on this machine; when the rest, `m` elements, takes
/// longer than the task latency `L` ([`par_task_ns`], measured on the
/// previous splits), it is cut into [`PAR_PIECES_PER_THREAD`] pieces per
/// thread (each of at least `min_len` and [`PAR_PROBE`] elements; pass 0
/// for no floor of your own), and the calling thread and one helper per
/// other thread of the pool take pieces until none is left. The calling
/// thread starts at once; a helper that wakes late takes what is left. A
/// rest cheaper than `L`, or a pool of one thread, stays on the calling
/// thread, so the call is never much slower than `solve(batch)`.
///
/// # Errors
///
/// The [`BatchError`] of [`BatchSplit::check`] when the slices of `batch`
/// differ in length, before `solve` is called on any piece; otherwise the
/// error `solve` returned for the first piece (in the batch's order) it
/// failed on.
///
/// ```
/// use mechanism::mechanism;
///
/// mechanism! {
///     pub FourBar {
///         params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
///         analysis position;
///         outputs { B }
///         let O2 = ground(0.0, 0.0);
///         let O4 = ground(ground, 0.0);
///         let A = crank(O2, crank, theta2) as link2;
///         let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
///     }
/// }
///
/// let n = 100_000;
/// let theta: Vec<f64> = (0..n).map(|k| k as f64 * 1e-4).collect(); // rad
/// let (mut bx, mut by, mut status) = (vec![0.0; n], vec![0.0; n], vec![0u8; n]);
/// let batch = FourBarBatch {
///     in_theta2: &theta,
///     pos_B_x: &mut bx,
///     pos_B_y: &mut by,
///     status: &mut status,
/// };
/// let fb = FourBar::<f64>::default();
/// let failed = mechanism::par_solve(batch, 0, &|mut piece| fb.solve_batch(&mut piece))?;
/// assert_eq!(failed, 0);
/// // Every element was solved: B lies right of the crank pivot (x >= 127 mm).
/// assert!(bx.iter().all(|&x| x > 100.0));
/// # Ok::<(), mechanism::BatchError>(())
/// ```
pub fn par_solve<B, F>(batch: B, min_len: usize, solve: &F) -> Result<usize, BatchError>
where
    B: BatchSplit,
    F: Fn(B) -> Result<usize, BatchError> + Sync,
{
    let n = batch.check()?;
    let threads = rayon::current_num_threads();
    if threads <= 1 || n <= PAR_PROBE {
        return solve(batch);
    }
    let (probe, rest) = batch.split_at(PAR_PROBE);
    let start = Instant::now();
    let failed = solve(probe)?;
    let per_element = start.elapsed().as_nanos() as f64 / PAR_PROBE as f64;
    let sharing = Sharing::new(rest.len(), per_element, min_len, threads, par_task_ns());
    if sharing.helpers == 0 {
        return Ok(failed + solve(rest)?);
    }
    let work_ns = rest.len() as f64 * per_element;
    let (result, elapsed_ns) = solve_shared(rest, sharing, solve);
    let seen = implied_task_ns(elapsed_ns, work_ns, sharing.helpers);
    let new = next_task_ns(par_task_ns(), seen);
    TASK_NS.store(new.to_bits(), Ordering::Relaxed);
    Ok(failed + result?)
}

/// The pieces of one shared batch and what their solving has returned.
struct Shared<B> {
    /// The pieces in the batch's order; each is taken once.
    pieces: Vec<Mutex<Option<B>>>,
    /// The next piece to take.
    next: AtomicUsize,
    /// The sum of the solved pieces' counts, and the error of the first
    /// piece (by index) that failed.
    total: Mutex<(usize, Option<(usize, BatchError)>)>,
}

impl<B: BatchSplit> Shared<B> {
    /// `batch` cut into `pieces` pieces of equal size (to one element).
    fn new(batch: B, pieces: usize) -> Self {
        let mut cut = Vec::with_capacity(pieces);
        let mut rest = batch;
        for left in (1..=pieces).rev() {
            let len = rest.len() / left;
            let (piece, after) = rest.split_at(len);
            cut.push(Mutex::new(Some(piece)));
            rest = after;
        }
        Shared {
            pieces: cut,
            next: AtomicUsize::new(0),
            total: Mutex::new((0, None)),
        }
    }

    /// Takes and solves pieces until none is left, then adds what they
    /// returned to the total.
    fn work<F>(&self, solve: &F)
    where
        F: Fn(B) -> Result<usize, BatchError> + Sync,
    {
        let (mut sum, mut first_error) = (0, None::<(usize, BatchError)>);
        loop {
            let k = self.next.fetch_add(1, Ordering::Relaxed);
            let Some(slot) = self.pieces.get(k) else {
                break;
            };
            // A lock is poisoned only by a panic while it is held; no code
            // that can panic runs under these, so the inner value is whole.
            let piece = slot.lock().unwrap_or_else(|e| e.into_inner()).take();
            match piece.map(solve) {
                Some(Ok(count)) => sum += count,
                Some(Err(e)) if first_error.is_none() => first_error = Some((k, e)),
                Some(Err(_)) | None => {}
            }
        }
        let mut total = self.total.lock().unwrap_or_else(|e| e.into_inner());
        total.0 += sum;
        total.1 = match (total.1, first_error) {
            (Some(a), Some(b)) => Some(if b.0 < a.0 { b } else { a }),
            (a, b) => a.or(b),
        };
    }
}

/// Solves `batch` in `sharing.pieces` pieces taken in turn by the calling
/// thread and `sharing.helpers` helper tasks on rayon's pool: the sum of
/// what `solve` returned, or the error of the first failed piece; and the
/// time from the first helper's spawn to the last helper's end, in ns.
fn solve_shared<B, F>(batch: B, sharing: Sharing, solve: &F) -> (Result<usize, BatchError>, f64)
where
    B: BatchSplit,
    F: Fn(B) -> Result<usize, BatchError> + Sync,
{
    let shared = Shared::new(batch, sharing.pieces);
    let began = Instant::now();
    rayon::in_place_scope(|scope| {
        invite(scope, &shared, solve, 0, sharing.helpers);
        shared.work(solve);
    });
    let elapsed = began.elapsed().as_nanos() as f64;
    let (sum, error) = shared.total.into_inner().unwrap_or_else(|e| e.into_inner());
    (error.map_or(Ok(sum), |(_, e)| Err(e)), elapsed)
}

/// Spawns helper `k` of `helpers` on `scope`: it first spawns helpers
/// `2k + 1` and `2k + 2` (when they exist), then takes pieces. The
/// invitations form a binary tree, so the calling thread spawns one task
/// (one wake-up of a sleeping thread, a system call) instead of one per
/// helper before its own work, and the wake-ups of a large pool run in
/// parallel, `log2(helpers)` deep.
fn invite<'s, B, F>(
    scope: &rayon::Scope<'s>,
    shared: &'s Shared<B>,
    solve: &'s F,
    k: usize,
    helpers: usize,
) where
    B: BatchSplit,
    F: Fn(B) -> Result<usize, BatchError> + Sync,
{
    if k < helpers {
        scope.spawn(move |scope| {
            invite(scope, shared, solve, 2 * k + 1, helpers);
            invite(scope, shared, solve, 2 * k + 2, helpers);
            shared.work(solve);
        });
    }
}

/// The task latency a split's time implies: with `helpers` helpers that
/// all start `L` after the split began and then work at the calling
/// thread's pace, `work_ns` of work ends at `T = L + (work_ns - L) /
/// (helpers + 1)`, so `L = ((helpers + 1) T - work_ns) / helpers`. It
/// counts whatever made the split slower than an even share of the work:
/// a helper that woke late, one that was taken off its core half-way, or
/// a core slower than the calling thread's. A split that gained nothing
/// (`T >= work_ns`) gives `L >= T >= work_ns`, so the same batch stays whole
/// next time. `helpers` 0 gives NaN (no observation).
fn implied_task_ns(elapsed_ns: f64, work_ns: f64, helpers: usize) -> f64 {
    let h = helpers as f64;
    ((h + 1.0) * elapsed_ns - work_ns) / h
}

#[cfg(test)]
mod tests {
    use super::Vec;
    use super::{
        implied_task_ns, next_task_ns, solve_shared, BatchError, BatchSplit, Sharing,
        PAR_PIECES_PER_THREAD, PAR_PROBE, PAR_TASK_NS, PAR_TASK_NS_RANGE,
    };
    use core::sync::atomic::{AtomicU8, Ordering};

    /// Helpers are invited exactly when the work is longer than the task
    /// latency, one per other thread; the rest is cut into
    /// `PAR_PIECES_PER_THREAD` pieces per thread of at least `PAR_PROBE`
    /// and `min_len` elements.
    #[test]
    fn sharing_follows_the_work_against_the_latency() {
        let l = PAR_TASK_NS;
        let whole = Sharing {
            pieces: 1,
            helpers: 0,
        };
        // 10 us of work against a latency of 10 us: whole.
        assert_eq!(Sharing::new(1000, 10.0, 0, 16, l), whole);
        // 10.01 us: 16 threads share it in 3 pieces of at least 256.
        assert_eq!(
            Sharing::new(1001, 10.0, 0, 16, l),
            Sharing {
                pieces: 3,
                helpers: 2
            }
        );
        // 100 latencies on 16 threads: 64 pieces, 15 helpers.
        let m = (100.0 * l / 10.0) as usize;
        let all = Sharing {
            pieces: 16 * PAR_PIECES_PER_THREAD,
            helpers: 15,
        };
        assert_eq!(Sharing::new(m, 10.0, 0, 16, l), all);
        // Pieces of at least m / 3 elements: 3 pieces, 2 helpers.
        let three = Sharing {
            pieces: 3,
            helpers: 2,
        };
        assert_eq!(Sharing::new(m, 10.0, m / 3, 16, l), three);
        // On 2 threads: 8 pieces, 1 helper.
        let two = Sharing::new(m, 10.0, 0, 2, l);
        assert_eq!((two.pieces, two.helpers), (8, 1));
        // The same work against a latency longer than it: whole.
        assert_eq!(Sharing::new(m, 10.0, 0, 16, 101.0 * l), whole);
        // A zero or NaN cost, one thread, or fewer than two probes' worth
        // of elements: whole.
        assert_eq!(Sharing::new(m, 0.0, 0, 16, l), whole);
        assert_eq!(Sharing::new(m, f64::NAN, 0, 16, l), whole);
        assert_eq!(Sharing::new(m, 10.0, 0, 1, l), whole);
        assert_eq!(Sharing::new(2 * PAR_PROBE - 1, 1e6, 0, 16, l), whole);
    }

    /// The measured latency moves a quarter of the way to each split's
    /// observation (kept in its range first), and ignores a non-finite
    /// observation.
    #[test]
    fn the_latency_follows_what_the_splits_measure() {
        let (lo, hi) = PAR_TASK_NS_RANGE;
        // 50 us seen at 10 us: 20 us.
        assert_eq!(next_task_ns(10_000.0, 50_000.0), 20_000.0);
        // Beyond the range: as if 250 us was seen.
        assert_eq!(
            next_task_ns(10_000.0, 1e12),
            10_000.0 + (hi - 10_000.0) / 4.0
        );
        // 10 us seen at 10 us: unchanged.
        assert_eq!(next_task_ns(10_000.0, 10_000.0), 10_000.0);
        // Late helpers repeatedly (a busy machine): it tends to the cap,
        // by 3/4 of the remaining distance per split.
        let mut l = PAR_TASK_NS;
        for _ in 0..200 {
            l = next_task_ns(l, 1e9);
        }
        assert!((l - hi).abs() < 1e-9 * hi, "{l}");
        // Helpers that start at once: it falls to the floor the same way;
        // one wake-up of 250 us among them lifts it by a quarter of the
        // range, and it halves again within three splits.
        for _ in 0..200 {
            l = next_task_ns(l, 0.0);
        }
        assert!((l - lo).abs() < 1e-9 * lo, "{l}");
        let woken = next_task_ns(l, 250_000.0);
        assert_eq!(woken, lo + (hi - lo) / 4.0);
        let later = (0..3).fold(woken, |l, _| next_task_ns(l, 0.0));
        assert!(later < woken / 2.0, "{later}");
        assert_eq!(next_task_ns(l, f64::NAN), l);
        assert_eq!(next_task_ns(l, f64::INFINITY), l);
    }

    /// The implied latency inverts `T = L + (W - L) / (h + 1)`: an even
    /// share with no delay implies 0, a split that took as long as the
    /// work on one thread implies at least that work, and no helper
    /// implies nothing (NaN, which leaves the estimate).
    #[test]
    fn a_split_time_implies_its_latency() {
        // 100 us of work, 3 helpers starting at 20 us: 20 + 80 / 4 = 40.
        assert_eq!(implied_task_ns(40_000.0, 100_000.0, 3), 20_000.0);
        assert_eq!(implied_task_ns(25_000.0, 100_000.0, 3), 0.0);
        assert_eq!(implied_task_ns(100_000.0, 100_000.0, 1), 100_000.0);
        assert!(implied_task_ns(150_000.0, 100_000.0, 1) >= 150_000.0);
        assert!(implied_task_ns(1.0, 1.0, 0).is_nan());
        assert_eq!(next_task_ns(5_000.0, implied_task_ns(1.0, 1.0, 0)), 5_000.0);
    }

    /// A batch of element indices `start..end` over a shared visit count
    /// per element; solving it fails with the index as `len` when it holds
    /// an element of `fail`.
    struct Indices<'a> {
        start: usize,
        end: usize,
        visits: &'a [AtomicU8],
        fail: &'a [usize],
    }

    impl BatchSplit for Indices<'_> {
        fn len(&self) -> usize {
            self.end - self.start
        }
        fn check(&self) -> Result<usize, BatchError> {
            Ok(self.len())
        }
        fn split_at(self, mid: usize) -> (Self, Self) {
            let mid = self.start + mid.min(self.len());
            (Indices { end: mid, ..self }, Indices { start: mid, ..self })
        }
    }

    fn solve(b: Indices<'_>) -> Result<usize, BatchError> {
        for v in &b.visits[b.start..b.end] {
            v.fetch_add(1, Ordering::Relaxed);
        }
        match b.fail.iter().find(|&&k| (b.start..b.end).contains(&k)) {
            Some(&k) => Err(BatchError::length_mismatch("fail", k, "start", b.start)),
            None => Ok(b.len()),
        }
    }

    /// Shared out over the pool, every element is solved exactly once,
    /// whatever the pieces and helpers (more helpers than the pool has
    /// threads, pieces that do not divide the length), the counts add up,
    /// and of several failing pieces the first in the batch's order gives
    /// the error.
    #[test]
    fn every_element_is_solved_once_and_the_first_error_wins() {
        let n = 10_007;
        for (pieces, helpers) in [(1, 0), (2, 1), (7, 3), (64, 15), (100, 99)] {
            let visits: Vec<AtomicU8> = (0..n).map(|_| AtomicU8::new(0)).collect();
            let batch = Indices {
                start: 0,
                end: n,
                visits: &visits,
                fail: &[],
            };
            let (r, elapsed) = solve_shared(batch, Sharing { pieces, helpers }, &solve);
            assert_eq!(r, Ok(n), "{pieces} pieces");
            assert!(elapsed > 0.0);
            assert!(visits.iter().all(|v| v.load(Ordering::Relaxed) == 1));
        }
        let visits: Vec<AtomicU8> = (0..n).map(|_| AtomicU8::new(0)).collect();
        // Pieces of about 100 elements: 9000 and 5000 fail, 5000 first.
        let batch = Indices {
            start: 0,
            end: n,
            visits: &visits,
            fail: &[9000, 5000],
        };
        let (r, _) = solve_shared(
            batch,
            Sharing {
                pieces: 100,
                helpers: 7,
            },
            &solve,
        );
        assert_eq!(r.map_err(|e| e.len), Err(5000));
        assert!(visits.iter().all(|v| v.load(Ordering::Relaxed) == 1));
    }
}
