//! The run-time mechanism's compiled plan: every name a statement reads or
//! writes resolved once, when the definition is read, to a slot of flat
//! storage ([`PointSlot`], [`LinkSlot`], [`GuideSlot`], [`InputSlot`],
//! [`StepSlot`]), and every dimension valued with the current parameters.
//! Each kind's [`RunKind::compile`] (in its own file) turns its statement
//! into a [`Step`]: a small struct of those slots and numbers whose
//! `position`, `rates` and `forces` make the core calls the generated code
//! makes, with the same arguments, reading and writing a [`RunPose`], a
//! [`Motion`] and a [`ForceRunCx`], all preallocated: an evaluation
//! allocates nothing, formats nothing and looks nothing up by name.

use super::forces::Held;
use crate::keys::GROUND;
use crate::keys::{GuideName, InputName, LinkName, Name, PointName};
use crate::model::Stmt;
use crate::names::Family;
use crate::value::Value;
use mechanism_core::force::{PrismaticReaction, Wrench};
use mechanism_core::guide::{Line, LineAcceleration, LineVelocity};
use mechanism_core::{driver, dyad, triad, Error, Point2, Vector2};
use std::collections::{BTreeMap, BTreeSet};
use syn::Ident;

/// A point's slot: the index of the statement that defines it (one past
/// the last statement: a name nothing defines, which reads as NaN).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PointSlot(u32);
/// A guide's slot: the index of the statement that defines it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GuideSlot(u32);
/// A link's slot: its place among the plan's links (by name).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LinkSlot(u32);
/// An input's slot: its place in the input struct.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct InputSlot(u32);
/// A statement's slot: its index in the definition (its group states).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StepSlot(u32);

impl PointSlot {
    /// Its index in the layout's per-point facts.
    pub fn index(self) -> usize {
        at(self.0)
    }
}

impl LinkSlot {
    /// Its index in the layout's per-link facts.
    pub fn index(self) -> usize {
        at(self.0)
    }
}

impl StepSlot {
    /// The step of the statement defining point `p`.
    pub fn of(p: PointSlot) -> Self {
        StepSlot(p.0)
    }
}

/// `usize` of a slot index (`u32` keeps the steps small).
fn at(i: u32) -> usize {
    i as usize
}

/// A slot index of a `usize` (a definition has far fewer than 2^32 names).
fn slot(i: usize) -> u32 {
    u32::try_from(i).unwrap_or(u32::MAX)
}

/// What a statement writes: its own slots and its group's name for errors.
#[derive(Clone, Copy, Debug)]
pub struct Me {
    /// Its group states.
    pub step: StepSlot,
    /// Its point (or guide: the same index).
    pub point: PointSlot,
    /// Its guide.
    pub guide: GuideSlot,
    /// The links it creates, in `Stmt::links` order (unused ones: the
    /// unknown slot).
    pub links: [LinkSlot; 4],
    /// Its name, kept for the life of the program (errors name their group).
    pub group: &'static str,
}

/// The static facts of the compiled plan, by slot: names, which points
/// move, which guides are carried, which link's rate each link shares,
/// the body owning each point and guide, each link's reference point.
#[derive(Debug)]
pub struct Layout {
    /// Statements (points, guides, steps); slot `stmts` is the unknown one.
    pub stmts: usize,
    /// Link names by slot; slot `links.len()` is the unknown one.
    pub link_names: Vec<LinkName>,
    /// Link slots by name.
    links: BTreeMap<LinkName, LinkSlot>,
    /// Statement slots by the name they define.
    defined: BTreeMap<Name, u32>,
    /// Input slots by name.
    inputs: BTreeMap<InputName, InputSlot>,
    /// `true` for a point that moves.
    pub moving: Vec<bool>,
    /// `true` for a guide carried by a link.
    pub carried: Vec<bool>,
    /// The link whose rate each link shares (`None`: it never turns).
    pub turning: Vec<Option<LinkSlot>>,
    /// The body owning each point (`None`: the ground).
    pub point_body: Vec<Option<LinkSlot>>,
    /// The body carrying each guide (`None`: the ground).
    pub guide_body: Vec<Option<LinkSlot>>,
    /// Each link's reference point (its first point).
    pub reference: Vec<Option<PointSlot>>,
}

