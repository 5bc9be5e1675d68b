//! The serial driver: the robot's own controller language over RS-232
//! (robots.md). The driver tracks the joint state itself, sends joint moves
//! (`MJ` degrees on the RV-M1, `MI` counts on the RM-501), checks every motion
//! with `ER` (RV-M1; the reply comes when the motion has ended) and re-reads
//! `WH` after every fault, so the state the program sees is the arm's.
//! Every read has a timeout; nothing blocks forever.

use super::protocol::{self, Unit};
use super::{DriverError, GripperState, Robot, wh};
use crate::kinematics::{JOINTS, Joints, Kinematics, RobotDescription};
use std::io::{Read, Write};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// A line-oriented link to a unit: the serial port, or a test double.
pub trait Link {
    /// Sends one command line (the link appends CR).
    fn send(&mut self, line: &str) -> Result<(), DriverError>;
    /// The next reply line (ended by CR, LF or CR LF) within `timeout`.
    fn read_line(&mut self, timeout: Duration) -> Result<String, DriverError>;
    /// Drops whatever the unit sent that nobody asked for (a reply sent
    /// twice, line noise), so that the next reply read is the answer to
    /// the next question.
    fn discard_input(&mut self) {}
}

/// How to reach the unit.
#[derive(Clone, Debug)]
pub struct PortSettings {
    pub path: String,
    pub baud: u32,
    /// Seconds a reply may take beyond a motion's expected time.
    pub timeout: f64,
}

/// A `serialport` port as a [`Link`].
pub struct SerialLink {
    port: Box<dyn serialport::SerialPort>,
    buf: Vec<u8>,
    interrupt: Option<Arc<AtomicBool>>,
}

impl SerialLink {
    /// Opens the port with the unit's framing; a port that does not open is
    /// `NoConnection` naming the port and the OS error.
    pub fn open(
        s: &PortSettings,
        unit: Unit,
        interrupt: Option<Arc<AtomicBool>>,
    ) -> Result<SerialLink, DriverError> {
        let (data, stop) = unit.framing();
        let port = serialport::new(&s.path, s.baud)
            .data_bits(if data == 7 {
                serialport::DataBits::Seven
            } else {
                serialport::DataBits::Eight
            })
            .parity(serialport::Parity::Even)
            .stop_bits(if stop == 2 {
                serialport::StopBits::Two
            } else {
                serialport::StopBits::One
            })
            .flow_control(serialport::FlowControl::Hardware)
            .timeout(Duration::from_millis(50))
            .open()
            .map_err(|e| DriverError::NoConnection(format!("port {}: {e}", s.path)))?;
        Ok(SerialLink {
            port,
            buf: Vec::new(),
            interrupt,
        })
    }
}

impl Link for SerialLink {
    fn send(&mut self, line: &str) -> Result<(), DriverError> {
        let mut bytes = line.as_bytes().to_vec();
        bytes.push(b'\r');
        self.port
            .write_all(&bytes)
            .and_then(|()| self.port.flush())
            .map_err(|e| DriverError::Fatal(format!("writing `{line}`: {e}")))
    }

    fn read_line(&mut self, timeout: Duration) -> Result<String, DriverError> {
        let end = Instant::now() + timeout;
        loop {
            // A complete line in the buffer (CR, LF or CR LF; empty lines are
            // the second half of a CR LF).
            while let Some(i) = self.buf.iter().position(|b| *b == b'\r' || *b == b'\n') {
                let line: Vec<u8> = self.buf.drain(..=i).collect();
                let text = String::from_utf8_lossy(&line[..line.len() - 1]).to_string();
                if !text.trim().is_empty() {
                    return Ok(text.trim().to_string());
                }
            }
            if self
                .interrupt
                .as_ref()
                .is_some_and(|f| f.swap(false, Ordering::SeqCst))
            {
                return Err(DriverError::Interrupted);
            }
            if Instant::now() >= end {
                return Err(DriverError::Lost(format!(
                    "no reply within {:.1} s",
                    timeout.as_secs_f64()
                )));
            }
            let mut chunk = [0u8; 256];
            match self.port.read(&mut chunk) {
                Ok(0) => return Err(DriverError::Fatal("the port reached end of file".into())),
                Ok(n) => self.buf.extend_from_slice(&chunk[..n]),
                Err(e) if e.kind() == std::io::ErrorKind::TimedOut => {}
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
                Err(e) => return Err(DriverError::Fatal(format!("reading: {e}"))),
            }
        }
    }

