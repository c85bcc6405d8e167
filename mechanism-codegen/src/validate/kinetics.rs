//! The rules of the force analysis, after planning (they need the points of
//! every link): it is asked for where there are loads, nothing is joined to
//! an actuator's cylinder, masses sit on links at points of those links,
//! forces act at points of one link (or name it), the guides and links loads
//! name exist, and load values have names of their own.

use super::names::{another, defined_where, link_hints, named_links, symbols};
use crate::diag::{did_you_mean, Diagnostics};
use crate::keys::GROUND;
use crate::keys::{GuideName, LinkName, Name, PointName};
use crate::kinds;
use crate::model::{ForceSpec, ForceSpecValue, Level, MassSpec, Model};
use crate::plan::{references, Plan};
use syn::Ident;

/// Rule (with a force analysis): no group or driver is joined to an
/// actuator's massless cylinder (at a point of it or on a guide it carries;
/// a barrel and a rod, `as (ARM, BARREL, ROD)`, carry what is joined to
/// them like any link). The force
/// analysis treats the cylinder as a massless two-force member (its force
/// along its axis is the drive) and solves no equations for it, so a
/// reaction passed to it would be lost and every effort behind it wrong; the
/// kinematics are fine, so this is an error of the force analysis only.
pub(super) fn nothing_on_a_cylinder(model: &Model, plan: &Plan, errors: &mut Diagnostics) {
    let cylinders: Vec<LinkName> = model
        .stmts
        .iter()
        .filter_map(|s| kinds::cylinder(s).map(LinkName::of))
        .collect();
    for stmt in &model.stmts {
        if stmt.kind.link_count() == 0 {
            continue;
        }
        for r in references(stmt) {
            let name = r.to_string();
            let (point, guide) = (PointName::of(r), GuideName::of(r));
            let (body, what) = match (plan.body_of_point(&point), plan.body_of_guide(&guide)) {
                (Some(b), _) => (b, "a point of"),
                (None, Some(b)) => (b, "a guide carried by"),
                (None, None) => continue,
            };
            if cylinders.contains(&body) {
                errors.push(
                    r.span(),
                    format!(
                        "`{name}` is {what} the actuator's cylinder `{body}`, which the force analysis takes as a massless two-force member (it carries only its axial force): `{}` cannot be joined to it there; join it to the link the actuator drives or to the ground, or make the cylinder a barrel and a rod by naming three links, `as (ARM, BARREL, ROD)`",
                        stmt.name
                    ),
                );
            }
        }
    }
}

/// Rule: `analysis forces` has something to carry (a mass, force or torque),
/// and an `analysis` below the force analysis is not written beside the
/// statements that ask for it.
pub(super) fn level_matches_loads(model: &Model, errors: &mut Diagnostics) {
    let k = &model.kinetics;
    let loaded = !k.masses.is_empty() || !k.forces.is_empty() || !k.torques.is_empty();
    if model.level >= Level::Forces && !loaded && !k.declared {
        if let Some(span) = model.level_span {
            errors.push(span, "`analysis forces` needs something to carry: add `mass LINK { m = .., at = POINT }`, `force at POINT = (fx, fy);` or `torque on LINK = t;`");
        }
    }
    if k.declared && model.level < Level::Forces {
        if let Some(span) = model.level_span {
            errors.push(span, "this `analysis` leaves out the force analysis that the `mass`, `force` and `torque` statements ask for; write `analysis forces;` or remove the line");
        }
    }
}

/// Rule: `gravity` comes with at least one mass, through which it acts.
pub(super) fn gravity_has_masses(model: &Model, errors: &mut Diagnostics) {
    let k = &model.kinetics;
    if k.gravity.is_some() && k.masses.is_empty() {
        if let Some((span, _, _)) = &k.gravity {
            errors.push(*span, "`gravity` acts through masses, and no link has one: add `mass LINK { m = .., at = POINT }`");
        }
    }
}

