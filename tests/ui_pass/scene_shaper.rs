//! The definition of `Shaper` in `examples/common/scenes.rs` (copied): it
//! passes the expansion-time checks and its generated code compiles.
use mechanism::mechanism;

mechanism! {
    /// Quick-return shaper of seed 001 (m): crank AB = 0.125 about A; the block
    /// at B slides on the rocker pivoted at C = (0, -0.275); D on the rocker at
    /// CD = 0.6; the connecting rod DE = 0.15 drives the ram E along y = 0.3
    /// (guide direction 180 deg, as in the document).
    #[self_test]
    pub Shaper {
        dof 1;
        let A = ground(0.0, 0.0);
        let C = ground(0.0, -0.275);
        let ram = guide((0.0, 0.3), 180 deg);
        let B = crank(A, 0.125, crank) as link2;
        let cb = rpr(B, C, plus) as (block, link3);
        let D = point(link3, from C, 0.6, 0 deg);
        let E = rrp(D, 0.15, ram, plus) as (link4, ram_block) slide s_ram;
        outputs { E, link3, link4 }
    }
}

fn main() {
    let report = Shaper::<f64>::default().check();
    assert!(report.assembles());
}