    fn discard_input(&mut self) {
        self.buf.clear();
        let _ = self.port.clear(serialport::ClearBuffer::Input);
    }
}

/// How far past a limit a joint read from `WH` may come out (0.1 degree:
/// the reply's rounding of 0.1 mm and 0.1 degree, at the arm's lengths).
const WH_SLACK: f64 = 0.1 * std::f64::consts::PI / 180.0;

/// A motion the unit has been sent and not yet waited for.
struct Pending {
    /// Seconds the motion is expected to take (the reply may take as long).
    expected: f64,
    /// The last line sent, for messages.
    last: String,
    /// When the service may return: the motion's start plus its time. The
    /// RM-501, which never answers, is timed by this alone; a `Time =>`
    /// motion on the RV-M1 waits out the rest after the unit's `ER`.
    until: Option<Instant>,
}

/// Opens links: the real port, or (in tests) anything else.
pub type Opener = Box<dyn FnMut(Unit) -> Result<Box<dyn Link>, DriverError>>;

/// The serial driver.
pub struct Serial {
    kin: Kinematics,
    /// The model with its limits widened by `WH`'s resolution, for reading
    /// the arm's pose: an arm at a limit may read a rounding past it.
    wh_kin: Kinematics,
    unit: Unit,
    settings: PortSettings,
    open: Opener,
    link: Option<Box<dyn Link>>,
    /// The joints the arm has (as far as the driver knows).
    joints: Joints,
    /// The controller position the commands add up to (controller deg).
    sent: [f64; JOINTS],
    gripper: GripperState,
    /// The speed level the unit has (`SP`), when known.
    speed: Option<u8>,
    /// The level the program's velocity asks for (`SetVelocity`); a timed
    /// motion may set another for its own time.
    level: u8,
    interrupt: Option<Arc<AtomicBool>>,
    /// A started motion not yet waited for.
    pending: Option<Pending>,
    /// The joints before the motion under way: where the arm is when the
    /// unit refuses it (the hint for `WH`, which cannot say J1 with the
    /// tool on the waist axis).
    before: Option<Joints>,
}

impl Serial {
    /// A driver for `desc` on the port of `settings`; the port opens at `init`.
    pub fn new(
        desc: RobotDescription,
        settings: PortSettings,
        interrupt: Option<Arc<AtomicBool>>,
    ) -> Serial {
        let s2 = settings.clone();
        let flag = interrupt.clone();
        let open: Opener = Box::new(move |unit| {
            SerialLink::open(&s2, unit, flag.clone()).map(|l| Box::new(l) as Box<dyn Link>)
        });
        Serial::with_opener(desc, settings, open, interrupt)
    }

    pub fn with_opener(
        desc: RobotDescription,
        settings: PortSettings,
        open: Opener,
        interrupt: Option<Arc<AtomicBool>>,
    ) -> Serial {
        let unit = Unit::of_robot(desc.name());
        let nest = desc.nest();
        let sent = desc.to_controller_deg(&nest);
        let opening = desc.gripper().opening_max;
        Serial {
            wh_kin: Kinematics::new(desc.with_limits_widened(WH_SLACK)),
            kin: Kinematics::new(desc),
            unit,
            settings,
            open,
            link: None,
            joints: nest,
            sent,
            gripper: GripperState {
                opening,
                force: 0.0,
            },
            speed: None,
            level: protocol::level_of_percent(50.0),
            interrupt,
            pending: None,
            before: None,
        }
    }

    fn timeout(&self, expected: f64) -> Duration {
        Duration::from_secs_f64((expected.max(0.0) + self.settings.timeout).min(86_400.0))
    }

    fn link(&mut self) -> Result<&mut Box<dyn Link>, DriverError> {
        self.link.as_mut().ok_or_else(|| {
            DriverError::NoConnection(format!(
                "port {}: the link is down; InitRobot opens it again",
                self.settings.path
            ))
        })
    }

