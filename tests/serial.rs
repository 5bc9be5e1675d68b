//! The serial driver against the virtual controller over a real
//! pseudo-terminal, for both robots: the same joints as the simulator, every
//! fault class as its exception (and the program goes on), a missing port,
//! a silent unit, the wrong robot, `--rehearse`, golden logs of the lines
//! sent, and the controller on its own with raw byte exchanges. Where the OS
//! has no pseudo-terminals, the tests are reported as ignored, with a message.

#![allow(clippy::print_stderr)] // a skipped test and the measured difference say so

use adair::driver::serial::{PortSettings, Serial};
use adair::golden::SharedBuf;
use adair::kinematics::RobotDescription;
use adair::session::{Outcome, Session};
mod common;

use std::io::{BufRead, BufReader, Read, Write};
use std::process::{Child, Command, Stdio};
use std::sync::mpsc;
use std::time::Duration;

const BIN: &str = env!("CARGO_BIN_EXE_adair");

/// A running `adair sim-controller`; killed (by its own pid) when dropped.
struct Controller {
    child: Child,
    path: String,
    log: std::path::PathBuf,
}

impl Drop for Controller {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
        let _ = std::fs::remove_file(&self.log);
    }
}

impl Controller {
    /// How many hand jogs the controller has made.
    fn jogs(&self) -> usize {
        let text = std::fs::read_to_string(&self.log).unwrap_or_default();
        text.lines().filter(|l| l.contains(" j ")).count()
    }

    /// The lines the controller received, in order.
    fn received(&self) -> Vec<String> {
        let text = std::fs::read_to_string(&self.log).unwrap_or_default();
        let mut bytes = String::new();
        for l in text.lines() {
            if let Some(i) = l.find(" < ") {
                bytes.push_str(&l[i + 3..]);
            }
        }
        bytes
            .split("\\r")
            .filter(|s| !s.is_empty())
            .map(str::to_string)
            .collect()
    }
}

static COUNTER: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);

/// Starts a controller; `None` (after saying so) when there are no ptys.
fn controller(robot: &str, extra: &[&str]) -> Option<Controller> {
    let n = COUNTER.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
    let log = std::env::temp_dir().join(format!("adair-simctl-{}-{n}.log", std::process::id()));
    let scale: &[&str] = if extra.contains(&"--time-scale") {
        &[]
    } else {
        &["--time-scale", "0.02"]
    };
    let mut child = Command::new(BIN)
        .args(["sim-controller", "--robot", robot])
        .args(scale)
        .arg("--log")
        .arg(&log)
        .args(extra)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("adair runs");
    let stdout = child.stdout.take().unwrap();
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let mut line = String::new();
        let _ = BufReader::new(stdout).read_line(&mut line);
        let _ = tx.send(line);
    });
    let line = rx.recv_timeout(Duration::from_secs(10)).unwrap_or_default();
    if line.trim().is_empty() {
        let mut err = String::new();
        if let Some(mut e) = child.stderr.take() {
            let _ = e.read_to_string(&mut err);
        }
        let _ = child.kill();
        let _ = child.wait();
        assert!(
            err.contains("no pseudo-terminal"),
            "sim-controller failed: {err}"
        );
        eprintln!("SKIPPED: this OS has no pseudo-terminals ({})", err.trim());
        return None;
    }
    Some(Controller {
        child,
        path: line.trim().to_string(),
        log,
    })
}

/// Runs `script` on `robot`, over `port` or (None) on the simulator:
/// (outcome, output, final joints read back in degrees).
fn run(robot: &str, port: Option<&str>, script: &str) -> (Outcome, String, [f64; 5]) {
    let desc = RobotDescription::builtin(robot).unwrap();
    let buf = SharedBuf::default();
    let mut s = Session::new(Box::new(buf.clone()));
    s.machine.input = Box::new(std::io::BufReader::new(std::io::empty()));
    match port {
        None => s.set_robot(desc, None, false),
        Some(p) => {
            let settings = PortSettings {
                path: p.to_string(),
                baud: 9600,
                timeout: 0.5,
            };
            let d = Serial::new(desc.clone(), settings, None);
            s.set_driver(desc, Box::new(d), None, false);
        }
    }
    let outcome = s.run_source("test.air", script);
    let q = s.robot_state().unwrap().robot.read_joints();
    let out = buf.take();
    (outcome, out, q.map(f64::to_degrees))
}