impl Layout {
    /// The layout of `stmts` statements with the links `link_names` (in slot
    /// order), the statement index defining each name, and the inputs (in
    /// slot order). The facts by slot (`moving`, `carried`, `point_body`,
    /// `guide_body`: one more than `stmts`, the unknown slot last; `turning`
    /// and `reference`: one more than the links) start as nothing moving,
    /// carried or turning, and are the caller's to fill from the plan
    /// (`runtime::slots`), so this stage reads no later one.
    pub fn with_names(
        stmts: usize,
        link_names: Vec<LinkName>,
        defined: impl IntoIterator<Item = (Name, usize)>,
        inputs: impl IntoIterator<Item = InputName>,
    ) -> Self {
        let links = link_names
            .iter()
            .enumerate()
            .map(|(k, n)| (n.clone(), LinkSlot(slot(k))))
            .collect();
        let n_links = link_names.len() + 1;
        Layout {
            stmts,
            link_names,
            links,
            defined: defined.into_iter().map(|(n, k)| (n, slot(k))).collect(),
            inputs: inputs
                .into_iter()
                .enumerate()
                .map(|(k, i)| (i, InputSlot(slot(k))))
                .collect(),
            moving: vec![false; stmts + 1],
            carried: vec![false; stmts + 1],
            turning: vec![None; n_links],
            point_body: vec![None; stmts + 1],
            guide_body: vec![None; stmts + 1],
            reference: vec![None; n_links],
        }
    }

    /// The slot of link `name` (the unknown slot when none).
    pub fn link_named(&self, name: &LinkName) -> LinkSlot {
        self.links
            .get(name)
            .copied()
            .unwrap_or(LinkSlot(slot(self.link_names.len())))
    }

    /// The slot of point `name` (the unknown slot when none).
    pub fn point_named(&self, name: &PointName) -> PointSlot {
        PointSlot(self.stmt_named(&name.name()))
    }

    /// The slot of guide `name` (the unknown slot when none).
    pub fn guide_named(&self, name: &GuideName) -> GuideSlot {
        GuideSlot(self.stmt_named(&name.name()))
    }

    /// The statement slot defining `name` (the unknown slot when none).
    fn stmt_named(&self, name: &Name) -> u32 {
        self.defined.get(name).copied().unwrap_or(slot(self.stmts))
    }

    /// The slot of input `name` (one past the inputs when none: reads NaN).
    pub fn input_named(&self, name: &InputName) -> InputSlot {
        self.inputs
            .get(name)
            .copied()
            .unwrap_or(InputSlot(slot(self.inputs.len())))
    }

    /// The name of link slot `l` (`ground` for none).
    pub fn link_name(&self, l: Option<LinkSlot>) -> &str {
        l.and_then(|l| self.link_names.get(at(l.0)))
            .map_or(GROUND, LinkName::as_str)
    }

    /// Number of link slots, the unknown one included.
    fn link_slots(&self) -> usize {
        self.link_names.len() + 1
    }
}

/// What a kind's `compile` reads: the layout, the run-time parameters'
/// values and the statement's own slots.
pub struct Compile<'c> {
    /// The slots by name.
    pub layout: &'c Layout,
    /// The run-time parameters' current values.
    pub params: &'c BTreeMap<String, f64>,
}

impl Compile<'_> {
    /// The slot of point `n`.
    pub fn point(&self, n: &Ident) -> PointSlot {
        self.layout.point_named(&PointName::of(n))
    }

    /// The slot of guide `n`.
    pub fn guide(&self, n: &Ident) -> GuideSlot {
        self.layout.guide_named(&GuideName::of(n))
    }

    /// The slot of link `n`.
    pub fn link(&self, n: &Ident) -> LinkSlot {
        self.layout.link_named(&LinkName::of(n))
    }

    /// `true` when point `p` moves (its rates are computed).
    pub fn moves(&self, p: PointSlot) -> bool {
        self.layout.moving.get(p.index()).copied().unwrap_or(false)
    }

    /// The slot of input `n`.
    pub fn input(&self, n: &Ident) -> InputSlot {
        self.layout.input_named(&InputName::of(n))
    }

    /// A dimension's value with the current parameters (NaN for one that
    /// does not evaluate; the primitives reject it with a typed error).
    pub fn num(&self, v: &Value) -> f64 {
        v.fold()
            .or_else(|| v.eval_with(&|n| self.params.get(&n.to_string()).copied()))
            .unwrap_or(f64::NAN)
    }

    /// The slots `stmt` writes.
    pub fn me(&self, stmt: &Stmt) -> Me {
        let name = stmt.name.to_string();
        let point = PointSlot(self.layout.stmt_named(&Name::of(&stmt.name)));
        let unknown = LinkSlot(slot(self.layout.link_names.len()));
        let mut links = [unknown; 4];
        for (l, n) in links.iter_mut().zip(&stmt.links) {
            *l = self.link(n);
        }
        Me {
            step: StepSlot(point.0),
            point,
            guide: GuideSlot(point.0),
            links,
            group: intern(&name),
        }
    }
}

