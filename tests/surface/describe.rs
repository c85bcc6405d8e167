//! A generated mechanism describes itself: `Describe::STRUCTURE` lists its
//! points (with how each is held), its moving links with the points on each,
//! its guides and inputs, as written in the definition; `Fields` reads every
//! output of the position, velocity and acceleration structs by name, with
//! the quantity it measures, and agrees with the struct's own fields.

use mechanism::mechanism;
use mechanism::structure::{Describe, Fields, LinkKind, PointKind, Quantity, Value};

use crate::render;

mechanism! {
    /// Crank-rocker four-bar (mm) with a coupler point.
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
        let P = point(link3, from A, 120.0, 30 deg);
    }
}

mechanism! {
    /// Quick-return shaper: crank, RPR, RRP on a fixed ram guide.
    pub Shaper {
        let A = ground(0.0, 0.0);
        let C = ground(0.0, -0.275);
        let ram = guide((0.0, 0.3), 180 deg);
        let B = crank(A, 0.125, theta) as link1;
        let s3 = rpr(B, C, plus) as (block2, link3);
        let D = point(link3, from C, 0.6, 0 deg);
        let E = rrp(D, 0.15, ram, plus) as (link4, slider5) slide x;
    }
}

#[test]
fn four_bar_structure_is_the_definition() {
    let s = FourBar::<f64>::STRUCTURE;
    assert_eq!(s.name, "FourBar");
    let points: Vec<(&str, PointKind)> = s.points.iter().map(|p| (p.name, p.kind)).collect();
    assert_eq!(
        points,
        [
            ("O2", PointKind::Ground),
            ("O4", PointKind::Ground),
            ("A", PointKind::Joint),
            ("B", PointKind::Joint),
            ("P", PointKind::OnLink),
        ]
    );
    let links: Vec<(&str, LinkKind, &[&str])> =
        s.links.iter().map(|l| (l.name, l.kind, l.points)).collect();
    assert_eq!(
        links,
        [
            ("link2", LinkKind::Crank, &["O2", "A"][..]),
            ("link3", LinkKind::Bar, &["A", "B", "P"][..]),
            ("link4", LinkKind::Bar, &["O4", "B"][..]),
        ]
    );
    assert!(s.links.iter().all(|l| l.named && l.guide.is_none()));
    assert!(s.guides.is_empty() && s.masses.is_empty());
    assert_eq!(s.inputs.len(), 1);
    assert_eq!(
        (s.inputs[0].name, s.inputs[0].quantity, s.inputs[0].driver),
        ("theta2", Quantity::Angle, "A")
    );
}

#[test]
fn shaper_structure_has_its_blocks_on_their_guides() {
    let s = Shaper::<f64>::STRUCTURE;
    let block = |n: &str| s.link(n).map(|l| (l.kind, l.guide));
    assert_eq!(block("slider5"), Some((LinkKind::Block, Some("ram"))));
    assert_eq!(block("block2"), Some((LinkKind::Block, None)));
    assert_eq!(block("link3").map(|b| b.0), Some(LinkKind::Bar));
    let ram = s.guide("ram").expect("the ram guide");
    assert_eq!((ram.carrier, ram.through), (None, None));
    assert_eq!(ram.angle, Some(std::f64::consts::PI));
    assert!(
        s.point("s3").is_none(),
        "an RPR defines a slide, not a point"
    );
    assert_eq!(s.point("E").map(|p| p.kind), Some(PointKind::Joint));
}

#[test]
fn fields_read_every_output_by_name_with_its_quantity() {
    let fb = FourBar::<f64>::default();
    let input = FourBarInput { theta2: 0.7 };
    let p = fb.position(&input).unwrap();
    let v = fb.velocity(&p, &FourBarInput { theta2: 3.0 }).unwrap();
    let a = fb
        .acceleration(&p, &v, &FourBarInput { theta2: -2.0 })
        .unwrap();
    let names: Vec<&str> = FourBarPosition::<f64>::FIELDS
        .iter()
        .map(|f| f.name)
        .collect();
    assert_eq!(
        names,
        ["O2", "O4", "A", "B", "P", "link2", "link3", "link4"]
    );
    assert_eq!(p.get("B"), Some(Value::Point(p.B)));
    assert_eq!(p.get("link3"), Some(Value::Scalar(p.link3)));
    assert_eq!(v.get("P"), Some(Value::Vector(v.P)));
    assert_eq!(v.get("condition"), Some(Value::Scalar(v.condition)));
    assert_eq!(a.get("link4"), Some(Value::Scalar(a.link4)));
    assert_eq!(p.get("nothing"), None);
    let quantity = |fields: &[mechanism::structure::Field], n: &str| {
        fields
            .iter()
            .find(|f| f.name == n)
            .map(|f| (f.quantity, f.planar))
    };
    assert_eq!(
        quantity(FourBarVelocity::<f64>::FIELDS, "link3"),
        Some((Quantity::AngularVelocity, false))
    );
    assert_eq!(
        quantity(FourBarAcceleration::<f64>::FIELDS, "B"),
        Some((Quantity::Acceleration, true))
    );
    assert_eq!(Quantity::AngularAcceleration.unit(), "rad/s^2");
}

