//! The next group the decomposition can place: the points of placed links,
//! a dyad (a joint on two links with placed joints), a triad (a ternary link
//! on three binary legs), a block in a slot (RPR, RRP on a carried line,
//! RPP, PRP) or a cylinder's joint.

use super::steps::{Axis, Placed, Step};
use super::{Drawing, InputId, JointId, LinkId};

/// Places, as points, the joints of placed links that are not yet placed.
/// `true` when it placed one.
pub(super) fn place_points(d: &Drawing, placed: &mut Placed, steps: &mut Vec<Step>) -> bool {
    let mut progress = false;
    for link in d.link_ids() {
        let Some(frame) = placed.frame(link) else {
            continue;
        };
        for &joint in &d.link(link).joints {
            if !placed.joint(joint) {
                placed.place(joint);
                if let Some((pivot, slider)) = placed.slot[link.0] {
                    steps.push(Step::SlotPoint {
                        link,
                        pivot,
                        slider,
                        joint,
                    });
                    progress = true;
                    continue;
                }
                steps.push(Step::Point { link, frame, joint });
                progress = true;
            }
        }
    }
    progress
}

/// A dyad: an unplaced joint on two unplaced links that each have a placed
/// joint (two different ones). Other unplaced links at the joint wait: they
/// gain it as a placed joint.
pub(super) fn find_dyad(d: &Drawing, placed: &Placed, ground: LinkId) -> Option<Step> {
    let known = |l: LinkId| d.link(l).joints.iter().copied().find(|&j| placed.joint(j));
    for c in (0..d.joints.len())
        .map(JointId)
        .filter(|&c| !placed.joint(c))
    {
        let on: Vec<(LinkId, JointId)> = d
            .link_ids()
            .filter(|&l| l != ground && placed.frame(l).is_none() && d.link(l).joints.contains(&c))
            .filter_map(|l| Some((l, known(l)?)))
            .collect();
        for (i, &(la, a)) in on.iter().enumerate() {
            if let Some(&(lb, b)) = on[i + 1..].iter().find(|(_, b)| *b != a) {
                return Some(Step::Rrr { a, la, b, lb, c });
            }
        }
        // A link with a placed joint and a block at `c` on its line.
        let block = d
            .sliders
            .iter()
            .position(|s| s.at == c && s.on.is_none() && placed.frame(s.link).is_none());
        if let (Some(&(la, a)), Some(slider)) = (on.first(), block) {
            return Some(Step::Rrp { a, la, c, slider });
        }
    }
    None
}

/// A triad: an unplaced link with three unplaced joints, each on one other
/// unplaced link, a binary leg whose other joint is placed, and no other
/// joint on an unplaced link. A leg may carry further joints that nothing
/// else uses (a mass centre drawn on it): they are points on the leg.
pub(super) fn find_triad(d: &Drawing, placed: &Placed, ground: LinkId) -> Option<Step> {
    let free = |l: LinkId| l != ground && placed.frame(l).is_none();
    for t in d
        .link_ids()
        .filter(|&t| free(t) && d.link(t).joints.len() >= 3)
    {
        if let Some([a, b, p]) = triad_legs(d, placed, t, &free) {
            return Some(Step::Triad {
                t,
                joints: [a.0, b.0, p.0],
                legs: [a.1, b.1, p.1],
                known: [a.2, b.2, p.2],
            });
        }
    }
    None
}

/// The three legs of a triad on the ternary link `t`, each `(joint on t,
/// leg, the leg's placed joint)`, or `None` when `t` is not such a link.
pub(super) fn triad_legs(
    d: &Drawing,
    placed: &Placed,
    t: LinkId,
    free: &dyn Fn(LinkId) -> bool,
) -> Option<[(JointId, LinkId, JointId); 3]> {
    let mut found = Vec::new();
    for &j in &d.link(t).joints {
        let others: Vec<LinkId> = d
            .link_ids()
            .filter(|&l| l != t && free(l) && d.link(l).joints.contains(&j))
            .collect();
        match others[..] {
            [] => {}
            [leg] if !placed.joint(j) => found.push((j, leg, leg_base(d, placed, leg, j)?)),
            _ => return None,
        }
    }
    found.try_into().ok()
}

/// The placed joint of a triad's leg `leg` hanging at `j`: its one placed
/// joint, when every other joint of it is unplaced and on no other link,
/// slider or cylinder (a point of the leg only); `None` otherwise.
fn leg_base(d: &Drawing, placed: &Placed, leg: LinkId, j: JointId) -> Option<JointId> {
    let mut base = None;
    for &x in d.link(leg).joints.iter().filter(|&&x| x != j) {
        if placed.joint(x) {
            if base.replace(x).is_some() {
                return None;
            }
            continue;
        }
        let elsewhere = d
            .link_ids()
            .any(|l| l != leg && d.link(l).joints.contains(&x))
            || d.sliders.iter().any(|s| s.at == x)
            || d.cylinders.iter().any(|c| c.from == x || c.to == x);
        if elsewhere {
            return None;
        }
    }
    base
}

