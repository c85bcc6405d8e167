//! The drawing's own rules, before and during the decomposition: every
//! joint on a link, every input on something it can drive, a point's two
//! coordinates given together, every cylinder driven; and a group's joint
//! drawn where its assembly is unambiguous (off a dyad's line, off an RRP's
//! normal, off an RPR's foot, on a yoke's slot, two lines that cross).

use super::steps::side;
use super::{Coordinate, Drawing, JointId, GROUND};
use crate::diag::{did_you_mean, Diagnostics};

/// A `ground` link, every joint on a link, every input on a moving link.
/// `false` with errors otherwise.
pub(super) fn structure_holds(d: &Drawing, errors: &mut Diagnostics) -> bool {
    let before = errors.len();
    if d.ground().is_none() {
        // Blocks on the ground's lines and no pin on it: a trammel's frame.
        let lines_only = d.sliders.iter().any(|s| s.on.is_none());
        errors.push(
            d.span,
            if lines_only {
                "the drawing has no fixed link: name it `ground`, with its joints, `ground = [O2, O4]`, or `ground = []` when it has no pin, only the lines its blocks slide on"
            } else {
                "the drawing has no fixed link: name it `ground`, with its joints, `ground = [O2, O4]`"
            },
        );
    }
    for (k, j) in d.joints.iter().enumerate() {
        if !d.links.iter().any(|l| l.joints.contains(&JointId(k))) {
            errors.push(
                j.name.span(),
                format!(
                    "joint `{}` is on no link; list it in the links it joins",
                    j.name
                ),
            );
        }
    }
    let link_names: Vec<String> = d.links.iter().map(|l| l.name.to_string()).collect();
    coordinates_hold(d, errors);
    cylinders_driven(d, errors);
    for i in d.inputs.iter().filter(|i| i.length) {
        if d.cylinder_named(&i.link).is_none() {
            let names = d.cylinders.iter().map(|c| c.names[0].to_string());
            let names: Vec<String> = names.collect();
            errors.push(
                i.link.span(),
                format!(
                    "no cylinder named `{}`: `length(..)` names a `cylinder` statement's cylinder{}",
                    i.link,
                    did_you_mean(&i.link.to_string(), names.iter().map(String::as_str))
                ),
            );
        }
    }
    for i in d
        .inputs
        .iter()
        .filter(|i| !i.length && i.coordinate.is_none())
    {
        for l in std::iter::once(&i.link).chain(&i.carrier) {
            if d.link_named(l).is_none() {
                errors.push(
                    l.span(),
                    format!(
                        "no link named `{l}`{}",
                        did_you_mean(&l.to_string(), link_names.iter().map(String::as_str))
                    ),
                );
            }
        }
        let block = |l: &syn::Ident| d.link_named(l).is_some_and(|l| d.slider_of(l).is_some());
        if let Some(c) = i.carrier.as_ref().filter(|c| block(c)) {
            errors.push(
                c.span(),
                format!("`{c}` is a block, whose axis is its line: a motor it carries is not drawn yet; write it with the group statements, `crank(K, r, {}, {c})`", i.name),
            );
        }
        if i.link == GROUND {
            errors.push(
                i.link.span(),
                "the ground does not turn; an input is the angle of a moving link",
            );
        }
        let block = d.link_named(&i.link).map(|l| d.slider_of(l).is_some());
        match (i.slide, block) {
            (true, Some(false)) => errors.push(
                i.link.span(),
                format!("`{}` is no slider's block: `slide(..)` names a block of a `slider` statement", i.link),
            ),
            (false, Some(true)) => errors.push(
                i.link.span(),
                format!("`{}` is a slider's block, which does not turn: its input is its slide, `input {} = slide({});`", i.link, i.name, i.link),
            ),
            _ => {}
        }
    }
    errors.len() == before
}

