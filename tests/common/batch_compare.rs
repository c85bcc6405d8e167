//! The batch-versus-scalar comparison of the test crates `tests/batch/` and
//! `tests/long_chain.rs`, included with `#[path]` and `#[macro_use]`; see
//! `tests/batch/examples.rs`'s module documentation for the four points
//! checked and for the tolerance `K`.
//!
//! `compare!` takes, before its other arguments, the analysis level of the
//! definition (`pos;`, `vel;`, `acc;`; without one, `acc`): a definition
//! written `analysis position` has no velocity code, no `vel_*`/`acc_*`
//! slices, and its statuses are 0 or 1. At the position level there is no
//! velocity `condition` to scale the error by: it is taken as 1 (the
//! definitions compared at that level stay away from their singular poses).
// Definitions without outputs leave the buffers' closure and the scalar
// results unread.
#![allow(dead_code, unused_macros, unused_variables)]

use std::collections::HashMap;

/// `(worst error in eps of the column scale times condition^2, lane rejects
/// of elements the scalar path solves, failed elements)`.
pub type Found = (f64, usize, usize);

/// Bound on the scaled error (see `tests/batch/examples.rs`'s module documentation).
pub const K: f64 = 64.0;

/// The number of levels of `pos`, `vel`, `acc`.
macro_rules! levels {
    (pos) => {
        1usize
    };
    (vel) => {
        2usize
    };
    (acc) => {
        3usize
    };
}

/// The batch view of definition `$ty` (analysis level `$lv`) over the input
/// maps `$q`, `$w`, `$a` and the output buffers `$bufs` (positions,
/// velocities, accelerations; points as x, y, then the scalar outputs), with
/// status slice `$st`.
macro_rules! batch {
    (pos; $ty:ident, [$($i:ident),*], [$($p:ident),*], [$($s:ident),*], $q:expr, $w:expr, $a:expr, $bufs:expr, $st:expr) => {{
        paste::paste! {
            let mut o = $bufs.iter_mut().map(|v| v.as_mut_slice());
            #[allow(unused_mut, unused_variables)]
            let mut nx = || o.next().unwrap();
            [<$ty Batch>] {
                $([<in_ $i>]: &$q[stringify!($i)],)*
                $([<pos_ $p _x>]: nx(), [<pos_ $p _y>]: nx(),)*
                $([<pos_ $s>]: nx(),)*
                status: $st,
            }
        }
    }};
    (vel; $ty:ident, [$($i:ident),*], [$($p:ident),*], [$($s:ident),*], $q:expr, $w:expr, $a:expr, $bufs:expr, $st:expr) => {{
        paste::paste! {
            let mut o = $bufs.iter_mut().map(|v| v.as_mut_slice());
            #[allow(unused_mut, unused_variables)]
            let mut nx = || o.next().unwrap();
            [<$ty Batch>] {
                $([<in_ $i>]: &$q[stringify!($i)],)*
                $([<rate_ $i>]: &$w[stringify!($i)],)*
                $([<pos_ $p _x>]: nx(), [<pos_ $p _y>]: nx(),)*
                $([<pos_ $s>]: nx(),)*
                $([<vel_ $p _x>]: nx(), [<vel_ $p _y>]: nx(),)*
                $([<vel_ $s>]: nx(),)*
                status: $st,
            }
        }
    }};
    (acc; $ty:ident, [$($i:ident),*], [$($p:ident),*], [$($s:ident),*], $q:expr, $w:expr, $a:expr, $bufs:expr, $st:expr) => {{
        paste::paste! {
            let mut o = $bufs.iter_mut().map(|v| v.as_mut_slice());
            #[allow(unused_mut, unused_variables)]
            let mut nx = || o.next().unwrap();
            [<$ty Batch>] {
                $([<in_ $i>]: &$q[stringify!($i)],)*
                $([<rate_ $i>]: &$w[stringify!($i)],)*
                $([<accel_ $i>]: &$a[stringify!($i)],)*
                $([<pos_ $p _x>]: nx(), [<pos_ $p _y>]: nx(),)*
                $([<pos_ $s>]: nx(),)*
                $([<vel_ $p _x>]: nx(), [<vel_ $p _y>]: nx(),)*
                $([<vel_ $s>]: nx(),)*
                $([<acc_ $p _x>]: nx(), [<acc_ $p _y>]: nx(),)*
                $([<acc_ $s>]: nx(),)*
                status: $st,
            }
        }
    }};
    ($ty:ident, $($rest:tt)*) => {
        batch!(acc; $ty, $($rest)*)
    };
}

