//! The live 3D view (`adair run --view`, `adair repl --view`): a small web
//! server on 127.0.0.1 (tiny_http) that serves the page and streams the
//! program's motions to every open page as Server-Sent Events.
//!
//! The services announce each motion when it starts ([`record::Watch`]);
//! the [`Hub`] formats it once and hands it to each page's own thread
//! through a channel, so the program never waits for a page: a slow or
//! closed page only ends its own thread. A page that connects late gets
//! everything so far first, then the rest as it happens.
//!
//! Events: `scene` (the robot, as a replay page's scene), `rows` (CSV rows
//! as `--record` writes them, without the header), `cut` (one row: the
//! motion announced last ended there, Ctrl-C), `devices` (a moment of the
//! device world, as a replay page's `devices.events` entry, sent when the
//! world makes it: in time order with the motions), `state` (how the
//! program or a REPL entry ended: time, exception, refused goal, path
//! positions; `done` when the program has ended).

use crate::services::RobotState;
use crate::services::record::{self, Sample};
use std::io::Write;
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, Sender};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// What every page gets: the events so far, and a channel to each open page.
#[derive(Default)]
pub struct Hub {
    inner: Mutex<Inner>,
}

#[derive(Default)]
struct Inner {
    history: Vec<Arc<str>>,
    pages: Vec<Sender<Arc<str>>>,
    threads: Vec<std::thread::JoinHandle<()>>,
    connected: usize,
}

/// One Server-Sent Event: its name and its data, a `data:` line per line.
fn sse(event: &str, data: &str) -> String {
    let mut s = format!("event: {event}\n");
    for line in data.trim_end_matches('\n').split('\n') {
        s.push_str("data: ");
        s.push_str(line);
        s.push('\n');
    }
    s.push('\n');
    s
}

impl Hub {
    /// Sends an event to every open page (and keeps it for later ones).
    pub fn publish(&self, event: &str, data: &str) {
        let msg: Arc<str> = sse(event, data).into();
        let mut g = self.inner.lock().unwrap_or_else(|e| e.into_inner());
        g.history.push(msg.clone());
        // A page whose thread has ended (closed tab) is dropped here.
        g.pages.retain(|p| p.send(msg.clone()).is_ok());
    }

    /// A new page: the events so far and a channel for the next ones.
    fn subscribe(&self) -> (Vec<Arc<str>>, Receiver<Arc<str>>) {
        let (tx, rx) = mpsc::channel();
        let mut g = self.inner.lock().unwrap_or_else(|e| e.into_inner());
        g.pages.push(tx);
        g.connected += 1;
        (g.history.clone(), rx)
    }

    /// How many pages have connected so far.
    pub fn connected(&self) -> usize {
        self.inner.lock().map(|g| g.connected).unwrap_or(0)
    }

    /// Waits up to `wait` for a first page to connect.
    pub fn wait_for_page(&self, wait: Duration) -> bool {
        let until = Instant::now() + wait;
        while self.connected() == 0 {
            if Instant::now() >= until {
                return false;
            }
            std::thread::sleep(Duration::from_millis(20));
        }
        true
    }

    /// The program has ended: every open page gets what is left to send,
    /// for at most `wait`, then its stream ends.
    pub fn finish(&self, wait: Duration) {
        let threads = {
            let mut g = self.inner.lock().unwrap_or_else(|e| e.into_inner());
            g.pages.clear();
            std::mem::take(&mut g.threads)
        };
        let until = Instant::now() + wait;
        for t in threads {
            while !t.is_finished() && Instant::now() < until {
                std::thread::sleep(Duration::from_millis(10));
            }
        }
    }
}

/// The running server: its address and its hub.
pub struct Server {
    pub port: u16,
    pub hub: Arc<Hub>,
    /// A browser was started on the page (`run` then waits for it).
    pub opened: bool,
}

