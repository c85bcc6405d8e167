//! No heap: a counting global allocator shows that evaluating every example
//! mechanism of `examples/common/scenes.rs` (position, velocity,
//! acceleration and, where defined, forces; f32 and f64, over a sweep of inputs, including poses that
//! fail to assemble) performs zero allocations.
//!
//! The counter is thread-local so that tests running in parallel (and the
//! test harness itself) do not interfere. The firmware in `tests/firmware`
//! proves the same for the target at link time: it has no global allocator,
//! so it would not link if anything used `alloc`.

#[path = "../examples/common/scenes.rs"]
mod scenes;

use mechanism::Real;
use scenes::*;
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::hint::black_box;

thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

/// The system allocator, counting allocations (and reallocations) made by
/// the current thread.
struct Counting;

// SAFETY: forwards every call unchanged to the system allocator; the counter
// is a const-initialized thread-local `Cell`, which never allocates.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// Allocations made by this thread while running `f`.
fn allocations(f: impl FnOnce()) -> usize {
    let before = ALLOCATIONS.with(Cell::get);
    f();
    ALLOCATIONS.with(Cell::get) - before
}

/// Inputs of the sweep (rad): a full turn and beyond, in 1 degree steps, so
/// that the range reduction of the sine and cosine and the poses where a
/// mechanism cannot assemble (typed errors) are both exercised.
fn sweep() -> impl Iterator<Item = f64> {
    (-360..=720).map(|d| (d as f64).to_radians())
}

/// Every scene at every input, in scalar `T`; returns how many evaluations
/// succeeded (so that the sweep is known to have done real work).
fn every_scene<T: Real>() -> usize {
    let l = T::lit;
    let mut ok = 0;
    let mut count = |r: Result<(), mechanism::Error<T>>| {
        if black_box(r).is_ok() {
            ok += 1;
        }
    };
    let (fb, sb, sh, sc, fv) = (
        FourBar::<T>::default(),
        SixBar::<T>::default(),
        Shaper::<T>::default(),
        SliderCrank::<T>::default(),
        FiveBar::<T>::default(),
    );
    let (sm, sf) = (SineMechanism::<T>::default(), ShaperForces::<T>::default());
    for q in sweep() {
        let q = black_box(q);
        count(
            fb.solve(
                &FourBarInput { theta2: l(q) },
                &FourBarInput { theta2: l(250.0) },
                &FourBarInput { theta2: l(2.0e4) },
            )
            .map(|s| {
                black_box(s);
            }),
        );
        count(
            sb.solve(
                &SixBarInput { phi1: l(q) },
                &SixBarInput { phi1: l(10.0) },
                &SixBarInput { phi1: l(-60.0) },
            )
            .map(|s| {
                black_box(s);
            }),
        );
        count(
            sh.solve(
                &ShaperInput { crank: l(q) },
                &ShaperInput { crank: l(1.0) },
                &ShaperInput { crank: l(0.7) },
            )
            .map(|s| {
                black_box(s);
            }),
        );
        count(
            sc.solve(
                &SliderCrankInput { theta: l(q) },
                &SliderCrankInput { theta: l(314.0) },
                &SliderCrankInput { theta: l(0.0) },
            )
            .map(|s| {
                black_box(s);
            }),
        );
        // The five-bar's two cranks: q and a second angle sweeping the other way.
        count(
            fv.solve(
                &FiveBarInput {
                    q1: l(q),
                    q2: l(1.2 - 0.5 * q),
                },
                &FiveBarInput {
                    q1: l(1.0),
                    q2: l(-2.0),
                },
                &FiveBarInput {
                    q1: l(0.5),
                    q2: l(0.0),
                },
            )
            .map(|s| {
                black_box(s);
            }),
        );
        // With forces (solve includes forces()).
        count(
            sm.solve(
                &SineMechanismInput { phi1: l(q) },
                &SineMechanismInput { phi1: l(10.0) },
                &SineMechanismInput { phi1: l(3.0) },
            )
            .map(|s| {
                black_box(s);
            }),
        );
        count(
            sf.solve(
                &ShaperForcesInput { crank: l(q) },
                &ShaperForcesInput { crank: l(1.0) },
                &ShaperForcesInput { crank: l(0.7) },
                &ShaperForcesLoads { cut: l(-5000.0) },
            )
            .map(|s| {
                black_box(s);
            }),
        );
    }
    ok
}

#[test]
fn the_counter_counts() {
    // Control: a real allocation is seen, so a zero below means something.
    assert_eq!(allocations(|| drop(black_box(Box::new(7u64)))), 1);
}

#[test]
fn every_example_scene_allocates_nothing_f64() {
    let mut ok = 0;
    let n = allocations(|| ok = every_scene::<f64>());
    assert_eq!(n, 0, "{n} allocations during the f64 sweep");
    // 1081 inputs x 7 scenes; some poses cannot assemble, most do.
    assert!(ok > 3500, "only {ok} evaluations succeeded");
}

#[test]
fn every_example_scene_allocates_nothing_f32() {
    let mut ok = 0;
    let n = allocations(|| ok = every_scene::<f32>());
    assert_eq!(n, 0, "{n} allocations during the f32 sweep");
    assert!(ok > 3500, "only {ok} evaluations succeeded");
}
