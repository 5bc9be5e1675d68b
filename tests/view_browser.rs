//! The 3D view in a real browser: headless Chromium with software WebGL
//! (SwiftShader) loads replay pages and the live page. The page's read-only
//! hook, `window.adairView.jointPositions(t)`, is asked through the page's
//! `#probe=t1,t2,...` (it writes the answers into the page as JSON, which
//! `--dump-dom` prints) and compared with adair's own forward kinematics;
//! screenshots of a known pose must show the arm where its joints project.
//!
//! Without Chromium these tests are reported as ignored, with a message
//! saying why; `ADAIR_REQUIRE_CHROMIUM=1` (set by `.ci/run`, which
//! installs Debian's `chromium`) makes a missing Chromium a failure.
//! `BLESS=1` rewrites the screenshots in docs/images that docs/tutorial.md
//! and docs/view.md show; without it they are compared with what the page
//! draws now.
#![allow(clippy::print_stderr)]

mod common;

use adair::kinematics::{Kinematics, RobotDescription};
use std::io::{BufRead, BufReader, Read};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// Three motions and a gripper action, then an unreachable goal: the run
/// ends with an exception (a red ghost on the page).
const SCRIPT: &str = r#"InitRobot;
MoveAxesAbsolute ((Rad (30.0), Rad (40.0), Rad (60.0), Rad (50.0), Rad (20.0)));
MoveFrameAbsolute (((-1.0, 0.0, 0.0, 280.0), (0.0, 1.0, 0.0, -40.0), (0.0, 0.0, -1.0, 150.0)));
CreatePath (1);
InsertPosition (1, 1, ValueFrameAbsolute);
SetMoveMode (StraightLine);
MoveFrameAbsolute (((-1.0, 0.0, 0.0, 280.0), (0.0, 1.0, 0.0, 60.0), (0.0, 0.0, -1.0, 150.0)));
InsertPosition (1, 2, ValueFrameAbsolute);
MoveTool (20.0, 5.0);
SetMoveMode (JointInterpolated);
MoveAxesAbsolute ((Rad (-45.0), Rad (20.0), Rad (70.0), Rad (-30.0), Rad (0.0)));
MoveFrameAbsolute (((-1.0, 0.0, 0.0, 620.0), (0.0, 1.0, 0.0, 0.0), (0.0, 0.0, -1.0, 150.0)));
"#;

