//! The live 3D view's latency: from a motion's start (the services announce
//! it to the view, before it is paced or driven) to the moment a client on
//! loopback has read its event off the socket. And the size of a replay
//! page for a 10-minute run.
//!
//! `cargo bench --bench view_live` prints the figures (no criterion: each
//! motion is one sample, and the run is paced to the wall clock as the
//! live view's runs are).
#![allow(clippy::print_stdout)]

use adair::services::record::{Sample, Watch};
use adair::view::live::{HubWatch, Server};
use std::io::{BufRead, BufReader, Write};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Notes when each motion started, then hands it on to the live view.
struct Timed {
    inner: HubWatch,
    starts: Arc<Mutex<Vec<Instant>>>,
}

impl Watch for Timed {
    fn samples(&mut self, samples: &[Sample]) {
        self.starts.lock().unwrap().push(Instant::now());
        self.inner.samples(samples);
    }
    fn cut(&mut self, s: &Sample) {
        self.inner.cut(s);
    }
}

fn percentile(v: &[f64], p: f64) -> f64 {
    v[((v.len() - 1) as f64 * p).round() as usize]
}

fn latency(motions: usize) {
    let sv = Server::start(0).expect("the view server starts");
    // A client on loopback: the time each `rows` event is read.
    let arrivals = Arc::new(Mutex::new(Vec::new()));
    let a = arrivals.clone();
    let port = sv.port;
    let client = std::thread::spawn(move || {
        let mut s = std::net::TcpStream::connect(("127.0.0.1", port)).unwrap();
        s.write_all(b"GET /events HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n")
            .unwrap();
        let mut r = BufReader::new(s);
        let mut line = String::new();
        while r.read_line(&mut line).unwrap_or(0) > 0 {
            if line == "event: rows\n" {
                a.lock().unwrap().push(Instant::now());
            }
            line.clear();
        }
    });
    let starts = Arc::new(Mutex::new(Vec::new()));
    let mut s = adair::session::Session::new(Box::new(std::io::sink()));
    let desc = adair::kinematics::RobotDescription::builtin("rv-m1").unwrap();
    // Paced to the wall clock, as the live view runs a program.
    s.set_robot(desc, None, true);
    s.robot_state_mut().unwrap().watch = Some(Box::new(Timed {
        inner: HubWatch(sv.hub.clone()),
        starts: starts.clone(),
    }));
    // Wait for the client, so that no event reaches it from the history.
    sv.hub.wait_for_page(Duration::from_secs(5));
    std::thread::sleep(Duration::from_millis(100));
    let mut text = String::from("InitRobot;\nSetVelocity (100.0);\n");
    for k in 0..motions {
        let a = if k % 2 == 0 { 2.0 } else { 0.0 };
        text.push_str(&format!(
            "MoveAxesAbsolute ((Rad ({a:.1}), 0.0, Rad (90.0), Rad (90.0), 0.0));\n"
        ));
    }
    let outcome = s.run_source("latency.air", text.as_str());
    assert_eq!(outcome.exit_code(), 0, "the program failed");
    sv.hub.finish(Duration::from_secs(2));
    std::thread::sleep(Duration::from_millis(200));
    let starts = starts.lock().unwrap().clone();
    let arrivals = arrivals.lock().unwrap().clone();
    drop(client);
    assert_eq!(
        starts.len(),
        arrivals.len(),
        "every motion reached the client"
    );
    let mut ms: Vec<f64> = starts
        .iter()
        .zip(&arrivals)
        .map(|(s, a)| a.duration_since(*s).as_secs_f64() * 1000.0)
        .collect();
    ms.sort_by(f64::total_cmp);
    println!(
        "live view latency, motion start -> event read by a loopback client, {} motions: \
         median {:.3} ms, p95 {:.3} ms, max {:.3} ms",
        ms.len(),
        percentile(&ms, 0.5),
        percentile(&ms, 0.95),
        ms[ms.len() - 1]
    );
}

/// A 10-minute run: back and forth between two poses for 600 s of
/// virtual time (not paced), written as a replay page.
fn page_size() {
    let mut s = adair::session::Session::new(Box::new(std::io::sink()));
    let desc = adair::kinematics::RobotDescription::builtin("rv-m1").unwrap();
    s.set_robot(desc, None, false);
    s.start_recording();
    // The program: as many round trips as take 600 s.
    let mut prog = String::from("InitRobot;\nSetVelocity (30.0);\n");
    // The virtual time after `k` round trips.
    let after = |k: usize| {
        let mut probe = adair::session::Session::new(Box::new(std::io::sink()));
        let d = adair::kinematics::RobotDescription::builtin("rv-m1").unwrap();
        probe.set_robot(d, None, false);
        probe.start_recording();
        let text = format!("{prog}{}", round_trip().repeat(k));
        let _ = probe.run_source("probe.air", text.as_str());
        probe
            .robot_state()
            .unwrap()
            .record
            .as_ref()
            .unwrap()
            .last()
            .unwrap()
            .t
    };
    let (one, two) = (after(1), after(2));
    let n = 1 + ((600.0 - one) / (two - one)).ceil() as usize;
    for _ in 0..n {
        prog.push_str(&round_trip());
    }
    let outcome = s.run_source("ten_minutes.air", prog.as_str());
    assert_eq!(outcome.exit_code(), 0, "the program failed");
    let st = s.robot_state().unwrap();
    let dir = std::env::temp_dir().join(format!("adair-bench-view-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let page = dir.join("ten_minutes.html");
    let ending = adair::view::Ending {
        t: s.machine.clock.now(),
        ..Default::default()
    };
    let bytes = adair::view::write_replay(&page, st, None, "ten_minutes.air", &ending).unwrap();
    let rows = st.record.as_ref().unwrap().len();
    let csv = adair::services::record::to_csv(st.record.as_ref().unwrap()).len();
    println!(
        "replay page of a {:.0} s run: {} bytes ({:.2} MB): {rows} support points ({csv} bytes of CSV), \
         three {} bytes, page and script the rest",
        ending.t,
        bytes,
        bytes as f64 / 1e6,
        include_str!("../assets/view/three.min.js").len()
    );
    let _ = std::fs::remove_dir_all(&dir);
}

fn round_trip() -> String {
    "MoveAxesAbsolute ((Rad (90.0), Rad (30.0), Rad (60.0), Rad (20.0), 0.0));\n\
     MoveAxesAbsolute ((Rad (-90.0), 0.0, Rad (90.0), Rad (90.0), 0.0));\n"
        .to_string()
}

fn main() {
    // `cargo test --benches` runs this too: a short run then.
    let quick =
        std::env::args().any(|a| a == "--test") || !std::env::args().any(|a| a == "--bench");
    latency(if quick { 10 } else { 200 });
    page_size();
}
