//! Terminal tests: the real binary under tmux, driven by keystrokes.
//!
//! Without tmux these tests are reported as ignored, with a message saying
//! why; `ADAIR_REQUIRE_TMUX=1` (set by `.ci/run`, which installs tmux) makes
//! a missing tmux a failure instead, so CI always runs them.
#![allow(clippy::print_stderr)]

mod common;

use std::process::Command;
use std::time::{Duration, Instant};

struct Tmux {
    name: String,
}

impl Tmux {
    fn start(name: &str, cmd: &str) -> Tmux {
        // One session per test run: two runs at once (two checkouts, two
        // engineers) share the tmux server, and a fixed name let each
        // kill the other's session.
        let name = &format!("{name}-{}", std::process::id());
        let _ = Command::new("tmux")
            .args(["kill-session", "-t", name])
            .output();
        let ok = Command::new("tmux")
            .args([
                "new-session",
                "-d",
                "-s",
                name,
                "-x",
                "150",
                "-y",
                "45",
                cmd,
            ])
            .status()
            .expect("tmux must be installed (apt-get install -y tmux)");
        assert!(ok.success(), "tmux new-session failed");
        Tmux {
            name: name.to_string(),
        }
    }
    fn keys(&self, keys: &[&str]) {
        for k in keys {
            // Key names are sent as keys, everything else literally (a `;`
            // would otherwise end the tmux command).
            let special = matches!(
                *k,
                "Enter" | "Tab" | "Escape" | "C-c" | "C-d" | "Up" | "Down" | "Left" | "Right"
            );
            let mut args = vec!["send-keys", "-t", &self.name];
            if !special {
                args.push("-l");
            }
            // tmux reads an argument that ends in `;` as a command separator: `\;` is the character.
            let escaped = match k.strip_suffix(';') {
                Some(rest) if !special => format!("{rest}\\;"),
                _ => k.to_string(),
            };
            args.push(&escaped);
            let ok = Command::new("tmux").args(&args).status().expect("tmux");
            assert!(ok.success());
            std::thread::sleep(Duration::from_millis(60));
        }
    }
    fn screen(&self) -> String {
        let out = Command::new("tmux")
            .args(["capture-pane", "-p", "-t", &self.name])
            .output()
            .expect("tmux");
        String::from_utf8_lossy(&out.stdout).into_owned()
    }
    /// Waits until one of the screen's lines is exactly one of `lines`
    /// (blanks around it aside), and returns the screen.
    fn wait_for_line(&self, lines: &[&str]) -> String {
        let start = Instant::now();
        loop {
            let s = self.screen();
            if s.lines().any(|l| lines.contains(&l.trim())) {
                return s;
            }
            assert!(
                start.elapsed() < Duration::from_secs(20),
                "timed out waiting for a line {lines:?}; screen:\n{s}"
            );
            std::thread::sleep(Duration::from_millis(100));
        }
    }
    /// Waits until the screen shows `text`, and returns the screen.
    fn wait_for(&self, text: &str) -> String {
        let start = Instant::now();
        loop {
            let s = self.screen();
            if s.contains(text) {
                return s;
            }
            assert!(
                start.elapsed() < Duration::from_secs(20),
                "timed out waiting for {text:?}; screen:\n{s}"
            );
            std::thread::sleep(Duration::from_millis(100));
        }
    }
}

impl Drop for Tmux {
    fn drop(&mut self) {
        let _ = Command::new("tmux")
            .args(["kill-session", "-t", &self.name])
            .output();
    }
}

