//! Tests of the kinematics. This file: the branch and representation
//! helpers (`wrap` at its boundaries, every case of `fit_limits`,
//! `nearest_representation`, the branch metric), the refusal message's
//! precision and the ValidFrame plane helpers. The submodules test through
//! the public API: robot descriptions, FK/IK spec vectors and branches,
//! straight lines, the motion rules (proptest), speed profiles, seeded
//! round trips and ValidFrame. They are unit tests of the library, not
//! integration tests, so that `cargo test --lib` covers `src/kinematics/`
//! and a mutation run (`scripts/mutants.sh`) builds one test binary. Like
//! the kinematics, they do no I/O (tests/layering.rs).

mod description;
mod fk_ik;
mod line;
mod motion_rules;
mod profile;
mod roundtrip;
mod valid_frame;

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use nalgebra::Vector3;

use super::error::{AdaException, KinError, LimitViolation, decimals_for};
use super::ik::wrap;
use super::ik::{Arm, Elbow};
use super::valid::{into_plane, out_of_plane};
use super::{Joints, Kinematics, Pose, RobotDescription, joints_from_deg, tolerance};

// Fixtures shared by the test modules below.

fn rv_m1() -> Kinematics {
    Kinematics::new(RobotDescription::builtin("rv-m1").unwrap())
}

fn rm_501() -> Kinematics {
    Kinematics::new(RobotDescription::builtin("rm-501").unwrap())
}

/// The RV-M1's description with every joint over -180 .. 180 deg, so that
/// all four branches exist (edit it further for other test robots).
fn wide_text() -> String {
    RobotDescription::builtin_text("rv-m1")
        .unwrap()
        .replace("min_deg = -150.0", "min_deg = -180.0")
        .replace("max_deg = 150.0", "max_deg = 180.0")
        .replace("min_deg = -30.0", "min_deg = -180.0")
        .replace("max_deg = 100.0", "max_deg = 180.0")
        .replace("min_deg = 0.0", "min_deg = -180.0")
        .replace("max_deg = 110.0", "max_deg = 180.0")
        .replace("min_deg = -90.0", "min_deg = -180.0")
        .replace("max_deg = 90.0", "max_deg = 180.0")
}

fn wide() -> Kinematics {
    Kinematics::new(RobotDescription::from_toml_str(&wide_text()).unwrap())
}

/// The TCP at (x, y, z), pointing straight down.
fn down_at(x: f64, y: f64, z: f64) -> Pose {
    let mut p = Pose::rot_y(PI);
    p.translation = Vector3::new(x, y, z);
    p
}

/// The angle (rad) between two rotations from the Frobenius norm of their
/// difference (`2 sqrt 2 sin(angle / 2)`), exact for small angles too
/// (unlike the trace's acos).
fn angle(a: &nalgebra::Matrix3<f64>, b: &nalgebra::Matrix3<f64>) -> f64 {
    2.0 * ((a - b).norm() / (2.0 * std::f64::consts::SQRT_2))
        .min(1.0)
        .asin()
}

/// SplitMix64: a seeded generator, so failures reproduce.
struct Rng(u64);