    /// Sends a line; a fatal error takes the link down. A motion still
    /// running (`Control => True`) is waited for first.
    fn send(&mut self, line: &str) -> Result<(), DriverError> {
        if !self.unit.knows(line) {
            // Never reached by the services: a line outside the unit's
            // command set would stop a real RM-501 without a sign.
            return Err(DriverError::Refused(format!(
                "adair does not send `{line}`: the {} has no such command",
                self.kin.description().name()
            )));
        }
        self.send_any(line)
    }

    /// Sends a line without looking it up: the probe `ER` at the start.
    fn send_any(&mut self, line: &str) -> Result<(), DriverError> {
        if self.pending.is_some() {
            self.wait_motion()?;
        }
        let link = self.link()?;
        // A question's answer is the next line the unit sends: nothing
        // left over from before (a reply sent twice) may stand in for it.
        if ["ER", "WH", "DR"].contains(&protocol::split(line).0.as_str()) {
            link.discard_input();
        }
        let r = link.send(line);
        self.check_fatal(r)
    }

    /// The seconds the unit takes for joint moves through `points` from
    /// the pose it has, at speed level `level` (adair's model of the unit:
    /// each line at the slowest joint's share of its maximum speed).
    fn unit_time(&self, points: &[Joints], level: u8) -> f64 {
        let desc = self.kin.description();
        let f = protocol::level_fraction(level);
        let mut from = self.joints;
        let mut t = 0.0;
        for p in points {
            let line = desc
                .joints()
                .iter()
                .enumerate()
                .map(|(j, spec)| (p[j] - from[j]).abs() / (spec.max_speed * f))
                .fold(0.0, f64::max);
            t += line;
            from = *p;
        }
        t
    }

    /// Sends `SP level` unless the unit has it already.
    fn ensure_level(&mut self, level: u8) -> Result<(), DriverError> {
        if self.speed != Some(level) {
            self.send(&format!("SP {level}"))?;
            self.speed = Some(level);
        }
        Ok(())
    }

    fn read(&mut self, expected: f64) -> Result<String, DriverError> {
        let t = self.timeout(expected);
        let r = self.link()?.read_line(t);
        self.check_fatal(r)
    }

    fn check_fatal<T>(&mut self, r: Result<T, DriverError>) -> Result<T, DriverError> {
        if let Err(DriverError::Fatal(_)) = &r {
            self.link = None;
        }
        r
    }

    /// `ER`, waiting up to `expected` + the margin: the end of a motion.
    fn error_status(&mut self, expected: f64, line: &str) -> Result<(), DriverError> {
        self.send("ER")?;
        let reply = self.read(expected)?;
        match protocol::parse_er(&reply) {
            Some(0) => Ok(()),
            Some(mode) => {
                self.send("RS")?;
                Err(if mode == 1 {
                    DriverError::Refused(format!("the unit refused `{line}` (error mode I)"))
                } else {
                    DriverError::UnitOutOfRange(format!(
                        "the unit says `{line}` is out of range (error mode II); model and unit disagree"
                    ))
                })
            }
            None => Err(DriverError::Invalid(format!(
                "`ER` answered `{reply}`, not 0, 1 or 2"
            ))),
        }
    }

    /// `WH`: the joint state from the arm itself.
    fn where_is(&mut self, near: Joints) -> Result<Joints, DriverError> {
        let pose = self.wh_reply()?;
        self.take_pose(&pose, near)
    }

    /// Sends `WH` and parses its reply.
    fn wh_reply(&mut self) -> Result<[f64; 5], DriverError> {
        self.send("WH")?;
        let reply = self.read(0.0)?;
        protocol::parse_wh(&reply).ok_or_else(|| {
            DriverError::Invalid(format!("`WH` answered `{reply}`, not five numbers"))
        })
    }

