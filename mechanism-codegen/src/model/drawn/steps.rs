//! What the decomposition finds, in the terms the emitter reads: the
//! steps (one group statement each, in solve order), the frames and axes of
//! the links they place, and the state of the placement while it runs.

use super::{Drawing, InputId, JointId, LinkId};

/// A link's frame: the joint at its origin and the joint its axis points to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Frame {
    pub origin: JointId,
    pub toward: JointId,
}

/// A placed link's drawn axis: from one of its joints toward another, or
/// from one of its joints along the line of a block sliding on it (the
/// slotted link of an RPR, whose axis is its slot).
#[derive(Clone, Copy, Debug)]
pub(super) enum Axis {
    Joints(Frame),
    Slot { origin: JointId, slider: usize },
}

impl Axis {
    /// The joint at the axis's origin.
    pub fn origin(self) -> JointId {
        match self {
            Axis::Joints(f) => f.origin,
            Axis::Slot { origin, .. } => origin,
        }
    }
}

/// The link that carries a driver's motor: the link, its frame as placed,
/// and the line the input is measured from (its first two joints as listed).
#[derive(Clone, Copy, Debug)]
pub(super) struct Carrier {
    pub link: LinkId,
    pub frame: Frame,
    pub listed: Frame,
}

/// One group statement, in solve order.
pub(super) enum Step {
    /// A joint of the ground.
    Ground(JointId),
    /// A driver: `link` turns by `input` about `frame.origin`, its axis
    /// pointing to `frame.toward` (the joint it places); `carrier`: the link
    /// carrying its motor (`None`: the ground).
    Crank {
        link: LinkId,
        frame: Frame,
        input: InputId,
        carrier: Option<Carrier>,
    },
    /// A gear pair: the link of `gears[gear]` turns about `frame.origin`,
    /// its axis pointing to `frame.toward` (the joint it places), geared to
    /// the link placed in `mesh` and pivoted on the one placed in `carrier`
    /// (`None`: the ground).
    Gear {
        gear: usize,
        frame: Frame,
        mesh: Option<Frame>,
        carrier: Option<Frame>,
    },
    /// An RRR dyad: joint `c` at its drawn distances from `a` on link `la`
    /// and from `b` on link `lb`.
    Rrr {
        a: JointId,
        la: LinkId,
        b: JointId,
        lb: LinkId,
        c: JointId,
    },
    /// A triad: the ternary link `t` with joints `joints` (A, B, P), each on
    /// the leg `legs[i]` from the placed joint `known[i]`.
    Triad {
        t: LinkId,
        joints: [JointId; 3],
        legs: [LinkId; 3],
        known: [JointId; 3],
    },
    /// The line a block slides on (the ground's): `sliders[k]`.
    Guide(usize),
    /// A slider driver: the block of `sliders[slider]` at its displacement
    /// `input` along its line.
    Slide { slider: usize, input: InputId },
    /// An RRP dyad: joint `c` at its drawn distance from `a` on link `la`,
    /// and on the block of `sliders[slider]`.
    Rrp {
        a: JointId,
        la: LinkId,
        c: JointId,
        slider: usize,
    },
    /// A target driver: `joint` placed at the inputs `x` and `y`, its
    /// coordinates (inverse kinematics).
    Target {
        joint: JointId,
        x: InputId,
        y: InputId,
    },
    /// A joint fixed on `link`, in the link's frame.
    Point {
        link: LinkId,
        frame: Frame,
        joint: JointId,
    },
    /// An RPR dyad: the block of `sliders[slider]`, pinned at the placed
    /// joint `j`, slides in the slot of `link` (its line), which turns about
    /// its placed joint `pivot`.
    Rpr {
        j: JointId,
        pivot: JointId,
        link: LinkId,
        slider: usize,
    },
    /// A joint fixed on the slotted `link` of an RPR, in its frame: at
    /// `pivot`, along the line of `sliders[slider]`.
    SlotPoint {
        link: LinkId,
        pivot: JointId,
        slider: usize,
        joint: JointId,
    },
    /// The line of `sliders[slider]`, carried by the placed link it slides
    /// on (whose drawn axis is `axis`): through the axis's origin, or
    /// (`mark`) through the block's drawn place, the point of [`Step::Mark`].
    CarriedGuide {
        slider: usize,
        axis: Axis,
        mark: bool,
    },
    /// The point `BLOCK_zero` of the link that `sliders[slider]` slides on
    /// (axis `axis`), where the drawing has the block: a carried slide is
    /// measured from it.
    Mark { slider: usize, axis: Axis },
    /// An RRP dyad on a carried line: joint `c` at its drawn distance from
    /// `a` on link `la`, and on the block of `sliders[slider]`, whose line is
    /// carried through `origin`.
    RrpCarried {
        a: JointId,
        la: LinkId,
        c: JointId,
        slider: usize,
        origin: JointId,
    },
    /// An RPP dyad (the sine mechanism's): the block of `sliders[slider]`,
    /// pinned at the placed joint `j`, slides in the slot of the block of
    /// `sliders[yoke]`, which slides on the ground or on a line a placed
    /// link carries through `origin`; defines that block's joint, where its
    /// slot crosses its line.
    Rpp {
        j: JointId,
        slider: usize,
        yoke: usize,
        origin: Option<JointId>,
    },
    /// A PRP dyad: joint `c` on the blocks of `sliders[k]`, each on a line
    /// (the ground's, or one its placed link carries through `origin[k]`).
    Prp {
        c: JointId,
        sliders: [usize; 2],
        origins: [Option<JointId>; 2],
    },
    /// A cylinder driver: `cylinders[cylinder]`, from its placed joint `b`,
    /// of length `input`, reaches joint `c` of `link`, which turns about its
    /// placed joint `a`.
    Actuator {
        a: JointId,
        link: LinkId,
        b: JointId,
        c: JointId,
        cylinder: usize,
        input: InputId,
    },
}

