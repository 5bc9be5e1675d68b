//! `adair sim-controller`: a virtual D/U-M1 (or Movemaster II unit) on a
//! pseudo-terminal, so that the serial driver's real byte stream can be
//! tested on a machine without a robot.
//!
//! It is a test oracle, written from robots.md alone: it shares no code
//! with the driver (nothing from `crate::driver` or `crate::services`), so
//! a misreading of the manuals is not made twice and tested against itself.
//! From the rest of adair it takes only the robot file (link lengths,
//! limits, speeds, the nest pose, the controller's joint directions). The
//! command grammar is in [`line`], the arm (counters, limits, timing, the
//! `WH` pose and the unit's own inverse kinematics) in [`arm`], the units in
//! [`rv_m1`] and [`rm_501`]; this module owns the line, timing, the byte
//! log, faults and hand jogs.
//!
//! Where robots.md is silent the units behave as a strict real unit would;
//! the choices (each is also in docs/serial.md):
//! - A line is two capital letters, optional spaces, comma-separated
//!   arguments. Decimals may carry any number of digits after the point
//!   and are rounded to the least increment 0.1; integer arguments (position
//!   numbers, levels, counts) take no point. An unknown command, a wrong
//!   argument count, a malformed or out-of-range argument: error mode I on
//!   the RV-M1, the error mode on the RM-501.
//! - Ranges: positions 1..629, `SP` 0..9, `TL` 0..300 mm, `GP` 0..15,
//!   0..15, 0..99, `TI` 0..32767, `OD` -32768..32767 or `&H0`..`&HFFFF`,
//!   `MS` 1..99 points, decimals at most 9999.9, `MI` counts at most 32767.
//! - The unit executes one line at a time: a line that arrives while the
//!   arm moves (or dwells, or works the hand) waits until it stands, so
//!   `ER` is answered only after the motion has ended. In an error mode the
//!   RV-M1 ignores every line except `ER` and `RS` (`WH` too is
//!   unanswered), the RM-501 every line except `RS`.
//! - Power-on: the arm stands at the robot file's nest pose (as if nested
//!   from the teach box), speed level 4, the robot file's tool length, the
//!   hand open. The RV-M1's `OG` origin is the nest.
//! - Motion time: the slowest joint's travel over its speed, each joint at
//!   `max_speed * max(L, 1) / 9` for level L (adair's model of the levels);
//!   `GO`/`GC` 0.3 s, `TI n` n x 0.1 s; `--time-scale` multiplies all of
//!   them. `MP`, `MO`, `MC` are joint moves; `MS` and `DW` straight lines
//!   whose intermediate points (`MS`: k of them, `DW`: every 10 mm) must all
//!   be reachable.
//! - `WH`'s `p` is wrapped into -180 .. 180. `MP`/`MO` solve with J1
//!   pointing at the target (or away from it), p read in that arm plane,
//!   J5 = r (not wrapped), choosing the reachable solution soonest reached.
//! - Hand jogs (the arm moved by the operator's teach box) move each joint
//!   by the given controller degrees and stop at its limit (clamped, the
//!   way a teach box stops); they are applied when the arm stands, never in
//!   the middle of a line's motion, in any mode.

pub mod arm;
pub mod line;
pub mod rm_501;
pub mod rv_m1;
#[cfg(test)]
mod tests;

use crate::kinematics::{JOINTS, RobotDescription};
use std::collections::VecDeque;
use std::io::{Read, Write};
use std::path::PathBuf;
use std::time::{Duration, Instant};

/// A unit's error mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Error {
    /// None.
    None,
    /// Error mode I: a command the unit refused (`ER` answers 1).
    Command,
    /// Error mode II: a position out of range (`ER` answers 2).
    Position,
}

impl Error {
    /// The digit `ER` answers.
    pub fn digit(self) -> u8 {
        match self {
            Error::None => 0,
            Error::Command => 1,
            Error::Position => 2,
        }
    }
}

/// What the unit does with one line.
#[derive(Debug, Default, PartialEq)]
pub struct Outcome {
    /// The reply line (without its CR LF), if the command has one.
    pub reply: Option<String>,
    /// Seconds the arm moves (or dwells) for this line, before the time
    /// scale.
    pub busy: f64,
}