    /// Takes the joints of a `WH` pose (the branch nearest `near`); a joint
    /// a rounding past its limit is the limit.
    fn take_pose(&mut self, pose: &[f64; 5], near: Joints) -> Result<Joints, DriverError> {
        let tl = self.kin.description().links().tool;
        let q = wh::to_joints(&self.wh_kin, pose, tl, &near).map(|mut q| {
            for (x, spec) in q.iter_mut().zip(self.kin.description().joints()) {
                *x = x.clamp(spec.min, spec.max);
            }
            q
        });
        let q = q.map_err(|e| {
            let shown: Vec<String> = pose.iter().map(|v| protocol::num(*v)).collect();
            DriverError::Invalid(format!(
                "`WH` answered `{}`, a pose the model cannot take: {e}",
                shown.join(",")
            ))
        })?;
        self.joints = q;
        self.sent = self.kin.description().to_controller_deg(&q);
        Ok(q)
    }

    /// After a fault: the joints from the arm, when the link is still up
    /// (after a user's stop the driver sends nothing more).
    fn resync(&mut self, e: DriverError) -> DriverError {
        let near = self.before.take().unwrap_or(self.joints);
        if self.unit == Unit::RvM1 && self.link.is_some() && e != DriverError::Interrupted {
            // A refused motion did not move the arm: without an answer for
            // J1, the one it had.
            self.joints = near;
            let _ = self.where_is(near);
        }
        e
    }

    fn sleep_interruptible(&mut self, seconds: f64) -> Result<(), DriverError> {
        let end = Instant::now() + Duration::from_secs_f64(seconds.clamp(0.0, 86_400.0));
        while Instant::now() < end {
            if self
                .interrupt
                .as_ref()
                .is_some_and(|f| f.swap(false, Ordering::SeqCst))
            {
                return Err(DriverError::Interrupted);
            }
            std::thread::sleep((end - Instant::now()).min(Duration::from_millis(20)));
        }
        Ok(())
    }

    /// Sends the lines of a motion; its end is checked by `finish`. A
    /// `timed` motion (`Time =>`) runs at the slowest speed level that ends
    /// it within `duration`, and the service returns at `duration`; any
    /// other runs at the program's level.
    fn motion(&mut self, points: &[Joints], duration: f64, timed: bool) -> Result<(), DriverError> {
        let desc = self.kin.description().clone();
        let level = if timed {
            (0..=9u8)
                .find(|l| self.unit_time(points, *l) <= duration + 1e-9)
                .unwrap_or(9)
        } else {
            self.level
        };
        // The RM-501 is timed by adair: the longer of the program's time
        // and the unit's own at its level.
        let own = self.unit_time(points, level);
        if self.pending.is_some() {
            self.wait_motion()?;
        }
        self.ensure_level(level)?;
        let start = Instant::now();
        self.before = Some(self.joints);
        let mut last = String::new();
        for p in points {
            let target = desc.to_controller_deg(p);
            match self.unit {
                Unit::RvM1 => {
                    let delta: [f64; JOINTS] =
                        std::array::from_fn(|j| ((target[j] - self.sent[j]) * 10.0).round() / 10.0);
                    if delta.iter().all(|d| *d == 0.0) {
                        continue;
                    }
                    last = protocol::mj(&delta);
                    self.send(&last)?;
                    for (s, d) in self.sent.iter_mut().zip(delta) {
                        *s += d;
                    }
                }
                Unit::Rm501 => {
                    let cpd = self.unit.counts_per_deg();
                    let counts: [i64; JOINTS] = std::array::from_fn(|j| {
                        ((target[j] - self.sent[j]) * cpd[j]).round() as i64
                    });
                    if counts.iter().all(|c| *c == 0) {
                        continue;
                    }
                    last = protocol::mi(&counts);
                    self.send(&last)?;
                    for ((s, c), k) in self.sent.iter_mut().zip(counts).zip(cpd) {
                        *s += c as f64 / k;
                    }
                }
            }
        }
        // The unit runs the lines: the arm ends at their target once the
        // motion has ended (or been stopped). The program's joints are the
        // target as commanded, the unit's are `sent` (0.1 deg or a count
        // from it): the next motion's lines are measured from `sent`, so
        // the rounding of one line is made good by the next and never adds
        // up.
        if let Some(last) = points.last() {
            self.joints = *last;
        }
        let wait = match self.unit {
            Unit::RvM1 => timed.then_some(duration),
            Unit::Rm501 => Some(duration.max(own)),
        };
        self.pending = Some(Pending {
            expected: duration.max(own),
            last,
            until: wait.map(|w| start + Duration::from_secs_f64(w.clamp(0.0, 86_400.0))),
        });
        Ok(())
    }