impl Server {
    /// Listens on 127.0.0.1:`port` (0: any free port) and serves the live
    /// page and its event stream from a thread of its own.
    pub fn start(port: u16) -> Result<Server, String> {
        let http = tiny_http::Server::http(("127.0.0.1", port))
            .map_err(|e| format!("cannot listen on 127.0.0.1:{port}: {e}"))?;
        let port = http
            .server_addr()
            .to_ip()
            .map(|a| a.port())
            .ok_or("no port")?;
        let hub = Arc::new(Hub::default());
        let h = hub.clone();
        std::thread::Builder::new()
            .name("adair-view".into())
            .spawn(move || serve(http, h))
            .map_err(|e| format!("cannot start the view server: {e}"))?;
        Ok(Server {
            port,
            hub,
            opened: false,
        })
    }

    pub fn url(&self) -> String {
        format!("http://127.0.0.1:{}/", self.port)
    }

    /// What the services call on each motion: this server's watcher.
    pub fn watch(&self) -> Box<dyn record::Watch> {
        Box::new(HubWatch(self.hub.clone()))
    }
}

fn header(name: &str, value: &str) -> tiny_http::Header {
    tiny_http::Header::from_bytes(name.as_bytes(), value.as_bytes()).expect("a valid header")
}

fn serve(http: tiny_http::Server, hub: Arc<Hub>) {
    let page: Arc<str> = super::live_page().into();
    for req in http.incoming_requests() {
        let path = req.url().split('?').next().unwrap_or("").to_string();
        match path.as_str() {
            "/" | "/index.html" => {
                let r = tiny_http::Response::from_string(page.to_string())
                    .with_header(header("Content-Type", "text/html; charset=utf-8"))
                    .with_header(header("Cache-Control", "no-store"));
                let _ = req.respond(r);
            }
            "/events" => {
                let (history, rx) = hub.subscribe();
                let w = req.into_writer();
                if let Ok(t) = std::thread::Builder::new()
                    .name("adair-view-page".into())
                    .spawn(move || stream(w, history, rx))
                    && let Ok(mut g) = hub.inner.lock()
                {
                    g.threads.retain(|t| !t.is_finished());
                    g.threads.push(t);
                }
            }
            _ => {
                let _ =
                    req.respond(tiny_http::Response::from_string("not here").with_status_code(404));
            }
        }
    }
}

/// One page's stream: what happened so far, then each event as it comes,
/// a comment every 15 s so that a closed page is noticed. Ends when the
/// page is gone or the program has ended.
fn stream(mut w: Box<dyn Write + Send>, history: Vec<Arc<str>>, rx: Receiver<Arc<str>>) {
    let head = "HTTP/1.1 200 OK\r\nContent-Type: text/event-stream\r\nCache-Control: no-store\r\nConnection: close\r\n\r\n";
    if w.write_all(head.as_bytes()).is_err() {
        return;
    }
    for m in &history {
        if w.write_all(m.as_bytes()).is_err() {
            return;
        }
    }
    if w.flush().is_err() {
        return;
    }
    loop {
        let msg = match rx.recv_timeout(Duration::from_secs(15)) {
            Ok(m) => m,
            Err(RecvTimeoutError::Timeout) => ": still here\n\n".into(),
            Err(RecvTimeoutError::Disconnected) => return,
        };
        if w.write_all(msg.as_bytes()).is_err() || w.flush().is_err() {
            return;
        }
    }
}

/// The services' [`record::Watch`]: each motion to the hub as it starts.
pub struct HubWatch(pub Arc<Hub>);

fn csv_rows(samples: &[Sample]) -> String {
    let csv = record::to_csv(samples);
    match csv.split_once('\n') {
        Some((_, rows)) => rows.to_string(),
        None => String::new(),
    }
}

impl record::Watch for HubWatch {
    fn samples(&mut self, samples: &[Sample]) {
        self.0.publish("rows", &csv_rows(samples));
    }
    fn cut(&mut self, s: &Sample) {
        self.0.publish("cut", &csv_rows(std::slice::from_ref(s)));
    }
}