impl Rng {
    /// Uniform in [0, 1).
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// RV-M1 with J1 over -200 .. 200 deg and J5 over -500 .. 500 deg.
fn wide_roll() -> Kinematics {
    let text = RobotDescription::builtin_text("rv-m1")
        .unwrap()
        .replace("min_deg = -150.0", "min_deg = -200.0")
        .replace("max_deg = 150.0", "max_deg = 200.0")
        .replace("min_deg = -180.0", "min_deg = -500.0")
        .replace("max_deg = 180.0", "max_deg = 500.0");
    Kinematics::new(RobotDescription::from_toml_str(&text).unwrap())
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-12
}

#[test]
fn wrap_boundaries() {
    assert_eq!(wrap(0.0), 0.0);
    assert_eq!(wrap(PI), PI);
    // -pi is the excluded end: it maps to +pi.
    assert_eq!(wrap(-PI), PI);
    assert!(close(wrap(PI + 1e-9), -PI + 1e-9));
    assert!(close(wrap(-PI + 1e-9), -PI + 1e-9));
    assert!(close(wrap(-PI - 1e-9), PI - 1e-9));
    assert!(close(wrap(TAU), 0.0));
    assert!(close(wrap(7.0), 7.0 - TAU));
    assert!(close(wrap(-7.0), -7.0 + TAU));
    assert!(close(wrap(2.5), 2.5));
    assert!(close(wrap(-2.5), -2.5));
    for i in -400..=400 {
        let x = i as f64 * 0.05;
        let y = wrap(x);
        assert!(y > -PI && y <= PI, "{x} -> {y}");
        let turns = (x - y) / TAU;
        assert!((turns - turns.round()).abs() < 1e-12, "{x} -> {y}");
    }
}

#[test]
fn fit_limits_narrow_range_inside_is_unchanged() {
    let k = rv_m1();
    let q = joints_from_deg([10.0, 20.0, 50.0, 30.0, 170.0]);
    assert_eq!(k.fit_limits(&q, &[0.0; 5]).unwrap(), q);
}

#[test]
fn fit_limits_clamps_within_the_slack() {
    let k = rv_m1();
    let mut q = joints_from_deg([150.0, 20.0, 110.0, -90.0, 0.0]);
    q[0] += 0.5 * tolerance::LIMIT;
    q[2] += 0.5 * tolerance::LIMIT;
    q[3] -= 0.5 * tolerance::LIMIT;
    let out = k.fit_limits(&q, &[0.0; 5]).unwrap();
    let spec = k.description().joints();
    assert_eq!(out[0], spec[0].max);
    assert_eq!(out[2], spec[2].max);
    assert_eq!(out[3], spec[3].min);
}

#[test]
fn fit_limits_moves_by_a_turn_into_the_limits() {
    let k = rv_m1();
    // J5 at 190 deg is -170 deg, inside -180 .. 180.
    let q = joints_from_deg([0.0, 20.0, 50.0, 30.0, 190.0]);
    let out = k.fit_limits(&q, &[0.0; 5]).unwrap();
    assert!(close(out[4], (-170.0f64).to_radians()), "{out:?}");
    // And at -190 deg: 170 deg.
    let q = joints_from_deg([0.0, 20.0, 50.0, 30.0, -190.0]);
    let out = k.fit_limits(&q, &[0.0; 5]).unwrap();
    assert!(close(out[4], 170.0f64.to_radians()), "{out:?}");
}

#[test]
fn fit_limits_range_of_one_turn_takes_the_end_nearest_the_reference() {
    // J5 over exactly -180 .. 180: 180 deg has two representations.
    let k = rv_m1();
    let q = joints_from_deg([0.0, 20.0, 50.0, 30.0, 180.0]);
    let near_minus = joints_from_deg([0.0, 0.0, 0.0, 0.0, -170.0]);
    let near_plus = joints_from_deg([0.0, 0.0, 0.0, 0.0, 170.0]);
    assert!(close(k.fit_limits(&q, &near_minus).unwrap()[4], -PI));
    assert!(close(k.fit_limits(&q, &near_plus).unwrap()[4], PI));
}

#[test]
fn fit_limits_wide_range_nearest_reference() {
    let k = wide_roll();
    let q = joints_from_deg([0.0, 20.0, 50.0, 30.0, 100.0]);
    for (reference, expected) in [
        (0.0, 100.0),
        (279.0, 100.0),
        (281.0, 460.0),
        (300.0, 460.0),
        (-79.0, 100.0),
        (-81.0, -260.0),
        // Beyond the range: the outermost representation inside it.
        (2000.0, 460.0),
        (-2000.0, -260.0),
    ] {
        let r = joints_from_deg([0.0, 0.0, 0.0, 0.0, reference]);
        let out = k.fit_limits(&q, &r).unwrap();
        assert!(
            (out[4].to_degrees() - expected).abs() < 1e-9,
            "reference {reference}: {}",
            out[4].to_degrees()
        );
    }
    // J1 over -200 .. 200: -170 deg has a second representation at 190.
    let q = joints_from_deg([-170.0, 20.0, 50.0, 30.0, 0.0]);
    let r = joints_from_deg([150.0, 0.0, 0.0, 0.0, 0.0]);
    assert!((k.fit_limits(&q, &r).unwrap()[0].to_degrees() - 190.0).abs() < 1e-9);
    let r = joints_from_deg([-150.0, 0.0, 0.0, 0.0, 0.0]);
    assert!((k.fit_limits(&q, &r).unwrap()[0].to_degrees() + 170.0).abs() < 1e-9);
}

#[test]
fn fit_limits_no_representation_reports_the_nearest() {
    let k = rv_m1();
    // J1 at 200 deg: -160 deg is nearer the range (by 10 deg) than 200 (by 50).
    let q = joints_from_deg([200.0, 20.0, 50.0, 30.0, 0.0]);
    let v = k.fit_limits(&q, &[0.0; 5]).unwrap_err();
    assert_eq!(v.joint, 1);
    assert!((v.target.to_degrees() + 160.0).abs() < 1e-9, "{v:?}");
    assert!((v.excess().to_degrees() - 10.0).abs() < 1e-9);
    assert_eq!(v.other_way, None);
    // -200 deg: 160 deg.
    let q = joints_from_deg([-200.0, 20.0, 50.0, 30.0, 0.0]);
    let v = k.fit_limits(&q, &[0.0; 5]).unwrap_err();
    assert!((v.target.to_degrees() - 160.0).abs() < 1e-9, "{v:?}");
    // The first joint that fits no way is reported (1-based), even when a
    // later one does not fit either.
    let q = joints_from_deg([0.0, 20.0, 120.0, 100.0, 0.0]);
    let v = k.fit_limits(&q, &[0.0; 5]).unwrap_err();
    assert_eq!(v.joint, 3);
    assert!((v.target.to_degrees() - 120.0).abs() < 1e-9, "{v:?}");
    assert_eq!(v.min, k.description().joints()[2].min);
    assert_eq!(v.max, k.description().joints()[2].max);
    // A value far away (several turns) is reported in its nearest form.
    let q = joints_from_deg([0.0, 20.0, 50.0, 30.0 + 3.0 * 360.0 + 100.0, 0.0]);
    let v = k.fit_limits(&q, &[0.0; 5]).unwrap_err();
    assert_eq!(v.joint, 4);
    assert!((v.target.to_degrees() - 130.0).abs() < 1e-9, "{v:?}");
    // Not a number: refused, never a panic.
    let q = [f64::NAN, 0.0, 0.0, 0.0, 0.0];
    assert_eq!(k.fit_limits(&q, &[0.0; 5]).unwrap_err().joint, 1);
    let k = wide_roll();
    let q = [0.0, 0.3, 0.5, 0.2, f64::NAN];
    assert_eq!(k.fit_limits(&q, &[0.0; 5]).unwrap_err().joint, 5);
}

#[test]
fn fit_limits_reports_the_representation_nearest_the_range() {
    // Every joint of both robots, targets all round several turns: the
    // reported target is the one of its representations (q + k 2 pi) that
    // exceeds the range least.
    for name in ["rv-m1", "rm-501"] {
        let k = Kinematics::new(RobotDescription::builtin(name).unwrap());
        for (j, spec) in k.description().joints().iter().enumerate() {
            if spec.max - spec.min >= TAU {
                continue;
            }
            for step in -200..=200 {
                let mut q = [0.0; 5];
                for (i, s) in k.description().joints().iter().enumerate() {
                    q[i] = 0.5 * (s.min + s.max);
                }
                q[j] = (step as f64 * 3.7).to_radians();
                let Err(v) = k.fit_limits(&q, &q) else {
                    continue;
                };
                assert_eq!(v.joint, j + 1);
                let nearest = (-4..=4)
                    .map(|t| q[j] + t as f64 * TAU)
                    .map(|c| LimitViolation::excess_of(c, spec.min, spec.max))
                    .fold(f64::INFINITY, f64::min);
                assert!(
                    (v.excess() - nearest).abs() < 1e-12,
                    "{name} J{}: {:.1} deg reported as {:.1} deg",
                    j + 1,
                    q[j].to_degrees(),
                    v.target.to_degrees()
                );
                assert!(
                    ((v.target - q[j]) / TAU - ((v.target - q[j]) / TAU).round()).abs() < 1e-12
                );
            }
        }
    }
}

#[test]
fn branches_report_how_far_the_approach_is_out_of_the_plane() {
    // Flange at (300, 0, 300), approach tilted by 20 deg out of the x-z
    // plane (towards +y or -y): refused with that angle.
    let k = rv_m1();
    for sign in [1.0, -1.0] {
        let mut flange = Pose::rot_x(sign * 20f64.to_radians()) * Pose::rot_y(PI);
        flange.translation = Vector3::new(300.0, 0.0, 300.0);
        match k.branches(&flange, &[0.0; 5]) {
            Err(KinError::OrientationUnreachable { angle }) => {
                assert!((angle.to_degrees() - 20.0).abs() < 1e-9, "{angle}")
            }
            other => panic!("{other:?}"),
        }
    }
}

#[test]
fn nearest_representation_next_to_reference() {
    let raw: Joints = joints_from_deg([100.0, -100.0, 10.0, 179.0, 0.0]);
    let reference = joints_from_deg([300.0, -300.0, 10.0 + 720.0, -179.0, 180.0]);
    let out = Kinematics::nearest_representation(&raw, &reference);
    let expected = [460.0, -460.0, 730.0, -181.0, 0.0];
    for (o, e) in out.iter().zip(expected) {
        assert!((o.to_degrees() - e).abs() < 1e-9, "{out:?}");
    }
    // Exactly half a turn apart: kept (either way is as short).
    let out = Kinematics::nearest_representation(&[0.0; 5], &[PI; 5]);
    assert_eq!(out, [0.0; 5]);
    let out = Kinematics::nearest_representation(&[0.0; 5], &[PI + 1e-9; 5]);
    assert!(out.iter().all(|v| close(*v, TAU)));
}

#[test]
fn joint_distance_is_slowest_joint_time_then_squares() {
    let k = rv_m1();
    let speeds: Vec<f64> = k
        .description()
        .joints()
        .iter()
        .map(|s| s.max_speed)
        .collect();
    let a = [0.1, -0.2, 0.3, -0.4, 0.5];
    let b = [-0.2, 0.1, 0.3, 0.1, -0.5];
    let (time, sq) = k.joint_distance(&a, &b);
    let d = [0.3, 0.3, 0.0, 0.5, 1.0];
    let want_time = d
        .iter()
        .zip(&speeds)
        .map(|(d, s)| d / s)
        .fold(0.0, f64::max);
    let want_sq: f64 = d.iter().map(|d| d * d).sum();
    assert!(close(time, want_time), "{time} {want_time}");
    assert!(close(sq, want_sq), "{sq} {want_sq}");
    // Symmetric, and zero from a pose to itself.
    assert_eq!(k.joint_distance(&b, &a), (time, sq));
    assert_eq!(k.joint_distance(&a, &a), (0.0, 0.0));
    // The slowest joint decides even when it moves less: J2 (72 deg/s)
    // moving 0.3 rad takes longer than J5 (163 deg/s) moving 0.6 rad.
    let (t2, _) = k.joint_distance(&[0.0, 0.3, 0.0, 0.0, 0.0], &[0.0; 5]);
    let (t5, _) = k.joint_distance(&[0.0, 0.0, 0.0, 0.0, 0.6], &[0.0; 5]);
    assert!(t2 > t5, "{t2} {t5}");
    assert!(close(t2, 0.3 / speeds[1]));
}

#[test]
fn refusal_shows_the_excess() {
    let v = LimitViolation {
        joint: 3,
        target: 110.0f64.to_radians() + 1e-6,
        min: 0.0,
        max: 110.0f64.to_radians(),
        other_way: None,
    };
    assert_eq!(
        v.to_string(),
        "joint 3 target 110.00006 deg outside 0.0 .. 110.0 deg by 0.00006 deg"
    );
    let v = LimitViolation {
        target: 120.0f64.to_radians(),
        other_way: Some((-240.0f64).to_radians()),
        ..v
    };
    assert_eq!(
        v.to_string(),
        "joint 3 target 120.0 deg outside 0.0 .. 110.0 deg by 10.0 deg (the other way round, -240.0 deg, by 240.0 deg)"
    );
    let v = LimitViolation {
        target: 110.04f64.to_radians(),
        other_way: Some(110.04f64.to_radians() - TAU),
        ..v
    };
    assert_eq!(
        v.to_string(),
        "joint 3 target 110.04 deg outside 0.0 .. 110.0 deg by 0.04 deg (the other way round, -250.0 deg, by 250.0 deg)"
    );
    assert_eq!(decimals_for(10.0), 1);
    assert_eq!(decimals_for(0.1), 1);
    assert_eq!(decimals_for(0.09), 2);
    assert_eq!(decimals_for(0.001), 3);
    assert_eq!(decimals_for(1e-12), 9);
    assert_eq!(decimals_for(-0.05), 2);
}

#[test]
fn plane_helpers() {
    let x = Vector3::new(1.0, 0.0, 0.0);
    let y = Vector3::new(0.0, 1.0, 0.0);
    let z = Vector3::new(0.0, 0.0, 1.0);
    let on_x = Vector3::new(300.0, 0.0, 100.0);
    assert!(close(out_of_plane(&y, &on_x), FRAC_PI_2));
    assert!(close(out_of_plane(&(y * 7.0), &on_x), FRAC_PI_2));
    assert_eq!(out_of_plane(&x, &on_x), 0.0);
    assert_eq!(out_of_plane(&z, &on_x), 0.0);
    assert_eq!(out_of_plane(&y, &Vector3::new(0.0, 0.0, 5.0)), 0.0);
    for a in [0.1f64, 0.5, 1.0, 1.5] {
        let v = Vector3::new(a.cos(), a.sin(), 0.0);
        assert!(close(out_of_plane(&v, &on_x), a));
        assert!(close(out_of_plane(&-v, &on_x), a));
        // Any length: the angle, not the component.
        assert!(close(out_of_plane(&(v * 3.0), &on_x), a));
        // Off the x axis: the plane through (1, 1, 0).
        let c = Vector3::new(200.0, 200.0, 0.0);
        let w = nalgebra::Rotation3::from_axis_angle(&Vector3::z_axis(), FRAC_PI_2 / 2.0) * v;
        assert!(close(out_of_plane(&w, &c), a));
        // into_plane turns by exactly that angle, into the plane, keeping
        // the in-plane part's direction.
        let r = into_plane(&w, &c);
        let turned = r * w;
        assert!(close(out_of_plane(&turned, &c), 0.0), "{turned:?}");
        assert!(close(turned.dot(&w).clamp(-1.0, 1.0).acos(), a));
        assert!((r.transpose() * r - nalgebra::Matrix3::identity()).amax() < 1e-12);
        assert!(close(r.determinant(), 1.0));
        let m = Vector3::new(-c.y, c.x, 0.0).normalize();
        let in_plane = (w - m * w.dot(&m)).normalize();
        assert!(
            (turned - in_plane).amax() < 1e-12,
            "{turned:?} {in_plane:?}"
        );
    }
    // Perpendicular: horizontal, away from the axis.
    let c = Vector3::new(-100.0, 100.0, 0.0);
    let m = Vector3::new(-c.y, c.x, 0.0).normalize();
    let turned = into_plane(&m, &c) * m;
    assert!((turned - Vector3::new(-1.0, 1.0, 0.0).normalize()).amax() < 1e-12);
    // On the axis, or already in the plane: no turn.
    assert_eq!(
        into_plane(&y, &Vector3::new(0.0, 0.0, 3.0)),
        nalgebra::Matrix3::identity()
    );
    assert_eq!(into_plane(&x, &on_x), nalgebra::Matrix3::identity());
}

#[test]
fn exception_names() {
    for (e, name) in [
        (AdaException::FrameInvalid, "FrameInvalid"),
        (AdaException::OutOfReach, "OutOfReach"),
        (AdaException::TimeInvalid, "TimeInvalid"),
        (AdaException::ConstraintError, "Constraint_Error"),
    ] {
        assert_eq!(e.name(), name);
        assert_eq!(e.to_string(), name);
    }
}

/// Positions in messages: one decimal, rounded half away from zero, never
/// "-0.0".
#[test]
fn positions_in_messages() {
    let e = KinError::WristTooFar {
        distance: 500.0,
        reach: 410.0,
        goal: Vector3::new(-0.04, 12.36, -7.0),
        nearest: Vector3::new(-0.0, 399.94, 0.25),
    };
    assert_eq!(
        e.to_string(),
        "goal (0.0, 12.4, -7.0) mm out of reach: wrist point 500.0 mm from shoulder, reach 410.0 mm; nearest within the arm's length with this orientation (0.0, 399.9, 0.3) mm"
    );
}

/// The inverse kinematics solve for the flange and name the TCP: `shifted`
/// moves the positions of a reach error, also inside a blocked line.
#[test]
fn shifted_moves_the_named_positions() {
    let by = Vector3::new(1.0, 2.0, 3.0);
    let far = KinError::WristTooFar {
        distance: 500.0,
        reach: 410.0,
        goal: Vector3::new(10.0, 0.0, 0.0),
        nearest: Vector3::new(5.0, 0.0, 0.0),
    };
    let moved = KinError::WristTooFar {
        distance: 500.0,
        reach: 410.0,
        goal: Vector3::new(11.0, 2.0, 3.0),
        nearest: Vector3::new(6.0, 2.0, 3.0),
    };
    assert_eq!(far.clone().shifted(by), moved);
    let line = |cause: KinError| KinError::LineBlocked {
        at: 4.0,
        length: 9.0,
        cause: Box::new(cause),
    };
    assert_eq!(line(far.clone()).shifted(by), line(moved));
    let other = KinError::TimeInvalid {
        requested: 1.0,
        minimum: 2.0,
    };
    assert_eq!(other.clone().shifted(by), other);
}

#[test]
fn every_branch_listed_with_separators() {
    let v = LimitViolation {
        joint: 1,
        target: 3.0,
        min: -2.0,
        max: 2.0,
        other_way: None,
    };
    let e = KinError::NoBranchWithinLimits {
        branches: vec![
            (Arm::Forward, Elbow::Above, v),
            (Arm::Backward, Elbow::Below, v),
        ],
    };
    let one = v.to_string();
    assert_eq!(
        e.to_string(),
        format!(
            "every arm configuration breaks a joint limit: {}/{}: {one}; {}/{}: {one}",
            Arm::Forward,
            Elbow::Above,
            Arm::Backward,
            Elbow::Below
        )
    );
}