    /// Waits for the end of the pending motion.
    fn finish(&mut self) -> Result<(), DriverError> {
        let Some(p) = self.pending.take() else {
            return Ok(());
        };
        let mut r = match self.unit {
            // The reply to ER comes when the motion has ended.
            Unit::RvM1 => self.error_status(p.expected, &p.last),
            // The RM-501 never answers: adair times the move.
            Unit::Rm501 => Ok(()),
        };
        if r.is_ok()
            && let Some(until) = p.until
        {
            let rest = until.saturating_duration_since(Instant::now());
            r = self.sleep_interruptible(rest.as_secs_f64());
        }
        if r.is_ok() {
            self.before = None;
        }
        r
    }

    /// The RV-M1's pose as the unit reports it now (`WH`): where it agrees
    /// with the joints the unit was sent within `WH`'s resolution (0.1 mm, 0.1 deg)
    /// they stand, so no rounding creeps in; otherwise the arm was moved
    /// outside the program and its joints are taken from `WH`.
    fn fresh_pose(&mut self) -> Result<(), DriverError> {
        if self.unit != Unit::RvM1 || self.link.is_none() {
            return Ok(());
        }
        let tracked = self.joints;
        let pose = self.wh_reply()?;
        let tl = self.kin.description().links().tool;
        let unit = self.kin.description().from_controller_deg(&self.sent);
        let expected = wh::of_joints(&self.kin, &unit, tl);
        let agrees = (0..5).all(|i| {
            let mut d = (pose[i] - expected[i]).abs();
            // The angles `p` and `r` may be reported wrapped by a turn.
            if i >= 3 {
                d %= 360.0;
                d = d.min(360.0 - d);
            }
            d <= 0.1 + 1e-6
        });
        if !agrees {
            self.take_pose(&pose, tracked)?;
        }
        Ok(())
    }
}

impl Serial {
    fn start(&mut self, points: &[Joints], duration: f64, timed: bool) -> Result<(), DriverError> {
        for p in points {
            if let Err(v) = self.kin.description().check_limits(p) {
                return Err(DriverError::Limit(v.to_string()));
            }
        }
        let r = self.motion(points, duration, timed);
        r.map_err(|e| self.resync(e))
    }

    /// The RM-501's `NT`: it runs to its origin from wherever it is, which
    /// adair cannot know, so the wait is the longest such run at the fastest
    /// level (every joint from its farthest limit to `nest`).
    fn nest_rm501(&mut self) -> Result<(), DriverError> {
        self.ensure_level(9)?;
        self.send("NT")?;
        let desc = self.kin.description().clone();
        let nest = desc.nest();
        let worst = desc
            .joints()
            .iter()
            .enumerate()
            .map(|(j, spec)| {
                let far = (nest[j] - spec.min).abs().max((spec.max - nest[j]).abs());
                far / spec.max_speed
            })
            .fold(0.0, f64::max);
        self.sleep_interruptible(worst)?;
        self.joints = nest;
        self.sent = desc.to_controller_deg(&nest);
        Ok(())
    }

    /// The arm's pose without moving it (for `--rehearse`): `WH` on the
    /// RV-M1; the RM-501 cannot say, so its `nest`.
    pub fn read_pose(&mut self) -> Result<Joints, DriverError> {
        self.link = Some((self.open)(self.unit)?);
        self.send_any(protocol::PROBE)?;
        let answered = match self.read(0.0) {
            Ok(_) => true,
            Err(DriverError::Lost(_)) => false,
            Err(e) => return Err(e),
        };
        match (self.unit, answered) {
            (Unit::RvM1, true) => {
                self.send("RS")?;
                let tl = self.kin.description().links().tool;
                self.send(&format!("TL {}", protocol::num(tl)))?;
                let nest = self.kin.description().nest();
                self.where_is(nest)
            }
            (Unit::RvM1, false) => Err(DriverError::NoRobot(format!(
                "port {}: no reply to `ER`",
                self.settings.path
            ))),
            (Unit::Rm501, true) => Err(DriverError::WrongRobot(format!(
                "port {}: the unit answered `ER`: an RV-M1, not an RM-501",
                self.settings.path
            ))),
            (Unit::Rm501, false) => {
                self.send("RS")?;
                Ok(self.kin.description().nest())
            }
        }
    }
}

