//! Synchronous point-to-point joint motion profiles.

use crate::kinematics::{AdaException, KinError, MotionProfile, RobotDescription, joints_from_deg};

fn rv_m1() -> RobotDescription {
    RobotDescription::builtin("rv-m1").unwrap()
}

#[test]
fn leading_joint_at_velocity_percent() {
    let d = rv_m1();
    let from = joints_from_deg([0.0, 0.0, 0.0, 0.0, 0.0]);
    let to = joints_from_deg([120.0, 30.0, 50.0, -40.0, 90.0]);
    let p = MotionProfile::plan(&from, &to, 50.0, &d, None).unwrap();
    // J1: 120 deg at 60 deg/s is the longest: 2 s + ramp.
    assert_eq!(p.leading_joint(), Some(0));
    let ramp = 60.0 / 480.0;
    assert!(
        (p.duration() - (2.0 + ramp)).abs() < 1e-12,
        "{}",
        p.duration()
    );
    let v = p.velocity_at(p.duration() / 2.0);
    assert!((v[0].to_degrees() - 60.0).abs() < 1e-9);
    // Every joint within its speed and at the same fraction.
    for (i, spec) in d.joints().iter().enumerate() {
        assert!(v[i].abs() <= 0.5 * spec.max_speed + 1e-12);
    }
    assert_eq!(p.at(0.0), from);
    assert_eq!(p.at(p.duration()), to);
    assert_eq!(p.at(p.duration() + 5.0), to);
    assert_eq!(p.at(-1.0), from);
    // All joints start and stop together: the same fraction of travel.
    let mid = p.at(0.7);
    let f0 = (mid[0] - from[0]) / (to[0] - from[0]);
    for i in 1..5 {
        let fi = (mid[i] - from[i]) / (to[i] - from[i]);
        assert!((fi - f0).abs() < 1e-12);
    }
}

#[test]
fn acceleration_and_monotone() {
    let d = rv_m1();
    let from = joints_from_deg([-100.0, 0.0, 0.0, 0.0, 0.0]);
    let to = joints_from_deg([100.0, 90.0, 100.0, 80.0, 170.0]);
    let p = MotionProfile::plan(&from, &to, 100.0, &d, None).unwrap();
    let n = 10_000;
    let dt = p.duration() / n as f64;
    let mut prev_v = p.velocity_at(0.0);
    let mut prev_q = p.at(0.0);
    for k in 1..=n {
        let t = k as f64 * dt;
        let q = p.at(t);
        let v = p.velocity_at(t);
        for (i, spec) in d.joints().iter().enumerate() {
            assert!(v[i].abs() <= spec.max_speed + 1e-9);
            assert!(((v[i] - prev_v[i]) / dt).abs() <= spec.max_accel * (1.0 + 1e-9) + 1e-6);
            assert!((q[i] - prev_q[i]) * (to[i] - from[i]) >= -1e-15);
        }
        prev_v = v;
        prev_q = q;
    }
}

#[test]
fn short_move_is_a_triangle() {
    let d = rv_m1();
    let from = [0.0; 5];
    let to = joints_from_deg([1.0, 0.0, 0.0, 0.0, 0.0]);
    let p = MotionProfile::plan(&from, &to, 100.0, &d, None).unwrap();
    // 1 deg at 480 deg/s^2: 2 * sqrt(1/480) s.
    assert!((p.duration() - 2.0 * (1.0f64 / 480.0).sqrt()).abs() < 1e-12);
    let peak = p.velocity_at(p.duration() / 2.0)[0].to_degrees();
    assert!(peak < 120.0);
    assert!((p.at(p.duration() / 2.0)[0] - to[0] / 2.0).abs() < 1e-12);
}

#[test]
fn requested_time() {
    let d = rv_m1();
    let from = [0.0; 5];
    let to = joints_from_deg([90.0, 20.0, 0.0, 0.0, 0.0]);
    let fastest = MotionProfile::plan(&from, &to, 100.0, &d, None).unwrap();
    let p = MotionProfile::plan(&from, &to, 100.0, &d, Some(3.0)).unwrap();
    assert_eq!(p.duration(), 3.0);
    assert_eq!(p.min_duration(), fastest.duration());
    assert_eq!(p.at(3.0), to);
    assert!((p.at(1.5)[0] - to[0] / 2.0).abs() < 1e-12);
    let e = MotionProfile::plan(&from, &to, 100.0, &d, Some(0.5)).unwrap_err();
    assert!(matches!(e, KinError::TimeInvalid { .. }));
    assert_eq!(e.exception(), AdaException::TimeInvalid);
    assert!(
        e.to_string().contains("shorter than the fastest possible"),
        "{e}"
    );
    // Exactly the fastest is fine.
    let p = MotionProfile::plan(&from, &to, 100.0, &d, Some(fastest.duration())).unwrap();
    assert!((p.duration() - fastest.duration()).abs() < 1e-12);
    let e = MotionProfile::plan(&from, &to, 100.0, &d, Some(f64::NAN)).unwrap_err();
    assert_eq!(e.exception(), AdaException::TimeInvalid);
    // No travel: stays put for the requested time.
    let p = MotionProfile::plan(&from, &from, 100.0, &d, Some(2.0)).unwrap();
    assert_eq!(p.duration(), 2.0);
    assert_eq!(p.at(1.0), from);
    let p = MotionProfile::plan(&from, &from, 100.0, &d, None).unwrap();
    assert_eq!(p.duration(), 0.0);
    assert_eq!(p.leading_joint(), None);
}