/// Rule: a mass sits on a link that can carry loads, at a point of that
/// link. A link may have several `mass` statements: each is a part of the
/// link with its own centre and moment of inertia about it (`emit::forces`
/// applies each part's loads at its own point).
pub(super) fn masses_on_their_links(model: &Model, plan: &Plan, errors: &mut Diagnostics) {
    for m in &model.kinetics.masses {
        mass_on_its_link(model, plan, m, errors);
    }
}

/// [`masses_on_their_links`] for the mass `m`.
fn mass_on_its_link(model: &Model, plan: &Plan, m: &MassSpec, errors: &mut Diagnostics) {
    if !loadable_link(model, plan, &m.link, "a mass", errors) {
        return;
    }
    let link = LinkName::of(&m.link);
    let points = &plan.links[&link].points;
    let at = PointName::of(&m.at);
    if !plan.owner.contains_key(&at) {
        let message = unknown_point(
            model,
            plan,
            &at,
            points,
            "the centre of mass is a point of the link",
        );
        if let Some(message) = message {
            errors.push(m.at.span(), message);
        }
        return;
    }
    if !points.contains(&at) {
        errors.push(
            m.at.span(),
            format!(
                "the centre of mass must be a point of `{link}`, and `{at}` is not; its points are {}; or define one: `let G = point({link}, from {}, distance, angle);`",
                points.iter().map(|p| format!("`{p}`")).collect::<Vec<_>>().join(", "),
                points.first().map_or("A", PointName::as_str),
            ),
        );
    }
}

/// Rule: a force acts at a point of one link that can carry loads (the link
/// named after `on`, or the only one the point is on), and a force `along` a
/// guide names a guide.
pub(super) fn forces_at_points_of_links(model: &Model, plan: &Plan, errors: &mut Diagnostics) {
    for f in &model.kinetics.forces {
        // A force at no known point gets that error alone.
        if force_at_a_point_of_its_link(model, plan, f, errors) {
            force_along_a_guide(model, plan, f, errors);
        }
    }
}

/// [`forces_at_points_of_links`]: the point and link of the force `f`;
/// `false` when its point is not found.
fn force_at_a_point_of_its_link(
    model: &Model,
    plan: &Plan,
    f: &ForceSpec,
    errors: &mut Diagnostics,
) -> bool {
    let at = PointName::of(&f.at);
    if !plan.owner.contains_key(&at) {
        let on =
            f.on.as_ref()
                .and_then(|l| plan.links.get(&LinkName::of(l)))
                .map_or(&[][..], |info| &info.points[..]);
        if let Some(message) = unknown_point(model, plan, &at, on, "a force acts at a point") {
            errors.push(f.at.span(), message);
        }
        return false;
    }
    match &f.on {
        Some(link) => {
            if loadable_link(model, plan, link, "a force", errors) {
                let l = LinkName::of(link);
                if !plan.links[&l].points.contains(&at) {
                    errors.push(
                        f.at.span(),
                        format!(
                            "`{at}` is not a point of `{l}`; its points are {}",
                            plan.links[&l]
                                .points
                                .iter()
                                .map(|p| format!("`{p}`"))
                                .collect::<Vec<_>>()
                                .join(", ")
                        ),
                    );
                }
            }
        }
        None => {
            let links = plan.links_with_point(&at);
            match links.len() {
                0 => errors.push(
                    f.at.span(),
                    format!("`{at}` is on no moving link (a force on the ground needs no analysis); apply the force at a point of a link"),
                ),
                1 => {
                    if is_cylinder(model, &links[0]) {
                        errors.push(f.at.span(), format!("`{at}` is on an actuator's cylinder only, a massless two-force member here; to load the cylinder, name its barrel and rod, `as (ARM, BARREL, ROD)`, and define the point on one of them"));
                    }
                }
                _ => errors.push(
                    f.at.span(),
                    format!(
                        "`{at}` joins {}: say which link the force acts on, e.g. `force at {at} on {} = (fx, fy);`",
                        links.iter().map(|l| format!("`{l}`")).collect::<Vec<_>>().join(" and "),
                        links[0]
                    ),
                ),
            }
        }
    }
    true
}

