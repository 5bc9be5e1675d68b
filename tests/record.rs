//! `adair run --record FILE.csv|FILE.json` through the real binary.

use std::path::{Path, PathBuf};
use std::process::Command;

/// Moves to a frame, draws a 60 mm line, opens the jaws, prints the final
/// TCP and joints, then fails with an unhandled exception (unreachable frame).
const SCRIPT: &str = r#"F : Frame;
A : AxesVector;
InitRobot;
MoveFrameAbsolute (((-1.0, 0.0, 0.0, 280.0), (0.0, 1.0, 0.0, 0.0), (0.0, 0.0, -1.0, 150.0)));
SetMoveMode (StraightLine);
MoveFrameAbsolute (((-1.0, 0.0, 0.0, 280.0), (0.0, 1.0, 0.0, 60.0), (0.0, 0.0, -1.0, 150.0)));
MoveTool (20.0, 5.0);
F := ValueFrameAbsolute;
A := ValueAxes;
Put_Line (Float'Image (F (1, 4)) & Float'Image (F (2, 4)) & Float'Image (F (3, 4)));
Put_Line (Float'Image (A (1)) & Float'Image (A (2)) & Float'Image (A (3)) & Float'Image (A (4)) & Float'Image (A (5)));
MoveFrameAbsolute (((-1.0, 0.0, 0.0, 5000.0), (0.0, 1.0, 0.0, 0.0), (0.0, 0.0, -1.0, 150.0)));
"#;

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("adair-record-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn run(d: &Path, out: &str) -> std::process::Output {
    let script = d.join("t.air");
    std::fs::write(&script, SCRIPT).unwrap();
    Command::new(env!("CARGO_BIN_EXE_adair"))
        .arg("run")
        .arg(&script)
        .arg("--record")
        .arg(d.join(out))
        .output()
        .unwrap()
}

fn floats(line: &str) -> Vec<f64> {
    line.split_whitespace()
        .map(|w| w.parse().unwrap())
        .collect()
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

/// The rows of the CSV; checks the header and the final pose against what
/// the script printed.
fn check_csv(text: &str, stdout: &str) -> Vec<Vec<f64>> {
    let mut lines = text.lines();
    // Each column with its unit (issue 37: the header had none).
    assert_eq!(
        lines.next(),
        Some("t_s,j1_deg,j2_deg,j3_deg,j4_deg,j5_deg,x_mm,y_mm,z_mm,grip_mm")
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert!(rows.len() > 10, "{} rows", rows.len());
    assert!(rows.iter().all(|r| r.len() == 10));
    // No row repeats the one before it: InitRobot's motion takes no time
    // and the next motion starts where it ended (it began with three equal
    // rows at t = 0), nor does a motion repeat the end of the one before.
    for w in rows.windows(2) {
        assert_ne!(w[0], w[1], "a repeated row");
    }
    assert_eq!(rows.iter().filter(|r| r[0] == 0.0).count(), 1, "{rows:?}");
    for w in rows.windows(2) {
        assert!(
            w[1][0] >= w[0][0],
            "time goes back: {:?} -> {:?}",
            w[0],
            w[1]
        );
    }
    let mut out = stdout.lines();
    let tcp = floats(out.next().unwrap());
    let axes = floats(out.next().unwrap());
    let last = rows.last().unwrap();
    for i in 0..3 {
        assert!(close(last[6 + i], tcp[i], 0.05), "{last:?} vs {tcp:?}");
    }
    for i in 0..5 {
        assert!(
            close(last[1 + i], axes[i].to_degrees(), 0.01),
            "{last:?} vs {axes:?}"
        );
    }
    assert!(close(last[9], 20.0, 1e-6), "gripper {last:?}");
    // The straight line: y runs from 0 to 60 at x = 280, z = 150.
    assert!(
        rows.iter()
            .any(|r| close(r[7], 30.0, 1.5) && close(r[6], 280.0, 0.5))
    );
    rows
}

#[test]
fn csv_is_written_even_when_the_run_ends_with_an_exception() {
    let d = dir("csv");
    let o = run(&d, "m.csv");
    assert_eq!(o.status.code(), Some(1), "{o:?}");
    let text = std::fs::read_to_string(d.join("m.csv")).unwrap();
    check_csv(&text, &String::from_utf8_lossy(&o.stdout));
}

#[test]
fn json_has_the_same_rows_as_csv() {
    let d = dir("json");
    let c = run(&d, "m.csv");
    let rows = check_csv(
        &std::fs::read_to_string(d.join("m.csv")).unwrap(),
        &String::from_utf8_lossy(&c.stdout),
    );
    let j = run(&d, "m.json");
    assert_eq!(j.status.code(), Some(1));
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("m.json")).unwrap()).unwrap();
    let arr = v.as_array().unwrap();
    assert_eq!(arr.len(), rows.len());
    let keys = ["t", "j1", "j2", "j3", "j4", "j5", "x", "y", "z", "grip"];
    for (o, r) in arr.iter().zip(&rows) {
        for (k, x) in keys.iter().zip(r) {
            assert!(close(o[k].as_f64().unwrap(), *x, 1e-9), "{k}: {o} vs {r:?}");
        }
    }
}

#[test]
fn a_missing_directory_is_refused_before_running() {
    let d = dir("missing");
    let o = run(&d, "no/such/dir/m.csv");
    assert_eq!(o.status.code(), Some(2));
    assert!(o.stdout.is_empty(), "the program ran: {o:?}");
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("--record") && err.contains("does not exist"),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1, "{err}");
}

#[test]
fn an_unwritable_file_is_one_error_line() {
    let d = dir("unwritable");
    std::fs::create_dir_all(d.join("m.csv")).unwrap();
    let o = run(&d, "m.csv");
    assert_eq!(o.status.code(), Some(2), "{o:?}");
    let err = String::from_utf8_lossy(&o.stderr);
    let rec: Vec<&str> = err.lines().filter(|l| l.contains("--record")).collect();
    assert_eq!(rec.len(), 1, "{err}");
}

/// A program that does not check runs nothing, so `--record` and `--plot`
/// leave an existing file as it was (it may be the last good run's).
#[test]
fn a_check_error_leaves_an_existing_recording_alone() {
    let d = dir("check_error");
    let script = d.join("bad.air");
    std::fs::write(&script, "InitRobot;\nMoveTool (Nowhere, 1.0);\n").unwrap();
    for name in ["keep.csv", "keep.json", "keep.svg"] {
        let out = d.join(name);
        std::fs::write(&out, "the last good run\n").unwrap();
        let flag = if name.ends_with(".svg") {
            "--plot"
        } else {
            "--record"
        };
        let o = Command::new(env!("CARGO_BIN_EXE_adair"))
            .arg("run")
            .arg(&script)
            .arg(flag)
            .arg(&out)
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(2), "{o:?}");
        assert_eq!(
            std::fs::read_to_string(&out).unwrap(),
            "the last good run\n",
            "{flag} {name} was written although nothing ran"
        );
    }
    let _ = std::fs::remove_dir_all(&d);
}

