//! The `serde` feature: the core's errors, positions and check reports
//! serialize to the JSON a reader expects from their field names (serde's
//! externally tagged enums), and the types that own their data read back to
//! equal values. `cargo test -p mechanism-core --features serde --test serde`.
#![cfg(feature = "serde")]

use mechanism_core::dyad::rrr;
use mechanism_core::sweep::{Range, Report};
use mechanism_core::{Error, Fault, Mode, Point2, Primitive};

/// A real failure: joints 10 apart, links of 1 and 1 reach 2, so the RRR
/// misses by 8 (all exact in binary floating point). Its JSON names the
/// group, the primitive and the fault with its numbers.
#[test]
fn an_rrr_error_serializes_with_its_numbers() {
    let e = rrr::position(
        &Point2::new(0.0, 0.0),
        1.0,
        &Point2::new(10.0, 0.0),
        1.0,
        Mode::Plus,
    )
    .map(|_| ())
    .unwrap_err()
    .in_group("B");
    let json = serde_json::to_string(&e).unwrap();
    assert_eq!(
        json,
        r#"{"group":"B","primitive":"Rrr","fault":{"CannotAssemble":{"miss":8.0,"reach":2.0}}}"#
    );
    // An f32 error serializes its numbers in f32 (0.1f32 prints as 0.1).
    let e32: Error<f32> = Error::new(
        Primitive::Crank,
        Fault::NonPositive {
            what: "length",
            value: -0.1,
        },
    );
    assert_eq!(
        serde_json::to_string(&e32).unwrap(),
        r#"{"group":"","primitive":"Crank","fault":{"NonPositive":{"what":"length","value":-0.1}}}"#
    );
}

/// A position of a primitive reads back equal to what was written; `Mode`
/// and `Primitive` are unit variants, written as their names.
#[test]
fn positions_modes_and_primitives_round_trip() {
    let p = rrr::position(
        &Point2::new(0.0, 0.0),
        3.0,
        &Point2::new(5.0, 0.0),
        4.0,
        Mode::Plus,
    )
    .unwrap();
    let json = serde_json::to_string(&p).unwrap();
    let back: rrr::RrrPosition<f64> = serde_json::from_str(&json).unwrap();
    assert_eq!(back, p);
    assert_eq!(serde_json::to_string(&Mode::Minus).unwrap(), r#""Minus""#);
    let prim: Primitive = serde_json::from_str(r#""LinearSystem""#).unwrap();
    assert_eq!(prim, Primitive::LinearSystem);
}

/// A check report (const-generic arrays of inputs, ranges and groups) writes
/// its arrays as JSON arrays and leaves its private bookkeeping out.
#[test]
fn a_report_serializes_its_arrays_as_sequences() {
    let full = Range {
        lo: 0.0,
        hi: 1.0,
        periodic: false,
    };
    let r: Report<2, 1> = Report::new(["theta"], [full], ["B", "C"]);
    let json = serde_json::to_string(&r).unwrap();
    let group = |name: &str| {
        format!(
            r#"{{"group":"{name}","failures":0,"failure":null,"fault":null,"singular":0,"first_singular":null}}"#
        )
    };
    let expected = format!(
        r#"{{"inputs":["theta"],"ranges":[{{"lo":0.0,"hi":1.0,"periodic":false}}],"groups":[{},{}]}}"#,
        group("B"),
        group("C")
    );
    assert_eq!(json, expected);
}