/// [`forces_at_points_of_links`]: the guide of a force `along` one.
fn force_along_a_guide(model: &Model, plan: &Plan, f: &ForceSpec, errors: &mut Diagnostics) {
    if let ForceSpecValue::Along(guide, _) = &f.value {
        let g = guide.to_string();
        if !plan.guides.contains_key(&GuideName::of(guide)) {
            let what = match symbols(model).get(&g) {
                Some((cat, _)) => format!("`{g}` is {}, not a guide", cat.article()),
                None => format!("cannot find guide `{g}`"),
            };
            errors.push(
                guide.span(),
                format!(
                    "{what}; `along` takes a guide, whose direction the force follows{}",
                    guide_hint(&g, plan.guides.keys().map(GuideName::as_str))
                ),
            );
        }
    }
}

/// The hint after an unknown guide `name`: the nearest guide's name; else
/// the one guide whose name ends in `_NAME` (a drawn block's line is
/// `BLOCK_line`, so `line` finds `ram_line`); else every guide there is,
/// with the drawn form's naming when a name ends in `_line`.
fn guide_hint<'a>(name: &str, guides: impl IntoIterator<Item = &'a str>) -> String {
    let guides: Vec<&str> = guides.into_iter().collect();
    let near = did_you_mean(name, guides.iter().copied());
    if !near.is_empty() {
        return near;
    }
    let suffix = format!("_{name}");
    let ending: Vec<&&str> = guides.iter().filter(|g| g.ends_with(&suffix)).collect();
    if let [one] = ending[..] {
        return format!("; did you mean `{one}`?");
    }
    if guides.is_empty() {
        return "; this definition has no guide".to_string();
    }
    let listed: Vec<String> = guides.iter().map(|g| format!("`{g}`")).collect();
    let drawn = if guides.iter().any(|g| g.ends_with("_line")) {
        " (a block of the drawn form slides on the line `BLOCK_line`)"
    } else {
        ""
    };
    format!("; the guides are {}{drawn}", listed.join(", "))
}

/// Rule: a torque acts on a link that can carry loads.
pub(super) fn torques_on_links(model: &Model, plan: &Plan, errors: &mut Diagnostics) {
    for t in &model.kinetics.torques {
        loadable_link(model, plan, &t.on, "a torque", errors);
    }
}