impl Robot for Serial {
    fn description(&self) -> &RobotDescription {
        self.kin.description()
    }
    fn joints(&self) -> Joints {
        self.joints
    }
    fn read_joints(&self) -> Joints {
        self.kin.description().quantize(&self.joints)
    }
    fn real_time(&self) -> bool {
        true
    }

    fn init(&mut self) -> Result<(), DriverError> {
        self.link = None;
        self.link = Some((self.open)(self.unit)?);
        // A reply to the first ER proves an RV-M1 is there; an RM-501 never
        // answers (and takes the unknown ER as a command error: RS clears it).
        self.send_any(protocol::PROBE)?;
        let answered = match self.read(0.0) {
            Ok(reply) => Some(reply),
            Err(DriverError::Lost(_)) => None,
            Err(e) => return Err(e),
        };
        match (self.unit, answered) {
            (Unit::RvM1, None) => {
                return Err(DriverError::NoRobot(format!(
                    "port {}: no reply to `ER` within {:.1} s: is the drive unit on and connected?",
                    self.settings.path, self.settings.timeout
                )));
            }
            (Unit::Rm501, Some(reply)) => {
                return Err(DriverError::WrongRobot(format!(
                    "port {}: the unit answered `ER` with `{reply}`: an RV-M1, not the RM-501 that --robot names",
                    self.settings.path
                )));
            }
            (Unit::RvM1, Some(reply)) => {
                if protocol::parse_er(&reply).is_none() {
                    return Err(DriverError::Invalid(format!(
                        "`ER` answered `{reply}`, not 0, 1 or 2"
                    )));
                }
                self.send("RS")?;
                let tl = self.kin.description().links().tool;
                self.send(&format!("TL {}", protocol::num(tl)))?;
                self.send("NT")?;
                // The nest run's length is not published: allow a minute.
                self.error_status(60.0, "NT")?;
                let nest = self.kin.description().nest();
                self.where_is(nest)?;
            }
            (Unit::Rm501, None) => {
                self.send("RS")?;
                self.speed = None;
                self.nest_rm501()?;
            }
        }
        self.speed = None;
        Ok(())
    }

    fn set_speed(&mut self, percent: f64) -> Result<(), DriverError> {
        self.level = protocol::level_of_percent(percent);
        if self.link.is_some() {
            self.ensure_level(self.level)?;
        }
        Ok(())
    }

    fn start_motion(&mut self, points: &[Joints], duration: f64) -> Result<(), DriverError> {
        self.start(points, duration, false)
    }

    fn start_timed_motion(&mut self, points: &[Joints], duration: f64) -> Result<(), DriverError> {
        self.start(points, duration, true)
    }

    fn refresh(&mut self) -> Result<(), DriverError> {
        let r = self.fresh_pose();
        r.map_err(|e| self.resync(e))
    }

    fn wait_motion(&mut self) -> Result<(), DriverError> {
        let r = self.finish();
        r.map_err(|e| self.resync(e))
    }

    fn motion_pending(&self) -> bool {
        self.pending.is_some()
    }

    fn stop_motion(&mut self) -> Result<(), DriverError> {
        // The unit cannot abort a line: send nothing more; it ends at the
        // line's target, which `joints` already is.
        self.pending = None;
        Ok(())
    }

    fn calibrate(&mut self) -> Result<(), DriverError> {
        match self.unit {
            Unit::RvM1 => {
                let near = self.joints;
                self.where_is(near)?;
            }
            // It cannot say where it is: `NT` finds the origin, and the
            // pose is the robot file's `nest` again.
            Unit::Rm501 => self.nest_rm501()?,
        }
        Ok(())
    }