mechanism! {
    /// Theo Jansen's leg (his published link lengths, in cm; the crank at the
    /// origin, the frame pivot Z at (-a, -l)). The triangles B-Z-D and E-C-F
    /// are written as groups of two links each: the same motion.
    pub JansenLeg {
        units { length = "cm" }
        let O = ground(0.0, 0.0);
        let Z = ground(-38.0, -7.8);
        let A = crank(O, 15.0, theta) as crank;
        let B = rrr(A, 50.0, Z, 41.5, right) as (j, b);
        let C = rrr(A, 61.9, Z, 39.3, left) as (k, c);
        let D = rrr(B, 55.8, Z, 40.1, right) as (e, d);
        let E = rrr(D, 39.4, C, 36.7, right) as (f, g);
        let F = rrr(E, 65.7, C, 49.0, right) as (h, i);
    }
}

/// A mechanism defined only here gets its drawing, animation, foot path, a
/// chart of its foot and table from the generic calls: the drawing has one
/// frame per pose, every link of the structure is drawn, the path of F spans
/// the foot's stride, the chart has F's two coordinates in cm, both pictures
/// render to pixels with their labels inside, and the CSV has a header with
/// units and one row per pose.
#[test]
fn jansen_leg_pictures_and_table_from_its_description_alone() {
    let leg = JansenLeg::<f64>::default();
    let poses: Vec<(f64, Option<JansenLegPosition>)> = (0..=72)
        .map(|k| {
            let t = k as f64 * std::f64::consts::TAU / 72.0;
            (t, leg.position(&JansenLegInput { theta: t }).ok())
        })
        .collect();
    assert!(
        poses.iter().all(|(_, p)| p.is_some()),
        "the leg turns fully"
    );
    let sketch = mechanism_plot::any::sketch::<JansenLeg, _>("Jansen leg", &poses, &["F"]).unwrap();
    assert_eq!(sketch.frame_count(), 73);
    let drawing = sketch.drawing(0).unwrap();
    for link in ["crank", "j", "b", "k", "c", "d", "e", "f", "g", "h", "i"] {
        assert!(
            drawing.contains(&format!("\"{link}\"")),
            "link {link} drawn"
        );
    }
    assert!(sketch.animation(4.0).unwrap().contains("<animate"));
    // The definition is the leg: the foot at two crank angles against the
    // dyads' circle intersections done independently in double precision
    // (Python, the same lengths and sides). Five dyads in a chain, well
    // conditioned here: 1e-12 cm is about 70 ulp of the foot's 90 cm.
    for (theta, fx, fy) in [
        (0.0, -43.160110524104724, -91.75693292612323),
        (2.0, -3.65655677514245, -88.88803151171112),
    ] {
        let f = leg.position(&JansenLegInput { theta }).unwrap().F;
        assert!(
            (f.x - fx).abs() < 1e-12 && (f.y - fy).abs() < 1e-12,
            "{theta}: {f:?}"
        );
    }
    // The drawn path of F is the foot's stride: tens of cm horizontally.
    let (xmin, xmax) = poses
        .iter()
        .map(|(_, p)| p.as_ref().unwrap().F.x)
        .fold((f64::MAX, f64::MIN), |(a, b), x| (a.min(x), b.max(x)));
    assert!(xmax - xmin > 30.0, "stride {}", xmax - xmin);
    // A chart of one output, the foot F, from its name alone: one panel of
    // positions in cm (the definition's `units`) with F.x and F.y over the turn.
    let chart = mechanism_plot::any::chart("Jansen leg: foot", ("θ", "rad"), &poses, &["F"])
        .unwrap()
        .to_svg()
        .unwrap();
    assert!(chart.contains("position (cm)"), "the unit of F");
    for series in ["\"F.x\"", "\"F.y\""] {
        assert_eq!(chart.matches(series).count(), 1, "{series} drawn once");
    }
    // Looked at: rendered to pixels, not blank, labels inside the canvas.
    let drawing_png = render::look(&drawing, "Jansen drawing", 0.01);
    let chart_png = render::look(&chart, "Jansen chart", 0.01);
    render::save_for_docs(&drawing_png, "jansen-drawing.png");
    render::save_for_docs(&chart_png, "jansen-foot.png");
    let table = mechanism_plot::any::csv("theta", "rad", &poses);
    let mut lines = table.lines();
    let header = lines.next().unwrap();
    assert!(
        header.starts_with("theta [rad],O.x [cm],O.y [cm],"),
        "{header}"
    );
    assert!(
        header.contains(",F.x [cm],F.y [cm],") && header.ends_with(",i [rad]"),
        "{header}"
    );
    assert_eq!(lines.count(), 73);
}