/// Rule: motors belong to an inverse-kinematics definition (one `target`,
/// whose two inputs they hold: two motors), each on a turning link, carried
/// by another link or the ground, under a name no input or other motor has
/// (its torque is the field `drive_NAME`).
pub(super) fn motors_hold_the_target(model: &Model, plan: &Plan, errors: &mut Diagnostics) {
    let motors = &model.kinetics.motors;
    let Some(first) = motors.first() else {
        return;
    };
    let targets = kinds::motors::targets(model);
    if targets.len() != 1 {
        let found = if targets.is_empty() {
            "this definition has none".to_string()
        } else {
            format!("this definition has {}", targets.len())
        };
        // A driver's own link: its torque is that driver's effort already.
        let driven = model.stmts.iter().find(|s| {
            s.kind.is_driver() && s.links.contains(&first.link) && s.kind.inputs().len() == 1
        });
        let forward = match driven {
            Some(s) => format!("`{}` is driven by `{i}`, whose torque is already the field `drive_{i}`", first.link, i = s.kind.inputs()[0]),
            None => "in a forward definition the motor is the driver (`crank`), its torque the field `drive_INPUT`".to_string(),
        };
        errors.push(
            first.name.span(),
            format!("a `motor` is what holds the point of an inverse-kinematics definition, one whose input is a point (`let P = target(x, y) as effector;`, or drawn `input x = P.x; input y = P.y;`), and {found}; {forward}"),
        );
        return;
    }
    if motors.len() != 2 {
        let at = motors.get(2).unwrap_or(first);
        errors.push(
            at.name.span(),
            format!("the target `{}` has two inputs, so two motors hold it, and {} {} declared: the force analysis maps the target's force to exactly two motor torques", targets[0].0.name, motors.len(), crate::diag::is_are(motors.len() as i64)),
        );
    }
    let inputs: Vec<String> = model.inputs.iter().map(|i| i.name.to_string()).collect();
    for (k, m) in motors.iter().enumerate() {
        let name = m.name.to_string();
        if inputs.contains(&name) || motors[..k].iter().any(|o| o.name == m.name) {
            errors.push(
                m.name.span(),
                format!("`{name}` is already an input's or a motor's name; a motor's torque is the field `drive_{name}`: name the motor another way, e.g. `{}`", another(&name)),
            );
        }
        for link in std::iter::once(&m.link).chain(&m.carrier) {
            if loadable_link(model, plan, link, "a motor", errors)
                && plan.turning_link(&LinkName::of(link)).is_none()
                && Some(link) == Some(&m.link)
            {
                errors.push(
                    link.span(),
                    format!("`{link}` does not turn, so no motor can turn it; a motor turns a link of a group hanging on the target"),
                );
            }
        }
        if m.carrier.as_ref() == Some(&m.link) {
            errors.push(
                m.link.span(),
                format!("the motor `{name}` turns `{}` relative to itself; name the link carrying it, or none for the ground", m.link),
            );
        } else if plan.turning_link(&LinkName::of(&m.link)).is_some()
            && motor_joint(plan, m) == Some(false)
        {
            let on = m
                .carrier
                .as_ref()
                .map_or("the ground".to_string(), |c| format!("`{c}`"));
            let own = plan
                .links
                .get(&LinkName::of(&m.link))
                .map(|i| i.points.clone())
                .unwrap_or_default();
            // A link pinned to it: the carrier the motor could have.
            let neighbour = plan
                .links
                .iter()
                .find(|(l, i)| **l != m.link && i.points.iter().any(|p| own.contains(p)))
                .map_or("LINK", |(l, _)| l.as_str());
            let own: Vec<&str> = own.iter().map(PointName::as_str).collect();
            errors.push(
                m.link.span(),
                format!("the motor `{name}` turns `{}` on {on}, and they share no joint for its axis (`{}` has {}); a motor sits at the joint of the two links it turns: `motor {name} = angle({}, {neighbour});`, or a motor on a link pinned to {on}", m.link, m.link, own.join(", "), m.link),
            );
        }
    }
}

/// Whether a motor's link and its carrier (or the ground) share a joint,
/// its axis; `None` when a link is unknown (reported elsewhere).
fn motor_joint(plan: &Plan, m: &crate::model::MotorSpec) -> Option<bool> {
    let points = |l: &Ident| plan.links.get(&LinkName::of(l)).map(|i| &i.points);
    let own = points(&m.link)?;
    Some(match &m.carrier {
        Some(c) => {
            let other = points(c)?;
            own.iter().any(|p| other.contains(p))
        }
        None => own.iter().any(|p| plan.is_ground(p)),
    })
}

/// Rule: a load value's name is not a parameter's, a constant's or a
/// statement's.
pub(super) fn load_names_unique(model: &Model, plan: &Plan, errors: &mut Diagnostics) {
    for (load, _) in &model.kinetics.loads {
        let name = load.to_string();
        if model.params.iter().any(|(p, _)| p == load)
            || model.consts.contains_key(&name)
            || plan.defined.contains_key(&Name::of(load))
        {
            let whence = defined_where(model, load)
                .map(|w| format!(" {w}"))
                .unwrap_or_default();
            errors.push(
                load.span(),
                format!("`{name}` is already defined{whence}; a load value needs a name of its own: rename it, e.g. `{}`, here and where it is used", another(&name)),
            );
        }
    }
}

/// `true` for the cylinder of an actuator (a massless two-force member).
fn is_cylinder(model: &Model, link: &LinkName) -> bool {
    model
        .stmts
        .iter()
        .any(|s| kinds::cylinder(s).is_some_and(|l| *link == *l))
}

