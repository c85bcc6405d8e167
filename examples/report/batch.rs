//! The batch API (`solve_batch`, structure of arrays) of every report scene
//! as report methods: serial, and (feature `rayon`) over all cores. The
//! samples are read from the batch's own output slices, so the report's
//! error columns are the batch's.

use crate::generated::Sample;
use crate::methods::{method, Method, Precision};
use crate::reference::Scene;
use crate::scenes::*;
use crate::timing::Sweep;
use std::cell::RefCell;

/// Owned buffers for every slice of a definition's batch: per input its
/// values, rates and accelerations; the outputs in the batch struct's field
/// order (`names`); the status bytes.
pub struct Buffers<T> {
    n: usize,
    input: Vec<[Vec<T>; 3]>,
    out: Vec<Vec<T>>,
    names: Vec<&'static str>,
    status: Vec<u8>,
}

impl<T: Copy + Default + Into<f64>> Buffers<T> {
    fn new(grid: &[Vec<T>], w: &[T], a: &[T], names: Vec<&'static str>) -> Self {
        let n = grid.len();
        let input = (0..w.len())
            .map(|j| {
                [
                    grid.iter().map(|q| q[j]).collect(),
                    vec![w[j]; n],
                    vec![a[j]; n],
                ]
            })
            .collect();
        Buffers {
            n,
            input,
            out: vec![vec![T::default(); n]; names.len()],
            names,
            status: vec![0; n],
        }
    }

    /// Output `name` (a batch field name) of element `i`.
    fn get(&self, name: &str, i: usize) -> f64 {
        let j = self.names.iter().position(|n| *n == name);
        j.map(|j| self.out[j][i].into()).unwrap_or(f64::NAN)
    }

    /// The report samples, from a scene's sample function over the outputs.
    fn samples(&self, grid: &[Vec<f64>], f: SampleFn) -> Vec<Option<Sample>> {
        (0..self.n)
            .map(|i| (self.status[i] == 0).then(|| f(&|name| self.get(name, i), &grid[i])))
            .collect()
    }
}

/// A scene's report sample from its batch outputs (by field name) and the
/// element's inputs (rounded to the method's precision).
type SampleFn = fn(&dyn Fn(&str) -> f64, &[f64]) -> Sample;

fn polar(r: f64, a: f64) -> (f64, f64) {
    (r * a.cos(), r * a.sin())
}

/// The report columns: `fields` at each of the three levels.
fn cols(g: &dyn Fn(&str) -> f64, fields: &[&str]) -> Vec<Option<f64>> {
    ["pos", "vel", "acc"]
        .iter()
        .flat_map(|l| fields.iter().map(move |f| Some(g(&format!("{l}_{f}")))))
        .collect()
}

fn pt(g: &dyn Fn(&str) -> f64, p: &str) -> (f64, f64) {
    (g(&format!("pos_{p}_x")), g(&format!("pos_{p}_y")))
}

fn fourbar_sample(g: &dyn Fn(&str) -> f64, _q: &[f64]) -> Sample {
    Sample {
        cols: cols(g, &["B_x", "B_y", "link3", "link4"]),
        points: vec![(0.0, 0.0), (304.8, 0.0), pt(g, "A"), pt(g, "B")],
    }
}

fn sixbar_sample(g: &dyn Fn(&str) -> f64, q: &[f64]) -> Sample {
    let k = polar(40.0, q[0]);
    let l4 = g("pos_link4");
    Sample {
        cols: cols(
            g,
            &["C_x", "C_y", "F_x", "F_y", "link2", "link3", "link4", "af"],
        ),
        points: vec![
            (0.0, 0.0),
            (70.0, 0.0),
            k,
            (-k.0, -k.1),
            pt(g, "F"),
            (70.0 - 35.0 * l4.cos(), -35.0 * l4.sin()),
            pt(g, "C"),
        ],
    }
}