impl Outcome {
    fn reply(text: String) -> Outcome {
        Outcome {
            reply: Some(text),
            busy: 0.0,
        }
    }

    fn busy(seconds: f64) -> Outcome {
        Outcome {
            reply: None,
            busy: seconds,
        }
    }
}

/// One of the two drive units.
#[derive(Clone, Debug)]
pub enum DriveUnit {
    /// The RV-M1's D/U-M1.
    RvM1(rv_m1::DuM1),
    /// The RM-501's Movemaster II unit.
    Rm501(rm_501::Movemaster2),
}

impl DriveUnit {
    /// The unit for the robot file's robot: the Movemaster II unit for the
    /// RM-501, the D/U-M1 for every other.
    pub fn new(desc: RobotDescription) -> DriveUnit {
        if desc.name().eq_ignore_ascii_case("RM-501") {
            DriveUnit::Rm501(rm_501::Movemaster2::new(desc))
        } else {
            DriveUnit::RvM1(rv_m1::DuM1::new(desc))
        }
    }

    /// Handles one line (without its CR).
    pub fn handle(&mut self, line: &str) -> Outcome {
        match self {
            DriveUnit::RvM1(u) => u.handle(line),
            DriveUnit::Rm501(u) => u.handle(line),
        }
    }

    /// The current error mode.
    pub fn error(&self) -> Error {
        match self {
            DriveUnit::RvM1(u) => u.error,
            DriveUnit::Rm501(u) => u.error,
        }
    }

    /// Puts the unit in an error mode (the `--refuse` fault).
    pub fn set_error(&mut self, e: Error) {
        match self {
            DriveUnit::RvM1(u) => u.error = e,
            DriveUnit::Rm501(u) => u.error = e,
        }
    }

    /// The arm.
    pub fn arm(&self) -> &arm::Arm {
        match self {
            DriveUnit::RvM1(u) => &u.arm,
            DriveUnit::Rm501(u) => &u.arm,
        }
    }

    /// The arm, to move by hand.
    pub fn arm_mut(&mut self) -> &mut arm::Arm {
        match self {
            DriveUnit::RvM1(u) => &mut u.arm,
            DriveUnit::Rm501(u) => &mut u.arm,
        }
    }
}

/// Faults to inject and hand jogs (commands are counted from 1).
#[derive(Clone, Debug)]
pub struct Faults {
    /// Answer nothing after this many commands.
    pub silent_after: Option<u64>,
    /// Garble the reply to this command.
    pub corrupt: Option<u64>,
    /// Close the line after this many commands.
    pub hangup_after: Option<u64>,
    /// Refuse this command with error mode 1 or 2 instead of executing it.
    pub refuse: Option<(u64, u8)>,
    /// Seconds added before every reply.
    pub slow: f64,
    /// Motion times are multiplied by this (1.0 = the arm's own speed).
    pub time_scale: f64,
    /// After the Nth command has been executed (and its motion ended), the
    /// arm is moved by hand by these controller degrees per joint.
    pub jog_after: Vec<(u64, [f64; JOINTS])>,
    /// A file or FIFO polled for `jog D1,D2,D3,D4,D5` lines.
    pub control: Option<PathBuf>,
}

impl Default for Faults {
    fn default() -> Self {
        Faults {
            silent_after: None,
            corrupt: None,
            hangup_after: None,
            refuse: None,
            slow: 0.0,
            time_scale: 1.0,
            jog_after: Vec::new(),
            control: None,
        }
    }
}

impl Faults {
    /// Whether the numbers make sense: a finite positive time scale, a
    /// finite non-negative `slow`, finite jogs.
    pub fn check(&self) -> Result<(), String> {
        let t = self.time_scale;
        if !t.is_finite() || t <= 0.0 {
            return Err(format!("--time-scale {t}: must be a finite number above 0"));
        }
        let s = self.slow;
        if !s.is_finite() || s < 0.0 {
            return Err(format!(
                "--slow {s}: must be a finite number of seconds, 0 or more"
            ));
        }
        if let Some((_, d)) = self
            .jog_after
            .iter()
            .find(|(_, d)| !d.iter().all(|v| v.is_finite()))
        {
            return Err(format!("--jog-after: {d:?} is not five finite numbers"));
        }
        Ok(())
    }
}

