//! Ctrl-C (SIGINT) during `adair run` on the simulator: the motion stops
//! where it is, the program ends (a handler cannot catch it), stderr says
//! where the program was, and the exit status is 130.

use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

#[test]
fn sigint_during_a_motion_stops_it_and_exits_130() {
    let dir = std::env::temp_dir().join(format!("adair-sigint-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let script = dir.join("long.air");
    std::fs::write(
        &script,
        "InitRobot;\nPut_Line (\"started\");\nbegin\n   \
         MoveAxesAbsolute ((2.0, 0.0, 0.0, 0.0, 0.0), Time => 30.0, RealTime => True);\n\
         exception\n   when others => Put_Line (\"caught (wrong)\");\nend;\n\
         Put_Line (\"went on (wrong)\");\n",
    )
    .unwrap();
    let child = Command::new(env!("CARGO_BIN_EXE_adair"))
        .arg("run")
        .arg(&script)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    std::thread::sleep(Duration::from_millis(1500));
    let t = Instant::now();
    let status = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(status.success());
    let out = child.wait_with_output().unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    let (stdout, stderr) = (
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr),
    );
    assert!(
        t.elapsed() < Duration::from_secs(5),
        "took {:?}",
        t.elapsed()
    );
    assert_eq!(out.status.code(), Some(130), "{stdout}\n{stderr}");
    assert_eq!(stdout, "started\n");
    assert!(
        stderr.contains("interrupted (Ctrl-C) at long.air:4 in MoveAxesAbsolute"),
        "{stderr}"
    );
    // J1 stopped part-way: between 0 and 2 rad (about 115 deg).
    let j1: f64 = stderr
        .split("stopped at (")
        .nth(1)
        .and_then(|r| r.split(',').next())
        .and_then(|x| x.trim().parse().ok())
        .unwrap_or(-1.0);
    assert!(j1 > 0.0 && j1 < 60.0, "{stderr}");
}