/// What is placed so far: joints known, links placed with their frames.
pub(super) struct Placed {
    /// Whether each joint is placed.
    pub(super) joint: Vec<bool>,
    /// Each placed link's frame.
    pub(super) frame: Vec<Option<Frame>>,
    /// The links whose axis is a slot's line: its origin and the slider.
    pub(super) slot: Vec<Option<(JointId, usize)>>,
}

impl Placed {
    pub(super) fn joint(&self, j: JointId) -> bool {
        self.joint[j.0]
    }

    pub(super) fn frame(&self, l: LinkId) -> Option<Frame> {
        self.frame[l.0]
    }

    pub(super) fn place(&mut self, j: JointId) {
        self.joint[j.0] = true;
    }

    pub(super) fn set_frame(&mut self, l: LinkId, origin: JointId, toward: JointId) {
        self.frame[l.0] = Some(Frame { origin, toward });
    }

    /// The drawn axis of the placed link `l`: a block's is its line (the
    /// direction of its guide, slot or slide in every group).
    pub(super) fn axis(&self, d: &Drawing, l: LinkId) -> Option<Axis> {
        self.frame(l)?;
        if let Some(k) = d.sliders.iter().position(|s| s.link == l) {
            let origin = d.sliders[k].at;
            return Some(Axis::Slot { origin, slider: k });
        }
        match self.slot[l.0] {
            Some((origin, slider)) => Some(Axis::Slot { origin, slider }),
            None => self.frame(l).map(Axis::Joints),
        }
    }
}

/// The side of `c` from the line `a -> b` (twice the signed area of the
/// triangle): positive on the left.
pub(super) fn side(a: (f64, f64), b: (f64, f64), c: (f64, f64)) -> f64 {
    (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0)
}

/// The joint after `j` in a link's list (wrapping): the one its axis points to.
pub(super) fn next_joint(list: &[JointId], j: JointId) -> JointId {
    let k = list.iter().position(|&x| x == j).unwrap_or(0);
    list[(k + 1) % list.len()]
}
