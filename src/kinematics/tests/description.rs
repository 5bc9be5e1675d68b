//! Robot description files: built-ins, a third robot, loading errors.

use crate::kinematics::{Kinematics, RobotDescription, joints_from_deg, joints_to_deg};

#[test]
fn builtins() {
    let rv = RobotDescription::builtin("rv-m1").unwrap();
    assert_eq!(rv.name(), "RV-M1");
    let l = rv.links();
    assert_eq!(
        (l.l1, l.l2, l.l3, l.l4, l.tool),
        (300.0, 250.0, 160.0, 72.0, 107.0)
    );
    let j2 = &rv.joints()[1];
    assert_eq!(j2.name, "shoulder");
    assert!((j2.min - (-30.0f64).to_radians()).abs() < 1e-15);
    assert!((j2.max - 100.0f64.to_radians()).abs() < 1e-15);
    assert!((j2.max_speed - 72.0f64.to_radians()).abs() < 1e-15);
    assert!((rv.joints()[0].resolution - (1.0f64 / 40.0).to_radians()).abs() < 1e-15);
    let g = rv.gripper();
    assert_eq!(
        (
            g.opening_min,
            g.opening_max,
            g.force_min,
            g.force_max,
            g.init_force
        ),
        (0.0, 60.0, 0.0, 30.0, 10.0)
    );

    let rm = RobotDescription::builtin("RM-501").unwrap();
    assert_eq!(rm.name(), "RM-501");
    assert_eq!(rm.links().tool, 149.6);
    assert!((rm.joints()[2].max - 90.0f64.to_radians()).abs() < 1e-15);
    assert!((rm.joints()[3].resolution - 0.075f64.to_radians()).abs() < 1e-15);
    for (a, b) in rm.joints().iter().zip(rv.joints()) {
        assert!((a.max_speed - 0.4 * b.max_speed).abs() < 1e-12);
    }
    let e = RobotDescription::builtin("puma").unwrap_err();
    assert!(
        e.to_string().contains("built-in robots: rv-m1, rm-501"),
        "{e}"
    );
}

/// A third robot: a description file's text, named in its errors (the
/// file itself is read by the services: tests/services/robot_file.rs).
#[test]
fn third_robot_from_a_files_text() {
    let text = RobotDescription::builtin_text("rv-m1")
        .unwrap()
        .replace("name = \"RV-M1\"", "name = \"Mini\"")
        .replace("l2 = 250.0", "l2 = 200.0");
    let d = RobotDescription::from_file_text(&text, "mini.toml").unwrap();
    assert_eq!(d.name(), "Mini");
    let k = Kinematics::new(d);
    assert_eq!(k.fk_tcp(&[0.0; 5], &k.standard_tool()).translation.z, 839.0);
    let e = RobotDescription::from_file_text("name = 1", "mini.toml").unwrap_err();
    assert_eq!(e.source, "mini.toml");
}

#[test]
fn every_missing_and_invalid_field_named() {
    let text = RobotDescription::builtin_text("rv-m1")
        .unwrap()
        .replace("l2 = 250.0", "")
        .replace("l4 = 72.0", "l4 = -72.0")
        .replacen("max_deg = 100.0", "max_deg = -40.0", 1)
        .replacen("speed_deg_s = 109.0", "", 1)
        .replacen("direction = 1", "direction = 2", 1)
        .replace("init_force_n = 10.0", "init_force_n = 31.0")
        .replace("opening_mm = [0.0, 60.0]", "opening_mm = [60.0, 0.0]")
        .replacen("resolution_deg = 0.025", "resolution_deg = 0.0", 1);
    let e = RobotDescription::from_toml_str(&text).unwrap_err();
    let all = e.to_string();
    for needle in [
        "missing field `links.l2`",
        "field `links.l4` = -72: expected a length > 0 mm",
        "joint[2]: min_deg -30 not below max_deg -40",
        "missing field `joint[3].speed_deg_s`",
        "field `joint[1].direction` = 2: expected 1 or -1",
        "field `gripper.init_force_n` = 31: outside gripper.force_n 0 .. 30",
        "field `gripper.opening_mm` = [60, 0]",
        "field `joint[1].resolution_deg` = 0: expected > 0 deg",
    ] {
        assert!(all.contains(needle), "`{needle}` not in:\n{all}");
    }
    assert_eq!(e.problems.len(), 8, "{all}");
    assert!(all.starts_with("robot description <string>:"));
}