    fn gripper(&self) -> GripperState {
        self.gripper
    }

    fn move_gripper(
        &mut self,
        opening: f64,
        force_limit: Option<f64>,
    ) -> Result<GripperState, DriverError> {
        let g = *self.kin.description().gripper();
        let line = if opening > self.gripper.opening || opening >= g.opening_max {
            "GO".to_string()
        } else {
            // The RV-M1's grip force levels 0..15 (start, hold) and 0.3 s of
            // start force; the RM-501 has no `GP`: it closes with its own.
            if self.unit == Unit::RvM1 {
                let f = force_limit.unwrap_or(g.init_force).clamp(0.0, g.force_max);
                let level = if g.force_max > 0.0 {
                    (f / g.force_max * 15.0).round() as i64
                } else {
                    0
                };
                self.send(&format!("GP {level},{level},3"))?;
            }
            "GC".to_string()
        };
        self.send(&line)?;
        if self.unit == Unit::RvM1 {
            self.error_status(1.0, &line).map_err(|e| self.resync(e))?;
        } else {
            self.sleep_interruptible(0.5)?;
        }
        // The hand has no opening sensor: report what was commanded.
        self.gripper = if line == "GO" {
            GripperState {
                opening: g.opening_max,
                force: 0.0,
            }
        } else {
            GripperState {
                opening: opening.clamp(g.opening_min, g.opening_max),
                force: force_limit.unwrap_or(g.init_force),
            }
        };
        Ok(self.gripper)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cell::RefCell;
    use std::collections::VecDeque;
    use std::rc::Rc;

    /// A unit that answers from a script: each line sent takes the next
    /// scripted reply (`None`: no reply), and `extra` is sent unasked.
    #[derive(Default)]
    struct Scripted {
        replies: VecDeque<Option<String>>,
        incoming: VecDeque<String>,
        sent: Vec<String>,
    }

    struct Fake(Rc<RefCell<Scripted>>);

    impl Link for Fake {
        fn send(&mut self, line: &str) -> Result<(), DriverError> {
            let mut s = self.0.borrow_mut();
            s.sent.push(line.to_string());
            if let Some(Some(r)) = s.replies.pop_front() {
                for part in r.split('|') {
                    s.incoming.push_back(part.to_string());
                }
            }
            Ok(())
        }
        fn read_line(&mut self, _timeout: Duration) -> Result<String, DriverError> {
            self.0
                .borrow_mut()
                .incoming
                .pop_front()
                .ok_or_else(|| DriverError::Lost("no reply".into()))
        }
        fn discard_input(&mut self) {
            self.0.borrow_mut().incoming.clear();
        }
    }

    /// A duplicated `ER` reply (the unit answered one question twice) must
    /// not shift every later reply by one: the next `WH` reads a pose, not
    /// the stale `0`.
    #[test]
    fn a_reply_sent_twice_does_not_shift_the_later_ones() {
        let unit = Rc::new(RefCell::new(Scripted::default()));
        let nest_wh = "+160.0,+0.0,+371.0,-90.0,+0.0";
        let script: Vec<Option<&str>> = vec![
            Some("0"),     // ER (probe)
            None,          // RS
            None,          // TL
            None,          // NT
            Some("0|0"),   // ER after the nest run, answered twice
            Some(nest_wh), // WH
        ];
        unit.borrow_mut().replies = script.into_iter().map(|r| r.map(str::to_string)).collect();
        let u = unit.clone();
        let open: Opener = Box::new(move |_| Ok(Box::new(Fake(u.clone())) as Box<dyn Link>));
        let settings = PortSettings {
            path: "fake".into(),
            baud: 9600,
            timeout: 0.1,
        };
        let desc = RobotDescription::builtin("rv-m1").unwrap();
        let mut d = Serial::with_opener(desc, settings, open, None);
        d.init().expect("init reads the pose, not the stale 0");
        let deg = d.joints().map(f64::to_degrees);
        assert!((deg[2] - 90.0).abs() < 1e-6, "{deg:?}");
        assert_eq!(
            unit.borrow().sent,
            ["ER", "RS", "TL +107.0", "NT", "ER", "WH"]
        );
    }
}
