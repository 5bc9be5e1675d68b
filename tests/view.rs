//! `--view`, the 3D view, through the real binary, without a browser: the
//! replay page carries what `--record` writes, the live stream carries
//! every motion in order, bad paths are refused before the run.
//! (The pages in a real browser: tests/view_browser.rs.)

use std::io::{BufRead, BufReader, Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// Moves to a frame, stores two path positions, draws a 60 mm line, closes
/// the jaws, then fails: an unreachable frame (unhandled exception).
const SCRIPT: &str = r#"Put_Line ("started");
InitRobot;
MoveFrameAbsolute (((-1.0, 0.0, 0.0, 280.0), (0.0, 1.0, 0.0, 0.0), (0.0, 0.0, -1.0, 150.0)));
CreatePath (1);
InsertPosition (1, 1, ValueFrameAbsolute);
SetMoveMode (StraightLine);
MoveFrameAbsolute (((-1.0, 0.0, 0.0, 280.0), (0.0, 1.0, 0.0, 60.0), (0.0, 0.0, -1.0, 150.0)));
InsertPosition (1, 2, ValueFrameAbsolute);
MoveTool (20.0, 5.0);
MoveFrameAbsolute (((-1.0, 0.0, 0.0, 5000.0), (0.0, 1.0, 0.0, 0.0), (0.0, 0.0, -1.0, 150.0)));
"#;

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("adair-view-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn adair() -> Command {
    Command::new(env!("CARGO_BIN_EXE_adair"))
}

fn script(d: &Path) -> PathBuf {
    let p = d.join("cell.air");
    std::fs::write(&p, SCRIPT).unwrap();
    p
}

/// The text of the page's `<script>` element with this id.
fn element<'a>(page: &'a str, id: &str) -> &'a str {
    let at = page
        .find(&format!("id=\"{id}\">"))
        .unwrap_or_else(|| panic!("no element {id}"));
    let rest = &page[at..];
    let open = rest.find('>').unwrap() + 1;
    let close = rest.find("</script>").unwrap();
    &rest[open..close]
}

#[test]
fn the_replay_page_carries_what_record_writes() {
    let d = dir("replay");
    let s = script(&d);
    for robot in ["rv-m1", "rm-501"] {
        let (page, csv) = (
            d.join(format!("{robot}.html")),
            d.join(format!("{robot}.csv")),
        );
        let out = adair()
            .args(["run", "--robot", robot, "--view"])
            .arg(&page)
            .arg("--record")
            .arg(&csv)
            .arg(&s)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(1), "{out:?}");
        let page = std::fs::read_to_string(&page).unwrap();
        let csv = std::fs::read_to_string(&csv).unwrap();
        assert!(csv.lines().count() > 50, "{csv}");
        assert_eq!(element(&page, "adair-record"), csv, "{robot}");
        assert_eq!(adair::view::embedded_record(&page), Some(csv.as_str()));
        // The scene: the robot, both path positions, the refused goal and
        // the message at the time it was raised.
        let scene: serde_json::Value = serde_json::from_str(element(&page, "adair-scene")).unwrap();
        let name = if robot == "rv-m1" { "RV-M1" } else { "RM-501" };
        assert_eq!(scene["robot"]["name"], name);
        assert_eq!(scene["paths"].as_array().unwrap().len(), 2, "{scene}");
        let end = &scene["end"];
        assert!(
            end["exception"].as_str().unwrap().contains("OUTOFREACH"),
            "{end}"
        );
        assert_eq!(end["goal"][0][3], 5000.0, "{end}");
        let last_t: f64 = csv
            .lines()
            .last()
            .unwrap()
            .split(',')
            .next()
            .unwrap()
            .parse()
            .unwrap();
        assert!(
            (end["t"].as_f64().unwrap() - last_t).abs() < 1e-3,
            "{end} {last_t}"
        );
        // Self-contained: three and the page's code are in it, nothing is
        // loaded from elsewhere.
        assert!(page.contains("var THREE="), "three is inlined");
        assert!(page.contains("window.adairView"), "view.js is inlined");
        for needle in ["src=\"http", "src='http", "import(", "href=\"http"] {
            assert!(!page.contains(needle), "the page loads {needle}");
        }
    }
}