/// Parses `--jog-after N:D1,D2,D3,D4,D5`.
pub fn parse_jog_after(s: &str) -> Result<(u64, [f64; JOINTS]), String> {
    let (n, d) = s
        .split_once(':')
        .ok_or_else(|| format!("`{s}`: expected N:D1,D2,D3,D4,D5, e.g. 3:+10.0,0,0,0,0"))?;
    let n: u64 = n
        .trim()
        .parse()
        .map_err(|_| format!("`{s}`: N is not a command count"))?;
    let d = parse_degrees(d).ok_or_else(|| format!("`{s}`: expected five finite degrees"))?;
    Ok((n, d))
}

/// Five comma-separated finite numbers.
fn parse_degrees(s: &str) -> Option<[f64; JOINTS]> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    if parts.len() != JOINTS {
        return None;
    }
    let mut out = [0.0; JOINTS];
    for (o, p) in out.iter_mut().zip(parts) {
        *o = p.parse::<f64>().ok().filter(|v| v.is_finite())?;
    }
    Some(out)
}

/// A timestamped log of every byte each way, and of hand jogs.
pub struct Log {
    out: Option<Box<dyn Write + Send>>,
    start: Instant,
}

impl Log {
    /// A log into `out` (none: nothing is logged), time 0 now.
    pub fn new(out: Option<Box<dyn Write + Send>>) -> Log {
        Log {
            out,
            start: Instant::now(),
        }
    }

    /// One line: seconds since the start, the direction (`<` received, `>`
    /// sent, `j` hand jog, `x` hang-up, `?` a control line not understood)
    /// and the bytes, escaped.
    fn record(&mut self, dir: &str, bytes: &[u8]) {
        if let Some(f) = &mut self.out {
            let text: String = bytes.escape_ascii().map(char::from).collect();
            let _ = writeln!(
                f,
                "{:10.4} {dir} {text}",
                self.start.elapsed().as_secs_f64()
            );
            let _ = f.flush();
        }
    }
}

/// What [`Link::receive`] got.
#[derive(Debug, PartialEq)]
pub enum Received {
    /// Bytes from the line.
    Bytes(Vec<u8>),
    /// Nothing within the timeout.
    Nothing,
    /// The line is gone.
    Closed,
}

/// The serial line as the unit sees it.
pub trait Link {
    /// Waits at most `timeout` for bytes.
    fn receive(&mut self, timeout: Duration) -> Received;
    /// Sends `bytes`; false when the line is gone.
    fn send(&mut self, bytes: &[u8]) -> bool;
}

/// The control channel: a file or FIFO read without blocking.
struct Control {
    file: std::fs::File,
    partial: Vec<u8>,
}

impl Control {
    /// Opens `path` for polling, creating an empty file when there is none.
    fn open(path: &std::path::Path) -> Result<Control, String> {
        use std::os::unix::fs::OpenOptionsExt;
        let named = |e: std::io::Error| format!("control file {}: {e}", path.display());
        if !path.exists() {
            std::fs::OpenOptions::new()
                .write(true)
                .create(true)
                .truncate(false)
                .open(path)
                .map_err(named)?;
        }
        // Non-blocking: a FIFO opens at once without a writer and reads
        // "nothing" instead of waiting.
        let file = std::fs::OpenOptions::new()
            .read(true)
            .custom_flags(nix::fcntl::OFlag::O_NONBLOCK.bits())
            .open(path)
            .map_err(named)?;
        Ok(Control {
            file,
            partial: Vec::new(),
        })
    }

    /// The complete lines written since the last poll.
    fn poll(&mut self) -> Vec<String> {
        let mut chunk = [0u8; 512];
        loop {
            match self.file.read(&mut chunk) {
                Ok(0) => break,
                Ok(n) => self.partial.extend_from_slice(&chunk[..n]),
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
                Err(_) => break,
            }
        }
        let mut lines = Vec::new();
        while let Some(i) = self.partial.iter().position(|b| *b == b'\n') {
            let raw: Vec<u8> = self.partial.drain(..=i).collect();
            let text = String::from_utf8_lossy(&raw).trim().to_string();
            if !text.is_empty() {
                lines.push(text);
            }
        }
        lines
    }
}

