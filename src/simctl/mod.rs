//! `adair sim-controller`: a virtual D/U-M1 (or Movemaster II unit) on a
//! pseudo-terminal, so the serial driver's real byte stream can be
//! exercised on a machine without a robot. The unit logic is in
//! [`unit`]; this module owns the pty, timing, the byte log and faults.

pub mod unit;

use crate::kinematics::RobotDescription;
use std::io::{Read, Write};
use std::time::{Duration, Instant};

/// Faults to inject (commands are counted from 1).
#[derive(Clone, Debug, Default)]
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
}

/// A timestamped log of every byte each way.
struct Log {
    out: Option<std::fs::File>,
    start: Instant,
}

impl Log {
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

/// Opens a pseudo-terminal, writes its device path as one line to `path_out`,
/// and serves the unit on it until the line is hung up (a fault) or the
/// process ends.
pub fn serve(
    desc: RobotDescription,
    faults: Faults,
    log: Option<std::fs::File>,
    path_out: &mut dyn Write,
) -> Result<(), String> {
    use nix::sys::termios;
    let pty = nix::pty::openpty(None, None).map_err(|e| format!("no pseudo-terminal: {e}"))?;
    // Raw: the line discipline must neither echo nor turn CR into LF.
    let mut t = termios::tcgetattr(&pty.slave).map_err(|e| format!("termios: {e}"))?;
    termios::cfmakeraw(&mut t);
    termios::tcsetattr(&pty.slave, termios::SetArg::TCSANOW, &t)
        .map_err(|e| format!("termios: {e}"))?;
    let path = nix::unistd::ttyname(&pty.slave).map_err(|e| format!("ttyname: {e}"))?;
    writeln!(path_out, "{}", path.display()).map_err(|e| e.to_string())?;
    let _ = path_out.flush();
    // The slave stays open here too, so that the driver closing and
    // re-opening the port does not hang up the master.
    let _slave = pty.slave;
    let mut master = std::fs::File::from(pty.master);
    let mut log = Log {
        out: log,
        start: Instant::now(),
    };
    let mut unit = unit::DriveUnit::new(desc);
    let scale = if faults.time_scale > 0.0 {
        faults.time_scale
    } else {
        1.0
    };
    let mut busy_until = Instant::now();
    let mut count: u64 = 0;
    let mut buf: Vec<u8> = Vec::new();
    let mut chunk = [0u8; 512];
    loop {
        let n = match master.read(&mut chunk) {
            Ok(0) => return Ok(()),
            Ok(n) => n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            // EIO: no process has the slave open (cannot happen while we
            // hold it); treat as the end.
            Err(_) => return Ok(()),
        };
        log.record("<", &chunk[..n]);
        buf.extend_from_slice(&chunk[..n]);
        while let Some(i) = buf.iter().position(|b| *b == b'\r' || *b == b'\n') {
            let raw: Vec<u8> = buf.drain(..=i).collect();
            let line = String::from_utf8_lossy(&raw[..raw.len() - 1])
                .trim()
                .to_string();
            if line.is_empty() {
                continue;
            }
            count += 1;
            // The unit executes one line at a time: the next waits for the
            // running motion (CTS low).
            let now = Instant::now();
            if busy_until > now {
                std::thread::sleep(busy_until - now);
            }
            let outcome = match faults.refuse {
                Some((k, mode)) if k == count => {
                    unit.error = mode;
                    unit::Outcome::default()
                }
                _ => unit.handle(&line),
            };
            busy_until = Instant::now() + Duration::from_secs_f64(outcome.busy * scale);
            if let Some(mut reply) = outcome.reply {
                let silent = faults.silent_after.is_some_and(|k| count > k);
                if !silent {
                    if faults.corrupt == Some(count) {
                        reply = format!("#{}", reply.replace(['0', '1', '2'], "?"));
                    }
                    if faults.slow > 0.0 {
                        std::thread::sleep(Duration::from_secs_f64(faults.slow));
                    }
                    let bytes = format!("{reply}\r\n");
                    log.record(">", bytes.as_bytes());
                    if master.write_all(bytes.as_bytes()).is_err() {
                        return Ok(());
                    }
                }
            }
            if faults.hangup_after.is_some_and(|k| count >= k) {
                log.record("x", b"hang up");
                return Ok(());
            }
        }
    }
}