#[test]
fn a_robot_file_is_drawn_with_its_own_links() {
    let d = dir("robotfile");
    let s = script(&d);
    let text = adair::kinematics::RobotDescription::builtin_text("rv-m1")
        .unwrap()
        .replace("l2 = 250.0", "l2 = 270.0")
        .replace("name = \"RV-M1\"", "name = \"Long arm\"");
    let file = d.join("long.toml");
    std::fs::write(&file, text).unwrap();
    let page = d.join("long.html");
    let out = adair()
        .args(["run", "--robot-file"])
        .arg(&file)
        .arg("--view")
        .arg(&page)
        .arg(&s)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1), "{out:?}");
    let page = std::fs::read_to_string(&page).unwrap();
    let scene: serde_json::Value = serde_json::from_str(element(&page, "adair-scene")).unwrap();
    assert_eq!(scene["robot"]["name"], "Long arm");
    assert_eq!(scene["robot"]["links"]["l2"], 270.0);
}

#[test]
fn a_bad_view_path_is_exit_2_before_the_run() {
    let d = dir("bad");
    let s = script(&d);
    let missing = d.join("no/such/dir/run.html");
    let cases: [(PathBuf, &str); 3] = [
        (missing, "does not exist"),
        (d.join("run.txt"), ".html"),
        (d.clone(), "must end in .html"),
    ];
    for (p, why) in cases {
        let out = adair()
            .args(["run", "--view"])
            .arg(&p)
            .arg(&s)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{p:?}: {out:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains("--view") && err.contains(why), "{err}");
        assert!(out.stdout.is_empty(), "the program ran: {out:?}");
    }
    // A directory named like a page is refused too.
    let page_dir = d.join("dir.html");
    std::fs::create_dir_all(&page_dir).unwrap();
    let out = adair()
        .args(["run", "--view"])
        .arg(&page_dir)
        .arg(&s)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2), "{out:?}");
    assert!(out.stdout.is_empty());
}

#[test]
fn the_repl_writes_a_page_with_colon_view() {
    let d = dir("repl");
    let page = d.join("repl.html");
    let csv = d.join("repl.csv");
    let input = format!(
        "InitRobot;\nMoveAxesAbsolute ((0.3, 0.2, 0.4, 0.1, 0.0));\n:view {}\n:record {}\n",
        page.display(),
        csv.display()
    );
    let mut child = adair()
        .arg("repl")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(input.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("wrote") && text.contains("repl.html"),
        "{text}"
    );
    let page = std::fs::read_to_string(&page).unwrap();
    let csv = std::fs::read_to_string(&csv).unwrap();
    assert_eq!(element(&page, "adair-record"), csv);
}

/// The events of a live view's stream, as (name, data) pairs, read by a
/// plain HTTP client over loopback until the program has ended.
fn read_events(port: u16) -> Vec<(String, String)> {
    let mut s = std::net::TcpStream::connect(("127.0.0.1", port)).unwrap();
    s.write_all(b"GET /events HTTP/1.1\r\nHost: 127.0.0.1\r\nAccept: text/event-stream\r\n\r\n")
        .unwrap();
    s.set_read_timeout(Some(std::time::Duration::from_secs(30)))
        .unwrap();
    let mut r = BufReader::new(s);
    let mut status = String::new();
    r.read_line(&mut status).unwrap();
    assert!(status.starts_with("HTTP/1.1 200"), "{status}");
    let mut line = String::new();
    loop {
        line.clear();
        r.read_line(&mut line).unwrap();
        if line == "\r\n" {
            break;
        }
    }
    let mut events = Vec::new();
    let (mut name, mut data) = (String::new(), String::new());
    loop {
        line.clear();
        if r.read_line(&mut line).unwrap_or(0) == 0 {
            break;
        }
        let l = line.trim_end_matches('\n');
        if let Some(n) = l.strip_prefix("event: ") {
            name = n.to_string();
        } else if let Some(x) = l.strip_prefix("data: ") {
            data.push_str(x);
            data.push('\n');
        } else if l.is_empty() && !name.is_empty() {
            let done = name == "state" && data.contains("\"done\":true");
            events.push((std::mem::take(&mut name), std::mem::take(&mut data)));
            if done {
                break;
            }
        }
    }
    events
}

