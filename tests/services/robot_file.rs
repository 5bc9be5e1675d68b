//! A robot description read from a file (`--robot-file`): the services
//! read it, the kinematics parse its text.

use adair::kinematics::{Kinematics, RobotDescription};
use adair::services::read_robot_file;

#[test]
fn third_robot_is_a_file() {
    let text = RobotDescription::builtin_text("rv-m1")
        .unwrap()
        .replace("name = \"RV-M1\"", "name = \"Mini\"")
        .replace("l2 = 250.0", "l2 = 200.0");
    let dir = std::env::temp_dir().join(format!("adair-kin-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("mini.toml");
    std::fs::write(&path, text).unwrap();
    let d = read_robot_file(&path).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(d.name(), "Mini");
    let k = Kinematics::new(d);
    assert_eq!(k.fk_tcp(&[0.0; 5], &k.standard_tool()).translation.z, 839.0);
}

#[test]
fn missing_file() {
    let e = read_robot_file("/nonexistent/robot.toml").unwrap_err();
    assert_eq!(e.source, "/nonexistent/robot.toml");
    assert!(e.problems[0].starts_with("cannot read the file"), "{e}");
}