/// The name `s` with a `'static` lifetime (errors name their group so);
/// each distinct name is kept once for the life of the program.
pub fn intern(s: &str) -> &'static str {
    use std::sync::{Mutex, PoisonError};
    static NAMES: Mutex<BTreeSet<&'static str>> = Mutex::new(BTreeSet::new());
    let mut names = NAMES.lock().unwrap_or_else(PoisonError::into_inner);
    if let Some(n) = names.get(s) {
        return n;
    }
    let n: &'static str = Box::leak(s.to_owned().into_boxed_str());
    names.insert(n);
    n
}

/// The core's state of one group, kept between the analyses: a position
/// state (`grp_NAME` of the generated code) or a velocity state
/// (`grp_v_NAME`).
#[derive(Clone, Copy, Debug, Default)]
pub enum Kept {
    /// Nothing kept (yet).
    #[default]
    None,
    /// A crank's or a gear's position.
    Crank(driver::crank::CrankPosition<f64>),
    /// A slider's position.
    Slider(driver::slider::SliderPosition<f64>),
    /// An actuator's velocity.
    ActuatorV(driver::actuator::ActuatorVelocity<f64>),
    /// An RRR's or an actuator's position (the same type).
    Rrr(dyad::rrr::RrrPosition<f64>),
    /// An RRR's velocity.
    RrrV(dyad::rrr::RrrVelocity<f64>),
    /// An RRP's position.
    Rrp(dyad::rrp::RrpPosition<f64>),
    /// An RRP's velocity.
    RrpV(dyad::rrp::RrpVelocity<f64>),
    /// An RPR's position.
    Rpr(dyad::rpr::RprPosition<f64>),
    /// An RPR's velocity.
    RprV(dyad::rpr::RprVelocity<f64>),
    /// A PRP's position.
    Prp(dyad::prp::PrpPosition<f64>),
    /// A PRP's velocity.
    PrpV(dyad::prp::PrpVelocity<f64>),
    /// An RPP's position.
    Rpp(dyad::rpp::RppPosition<f64>),
    /// An RPP's velocity.
    RppV(dyad::rpp::RppVelocity<f64>),
    /// A triad's position.
    Triad(triad::TriadPosition<f64>),
    /// A triad's velocity.
    TriadV(triad::TriadVelocity<f64>),
}

/// A core state that a [`Kept`] holds.
pub trait State: Sized {
    /// `self` as kept.
    fn kept(self) -> Kept;
    /// The state `k` holds, if of this type.
    fn of(k: &Kept) -> Option<&Self>;
}

/// `State` for each kept type.
macro_rules! states {
    ($($v:ident: $t:ty,)*) => {$(
        impl State for $t {
            fn kept(self) -> Kept {
                Kept::$v(self)
            }
            fn of(k: &Kept) -> Option<&Self> {
                match k {
                    Kept::$v(s) => Some(s),
                    _ => None,
                }
            }
        }
    )*};
}

states! {
    Crank: driver::crank::CrankPosition<f64>,
    Slider: driver::slider::SliderPosition<f64>,
    ActuatorV: driver::actuator::ActuatorVelocity<f64>,
    Rrr: dyad::rrr::RrrPosition<f64>,
    RrrV: dyad::rrr::RrrVelocity<f64>,
    Rrp: dyad::rrp::RrpPosition<f64>,
    RrpV: dyad::rrp::RrpVelocity<f64>,
    Rpr: dyad::rpr::RprPosition<f64>,
    RprV: dyad::rpr::RprVelocity<f64>,
    Prp: dyad::prp::PrpPosition<f64>,
    PrpV: dyad::prp::PrpVelocity<f64>,
    Rpp: dyad::rpp::RppPosition<f64>,
    RppV: dyad::rpp::RppVelocity<f64>,
    Triad: triad::TriadPosition<f64>,
    TriadV: triad::TriadVelocity<f64>,
}

/// A NaN vector: what a value not (yet) known reads as; the primitives
/// reject it with a typed error.
fn nan2() -> Vector2<f64> {
    Vector2::new(f64::NAN, f64::NAN)
}

/// The position at one input, by slot: points, guides' lines, links' unit
/// axes and the groups' position states; the inputs' values.
#[derive(Clone, Debug)]
pub struct RunPose {
    points: Vec<Point2<f64>>,
    lines: Vec<Line<f64>>,
    axes: Vec<Vector2<f64>>,
    kept: Vec<Kept>,
    /// The inputs' values (one more, NaN: the unknown input).
    pub q: Vec<f64>,
}