/// `--record` to a FIFO or a directory is refused before the program runs
/// (nothing is written into the pipe, and the run does not block on it).
#[test]
#[allow(clippy::print_stdout)] // says when it is skipped
fn a_recording_to_a_fifo_is_refused_before_running() {
    let d = dir("fifo");
    let fifo = d.join("m.csv");
    let _ = std::fs::remove_file(&fifo);
    let made = Command::new("mkfifo").arg(&fifo).status();
    if !made.is_ok_and(|s| s.success()) {
        println!("skipped: no mkfifo");
        return;
    }
    let script = d.join("t.air");
    std::fs::write(&script, SCRIPT).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_adair"))
        .arg("run")
        .arg(&script)
        .arg("--record")
        .arg(&fifo)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let start = std::time::Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > std::time::Duration::from_secs(20) {
            let _ = child.kill();
            let _ = child.wait();
            let _ = std::fs::remove_dir_all(&d);
            panic!("adair run --record FIFO blocked");
        }
        std::thread::sleep(std::time::Duration::from_millis(50));
    }
    let o = child.wait_with_output().unwrap();
    let kind = std::fs::symlink_metadata(&fifo).unwrap().file_type();
    let _ = std::fs::remove_dir_all(&d);
    assert_eq!(o.status.code(), Some(2), "{o:?}");
    assert!(o.stdout.is_empty(), "the program ran: {o:?}");
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("--record") && err.contains("FIFO"), "{err}");
    use std::os::unix::fs::FileTypeExt;
    assert!(kind.is_fifo());
}