/// Checks that `link` names a link that can carry loads; pushes an error otherwise.
fn loadable_link(
    model: &Model,
    plan: &Plan,
    link: &Ident,
    what: &str,
    errors: &mut Diagnostics,
) -> bool {
    let name = link.to_string();
    // A link of a rejected statement (or drawing) was reported there: a
    // load on it blames nothing more.
    if model
        .failed
        .iter()
        .any(|f| f.links.iter().any(|l| *l == name))
    {
        return false;
    }
    let key = LinkName::of(link);
    if !plan.links.contains_key(&key) {
        let named = named_links(model);
        let hint = did_you_mean(&name, named.iter().map(String::as_str));
        if name == GROUND || name == "frame" {
            errors.push(
                link.span(),
                format!("`{name}` is the frame, which is fixed: {what} on it moves nothing; put it on a moving link (the names after `as`){hint}"),
            );
            return false;
        }
        let (kind, hint) = if plan.defined.contains_key(&Name::of(link))
            || plan.guides.contains_key(&GuideName::of(link))
        {
            (format!("`{name}` is not a link"), hint)
        } else {
            (
                format!("cannot find link `{name}`"),
                link_hints(model, hint),
            )
        };
        errors.push(
            link.span(),
            format!("{kind}; {what} belongs to a link (the names after `as`){hint}"),
        );
        return false;
    }
    if is_cylinder(model, &key) {
        errors.push(
            link.span(),
            format!("`{name}` is an actuator's cylinder, a massless two-force member here; put the load on the link it drives, or give the actuator a third name to make its cylinder a barrel (pivoted at its base) and a rod (pinned at its joint) that carry loads: `as (ARM, BARREL, ROD)`"),
        );
        return false;
    }
    true
}

/// The error for a load's point `at` that is no point: what it is instead,
/// or that nothing has that name, with the nearest point's name (among
/// `first`, the points of the link named, when one is near; else among every
/// point). `what` says what the point is for ("a force acts at a point").
/// `None` when `at` is defined by a statement whose arguments were rejected
/// (that error is reported; this one would follow from it).
fn unknown_point(
    model: &Model,
    plan: &Plan,
    at: &PointName,
    first: &[PointName],
    what: &str,
) -> Option<String> {
    if model.failed.iter().any(|f| *at == f.name) {
        return None;
    }
    let mut hint = did_you_mean(at.as_str(), first.iter().map(PointName::as_str));
    if hint.is_empty() {
        hint = did_you_mean(at.as_str(), plan.owner.keys().map(PointName::as_str));
    }
    Some(match symbols(model).get(at.as_str()) {
        Some((cat, _)) => format!("`{at}` is {}, not a point; {what}{hint}", cat.article()),
        None => format!("cannot find point `{at}`{hint}"),
    })
}

/// Rule (`analysis dynamics`): some inertia moves with the inputs. A mass
/// counts when its centre is not a ground point, or its moment of inertia
/// is not a literal 0 and its link turns; without one the mass matrix is
/// zero and no input can be accelerated. The error is on the `dynamics`
/// word and names the moving links that could be given a mass.
pub(super) fn dynamics_has_inertia(model: &Model, plan: &Plan, errors: &mut Diagnostics) {
    if model.level != Level::Dynamics {
        return;
    }
    let moves = |m: &MassSpec| {
        let centre_moves = !plan.is_ground(&PointName::of(&m.at));
        let turns = plan.turning_link(&LinkName::of(&m.link)).is_some()
            && m.inertia.as_ref().is_some_and(|j| j.fold() != Some(0.0));
        centre_moves || turns
    };
    if model.kinetics.masses.iter().any(moves) {
        return;
    }
    let Some(span) = model.level_span else {
        return;
    };
    let links: Vec<String> = plan
        .links
        .iter()
        .filter(|(_, info)| info.named)
        .map(|(l, _)| format!("`{l}`"))
        .collect();
    let first = links.first().cloned().unwrap_or_else(|| "`LINK`".into());
    errors.push(
        span,
        format!(
            "`analysis dynamics` needs inertia that moves with the inputs, and no mass here moves: give the moving links a mass ({}), e.g. `mass {} {{ m = 1.0, at = POINT, j = 0.01 }};` with `POINT` a joint or `point` of that link away from the ground",
            links.join(", "),
            first.trim_matches('`')
        ),
    );
}