impl RunPose {
    /// Storage for `layout` with `inputs` inputs, every value NaN.
    pub fn new(layout: &Layout, inputs: usize) -> Self {
        let n = layout.stmts + 1;
        let line = Line {
            origin: Point2::new(f64::NAN, f64::NAN),
            dir: nan2(),
        };
        RunPose {
            points: vec![Point2::new(f64::NAN, f64::NAN); n],
            lines: vec![line; n],
            axes: vec![nan2(); layout.link_slots()],
            kept: vec![Kept::None; n],
            q: vec![f64::NAN; inputs + 1],
        }
    }

    /// Point `p`.
    pub fn point(&self, p: PointSlot) -> Point2<f64> {
        self.points[at(p.0)]
    }

    /// Guide `g`'s line.
    pub fn line(&self, g: GuideSlot) -> Line<f64> {
        self.lines[at(g.0)]
    }

    /// Link `l`'s unit axis.
    pub fn axis(&self, l: LinkSlot) -> Vector2<f64> {
        self.axes[at(l.0)]
    }

    /// Input `i`'s value.
    pub fn input(&self, i: InputSlot) -> f64 {
        self.q[at(i.0)]
    }

    /// The position state of step `me`, if of type `S`.
    pub fn kept<S: State>(&self, me: &Me) -> Option<&S> {
        S::of(&self.kept[at(me.step.0)])
    }

    /// Records `me`'s point and its links' axes.
    pub fn found(&mut self, me: &Me, point: Point2<f64>, axes: &[Vector2<f64>]) {
        self.points[at(me.point.0)] = point;
        for (l, a) in me.links.iter().zip(axes) {
            self.axes[at(l.0)] = *a;
        }
    }

    /// Records the axes of `me`'s links (a statement without a point).
    pub fn found_axes(&mut self, me: &Me, axes: &[Vector2<f64>]) {
        for (l, a) in me.links.iter().zip(axes) {
            self.axes[at(l.0)] = *a;
        }
    }

    /// `true` when this pose has `layout`'s shape with `inputs` inputs
    /// (a pose of another mechanism does not).
    pub fn fits(&self, layout: &Layout, inputs: usize) -> bool {
        self.points.len() == layout.stmts + 1
            && self.axes.len() == layout.link_slots()
            && self.q.len() == inputs + 1
    }

    /// Records `me`'s line.
    pub fn found_line(&mut self, me: &Me, line: Line<f64>) {
        self.lines[at(me.guide.0)] = line;
    }

    /// Keeps `me`'s position state.
    pub fn keep<S: State>(&mut self, me: &Me, state: S) {
        self.kept[at(me.step.0)] = state.kept();
    }
}

/// A pose read by name: what the statements solved so far found, as the
/// expansion-time check hands it to a kind that follows its assembly over
/// the input range (`GroupKind::track`).
pub struct NamedPose<'l> {
    /// The pose.
    pub pose: RunPose,
    /// Its slots by name.
    pub layout: &'l Layout,
}

impl NamedPose<'_> {
    /// Point `n` (NaN when not solved, or not a point).
    pub fn point(&self, n: &Ident) -> Point2<f64> {
        self.pose.point(self.layout.point_named(&PointName::of(n)))
    }
}

/// The rates at one level (velocity or acceleration), by slot: the points'
/// motions, the links' rates, the carried guides' motions, the groups'
/// velocity states, the slides' rates, the groups' conditioning; the
/// inputs' rates.
#[derive(Clone, Debug)]
pub struct Motion {
    points: Vec<Vector2<f64>>,
    links: Vec<f64>,
    guide_vel: Vec<LineVelocity<f64>>,
    guide_acc: Vec<LineAcceleration<f64>>,
    groups: Vec<Kept>,
    slides: Vec<[f64; 2]>,
    /// Conditioning of each group's velocity system, in solve order
    /// (velocity level only).
    pub conditions: Vec<f64>,
    /// The inputs' rates at this level (one more, NaN: the unknown input).
    pub q: Vec<f64>,
}

impl Motion {
    /// Storage for `layout` with `inputs` inputs: motions NaN, slide rates 0.
    pub fn new(layout: &Layout, inputs: usize) -> Self {
        let n = layout.stmts + 1;
        let zero = Vector2::zeros();
        Motion {
            points: vec![nan2(); n],
            links: vec![f64::NAN; layout.link_slots()],
            guide_vel: vec![
                LineVelocity {
                    v_origin: zero,
                    omega: f64::NAN
                };
                n
            ],
            guide_acc: vec![
                LineAcceleration {
                    a_origin: zero,
                    alpha: f64::NAN
                };
                n
            ],
            groups: vec![Kept::None; n],
            slides: vec![[0.0; 2]; n],
            conditions: Vec::with_capacity(n),
            q: vec![f64::NAN; inputs + 1],
        }
    }