/// Makes the live view watch the run of `s`: each motion goes to the
/// pages as it starts, and they draw its robot. With a browser just opened
/// (`waits`), the run starts when that page is there (10 s at most); with
/// `--no-open` or no browser to start, at once.
pub fn attach(sv: &Server, s: &mut crate::session::Session, title: &str, waits: bool) {
    if let Some(w) = s.machine.world.as_mut() {
        w.set_sink(Some(device_sink(sv.hub.clone())));
    }
    let world = s.machine.world.as_ref();
    if let Some(st) = s.robot.as_mut() {
        st.watch = Some(sv.watch());
        publish_scene(&sv.hub, st, world, title);
    }
    if waits {
        sv.hub.wait_for_page(Duration::from_secs(10));
    }
}

/// What the device world calls with each moment: a `devices` event.
pub fn device_sink(hub: Arc<Hub>) -> crate::devices::Sink {
    Arc::new(move |m: &crate::devices::Moment| {
        hub.publish("devices", &super::moment_json(m).to_string())
    })
}

/// The `scene` event: the robot and devices (no path positions yet).
pub fn publish_scene(
    hub: &Hub,
    st: &RobotState,
    world: Option<&crate::devices::World>,
    title: &str,
) {
    let scene = super::scene_json(st, world, title, &super::Ending::default());
    let mut scene = scene;
    scene["end"] = serde_json::Value::Null;
    hub.publish("scene", &scene.to_string());
}

/// The `state` event: how the program (`done`) or a REPL entry ended.
pub fn publish_state(hub: &Hub, st: &RobotState, ending: &super::Ending, done: bool) {
    let v = serde_json::json!({
        "t": ending.t,
        "exception": ending.exception,
        "goal": ending.goal.as_ref().map(|p| p.to_rows()),
        "paths": super::paths_json(st),
        "done": done,
    });
    hub.publish("state", &v.to_string());
}

/// Opens `url` in the user's browser, when there is one to open.
pub fn open_browser(url: &str) -> Result<(), String> {
    let cmd = if cfg!(target_os = "macos") {
        "open"
    } else if cfg!(windows) {
        "explorer"
    } else {
        if std::env::var_os("DISPLAY").is_none() && std::env::var_os("WAYLAND_DISPLAY").is_none() {
            return Err("no display".into());
        }
        "xdg-open"
    };
    std::process::Command::new(cmd)
        .arg(url)
        .stdin(std::process::Stdio::null())
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .map(|_| ())
        .map_err(|e| format!("{cmd}: {e}"))
}

/// `--view` on the command line with no file after it (the next argument
/// is the program, another option or nothing) is written
/// `--view=` for clap: the live view.
pub fn bare_view_flag(args: Vec<std::ffi::OsString>) -> Vec<std::ffi::OsString> {
    let mut out = Vec::with_capacity(args.len());
    let mut it = args.into_iter().peekable();
    while let Some(a) = it.next() {
        let bare = it.peek().is_none_or(|n| {
            let n = n.to_string_lossy();
            n.starts_with('-') || n.ends_with(".air") || n.ends_with(".adb")
        });
        if a == "--view" && bare {
            out.push("--view=".into());
        } else {
            out.push(a);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_event_has_a_data_line_per_line() {
        assert_eq!(
            sse("rows", "1,2\n3,4\n"),
            "event: rows\ndata: 1,2\ndata: 3,4\n\n"
        );
    }

    #[test]
    fn a_bare_view_flag_is_the_live_view() {
        let a = |v: &[&str]| v.iter().map(std::ffi::OsString::from).collect::<Vec<_>>();
        assert_eq!(
            bare_view_flag(a(&["adair", "run", "--view", "x.air"])),
            a(&["adair", "run", "--view=", "x.air"])
        );
        assert_eq!(
            bare_view_flag(a(&["adair", "run", "--view", "x.html", "x.air"])),
            a(&["adair", "run", "--view", "x.html", "x.air"])
        );
        assert_eq!(
            bare_view_flag(a(&["adair", "repl", "--view"])),
            a(&["adair", "repl", "--view="])
        );
    }

    #[test]
    fn a_closed_page_is_dropped_and_the_program_goes_on() {
        let hub = Hub::default();
        let (_, rx) = hub.subscribe();
        drop(rx);
        hub.publish("rows", "1");
        hub.publish("rows", "2");
        assert!(hub.inner.lock().unwrap().pages.is_empty());
        assert_eq!(hub.inner.lock().unwrap().history.len(), 2);
    }
}