fn script(name: &str, text: &str) -> String {
    let dir = std::env::temp_dir().join(format!("adair-term-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let p = dir.join(name);
    std::fs::write(&p, text).expect("script");
    p.to_string_lossy().into_owned()
}

fn teachbox_jogs_refuses_at_limits_stores_and_returns() {
    let prog = script(
        "teach.air",
        "InitRobot;\nTeachBox (\"Jog J1, then store\");\nPut_Line (\"after: J1 =\" & Float'Image (Deg (ValueAxes (1))));\ndeclare\n   F : Frame;\nbegin\n   ValuePosition (1, 1, F);\n   Put_Line (\"stored:\" & Float'Image (F (3, 4)));\nend;\n",
    );
    let t = Tmux::start(
        "adair-teach",
        &format!("{} run {prog}; sleep 60", env!("CARGO_BIN_EXE_adair")),
    );
    t.wait_for("AdaIR teach box");
    t.keys(&["q", "q"]);
    let s = t.wait_for("J1    10.00 [");
    assert!(s.contains("side view") && s.contains("top view"), "{s}");
    // The grip force after InitRobot is InitToolForce, as ValueTool says.
    assert!(s.contains("hand 60.0 mm, 10.0 N"), "{s}");
    // J3 is at its lower limit 0 deg: a jog down is refused and nothing moves.
    t.keys(&["d"]);
    let s = t.wait_for("J3 is at its lower limit 0.0 deg");
    assert!(s.contains("J3 -5 deg refused"), "{s}");
    assert!(s.contains("J3     0.00 ["), "{s}");
    // `p` says what it stored: where, the TCP and the joints.
    t.keys(&["p"]);
    let s = t.wait_for("stored as position 1 of path 1:");
    assert!(s.contains("TCP (0.0, 0.0, 889.0) mm"), "{s}");
    assert!(s.contains("J (10.0, 0.0, 0.0, 0.0, 0.0) deg"), "{s}");
    t.keys(&["x"]);
    let s = t.wait_for("stored:");
    assert!(s.contains("after: J1 = 1.00000E+01"), "{s}");
    assert!(s.contains("stored: 8.89000E+02"), "{s}");
}

/// Issue 37: a refused jog says what the step would pass and what is
/// left (it said "J3 at its limit" 4 degrees away); the arrow keys choose
/// a joint and jog it; `}` never offers a position past the path's end
/// (it offered position 4 of a 2-position path).
fn teachbox_says_what_is_left_jogs_with_arrows_and_keeps_positions_in_the_path() {
    let prog = script(
        "teach_left.air",
        "InitRobot;\nMoveAxesAbsolute ((0.0, 0.0, Rad (106.0), 0.0, 0.0));\nTeachBox (\"limits and arrows\");\nPut_Line (\"after: J3 =\" & Integer'Image (Integer (Deg (ValueAxes (3)))));\n",
    );
    let t = Tmux::start(
        "adair-teachleft",
        &format!("{} run {prog}; sleep 60", env!("CARGO_BIN_EXE_adair")),
    );
    t.wait_for("limits and arrows");
    // Step 10 deg: J3 at 106 deg, its upper limit 110 deg.
    t.keys(&["+", "e"]);
    let s = t.wait_for("J3 +10 deg would pass its upper limit 110.0 deg:");
    assert!(s.contains("4.0 deg left"), "{s}");
    assert!(s.contains("J3   106.00 ["), "{s}");
    // e chose J3; Down, Up move the choice (>), Left and Right jog it.
    assert!(s.contains(">J3   106.00 ["), "{s}");
    t.keys(&["Up", "Up"]);
    t.wait_for(">J1     0.00 [");
    t.keys(&["Right"]);
    t.wait_for(">J1    10.00 [");
    t.keys(&["Down", "Down", "Left"]);
    t.wait_for(">J3    96.00 [");
    // Two positions; `}` at the end stays at the end and says so; `{`
    // goes back to position 2, `}` from there to the end again.
    t.keys(&["p", "p"]);
    t.wait_for("path 1: 2 positions, store at the end");
    t.keys(&["}", "}"]);
    let s = t.wait_for("store at the end already: path 1 has 2 positions");
    assert!(s.contains("store at the end"), "{s}");
    t.keys(&["{"]);
    t.wait_for("store at position 2");
    t.keys(&["}", "}", "}"]);
    let s = t.wait_for("store at the end already");
    assert!(!s.contains("store at position 3"), "{s}");
    t.keys(&["{", "{", "{", "{"]);
    let s = t.wait_for("store at position 1");
    assert!(!s.contains("store at position 0"), "{s}");
    t.keys(&["x"]);
    t.wait_for("after: J3 = 96");
}

fn repl_multiline_completion_and_values() {
    let t = Tmux::start(
        "adair-repl",
        &format!("{} repl; sleep 60", env!("CARGO_BIN_EXE_adair")),
    );
    t.wait_for("adair>");
    // A multi-line entry continues until the parser sees it complete.
    t.keys(&["for I in 1 .. 3 loop", "Enter"]);
    // ... at its own prompt.
    t.wait_for("   ...>");
    t.keys(&["Put (Integer'Image (I));", "Enter"]);
    t.keys(&["end loop;", "Enter"]);
    t.wait_for(" 1 2 3");
    // Tab completes a service name.
    t.keys(&["InitRob", "Tab"]);
    t.keys(&["Enter"]);
    t.keys(&["ValueFrameAbsol", "Tab", "Enter"]);
    let s = t.wait_for("889.0000");
    assert!(s.contains("1.0000"), "{s}");
    // Tab on an ambiguous name completes the common part; Tab again lists
    // the candidates.
    t.keys(&["MoveFrame", "Tab", "Tab"]);
    let s = t.wait_for("MoveFrameRelative");
    assert!(s.contains("MoveFrameAbsolute"), "{s}");
    t.keys(&["C-c"]);
    t.keys(&[":quit", "Enter"]);
}

/// `:load ex` + Tab completes a file name of the current folder, as a
/// shell does (only Ada sources and folders: `extra.txt` is not offered).
fn repl_load_completes_file_names() {
    let dir = std::env::temp_dir().join(format!("adair-term-load-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    std::fs::write(
        dir.join("example.air"),
        "Put_Line (\"from the example\");\n",
    )
    .expect("script");
    std::fs::write(dir.join("extra.txt"), "not Ada\n").expect("text");
    let t = Tmux::start(
        "adair-load",
        &format!(
            "cd '{}' && {} repl; sleep 60",
            dir.display(),
            env!("CARGO_BIN_EXE_adair")
        ),
    );
    t.wait_for("adair>");
    t.keys(&[":load ex", "Tab"]);
    t.wait_for(":load example.air");
    t.keys(&["Enter"]);
    let s = t.wait_for_line(&["loaded example.air"]);
    assert!(s.lines().any(|l| l.trim() == "from the example"), "{s}");
    t.keys(&[":quit", "Enter"]);
    let _ = std::fs::remove_dir_all(&dir);
}

/// A one-line entry without its final `;` runs at once; an open `loop`
/// continues, and an empty line ends a continuation no line can mend.
fn repl_forgiving_continuation() {
    let t = Tmux::start(
        "adair-forgive",
        &format!("{} repl; sleep 60", env!("CARGO_BIN_EXE_adair")),
    );
    t.wait_for("adair>");
    t.keys(&["X : Integer := 3", "Enter"]);
    t.wait_for("added");
    t.keys(&["X * 14", "Enter"]);
    let s = t.wait_for_line(&["42"]);
    assert!(!s.contains("...>"), "{s}");
    let last = s.lines().rev().find(|l| !l.trim().is_empty()).unwrap_or("");
    assert_eq!(last.trim_end(), "adair>", "{s}");
    // An open loop continues at the continuation prompt.
    t.keys(&["for I in 1 .. 2 loop", "Enter"]);
    t.wait_for("   ...>");
    t.keys(&["W : Integer := 1 begin", "Enter"]);
    let s = t.screen();
    assert!(!s.contains("error["), "ended too early:\n{s}");
    // An empty line ends it: the error is shown and the main prompt is back.
    t.keys(&["Enter"]);
    let s = t.wait_for("error[");
    let last = s.lines().rev().find(|l| !l.trim().is_empty()).unwrap_or("");
    assert_eq!(last.trim_end(), "adair>", "{s}");
    t.keys(&[":quit", "Enter"]);
}

fn repl_ctrl_c_stops_a_running_entry_and_keeps_state() {
    let t = Tmux::start(
        "adair-ctrlc",
        &format!("{} repl; sleep 60", env!("CARGO_BIN_EXE_adair")),
    );
    t.wait_for("adair>");
    t.keys(&["Kept : Integer := 7;", "Enter"]);
    t.keys(&["loop null; end loop;", "Enter"]);
    std::thread::sleep(Duration::from_millis(500));
    t.keys(&["C-c"]);
    t.wait_for("interrupted");
    t.keys(&["Kept * 6", "Enter"]);
    t.wait_for("42");
    t.keys(&["C-d"]);
}

/// Ctrl-C always wins: an entry that catches the first Ctrl-C ends the
/// REPL at the second (exit 130).
fn repl_second_ctrl_c_ends_an_entry_that_caught_the_first() {
    let t = Tmux::start(
        "adair-ctrlc2",
        &format!(
            "{} repl; echo \"exit status $?\"; sleep 60",
            env!("CARGO_BIN_EXE_adair")
        ),
    );
    t.wait_for("adair>");
    t.keys(&[
        "loop begin loop null; end loop; exception when others => Put_Line (\"caught\"); end; end loop;",
        "Enter",
    ]);
    std::thread::sleep(Duration::from_millis(500));
    t.keys(&["C-c"]);
    t.wait_for("caught");
    t.keys(&["C-c"]);
    t.wait_for("exit status 130");
}

fn repl_ctrl_c_stops_a_long_motion_where_it_is() {
    let t = Tmux::start(
        "adair-motion",
        &format!("{} repl; sleep 60", env!("CARGO_BIN_EXE_adair")),
    );
    t.wait_for("adair>");
    t.keys(&["InitRobot;", "Enter"]);
    t.keys(&[
        "MoveAxesAbsolute ((2.0, 0.0, 0.0, 0.0, 0.0), Time => 20.0, RealTime => True);",
        "Enter",
    ]);
    std::thread::sleep(Duration::from_millis(1500));
    t.keys(&["C-c"]);
    t.wait_for("the robot stopped at");
    // The robot is where the motion was stopped: J1 between 0 and 2 rad.
    t.keys(&["J : Float := ValueAxes (1);", "Enter"]);
    t.keys(&["J > 0.0 and J < 1.0", "Enter"]);
    // The reply is a line of its own: `True` in the typed `RealTime => True`
    // or in the input line does not count.
    let s = t.wait_for_line(&["True", "False"]);
    assert!(s.lines().any(|l| l.trim() == "True"), "{s}");
    assert!(!s.lines().any(|l| l.trim() == "False"), "{s}");
}

fn repl_completes_record_fields() {
    let t = Tmux::start(
        "adair-fields",
        &format!("{} repl; sleep 60", env!("CARGO_BIN_EXE_adair")),
    );
    t.wait_for("adair>");
    t.keys(&["InitRobot;", "Enter"]);
    t.keys(&["T : ToolDescriptor := ValueTool;", "Enter"]);
    t.keys(&["T.ForceMa", "Tab", "Enter"]);
    t.wait_for("T.ForceMax");
    t.wait_for("30.0");
}

fn repl_teach_opens_the_teachbox_and_the_repl_reads_the_new_pose() {
    let t = Tmux::start(
        "adair-replteach",
        &format!("{} repl; sleep 60", env!("CARGO_BIN_EXE_adair")),
    );
    t.wait_for("adair>");
    t.keys(&["InitRobot;", "Enter"]);
    t.keys(&[":teach jog J1 twice", "Enter"]);
    t.wait_for("jog J1 twice");
    t.keys(&["q", "q"]);
    t.wait_for("J1    10.00 [");
    t.keys(&["x"]);
    t.wait_for("adair>");
    t.keys(&["Deg (ValueAxes (1))", "Enter"]);
    // The REPL reads the pose the TeachBox left: J1 at 10 degrees.
    t.wait_for("adair> Deg (ValueAxes (1))\n10.0\n");
}

/// The banner says which arm the REPL drives: here the simulated RM-501
/// (it said "a simulated RV-M1" whatever the robot or the port).
fn repl_banner_names_the_arm() {
    let t = Tmux::start(
        "adair-banner",
        &format!(
            "{} repl --robot rm-501; sleep 60",
            env!("CARGO_BIN_EXE_adair")
        ),
    );
    t.wait_for("AdaIR on a simulated RM-501.");
    t.keys(&[":quit", "Enter"]);
}

/// A virtual controller (`adair sim-controller`) on a pseudo-terminal,
/// killed by its own pid when dropped.
struct Unit {
    child: std::process::Child,
    path: String,
    log: std::path::PathBuf,
}

impl Unit {
    fn start() -> Unit {
        use std::io::BufRead;
        let log = std::env::temp_dir().join(format!("adair-term-unit-{}.log", std::process::id()));
        let mut child = Command::new(env!("CARGO_BIN_EXE_adair"))
            .args(["sim-controller", "--time-scale", "0.02", "--log"])
            .arg(&log)
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::null())
            .spawn()
            .expect("adair sim-controller");
        let mut line = String::new();
        let out = child.stdout.take().expect("stdout");
        let _ = std::io::BufReader::new(out).read_line(&mut line);
        assert!(line.starts_with("/dev/"), "sim-controller: {line:?}");
        Unit {
            child,
            path: line.trim().to_string(),
            log,
        }
    }
    /// The lines the unit received.
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

impl Drop for Unit {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
        let _ = std::fs::remove_file(&self.log);
    }
}

/// `adair repl --port P --rehearse` on a (virtual) arm: the banner names
/// the arm and its port; `:teach` opens the pendant (it used to be refused:
/// its rehearsal on the stand-in simulator had no pendant), and each jog
/// moves the real arm, one `MJ` line each.
fn repl_teach_moves_a_real_arm_with_rehearse() {
    let unit = Unit::start();
    let t = Tmux::start(
        "adair-realteach",
        &format!(
            "{} repl --port {} --rehearse; sleep 60",
            env!("CARGO_BIN_EXE_adair"),
            unit.path
        ),
    );
    t.wait_for(&format!(
        "AdaIR on the RV-M1 on {} (serial, 9600 baud), --rehearse",
        unit.path
    ));
    t.keys(&["InitRobot", "Enter"]);
    t.keys(&[":teach jog the real arm", "Enter"]);
    t.wait_for("jog the real arm");
    t.keys(&["q"]);
    t.wait_for("J1     5.00 [");
    t.keys(&["q"]);
    t.wait_for("J1    10.00 [");
    t.keys(&["x"]);
    t.keys(&[":where", "Enter"]);
    let s = t.wait_for("TCP frame:");
    assert!(s.contains("J1 =    0.1745 rad    10.000 deg"), "{s}");
    let jogs: Vec<String> = unit
        .received()
        .into_iter()
        .filter(|l| l.starts_with("MJ +5.0"))
        .collect();
    assert_eq!(
        jogs,
        ["MJ +5.0,+0.0,+0.0,+0.0,+0.0"; 2],
        "{:?}",
        unit.received()
    );
}

/// `--trace` while the pendant is open: the jogs' trace lines are held and
/// written when it closes; written over the pendant they corrupted its
/// screen (seen: J1 shown as 0.00 while it was at 10.00). In the REPL (the
/// trace on standard output) and in `adair run` (on standard error).
fn trace_lines_never_overwrite_the_teachbox() {
    let prog = script(
        "teach_trace.air",
        "InitRobot;\nTeachBox (\"traced jogs\");\nPut_Line (\"after the box\");\n",
    );
    for (name, cmd, open) in [
        ("adair-tracerepl", "repl --trace".to_string(), true),
        ("adair-tracerun", format!("run --trace {prog}"), false),
    ] {
        let t = Tmux::start(
            name,
            &format!("{} {cmd}; sleep 60", env!("CARGO_BIN_EXE_adair")),
        );
        if open {
            t.wait_for("adair>");
            t.keys(&["InitRobot", "Enter"]);
            t.keys(&[":teach traced jogs", "Enter"]);
        }
        t.wait_for("traced jogs");
        t.keys(&["q"]);
        t.wait_for("J1     5.00 [");
        t.keys(&["q"]);
        let s = t.wait_for("J1    10.00 [");
        // Give a trace line time to arrive, then look again.
        std::thread::sleep(Duration::from_millis(300));
        let s2 = t.screen();
        for s in [&s, &s2] {
            assert!(
                !s.contains("TeachBox jog"),
                "{cmd}: a trace line on the pendant:\n{s}"
            );
            assert!(s.contains("J1    10.00 ["), "{cmd}:\n{s}");
        }
        t.keys(&["x"]);
        let s = t.wait_for("TeachBox jog: (5.00, 0.00, 0.00, 0.00, 0.00) -> (10.00,");
        assert!(
            s.contains("TeachBox jog: (0.00, 0.00, 0.00, 0.00, 0.00) -> (5.00,"),
            "{s}"
        );
    }
}

/// tasks.md: another task that moves the arm while the TeachBox is open
/// meets `RobotBusy` (it used to wait, then move); a motion after the box
/// has closed works.
fn another_tasks_motion_while_the_teachbox_is_open_is_robot_busy() {
    let prog = script(
        "teach_busy.air",
        "task Other is\n   entry Go;\nend Other;\n\ntask body Other is\nbegin\n   accept Go;\n   delay 0.2;\n   begin\n      MoveAxesRelative ((Rad (1.0), 0.0, 0.0, 0.0, 0.0));\n      Put_Line (\"Other moved\");\n   exception\n      when RobotBusy => Put_Line (\"Other: RobotBusy\");\n   end;\n   delay 600.0;\n   MoveAxesRelative ((Rad (1.0), 0.0, 0.0, 0.0, 0.0));\n   Put_Line (\"Other moved later, J1 =\" & Integer'Image (Integer (Deg (ValueAxes (1)))));\nend Other;\n\nInitRobot;\nOther.Go;\nTeachBox (\"busy\");\nPut_Line (\"box closed\");\n",
    );
    let t = Tmux::start(
        "adair-busy",
        &format!("{} run {prog}; sleep 60", env!("CARGO_BIN_EXE_adair")),
    );
    t.wait_for("busy");
    t.keys(&["q"]);
    t.wait_for("J1     5.00 [");
    // The operator keeps the box open for a while.
    std::thread::sleep(Duration::from_millis(500));
    t.keys(&["x"]);
    let s = t.wait_for("Other moved later");
    assert!(s.contains("Other: RobotBusy"), "{s}");
    assert!(!s.contains("Other moved\n"), "{s}");
    assert!(s.contains("Other moved later, J1 = 6"), "{s}");
}

/// Ctrl-C at the pendant leaves it, as `x` does, and moves nothing (it was
/// taken as `c` and closed the hand, which on a real arm grips whatever is
/// between the jaws).
fn ctrl_c_leaves_the_teachbox_and_moves_nothing() {
    let prog = script(
        "teach_ctrl_c.air",
        "InitRobot;\nTeachBox (\"press Ctrl-C\");\nPut_Line (\"left with the hand at\" & Integer'Image (Integer (ValueTool.CurrDist)));\n",
    );
    let t = Tmux::start(
        "adair-teachctrlc",
        &format!("{} run {prog}; sleep 60", env!("CARGO_BIN_EXE_adair")),
    );
    t.wait_for("press Ctrl-C");
    t.keys(&["C-c"]);
    t.wait_for("left with the hand at 60");
}

fn tmux_available() -> bool {
    Command::new("tmux")
        .arg("-V")
        .output()
        .is_ok_and(|o| o.status.success())
}

fn main() {
    let tests: &[(&str, fn())] = &[
        (
            "teachbox_jogs_refuses_at_limits_stores_and_returns",
            teachbox_jogs_refuses_at_limits_stores_and_returns,
        ),
        (
            "teachbox_says_what_is_left_jogs_with_arrows_and_keeps_positions_in_the_path",
            teachbox_says_what_is_left_jogs_with_arrows_and_keeps_positions_in_the_path,
        ),
        (
            "repl_multiline_completion_and_values",
            repl_multiline_completion_and_values,
        ),
        (
            "repl_load_completes_file_names",
            repl_load_completes_file_names,
        ),
        ("repl_forgiving_continuation", repl_forgiving_continuation),
        (
            "repl_ctrl_c_stops_a_running_entry_and_keeps_state",
            repl_ctrl_c_stops_a_running_entry_and_keeps_state,
        ),
        (
            "repl_second_ctrl_c_ends_an_entry_that_caught_the_first",
            repl_second_ctrl_c_ends_an_entry_that_caught_the_first,
        ),
        (
            "repl_ctrl_c_stops_a_long_motion_where_it_is",
            repl_ctrl_c_stops_a_long_motion_where_it_is,
        ),
        ("repl_completes_record_fields", repl_completes_record_fields),
        (
            "repl_teach_opens_the_teachbox_and_the_repl_reads_the_new_pose",
            repl_teach_opens_the_teachbox_and_the_repl_reads_the_new_pose,
        ),
        ("repl_banner_names_the_arm", repl_banner_names_the_arm),
        (
            "repl_teach_moves_a_real_arm_with_rehearse",
            repl_teach_moves_a_real_arm_with_rehearse,
        ),
        (
            "trace_lines_never_overwrite_the_teachbox",
            trace_lines_never_overwrite_the_teachbox,
        ),
        (
            "another_tasks_motion_while_the_teachbox_is_open_is_robot_busy",
            another_tasks_motion_while_the_teachbox_is_open_is_robot_busy,
        ),
        (
            "ctrl_c_leaves_the_teachbox_and_moves_nothing",
            ctrl_c_leaves_the_teachbox_and_moves_nothing,
        ),
    ];
    let have_tmux = tmux_available();
    let required = std::env::var_os("ADAIR_REQUIRE_TMUX").is_some();
    if !have_tmux {
        if required {
            eprintln!("terminal tests: ADAIR_REQUIRE_TMUX is set but tmux is not installed");
            std::process::exit(1);
        }
        eprintln!(
            "terminal tests: tmux is not installed, so the {} tests below are IGNORED \
             (apt-get install -y tmux to run them; CI does)",
            tests.len()
        );
    }
    common::run_fns(tests, !have_tmux);
}