#[test]
fn structure_errors() {
    let base = RobotDescription::builtin_text("rv-m1").unwrap();
    // Unknown key: named with its line by the parser.
    let e = RobotDescription::from_toml_str(&base.replace("l1 = 300.0", "l1 = 300.0\nl9 = 1.0"))
        .unwrap_err();
    assert!(e.to_string().contains("l9"), "{e}");
    assert!(e.to_string().contains("line"), "{e}");
    // Wrong type.
    let e =
        RobotDescription::from_toml_str(&base.replace("l1 = 300.0", "l1 = \"300\"")).unwrap_err();
    assert!(e.to_string().contains("line"), "{e}");
    // Missing tables and joints.
    let e = RobotDescription::from_toml_str("name = \"x\"").unwrap_err();
    assert_eq!(e.problems.len(), 3, "{e}");
    assert!(e.to_string().contains("missing table `[links]`"));
    assert!(e.to_string().contains("missing table `[gripper]`"));
    assert!(
        e.to_string()
            .contains("missing `[[joint]]` tables (expected 5)")
    );
    // Wrong number of joints.
    let four = base.rsplit_once("[[joint]]").unwrap().0;
    let e = RobotDescription::from_toml_str(four).unwrap_err();
    assert!(
        e.to_string().contains("4 `[[joint]]` tables, expected 5"),
        "{e}"
    );
    // Not TOML at all.
    let e = RobotDescription::from_toml_str("this is = = not toml").unwrap_err();
    assert_eq!(e.problems.len(), 1);
    // Integers are accepted where a number is expected.
    let d = RobotDescription::from_toml_str(&base.replace("l1 = 300.0", "l1 = 300")).unwrap();
    assert_eq!(d.links().l1, 300.0);
}

#[test]
fn controller_conversion_and_quantisation() {
    let text = RobotDescription::builtin_text("rm-501")
        .unwrap()
        .replacen("direction = 1", "direction = -1", 1)
        .replacen("zero_offset_deg = 0.0", "zero_offset_deg = 10.0", 1);
    let d = RobotDescription::from_toml_str(&text).unwrap();
    let q = joints_from_deg([30.0, 20.0, 10.0, 5.0, 1.0]);
    let c = d.to_controller_deg(&q);
    assert!((c[0] - (-30.0 + 10.0)).abs() < 1e-12);
    let back = d.from_controller_deg(&c);
    for (a, b) in back.iter().zip(&q) {
        assert!((a - b).abs() < 1e-15);
    }
    let quant = joints_to_deg(&d.quantize(&joints_from_deg([10.01, 10.01, 10.01, 10.01, 10.04])));
    // J1 with its offset and reversed direction: still the nearest step.
    assert!((quant[0] - 10.0).abs() < 1e-9, "{quant:?}");
    assert!((quant[1] - 10.0).abs() < 1e-9);
    assert!((quant[3] - 9.975).abs() < 1e-9, "{quant:?}");
    assert!((quant[4] - 10.05).abs() < 1e-9, "{quant:?}");
}

#[test]
fn the_nest_pose_is_read_and_checked_against_the_limits() {
    let d = RobotDescription::builtin("rm-501").unwrap();
    let nest: Vec<f64> = d.nest().iter().map(|q| q.to_degrees()).collect();
    for (a, b) in nest.iter().zip([0.0, 0.0, 90.0, 90.0, 0.0]) {
        assert!((a - b).abs() < 1e-9, "{nest:?}");
    }
    let text = RobotDescription::builtin_text("rv-m1").unwrap().replace(
        "nest_deg = [0.0, 0.0, 90.0, 90.0, 0.0]",
        "nest_deg = [0.0, 0.0, 120.0, 90.0, 0.0]",
    );
    let e = RobotDescription::from_toml_str(&text).unwrap_err();
    assert!(e.to_string().contains("nest_deg[3]"), "{e}");
}
