//! The harness of `scale_definitions.rs` and `singular_definitions.rs`: the
//! finiteness check, the typed-error check, the bound check with its summary
//! figures, and the decades a singular pose is approached by.
#![allow(dead_code)]

use mechanism::{Error, Fault, Real};

/// Asserts every number is finite (`what` names the case).
pub fn all_finite(xs: &[f64], what: &str) {
    assert!(
        xs.iter().all(|x| x.is_finite()),
        "{what}: non-finite inside Ok: {xs:?}"
    );
}

/// Asserts an error is typed for `group` with a fault `ok_fault` accepts.
pub fn typed<T: Real + core::fmt::Debug>(
    e: &Error<T>,
    group: &str,
    ok_fault: impl Fn(&Fault<T>) -> bool,
    what: &str,
) {
    assert_eq!(e.group, group, "{what}: error names the wrong group: {e:?}");
    assert!(ok_fault(&e.fault), "{what}: unexpected fault {e:?}");
}

/// 1e-1 .. 1e-15 by decades, with a non-round mantissa (1.37).
pub fn decades() -> Vec<f64> {
    (1..=15).map(|k| 1.37 * 10f64.powi(-k)).collect()
}

/// Worst ratio of error to bound, and the worst errors, for a summary line.
#[derive(Default, Debug)]
pub struct Worst {
    /// Largest `err / (eps / kappa^k)` seen per stage (positions, rates,
    /// accelerations): the measured constant `c`.
    pub c: [f64; 3],
    /// Largest raw relative error per stage.
    pub err: [f64; 3],
    /// Smallest condition met with an `Ok`.
    pub kappa: f64,
    /// Extreme ratios `condition / kappa` of the indicator, when checked.
    pub cond_ratio: Option<(f64, f64)>,
    /// Number of `Ok` samples and of typed errors.
    pub ok: usize,
    pub errs: usize,
}

impl Worst {
    pub fn new() -> Worst {
        Worst {
            kappa: 1.0,
            ..Worst::default()
        }
    }
    /// Records a sample: errors `e` per stage, condition `kappa`, powers `k`
    /// per stage, epsilon `eps`; asserts `e[i] <= c[i] eps / kappa^k[i]`.
    /// `EXTREME_TRACE=1` prints every sample.
    pub fn record(
        &mut self,
        e: [f64; 3],
        kappa: f64,
        k: [i32; 3],
        c: [f64; 3],
        eps: f64,
        what: &str,
    ) {
        for i in 0..3 {
            let unit = eps / kappa.powi(k[i]);
            let ratio = e[i] / unit;
            if std::env::var("EXTREME_TRACE").is_ok() {
                println!(
                    "TRACE {what}: stage {i} err {:.3e} kappa {kappa:.3e} ratio {ratio:.3}",
                    e[i]
                );
            }
            assert!(
                e[i] <= c[i] * unit,
                "{what}: stage {i} error {:e} > {} eps / kappa^{} (kappa {kappa:e}, ratio {ratio:.3})",
                e[i],
                c[i],
                k[i]
            );
            self.c[i] = self.c[i].max(ratio);
            self.err[i] = self.err[i].max(e[i]);
        }
        self.kappa = self.kappa.min(kappa);
        self.ok += 1;
    }
    /// Asserts the indicator `condition` is within a factor 2 of `kappa`
    /// (clamped to 1 as the indicator is): it is computed from the rounded
    /// pose, whose relative error in `kappa` is `eps / kappa` at most, below
    /// a factor 2 down to `kappa ~ 1e-15` in f64 (1e-6 in f32).
    pub fn indicator(&mut self, condition: f64, kappa: f64, what: &str) {
        let want = kappa.min(1.0);
        let r = condition / want;
        assert!(
            (0.5..=2.0).contains(&r),
            "{what}: condition {condition:e} against kappa {want:e}"
        );
        let (lo, hi) = self.cond_ratio.unwrap_or((f64::INFINITY, 0.0));
        self.cond_ratio = Some((lo.min(r), hi.max(r)));
    }
    pub fn print(&self, what: &str) {
        let cond = match self.cond_ratio {
            Some((lo, hi)) => format!("; condition/kappa in [{lo:.3}, {hi:.3}]"),
            None => String::new(),
        };
        println!(
            "{what}: {} ok, {} typed errors, min kappa {:.2e}; worst err pos {:.2e} vel {:.2e} acc {:.2e}; measured c pos {:.3} vel {:.3} acc {:.3}{cond}",
            self.ok, self.errs, self.kappa, self.err[0], self.err[1], self.err[2], self.c[0], self.c[1], self.c[2]
        );
    }
}