    /// `true` when this level has `layout`'s shape with `inputs` inputs.
    pub fn fits(&self, layout: &Layout, inputs: usize) -> bool {
        self.points.len() == layout.stmts + 1
            && self.links.len() == layout.link_slots()
            && self.q.len() == inputs + 1
    }

    /// The motion of point `p` (as recorded; see [`RunCx::motion_of`]).
    pub fn point(&self, p: PointSlot) -> Vector2<f64> {
        self.points[at(p.0)]
    }

    /// The rate recorded for link `l`.
    pub fn link(&self, l: LinkSlot) -> f64 {
        self.links[at(l.0)]
    }

    /// Slide `k` of statement `s`.
    pub fn slide(&self, s: StepSlot, k: usize) -> f64 {
        self.slides[at(s.0)].get(k).copied().unwrap_or(0.0)
    }
}

/// What a kind's run-time rate step reads and where it writes.
pub struct RunCx<'r> {
    /// The position.
    pub pose: &'r RunPose,
    /// The velocity level, when computing accelerations.
    pub vel: Option<&'r Motion>,
    /// The level being computed.
    pub out: &'r mut Motion,
    /// The static facts.
    pub layout: &'r Layout,
}

impl RunCx<'_> {
    /// `true` in the acceleration analysis.
    pub fn accel(&self) -> bool {
        self.vel.is_some()
    }

    /// `true` when point `p` moves.
    pub fn moves(&self, p: PointSlot) -> bool {
        self.layout.moving[at(p.0)]
    }

    /// The motion of point `p` at this level (zero when it does not move).
    pub fn motion_of(&self, p: PointSlot) -> Vector2<f64> {
        if self.moves(p) {
            self.out.points[at(p.0)]
        } else {
            Vector2::zeros()
        }
    }

    /// The motion of a known point as the optional argument of a core call
    /// (`None` for a point that does not move, as the generated code).
    pub fn point_arg(&self, p: PointSlot) -> Option<Vector2<f64>> {
        self.moves(p).then(|| self.out.points[at(p.0)])
    }

    /// A carried guide's velocity (`None` for a fixed guide).
    pub fn guide_vel(&self, g: GuideSlot) -> Option<LineVelocity<f64>> {
        if !self.layout.carried[at(g.0)] {
            return None;
        }
        let level = self.vel.unwrap_or(&*self.out);
        Some(level.guide_vel[at(g.0)])
    }

    /// A carried guide's acceleration (`None` for a fixed guide).
    pub fn guide_acc(&self, g: GuideSlot) -> Option<LineAcceleration<f64>> {
        self.layout.carried[at(g.0)].then(|| self.out.guide_acc[at(g.0)])
    }

    /// Records carried guide `me`'s velocity.
    pub fn set_guide_vel(&mut self, me: &Me, v: LineVelocity<f64>) {
        self.out.guide_vel[at(me.guide.0)] = v;
    }

    /// Records carried guide `me`'s acceleration.
    pub fn set_guide_acc(&mut self, me: &Me, a: LineAcceleration<f64>) {
        self.out.guide_acc[at(me.guide.0)] = a;
    }

    /// The rate of `link` at this level (`None`: it does not turn).
    pub fn link_rate(&self, link: LinkSlot) -> Option<f64> {
        let l = self.layout.turning[at(link.0)]?;
        Some(self.out.links[at(l.0)])
    }

    /// The angular velocity of `link`, read in the acceleration analysis
    /// (`None`: it does not turn).
    pub fn link_omega_in_accel(&self, link: LinkSlot) -> Option<f64> {
        let l = self.layout.turning[at(link.0)]?;
        Some(self.vel?.links[at(l.0)])
    }

    /// Input `i`'s value (`pos.input.NAME`).
    pub fn value(&self, i: InputSlot) -> f64 {
        self.pose.q[at(i.0)]
    }

    /// Input `i`'s rate.
    pub fn rate(&self, i: InputSlot) -> f64 {
        self.vel.unwrap_or(&*self.out).q[at(i.0)]
    }

    /// Input `i`'s acceleration (NaN in the velocity analysis).
    pub fn accel_of(&self, i: InputSlot) -> f64 {
        if self.accel() {
            self.out.q[at(i.0)]
        } else {
            f64::NAN
        }
    }

    /// Records the motion of `me`'s point.
    pub fn set_motion(&mut self, me: &Me, v: Vector2<f64>) {
        self.out.points[at(me.point.0)] = v;
    }

    /// Records the rate of `me`'s link `k`.
    pub fn set_own(&mut self, me: &Me, k: usize, w: f64) {
        if let Some(l) = me.links.get(k) {
            self.out.links[at(l.0)] = w;
        }
    }

    /// Records the rate of `me`'s slide `k`.
    pub fn set_slide(&mut self, me: &Me, k: usize, v: f64) {
        if let Some(s) = self.out.slides[at(me.step.0)].get_mut(k) {
            *s = v;
        }
    }

    /// Keeps `me`'s group rate state; `condition`: its velocity system's
    /// conditioning (joins the mechanism's).
    pub fn keep<S: State>(&mut self, me: &Me, state: S, condition: Option<f64>) {
        self.out.groups[at(me.step.0)] = state.kept();
        if let (false, Some(c)) = (self.accel(), condition) {
            self.out.conditions.push(c);
        }
    }

    /// The velocity-level rate state of `me`.
    pub fn vel_group<S: State>(&self, me: &Me) -> Option<&S> {
        S::of(&self.vel?.groups[at(me.step.0)])
    }
}

