//! Pieces of the service core on their own: the motion options read from
//! their positions, interpolation along support points, the wall clock of
//! a real arm, the import profiles the checker compares, the service
//! table's lookups and group titles. (Whole programs through a `Session`:
//! tests/services/.)

use crate::interp::Clock;
use crate::interp::value::Value;
use crate::services::table::{self, Group};

#[test]
fn interpolate_goes_evenly_through_the_support_points() {
    let from = [0.0; 5];
    let p1 = [1.0, 2.0, 0.0, 0.0, -1.0];
    let p2 = [3.0, 2.0, 4.0, 0.0, -1.0];
    let at = |f| crate::services::interpolate(&from, &[p1, p2], f);
    assert_eq!(at(0.0), from);
    assert_eq!(at(0.25), [0.5, 1.0, 0.0, 0.0, -0.5]);
    assert_eq!(at(0.5), p1);
    assert_eq!(at(0.75), [2.0, 2.0, 2.0, 0.0, -1.0]);
    assert_eq!(at(1.0), p2);
    assert_eq!(at(7.0), p2, "clamped");
    assert_eq!(crate::services::interpolate(&p1, &[], 0.5), p1);
}

#[test]
fn the_motion_options_are_read_from_their_own_positions() {
    let args = [
        Value::Int(0),
        Value::Real(1.5),
        Value::Int(0),
        Value::Int(1),
    ];
    let o = crate::services::opts(&args, 1);
    assert_eq!(
        (o.time, o.time_arg, o.control, o.realtime),
        (Some(1.5), 1.5, false, true)
    );
    let args = [Value::Real(0.0), Value::Int(1), Value::Int(0)];
    let o = crate::services::opts(&args, 0);
    assert_eq!((o.time, o.control, o.realtime), (None, true, false));
}

#[test]
fn the_wall_clock_of_a_real_arm_counts_real_seconds() {
    let mut c = crate::services::WallClock::default();
    let t0 = c.now();
    assert!((0.0..0.5).contains(&t0), "{t0}");
    c.sleep(0.03);
    let t1 = c.now();
    assert!(t1 - t0 >= 0.03, "{t0} -> {t1}");
    c.sleep(-5.0);
    assert!(c.now() - t1 < 1.0, "a negative sleep does not wait");
}

#[test]
fn every_service_gives_the_checker_its_import_profile() {
    for svc in crate::services::SERVICES {
        let p = crate::services::import_profile(svc.import)
            .unwrap_or_else(|| panic!("{} has no import profile", svc.name));
        assert_eq!(p.text, svc.import_profile().text, "{}", svc.name);
        assert!(!p.text.is_empty(), "{}", svc.name);
    }
    assert!(crate::services::import_profile("NoSuchService").is_none());
}

#[test]
fn the_table_finds_services_by_import_name_and_by_ada_name() {
    let s = table::by_import("MoveAxesRelative").expect("by import");
    assert_eq!(s.name, "MoveAxesRelative");
    assert!(table::by_import("NoSuchImport").is_none());
    // By Ada name: any case, services only (not the value functions).
    assert_eq!(table::by_name("movetool").map(|s| s.name), Some("MoveTool"));
    // ValueAxes is a procedure and a function: the procedure is the service.
    assert_eq!(
        table::by_name("ValueAxes").map(|s| s.import),
        Some("ValueAxes")
    );
    assert!(table::by_name("NoSuchService").is_none());
    assert_eq!(table::code_of("MoveAxesRelative"), 190);
    assert_eq!(table::code_of("NoSuchService"), 0);
}

#[test]
fn every_group_has_its_own_title() {
    let mut titles: Vec<&str> = Group::ALL.iter().map(|g| g.title()).collect();
    assert_eq!(Group::Motion.title(), "motion");
    assert!(
        titles
            .iter()
            .all(|t| !t.is_empty() && t.chars().all(|c| c.is_ascii_lowercase() || c == ' '))
    );
    titles.sort();
    titles.dedup();
    assert_eq!(titles.len(), Group::ALL.len());
}