/// Starts `adair run --view --no-open` and returns it with its port.
fn live_run(
    args: &[&str],
    s: &Path,
) -> (
    std::process::Child,
    u16,
    BufReader<std::process::ChildStderr>,
) {
    let mut child = adair()
        .args(["run", "--view", "--no-open"])
        .args(args)
        .arg(s)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut err = BufReader::new(child.stderr.take().unwrap());
    let mut line = String::new();
    err.read_line(&mut line).unwrap();
    assert!(line.contains("loopback"), "{line}");
    let port: u16 = line
        .split("http://127.0.0.1:")
        .nth(1)
        .and_then(|r| r.split('/').next())
        .and_then(|p| p.parse().ok())
        .unwrap_or_else(|| panic!("no port in {line}"));
    (child, port, err)
}

#[test]
fn the_live_stream_carries_every_motion_in_order() {
    let d = dir("live");
    let s = script(&d);
    let csv = d.join("cell.csv");
    let rec = adair()
        .args(["run", "--record"])
        .arg(&csv)
        .arg(&s)
        .output()
        .unwrap();
    assert_eq!(rec.status.code(), Some(1));
    let recorded = std::fs::read_to_string(&csv).unwrap();
    let started = std::time::Instant::now();
    let (mut child, port, mut err) = live_run(&[], &s);
    let events = read_events(port);
    let status = child.wait().unwrap();
    let mut rest = String::new();
    err.read_to_string(&mut rest).unwrap();
    assert_eq!(status.code(), Some(1), "{rest}");
    // Paced to the wall clock as --realtime is: the arm's motions took
    // their time (the jaws' 0.8 s are not paced, as with --realtime).
    let last_t: f64 = recorded
        .lines()
        .last()
        .unwrap()
        .split(',')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(
        started.elapsed().as_secs_f64() >= last_t * 0.6,
        "{:?} for {last_t} s of motion",
        started.elapsed()
    );
    assert_eq!(events[0].0, "scene", "{events:?}");
    let mut streamed = format!("{}\n", adair::services::record::CSV_HEADER);
    for (name, data) in &events {
        if name == "rows" {
            streamed.push_str(data);
        }
    }
    assert_eq!(streamed, recorded, "the stream and the recording differ");
    let (last, data) = events.last().unwrap();
    assert_eq!(last, "state");
    assert!(
        data.contains("OUTOFREACH") && data.contains("5000.0"),
        "{data}"
    );
}

#[test]
fn the_live_view_says_it_listens_on_loopback_only_and_a_closed_page_does_not_disturb_the_run() {
    let d = dir("closed");
    let s = script(&d);
    let (mut child, port, mut err) = live_run(&["--view-port", "0"], &s);
    // A page that connects and goes at once, and one that stays.
    {
        let mut c = std::net::TcpStream::connect(("127.0.0.1", port)).unwrap();
        c.write_all(b"GET /events HTTP/1.1\r\nHost: x\r\n\r\n")
            .unwrap();
    }
    let page = {
        let mut c = std::net::TcpStream::connect(("127.0.0.1", port)).unwrap();
        c.write_all(b"GET / HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")
            .unwrap();
        let mut text = String::new();
        c.read_to_string(&mut text).unwrap();
        text
    };
    assert!(page.contains("ADAIR_MODE = \"live\""), "{}", &page[..200]);
    let events = read_events(port);
    let out = child.wait().unwrap();
    let mut rest = String::new();
    err.read_to_string(&mut rest).unwrap();
    assert_eq!(out.code(), Some(1), "{rest}");
    assert!(
        events.iter().filter(|e| e.0 == "rows").count() >= 4,
        "{events:?}"
    );
    assert!(!rest.contains("panicked"), "{rest}");
}