fn shaper_sample(g: &dyn Fn(&str) -> f64, q: &[f64]) -> Sample {
    let l3 = g("pos_link3");
    Sample {
        cols: cols(g, &["E_x", "E_y", "link3", "link4"]),
        points: vec![
            (0.0, 0.0),
            (0.0, -0.275),
            (0.0, 0.3),
            (-1.0, 0.3),
            polar(0.125, q[0]),
            (0.6 * l3.cos(), -0.275 + 0.6 * l3.sin()),
            pt(g, "E"),
        ],
    }
}

fn slider_crank_sample(g: &dyn Fn(&str) -> f64, q: &[f64]) -> Sample {
    Sample {
        cols: cols(g, &["B_x", "B_y", "link3"]),
        points: vec![
            (0.0, 0.0),
            (0.0, 0.02),
            (1.0, 0.02),
            polar(0.1, q[0]),
            pt(g, "B"),
        ],
    }
}

fn five_bar_sample(g: &dyn Fn(&str) -> f64, q: &[f64]) -> Sample {
    let c = polar(0.1, q[1]);
    Sample {
        cols: cols(g, &["P_x", "P_y"]),
        points: vec![
            (0.0, 0.0),
            (0.08, 0.0),
            polar(0.1, q[0]),
            (0.08 + c.0, c.1),
            pt(g, "P"),
        ],
    }
}

fn geared_five_bar_sample(g: &dyn Fn(&str) -> f64, _q: &[f64]) -> Sample {
    Sample {
        cols: cols(g, &["B_x", "B_y", "link3", "link4", "link5"]),
        points: vec![(0.0, 0.0), (0.3, 0.0), pt(g, "A"), pt(g, "C"), pt(g, "B")],
    }
}

/// Serial and (feature `rayon`) parallel batch methods of definition `$ty`
/// in precision `$t`: inputs `[$i]`, point outputs `[$p]`, scalar outputs
/// `[$s]` (every output of the batch, in the definition's order: ground
/// points and crank links are left out of batches), the column summed
/// by the timed sweep `$sum` and the sample function `$sample`.
macro_rules! batch_methods {
    ($v:ident, $scene:ident, $ty:ident, $t:ty, $prec:expr, $label:expr, [$($i:ident),*], [$($p:ident),*], [$($s:ident),*], $sum:literal, $sample:expr) => {{
        paste::paste! {
            let m = $ty::<$t>::default();
            let grid: Vec<Vec<$t>> = $scene.grid.iter().map(|q| q.iter().map(|x| *x as $t).collect()).collect();
            let grid64: Vec<Vec<f64>> = grid.iter().map(|q| q.iter().map(|x| *x as f64).collect()).collect();
            let w: Vec<$t> = $scene.rates.iter().map(|x| *x as $t).collect();
            let a: Vec<$t> = $scene.accels.iter().map(|x| *x as $t).collect();
            let mut names: Vec<&'static str> = Vec::new();
            for l in ["pos", "vel", "acc"] {
                let level: Vec<&'static str> = match l {
                    "pos" => vec![$(stringify!([<pos_ $p _x>]), stringify!([<pos_ $p _y>]),)* $(stringify!([<pos_ $s>]),)*],
                    "vel" => vec![$(stringify!([<vel_ $p _x>]), stringify!([<vel_ $p _y>]),)* $(stringify!([<vel_ $s>]),)*],
                    _ => vec![$(stringify!([<acc_ $p _x>]), stringify!([<acc_ $p _y>]),)* $(stringify!([<acc_ $s>]),)*],
                };
                names.extend(level);
            }
            let sum_at = names.iter().position(|n| *n == $sum).expect("summed column");
            fn view<'b>(b: &'b mut Buffers<$t>) -> [<$ty Batch>]<'b, $t> {
                let mut ins = b.input.iter();
                $(let [<q_ $i>] = ins.next().expect("input");)*
                let mut o = b.out.iter_mut().map(|v| v.as_mut_slice());
                let mut nx = || o.next().expect("output buffer");
                [<$ty Batch>] {
                    $([<in_ $i>]: &[<q_ $i>][0], [<rate_ $i>]: &[<q_ $i>][1], [<accel_ $i>]: &[<q_ $i>][2],)*
                    $([<pos_ $p _x>]: nx(), [<pos_ $p _y>]: nx(),)*
                    $([<pos_ $s>]: nx(),)*
                    $([<vel_ $p _x>]: nx(), [<vel_ $p _y>]: nx(),)*
                    $([<vel_ $s>]: nx(),)*
                    $([<acc_ $p _x>]: nx(), [<acc_ $p _y>]: nx(),)*
                    $([<acc_ $s>]: nx(),)*
                    status: &mut b.status,
                }
            }
            let mut buf = Buffers::new(&grid, &w, &a, names.clone());
            m.solve_batch(&mut view(&mut buf)).expect("slices of one length");
            let s = buf.samples(&grid64, $sample);
            let cell = RefCell::new(buf);
            let sweep: Sweep = Box::new(move || {
                let mut b = cell.borrow_mut();
                let failed = m.solve_batch(&mut view(&mut b)).expect("slices of one length");
                let acc: $t = b.out[sum_at].iter().sum();
                std::hint::black_box(acc) as f64 + failed as f64
            });
            $v.push(method(
                "generated batch (SoA)",
                concat!("generated batch ", $label),
                $prec,
                s,
                Some(sweep),
            ));
            #[cfg(feature = "rayon")]
            {
                let mut buf = Buffers::new(&grid, &w, &a, names);
                mechanism::par_solve(view(&mut buf), 512, &|mut b| m.solve_batch(&mut b))
                    .expect("slices of one length");
                let s = buf.samples(&grid64, $sample);
                let cell = RefCell::new(buf);
                let sweep: Sweep = Box::new(move || {
                    let mut b = cell.borrow_mut();
                    let failed = mechanism::par_solve(view(&mut b), 512, &|mut c| m.solve_batch(&mut c))
                        .expect("slices of one length");
                    let acc: $t = b.out[sum_at].iter().sum();
                    std::hint::black_box(acc) as f64 + failed as f64
                });
                $v.push(method(
                    "generated batch, rayon",
                    concat!("generated batch, rayon ", $label),
                    $prec,
                    s,
                    Some(sweep),
                ));
            }
        }
    }};
}