#[test]
fn invalid_velocity() {
    let d = rv_m1();
    for v in [0.0, -5.0, 100.5, f64::NAN] {
        let e = MotionProfile::plan(&[0.0; 5], &[1.0; 5], v, &d, None).unwrap_err();
        assert_eq!(e.exception(), AdaException::ConstraintError);
    }
    let e = MotionProfile::plan(&[f64::INFINITY; 5], &[1.0; 5], 50.0, &d, None).unwrap_err();
    assert_eq!(e.exception(), AdaException::ConstraintError);
}

#[test]
fn rm_501_is_slower() {
    let rv = rv_m1();
    let rm = RobotDescription::builtin("rm-501").unwrap();
    let to = joints_from_deg([90.0, 0.0, 0.0, 0.0, 0.0]);
    let a = MotionProfile::plan(&[0.0; 5], &to, 100.0, &rv, None).unwrap();
    let b = MotionProfile::plan(&[0.0; 5], &to, 100.0, &rm, None).unwrap();
    // 90 deg at 120 deg/s + 0.25 s ramp; at 48 deg/s + 0.25 s.
    assert!((a.duration() - 1.0).abs() < 1e-12);
    assert!((b.duration() - (90.0 / 48.0 + 0.25)).abs() < 1e-12);
}

#[test]
fn the_trapezoid_in_closed_form() {
    // RV-M1 J1 from -30 to 90 deg at 100 %: 120 deg at 120 deg/s and
    // 480 deg/s^2, so the normalised profile has cruise 1/s, acceleration
    // 4/s^2, ramps of 0.25 s and lasts 1.25 s. J2 travels 36 deg the same way.
    let d = rv_m1();
    let from = joints_from_deg([-30.0, 10.0, 0.0, 0.0, 0.0]);
    let to = joints_from_deg([90.0, 46.0, 0.0, 0.0, 0.0]);
    let p = MotionProfile::plan(&from, &to, 100.0, &d, None).unwrap();
    assert!((p.duration() - 1.25).abs() < 1e-12, "{}", p.duration());
    assert_eq!(p.min_duration(), p.duration());
    // (t, fraction s(t), normalised speed s'(t)) in each phase.
    for (t, s, ds) in [(0.1, 0.02, 0.4), (0.5, 0.375, 1.0), (1.1, 0.955, 0.6)] {
        assert!(
            (p.fraction_at(t) - s).abs() < 1e-12,
            "s({t}) = {}",
            p.fraction_at(t)
        );
        let q = p.at(t);
        let v = p.velocity_at(t);
        for (j, travel) in [(0, 120.0), (1, 36.0)] {
            let start = from[j].to_degrees();
            assert!(
                (q[j].to_degrees() - (start + travel * s)).abs() < 1e-9,
                "q{j}({t})"
            );
            assert!((v[j].to_degrees() - travel * ds).abs() < 1e-9, "v{j}({t})");
        }
        assert_eq!(q[2], 0.0);
    }
    // Standing still before the start, after the end and at no time.
    for t in [-1.0, 0.0, 1.25, 3.0, f64::NAN] {
        assert_eq!(p.velocity_at(t), [0.0; 5], "v({t})");
    }
    assert_eq!(p.fraction_at(f64::NAN), 0.0);
    assert_eq!(p.at(f64::NAN), from);
    let still = MotionProfile::plan(&from, &from, 100.0, &d, Some(1.0)).unwrap();
    assert_eq!(still.velocity_at(0.5), [0.0; 5]);
    assert_eq!(still.fraction_at(0.5), 0.0);
    // Given 2 s, the fastest time is still 1.25 s.
    let slow = MotionProfile::plan(&from, &to, 100.0, &d, Some(2.0)).unwrap();
    assert_eq!(slow.min_duration(), p.duration());
    assert_eq!(slow.duration(), 2.0);
}

#[test]
fn of_joints_that_need_equally_long_the_first_leads() {
    // J1 120 deg at 120 deg/s and J2 72 deg at 72 deg/s: 1 s each.
    let d = rv_m1();
    let to = joints_from_deg([120.0, 72.0, 0.0, 0.0, 0.0]);
    let p = MotionProfile::plan(&[0.0; 5], &to, 100.0, &d, None).unwrap();
    assert_eq!(p.leading_joint(), Some(0));
    let back = joints_from_deg([0.0, 72.0, 0.0, 0.0, 0.0]);
    let p = MotionProfile::plan(&[0.0; 5], &back, 100.0, &d, None).unwrap();
    assert_eq!(p.leading_joint(), Some(1));
}