/// The scalar path on element `$k` of `$m` at level `$lv`: pushes the
/// outputs of every level that succeeds to `$vals`, sets `$c` to the failing
/// level (0: none) and `$cond` to the velocity's `condition`. `$mk(map, k)`
/// builds an input struct.
macro_rules! scalar_levels {
    (pos; $m:ident, $mk:ident, $q:ident, $w:ident, $a:ident, $k:ident, $vals:ident, $c:ident, $cond:ident, [$($p:ident),*], [$($s:ident),*]) => {
        match $m.position(&$mk(&$q, $k)) {
            Err(_) => $c = 1,
            Ok(p) => {
                $($vals.extend([p.$p.x as f64, p.$p.y as f64]);)*
                $($vals.push(p.$s as f64);)*
            }
        }
    };
    (vel; $m:ident, $mk:ident, $q:ident, $w:ident, $a:ident, $k:ident, $vals:ident, $c:ident, $cond:ident, [$($p:ident),*], [$($s:ident),*]) => {
        match $m.position(&$mk(&$q, $k)) {
            Err(_) => $c = 1,
            Ok(p) => {
                $($vals.extend([p.$p.x as f64, p.$p.y as f64]);)*
                $($vals.push(p.$s as f64);)*
                match $m.velocity(&p, &$mk(&$w, $k)) {
                    Err(_) => $c = 2,
                    Ok(v) => {
                        $cond = v.condition as f64;
                        $($vals.extend([v.$p.x as f64, v.$p.y as f64]);)*
                        $($vals.push(v.$s as f64);)*
                    }
                }
            }
        }
    };
    (acc; $m:ident, $mk:ident, $q:ident, $w:ident, $a:ident, $k:ident, $vals:ident, $c:ident, $cond:ident, [$($p:ident),*], [$($s:ident),*]) => {
        match $m.position(&$mk(&$q, $k)) {
            Err(_) => $c = 1,
            Ok(p) => {
                $($vals.extend([p.$p.x as f64, p.$p.y as f64]);)*
                $($vals.push(p.$s as f64);)*
                match $m.velocity(&p, &$mk(&$w, $k)) {
                    Err(_) => $c = 2,
                    Ok(v) => {
                        $cond = v.condition as f64;
                        $($vals.extend([v.$p.x as f64, v.$p.y as f64]);)*
                        $($vals.push(v.$s as f64);)*
                        match $m.acceleration(&p, &v, &$mk(&$a, $k)) {
                            Err(_) => $c = 3,
                            Ok(_ac) => {
                                $($vals.extend([_ac.$p.x as f64, _ac.$p.y as f64]);)*
                                $($vals.push(_ac.$s as f64);)*
                            }
                        }
                    }
                }
            }
        }
    };
}