/// A block on a moving link: an RPR (the block's joint placed, the slotted
/// link turning about a placed joint) or an RRP on the line the placed link
/// carries (the block's joint on a link with a placed joint); the steps
/// pushed, `true` when it placed one.
pub(super) fn place_slot(d: &Drawing, placed: &mut Placed, steps: &mut Vec<Step>) -> bool {
    for (slider, s) in d.sliders.iter().enumerate() {
        let Some(link) = s.on else {
            continue;
        };
        if placed.frame(s.link).is_some() {
            continue;
        }
        let j = s.at;
        // The yoke: a block on the ground, or on a placed link's line.
        let carried = |y: &super::Slider| y.on.map(|l| placed.axis(d, l));
        let yoke = d.sliders.iter().position(|y| {
            y.link == link && !matches!(carried(y), Some(None)) && !placed.joint(y.at)
        });
        if let Some(yoke) = yoke.filter(|_| placed.joint(j)) {
            let axis = carried(&d.sliders[yoke]).flatten();
            if let Some(axis) = axis {
                steps.push(Step::CarriedGuide {
                    slider: yoke,
                    axis,
                    mark: false,
                });
            }
            let origin = axis.map(Axis::origin);
            steps.push(Step::Rpp {
                j,
                slider,
                yoke,
                origin,
            });
            let q = d.sliders[yoke].at;
            placed.place(q);
            placed.set_frame(link, q, q);
            placed.set_frame(s.link, j, j);
            return true;
        }
        if placed.joint(j) && placed.frame(link).is_none() {
            let Some(pivot) = d
                .link(link)
                .joints
                .iter()
                .copied()
                .find(|&p| placed.joint(p))
            else {
                continue;
            };
            steps.push(Step::Rpr {
                j,
                pivot,
                link,
                slider,
            });
            placed.set_frame(s.link, j, j);
            placed.set_frame(link, pivot, pivot);
            placed.slot[link.0] = Some((pivot, slider));
            return true;
        }
        let Some(axis) = placed.axis(d, link).filter(|_| !placed.joint(j)) else {
            continue;
        };
        let leg = d.link_ids().find_map(|la| {
            let free = la != s.link && placed.frame(la).is_none();
            let joints = &d.link(la).joints;
            let a = joints.iter().copied().find(|&a| placed.joint(a));
            (free && joints.contains(&j)).then_some((la, a?))
        });
        let Some((la, a)) = leg else {
            if let Some(prp) = prp_at(d, placed, slider) {
                place_prp(d, placed, steps, prp);
                return true;
            }
            continue;
        };
        steps.push(Step::CarriedGuide {
            slider,
            axis,
            mark: false,
        });
        steps.push(Step::RrpCarried {
            a,
            la,
            c: j,
            slider,
            origin: axis.origin(),
        });
        placed.place(j);
        placed.set_frame(la, a, j);
        placed.set_frame(s.link, j, j);
        return true;
    }
    false
}

/// Places the cylinder of the length input `k` when its barrel's joint is
/// placed and its rod's joint is on a link turning about a placed joint:
/// an actuator driver. `true` when placed.
pub(super) fn place_actuator(
    d: &Drawing,
    k: InputId,
    placed: &mut Placed,
    steps: &mut Vec<Step>,
) -> bool {
    let Some(cylinder) = d.cylinder_named(&d.input(k).link) else {
        return false;
    };
    let (b, c) = (d.cylinders[cylinder].from, d.cylinders[cylinder].to);
    if !placed.joint(b) || placed.joint(c) {
        return false;
    }
    let ground = d.ground();
    let found = d.link_ids().find_map(|l| {
        let joints = &d.link(l).joints;
        let free = Some(l) != ground && placed.frame(l).is_none() && joints.contains(&c);
        let a = joints.iter().copied().find(|&a| placed.joint(a));
        free.then_some((l, a?))
    });
    let Some((link, a)) = found else {
        return false;
    };
    steps.push(Step::Actuator {
        a,
        link,
        b,
        c,
        cylinder,
        input: k,
    });
    placed.place(c);
    placed.set_frame(link, a, c);
    true
}

/// A PRP at the joint of `sliders[first]` (on a placed moving link): a
/// second block at that joint whose line is placed (the ground's, or one a
/// placed link carries), both blocks unplaced.
pub(super) fn prp_at(d: &Drawing, placed: &Placed, first: usize) -> Option<Step> {
    let c = d.sliders[first].at;
    let origin = |k: usize| {
        d.sliders[k]
            .on
            .and_then(|l| placed.axis(d, l))
            .map(Axis::origin)
    };
    let second = (0..d.sliders.len()).find(|&k| {
        let s = &d.sliders[k];
        let line = s.on.is_none() || origin(k).is_some();
        k != first && s.at == c && line && placed.frame(s.link).is_none()
    })?;
    Some(Step::Prp {
        c,
        sliders: [first, second],
        origins: [origin(first), origin(second)],
    })
}

/// Pushes a PRP and the carried lines it needs, and places its joint.
pub(super) fn place_prp(d: &Drawing, placed: &mut Placed, steps: &mut Vec<Step>, prp: Step) {
    let Step::Prp { c, sliders, .. } = prp else {
        return;
    };
    for k in sliders {
        if let Some(axis) = d.sliders[k].on.and_then(|l| placed.axis(d, l)) {
            steps.push(Step::CarriedGuide {
                slider: k,
                axis,
                mark: false,
            });
        }
        placed.set_frame(d.sliders[k].link, c, c);
    }
    placed.place(c);
    steps.push(prp);
}