/// The Chromium to use: `ADAIR_CHROMIUM`, else the first of the usual
/// names on the PATH.
fn chromium() -> Option<PathBuf> {
    if let Some(p) = std::env::var_os("ADAIR_CHROMIUM") {
        return Some(PathBuf::from(p));
    }
    [
        "chromium",
        "chromium-browser",
        "google-chrome",
        "google-chrome-stable",
    ]
    .iter()
    .find(|n| {
        Command::new(n)
            .arg("--version")
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status()
            .is_ok_and(|s| s.success())
    })
    .map(PathBuf::from)
}

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("adair-view-browser-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

const WIDTH: u32 = 900;
const HEIGHT: u32 = 650;

/// Headless Chromium on `url` with these last arguments; its stdout.
fn browse(url: &str, args: &[String]) -> String {
    let profile = dir(&format!("profile-{}", rand_tag()));
    let out = Command::new(chromium().expect("chromium"))
        .args([
            "--headless=new",
            "--no-sandbox",
            "--use-angle=swiftshader",
            "--enable-unsafe-swiftshader",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--no-first-run",
            "--hide-scrollbars",
            "--force-device-scale-factor=1",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .arg(format!("--window-size={WIDTH},{HEIGHT}"))
        .args(args)
        .arg(url)
        .stdin(Stdio::null())
        .output()
        .expect("chromium runs");
    let _ = std::fs::remove_dir_all(&profile);
    String::from_utf8_lossy(&out.stdout).into_owned()
}

fn rand_tag() -> String {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static N: AtomicUsize = AtomicUsize::new(0);
    format!("{}", N.fetch_add(1, Ordering::SeqCst))
}

/// The hook's answers the page wrote for `#probe=...`.
fn probe(url: &str, extra: &[&str]) -> serde_json::Value {
    let mut args: Vec<String> = extra.iter().map(|s| s.to_string()).collect();
    args.push("--dump-dom".into());
    let dom = browse(url, &args);
    let start = dom
        .find("<pre id=\"adair-probe\">{")
        .unwrap_or_else(|| panic!("the page wrote no probe: {}", &dom[..dom.len().min(3000)]))
        + "<pre id=\"adair-probe\">".len();
    let end = start + dom[start..].find("</pre>").unwrap();
    let text = dom[start..end]
        .replace("&quot;", "\"")
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&amp;", "&");
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{e}: {text}"))
}

fn file_url(p: &Path) -> String {
    format!("file://{}", p.display())
}

/// Runs the script on `robot` with `--view` and `--record`: the page and
/// the recorded rows.
fn replay(d: &Path, robot: &str) -> (PathBuf, Vec<Vec<f64>>) {
    let s = d.join("cell.air");
    std::fs::write(&s, SCRIPT).unwrap();
    let page = d.join(format!("{robot}.html"));
    let csv = d.join(format!("{robot}.csv"));
    let out = Command::new(env!("CARGO_BIN_EXE_adair"))
        .args(["run", "--robot", robot, "--view"])
        .arg(&page)
        .arg("--record")
        .arg(&csv)
        .arg(&s)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1), "{out:?}");
    (page, rows(&std::fs::read_to_string(&csv).unwrap()))
}

fn rows(csv: &str) -> Vec<Vec<f64>> {
    csv.lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect()
}

/// The joints (rad) at time t from the recorded rows: the last row at or
/// before t, linear to the next (docs/record.md).
fn joints_at(rows: &[Vec<f64>], t: f64) -> [f64; 5] {
    let i = rows.iter().rposition(|r| r[0] <= t).unwrap_or(0);
    let a = &rows[i];
    let f = match rows.get(i + 1) {
        Some(b) if b[0] > a[0] && t > a[0] => ((t - a[0]) / (b[0] - a[0])).min(1.0),
        _ => 0.0,
    };
    let mut q = [0.0; 5];
    for (k, x) in q.iter_mut().enumerate() {
        let b = rows.get(i + 1).map_or(a[k + 1], |b| b[k + 1]);
        *x = (a[k + 1] + (b - a[k + 1]) * f).to_radians();
    }
    q
}

const NAMES: [&str; 6] = ["base", "shoulder", "elbow", "wrist", "flange", "tcp"];

/// Checks the hook's points against adair's forward kinematics at each
/// probed time (0.1 mm); returns how many points were compared.
fn compare(robot: &str, rows: &[Vec<f64>], answer: &serde_json::Value) -> usize {
    let desc = RobotDescription::builtin(robot).unwrap();
    let tool = desc.standard_tool();
    let kin = Kinematics::new(desc);
    let mut n = 0;
    for probe in answer["times"].as_array().unwrap() {
        let t = probe["t"].as_f64().unwrap();
        let q = joints_at(rows, t);
        let want = adair::view::joint_points(&kin, &q, &tool);
        for (k, name) in NAMES.iter().enumerate() {
            let got = &probe["points"][name];
            for (axis, w) in want[k].iter().enumerate() {
                let g = got[axis]
                    .as_f64()
                    .unwrap_or_else(|| panic!("{robot} t={t}: no {name}: {probe}"));
                assert!(
                    (g - w).abs() <= 0.1,
                    "{robot} at t = {t}: the page draws the {name} at {got}, adair's FK says {:?}",
                    want[k]
                );
                n += 1;
            }
        }
    }
    n
}

/// Times inside each motion of the script, and its ends.
fn times(rows: &[Vec<f64>]) -> Vec<f64> {
    let end = rows.last().unwrap()[0];
    let mut v: Vec<f64> = (1..12).map(|k| end * k as f64 / 12.0).collect();
    v.push(0.0);
    v.push(end);
    v
}

fn hook_matches_fk_on(robot: &str) {
    let d = dir(robot);
    let (page, rows) = replay(&d, robot);
    let ts: Vec<String> = times(&rows).iter().map(|t| format!("{t:.4}")).collect();
    let url = format!("{}#probe={}", file_url(&page), ts.join(","));
    let answer = probe(&url, &["--virtual-time-budget=3000"]);
    assert_eq!(answer["rows"].as_u64().unwrap() as usize, rows.len());
    let n = compare(robot, &rows, &answer);
    assert_eq!(n, ts.len() * 6 * 3);
}

fn replay_hook_matches_adairs_fk_on_the_rv_m1() {
    hook_matches_fk_on("rv-m1");
}

fn replay_hook_matches_adairs_fk_on_the_rm_501() {
    hook_matches_fk_on("rm-501");
}

/// The page reads its record with the header `--record` writes now (with
/// units, `t_s,j1_deg,...`) and with the one it wrote before (`t,j1,...`):
/// a header is never taken for a row of numbers.
fn the_page_reads_the_record_header_with_and_without_units() {
    use adair::services::record::{CSV_HEADER, OLD_CSV_HEADER};
    let d = dir("headers");
    let (page, rows) = replay(&d, "rv-m1");
    let text = std::fs::read_to_string(&page).unwrap();
    let record = adair::view::embedded_record(&text).unwrap();
    assert!(
        record.starts_with(&format!("{CSV_HEADER}\n")),
        "{record:.200}"
    );
    let old = d.join("old-header.html");
    std::fs::write(&old, text.replacen(CSV_HEADER, OLD_CSV_HEADER, 1)).unwrap();
    for p in [&page, &old] {
        let answer = probe(
            &format!("{}#probe=0", file_url(p)),
            &["--virtual-time-budget=3000"],
        );
        assert_eq!(
            answer["rows"].as_u64().unwrap() as usize,
            rows.len(),
            "{}",
            p.display()
        );
        let q = &answer["times"][0]["joints"];
        assert!(q[0].as_f64().is_some(), "{}: {q}", p.display());
    }
}

fn live_page_hook_matches_adairs_fk() {
    let d = dir("live");
    let s = d.join("cell.air");
    std::fs::write(&s, SCRIPT).unwrap();
    let csv = d.join("cell.csv");
    let rec = Command::new(env!("CARGO_BIN_EXE_adair"))
        .args(["run", "--robot", "rm-501", "--record"])
        .arg(&csv)
        .arg(&s)
        .output()
        .unwrap();
    assert_eq!(rec.status.code(), Some(1));
    let rows = rows(&std::fs::read_to_string(&csv).unwrap());
    let mut child = Command::new(env!("CARGO_BIN_EXE_adair"))
        .args(["run", "--robot", "rm-501", "--view", "--no-open"])
        .arg(&s)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut err = BufReader::new(child.stderr.take().unwrap());
    let mut line = String::new();
    err.read_line(&mut line).unwrap();
    let port = line
        .split("http://127.0.0.1:")
        .nth(1)
        .and_then(|r| r.split('/').next())
        .unwrap_or_else(|| panic!("no address in {line}"))
        .to_string();
    let ts: Vec<String> = times(&rows).iter().map(|t| format!("{t:.4}")).collect();
    let url = format!("http://127.0.0.1:{port}/#probe={}", ts.join(","));
    // The page answers when the program has ended (it runs on the wall
    // clock): the browser's virtual time waits while the stream is open,
    // and the stream ends with the program.
    let answer = probe(&url, &["--virtual-time-budget=120000"]);
    let status = child.wait().unwrap();
    let mut rest = String::new();
    err.read_to_string(&mut rest).unwrap();
    assert_eq!(status.code(), Some(1), "{rest}");
    assert_eq!(answer["rows"].as_u64().unwrap() as usize, rows.len());
    compare("rm-501", &rows, &answer);
}

/// The inputs a program gave the device world, read off its `--trace`:
/// (time, what) with what a motor write (address, value), a pick or a
/// put-down (object name).
#[derive(Debug)]
enum Input {
    Write(u32, u16),
    Pick(String),
    PutDown(String),
}

fn inputs(trace: &str) -> Vec<(f64, Input)> {
    let mut out = Vec::new();
    for line in trace.lines() {
        let Some(rest) = line.strip_prefix("[t=") else {
            continue;
        };
        let Some((t, what)) = rest.split_once(" s] devices: ") else {
            continue;
        };
        let t: f64 = t.trim().parse().unwrap();
        if let Some(obj) = what.strip_prefix("gripper: ") {
            if let Some(name) = obj.strip_suffix(" picked") {
                out.push((t, Input::Pick(name.to_string())));
            } else if let Some((name, _)) = obj.split_once(" put down at ") {
                out.push((t, Input::PutDown(name.to_string())));
            }
        } else if let Some((_, reg)) = what.split_once(": motor register 8#") {
            let (addr, value) = reg.split_once("# := 16#").unwrap();
            let value = value.trim_end_matches('#');
            out.push((
                t,
                Input::Write(
                    u32::from_str_radix(addr, 8).unwrap(),
                    u16::from_str_radix(value, 16).unwrap(),
                ),
            ));
        }
    }
    out
}

/// Where adair's device world has each object at time `t`: the world of
/// the device file run again with the program's inputs up to `t` (a
/// held object is at the TCP, by adair's FK of the recorded joints), each
/// belt position drawn where `adair::view::belt_point` puts it.
fn simulated_objects(
    devs: &adair::devices::Devices,
    inputs: &[(f64, Input)],
    tcp_at: &dyn Fn(f64) -> [f64; 3],
    t: f64,
) -> Vec<(String, [f64; 3])> {
    use adair::devices::{DeviceKind, Place, World};
    let mut w = World::new(devs.clone());
    for (at, input) in inputs.iter().filter(|(at, _)| *at <= t) {
        w.advance_to(*at);
        match input {
            Input::Write(a, v) => w.write(*a, *v).unwrap(),
            Input::Pick(name) => drop(w.pick(name).unwrap()),
            Input::PutDown(name) => w.put_down(name, tcp_at(*at)).unwrap(),
        }
    }
    w.advance_to(t);
    w.objects()
        .into_iter()
        .map(|o| {
            let at = match o.place {
                Place::OnBelt { belt, position, .. } => match devs.devices()[belt].kind {
                    DeviceKind::Conveyor { length, end, .. } => {
                        adair::view::belt_point(end, length, position)
                    }
                    _ => unreachable!("an object on a belt"),
                },
                Place::Held => tcp_at(t),
                Place::At(p) => p,
            };
            (o.name, at)
        })
        .collect()
}

/// The page's objects move on the timeline as adair's device world moves
/// them: `adairView.objectAt` (through `#probe`) at times while the boxes
/// ride the belt, queue behind one another, ride in the gripper and lie
/// where they were put down, within 0.1 mm of the world run again with the
/// program's inputs; before an object is on the belt the page has none.
fn replay_objects_move_as_the_device_world_says() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let d = dir("objects");
    let (page, csv) = (d.join("belt.html"), d.join("belt.csv"));
    let toml = root.join("tests/view/belt.toml");
    let out = Command::new(env!("CARGO_BIN_EXE_adair"))
        .arg("--devices")
        .arg(&toml)
        .args(["run", "--trace", "--view"])
        .arg(&page)
        .arg("--record")
        .arg(&csv)
        .arg(root.join("tests/view/belt.air"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    let trace = String::from_utf8_lossy(&out.stderr);
    let inputs = inputs(&trace);
    assert_eq!(inputs.len(), 6, "{inputs:?}\n{trace}");
    let rows = rows(&std::fs::read_to_string(&csv).unwrap());
    let desc = RobotDescription::builtin("rv-m1").unwrap();
    let tool = desc.standard_tool();
    let kin = Kinematics::new(desc);
    let tcp_at = |t: f64| adair::view::joint_points(&kin, &joints_at(&rows, t), &tool)[5];
    let devs = adair::devices::Devices::load(&toml).unwrap();
    let end = rows.last().unwrap()[0];
    // Every 0.1 s, and times inside the belt's runs (box2 moving up to
    // box1 until 2.75 s, moving again from 6.09 s), away from the inputs'
    // times (the trace gives them to 1 ms).
    let mut ts: Vec<f64> = (0..((end + 0.3) / 0.1) as usize)
        .map(|k| k as f64 * 0.1 + 0.013)
        .collect();
    ts.extend([0.4, 0.75, 2.6, 2.74, 2.8, 6.2, 6.3, 6.5, end + 0.5]);
    ts.retain(|t| inputs.iter().all(|(at, _)| (t - at).abs() > 0.01));
    let list: Vec<String> = ts.iter().map(|t| format!("{t:.4}")).collect();
    let url = format!("{}#probe={}", file_url(&page), list.join(","));
    let answer = probe(&url, &["--virtual-time-budget=3000"]);
    let (mut on_belt, mut held, mut compared) = (0, 0, 0);
    for p in answer["times"].as_array().unwrap() {
        let t = p["t"].as_f64().unwrap();
        let want = simulated_objects(&devs, &inputs, &tcp_at, t);
        let got = p["objects"].as_object().unwrap();
        for name in ["box1", "box2"] {
            let w = want.iter().find(|(n, _)| n == name).map(|x| x.1);
            let g = got.get(name).filter(|v| !v.is_null());
            match (w, g) {
                (None, None) => {}
                (Some(w), Some(g)) => {
                    for k in 0..3 {
                        let gk = g[k].as_f64().unwrap();
                        assert!(
                            (gk - w[k]).abs() <= 0.1,
                            "t = {t}: the page has {name} at {g}, the device world at {w:?}"
                        );
                    }
                    compared += 1;
                    if name == "box1" && (3.8..5.8).contains(&t) {
                        held += 1;
                    }
                    if (w[0] - 250.0).abs() > 1.0 && w[1] > 0.0 {
                        on_belt += 1;
                    }
                }
                _ => panic!("t = {t}: the page has {name} at {g:?}, the device world at {w:?}"),
            }
        }
    }
    assert!(compared > 100, "{compared} positions compared");
    assert!(
        held >= 10 && on_belt >= 20,
        "held {held}, on the belt {on_belt}"
    );
}

/// A decoded screenshot: width, height, RGB pixels.
struct Shot {
    w: u32,
    h: u32,
    rgb: Vec<[u8; 3]>,
}

fn decode(path: &Path) -> Shot {
    let dec = png::Decoder::new(std::fs::File::open(path).unwrap());
    let mut reader = dec.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).unwrap();
    let k = info.color_type.samples();
    assert_eq!(info.bit_depth, png::BitDepth::Eight);
    let rgb = buf[..info.buffer_size()]
        .chunks(k)
        .map(|p| [p[0], p[1], p[2]])
        .collect();
    Shot {
        w: info.width,
        h: info.height,
        rgb,
    }
}

impl Shot {
    fn at(&self, x: i64, y: i64) -> Option<[u8; 3]> {
        (x >= 0 && y >= 0 && (x as u32) < self.w && (y as u32) < self.h)
            .then(|| self.rgb[(y as u32 * self.w + x as u32) as usize])
    }
    /// A pixel of the arm's paint: orange links or blue joint axes, never
    /// the grey floor grid or the background.
    fn arm_near(&self, x: f64, y: f64, r: i64) -> bool {
        let (cx, cy) = (x.round() as i64, y.round() as i64);
        (-r..=r).any(|dy| {
            (-r..=r).any(|dx| {
                self.at(cx + dx, cy + dy).is_some_and(|[r, g, b]| {
                    let (hi, lo) = (r.max(g).max(b), r.min(g).min(b));
                    hi - lo > 60
                })
            })
        })
    }
    /// The mean difference of the colour channels of `self` and `other`
    /// in the square of half side `r` about (x, y).
    fn differs(&self, other: &Shot, x: f64, y: f64, r: i64) -> f64 {
        let (cx, cy) = (x.round() as i64, y.round() as i64);
        let (mut sum, mut n) = (0.0, 0usize);
        for dy in -r..=r {
            for dx in -r..=r {
                if let (Some(a), Some(b)) = (self.at(cx + dx, cy + dy), other.at(cx + dx, cy + dy))
                {
                    for k in 0..3 {
                        sum += (a[k] as f64 - b[k] as f64).abs();
                    }
                    n += 3;
                }
            }
        }
        if n == 0 { 0.0 } else { sum / n as f64 }
    }
    /// The share of the 3D area's pixels that are not the background.
    fn drawn(&self, bottom: u32) -> f64 {
        let mut n = 0usize;
        let mut all = 0usize;
        for y in 60..bottom.min(self.h) {
            for x in 0..self.w {
                all += 1;
                let [r, g, b] = self.rgb[(y * self.w + x) as usize];
                if (r as i32 - 0xf4).abs() + (g as i32 - 0xf4).abs() + (b as i32 - 0xf0).abs() > 24
                {
                    n += 1;
                }
            }
        }
        n as f64 / all.max(1) as f64
    }
}

/// The page at time `t` and view `view`: the screenshot (written to
/// `png`) and where the hook says the joints are on the screen.
fn screenshot(page: &Path, t: f64, view: &str, png: &Path) -> (Shot, Vec<(f64, f64)>) {
    // The same drawing size in both runs: the window's inner size differs
    // between --dump-dom and --screenshot.
    let url = format!(
        "{}#t={t}&view={view}&size={WIDTH}x{}&probe=",
        file_url(page),
        HEIGHT - 76
    );
    let answer = probe(&url, &["--virtual-time-budget=3000"]);
    browse(
        &url,
        &[
            "--virtual-time-budget=3000".into(),
            format!("--screenshot={}", png.display()),
        ],
    );
    let points = answer["screen"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| (p[0].as_f64().unwrap(), p[1].as_f64().unwrap()))
        .collect();
    (decode(png), points)
}

fn a_screenshot_shows_the_arm_where_its_joints_project() {
    let d = dir("shot");
    for (robot, view) in [("rv-m1", "front"), ("rm-501", "iso")] {
        let (page, rows) = replay(&d, robot);
        let t = rows.last().unwrap()[0] * 0.3;
        let png = d.join(format!("{robot}-{view}.png"));
        let (shot, points) = screenshot(&page, t, view, &png);
        assert_eq!((shot.w, shot.h), (WIDTH, HEIGHT));
        let drawn = shot.drawn(HEIGHT - 80);
        assert!(
            drawn > 0.05,
            "{robot}: the 3D view is blank ({drawn:.3} drawn)"
        );
        // The shoulder, elbow and wrist axes and the links between them.
        for (k, name) in NAMES.iter().enumerate().take(4).skip(1) {
            let (x, y) = points[k];
            assert!(
                shot.arm_near(x, y, 6),
                "{robot} {view}: no arm pixel near the {name} at ({x:.0}, {y:.0}) in {}",
                png.display()
            );
        }
        // Far from the arm (a corner of the floor), no arm paint.
        assert!(
            !shot.arm_near(30.0, 300.0, 4),
            "{robot}: arm paint in the corner"
        );
    }
}

/// The screenshots of docs/tutorial.md and docs/view.md, drawn by the page
/// as it is now: `BLESS=1` writes them, otherwise each must still match
/// (same size, about as much drawn, the same pixels about each joint).
fn the_docs_screenshots_are_what_the_page_draws() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let d = dir("docs");
    let example = root.join("examples/pick_and_place.air");
    let page = d.join("pick_and_place.html");
    let out = Command::new(env!("CARGO_BIN_EXE_adair"))
        .args(["run", "--view"])
        .arg(&page)
        .arg(&example)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    let (failing, _) = replay(&d, "rv-m1");
    let bless = std::env::var_os("BLESS").is_some();
    for (name, page, t, view) in [
        ("view-pick-and-place.png", &page, 2.0, "iso"),
        ("view-exception.png", &failing, 1000.0, "iso"),
    ] {
        let fresh = d.join(name);
        let (shot, points) = screenshot(page, t, view, &fresh);
        let kept = root.join("docs/images").join(name);
        if bless {
            std::fs::copy(&fresh, &kept).unwrap();
            eprintln!("view_browser: wrote {}", kept.display());
            continue;
        }
        assert!(
            kept.exists(),
            "{} is missing: run BLESS=1 cargo test --test view_browser",
            kept.display()
        );
        let old = decode(&kept);
        assert_eq!((old.w, old.h), (shot.w, shot.h), "{name}");
        let (a, b) = (old.drawn(HEIGHT - 80), shot.drawn(HEIGHT - 80));
        assert!(
            (a - b).abs() < 0.25 * b.max(0.01),
            "{name}: docs/images has {a:.3} drawn, the page draws {b:.3} now: BLESS=1 to update"
        );
        for (x, y) in &points {
            let d = old.differs(&shot, *x, *y, 10);
            assert!(
                d < 30.0,
                "{name}: docs/images differs from the page near ({x:.0}, {y:.0}) by {d:.1}: BLESS=1 to update"
            );
        }
    }
}