/// [`batch_methods!`] in f64 and in f32.
macro_rules! for_both {
    ($v:ident, $scene:ident, $ty:ident, $($rest:tt)*) => {
        batch_methods!($v, $scene, $ty, f64, Precision::F64, "f64", $($rest)*);
        batch_methods!($v, $scene, $ty, f32, Precision::F32, "f32", $($rest)*);
    };
}

/// Batch methods of a scene, f64 and f32 (none for a scene without a batch
/// row).
pub fn for_scene(scene: &Scene) -> Vec<Method<'_>> {
    let mut v = Vec::new();
    match scene.name {
        "FourBar" => {
            for_both!(
                v,
                scene,
                FourBar,
                [theta2],
                [A, B],
                [link3, link4],
                "pos_link3",
                fourbar_sample
            );
        }
        "SixBar" => {
            for_both!(
                v,
                scene,
                SixBar,
                [phi1],
                [C, F, K, B, D],
                [link2, link3, link4, af],
                "pos_link2",
                sixbar_sample
            );
        }
        "Shaper" => {
            for_both!(
                v,
                scene,
                Shaper,
                [crank],
                [E, B, D],
                [link3, link4],
                "pos_link3",
                shaper_sample
            );
        }
        "SliderCrank" => {
            for_both!(
                v,
                scene,
                SliderCrank,
                [theta],
                [B, A],
                [link3, x],
                "pos_link3",
                slider_crank_sample
            );
        }
        "FiveBar" => {
            for_both!(
                v,
                scene,
                FiveBar,
                [q1, q2],
                [P, A, C],
                [],
                "pos_P_x",
                five_bar_sample
            );
        }
        "GearedFiveBar" => {
            for_both!(
                v,
                scene,
                GearedFiveBar,
                [theta],
                [B, A, C],
                [link3, link4, link5],
                "pos_link3",
                geared_five_bar_sample
            );
        }
        _ => {}
    }
    v
}