/// `Debug` of a result shows the user's fields (and the velocity's
/// `condition`), not the solver state kept for later analyses.
#[test]
fn debug_shows_the_users_fields_only() {
    let fb = FourBar::<f64>::default();
    let p = fb.position(&FourBarInput { theta2: 0.7 }).unwrap();
    let v = fb.velocity(&p, &FourBarInput { theta2: 1.0 }).unwrap();
    let shown = format!("{p:?} {v:?}");
    assert!(shown.starts_with("FourBarPosition { O2: "), "{shown}");
    assert!(
        shown.contains("link4: ") && shown.contains("condition: "),
        "{shown}"
    );
    assert!(
        !shown.contains("grp_") && !shown.contains("rates"),
        "{shown}"
    );
}

mechanism! {
    /// Slider-crank with a mass on the coupler and a load on the slider.
    pub Press {
        let O = ground(0.0, 0.0);
        let line = guide(O, 0 deg);
        let A = crank(O, 0.05, theta) as crank;
        let B = rrp(A, 0.2, line, plus) as (rod, ram) slide s;
        let G = point(rod, from A, 0.1, 0 deg);
        mass rod { m = 1.5, at = G, j = 0.005 }
        gravity (0.0, -9.81);
        force at B on ram = (-200.0, 0.0);
    }
}

/// The forces struct reads by name too: a revolute reaction as a force
/// vector, a prismatic pair's as its normal force vector and its couple, the
/// crank's driving torque as a moment, equal to the struct's own fields.
#[test]
fn forces_read_by_name_with_quantities() {
    let press = Press::<f64>::default();
    let s = press
        .solve(
            &PressInput { theta: 0.4 },
            &PressInput { theta: 10.0 },
            &PressInput { theta: 0.0 },
        )
        .unwrap();
    let f = &s.forces;
    let fields = PressForces::<f64>::FIELDS;
    let find = |n: &str| {
        fields
            .iter()
            .find(|x| x.name == n)
            .map(|x| (x.quantity, x.planar))
    };
    assert_eq!(find("drive_theta"), Some((Quantity::Moment, false)));
    assert_eq!(f.get("drive_theta"), Some(Value::Scalar(f.drive_theta)));
    let prismatic = fields
        .iter()
        .find(|x| x.name.ends_with(".moment"))
        .expect("the ram's prismatic pair");
    assert_eq!(prismatic.quantity, Quantity::Moment);
    let revolute = fields
        .iter()
        .find(|x| x.planar && !x.name.contains('.'))
        .expect("a revolute reaction");
    assert_eq!(revolute.quantity, Quantity::Force);
    assert!(matches!(f.get(revolute.name), Some(Value::Vector(_))));
    assert_eq!(find("power_residual"), Some((Quantity::Ratio, false)));
    assert_eq!(
        f.get("power_residual"),
        Some(Value::Scalar(f.power_residual))
    );
}

/// Where a real mechanism cannot be assembled, the generic pictures show a
/// gap, not a line across it: the four-bar with a 200 mm crank cannot close
/// while A is more than coupler + rocker = 431.8 mm from O4 (crank angles
/// round 180 deg), so over a turn its chart of link3 has two runs with no
/// vertex for the failed rows, the drawn path of P two pieces, the drawing
/// one frame per pose that closes, and the CSV an empty row per failure.
#[test]
fn poses_that_fail_are_gaps_in_every_picture() {
    let fb = FourBar::<f64> {
        crank: 200.0,
        ..Default::default()
    };
    let rows: Vec<(f64, Option<FourBarPosition<f64>>)> = (0..=72)
        .map(|k| {
            let deg = 5.0 * k as f64;
            let input = FourBarInput {
                theta2: deg.to_radians(),
            };
            (deg, fb.position(&input).ok())
        })
        .collect();
    // Independently: A = 200 (cos t, sin t), O4 = (304.8, 0).
    let closes = |deg: f64| {
        let t = deg.to_radians();
        (200.0 * t.cos() - 304.8).hypot(200.0 * t.sin()) <= 254.0 + 177.8
    };
    for (deg, p) in &rows {
        assert_eq!(p.is_some(), closes(*deg), "{deg} deg");
    }
    let solved = rows.iter().filter(|(_, p)| p.is_some()).count();
    assert!(solved > 20 && solved < 60, "{solved} of 73 close");
    let chart = mechanism_plot::any::chart("gaps", ("θ2", "deg"), &rows, &["link3"])
        .unwrap()
        .to_svg()
        .unwrap();
    let doc = roxmltree::Document::parse(&chart).unwrap();
    let d = doc
        .descendants()
        .find(|n| n.attribute("data-series") == Some("link3"))
        .and_then(|n| n.attribute("d"))
        .unwrap();
    assert_eq!(d.matches('M').count(), 2, "two runs: {d}");
    assert_eq!(
        d.matches('L').count(),
        solved - 2,
        "one vertex per solved row"
    );
    let sketch = mechanism_plot::any::sketch::<FourBar<f64>, _>("gaps", &rows, &["P"]).unwrap();
    assert_eq!(sketch.frame_count(), solved);
    let drawing = sketch.drawing(0).unwrap();
    assert_eq!(drawing.matches(r#"class="path" data-name="P""#).count(), 2);
    let csv = mechanism_plot::any::csv("theta2", "deg", &rows);
    let empty = csv.lines().filter(|l| l.ends_with(",,,,")).count();
    assert_eq!(empty, 73 - solved);
}