/// The error of a run-time step that finds a state missing (a plan the
/// evaluator cannot walk: a bug of the evaluator, reported, not a panic).
pub fn missing(primitive: mechanism_core::Primitive) -> Error<f64> {
    Error::new(
        primitive,
        mechanism_core::Fault::NonFinite {
            what: "state of an earlier step",
        },
    )
}

/// The walks after the position in which a [`Step`] does something.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Walks {
    /// Its `rates` write a motion (velocity and acceleration walks).
    pub rates: bool,
    /// Its `forces` write reactions or loads (the force walk).
    pub forces: bool,
}

impl Walks {
    /// Both walks: a group or driver.
    pub const ALL: Walks = Walks {
        rates: true,
        forces: true,
    };
}

/// A kind's run-time facet: its statement compiled into a [`Step`].
pub trait RunKind {
    /// The statement as a step of the compiled plan: its slots resolved,
    /// its dimensions valued with the current parameters.
    fn compile(&self, cx: &Compile<'_>) -> Box<dyn Step>;
}

/// One statement of the compiled plan: the `f64` twin of its kind's
/// emitted position, rate, force, link-angle and slide code, calling the
/// same core primitives with the same arguments.
pub trait Step: Send + Sync {
    /// The name of its group (what its errors name).
    fn group(&self) -> &'static str;

    /// Its position: what its `GroupKind::position` emits, computed into
    /// `pose`; its velocity system's scaled determinant, if it has one.
    fn position(&self, pose: &mut RunPose) -> Result<Option<f64>, Error<f64>>;