/// Every coordinate input names a moving joint, once, with its other
/// coordinate an input too; errors otherwise.
pub(super) fn coordinates_hold(d: &Drawing, errors: &mut Diagnostics) {
    let joint_names: Vec<String> = d.joints.iter().map(|j| j.name.to_string()).collect();
    let fixed = d.ground().map(|g| &d.link(g).joints);
    for (n, i) in d.inputs.iter().enumerate() {
        let Some(axis) = i.coordinate else { continue };
        let (joint, (this, other)) = (
            &i.link,
            match axis {
                Coordinate::X => ("x", "y"),
                Coordinate::Y => ("y", "x"),
            },
        );
        let Some(j) = d.joints.iter().position(|j| &j.name == joint) else {
            errors.push(
                joint.span(),
                format!(
                    "no joint named `{joint}` (a coordinate input, `input {} = P.{this};`, names a joint of `joints`){}",
                    i.name,
                    did_you_mean(&joint.to_string(), joint_names.iter().map(String::as_str)),
                ),
            );
            continue;
        };
        if fixed.is_some_and(|f| f.contains(&JointId(j))) {
            errors.push(
                joint.span(),
                format!("`{joint}` is a joint of the ground, which does not move; a coordinate input places a moving joint (an end point, a foot)"),
            );
            continue;
        }
        let same = |k: &super::Input| k.coordinate == i.coordinate && &k.link == joint;
        if d.inputs[..n].iter().any(same) {
            errors.push(
                i.name.span(),
                format!("`{joint}.{this}` is already an input; remove this one"),
            );
        }
        // A partner on an unknown joint is reported there (a misspelt name).
        let partner = d.inputs.iter().any(|k| {
            k.coordinate.is_some()
                && k.coordinate != i.coordinate
                && (&k.link == joint || !d.joints.iter().any(|j| j.name == k.link))
        });
        if !partner {
            errors.push(
                i.name.span(),
                format!("`{joint}.{this}` is an input, so `{joint}.{other}` must be one too: a joint is placed by both its coordinates (inverse kinematics); add `input {joint}_{other} = {joint}.{other};`"),
            );
        }
    }
}

/// `true` when the drawing has the dyad's joint `c` clearly on one side of
/// the line through its known joints `a`, `b` (the side that picks its
/// assembly); else an error on `c` (a drawing at a dead centre, or with `c`
/// on that line, does not say which).
pub(super) fn off_the_line(
    d: &Drawing,
    a: JointId,
    b: JointId,
    c: JointId,
    errors: &mut Diagnostics,
) -> bool {
    let (pa, pb, pc) = (d.joint(a).at, d.joint(b).at, d.joint(c).at);
    let scale = (pb.0 - pa.0).hypot(pb.1 - pa.1) * (pc.0 - pa.0).hypot(pc.1 - pa.1);
    let cross = side(pa, pb, pc);
    // 1e-9: a sine that small is a drawing on the line to its last digits.
    // A drawing too large for an f64 is not judged here: its lengths
    // overflow, which the lowering reports on the joint.
    if cross.abs() > 1e-9 * scale || !(cross.is_finite() && scale.is_finite()) {
        return true;
    }
    let (na, nb, nc) = (&d.joint(a).name, &d.joint(b).name, &d.joint(c).name);
    errors.push(
        nc.span(),
        format!("the drawing has `{nc}` on the line through `{na}` and `{nb}`, which it is solved from (a dead centre), so it does not say on which side `{nc}` assembles: draw the mechanism at a pose where `{nc}` is off that line"),
    );
    false
}

/// `true` when the drawing has the RRP's joint `c` clearly ahead of or
/// behind the foot of `a` on the block's line (which picks its assembly);
/// else an error on `c`: the link drawn square to the line (the tangent
/// pose, where the two assemblies meet).
pub(super) fn off_the_normal(
    d: &Drawing,
    a: JointId,
    c: JointId,
    slider: usize,
    errors: &mut Diagnostics,
) -> bool {
    let (pa, pc, dir) = (d.joint(a).at, d.joint(c).at, d.sliders[slider].dir);
    let (dx, dy) = (pc.0 - pa.0, pc.1 - pa.1);
    let along = dx * dir.0 + dy * dir.1;
    if along.abs() > 1e-9 * dx.hypot(dy) || !along.is_finite() {
        return true;
    }
    let (na, nc) = (&d.joint(a).name, &d.joint(c).name);
    errors.push(
        nc.span(),
        format!("the drawing has `{na}`-`{nc}` square to the line `{nc}`'s block slides on (the pose where its two assemblies meet), so it does not say which is meant: draw the mechanism at a pose where `{nc}` is ahead of or behind the foot of `{na}` on that line"),
    );
    false
}

