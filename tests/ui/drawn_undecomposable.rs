// Error: a class IV group (two ternary links joined by two binary links,
// each ternary with one outer joint) driven by a crank: no dyad and no triad
// of binary legs, so the drawing has no decomposition into the supported groups.
use mechanism::mechanism;

mechanism! {
    pub Class4 {
        joints {
            O1 = (0.0, 0.0), O2 = (3.0, 0.0), A = (0.3, 0.9),
            X = (1.0, 1.6), Y = (0.6, 2.4), Z = (2.4, 1.5), W = (2.2, 2.6),
        }
        links {
            ground = [O1, O2],
            crank = [O1, A],
            t1 = [A, X, Y],
            t2 = [O2, Z, W],
            l1 = [X, Z],
            l2 = [Y, W],
        }
        input theta = angle(crank);
    }
}

fn main() {}