    /// Its velocity (`cx.accel()` false) or acceleration: what its `rates`
    /// emits, computed. A kind without rates (a ground point) does nothing.
    fn rates(&self, cx: &mut RunCx<'_>) -> Result<(), Error<f64>>;

    /// Its joint reactions and driving efforts in the force analysis: what
    /// its `GroupKind::forces` emits, computed with the same core call on
    /// the same loads, passing the same reactions to the same bodies. A
    /// kind without forces (a ground point, a guide, a point on a link)
    /// does nothing.
    fn forces(&self, cx: &mut ForceRunCx<'_>) -> Result<(), Error<f64>>;

    /// The walks whose calls of it do something: the compiled plan leaves
    /// it out of the others (a ground point's rates and forces, a fixed
    /// guide's rates, a point's forces).
    fn walks(&self) -> Walks;

    /// The raw direction of its link `index` (the second of
    /// `GroupKind::link_direction`), from the position.
    fn link_dir(&self, index: usize, pose: &RunPose) -> Vector2<f64>;

    /// The angle output of its link when not the angle of its direction
    /// (a crank's: its input reduced to (-pi, pi]).
    fn link_angle(&self, _pose: &RunPose) -> Option<f64> {
        None
    }

    /// Its slide `k` (length units) from the position; `None` for a kind
    /// without slides.
    fn slide(&self, _k: usize, _pose: &RunPose) -> Option<f64> {
        None
    }
}

/// The power balance's terms summed as they come, as the generated
/// `forces()` sums them: the first term, then each next one added in
/// order; beside it the largest magnitude, and whether any was seen.
#[derive(Clone, Copy, Debug, Default)]
pub struct PowerSum {
    sum: Option<f64>,
    scale: f64,
}

impl PowerSum {
    /// Adds the next term (W: force x length / time).
    pub fn push(&mut self, term: f64) {
        self.sum = Some(match self.sum {
            Some(s) => s + term,
            None => term,
        });
        let a = mechanism_core::geometry::abs(term);
        if a > self.scale {
            self.scale = a;
        }
    }

    /// |sum| over the largest |term|: 0 with no term or when all vanish,
    /// 1 when the sum or the largest term is not finite (the generated
    /// `__power_residual`).
    pub fn residual(&self) -> f64 {
        let Some(sum) = self.sum else {
            return 0.0;
        };
        if !(self.scale.is_finite() && sum.is_finite()) {
            1.0
        } else if self.scale > 0.0 {
            mechanism_core::geometry::abs(sum) / self.scale
        } else {
            0.0
        }
    }
}

/// The smallest of a sequence of conditioning figures, folded in order
/// with `geometry::min` from a starting value (as the generated code
/// folds them).
#[derive(Clone, Copy, Debug)]
pub struct RunningMin(pub f64);

impl RunningMin {
    /// Folds in the next figure.
    pub fn push(&mut self, x: f64) {
        self.0 = mechanism_core::geometry::min(self.0, x);
    }
}

/// The reaction at the joint between a group's two links.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ForceValue {
    /// A revolute joint's force (force units, global frame).
    Force(Vector2<f64>),
    /// A prismatic pair's reaction (normal force, couple about its point).
    Prismatic(PrismaticReaction<f64>),
}

/// What a kind's run-time force step reads and where it writes: the `f64`
/// twin of [`super::forces::ForceCx`]. Loads are accumulated per link as a
/// wrench about the link's reference point (its first point), in the order
/// and with the operations the emitted `forces()` uses. The fields' values
/// go to `values` in the order of the forces struct; their names are
/// written once, when the plan is compiled (`names`).
pub struct ForceRunCx<'r> {
    /// The position.
    pub pose: &'r RunPose,
    /// The velocity level.
    pub vel: &'r Motion,
    /// The acceleration level.
    pub acc: &'r Motion,
    /// The static facts.
    pub layout: &'r Layout,
    /// The load of each loaded link, about its reference point.
    pub loads: &'r mut Vec<Option<Wrench<f64>>>,
    /// The fields' values, in order (a revolute force: x, y; a prismatic
    /// reaction: force x, y and moment; a scalar: itself).
    pub values: &'r mut Vec<f64>,
    /// The power terms of the balance, summed in order.
    pub power: &'r mut PowerSum,
    /// The groups' force-system conditioning, the smallest so far.
    pub conditions: &'r mut RunningMin,
    /// The fields' names and kinds, when the plan is compiled (`None` when
    /// evaluating).
    pub names: Option<&'r mut Vec<(String, Held)>>,
}

impl ForceRunCx<'_> {
    /// Point `p` of the position.
    pub fn at(&self, p: PointSlot) -> Point2<f64> {
        self.pose.point(p)
    }

    /// The body owning point `p` (`None`: the ground).
    pub fn body_of_point(&self, p: PointSlot) -> Option<LinkSlot> {
        self.layout.point_body[at(p.0)]
    }

    /// The body carrying guide `g` (`None`: the ground).
    pub fn body_of_guide(&self, g: GuideSlot) -> Option<LinkSlot> {
        self.layout.guide_body[at(g.0)]
    }

    /// The reference point of `link`'s load: its first point.
    pub fn reference(&self, link: LinkSlot) -> Option<PointSlot> {
        self.layout.reference[at(link.0)]
    }

    /// The velocity of point `p` (`None`: it never moves).
    pub fn velocity_of(&self, p: PointSlot) -> Option<Vector2<f64>> {
        self.layout.moving[at(p.0)].then(|| self.vel.points[at(p.0)])
    }

    /// The acceleration of point `p`.
    pub fn acceleration_of(&self, p: PointSlot) -> Vector2<f64> {
        self.acc.points[at(p.0)]
    }

    /// The angular velocity and acceleration of `link` (`None`: it does
    /// not turn).
    pub fn rates_of(&self, link: LinkSlot) -> Option<(f64, f64)> {
        let l = self.layout.turning[at(link.0)]?;
        Some((self.vel.links[at(l.0)], self.acc.links[at(l.0)]))
    }

    /// Input `i`'s rate.
    pub fn rate(&self, i: InputSlot) -> f64 {
        self.vel.q[at(i.0)]
    }

    /// The angular velocity and acceleration recorded for link slot `l`
    /// (a slot of `Layout::turning`: the link whose rates a link shares).
    pub fn link_rates(&self, l: LinkSlot) -> (f64, f64) {
        (self.vel.links[at(l.0)], self.acc.links[at(l.0)])
    }

    /// The load of `link` as a wrench about `point` (zero when it carries
    /// none yet).
    pub fn load_about(&self, link: LinkSlot, point: PointSlot) -> Wrench<f64> {
        let (Some(load), Some(r)) = (self.loads[at(link.0)], self.reference(link)) else {
            return Wrench::zero();
        };
        if point == r {
            load
        } else {
            load.moved(&self.at(r), &self.at(point))
        }
    }