/// Every cylinder is driven by one `length(..)` input; an error on the
/// cylinder otherwise (a cylinder left free is not drawn yet).
pub(super) fn cylinders_driven(d: &Drawing, errors: &mut Diagnostics) {
    for c in &d.cylinders {
        let name = &c.names[0];
        let drives = d.inputs.iter().filter(|i| i.length && &i.link == name);
        match drives.count() {
            1 => {}
            0 => errors.push(
                name.span(),
                format!("cylinder `{name}` has no input: the drawn form drives a cylinder by its length, `input len = length({name});` (a cylinder that moves freely is not drawn yet: write it with the group statements, `rpr`)"),
            ),
            n => errors.push(
                name.span(),
                format!("cylinder `{name}` is driven by {n} inputs; give it one, `input len = length({name});`"),
            ),
        }
    }
}

/// `true` when the drawing has the RPR's pinned joint `j` clearly ahead of
/// or behind the foot of `pivot` on the slot's line (which picks its
/// assembly); else an error on `j` (the pose where the two meet).
pub(super) fn off_the_foot(
    d: &Drawing,
    j: JointId,
    pivot: JointId,
    slider: usize,
    errors: &mut Diagnostics,
) -> bool {
    let (pj, pp, dir) = (d.joint(j).at, d.joint(pivot).at, d.sliders[slider].dir);
    let (dx, dy) = (pj.0 - pp.0, pj.1 - pp.1);
    let along = dx * dir.0 + dy * dir.1;
    if along.abs() > 1e-9 * dx.hypot(dy) || !along.is_finite() {
        return true;
    }
    let (nj, np) = (&d.joint(j).name, &d.joint(pivot).name);
    let block = &d.link(d.sliders[slider].link).name;
    errors.push(
        nj.span(),
        format!("the drawing has `{block}`'s line square to `{np}`-`{nj}`, with `{nj}` at the foot of `{np}` on it (the pose where its two assemblies meet), so it does not say which is meant: draw the mechanism at a pose where `{nj}` is ahead of or behind that foot along the line"),
    );
    false
}

/// `true` when the yoke's joint (the block of `sliders[yoke]`) is drawn on
/// its slot's line, the line of `sliders[slider]` through `j`, and the slot
/// crosses the yoke's line; else an error on the yoke's joint.
pub(super) fn on_the_slot(
    d: &Drawing,
    j: JointId,
    slider: usize,
    yoke: usize,
    errors: &mut Diagnostics,
) -> bool {
    let (s, y) = (&d.sliders[slider], &d.sliders[yoke]);
    let (pj, pq) = (d.joint(j).at, d.joint(y.at).at);
    let (dx, dy) = (pq.0 - pj.0, pq.1 - pj.1);
    let off = s.dir.0 * dy - s.dir.1 * dx;
    let cross = s.dir.0 * y.dir.1 - s.dir.1 * y.dir.0;
    let (nq, yoke_name) = (&d.joint(y.at).name, &d.link(y.link).name);
    let slot = &d.link(s.link).name;
    if cross.abs() <= 1e-9 {
        errors.push(
            nq.span(),
            format!("`{slot}`'s slot is drawn parallel to the line `{yoke_name}` slides on, so it cannot drive `{yoke_name}` (an RPP with its slot along its guide is singular at every pose): draw the slot across that line"),
        );
        return false;
    }
    // 1e-9: a sine that small is a drawing on the line to its last digits.
    if off.abs() <= 1e-9 * dx.hypot(dy) || !off.is_finite() {
        return true;
    }
    errors.push(
        nq.span(),
        format!("`{nq}` is the reference point of `{yoke_name}`, in whose slot `{slot}` slides (an RPP): draw it where that slot (the line of `{slot}` through `{}`) crosses the line `{yoke_name}` slides on", d.joint(j).name),
    );
    false
}

/// `true` when the two lines of a PRP cross (not parallel as drawn); else
/// an error on its joint.
pub(super) fn across(
    d: &Drawing,
    c: JointId,
    sliders: [usize; 2],
    errors: &mut Diagnostics,
) -> bool {
    let (a, b) = (d.sliders[sliders[0]].dir, d.sliders[sliders[1]].dir);
    if (a.0 * b.1 - a.1 * b.0).abs() > 1e-9 {
        return true;
    }
    let nc = &d.joint(c).name;
    errors.push(
        nc.span(),
        format!("the two blocks at `{nc}` slide on lines drawn parallel, so they do not fix `{nc}` (a PRP with parallel lines is singular): draw them across each other"),
    );
    false
}