const MOTIONS: &str = "
F : Frame;
InitRobot;
MoveAxesAbsolute ((Rad (30.0), Rad (20.0), Rad (40.0), Rad (-10.0), Rad (50.0)));
MoveAxesRelative ((Rad (-5.5), Rad (3.3), Rad (1.1), Rad (7.7), Rad (-20.2)));
SetVelocity (80.0);
F := ValueFrameAbsolute;
MoveAxesRelative ((Rad (12.0), Rad (-6.0), Rad (9.0), Rad (-4.0), Rad (33.0)));
MoveFrameAbsolute (F);
MoveTool (10.0, 5.0);
Put_Line (\"done\");
";

fn same_joints(robot: &str) {
    let Some(c) = controller(robot, &[]) else {
        return;
    };
    let (o1, out1, sim) = run(robot, None, MOTIONS);
    let (o2, out2, ser) = run(robot, Some(&c.path), MOTIONS);
    assert!(matches!(o1, Outcome::Ok), "{o1:?}");
    assert!(matches!(o2, Outcome::Ok), "{o2:?}");
    assert_eq!(out1, out2);
    let worst = sim
        .iter()
        .zip(ser)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    eprintln!("{robot}: largest simulator-vs-serial joint difference {worst:.4} deg");
    // One decimal in MJ (0.05 deg) plus the read-back resolution.
    assert!(worst <= 0.05 + 0.075 + 1e-9, "{sim:?} vs {ser:?}");
}

fn same_joints_on_the_simulator_and_over_the_line_rv_m1() {
    same_joints("rv-m1");
}

fn same_joints_on_the_simulator_and_over_the_line_rm_501() {
    same_joints("rm-501");
}

/// The script for the fault tests: the exception's name, then the program
/// goes on (a second service, whose exception is printed too).
const FAULT: &str = "
InitRobot;
begin
   MoveAxesAbsolute ((Rad (10.0), 0.0, 0.0, 0.0, 0.0));
   Put_Line (\"moved\");
exception
   when E : others => Put_Line (Ada.Exceptions.Exception_Name (E) & \": \" & Ada.Exceptions.Exception_Message (E));
end;
begin
   MoveAxesAbsolute ((Rad (20.0), 0.0, 0.0, 0.0, 0.0));
   Put_Line (\"moved again\");
exception
   when E : others => Put_Line (Ada.Exceptions.Exception_Name (E) & \": \" & Ada.Exceptions.Exception_Message (E));
end;
Put_Line (\"went on\");
";

/// InitRobot sends ER RS TL NT ER WH SP MJ ER GO ER; the first motion
/// then reads the arm's pose afresh (WH, command 12): its MJ is command 13,
/// its ER command 14.
fn fault(extra: &[&str]) -> Option<String> {
    let c = controller("rv-m1", extra)?;
    let t = std::time::Instant::now();
    let (o, out, _) = run("rv-m1", Some(&c.path), FAULT);
    assert!(matches!(o, Outcome::Ok), "{o:?}\n{out}");
    assert!(out.ends_with("went on\n"), "{out}");
    assert!(
        t.elapsed() < Duration::from_secs(20),
        "took {:?}",
        t.elapsed()
    );
    Some(out)
}

fn a_silent_unit_is_message_lost() {
    let Some(out) = fault(&["--silent-after", "12"]) else {
        return;
    };
    assert!(out.contains("ADAIR.MESSAGELOST: no reply"), "{out}");
}

fn a_garbled_reply_is_message_invalid() {
    let Some(out) = fault(&["--corrupt", "14"]) else {
        return;
    };
    assert!(out.contains("ADAIR.MESSAGEINVALID"), "{out}");
    assert!(out.contains("moved again"), "{out}");
}

fn error_mode_one_is_command_not_supported_and_reset() {
    let Some(out) = fault(&["--refuse", "13:1"]) else {
        return;
    };
    assert!(
        out.contains("ADAIR.COMMANDNOTSUPPORTED: the unit refused `MJ +10.0"),
        "{out}"
    );
    assert!(out.contains("moved again"), "{out}");
}

fn error_mode_two_is_out_of_reach_and_reset() {
    let Some(out) = fault(&["--refuse", "13:2"]) else {
        return;
    };
    assert!(out.contains("ADAIR.OUTOFREACH: the unit says"), "{out}");
    assert!(out.contains("moved again"), "{out}");
}

/// The unit refuses the first motion, from the zero pose where `WH` cannot
/// tell J1 (the tool on the waist axis): the program must still see the J1
/// the arm has, 0, not the refused target; the next relative motion then
/// ends where the program thinks.
fn a_refused_motion_leaves_the_joints_where_the_arm_is() {
    let Some(c) = controller("rv-m1", &["--refuse", "13:1"]) else {
        return;
    };
    let script = "
InitRobot;
begin
   MoveAxesRelative ((Rad (10.0), 0.0, 0.0, 0.0, 0.0));
exception
   when E : others => Put_Line (Ada.Exceptions.Exception_Name (E));
end;
A : AxesVector := ValueAxes;
Put_Line (Integer'Image (Integer (Deg (A (1)))));
MoveAxesRelative ((Rad (5.0), Rad (30.0), 0.0, 0.0, 0.0));
";
    let (o, out, q) = run("rv-m1", Some(&c.path), script);
    assert!(matches!(o, Outcome::Ok), "{o:?}\n{out}");
    assert_eq!(out, "ADAIR.COMMANDNOTSUPPORTED\n 0\n");
    assert!(
        (q[0] - 5.0).abs() < 0.05 && (q[1] - 30.0).abs() < 0.05,
        "{q:?}"
    );
    // What the arm was told: J1 by +5 in all, not +10 then +5.
    let log = std::fs::read_to_string(&c.log).unwrap_or_default();
    assert!(log.contains("MJ +5.0"), "{log}");
}

fn a_hang_up_is_fatal_then_no_connection() {
    let Some(out) = fault(&["--hangup-after", "13"]) else {
        return;
    };
    assert!(out.contains("ADAIR.FATALCOMMUNICATIONERROR"), "{out}");
    assert!(out.contains("ADAIR.NOCONNECTION"), "{out}");
}

/// Replies slower than usual but within `--serial-timeout` (0.5 s here):
/// everything works, only later.
fn slow_replies_within_the_timeout_work() {
    let Some(out) = fault(&["--slow", "0.2"]) else {
        return;
    };
    assert_eq!(out, "moved\nmoved again\nwent on\n");
}

/// Replies beyond the timeout: the first `ER` at `InitRobot` finds no unit
/// (`NoRobotInstalled`), in about the timeout, not forever.
fn slow_replies_beyond_the_timeout_are_no_robot() {
    let Some(c) = controller("rv-m1", &["--slow", "1.5"]) else {
        return;
    };
    let t = std::time::Instant::now();
    let (_, out, _) = run("rv-m1", Some(&c.path), INIT);
    assert!(out.starts_with("ADAIR.NOROBOTINSTALLED"), "{out}");
    assert!(
        t.elapsed() < Duration::from_secs(5),
        "took {:?}",
        t.elapsed()
    );
}

const INIT: &str = "
begin
   InitRobot;
exception
   when E : others => Put_Line (Ada.Exceptions.Exception_Name (E) & \": \" & Ada.Exceptions.Exception_Message (E));
end;
";

fn a_missing_port_is_no_connection_naming_it() {
    let (o, out, _) = run("rv-m1", Some("/dev/adair-no-such-port"), INIT);
    assert!(matches!(o, Outcome::Ok));
    assert!(
        out.starts_with("ADAIR.NOCONNECTION: port /dev/adair-no-such-port: "),
        "{out}"
    );
}

fn a_unit_that_never_answers_is_no_robot_installed() {
    let Some(c) = controller("rv-m1", &["--silent-after", "0"]) else {
        return;
    };
    let (_, out, _) = run("rv-m1", Some(&c.path), INIT);
    assert!(out.starts_with("ADAIR.NOROBOTINSTALLED"), "{out}");
}

fn an_rv_m1_where_an_rm_501_is_expected_is_wrong_robot() {
    let Some(c) = controller("rv-m1", &[]) else {
        return;
    };
    let (_, out, _) = run("rm-501", Some(&c.path), INIT);
    assert!(out.starts_with("ADAIR.WRONGROBOTINSTALLED"), "{out}");
}

fn a_failed_rehearsal_sends_no_motion() {
    let Some(c) = controller("rv-m1", &[]) else {
        return;
    };
    let dir = std::env::temp_dir().join(format!("adair-rehearse-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let script = dir.join("fails_later.air");
    std::fs::write(
        &script,
        "InitRobot;\nMoveAxesAbsolute ((Rad (10.0), 0.0, 0.0, 0.0, 0.0));\nMoveAxesAbsolute ((0.0, Rad (150.0), 0.0, 0.0, 0.0));\n",
    )
    .unwrap();
    let out = Command::new(BIN)
        .args([
            "run",
            "--port",
            &c.path,
            "--serial-timeout",
            "0.5",
            "--rehearse",
        ])
        .arg(&script)
        .output()
        .unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(err.contains("OUTOFREACH"), "{err}");
    assert!(err.contains("the arm was not moved"), "{err}");
    let sent = c.received();
    assert!(
        sent.iter()
            .all(|l| ["ER", "RS", "WH"].contains(&l.as_str()) || l.starts_with("TL")),
        "{sent:?}"
    );
}

/// The rehearsal stands in for the real arm, not for the simulator: a
/// script that calls a simulator-only service (`PlaceObject`) fails its
/// rehearsal with `CommandNotSupported`, so the arm never starts a job it
/// cannot finish; no motion command is sent.
fn a_rehearsal_refuses_a_simulator_only_service() {
    let Some(c) = controller("rv-m1", &[]) else {
        return;
    };
    let dir = std::env::temp_dir().join(format!("adair-rehearse-sim-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let script = dir.join("places.air");
    std::fs::write(
        &script,
        "InitRobot;\nMoveAxesAbsolute ((Rad (10.0), 0.0, 0.0, 0.0, 0.0));\nPlaceObject (30.0);\nMoveTool (0.0, 5.0);\n",
    )
    .unwrap();
    let out = Command::new(BIN)
        .args([
            "run",
            "--port",
            &c.path,
            "--serial-timeout",
            "0.5",
            "--rehearse",
        ])
        .arg(&script)
        .env("NO_COLOR", "1")
        .output()
        .unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(
        err.contains("places.air:3:1: warning[W0002]: `PlaceObject` exists only on the simulator"),
        "{err}"
    );
    assert!(
        err.contains("COMMANDNOTSUPPORTED")
            && err.contains("PlaceObject exists only on the simulator"),
        "{err}"
    );
    assert!(err.contains("the arm was not moved"), "{err}");
    let sent = c.received();
    assert!(
        sent.iter()
            .all(|l| ["ER", "RS", "WH"].contains(&l.as_str()) || l.starts_with("TL")),
        "{sent:?}"
    );
}

/// `adair test --port` runs golden scripts on the arm: a script that passes
/// moved it; with `--rehearse`, a script that fails later is reported and
/// sends no motion command.
fn adair_test_runs_golden_scripts_on_the_arm() {
    let Some(c) = controller("rv-m1", &[]) else {
        return;
    };
    let dir = std::env::temp_dir().join(format!("adair-testport-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(
        dir.join("moves.air"),
        "InitRobot;\nMoveAxesAbsolute ((Rad (10.0), 0.0, 0.0, 0.0, 0.0));\n\
         Put_Line (\"J1 about 10: \" & Boolean'Image (abs (Deg (ValueAxes (1)) - 10.0) < 0.2));\n",
    )
    .unwrap();
    std::fs::write(dir.join("moves.out"), "J1 about 10: TRUE\n").unwrap();
    let test = |args: &[&str], path: &std::path::Path| {
        let out = Command::new(BIN)
            .arg("test")
            .args(args)
            .args(["--port", &c.path, "--serial-timeout", "0.5"])
            .arg(path)
            .output()
            .unwrap();
        (
            out.status.code(),
            String::from_utf8_lossy(&out.stdout).into_owned(),
        )
    };
    let (code, out) = test(&[], &dir.join("moves.air"));
    assert_eq!(code, Some(0), "{out}");
    assert!(out.contains("1 passed, 0 failed"), "{out}");
    assert!(
        c.received().iter().any(|l| l.starts_with("MJ +10.0")),
        "{:?}",
        c.received()
    );
    let before = c.received().len();
    std::fs::write(
        dir.join("fails_later.air"),
        "InitRobot;\nMoveAxesAbsolute ((Rad (20.0), 0.0, 0.0, 0.0, 0.0));\n\
         MoveAxesAbsolute ((0.0, Rad (150.0), 0.0, 0.0, 0.0));\n",
    )
    .unwrap();
    std::fs::write(dir.join("fails_later.out"), "").unwrap();
    let (code, out) = test(&["--rehearse"], &dir.join("fails_later.air"));
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(code, Some(1), "{out}");
    assert!(
        out.contains("FAIL") && out.contains("the arm was not moved"),
        "{out}"
    );
    let sent = c.received();
    assert!(
        sent[before..]
            .iter()
            .all(|l| ["ER", "RS", "WH"].contains(&l.as_str()) || l.starts_with("TL")),
        "{sent:?}"
    );
}

/// The exact lines sent for a script, against `tests/serial/NAME.log`
/// (`BLESS=1` rewrites it), so that a protocol change shows in review.
fn golden_log(robot: &str, name: &str, script: &str) {
    let Some(c) = controller(robot, &[]) else {
        return;
    };
    let (o, out, _) = run(robot, Some(&c.path), script);
    assert!(matches!(o, Outcome::Ok), "{o:?}\n{out}");
    let got = c.received().join("\n") + "\n";
    let path = format!("{}/tests/serial/{name}.log", env!("CARGO_MANIFEST_DIR"));
    if std::env::var_os("BLESS").is_some() {
        std::fs::write(&path, &got).unwrap();
    }
    let want = std::fs::read_to_string(&path).unwrap_or_default();
    assert_eq!(
        got, want,
        "lines sent differ from {path} (BLESS=1 rewrites)"
    );
}

fn golden_lines_rv_m1() {
    golden_log("rv-m1", "rv_m1_motions", MOTIONS);
}

fn golden_lines_rm_501() {
    golden_log("rm-501", "rm_501_motions", MOTIONS);
}

fn golden_lines_straight_line_rv_m1() {
    golden_log(
        "rv-m1",
        "rv_m1_straight_line",
        "InitRobot;\nMoveFrameAbsolute (Trans (250.0, 0.0, 300.0) * RotY (Rad (180.0)));\nSetMoveMode (StraightLine);\nSetInterpolation (25.0);\nMoveFrameAbsolute (Trans (250.0, 100.0, 300.0) * RotY (Rad (180.0)));\n",
    );
}

/// The controller on its own: raw bytes, as robots.md describes the unit.
fn the_controller_speaks_the_units_language() {
    let Some(c) = controller("rv-m1", &[]) else {
        return;
    };
    let mut port = std::fs::OpenOptions::new()
        .read(true)
        .write(true)
        .open(&c.path)
        .unwrap();
    let (tx, rx) = mpsc::channel::<String>();
    let mut reader = port.try_clone().unwrap();
    std::thread::spawn(move || {
        let mut buf = Vec::new();
        let mut b = [0u8; 1];
        while reader.read(&mut b).is_ok_and(|n| n == 1) {
            buf.push(b[0]);
            if buf.ends_with(b"\r\n") {
                let _ = tx.send(String::from_utf8_lossy(&buf).to_string());
                buf.clear();
            }
        }
    });
    let mut ask = |line: &str| -> Option<String> {
        port.write_all(format!("{line}\r").as_bytes()).unwrap();
        rx.recv_timeout(Duration::from_millis(800)).ok()
    };
    assert_eq!(ask("ER").as_deref(), Some("0\r\n"));
    assert_eq!(ask("NT"), None);
    let wh = ask("WH").unwrap();
    // Nest: J = 0, 0, 90, 90, 0 with the 107 mm tool: hand pointing down.
    assert_eq!(wh, "+160.0,+0.0,+371.0,-90.0,+0.0\r\n");
    assert_eq!(ask("XY"), None);
    assert_eq!(ask("ER").as_deref(), Some("1\r\n"));
    assert_eq!(ask("RS"), None);
    assert_eq!(ask("ER").as_deref(), Some("0\r\n"));
    assert_eq!(ask("MJ +10.0,+5.0,-10.0,-20.0,+0.0"), None);
    let there = ask("WH").unwrap();
    assert_ne!(there, wh);
    assert_eq!(ask("MJ -10.0,-5.0,+10.0,+20.0,+0.0"), None);
    assert_eq!(ask("WH").as_deref(), Some(wh.as_str()));
    assert_eq!(ask(&format!("PD 7,{}", there.trim())), None);
    assert_eq!(ask("MO 7"), None);
    assert_eq!(ask("WH").as_deref(), Some(there.as_str()));
    assert_eq!(ask("ER").as_deref(), Some("0\r\n"));
    assert_eq!(ask("MO 8"), None);
    assert_eq!(ask("ER").as_deref(), Some("2\r\n"));
    assert_eq!(ask("RS"), None);
    assert_eq!(ask("MJ +0.0,+200.0,+0.0,+0.0,+0.0"), None);
    assert_eq!(ask("ER").as_deref(), Some("2\r\n"));
    assert_eq!(ask("RS"), None);
    assert_eq!(ask("DR").as_deref(), Some("&H0005A,&H0000\r\n"));
}

/// Ctrl-C during a long motion over the line: the driver stops waiting and
/// sends nothing more (the unit finishes the line it has, robots.md), the
/// program ends (no handler catches it), stderr says where it was, exit 130.
fn sigint_stops_a_real_motion() {
    let Some(c) = controller("rv-m1", &["--time-scale", "1.0"]) else {
        return;
    };
    let dir = std::env::temp_dir().join(format!("adair-sigint-serial-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let script = dir.join("long.air");
    std::fs::write(
        &script,
        "InitRobot;\nSetVelocity (5.0);\nbegin\n   MoveAxesAbsolute ((Rad (150.0), 0.0, 0.0, 0.0, 0.0));\n\
         exception\n   when others => Put_Line (\"caught (wrong)\");\nend;\nPut_Line (\"went on (wrong)\");\n",
    )
    .unwrap();
    let child = Command::new(BIN)
        .args(["run", "--serial-timeout", "0.5", "--port", &c.path])
        .arg(&script)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Wait until the long motion's line has gone out.
    let t0 = std::time::Instant::now();
    while !c.received().iter().any(|l| l.starts_with("MJ +150.0")) {
        assert!(t0.elapsed() < Duration::from_secs(30), "{:?}", c.received());
        std::thread::sleep(Duration::from_millis(50));
    }
    std::thread::sleep(Duration::from_millis(300));
    let t = std::time::Instant::now();
    let _ = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status();
    let out = child.wait_with_output().unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    let (stdout, stderr) = (
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr),
    );
    assert!(
        t.elapsed() < Duration::from_secs(3),
        "took {:?}",
        t.elapsed()
    );
    assert_eq!(out.status.code(), Some(130), "{stdout}\n{stderr}");
    assert_eq!(stdout, "");
    assert!(
        stderr.contains("interrupted (Ctrl-C) at long.air:4 in MoveAxesAbsolute"),
        "{stderr}"
    );
    // Nothing was sent after the motion's ER.
    let sent = c.received();
    let mj = sent
        .iter()
        .position(|l| l.starts_with("MJ +150.0"))
        .unwrap();
    assert_eq!(&sent[mj + 1..], ["ER"], "{sent:?}");
}

/// `adair repl` on the controller's port (`--serial-timeout 0.5` and
/// `extra`), fed `input` on standard input; its whole output.
fn piped_repl(c: &Controller, extra: &[&str], input: &[u8]) -> std::process::Output {
    let mut child = Command::new(BIN)
        .args(["repl", "--serial-timeout", "0.5", "--port", &c.path])
        .args(extra)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child.stdin.take().unwrap().write_all(input).unwrap();
    child.wait_with_output().unwrap()
}

fn the_repl_jogs_a_real_arm() {
    let Some(c) = controller("rv-m1", &[]) else {
        return;
    };
    let out = piped_repl(
        &c,
        &["--strict"],
        b"InitRobot;\nMoveAxesRelative ((Rad (10.0), 0.0, 0.0, 0.0, 0.0));\n",
    );
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let sent = c.received();
    assert!(
        sent.iter().any(|l| l == "MJ +10.0,+0.0,+0.0,+0.0,+0.0"),
        "{sent:?}"
    );
}

/// `adair repl --port --rehearse`: each entry runs on the simulator from
/// the arm's pose first; an entry whose rehearsal raises moves nothing on
/// the arm (no motion line is sent, though its first motion was fine) and
/// changes none of the session's data (a variable, an object reached
/// through an access value); an entry that rehearses well moves the arm.
fn the_repl_rehearses_each_entry_before_the_arm_moves() {
    let Some(c) = controller("rv-m1", &[]) else {
        return;
    };
    let out = piped_repl(&c, &["--rehearse"], b"type Cell is access Integer;\n\
N : Integer := 0;\n\
C : Cell := new Integer'(0);\n\
InitRobot;\n\
N := N + 1; C.all := 7; MoveAxesRelative ((Rad (10.0), 0.0, 0.0, 0.0, 0.0)); MoveAxesAbsolute ((Rad (170.0), 0.0, 0.0, 0.0, 0.0));\n\
N\n\
C.all\n\
MoveAxesRelative ((Rad (-5.0), 0.0, 0.0, 0.0, 0.0));\n",);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.contains("rehearsal on the simulator failed: the arm was not moved"),
        "{stdout}"
    );
    assert!(stdout.contains("OUTOFREACH"), "{stdout}");
    // The refused entry changed nothing: N and C.all are still 0.
    let values: Vec<&str> = stdout
        .lines()
        .filter(|l| l.trim().parse::<i64>().is_ok())
        .collect();
    assert_eq!(values, ["0", "0"], "{stdout}");
    let sent = c.received();
    assert!(
        !sent.iter().any(|l| l.starts_with("MJ +10.0")),
        "the refused entry moved the arm: {sent:?}"
    );
    assert!(
        sent.iter().any(|l| l == "MJ -5.0,+0.0,+0.0,+0.0,+0.0"),
        "the good entry did not move the arm: {sent:?}"
    );
}

/// Every command each unit takes, from robots.md (not from the driver):
/// the RV-M1's D/U-M1 and the RM-501's Movemaster II unit. The RM-501's
/// `ER` is the probe at the start only (it puts it in error mode, which the
/// next line, `RS`, clears).
const RV_M1_COMMANDS: &[&str] = &[
    "NT", "OG", "MJ", "MP", "PD", "MO", "MS", "MC", "DW", "HE", "SP", "TL", "GO", "GC", "GP", "TI",
    "WH", "ER", "RS", "ID", "DR", "OD",
];
const RM_501_COMMANDS: &[&str] = &["MI", "PS", "MO", "NT", "HO", "OG", "SP", "GO", "GC", "RS"];

/// Every service of the handbook's appendix A, with every option (`Time`,
/// `Control`, `RealTime`, both move modes, opening and closing the hand
/// with and without a force), each in a block that reports an exception
/// and goes on.
const EVERY_SERVICE: &str = r#"
F, G : Frame;
A : AxesVector;
T : ToolDescriptor;
Arm : ArmConfig;
Elbow : ElbowConfig;
Hand : HandConfig;
Code : ErrorCode;
procedure Try (Step : String) is
begin
   Put_Line (Step & ": error status" & ErrorCode'Image (ValueErrorStatus));
end Try;
Name : constant String := "adair-every-service-paths.txt";
InitRobot;
CalibrateRobot;
SetVelocity (80.0);
SetMoveMode (JointInterpolated);
SetInterpolation (20.0);
SetRobotConfig (ArmForward, ElbowAbove, NoHandConfig);
ValueRobotConfig (Arm, Elbow, Hand);
ValueTool (T);
SetTool (T);
T := ValueTool;
MoveTool (20.0, 5.0);
MoveTool (Distance => 50.0, Force => 0.0);
MoveTool (10.0, 0.0);
MoveTool (60.0, 0.0);
MoveAxesAbsolute ((Rad (20.0), Rad (20.0), Rad (60.0), Rad (40.0), Rad (10.0)));
MoveAxesAbsolute ((Rad (25.0), Rad (20.0), Rad (60.0), Rad (40.0), Rad (10.0)), Time => 2.0);
MoveAxesRelative ((Rad (-5.0), Rad (5.0), 0.0, 0.0, Rad (-10.0)), Control => True);
A := ValueAxes;
ValueAxes (A);
MoveAxesRelative ((Rad (2.0), 0.0, 0.0, 0.0, 0.0), RealTime => True);
F := ValueFrameAbsolute;
ValueFrameAbsolute (G);
ValueFrameRelative (G);
G := ValueFrameRelative;
MoveFrameAbsolute (Trans (0.0, 0.0, -20.0) * F);
SetMoveMode (StraightLine);
MoveFrameAbsolute (F);
SetBase (Trans (10.0, 0.0, 0.0));
MoveFrameRelative (Trans (-10.0, 0.0, -20.0) * F, Time => 3.0);
SetBase (Identity);
G := F;
ValidFrame (G);
CreatePath (1);
InsertPosition (1, 1, F);
InsertPosition (1, 2, Trans (0.0, 0.0, -30.0) * F);
InsertPosition (1, 3, F);
DeletePosition (1, 3);
ValuePosition (1, 2, G);
MovePath (1);
SetMoveMode (JointInterpolated);
MovePath (1, Control => True);
ValueErrorStatus (Code);
SavePathSystem (Name);
DeletePath (1);
LoadPathSystem (Name);
MovePath (1, Time => 4.0);
begin
   TeachBox ("not on a pipe");
exception
   when CommandNotSupported => Try ("TeachBox");
end;
begin
   MoveAxesAbsolute ((Rad (170.0), 0.0, 0.0, 0.0, 0.0));
exception
   when OutOfReach => Try ("refused");
end;
EndRobot;
Put_Line ("done");
"#;

/// Drives every service against the virtual controller and fails on any
/// line outside the unit's command set: the RM-501 enters error mode on an
/// unknown command and never says so, so such a line would stop a real
/// arm while the program goes on.
fn only_commands_the_unit_knows(robot: &str, commands: &[&str]) {
    let Some(c) = controller(robot, &[]) else {
        return;
    };
    let dir = std::env::temp_dir().join(format!("adair-every-{robot}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("paths.txt");
    let script = EVERY_SERVICE.replace("adair-every-service-paths.txt", &file.to_string_lossy());
    let (o, out, _) = run(robot, Some(&c.path), &script);
    let _ = std::fs::remove_dir_all(&dir);
    assert!(matches!(o, Outcome::Ok), "{o:?}\n{out}");
    assert_eq!(
        out, "TeachBox: error status 350\nrefused: error status 180\ndone\n",
        "{robot}"
    );
    let sent = c.received();
    assert!(sent.len() > 30, "{sent:?}");
    for (i, line) in sent.iter().enumerate() {
        let code: String = line.chars().take(2).collect();
        let probe = i == 0 && code == "ER";
        assert!(
            probe || commands.contains(&code.as_str()),
            "{robot}: line {} `{line}` is not in the unit's command set; all lines: {sent:?}",
            i + 1
        );
    }
}

fn every_service_sends_only_rv_m1_commands() {
    only_commands_the_unit_knows("rv-m1", RV_M1_COMMANDS);
}

fn every_service_sends_only_rm_501_commands() {
    only_commands_the_unit_knows("rm-501", RM_501_COMMANDS);
}

/// The arm moved by hand while the program waits at `Get_Line` (handbook
/// 6.1: the operator jogs it with the unit's teach box): `ValueAxes` then
/// reads the jogged pose, an absolute move ends at its target (its `MJ`
/// undoes the jog exactly), and a relative move after a second jog is
/// relative to where the arm really is.
fn a_hand_jog_while_the_program_waits_is_seen() {
    let dir = std::env::temp_dir().join(format!("adair-handjog-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let control = dir.join("control");
    let control_arg = control.to_string_lossy().into_owned();
    let Some(c) = controller("rv-m1", &["--control", &control_arg]) else {
        return;
    };
    let script = dir.join("jogged.air");
    std::fs::write(
        &script,
        r#"procedure Show is
   A : constant AxesVector := ValueAxes;
begin
   for J in 1 .. 5 loop
      Put (Integer'Image (Integer (Deg (A (J)))));
   end loop;
   New_Line;
end Show;
procedure Wait is
   S : String (1 .. 80);
   L : Natural;
begin
   Put_Line ("jog now");
   Get_Line (S, L);
end Wait;
InitRobot;
MoveAxesAbsolute ((Rad (10.0), Rad (20.0), Rad (30.0), Rad (40.0), Rad (50.0)));
Wait;
Show;
MoveAxesAbsolute ((Rad (10.0), Rad (20.0), Rad (30.0), Rad (40.0), Rad (50.0)));
Show;
Wait;
MoveAxesRelative ((Rad (5.0), 0.0, 0.0, 0.0, 0.0));
Show;
"#,
    )
    .unwrap();
    let mut child = Command::new(BIN)
        .args(["run", "--serial-timeout", "0.5", "--port", &c.path])
        .arg(&script)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdin = child.stdin.take().unwrap();
    let stdout = child.stdout.take().unwrap();
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        for line in BufReader::new(stdout).lines() {
            let Ok(line) = line else { break };
            if tx.send(line).is_err() {
                break;
            }
        }
    });
    let mut seen = Vec::new();
    let mut jog = |deg: &str, seen: &mut Vec<String>| {
        loop {
            let line = rx
                .recv_timeout(Duration::from_secs(30))
                .expect("the program waits for input");
            let waiting = line == "jog now";
            seen.push(line);
            if waiting {
                break;
            }
        }
        let before = c.jogs();
        let mut f = std::fs::OpenOptions::new()
            .append(true)
            .open(&control)
            .unwrap();
        writeln!(f, "jog {deg}").unwrap();
        let t0 = std::time::Instant::now();
        while c.jogs() == before {
            assert!(t0.elapsed() < Duration::from_secs(10), "no hand jog logged");
            std::thread::sleep(Duration::from_millis(20));
        }
        stdin.write_all(b"\n").unwrap();
    };
    jog("+10.0,-5.0,+5.0,+0.0,+20.0", &mut seen);
    jog("+0.0,+0.0,+0.0,+10.0,+0.0", &mut seen);
    drop(stdin);
    let status = child.wait().unwrap();
    seen.extend(rx.iter());
    let _ = std::fs::remove_dir_all(&dir);
    assert!(status.success(), "{seen:?}");
    assert_eq!(
        seen,
        [
            "jog now",
            " 20 15 35 40 70",
            " 10 20 30 40 50",
            "jog now",
            " 15 20 30 50 50",
        ],
        "lines sent: {:?}",
        c.received()
    );
    assert!(
        c.received()
            .iter()
            .any(|l| l == "MJ -10.0,+5.0,-5.0,+0.0,-20.0"),
        "the absolute move does not undo the jog: {:?}",
        c.received()
    );
}

/// When nothing moves the arm but the program, the tracked joints stand
/// (the fresh `WH` agrees within its resolution), so 100 relative moves of
/// odd sizes end where their sum says, with no rounding drift.
fn no_rounding_drift_over_100_moves() {
    let Some(c) = controller("rv-m1", &[]) else {
        return;
    };
    let script = "
InitRobot;
MoveAxesAbsolute ((Rad (10.0), Rad (20.0), Rad (30.0), Rad (40.0), Rad (50.0)));
for I in 1 .. 100 loop
   MoveAxesRelative ((Rad (0.37), Rad (-0.13), Rad (0.21), Rad (-0.29), Rad (0.43)));
end loop;
";
    let (o, out, q) = run("rv-m1", Some(&c.path), script);
    assert!(matches!(o, Outcome::Ok), "{o:?}\n{out}");
    let want = [47.0, 7.0, 51.0, 11.0, 93.0];
    for (j, (got, want)) in q.iter().zip(want).enumerate() {
        // One decimal in MJ (0.05 deg) plus the read-back resolution.
        assert!(
            (got - want).abs() <= 0.05 + 0.025 + 1e-9,
            "J{}: {got} after 100 moves, not {want}: {q:?}",
            j + 1
        );
    }
    // The arm agrees: its last WH is the one of the target pose.
    let mj: Vec<String> = c
        .received()
        .into_iter()
        .filter(|l| l.starts_with("MJ"))
        .collect();
    let sum: f64 = mj[2..]
        .iter()
        .map(|l| l[3..].split(',').next().unwrap().parse::<f64>().unwrap())
        .sum();
    assert!((sum - 37.0).abs() < 1e-6, "J1 sent {sum} in all: {mj:?}");
}

/// `Time =>` on a real arm: the driver picks the speed level whose motion
/// ends closest below the stated time, and the service returns at that
/// time. The unit's own time is read from its byte log (the `MJ` line to
/// the `ER` reply, which comes when the arm stops).
fn a_timed_motion_ends_at_its_time_on_the_arm() {
    let Some(c) = controller("rv-m1", &["--time-scale", "1.0"]) else {
        return;
    };
    let script = "
InitRobot;
declare
   Start : constant Ada.Calendar.Time := Ada.Calendar.Clock;
   Took : Duration;
begin
   MoveAxesAbsolute ((Rad (60.0), 0.0, 0.0, 0.0, 0.0), Time => 2.0);
   Took := Ada.Calendar.\"-\" (Ada.Calendar.Clock, Start);
   Put_Line (Boolean'Image (Took >= 2.0 and Took < 2.4));
end;
";
    let (o, out, q) = run("rv-m1", Some(&c.path), script);
    assert!(matches!(o, Outcome::Ok), "{o:?}\n{out}");
    assert_eq!(out, "TRUE\n");
    assert!((q[0] - 60.0).abs() < 0.05, "{q:?}");
    let log = std::fs::read_to_string(&c.log).unwrap();
    let stamp = |l: &str| l.split_whitespace().next().unwrap().parse::<f64>().unwrap();
    let lines: Vec<&str> = log.lines().collect();
    let mj = lines
        .iter()
        .position(|l| l.contains(" < ") && l.contains("MJ +60.0"))
        .unwrap_or_else(|| panic!("the motion was not sent: {log}"));
    // The unit receives lines as they come (several to a log line): the
    // speed level in force is the last `SP` before the motion.
    let before: String = lines[..=mj].join("\n");
    let upto = &before[..before.find("MJ +60.0").unwrap()];
    let sp = &upto[upto
        .rfind("SP ")
        .expect("a speed level before the timed motion")..];
    let sp = &sp[..sp.find('\\').unwrap_or(sp.len())];
    let reply = lines[mj + 1..]
        .iter()
        .find(|l| l.contains(" > 0"))
        .unwrap_or_else(|| panic!("no ER reply after the motion: {log}"));
    let unit = stamp(reply) - stamp(lines[mj]);
    eprintln!("Time => 2.0: the unit took {unit:.3} s at `{sp}`");
    // J1 60 deg at 120 deg/s: level 2 (2/9 of the speed) takes 2.25 s, too
    // long; level 3 takes 1.5 s: the unit is done 0.5 s early and the
    // service waits out the rest.
    assert_eq!(sp, "SP 3", "{log}");
    assert!((1.4..=2.0).contains(&unit), "the unit took {unit} s");
}

/// `Control => True` on a real arm: the service returns once the line is
/// sent, the program computes while the arm moves, and the next service
/// (here `ValueAxes`) waits for the motion's end before it reads the pose.
fn a_control_motion_returns_at_once_and_the_next_service_waits() {
    let Some(c) = controller("rv-m1", &["--time-scale", "1.0"]) else {
        return;
    };
    let script = "
InitRobot;
declare
   Start : constant Ada.Calendar.Time := Ada.Calendar.Clock;
   Sent, Read : Duration;
   A : AxesVector;
begin
   MoveAxesAbsolute ((Rad (60.0), 0.0, 0.0, 0.0, 0.0), Control => True);
   Sent := Ada.Calendar.\"-\" (Ada.Calendar.Clock, Start);
   A := ValueAxes;
   Read := Ada.Calendar.\"-\" (Ada.Calendar.Clock, Start);
   Put_Line (Boolean'Image (Sent < 0.3) & Boolean'Image (Read > 0.8) & Integer'Image (Integer (Deg (A (1)))));
end;
";
    let (o, out, _) = run("rv-m1", Some(&c.path), script);
    assert!(matches!(o, Outcome::Ok), "{o:?}\n{out}");
    // J1 60 deg at level 5 (5/9 of 120 deg/s): 0.9 s on the unit.
    assert_eq!(out, "TRUETRUE 60\n");
}

/// The REPL on a real arm says which arm is connected on which port (and
/// `--rehearse` when it is on) in `:where`, as the banner does.
fn the_repl_names_the_arm_and_its_port() {
    for (robot, rehearse) in [("rv-m1", true), ("rm-501", false)] {
        let Some(c) = controller(robot, &[]) else {
            return;
        };
        let mut args = vec![
            "repl",
            "--robot",
            robot,
            "--serial-timeout",
            "0.5",
            "--port",
            &c.path,
        ];
        if rehearse {
            args.push("--rehearse");
        }
        let mut child = Command::new(BIN)
            .args(&args)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        child
            .stdin
            .take()
            .unwrap()
            .write_all(b":where\nInitRobot\n:where\n")
            .unwrap();
        let out = child.wait_with_output().unwrap();
        let stdout = String::from_utf8_lossy(&out.stdout);
        let name = robot.to_ascii_uppercase();
        let arm = format!(
            "robot: {name} on {} (serial, 9600 baud){}",
            c.path,
            if rehearse { ", --rehearse" } else { "" }
        );
        assert!(
            stdout.contains(&format!("{arm} (not initialised)\n")),
            "{stdout}"
        );
        assert!(stdout.contains(&format!("{arm}\n")), "{stdout}");
    }
}

/// A stand-in for the operator at the screen pendant: jogs by each of
/// `deltas` (degrees), reading the arm's pose first as the pendant does,
/// and keeps what each jog answered.
struct Operator {
    deltas: Vec<[f64; 5]>,
    answers: std::rc::Rc<std::cell::RefCell<Vec<Result<(), String>>>>,
}

impl adair::services::Pendant for Operator {
    fn teach(
        &mut self,
        st: &mut adair::services::RobotState,
        clock: &mut dyn adair::interp::Clock,
        _text: &str,
        _refresh: bool,
        _clear: bool,
    ) -> Result<(), String> {
        for d in &self.deltas {
            adair::services::fresh_pose(st)?;
            let mut q = st.robot.joints();
            for j in 0..5 {
                q[j] += d[j].to_radians();
            }
            let r = adair::services::jog(st, clock, q);
            self.answers.borrow_mut().push(r);
        }
        Ok(())
    }
}

/// `adair repl --port --rehearse`: `:teach` is not rehearsed on the
/// stand-in simulator (it failed there: the stand-in has no pendant); it
/// runs on the arm, and each jog is checked against the limits before it
/// is sent: the good ones move the arm (their `MJ` lines), the one beyond
/// J3's lower limit sends nothing. The jogs are in `:record`. A `TeachBox`
/// typed as an entry is refused in its rehearsal, saying why.
fn the_repl_teaches_a_real_arm_with_rehearse() {
    let Some(c) = controller("rv-m1", &[]) else {
        return;
    };
    let out = SharedBuf::default();
    let o2 = out.clone();
    let mut repl = adair::repl::Repl::new(
        Box::new(move || Box::new(o2.clone()) as Box<dyn Write>),
        false,
    );
    repl.drive(adair::repl::Drive {
        port: Some(PortSettings {
            path: c.path.clone(),
            baud: 9600,
            timeout: 0.5,
        }),
        rehearse: true,
        ..Default::default()
    })
    .unwrap();
    let r = repl.entry("InitRobot;");
    assert!(!r.failed, "{}", r.text);
    let answers = std::rc::Rc::new(std::cell::RefCell::new(Vec::new()));
    repl.session.install_pendant(Box::new(Operator {
        deltas: vec![
            [10.0, 0.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, -5.0, 0.0, 0.0],
            [0.0, 5.0, 0.0, 0.0, 0.0],
        ],
        answers: answers.clone(),
    }));
    let before = c.received().len();
    let r = repl.entry("TeachBox (\"jog\");");
    assert!(
        r.failed && r.text.contains("the TeachBox cannot be rehearsed"),
        "{}",
        r.text
    );
    assert!(answers.borrow().is_empty());
    let r = repl.entry(":teach");
    assert!(!r.failed, "{}", r.text);
    let a = answers.borrow().clone();
    assert!(a[0].is_ok() && a[2].is_ok(), "{a:?}");
    assert!(a[1].as_ref().is_err_and(|e| e.contains("joint 3")), "{a:?}");
    let sent = c.received();
    let moves: Vec<&String> = sent[before..]
        .iter()
        .filter(|l| l.starts_with("MJ"))
        .collect();
    assert_eq!(
        moves,
        [
            "MJ +10.0,+0.0,+0.0,+0.0,+0.0",
            "MJ +0.0,+5.0,+0.0,+0.0,+0.0"
        ],
        "{sent:?}"
    );
    let csv = std::env::temp_dir().join(format!("adair-teach-{}.csv", std::process::id()));
    let r = repl.entry(&format!(":record {}", csv.display()));
    assert!(!r.failed, "{}", r.text);
    let text = std::fs::read_to_string(&csv).unwrap();
    let _ = std::fs::remove_file(&csv);
    let rows: Vec<Vec<f64>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    // The J1 jog's way (0 to 10 degrees) and the J2 jog's end.
    assert!(
        rows.iter().any(|r| r[1] > 1.0 && r[1] < 9.0),
        "the jog is not recorded: {text}"
    );
    let last = rows.last().unwrap();
    assert!(
        (last[1] - 10.0).abs() < 1e-6 && (last[2] - 5.0).abs() < 1e-6,
        "{text}"
    );
}

/// `adair run --rehearse` of a program that opens the `TeachBox`: its
/// rehearsal says the box cannot be rehearsed (not that it needs a
/// terminal), and no motion command is sent.
fn a_teachbox_program_fails_its_rehearsal_saying_why() {
    let Some(c) = controller("rv-m1", &[]) else {
        return;
    };
    let script =
        std::env::temp_dir().join(format!("adair-teach-rehearse-{}.air", std::process::id()));
    std::fs::write(&script, "InitRobot;\nTeachBox (\"jog\");\n").unwrap();
    let out = Command::new(BIN)
        .args([
            "run",
            "--port",
            &c.path,
            "--serial-timeout",
            "0.5",
            "--rehearse",
        ])
        .arg(&script)
        .output()
        .unwrap();
    let _ = std::fs::remove_file(&script);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(err.contains("the TeachBox cannot be rehearsed"), "{err}");
    assert!(err.contains("the arm was not moved"), "{err}");
    let sent = c.received();
    assert!(
        sent.iter()
            .all(|l| ["ER", "RS", "WH"].contains(&l.as_str()) || l.starts_with("TL")),
        "{sent:?}"
    );
}

/// The REPL's rehearsal stands in for the real arm too: an entry that
/// calls `PlaceObject` fails its rehearsal with `CommandNotSupported` and
/// sends no motion line, though its first motion was fine.
fn the_repl_rehearsal_refuses_a_simulator_only_service() {
    let Some(c) = controller("rv-m1", &[]) else {
        return;
    };
    let out = piped_repl(
        &c,
        &["--rehearse"],
        b"InitRobot;\nMoveAxesRelative ((Rad (10.0), 0.0, 0.0, 0.0, 0.0)); PlaceObject (30.0);\n",
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.contains("COMMANDNOTSUPPORTED")
            && stdout.contains("rehearsal on the simulator failed: the arm was not moved"),
        "{stdout}"
    );
    let sent = c.received();
    assert!(
        !sent.iter().any(|l| l.starts_with("MJ +10.0")),
        "the refused entry moved the arm: {sent:?}"
    );
}

/// A pose whose tool elevation `p = 90 - (J2 + J3 + J4)` lies beyond -180
/// degrees: the unit reports it wrapped by a turn, which is the same pose,
/// so the fresh `WH` agrees and the joints stand.
fn a_wrapped_tool_elevation_is_the_same_pose() {
    let Some(c) = controller("rv-m1", &[]) else {
        return;
    };
    let script = "
InitRobot;
MoveAxesAbsolute ((0.0, Rad (100.0), Rad (110.0), Rad (90.0), Rad (30.0)));
declare
   A : constant AxesVector := ValueAxes;
begin
   for J in 1 .. 5 loop
      Put (Integer'Image (Integer (Deg (A (J)))));
   end loop;
   New_Line;
end;
";
    let (o, out, _) = run("rv-m1", Some(&c.path), script);
    assert!(matches!(o, Outcome::Ok), "{o:?}\n{out}");
    assert_eq!(out, " 0 100 110 90 30\n", "{:?}", c.received());
}

/// The operator jogs the arm to a joint limit (the unit's teach box stops
/// there): `WH`, rounded to 0.1 mm, gives a pose whose joints come out a
/// rounding past the limit. That is the limit, not `MessageInvalid`.
fn a_hand_jog_to_a_limit_reads_the_limit() {
    // InitRobot is 11 lines, the motion WH MJ ER: jog after its ER.
    let Some(c) = controller("rv-m1", &["--jog-after", "14:+0.0,+0.0,+0.0,+10.0,+0.0"]) else {
        return;
    };
    let script = "
InitRobot;
MoveAxesAbsolute ((0.0, Rad (100.0), Rad (110.0), Rad (80.0), Rad (30.0)));
declare
   A : constant AxesVector := ValueAxes;
begin
   for J in 1 .. 5 loop
      Put (Integer'Image (Integer (Deg (A (J)))));
   end loop;
   New_Line;
end;
";
    let (o, out, _) = run("rv-m1", Some(&c.path), script);
    assert!(matches!(o, Outcome::Ok), "{o:?}\n{out}");
    assert_eq!(out, " 0 100 110 90 30\n", "{:?}", c.received());
}

fn main() {
    let tests: &[(&str, fn())] = &[
        (
            "a_hand_jog_to_a_limit_reads_the_limit",
            a_hand_jog_to_a_limit_reads_the_limit,
        ),
        (
            "a_wrapped_tool_elevation_is_the_same_pose",
            a_wrapped_tool_elevation_is_the_same_pose,
        ),
        (
            "the_repl_rehearsal_refuses_a_simulator_only_service",
            the_repl_rehearsal_refuses_a_simulator_only_service,
        ),
        (
            "a_control_motion_returns_at_once_and_the_next_service_waits",
            a_control_motion_returns_at_once_and_the_next_service_waits,
        ),
        (
            "a_hand_jog_while_the_program_waits_is_seen",
            a_hand_jog_while_the_program_waits_is_seen,
        ),
        (
            "no_rounding_drift_over_100_moves",
            no_rounding_drift_over_100_moves,
        ),
        (
            "a_timed_motion_ends_at_its_time_on_the_arm",
            a_timed_motion_ends_at_its_time_on_the_arm,
        ),
        (
            "every_service_sends_only_rv_m1_commands",
            every_service_sends_only_rv_m1_commands,
        ),
        (
            "every_service_sends_only_rm_501_commands",
            every_service_sends_only_rm_501_commands,
        ),
        (
            "a_rehearsal_refuses_a_simulator_only_service",
            a_rehearsal_refuses_a_simulator_only_service,
        ),
        (
            "the_repl_rehearses_each_entry_before_the_arm_moves",
            the_repl_rehearses_each_entry_before_the_arm_moves,
        ),
        (
            "same_joints_on_the_simulator_and_over_the_line_rv_m1",
            same_joints_on_the_simulator_and_over_the_line_rv_m1,
        ),
        (
            "same_joints_on_the_simulator_and_over_the_line_rm_501",
            same_joints_on_the_simulator_and_over_the_line_rm_501,
        ),
        (
            "a_silent_unit_is_message_lost",
            a_silent_unit_is_message_lost,
        ),
        (
            "a_garbled_reply_is_message_invalid",
            a_garbled_reply_is_message_invalid,
        ),
        (
            "error_mode_one_is_command_not_supported_and_reset",
            error_mode_one_is_command_not_supported_and_reset,
        ),
        (
            "error_mode_two_is_out_of_reach_and_reset",
            error_mode_two_is_out_of_reach_and_reset,
        ),
        (
            "a_refused_motion_leaves_the_joints_where_the_arm_is",
            a_refused_motion_leaves_the_joints_where_the_arm_is,
        ),
        (
            "a_hang_up_is_fatal_then_no_connection",
            a_hang_up_is_fatal_then_no_connection,
        ),
        (
            "slow_replies_within_the_timeout_work",
            slow_replies_within_the_timeout_work,
        ),
        (
            "slow_replies_beyond_the_timeout_are_no_robot",
            slow_replies_beyond_the_timeout_are_no_robot,
        ),
        (
            "a_missing_port_is_no_connection_naming_it",
            a_missing_port_is_no_connection_naming_it,
        ),
        (
            "a_unit_that_never_answers_is_no_robot_installed",
            a_unit_that_never_answers_is_no_robot_installed,
        ),
        (
            "an_rv_m1_where_an_rm_501_is_expected_is_wrong_robot",
            an_rv_m1_where_an_rm_501_is_expected_is_wrong_robot,
        ),
        (
            "a_failed_rehearsal_sends_no_motion",
            a_failed_rehearsal_sends_no_motion,
        ),
        (
            "adair_test_runs_golden_scripts_on_the_arm",
            adair_test_runs_golden_scripts_on_the_arm,
        ),
        ("golden_lines_rv_m1", golden_lines_rv_m1),
        ("golden_lines_rm_501", golden_lines_rm_501),
        (
            "golden_lines_straight_line_rv_m1",
            golden_lines_straight_line_rv_m1,
        ),
        (
            "the_controller_speaks_the_units_language",
            the_controller_speaks_the_units_language,
        ),
        ("the_repl_jogs_a_real_arm", the_repl_jogs_a_real_arm),
        (
            "the_repl_names_the_arm_and_its_port",
            the_repl_names_the_arm_and_its_port,
        ),
        (
            "the_repl_teaches_a_real_arm_with_rehearse",
            the_repl_teaches_a_real_arm_with_rehearse,
        ),
        (
            "a_teachbox_program_fails_its_rehearsal_saying_why",
            a_teachbox_program_fails_its_rehearsal_saying_why,
        ),
        ("sigint_stops_a_real_motion", sigint_stops_a_real_motion),
    ];
    let ptys = nix::pty::openpty(None, None).is_ok();
    if !ptys {
        eprintln!(
            "serial tests: this OS has no pseudo-terminals, so the {} tests below are IGNORED",
            tests.len()
        );
    }
    common::run_fns(tests, !ptys);
}
