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

/// `adair run --realtime --record r.csv` stopped by Ctrl-C in the middle of
/// a motion: the CSV holds that motion up to where the arm stopped (its
/// last row is the pose stderr names), not only the motions before it.
#[test]
fn sigint_during_a_recorded_motion_keeps_it_up_to_the_stop() {
    let dir = std::env::temp_dir().join(format!("adair-sigint-rec-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let script = dir.join("long.air");
    let csv = dir.join("r.csv");
    std::fs::write(
        &script,
        "InitRobot;\nMoveAxesAbsolute ((0.2, 0.0, 0.0, 0.0, 0.0), Time => 0.5);\n\
         Put_Line (\"started\");\n\
         MoveAxesAbsolute ((2.0, 0.0, 0.0, 0.0, 0.0), Time => 30.0);\n\
         Put_Line (\"went on (wrong)\");\n",
    )
    .unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_adair"))
        .arg("run")
        .arg("--realtime")
        .arg("--record")
        .arg(&csv)
        .arg(&script)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Wait for the second motion to be under way.
    let mut line = String::new();
    std::io::BufRead::read_line(
        &mut std::io::BufReader::new(child.stdout.as_mut().unwrap()),
        &mut line,
    )
    .unwrap();
    assert_eq!(line, "started\n");
    std::thread::sleep(Duration::from_millis(1000));
    let status = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(status.success());
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(130), "{stderr}");
    let text = std::fs::read_to_string(&csv).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    let rows: Vec<Vec<f64>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    let stopped_j1: f64 = stderr
        .split("stopped at (")
        .nth(1)
        .and_then(|r| r.split(',').next())
        .and_then(|x| x.trim().parse().ok())
        .unwrap_or_else(|| panic!("{stderr}"));
    let last = rows.last().unwrap();
    // t, j1 ...: the last row is the stop, about a second into the motion.
    assert!((last[1] - stopped_j1).abs() < 0.01, "{last:?}\n{stderr}");
    assert!(last[0] > 0.5 + 0.5 && last[0] < 0.5 + 10.0, "{last:?}");
    assert!(stopped_j1 > 0.2f64.to_degrees() + 1.0, "{stderr}");
    // The stopped motion is sampled all the way (a long one at even
    // intervals of a few tens of ms), in order.
    let during = rows.iter().filter(|r| r[0] > 0.5 + 1e-9).count();
    assert!(during >= 10, "{during} rows for {} s", last[0] - 0.5);
    for w in rows.windows(2) {
        assert!(w[1][0] >= w[0][0], "time goes back: {w:?}");
        assert!(w[1][0] - w[0][0] < 0.1, "a gap: {w:?}");
    }
}

/// Runs `adair run --realtime` on `text`, waits for its first line of
/// output, sends SIGINT `ms` later, and returns the exit status and stderr.
fn interrupt_after_start(name: &str, text: &str, ms: u64) -> (Option<i32>, String) {
    let dir = std::env::temp_dir().join(format!("adair-sigint-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let script = dir.join(format!("{name}.air"));
    std::fs::write(&script, text).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_adair"))
        .arg("run")
        .arg("--realtime")
        .arg(&script)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut line = String::new();
    std::io::BufRead::read_line(
        &mut std::io::BufReader::new(child.stdout.as_mut().unwrap()),
        &mut line,
    )
    .unwrap();
    assert_eq!(line, "go\n");
    std::thread::sleep(Duration::from_millis(ms));
    let status = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(status.success());
    let out = child.wait_with_output().unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Ctrl-C in a script whose library-level task runs on after the script's
/// statements: the report names the user's file, where the main program
/// waited (the end of its last statement) and where the task was, never
/// the predefined library (it said `stdlib/ada.air:1:1`).
#[test]
fn sigint_with_tasks_names_where_the_main_program_was() {
    let (code, stderr) = interrupt_after_start(
        "tasks_end",
        "task T;\ntask body T is\nbegin\n   loop\n      delay 0.1;\n   end loop;\nend T;\n\
         Put_Line (\"go\");\n",
        500,
    );
    assert_eq!(code, Some(130), "{stderr}");
    assert!(!stderr.contains("stdlib"), "{stderr}");
    assert!(
        stderr
            .contains("tasks_end.air:8:17: error[E0903]: interrupted (Ctrl-C): every task stopped"),
        "{stderr}"
    );
    assert!(stderr.contains("the main program was here"), "{stderr}");
    assert!(
        stderr.contains("main waits for its tasks to end"),
        "{stderr}"
    );
    assert!(stderr.contains("T runs"), "{stderr}");
    // T was stopped at its loop's head (the loop is shown), not where it
    // last waited (its delay).
    assert!(stderr.contains("end loop;"), "{stderr}");
    // In a block, the main program waits at the block's end.
    let (code, stderr) = interrupt_after_start(
        "tasks_block",
        "Put_Line (\"go\");\ndeclare\n   task T;\n   task body T is\n   begin\n      loop\n         \
         delay 0.1;\n      end loop;\n   end T;\nbegin\n   null;\nend;\n",
        500,
    );
    assert_eq!(code, Some(130), "{stderr}");
    assert!(
        stderr.contains(
            "tasks_block.air:12:1: error[E0903]: interrupted (Ctrl-C): every task stopped"
        ),
        "{stderr}"
    );
    assert!(stderr.contains("T runs"), "{stderr}");
}

/// Starts `adair run` on `text` (its first line of output must be `go`),
/// then sends SIGINT once per entry of `gaps` (waiting that many ms
/// before each) and returns the exit status, stdout after `go`, stderr and
/// the time from the last SIGINT to the end.
fn interrupt_times(
    name: &str,
    text: &str,
    gaps: &[u64],
) -> (Option<i32>, String, String, Duration) {
    let dir = std::env::temp_dir().join(format!("adair-sigint-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let script = dir.join(format!("{name}.air"));
    std::fs::write(&script, text).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_adair"))
        .arg("run")
        .arg(&script)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdout = std::io::BufReader::new(child.stdout.take().unwrap());
    let mut line = String::new();
    std::io::BufRead::read_line(&mut stdout, &mut line).unwrap();
    assert_eq!(line, "go\n");
    let mut last = Instant::now();
    for ms in gaps {
        std::thread::sleep(Duration::from_millis(*ms));
        if child.try_wait().unwrap().is_some() {
            break;
        }
        let status = Command::new("kill")
            .args(["-INT", &child.id().to_string()])
            .status()
            .unwrap();
        assert!(status.success());
        last = Instant::now();
    }
    // At most 10 s more: a run that does not end is killed and fails.
    while child.try_wait().unwrap().is_none() {
        if last.elapsed() > Duration::from_secs(10) {
            let _ = child.kill();
            break;
        }
        std::thread::sleep(Duration::from_millis(10));
    }
    let took = last.elapsed();
    let mut rest = String::new();
    let _ = std::io::Read::read_to_string(&mut stdout, &mut rest);
    let out = child.wait_with_output().unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    (
        out.status.code(),
        rest,
        String::from_utf8_lossy(&out.stderr).into_owned(),
        took,
    )
}

/// A recursion that recurses again from its `Storage_Error` handler polls
/// no loop: Ctrl-C is seen at a call, and the `Program_Error` it raises
/// passes the handlers for `Storage_Error`: the run ends (exit 130). It
/// did not end at all.
#[test]
fn sigint_ends_a_recursion_that_recurses_again_from_its_handler() {
    let (code, _, stderr, took) = interrupt_times(
        "recurse",
        "procedure P is\nbegin\n   P;\nexception\n   when Storage_Error => P;\nend P;\n\
         Put_Line (\"go\");\nP;\n",
        &[300],
    );
    assert_eq!(code, Some(130), "{stderr}");
    assert!(took < Duration::from_secs(5), "took {took:?}");
    assert!(
        stderr.contains("PROGRAM_ERROR : interrupted (Ctrl-C)"),
        "{stderr}"
    );
}

/// Ctrl-C always wins: a program that catches the first one (its
/// `Program_Error`) with `when others` and goes on, in a busy loop or in
/// a recursion, ends at the second at once with exit 130.
#[test]
fn a_second_sigint_ends_the_run_at_once_whatever_it_catches() {
    let (code, out, stderr, took) = interrupt_times(
        "busy",
        "Put_Line (\"go\");\nloop\n   begin\n      loop\n         null;\n      end loop;\n   \
         exception\n      when others => Put_Line (\"caught\");\n   end;\nend loop;\n",
        &[300, 500],
    );
    assert_eq!(code, Some(130), "{out}\n{stderr}");
    assert!(out.starts_with("caught\n"), "the first was caught: {out}");
    assert!(took < Duration::from_secs(2), "took {took:?}");
    let (code, _, stderr, took) = interrupt_times(
        "recurse_others",
        "procedure P is\nbegin\n   P;\nexception\n   when others => P;\nend P;\n\
         Put_Line (\"go\");\nP;\n",
        &[300, 500],
    );
    assert_eq!(code, Some(130), "{stderr}");
    assert!(took < Duration::from_secs(2), "took {took:?}");
}

/// A recursion of quick calls (calls and returns the engine's inner loop
/// makes itself, see `vm/fast.rs`) polls no loop either: Ctrl-C is seen at
/// a call, there too. Without the stop check of the inner loop's calls,
/// `F (60)` ran on (for years).
#[test]
fn sigint_ends_a_recursion_of_quick_calls() {
    let (code, _, stderr, took) = interrupt_times(
        "quick_calls",
        "function F (N : Integer) return Integer is\nbegin\n   if N < 2 then\n      return N;\n   \
         end if;\n   return F (N - 1) + F (N - 2);\nend F;\n\
         Put_Line (\"go\");\nPut_Line (Integer'Image (F (60)));\n",
        &[300],
    );
    assert_eq!(code, Some(130), "{stderr}");
    assert!(took < Duration::from_secs(5), "took {took:?}");
    assert!(
        stderr.contains("PROGRAM_ERROR : interrupted (Ctrl-C)"),
        "{stderr}"
    );
}