/// How often the control channel is looked at while nothing arrives.
const POLL: Duration = Duration::from_millis(20);

/// `now + seconds`, saturating (a huge time scale must not panic).
fn after(now: Instant, seconds: f64) -> Instant {
    Duration::try_from_secs_f64(seconds)
        .ok()
        .and_then(|d| now.checked_add(d))
        .or_else(|| now.checked_add(Duration::from_secs(1 << 32)))
        .unwrap_or(now)
}

/// A hand jog's degrees as logged: one decimal when that is exact.
fn jog_text(deg: &[f64; JOINTS]) -> String {
    let parts: Vec<String> = deg
        .iter()
        .map(|v| {
            let v = if *v == 0.0 { 0.0 } else { *v };
            if ((v * 10.0).round() - v * 10.0).abs() < 1e-9 {
                format!("{v:+.1}")
            } else {
                format!("{v:+.3}")
            }
        })
        .collect();
    parts.join(",")
}

/// The unit on a line: takes lines as they arrive, executes them one at a
/// time, answers, injects faults and hand jogs.
pub struct Station {
    /// The drive unit.
    pub unit: DriveUnit,
    faults: Faults,
    log: Log,
    control: Option<Control>,
    busy_until: Instant,
    count: u64,
    partial: Vec<u8>,
    lines: VecDeque<String>,
    jogs: VecDeque<[f64; JOINTS]>,
}

impl Station {
    /// A station for `unit`; opens the control channel if there is one.
    pub fn new(unit: DriveUnit, faults: Faults, log: Log) -> Result<Station, String> {
        faults.check()?;
        let control = match &faults.control {
            Some(p) => Some(Control::open(p)?),
            None => None,
        };
        Ok(Station {
            unit,
            faults,
            log,
            control,
            busy_until: Instant::now(),
            count: 0,
            partial: Vec::new(),
            lines: VecDeque::new(),
            jogs: VecDeque::new(),
        })
    }

    /// Serves `link` until it closes or the hang-up fault ends the line.
    pub fn run(&mut self, link: &mut dyn Link) {
        loop {
            let now = Instant::now();
            if now >= self.busy_until {
                while let Some(d) = self.jogs.pop_front() {
                    let moved = self.unit.arm_mut().jog(&d);
                    self.log.record("j", jog_text(&moved).as_bytes());
                }
                if let Some(line) = self.lines.pop_front() {
                    if !self.execute(&line, link) {
                        return;
                    }
                    continue;
                }
            }
            let wait = if now < self.busy_until {
                (self.busy_until - now).min(POLL)
            } else {
                POLL
            };
            match link.receive(wait) {
                Received::Bytes(b) => {
                    self.log.record("<", &b);
                    self.take(&b);
                }
                Received::Nothing => {}
                Received::Closed => return,
            }
            self.poll_control();
        }
    }

    /// Splits received bytes into lines (CR or LF ends one; empty lines
    /// are no commands).
    fn take(&mut self, bytes: &[u8]) {
        self.partial.extend_from_slice(bytes);
        while let Some(i) = self.partial.iter().position(|b| *b == b'\r' || *b == b'\n') {
            let raw: Vec<u8> = self.partial.drain(..=i).collect();
            let line = String::from_utf8_lossy(&raw[..raw.len() - 1]).to_string();
            if !line.trim().is_empty() {
                self.lines.push_back(line);
            }
        }
    }

    fn poll_control(&mut self) {
        let Some(c) = &mut self.control else {
            return;
        };
        for l in c.poll() {
            let jog = l
                .strip_prefix("jog")
                .filter(|r| r.starts_with([' ', '\t']))
                .and_then(parse_degrees);
            match jog {
                Some(d) => self.jogs.push_back(d),
                None => self.log.record("?", l.as_bytes()),
            }
        }
    }