    /// The loads of `me`'s two links about `point`.
    pub fn loads_about(&self, me: &Me, point: PointSlot) -> (Wrench<f64>, Wrench<f64>) {
        (
            self.load_about(me.links[0], point),
            self.load_about(me.links[1], point),
        )
    }

    /// Adds a wrench (about the link's reference point) to a link's load.
    pub fn add(&mut self, link: LinkSlot, wrench: Wrench<f64>) {
        let load = &mut self.loads[at(link.0)];
        *load = Some(match *load {
            Some(l) => l + wrench,
            None => wrench,
        });
    }

    /// A force acting on `link` at point `at`, added to its load.
    pub fn force_on(&mut self, link: LinkSlot, force: Vector2<f64>, at: PointSlot) {
        let Some(r) = self.reference(link) else {
            return;
        };
        let wrench = if at == r {
            Wrench::new(force, 0.0)
        } else {
            Wrench::force_at(&force, &self.at(at), &self.at(r))
        };
        self.add(link, wrench);
    }

    /// A wrench of a force at point `at` (and a couple) whose negation acts
    /// on `body` (nothing for the ground): a driver's reaction on the body
    /// carrying it.
    pub fn react_on(
        &mut self,
        body: Option<LinkSlot>,
        force: Vector2<f64>,
        at: Point2<f64>,
        couple: Option<f64>,
    ) {
        let Some(b) = body else { return };
        let Some(r) = self.reference(b) else { return };
        let w = Wrench::force_at(&(-force), &at, &self.at(r));
        let w = match couple {
            Some(c) => w.with_couple(-c),
            None => w,
        };
        self.add(b, w);
    }

    /// A prismatic reaction (about point `about`) negated onto `body`.
    pub fn prismatic_on(
        &mut self,
        body: Option<LinkSlot>,
        rx: &PrismaticReaction<f64>,
        about: PointSlot,
    ) {
        let Some(body) = body else {
            return;
        };
        let Some(r) = self.reference(body) else {
            return;
        };
        let wrench = if about == r {
            -rx.wrench()
        } else {
            -rx.wrench_about(&self.at(about), &self.at(r))
        };
        self.add(body, wrench);
    }

    /// An outer revolute joint at `point` whose reaction on the group is
    /// `force`: passes it, negated, to the body owning the point (nothing
    /// for the ground) and returns that body.
    pub fn pass_revolute(&mut self, point: PointSlot, force: Vector2<f64>) -> Option<LinkSlot> {
        let body = self.body_of_point(point);
        if let Some(b) = body {
            self.force_on(b, -force, point);
        }
        body
    }

    /// A revolute reaction: the force of `from` (a body or the ground) on
    /// `to` (`r_FROM_TO`).
    pub fn revolute(&mut self, from: Option<LinkSlot>, to: LinkSlot, force: Vector2<f64>) {
        self.name(
            |l| Family::Reaction.pair_text(l.link_name(from), l.link_name(Some(to))),
            Held::Force,
        );
        self.values.extend([force.x, force.y]);
    }

    /// A prismatic pair's reaction of `from` on `to`.
    pub fn prismatic(&mut self, from: Option<LinkSlot>, to: LinkSlot, rx: PrismaticReaction<f64>) {
        self.name(
            |l| Family::Reaction.pair_text(l.link_name(from), l.link_name(Some(to))),
            Held::Prismatic,
        );
        self.values.extend([rx.force.x, rx.force.y, rx.moment]);
    }

    /// The joint between `me`'s first two links (the force of the first
    /// on the second).
    pub fn inner(&mut self, me: &Me, value: ForceValue) {
        let (a, b) = (me.links[0], me.links[1]);
        match value {
            ForceValue::Prismatic(rx) => self.prismatic(Some(a), b, rx),
            ForceValue::Force(f) => self.revolute(Some(a), b, f),
        }
    }

    /// A driving effort of `input` (`drive_INPUT`), named `name`.
    pub fn drive(&mut self, input: &'static str, held: Held, value: f64) {
        self.scalar(|_| Family::Drive.text(input), held, value);
    }

    /// A scalar field named by `name` (called only when compiling).
    pub fn scalar(&mut self, name: impl FnOnce(&Layout) -> String, held: Held, value: f64) {
        self.name(name, held);
        self.values.push(value);
    }

    /// Records a field's name when compiling.
    fn name(&mut self, name: impl FnOnce(&Layout) -> String, held: Held) {
        let layout = self.layout;
        if let Some(names) = self.names.as_deref_mut() {
            names.push((name(layout), held));
        }
    }
}
