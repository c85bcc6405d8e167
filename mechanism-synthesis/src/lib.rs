//! Dimensional synthesis of `mechanism!` definitions: choose a definition's
//! parameters, its frame placement and its free input values so that an output
//! follows targets over a sweep, in the least-squares sense.
//!
//! - [`Problem`]: the residuals of a design, written once for any scalar
//!   [`mechanism::Real`]; the same code runs on `f64` (the objective) and on
//!   [`mechanism::dual::Dual`] (the exact Jacobian, [`jacobian`]).
//! - [`lm`]: a bounded Levenberg-Marquardt on those residuals and that Jacobian.
//! - [`minimax`]: the largest error instead of the sum of squares (a
//!   high power of the errors, on any problem).
//! - [`multistart`]: the global strategy: quasi-random starts, each polished by
//!   the bounded LM, the best kept.
//! - [`de`]: plain differential evolution (DE/rand/1/bin), the literature's
//!   family of global methods, as the baseline the report measures against.
//! - [`fourbar`]: path generation by a four-bar (`fourbar::FourBarPath`, a
//!   `mechanism!` definition evaluated in either assembly mode), with prescribed
//!   or free timing, Grashof crank-rocker by construction; [`cases`]: the five
//!   benchmark cases of the literature.
//! - [`function`]: function generation (the rocker's angle as a function of
//!   the crank's) by the same four-bar definition.
//! - [`jansen`]: foot-path synthesis of Jansen's leg, a definition of three
//!   dyads on a crank, through the same machinery.
//!
//! Why a crate of its own (std, nalgebra's dynamic matrices) and not a module
//! of the facade: the facade and the core are `no_std`; synthesis needs
//! growable buffers and dense linear algebra of run-time size, and only
//! desktop users run it.

pub mod cases;
pub mod de;
pub mod fourbar;
pub mod function;
pub mod jacobian;
pub mod jansen;
pub mod lm;
pub mod minimax;
pub mod multistart;
pub mod problem;
pub mod rng;

pub use problem::Problem;