    /// Executes one line; false when the line is to be hung up.
    fn execute(&mut self, line: &str, link: &mut dyn Link) -> bool {
        self.count += 1;
        let count = self.count;
        let outcome = match self.faults.refuse {
            Some((k, mode)) if k == count => {
                let e = if mode == 2 {
                    Error::Position
                } else {
                    Error::Command
                };
                self.unit.set_error(e);
                Outcome::default()
            }
            _ => self.unit.handle(line),
        };
        self.busy_until = after(Instant::now(), outcome.busy * self.faults.time_scale);
        if let Some(mut reply) = outcome.reply {
            let silent = self.faults.silent_after.is_some_and(|k| count > k);
            if !silent {
                if self.faults.corrupt == Some(count) {
                    reply = format!("#{}", reply.replace(['0', '1', '2'], "?"));
                }
                if self.faults.slow > 0.0 {
                    std::thread::sleep(
                        Duration::try_from_secs_f64(self.faults.slow).unwrap_or(Duration::MAX),
                    );
                }
                let bytes = format!("{reply}\r\n");
                self.log.record(">", bytes.as_bytes());
                if !link.send(bytes.as_bytes()) {
                    return false;
                }
            }
        }
        for (_, d) in self.faults.jog_after.iter().filter(|(n, _)| *n == count) {
            self.jogs.push_back(*d);
        }
        if self.faults.hangup_after.is_some_and(|k| count >= k) {
            self.log.record("x", b"hang up");
            return false;
        }
        true
    }
}

/// The pseudo-terminal's master side: a thread reads it (blocking) into a
/// channel, so that the station can wait with a timeout.
struct PtyLink {
    master: std::fs::File,
    rx: std::sync::mpsc::Receiver<Received>,
}

impl Link for PtyLink {
    fn receive(&mut self, timeout: Duration) -> Received {
        use std::sync::mpsc::RecvTimeoutError;
        match self.rx.recv_timeout(timeout) {
            Ok(r) => r,
            Err(RecvTimeoutError::Timeout) => Received::Nothing,
            Err(RecvTimeoutError::Disconnected) => Received::Closed,
        }
    }

    fn send(&mut self, bytes: &[u8]) -> bool {
        self.master.write_all(bytes).is_ok()
    }
}

/// Opens a pseudo-terminal, writes its device path as one line to `path_out`,
/// and serves the unit for `desc` on it until the line is hung up (a fault)
/// or the process ends.
pub fn serve(
    desc: RobotDescription,
    faults: Faults,
    log: Option<std::fs::File>,
    path_out: &mut dyn Write,
) -> Result<(), String> {
    use nix::sys::termios;
    let log = Log::new(log.map(|f| Box::new(f) as Box<dyn Write + Send>));
    let mut station = Station::new(DriveUnit::new(desc), faults, log)?;
    let pty = nix::pty::openpty(None, None).map_err(|e| format!("no pseudo-terminal: {e}"))?;
    // Raw: the line discipline must neither echo nor turn CR into LF.
    let mut t = termios::tcgetattr(&pty.slave).map_err(|e| format!("termios: {e}"))?;
    termios::cfmakeraw(&mut t);
    termios::tcsetattr(&pty.slave, termios::SetArg::TCSANOW, &t)
        .map_err(|e| format!("termios: {e}"))?;
    let path = nix::unistd::ttyname(&pty.slave).map_err(|e| format!("ttyname: {e}"))?;
    // The slave stays open here too, so that the driver closing and
    // re-opening the port does not hang up the master.
    let _slave = pty.slave;
    let master = std::fs::File::from(pty.master);
    let mut reader = master.try_clone().map_err(|e| format!("pty: {e}"))?;
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let mut chunk = [0u8; 512];
        loop {
            match reader.read(&mut chunk) {
                Ok(0) => break,
                Ok(n) => {
                    if tx.send(Received::Bytes(chunk[..n].to_vec())).is_err() {
                        return;
                    }
                }
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
                // EIO: no process has the slave open (cannot happen while
                // we hold it); the end.
                Err(_) => break,
            }
        }
        let _ = tx.send(Received::Closed);
    });
    writeln!(path_out, "{}", path.display()).map_err(|e| e.to_string())?;
    let _ = path_out.flush();
    station.run(&mut PtyLink { master, rx });
    Ok(())
}
