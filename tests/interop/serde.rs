//! The serde derives written on a definition (feature `serde`).

use mechanism::mechanism;

mechanism! {
    /// Seed 002's crank-rocker (mm) with a coupler point, serializable.
    #[derive(serde::Serialize, serde::Deserialize)]
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8, circuit = left }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, circuit) as (link3, link4);
        let P = point(link3, from A, 120.0, 30 deg);
        mass link3 { m = 2.0, at = P };
    }
}

// Proves the JSON of a solution holds the user's names only, as nested
// objects per analysis (no hidden `grp_*`, `rates` or `input` fields), with
// the velocity's `condition` and the forces' reactions, and that its numbers
// are the solution's.
#[test]
fn a_solution_serializes_its_user_fields_only() {
    let fb = FourBar::<f64>::default();
    let i = |theta2| FourBarInput { theta2 };
    let s = fb.solve(&i(0.5), &i(250.0), &i(0.0)).unwrap();
    let json = serde_json::to_string(&s).unwrap();
    assert!(
        !json.contains("grp_") && !json.contains("rates") && !json.contains("input"),
        "{json}"
    );
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    let keys =
        |part: &str| -> Vec<String> { v[part].as_object().unwrap().keys().cloned().collect() };
    let mut want = vec!["A", "B", "O2", "O4", "P", "link2", "link3", "link4"];
    assert_eq!(keys("position"), want);
    want.push("condition");
    want.sort();
    assert_eq!(keys("velocity"), want);
    // docs/dsl.md: the crank's pin `r_X_L`, the RRR's `r_X_L1` at A,
    // `r_Y_L2` at O4 and `r_L1_L2` at B, the crank's torque.
    let forces = [
        "condition",
        "drive_theta2",
        "power_residual",
        "r_ground_link2",
        "r_ground_link4",
        "r_link2_link3",
        "r_link3_link4",
    ];
    assert_eq!(keys("forces"), forces, "{json}");
    assert_eq!(v["position"]["B"][0].as_f64().unwrap(), s.position.B.x);
    assert_eq!(v["velocity"]["link3"].as_f64().unwrap(), s.velocity.link3);
}

// Proves the parameters (with the run-time mode) and the inputs go to JSON
// and back unchanged, a missing or unknown key is an error, and a mode
// reads as `Plus` / `Minus`.
#[test]
fn parameters_and_inputs_round_trip() {
    let fb = FourBar::<f64> {
        crank: 90.0,
        circuit: mechanism::Mode::Minus,
        ..Default::default()
    };
    let json = serde_json::to_string(&fb).unwrap();
    assert_eq!(
        json,
        r#"{"ground":304.8,"crank":90.0,"coupler":254.0,"rocker":177.8,"circuit":"Minus"}"#
    );
    assert_eq!(serde_json::from_str::<FourBar>(&json).unwrap(), fb);
    let input: FourBarInput = serde_json::from_str(r#"{"theta2":0.25}"#).unwrap();
    assert_eq!(input, FourBarInput { theta2: 0.25 });
    let missing = serde_json::from_str::<FourBarInput>("{}").unwrap_err();
    assert!(
        missing.to_string().contains("missing field `theta2`"),
        "{missing}"
    );
    let unknown =
        serde_json::from_str::<FourBarInput>(r#"{"theta2":0.25,"theta3":1.0}"#).unwrap_err();
    assert!(
        unknown.to_string().contains("unknown field `theta3`"),
        "{unknown}"
    );
}

mechanism! {
    /// A press whose load is given per evaluation; `Deserialize` only, under
    /// a `cfg_attr` whose predicate holds.
    #[cfg_attr(all(), derive(serde::Deserialize))]
    pub Press {
        params { crank = 0.1, rod = 0.4 }
        loads { press = 0.0 }
        let O = ground(0.0, 0.0);
        let line = guide((0.0, 0.0), 0 deg);
        let A = crank(O, crank, theta) as link2;
        let B = rrp(A, rod, line, plus) as (link3, ram) slide x;
        mass ram { m = 5.0, at = B };
        force at B on ram along line = -press;
    }
}

// Proves the loads struct reads from JSON (with the parameters and inputs),
// through a derive under `cfg_attr`.
#[test]
fn loads_read_back() {
    let loads: PressLoads = serde_json::from_str(r#"{"press":1000.0}"#).unwrap();
    assert_eq!(loads, PressLoads { press: 1000.0 });
    let p: Press = serde_json::from_str(r#"{"crank":0.2,"rod":0.5}"#).unwrap();
    assert_eq!((p.crank, p.rod), (0.2, 0.5));
}