/// Evaluates definition `$ty` (analysis level `$lv`: `pos`, `vel` or `acc`,
/// `acc` when left out) in precision `$t` over the inputs `$q`, `$w`, `$a`
/// (maps from input name to one value per element, `f64`; the rates and
/// accelerations are not read below their level) through `solve_batch`,
/// through the lane kernel alone and through the scalar path, and checks
/// points 1 to 4 of `tests/batch/examples.rs`'s module documentation. `$p`: the point
/// outputs, `$s`: the scalar ones (link angles, slides). Returns [`Found`].
macro_rules! compare {
    ($lv:ident; $m:expr, $t:ty, $ty:ident, [$($i:ident),*], [$($p:ident),*], [$($s:ident),*], $q:expr, $w:expr, $a:expr) => {{
        paste::paste! {
            let m: $ty<$t> = $m;
            let conv = |h: &HashMap<&'static str, Vec<f64>>| -> HashMap<&'static str, Vec<$t>> {
                h.iter().map(|(k, v)| (*k, v.iter().map(|x| *x as $t).collect())).collect()
            };
            let (q, w, a) = (conv(&$q), conv(&$w), conv(&$a));
            let _ = (&w, &a);
            let n = q.values().next().unwrap().len();
            let nl = levels!($lv);
            let per_level = 2 * <[&str]>::len(&[$(stringify!($p)),*]) + <[&str]>::len(&[$(stringify!($s)),*]);
            let mut full = vec![vec![<$t>::NAN; n]; nl * per_level];
            let mut lane = full.clone();
            let mut status = vec![7u8; n];
            let mut lane_status = vec![7u8; n];
            let failed = m.solve_batch(&mut batch!($lv; $ty, [$($i),*], [$($p),*], [$($s),*], q, w, a, full, &mut status)).expect("slices of one length");
            assert!(
                m.__solve_batch_lane_only(&mut batch!($lv; $ty, [$($i),*], [$($p),*], [$($s),*], q, w, a, lane, &mut lane_status)),
                "{}: no lane kernel",
                stringify!($ty)
            );
            let mk = |h: &HashMap<&'static str, Vec<$t>>, k: usize| [<$ty Input>] {
                $($i: h[stringify!($i)][k],)*
            };
            // The scalar path, level by level.
            let mut want: Vec<Option<Vec<f64>>> = Vec::new();
            let mut code = Vec::new();
            let mut cond = Vec::new();
            let mut lane_rejects = 0;
            for k in 0..n {
                #[allow(unused_mut)]
                let mut vals: Vec<f64> = Vec::new();
                let mut c = 0u8;
                #[allow(unused_mut)]
                let mut condition = 1.0;
                scalar_levels!($lv; m, mk, q, w, a, k, vals, c, condition, [$($p),*], [$($s),*]);
                let got: Vec<f64> = full.iter().map(|v| v[k] as f64).collect();
                // 3: the scalar status; the scalar values bit for bit on the
                // levels before a failure, zeros after.
                assert_eq!(status[k], c, "{} element {k}", stringify!($ty));
                if c != 0 {
                    let from = per_level * (c as usize - 1);
                    assert_eq!(&got[..from], &vals[..], "{} element {k}", stringify!($ty));
                    assert!(got[from..].iter().all(|g| *g == 0.0), "{} element {k}", stringify!($ty));
                }
                // 2: the kernel accepts only what the scalar path solves.
                if lane_status[k] == 0 {
                    assert_eq!(c, 0, "{}: kernel accepted element {k}", stringify!($ty));
                } else {
                    assert_eq!(lane_status[k], u8::MAX);
                    lane_rejects += (c == 0) as usize;
                }
                code.push(c);
                cond.push(condition);
                want.push((c == 0).then_some(vals));
            }
            assert_eq!(failed, code.iter().filter(|c| **c != 0).count());
            // 4: the ok elements within tolerance.
            let eps = <$t>::EPSILON as f64;
            let cols = nl * per_level;
            // The scale of an output: the terms summed into the outputs of
            // one level (positions, velocities, accelerations) are about the
            // size of the element's largest output of that level (larger
            // near singular poses), and not much smaller than the level's
            // typical largest output (the median over the grid: near a
            // dead point the outputs are small differences of larger terms).
            let level_max = |v: &[f64], l: usize| {
                v[l * per_level..(l + 1) * per_level]
                    .iter()
                    .fold(f64::MIN_POSITIVE, |m, x| m.max(x.abs()))
            };
            let typical: Vec<f64> = (0..nl)
                .map(|l| {
                    let mut m: Vec<f64> = want.iter().flatten().map(|v| level_max(v, l)).collect();
                    m.sort_by(f64::total_cmp);
                    m.get(m.len() / 2).copied().unwrap_or(f64::MIN_POSITIVE)
                })
                .collect();
            let mut worst: (f64, usize, usize) = (0.0, 0, 0);
            for k in 0..n {
                let Some(wv) = &want[k] else { continue };
                let scale: Vec<f64> = (0..nl).map(|l| level_max(wv, l).max(typical[l])).collect();
                for j in 0..cols {
                    let scale = scale[j / per_level];
                    let e = (full[j][k] as f64 - wv[j]).abs() / (eps * scale)
                        * cond[k]
                        * cond[k];
                    if e > worst.0 {
                        worst = (e, k, j);
                    }
                    assert!(
                        e <= K,
                        "{} element {k} output {j}: {} vs {} (scale {}, condition {})",
                        stringify!($ty),
                        full[j][k],
                        wv[j],
                        scale,
                        cond[k]
                    );
                }
            }
            let fails = code.iter().filter(|c| **c != 0).count();
            println!(
                "{} {}: {} elements, {} failed, {} solved by the scalar path after the kernel; worst {:.2} (element {}, output {})",
                stringify!($ty),
                stringify!($t),
                n,
                fails,
                lane_rejects,
                worst.0,
                worst.1,
                worst.2
            );
            let found: Found = (worst.0, lane_rejects, fails);
            found
        }
    }};
    ($m:expr, $t:ty, $($rest:tt)*) => {
        compare!(acc; $m, $t, $($rest)*)
    };
}

