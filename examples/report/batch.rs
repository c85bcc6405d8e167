//! The four-bar's batch API (`FourBar::solve_batch`, structure of arrays) as
//! report methods: serial, and (feature `rayon`) over all cores.

use crate::generated::Sample;
use crate::methods::{method, Method, Precision};
use crate::reference::Scene;
use crate::scenes::{FourBar, FourBarBatch};
use crate::timing::Sweep;
use std::cell::RefCell;

/// Owned buffers for every slice of `FourBarBatch`.
pub struct Buffers<T> {
    n: usize,
    input: [Vec<T>; 3],
    out: Vec<Vec<T>>,
    status: Vec<u8>,
}

/// Outputs per level: O2 (x, y), O4 (x, y), A (x, y), B (x, y), link2, link3, link4.
const PER_LEVEL: usize = 11;

impl<T: Copy + Default> Buffers<T> {
    pub fn new(inputs: &[T], w: T, a: T) -> Self {
        let n = inputs.len();
        Buffers {
            n,
            input: [inputs.to_vec(), vec![w; n], vec![a; n]],
            out: vec![vec![T::default(); n]; 3 * PER_LEVEL],
            status: vec![0; n],
        }
    }

    /// The batch view over the buffers.
    pub fn batch(&mut self) -> FourBarBatch<'_, T> {
        let [i0, i1, i2] = &self.input;
        let mut o = self.out.iter_mut().map(|v| v.as_mut_slice());
        let mut nx = || o.next().expect("3 * PER_LEVEL buffers");
        FourBarBatch {
            in_theta2: i0,
            rate_theta2: i1,
            accel_theta2: i2,
            pos_O2_x: nx(),
            pos_O2_y: nx(),
            pos_O4_x: nx(),
            pos_O4_y: nx(),
            pos_A_x: nx(),
            pos_A_y: nx(),
            pos_B_x: nx(),
            pos_B_y: nx(),
            pos_link2: nx(),
            pos_link3: nx(),
            pos_link4: nx(),
            vel_O2_x: nx(),
            vel_O2_y: nx(),
            vel_O4_x: nx(),
            vel_O4_y: nx(),
            vel_A_x: nx(),
            vel_A_y: nx(),
            vel_B_x: nx(),
            vel_B_y: nx(),
            vel_link2: nx(),
            vel_link3: nx(),
            vel_link4: nx(),
            acc_O2_x: nx(),
            acc_O2_y: nx(),
            acc_O4_x: nx(),
            acc_O4_y: nx(),
            acc_A_x: nx(),
            acc_A_y: nx(),
            acc_B_x: nx(),
            acc_B_y: nx(),
            acc_link2: nx(),
            acc_link3: nx(),
            acc_link4: nx(),
            status: &mut self.status,
        }
    }
}

fn samples<T: Copy + Into<f64>>(b: &Buffers<T>) -> Vec<Option<Sample>> {
    let f = |lvl: usize, k: usize, i: usize| b.out[lvl * PER_LEVEL + k][i].into();
    (0..b.n)
        .map(|i| {
            if b.status[i] != 0 {
                return None;
            }
            // Report columns: B.x, B.y, link3, link4 at each level.
            let cols = (0..3)
                .flat_map(|l| [6, 7, 9, 10].map(|k| Some(f(l, k, i))))
                .collect();
            Some(Sample {
                cols,
                points: vec![
                    (0.0, 0.0),
                    (304.8, 0.0),
                    (f(0, 4, i), f(0, 5, i)),
                    (f(0, 6, i), f(0, 7, i)),
                ],
            })
        })
        .collect()
}

macro_rules! batch_methods {
    ($v:ident, $scene:ident, $t:ty, $prec:expr, $label:expr) => {{
        let m = FourBar::<$t>::default();
        let inputs: Vec<$t> = $scene.grid.iter().map(|q| q[0] as $t).collect();
        let (w, a) = ($scene.rates[0] as $t, $scene.accels[0] as $t);
        let mut buf = Buffers::new(&inputs, w, a);
        m.solve_batch(&mut buf.batch());
        let s = samples(&buf);
        let cell = RefCell::new(buf);
        let sweep: Sweep = Box::new(move || {
            let mut b = cell.borrow_mut();
            let failed = m.solve_batch(&mut b.batch());
            let acc: $t = b.out[9].iter().sum();
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
            let mut buf = Buffers::new(&inputs, w, a);
            mechanism::par_solve(buf.batch(), 512, &|mut b| m.solve_batch(&mut b));
            let s = samples(&buf);
            let cell = RefCell::new(buf);
            let sweep: Sweep = Box::new(move || {
                let mut b = cell.borrow_mut();
                let failed = mechanism::par_solve(b.batch(), 512, &|mut c| m.solve_batch(&mut c));
                let acc: $t = b.out[9].iter().sum();
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
    }};
}

/// Batch methods of the four-bar.
pub fn fourbar<'a>(scene: &'a Scene) -> Vec<Method<'a>> {
    let mut v = Vec::new();
    batch_methods!(v, scene, f64, Precision::F64, "f64");
    batch_methods!(v, scene, f32, Precision::F32, "f32");
    v
}