#[test]
fn the_repl_streams_each_entrys_motions_live() {
    let mut child = adair()
        .args(["repl", "--view", "--no-open"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut err = BufReader::new(child.stderr.take().unwrap());
    let mut line = String::new();
    err.read_line(&mut line).unwrap();
    assert!(
        line.contains("127.0.0.1") && line.contains("loopback"),
        "{line}"
    );
    let port: u16 = line
        .split("http://127.0.0.1:")
        .nth(1)
        .and_then(|r| r.split('/').next())
        .and_then(|p| p.parse().ok())
        .unwrap();
    let mut s = std::net::TcpStream::connect(("127.0.0.1", port)).unwrap();
    s.write_all(b"GET /events HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n")
        .unwrap();
    s.set_read_timeout(Some(std::time::Duration::from_secs(30)))
        .unwrap();
    let mut stdin = child.stdin.take().unwrap();
    stdin
        .write_all(b"InitRobot;\nMoveAxesRelative ((Rad (10.0), 0.0, 0.0, 0.0, 0.0));\nMoveFrameAbsolute (((-1.0, 0.0, 0.0, 5000.0), (0.0, 1.0, 0.0, 0.0), (0.0, 0.0, -1.0, 150.0)));\n")
        .unwrap();
    // The events up to the third entry's state: the scene, the motions of
    // the first two entries, a state after each entry.
    let mut r = BufReader::new(s);
    let mut names = Vec::new();
    let mut last_state = String::new();
    let mut l = String::new();
    while names.iter().filter(|n: &&String| *n == "state").count() < 3 {
        l.clear();
        assert!(
            r.read_line(&mut l).unwrap() > 0,
            "the stream ended: {names:?}"
        );
        if let Some(n) = l.strip_prefix("event: ") {
            names.push(n.trim().to_string());
        } else if names.last().is_some_and(|n| n == "state") && l.starts_with("data: ") {
            last_state = l.clone();
        }
    }
    // The third state's data line.
    last_state.clear();
    r.read_line(&mut last_state).unwrap();
    drop(stdin);
    let out = child.wait_with_output().unwrap();
    assert!(
        out.status.success() || out.status.code() == Some(1),
        "{out:?}"
    );
    assert_eq!(names[0], "scene", "{names:?}");
    let rows = names.iter().filter(|n| *n == "rows").count();
    assert!(
        rows >= 2,
        "InitRobot's and the relative motion's rows: {names:?}"
    );
    // The refused goal of the third entry, with its message.
    assert!(
        last_state.contains("OUTOFREACH") && last_state.contains("5000.0"),
        "{last_state}"
    );
}

#[test]
fn the_devices_of_the_cell_are_in_the_scene() {
    let d = dir("devices");
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let page = d.join("cell.html");
    let out = adair()
        .arg("run")
        .arg("--devices")
        .arg(root.join("examples/devices/cell.toml"))
        .arg("--view")
        .arg(&page)
        .arg(root.join("examples/tasks/conveyor_cell.air"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    let page = std::fs::read_to_string(&page).unwrap();
    let scene: serde_json::Value = serde_json::from_str(element(&page, "adair-scene")).unwrap();
    let dev = &scene["devices"];
    assert_eq!(dev["belts"][0]["name"], "belt", "{dev}");
    assert_eq!(dev["belts"][0]["end"][0], 250.0, "{dev}");
    assert_eq!(dev["barriers"][0]["on"], "belt", "{dev}");
    assert_eq!(dev["objects"][0]["name"], "box1", "{dev}");
}

/// The time an event of the live stream starts at: a motion's first row,
/// a cut's row, a device moment's time (None for the others).
fn starts_at(name: &str, data: &str) -> Option<f64> {
    match name {
        "rows" | "cut" => data.split(',').next().and_then(|t| t.trim().parse().ok()),
        "devices" => serde_json::from_str::<serde_json::Value>(data).ok()?["t"].as_f64(),
        _ => None,
    }
}

/// The device world's moments reach the live page as `devices` events, in
/// time order with the motions (a box that reaches the belt's end while
/// the arm moves comes after that motion, before the next), and they are
/// the moments a replay page of the same run carries.
#[test]
fn the_live_stream_carries_the_device_moments_in_order_with_the_motions() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let toml = root.join("tests/view/belt.toml");
    let s = root.join("tests/view/belt.air");
    let d = dir("live-devices");
    let page = d.join("belt.html");
    let out = adair()
        .arg("--devices")
        .arg(&toml)
        .args(["run", "--view"])
        .arg(&page)
        .arg(&s)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    let page = std::fs::read_to_string(&page).unwrap();
    let scene: serde_json::Value = serde_json::from_str(element(&page, "adair-scene")).unwrap();
    let replayed = scene["devices"]["events"].as_array().unwrap().clone();
    assert!(replayed.len() >= 8, "{replayed:?}");
    let (mut child, port, mut err) = live_run(&["--devices", &toml.to_string_lossy()], &s);
    let events = read_events(port);
    let status = child.wait().unwrap();
    let mut rest = String::new();
    err.read_to_string(&mut rest).unwrap();
    assert_eq!(status.code(), Some(0), "{rest}");
    let streamed: Vec<serde_json::Value> = events
        .iter()
        .filter(|e| e.0 == "devices")
        .map(|e| serde_json::from_str(&e.1).unwrap())
        .collect();
    assert_eq!(streamed, replayed, "the stream's moments and the page's");
    let mut last = f64::NEG_INFINITY;
    let mut order = Vec::new();
    for (name, data) in &events {
        if let Some(t) = starts_at(name, data) {
            order.push(format!("{name} {t:.3}"));
            // Rows carry 4 decimals.
            assert!(t >= last - 1e-4, "{name} at {t} after {last}: {order:?}");
            last = t;
        }
    }
    // box2 reaches the end (6.342 s) while the arm rises from the place
    // (6.092 s to 6.609 s): after that motion's rows, before the program's end.
    let arrival = order.iter().position(|e| e == "devices 6.342").unwrap();
    let motion = order[..arrival]
        .iter()
        .rev()
        .find_map(|e| e.strip_prefix("rows "))
        .and_then(|t| t.parse::<f64>().ok());
    assert!(
        motion.is_some_and(|t| (6.09..6.2).contains(&t)),
        "{order:?}"
    );
}

/// With `--port`, the live page shows the pose the driver reports: the
/// virtual controller (`adair sim-controller` on a pseudo-terminal) moves
/// the arm by hand after the first motion (`--jog-after`), and the
/// program's next read-back (`ValueAxes`, whose fresh `WH` sees the jog)
/// sends the page the jogged pose, not the pose the arm was sent.
#[test]
#[allow(clippy::print_stderr)] // a skipped test says so
fn the_live_view_of_a_real_arm_shows_the_pose_it_reports_after_a_hand_jog() {
    // InitRobot is 11 lines, the motion WH MJ ER: the jog comes after its ER.
    let mut ctl = adair()
        .args(["sim-controller", "--robot", "rv-m1", "--time-scale", "0.02"])
        .args(["--jog-after", "14:+10.0,+0.0,+0.0,-5.0,+0.0"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut path = String::new();
    BufReader::new(ctl.stdout.take().unwrap())
        .read_line(&mut path)
        .unwrap();
    let path = path.trim().to_string();
    if path.is_empty() {
        let mut e = String::new();
        ctl.stderr.take().unwrap().read_to_string(&mut e).unwrap();
        let _ = ctl.kill();
        let _ = ctl.wait();
        assert!(e.contains("no pseudo-terminal"), "sim-controller: {e}");
        eprintln!("SKIPPED: this OS has no pseudo-terminals ({})", e.trim());
        return;
    }
    let d = dir("port");
    let s = d.join("jogged.air");
    std::fs::write(
        &s,
        "InitRobot;
MoveAxesAbsolute ((Rad (10.0), Rad (20.0), Rad (30.0), Rad (40.0), Rad (50.0)));
declare
   A : constant AxesVector := ValueAxes;
begin
   for J in 1 .. 5 loop
      Put (Integer'Image (Integer (Deg (A (J)))));
   end loop;
   New_Line;
end;
",
    )
    .unwrap();
    let (child, port, mut err) = live_run(&["--port", &path, "--serial-timeout", "0.5"], &s);
    let events = read_events(port);
    let out = child.wait_with_output().unwrap();
    let mut rest = String::new();
    err.read_to_string(&mut rest).unwrap();
    let _ = ctl.kill();
    let _ = ctl.wait();
    assert!(out.status.success(), "{rest}");
    assert_eq!(String::from_utf8_lossy(&out.stdout), " 20 20 30 35 50\n");
    // The last row of each rows event: the pose shown after it.
    let shown: Vec<Vec<f64>> = events
        .iter()
        .filter(|e| e.0 == "rows")
        .map(|e| {
            let last = e.1.lines().last().unwrap();
            last.split(',').map(|x| x.parse().unwrap()).collect()
        })
        .collect();
    let near = |row: &Vec<f64>, q: [f64; 5]| (0..5).all(|k| (row[k + 1] - q[k]).abs() < 0.05);
    let sent = shown
        .iter()
        .position(|r| near(r, [10.0, 20.0, 30.0, 40.0, 50.0]))
        .unwrap_or_else(|| panic!("no motion to the pose sent: {shown:?}"));
    let reported = shown
        .iter()
        .position(|r| near(r, [20.0, 20.0, 30.0, 35.0, 50.0]))
        .unwrap_or_else(|| panic!("the page never got the jogged pose: {shown:?}"));
    assert!(sent < reported, "{shown:?}");
    assert!(near(shown.last().unwrap(), [20.0, 20.0, 30.0, 35.0, 50.0]));
    // Each motion ends when the unit reports its end (this controller
    // moves 50 times faster than planned): the rows the page keeps, a
    // cut dropping what comes after it, run forward in time.
    let mut kept: Vec<f64> = Vec::new();
    for (name, data) in &events {
        let times = data
            .lines()
            .filter_map(|l| l.split(',').next()?.parse::<f64>().ok());
        match name.as_str() {
            "rows" => kept.extend(times),
            "cut" => {
                for t in times {
                    while kept.last().is_some_and(|l| *l >= t) {
                        kept.pop();
                    }
                    kept.push(t);
                }
            }
            _ => {}
        }
    }
    assert!(
        kept.windows(2).all(|w| w[0] <= w[1]),
        "time goes back: {kept:?}"
    );
}

/// `adair test --view`: each script's replay page, `X.view.html` beside
/// `X.air` (or in the folder `--view=FOLDER` names), carrying what
/// `adair run --record` writes of the same script; a script that does not
/// check runs nothing and gets no page; the results are those without
/// `--view`. A folder that is not one, or two scripts of one name going
/// to one folder, are refused before anything runs (exit 2).
#[test]
fn adair_test_view_writes_a_replay_page_per_script() {
    let d = dir("test-view");
    let cell = script(&d);
    std::fs::write(d.join("bad.air"), "Put_Line (Undeclared);\n").unwrap();
    let run = |args: &[&str]| {
        adair()
            .arg("test")
            .args(args)
            .arg(&d)
            .current_dir(&d)
            .output()
            .unwrap()
    };
    let out = run(&["--bless", "--view"]);
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    let out = run(&["--view"]);
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    let page = std::fs::read_to_string(d.join("cell.view.html")).expect("cell.view.html");
    assert!(
        !d.join("bad.view.html").exists(),
        "a page of a run that never was"
    );
    let csv = d.join("cell.csv");
    let rec = adair()
        .args(["run", "--record"])
        .arg(&csv)
        .arg(&cell)
        .current_dir(&d)
        .output()
        .unwrap();
    assert_eq!(rec.status.code(), Some(1));
    assert_eq!(
        element(&page, "adair-record"),
        std::fs::read_to_string(&csv).unwrap()
    );
    let scene: serde_json::Value = serde_json::from_str(element(&page, "adair-scene")).unwrap();
    assert_eq!(scene["title"], "cell.air");
    assert!(
        scene["end"]["exception"]
            .as_str()
            .is_some_and(|e| e.contains("OUTOFREACH")),
        "{scene}"
    );
    // Into a folder.
    let pages = d.join("pages");
    std::fs::create_dir_all(&pages).unwrap();
    let out = run(&[&format!("--view={}", pages.display())]);
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    assert_eq!(
        std::fs::read_to_string(pages.join("cell.view.html")).unwrap(),
        page
    );
    // Refused before anything runs.
    let out = run(&["--view=no-such-folder"]);
    assert_eq!(out.status.code(), Some(2), "{out:?}");
    assert!(String::from_utf8_lossy(&out.stderr).contains("not a directory"));
    std::fs::create_dir_all(d.join("again")).unwrap();
    std::fs::copy(d.join("cell.air"), d.join("again/cell.air")).unwrap();
    std::fs::copy(d.join("cell.out"), d.join("again/cell.out")).unwrap();
    std::fs::remove_file(pages.join("cell.view.html")).unwrap();
    let out = run(&[&format!("--view={}", pages.display())]);
    assert_eq!(out.status.code(), Some(2), "{out:?}");
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("the same page"),
        "{out:?}"
    );
    assert!(!pages.join("cell.view.html").exists());
}