fn main() {
    let tests: &[(&str, fn())] = &[
        (
            "replay_hook_matches_adairs_fk_on_the_rv_m1",
            replay_hook_matches_adairs_fk_on_the_rv_m1,
        ),
        (
            "replay_hook_matches_adairs_fk_on_the_rm_501",
            replay_hook_matches_adairs_fk_on_the_rm_501,
        ),
        (
            "live_page_hook_matches_adairs_fk",
            live_page_hook_matches_adairs_fk,
        ),
        (
            "replay_objects_move_as_the_device_world_says",
            replay_objects_move_as_the_device_world_says,
        ),
        (
            "the_page_reads_the_record_header_with_and_without_units",
            the_page_reads_the_record_header_with_and_without_units,
        ),
        (
            "a_screenshot_shows_the_arm_where_its_joints_project",
            a_screenshot_shows_the_arm_where_its_joints_project,
        ),
        (
            "the_docs_screenshots_are_what_the_page_draws",
            the_docs_screenshots_are_what_the_page_draws,
        ),
    ];
    let have = chromium().is_some();
    if !have {
        if std::env::var_os("ADAIR_REQUIRE_CHROMIUM").is_some() {
            eprintln!(
                "view browser tests: ADAIR_REQUIRE_CHROMIUM is set but Chromium is not installed"
            );
            std::process::exit(1);
        }
        eprintln!(
            "view browser tests: Chromium is not installed, so the {} tests below are IGNORED \
             (apt-get install -y chromium to run them, or set ADAIR_CHROMIUM; CI does)",
            tests.len()
        );
    }
    common::run_fns(tests, !have);
}