/// One input's values per element.
pub fn one(name: &'static str, v: Vec<f64>) -> HashMap<&'static str, Vec<f64>> {
    HashMap::from([(name, v)])
}

/// A turn and a half of angles, some out of the lane's range (|x| > 1e5:
/// scalar path), non-finite ones (status 1).
pub fn angles(n: usize) -> Vec<f64> {
    let mut v: Vec<f64> = (0..n).map(|i| -3.0 + i as f64 * (9.5 / n as f64)).collect();
    v.extend([2.0e5, -1.0e6, f64::NAN, f64::INFINITY, 1.0e5]);
    v
}

/// Rates and accelerations for `n` elements, with one infinite rate (element
/// `bad_w`: status 2 if it assembles) and one NaN acceleration (`bad_a`:
/// status 3).
pub fn rates(n: usize, x: f64, bad: Option<usize>) -> Vec<f64> {
    let mut v = vec![x; n];
    if let Some(k) = bad {
        v[k] = if x > 0.0 { f64::INFINITY } else { f64::NAN };
    }
    v
}

/// Runs a one-input definition (acceleration level) in both precisions over
/// the inputs `$q` with failing rates at `bad_w`, `bad_a`; at least
/// `min_fail` failures, and the kernel hands back at most 1 % of the
/// elements.
macro_rules! one_input {
    ($m64:expr, $m32:expr, $ty:ident, $i:ident, $p:tt, $s:tt, $q:expr, $bad_w:expr, $bad_a:expr, $min_fail:expr) => {{
        let q: Vec<f64> = $q;
        let n = q.len();
        let w = rates(n, 3.0, Some($bad_w));
        let a = rates(n, -2.0, Some($bad_a));
        let name = stringify!($i);
        for (found, t) in [
            compare!($m64, f64, $ty, [$i], $p, $s, one(name, q.clone()), one(name, w.clone()), one(name, a.clone())),
            compare!($m32, f32, $ty, [$i], $p, $s, one(name, q.clone()), one(name, w.clone()), one(name, a.clone())),
        ]
        .into_iter()
        .zip(["f64", "f32"])
        {
            assert!(found.2 >= $min_fail, "{} {t}: {} failures", stringify!($ty), found.2);
            // The kernel hands back only elements at the edges (rounding
            // bands, twice the singular threshold): a handful per grid.
            assert!(found.1 <= n / 100, "{} {t}: {} handed back", stringify!($ty), found.1);
        }
    }};
}
