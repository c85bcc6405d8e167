//! What `check()`'s report prints: the ranges swept, and per group where it
//! first fails (with the fault) and its first singular position, so that
//! `println!("{}", m.check())` answers the user's question without a loop.

use mechanism_core::sweep::{Event, Range, Report};
use mechanism_core::Fault;

fn full_turn() -> Range {
    Range {
        lo: 0.0,
        hi: 6.5,
        periodic: false,
    }
}

#[test]
fn a_clean_report_says_so_in_one_line() {
    let r: Report<2, 1> = Report::new(["theta"], [full_turn()], ["B", "C"]);
    assert_eq!(
        r.to_string(),
        "checked over theta in [0, 6.5]: every group assembles, no singular position"
    );
}

#[test]
fn a_failing_group_shows_its_first_interval_and_fault() {
    let mut r: Report<2, 1> = Report::new(["theta"], [full_turn()], ["B", "C"]);
    let fault = Fault::CannotAssemble {
        miss: 0.5,
        reach: 2.0,
    };
    r.record(&Event::Fails {
        group: 1,
        lo: [3.0],
        hi: [3.5],
        fault,
        count: 1,
    });
    r.record(&Event::Fails {
        group: 1,
        lo: [1.0],
        hi: [1.25],
        fault,
        count: 1,
    });
    r.record(&Event::Singular {
        group: 0,
        at: [2.0],
        det: 0.0,
        count: 1,
    });
    let text = r.to_string();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "checked over theta in [0, 6.5]");
    assert_eq!(
        lines[1],
        "  B: assembles; 1 singular, the first at theta = 2"
    );
    // The lowest interval of the two found, and the fault's own words.
    let want = format!("  C: fails (2 found), first over theta in [1, 1.25]: {fault}");
    assert_eq!(lines[2], want);
    assert_eq!(lines.len(), 3);
}