/// Runs `adair [GLOBAL] run SCRIPT --record OUT` on `text`.
fn run_text(d: &Path, text: &str, out: &str, global: &[&str]) -> std::process::Output {
    let script = d.join("long.air");
    std::fs::write(&script, text).unwrap();
    Command::new(env!("CARGO_BIN_EXE_adair"))
        .args(global)
        .arg("run")
        .arg(&script)
        .arg("--record")
        .arg(d.join(out))
        .output()
        .unwrap()
}

/// A motion as long as `Duration'Last` (or at a velocity of 1.0E-6) is
/// sampled at even intervals, at most a few thousand samples, its start
/// and end kept: it was sampled every 20 ms, hundreds of billions of rows,
/// and the run aborted allocating them.
#[test]
fn a_very_long_motion_is_thinned_not_sampled_for_ever() {
    let d = dir("long_motion");
    for (what, motion) in [
        (
            "Time => Duration'Last",
            "MoveAxesRelative ((0.5, 0.0, 0.0, 0.0, 0.0), Time => Duration'Last);",
        ),
        (
            "SetVelocity (1.0E-6)",
            "SetVelocity (1.0E-6);\nMoveAxesRelative ((0.5, 0.0, 0.0, 0.0, 0.0));",
        ),
    ] {
        let text = format!(
            "A : AxesVector;\nInitRobot;\n{motion}\nA := ValueAxes;\n\
             Put_Line (Float'Image (A (1)));\n"
        );
        let o = run_text(&d, &text, "m.csv", &[]);
        assert_eq!(o.status.code(), Some(0), "{what}: {o:?}");
        let csv = std::fs::read_to_string(d.join("m.csv")).unwrap();
        let rows: Vec<Vec<f64>> = csv
            .lines()
            .skip(1)
            .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
            .collect();
        assert!(
            (100..=5_000).contains(&rows.len()),
            "{what}: {} rows",
            rows.len()
        );
        let j1 = floats(&String::from_utf8_lossy(&o.stdout))[0].to_degrees();
        let last = rows.last().unwrap();
        assert!(
            close(last[1], j1, 0.01),
            "{what}: ends at {last:?}, not {j1}"
        );
        assert!(last[0] > 1.0e6, "{what}: the end's time {}", last[0]);
        // Evenly spaced in time (after the rows of InitRobot at 0 s).
        let moving: Vec<f64> = rows.iter().map(|r| r[0]).filter(|t| *t > 0.0).collect();
        let gaps: Vec<f64> = moving.windows(2).map(|w| w[1] - w[0]).collect();
        let (lo, hi) = gaps
            .iter()
            .fold((f64::MAX, 0.0f64), |(lo, hi), g| (lo.min(*g), hi.max(*g)));
        assert!(hi <= lo * 1.01 + 1e-3, "{what}: gaps from {lo} to {hi}");
    }
    let _ = std::fs::remove_dir_all(&d);
}

/// The recording counts against `--max-memory`: 2,000 motions of 40 s
/// (4 million samples, 320 MB) under a limit of 32M thin the recording
/// (every other sample, the ends kept) instead of aborting the run.
#[test]
fn a_recording_past_max_memory_is_thinned_not_fatal() {
    let d = dir("max_memory");
    let text = "InitRobot;\nfor K in 1 .. 1_000 loop\n   \
                MoveAxesRelative ((0.5, 0.0, 0.0, 0.0, 0.0), Time => 40.0);\n   \
                MoveAxesRelative ((-0.5, 0.0, 0.0, 0.0, 0.0), Time => 40.0);\n\
                end loop;\nPut_Line (\"done\");\n";
    let o = run_text(&d, text, "m.csv", &["--max-memory", "32M"]);
    assert_eq!(o.status.code(), Some(0), "{o:?}");
    assert_eq!(String::from_utf8_lossy(&o.stdout), "done\n");
    let csv = std::fs::read_to_string(d.join("m.csv")).unwrap();
    let rows: Vec<Vec<f64>> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    let _ = std::fs::remove_dir_all(&d);
    assert!(rows.len() > 1_000, "{} rows", rows.len());
    assert!(rows.len() < 2_000_000, "{} rows", rows.len());
    assert_eq!(rows[0][0], 0.0);
    assert!(
        close(rows.last().unwrap()[0], 80_000.0, 1.0),
        "{:?}",
        rows.last()
    );
    for w in rows.windows(2) {
        assert!(w[1][0] >= w[0][0], "time goes back: {w:?}");
    }
}
