use mechanism_synthesis::cases;
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let starts: usize = a[1].parse().unwrap();
    let screen: usize = a[2].parse().unwrap();
    let seeds: u64 = a[3].parse().unwrap();
    let iters: usize = a[4].parse().unwrap();
    let hops: usize = a[5].parse().unwrap();
    let only = a.get(6).cloned();
    for c in cases::all() {
        if let Some(o) = &only {
            if c.id != o {
                continue;
            }
        }
        let mut objs = vec![];
        let t = std::time::Instant::now();
        for s in 0..seeds {
            let f = cases::solve(&c, starts, screen, iters, hops, s);
            objs.push(f.objective);
            if s == 0 {
                eprintln!(
                    "{} {:?} {:?} ev {} jac {}",
                    c.id, f.design.0, f.mode, f.evaluations, f.jacobians
                );
            }
        }
        let dt = t.elapsed().as_secs_f64() / seeds as f64;
        let mut so = objs.clone();
        so.sort_by(|a, b| a.total_cmp(b));
        println!(
            "{:16} best {:.10e} med {:.6e} worst {:.6e} t/run {:.3}s  all {:?}",
            c.id,
            so[0],
            so[so.len() / 2],
            so[so.len() - 1],
            dt,
            objs.iter()
                .map(|v| format!("{:.6e}", v))
                .collect::<Vec<_>>()
        );
    }
}
