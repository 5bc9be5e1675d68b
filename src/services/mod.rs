//! The AdaIR services: each is one table entry (import name, command code,
//! native body). A service validates its arguments, asks the kinematics,
//! and only then commands the driver, so a refused motion moves nothing and
//! every raised exception leaves the state as it was.

pub mod lint;
pub mod paths;
pub mod record;
pub mod table;

mod exc;
#[cfg(test)]
mod tests;

use crate::driver::{Robot, sim::Simulator};
pub use crate::interp::STOP_LABEL;
use crate::interp::{Clock, ServiceCx as Cx, ServiceFault, Services, Value, value::Array};
use crate::kinematics::{
    Arm, Elbow, Joints, KinError, Kinematics, MotionProfile, Pose, RobotDescription,
};
pub use exc::{Exc, ExcIds, exception_doc};
use std::collections::BTreeMap;
use std::io::Write;
use std::rc::Rc;

/// Everything the services keep between calls.
pub struct RobotState {
    pub kin: Kinematics,
    pub robot: Box<dyn Robot>,
    pub initialized: bool,
    pub velocity: f64,
    pub straight: bool,
    pub interpolation: f64,
    pub arm: Arm,
    pub elbow: Elbow,
    pub hand: i64,
    pub tool: Tool,
    pub base: Pose,
    pub paths: paths::PathMem,
    pub error_status: i64,
    /// Virtual time at which a `Control => True` motion ends.
    pub busy_until: f64,
    /// That motion when it is paced to the wall clock (`RealTime`,
    /// `--realtime`): waiting for it takes its rest on the wall clock, and a
    /// stop then leaves the arm where it had got to. Its start (virtual
    /// time), duration, start joints and support points.
    pub busy_paced: Option<(f64, f64, Joints, Vec<Joints>)>,
    pub trace: Option<Box<dyn Write>>,
    /// The support points of every motion, when `--record`/`--plot` asked.
    pub record: Option<Vec<record::Sample>>,
    pub realtime: bool,
    /// The force the jaws apply when they close on something, N.
    pub force_setting: f64,
    /// The screen teach pendant, when a terminal is there (installed by the CLI).
    pub pendant: Option<Box<dyn Pendant>>,
    /// The exceptions of the program the services run in.
    pub excs: ExcIds,
    /// Set when the user stopped the program (Ctrl-C) during or before a
    /// motion: where it was and where the robot stayed. The run has ended.
    pub stopped: Option<String>,
    /// The device object (tasks.md) between the simulated jaws.
    pub held: Option<String>,
    /// The program's time at which the TeachBox last closed: it was open
    /// until then, and another task's motion service called before then
    /// raises `RobotBusy` (tasks.md "Robot services from several tasks").
    pub teach_until: f64,
    /// This state is a rehearsal's stand-in for a real arm.
    pub rehearsal: bool,
    /// Who sees each motion as it starts (the live 3D view, `--view`).
    pub watch: Option<Box<dyn record::Watch>>,
    /// The goal of the last motion refused (virtual time, TCP pose), for
    /// the 3D view's red ghost; a motion that runs clears it.
    pub refused: Option<(f64, Pose)>,
    /// The last sample recorded or shown to the watch: a motion's samples
    /// that repeat it are left out of both (`record::samples_of`).
    pub last_sample: Option<record::Sample>,
}

/// How a service ends early: an exception, or the user's stop.
type R<T> = Result<T, ServiceFault>;

/// A service body: the call's narrow context, the robot state lent to it,
/// the arguments (`out` parameters written back in place).
pub type ServiceFn = fn(&mut Cx, &mut RobotState, &mut [Value]) -> R<Option<Value>>;

impl Services for RobotState {
    fn call(&mut self, index: u32, cx: &mut Cx, args: &mut [Value]) -> R<Option<Value>> {
        match SERVICES.get(index as usize).map(|s| (s.body, s.import)) {
            // While the TeachBox is open, another task's motion is refused.
            Some((_, name))
                if MOVES_THE_ARM.contains(&name) && cx.clock.now() < self.teach_until =>
            {
                let msg = format!(
                    "{name} while the TeachBox is open (until t = {:.3} s, now {:.3} s): the operator has the arm",
                    self.teach_until,
                    cx.clock.now()
                );
                Err(fail(self, name, Exc::RobotBusy, msg))
            }
            Some((table::Body::Robot(f), _)) => f(cx, self, args),
            _ => Err(ServiceFault::Raise(
                crate::check::PROGRAM_ERROR,
                format!("no robot service number {index}"),
            )),
        }
    }
    fn busy_until(&self) -> f64 {
        self.busy_until
    }
    fn teach_until(&self) -> f64 {
        self.teach_until
    }
    fn moves_the_arm(&self, index: u32) -> bool {
        SERVICES
            .get(index as usize)
            .is_some_and(|s| MOVES_THE_ARM.contains(&s.import))
    }
}

/// The motion services (import names): the ones that move the arm or the
/// hand. While the TeachBox is open, another task's call of one raises
/// `RobotBusy` (tasks.md); any other service waits for the box to close.
pub const MOVES_THE_ARM: &[&str] = &[
    "InitRobot",
    "EndRobot",
    "CalibrateRobot",
    "MoveTool",
    "MoveAxesAbsolute",
    "MoveAxesRelative",
    "MoveFrameAbsolute",
    "MoveFrameRelative",
    "MovePath",
    "TeachBox",
];

/// The screen teach pendant behind the `TeachBox` service. The terminal
/// code lives in `repl::teach`; the services only call this trait.
pub trait Pendant {
    /// Shows the teach box until the user leaves it; jogs move `st.robot`.
    fn teach(
        &mut self,
        st: &mut RobotState,
        clock: &mut dyn Clock,
        text: &str,
        refresh: bool,
        clear: bool,
    ) -> Result<(), String>;
}

#[derive(Clone, Copy, Debug)]
pub struct Tool {
    pub trans: Pose,
    pub force_min: f64,
    pub force_max: f64,
    pub dist_min: f64,
    pub dist_max: f64,
}

impl RobotState {
    pub fn new(desc: RobotDescription, excs: ExcIds) -> RobotState {
        let sim = Box::new(Simulator::new(desc.clone()));
        RobotState::with_driver(desc, excs, sim)
    }

    /// The state for `desc` driven by `robot` (the simulator or a real arm).
    pub fn with_driver(desc: RobotDescription, excs: ExcIds, robot: Box<dyn Robot>) -> RobotState {
        let kin = Kinematics::new(desc.clone());
        let tool = standard_tool(&kin);
        RobotState {
            kin,
            robot,
            initialized: false,
            velocity: 50.0,
            straight: false,
            interpolation: 1.0,
            arm: Arm::None,
            elbow: Elbow::None,
            hand: 2,
            tool,
            base: Pose::identity(),
            paths: paths::PathMem::default(),
            error_status: 0,
            busy_until: 0.0,
            busy_paced: None,
            trace: None,
            record: None,
            realtime: false,
            force_setting: 0.0,
            pendant: None,
            excs,
            stopped: None,
            held: None,
            teach_until: f64::NEG_INFINITY,
            rehearsal: false,
            watch: None,
            refused: None,
            last_sample: None,
        }
    }
}

impl RobotState {
    /// A simulated stand-in for this robot, for a rehearsal: the same
    /// description, settings, tool, base, paths and pose (joints and
    /// gripper), on the simulator, without trace, record or pendant.
    pub fn rehearsal(&self) -> RobotState {
        let desc = self.kin.description().clone();
        let mut sim = Simulator::new(desc.clone());
        if self.robot.real_time() {
            sim.stand_in_for_real_arm();
        }
        sim.set_joints(self.robot.joints());
        let _ = sim.move_gripper(self.robot.gripper().opening, None);
        let mut st = RobotState::with_driver(desc, self.excs.clone(), Box::new(sim));
        st.initialized = self.initialized;
        st.velocity = self.velocity;
        st.straight = self.straight;
        st.interpolation = self.interpolation;
        st.arm = self.arm;
        st.elbow = self.elbow;
        st.hand = self.hand;
        st.tool = self.tool;
        st.base = self.base;
        st.paths = self.paths.clone();
        st.error_status = self.error_status;
        st.force_setting = self.force_setting;
        st.rehearsal = true;
        st
    }
}

fn standard_tool(kin: &Kinematics) -> Tool {
    let g = *kin.description().gripper();
    Tool {
        trans: kin.standard_tool(),
        force_min: g.force_min,
        force_max: g.force_max,
        dist_min: g.opening_min,
        dist_max: g.opening_max,
    }
}

pub use table::{Group, SERVICES, Service};

/// The trace lines written while the teach pendant is open.
#[derive(Clone, Default)]
struct Held(Rc<std::cell::RefCell<Vec<u8>>>);

impl Write for Held {
    fn write(&mut self, b: &[u8]) -> std::io::Result<usize> {
        self.0.borrow_mut().extend_from_slice(b);
        Ok(b.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// The import names of the services only the simulator has: on a real arm,
/// and in the rehearsal that stands in for it, they raise
/// `CommandNotSupported` (`adair check` warns of them).
pub const SIMULATOR_ONLY: &[&str] = &["PlaceObject"];

/// The service bound to an import name, as the interpreter binds it.
pub fn lookup(name: &str) -> Option<crate::interp::Binding> {
    table::index_of(name).map(crate::interp::Binding::Service)
}

/// Reads and parses a robot description file (`--robot-file`). The
/// kinematics parse the text and do no I/O; the file is read here.
pub fn read_robot_file(
    path: impl AsRef<std::path::Path>,
) -> Result<RobotDescription, crate::kinematics::DescriptionError> {
    let path = path.as_ref();
    let source = path.display().to_string();
    match std::fs::read_to_string(path) {
        Ok(text) => RobotDescription::from_file_text(&text, source),
        Err(e) => Err(crate::kinematics::DescriptionError {
            source,
            problems: vec![format!("cannot read the file: {e}")],
        }),
    }
}

/// The profile an import name expects, for the checker.
pub fn import_profile(name: &str) -> Option<crate::check::ImportProfile> {
    table::by_import(name).map(|s| s.import_profile())
}

fn code_of(name: &str) -> i64 {
    table::code_of(name)
}

// ---- plumbing ----

/// Raises an AdaIR exception from a service, recording its command code.
pub(crate) fn fail(st: &mut RobotState, service: &str, exc: Exc, msg: String) -> ServiceFault {
    st.error_status = code_of(service);
    ServiceFault::Raise(st.excs.id(exc), msg)
}

fn kin_fail(st: &mut RobotState, service: &str, e: &KinError) -> ServiceFault {
    fail(st, service, e.exception().into(), e.to_string())
}

fn require_init(cx: &mut Cx, st: &mut RobotState, service: &str) -> R<()> {
    if !st.initialized {
        return Err(fail(
            st,
            service,
            Exc::SystemNotInitialized,
            format!("{service} before InitRobot: call InitRobot first"),
        ));
    }
    wait_for_control(cx, st, service)
}

/// `require_init`, then the arm's pose as it is now: on a real arm that
/// may have been moved by hand while the program waited, a fresh `WH`
/// (robots.md "The arm moved outside the program"). Every read-back and
/// every motion service starts here.
fn require_fresh_pose(cx: &mut Cx, st: &mut RobotState, service: &str) -> R<()> {
    require_init(cx, st, service)?;
    let before = st.robot.joints();
    if let Err(e) = st.robot.refresh() {
        return Err(driver_fail(st, service, e));
    }
    // The arm was moved by hand: the recording and the live view show
    // where the driver reports it, from now on.
    if st.robot.joints() != before {
        record::reported(st, cx.clock.now(), before);
    }
    Ok(())
}

/// A `Control => True` motion still running: wait for its end (virtual
/// time on the simulator; the arm's reply on a real one).
fn wait_for_control(cx: &mut Cx, st: &mut RobotState, service: &str) -> R<()> {
    let now = cx.clock.now();
    let paced = st.busy_paced.take();
    if st.busy_until > now {
        let rest = st.busy_until - now;
        if let Some((start, duration, before, points)) = paced {
            let done = cx.pace(rest);
            if done < 1.0 {
                cx.clock.sleep(rest * done);
                st.busy_until = cx.clock.now();
                let reached = interpolate(&before, &points, (st.busy_until - start) / duration);
                let _ = st.robot.move_joints(&[reached], 0.0);
                // Recorded whole when it started: it ends here.
                record::cut(st, st.busy_until, reached);
                return Err(stop(
                    cx,
                    st,
                    service,
                    "waiting for a Control => True motion",
                ));
            }
        }
        cx.clock.sleep(rest);
    }
    if st.robot.motion_pending() {
        match st.robot.wait_motion() {
            Ok(()) => {}
            Err(crate::driver::DriverError::Interrupted) => {
                let _ = st.robot.stop_motion();
                return Err(stop(
                    cx,
                    st,
                    service,
                    "waiting for a Control => True motion",
                ));
            }
            Err(e) => return Err(driver_fail(st, service, e)),
        }
    }
    Ok(())
}

/// Ends the program because the user stopped it: records where the program
/// was and where the robot stayed, and leaves every frame (`STOP_LABEL`).
fn stop(cx: &mut Cx, st: &mut RobotState, service: &str, what: &str) -> ServiceFault {
    let q = st.robot.joints();
    st.stopped = Some(format!(
        "interrupted (Ctrl-C) at {} in {service} ({what}); the robot stopped at {} deg",
        cx.here(),
        deg5(&q)
    ));
    ServiceFault::Stop
}

pub fn frame_value(p: &Pose) -> Value {
    let rows = p.to_rows();
    let data = rows
        .iter()
        .flat_map(|row| row.iter().map(|x| Value::Real(*x)))
        .collect();
    Value::Arr(Rc::new(Array {
        bounds: vec![(1, 3), (1, 4)],
        data,
    }))
}

pub fn frame_rows(v: &Value) -> [[f64; 4]; 3] {
    let mut rows = [[0.0; 4]; 3];
    if let Value::Arr(a) = v {
        for (k, x) in a.data.iter().enumerate().take(12) {
            rows[k / 4][k % 4] = x.real();
        }
    }
    rows
}

fn axes_value(j: &Joints) -> Value {
    Value::Arr(Rc::new(Array {
        bounds: vec![(1, 5)],
        data: j.iter().map(|x| Value::Real(*x)).collect(),
    }))
}

fn axes_of(v: &Value) -> Joints {
    let mut j = [0.0; 5];
    if let Value::Arr(a) = v {
        for (k, x) in a.data.iter().enumerate().take(5) {
            j[k] = x.real();
        }
    }
    j
}

fn deg5(j: &Joints) -> String {
    let d: Vec<String> = j
        .iter()
        .map(|x| format!("{:.2}", x.to_degrees() + 0.0))
        .collect();
    format!("({})", d.join(", "))
}

/// Motion options common to every motion service.
struct MotionOpts {
    time: Option<f64>,
    /// `Time` as given (0.0 = as fast as the velocity allows).
    time_arg: f64,
    control: bool,
    realtime: bool,
}

fn opts(a: &[Value], first: usize) -> MotionOpts {
    let t = a.get(first).map(|v| v.real()).unwrap_or(0.0);
    MotionOpts {
        time: if t > 0.0 { Some(t) } else { None },
        time_arg: t,
        control: a.get(first + 1).is_some_and(|v| v.int() != 0),
        realtime: a.get(first + 2).is_some_and(|v| v.int() != 0),
    }
}

/// `require_init` for a motion service, and its `Time`: a NaN, an infinite
/// or a negative duration is `TimeInvalid` before anything moves.
fn require_motion(cx: &mut Cx, st: &mut RobotState, service: &str, o: &MotionOpts) -> R<()> {
    require_fresh_pose(cx, st, service)?;
    let t = o.time_arg;
    if !t.is_finite() || t < 0.0 {
        return Err(fail(
            st,
            service,
            Exc::TimeInvalid,
            format!("Time => {t} s: a duration must be a finite number of seconds, 0.0 or more"),
        ));
    }
    Ok(())
}

/// Executes a planned joint motion: driver, clock, trace.
fn perform(
    cx: &mut Cx,
    st: &mut RobotState,
    service: &str,
    points: &[Joints],
    duration: f64,
    o: &MotionOpts,
) -> R<()> {
    let before = st.robot.joints();
    let real = st.robot.real_time();
    if cx.interrupt_requested() {
        return Err(stop(cx, st, service, "before the motion started"));
    }
    st.refused = None;
    record::announce(st, cx.clock.now(), &before, points, duration);
    // Paced to the wall clock: the user can stop the motion (Ctrl-C); the
    // robot then stays where it had got to. A real arm takes its own time.
    if (o.realtime || st.realtime) && !o.control && !real {
        let done = cx.pace(duration);
        if done < 1.0 {
            let reached = interpolate(&before, points, done);
            let _ = st.robot.move_joints(&[reached], duration * done);
            // The recording holds the motion up to where the arm stopped.
            let start = cx.clock.now();
            record::motion(st, start, &before, points, duration);
            record::cut(st, start + duration * done, reached);
            cx.clock.sleep(duration * done);
            let what = format!("after {:.3} of {duration:.3} s", duration * done);
            return Err(stop(cx, st, service, &what));
        }
    }
    let start = cx.clock.now();
    let started = if o.time.is_some() {
        st.robot.start_timed_motion(points, duration)
    } else {
        st.robot.start_motion(points, duration)
    };
    if let Err(e) = started {
        return Err(driver_fail(st, service, e));
    }
    if real {
        // A real arm takes its own (wall-clock) time: wait for its end,
        // unless the program goes on computing (`Control => True`).
        if !o.control {
            match st.robot.wait_motion() {
                Ok(()) => {
                    // The unit reports the end (the RV-M1's `ER` reply)
                    // before the end adair planned: the motion ends there,
                    // at its target, for the recording and the live view.
                    let now = cx.clock.now();
                    if now < start + duration {
                        record::motion(st, start, &before, points, duration);
                        record::cut(st, now, st.robot.joints());
                        trace_motion(cx, st, service, start, &before, duration);
                        return Ok(());
                    }
                }
                Err(crate::driver::DriverError::Interrupted) => {
                    let _ = st.robot.stop_motion();
                    // Recorded up to the stop, ending at the target of the
                    // line the unit finishes.
                    let now = cx.clock.now();
                    record::motion(st, start, &before, points, duration);
                    record::cut(st, now, st.robot.joints());
                    let what = format!(
                        "{:.3} s into the motion; the unit finishes the line it has",
                        now - start
                    );
                    return Err(stop(cx, st, service, &what));
                }
                Err(e) => {
                    let fault = driver_fail(st, service, e);
                    // The motion ends where the driver reports the arm
                    // after the fault (it read `WH` again when it could).
                    record::motion(st, start, &before, points, duration);
                    record::cut(st, cx.clock.now(), st.robot.joints());
                    return Err(fault);
                }
            }
        }
    } else if o.control {
        st.busy_until = start + duration;
        st.busy_paced =
            (o.realtime || st.realtime).then(|| (start, duration, before, points.to_vec()));
    } else {
        cx.clock.sleep(duration);
    }
    record::motion(st, start, &before, points, duration);
    trace_motion(cx, st, service, start, &before, duration);
    Ok(())
}

/// The `--trace` line of a motion that ran.
fn trace_motion(
    cx: &mut Cx,
    st: &mut RobotState,
    service: &str,
    start: f64,
    before: &Joints,
    duration: f64,
) {
    if st.trace.is_some() {
        let after = st.robot.joints();
        let (from, to) = (tcp_mm(st, before), tcp_mm(st, &after));
        if let Some(t) = &mut st.trace {
            let _ = writeln!(
                t,
                "[t={start:9.3} s] {service} at {}: {} -> {} deg, TCP {from} -> {to} mm, {duration:.3} s",
                cx.here(),
                deg5(before),
                deg5(&after)
            );
        }
    }
}

/// The arm's pose as it is now, before the teach pendant computes a jog:
/// on a real arm that may have been moved by hand, a fresh `WH` (as every
/// motion service reads it, robots.md "The arm moved outside the program").
pub fn fresh_pose(st: &mut RobotState) -> Result<(), String> {
    st.robot.refresh().map_err(|e| e.to_string())
}

/// A jog of the teach pendant to `target`: checked against the limits
/// before anything is sent (on a real arm each jog is one motion, checked
/// on its own), timed at the current velocity, driven, clocked, recorded
/// (`--record`, `--plot`, the REPL's `:record`) and traced like a
/// program's joint motion.
pub fn jog(st: &mut RobotState, clock: &mut dyn Clock, target: Joints) -> Result<(), String> {
    let from = st.robot.joints();
    let desc = st.kin.description();
    desc.check_limits(&target).map_err(|v| v.to_string())?;
    let d = MotionProfile::plan(&from, &target, st.velocity, desc, None)
        .map_err(|e| e.to_string())?
        .duration();
    let start = clock.now();
    record::announce(st, start, &from, &[target], d);
    st.robot
        .move_joints(&[target], d)
        .map_err(|e| e.to_string())?;
    if !st.robot.real_time() {
        clock.sleep(d);
    }
    record::motion(st, start, &from, &[target], d);
    if st.trace.is_some() {
        let to = st.robot.joints();
        let (p, q) = (tcp_mm(st, &from), tcp_mm(st, &to));
        if let Some(t) = &mut st.trace {
            let _ = writeln!(
                t,
                "[t={start:9.3} s] TeachBox jog: {} -> {} deg, TCP {p} -> {q} mm, {d:.3} s",
                deg5(&from),
                deg5(&to)
            );
        }
    }
    Ok(())
}

/// The teach pendant's hand key: open fully, or close with the force
/// setting; clocked, recorded and traced as `MoveTool` is. Returns the
/// hand's reading.
pub fn jog_hand(
    st: &mut RobotState,
    clock: &mut dyn Clock,
    open: bool,
) -> Result<crate::driver::GripperState, String> {
    let g = *st.kin.description().gripper();
    let before = st.robot.gripper();
    let moved = if open {
        st.robot.move_gripper(g.opening_max, None)
    } else {
        st.robot.move_gripper(g.opening_min, Some(st.force_setting))
    }
    .map_err(|e| e.to_string())?;
    // The jaws move at 100 mm/s at full velocity (as `MoveTool`).
    let d = (before.opening - moved.opening).abs() / (100.0 * st.velocity / 100.0).max(1e-6);
    let start = clock.now();
    if !st.robot.real_time() {
        clock.sleep(d);
    }
    record::point(st, clock.now());
    let reading = grip_reading(st);
    if let Some(tr) = &mut st.trace {
        let _ = writeln!(
            tr,
            "[t={start:9.3} s] TeachBox hand: opening {:.1} -> {:.1} mm, force {:.1} N",
            before.opening, reading.opening, reading.force
        );
    }
    Ok(reading)
}

/// Wall-clock time, for a real arm: motions take the time they take.
pub struct WallClock {
    start: std::time::Instant,
}

impl Default for WallClock {
    fn default() -> Self {
        WallClock {
            start: std::time::Instant::now(),
        }
    }
}

impl Clock for WallClock {
    fn now(&self) -> f64 {
        self.start.elapsed().as_secs_f64()
    }
    fn sleep(&mut self, seconds: f64) {
        if seconds > 0.0 {
            std::thread::sleep(std::time::Duration::from_secs_f64(seconds.min(86_400.0)));
        }
    }
}

/// A driver's failure as the handbook's exception (robots.md's fault table).
pub(crate) fn driver_fail(
    st: &mut RobotState,
    service: &str,
    e: crate::driver::DriverError,
) -> ServiceFault {
    use crate::driver::DriverError as D;
    let exc = match &e {
        D::NoConnection(_) => Exc::NoConnection,
        D::NoRobot(_) => Exc::NoRobotInstalled,
        D::WrongRobot(_) => Exc::WrongRobotInstalled,
        D::Lost(_) => Exc::MessageLost,
        D::Invalid(_) => Exc::MessageInvalid,
        D::Fatal(_) => Exc::FatalCommunicationError,
        D::Refused(_) => Exc::CommandNotSupported,
        D::UnitOutOfRange(_) | D::Limit(_) => Exc::OutOfReach,
        D::Interrupted => Exc::ProgramError,
    };
    fail(st, service, exc, e.to_string())
}

/// The joints a fraction of the way along a motion through `points`.
fn interpolate(from: &Joints, points: &[Joints], fraction: f64) -> Joints {
    let n = points.len();
    if n == 0 {
        return *from;
    }
    let x = fraction.clamp(0.0, 1.0) * n as f64;
    let i = (x.floor() as usize).min(n - 1);
    let a = if i == 0 { *from } else { points[i - 1] };
    let b = points[i];
    let t = x - i as f64;
    let mut q = a;
    for j in 0..q.len() {
        q[j] = a[j] + (b[j] - a[j]) * t;
    }
    q
}

/// Plans a point-to-point joint motion to `target`.
fn plan(st: &mut RobotState, service: &str, target: &Joints, o: &MotionOpts) -> R<f64> {
    let from = st.robot.joints();
    // With `Time`, the motion may use the robot's full speed.
    let velocity = if o.time.is_some() { 100.0 } else { st.velocity };
    match MotionProfile::plan(&from, target, velocity, st.kin.description(), o.time) {
        Ok(p) => Ok(p.duration()),
        Err(e) => Err(kin_fail(st, service, &e)),
    }
}

/// The duration of a path through support points at the current velocity.
fn path_duration(st: &RobotState, from: &Joints, points: &[Joints], velocity: f64) -> f64 {
    let desc = st.kin.description();
    let mut t = 0.0;
    let mut prev = *from;
    for p in points {
        let mut seg: f64 = 0.0;
        for (j, spec) in desc.joints().iter().enumerate() {
            let v = spec.max_speed * velocity / 100.0;
            if v > 0.0 {
                seg = seg.max((p[j] - prev[j]).abs() / v);
            }
        }
        t += seg;
        prev = *p;
    }
    t
}

/// Solves a frame goal in the current move mode: the support points to go through.
fn frame_motion(st: &RobotState, from: &Joints, goal: &Pose) -> Result<Vec<Joints>, KinError> {
    if st.straight {
        st.kin
            .straight_line(from, goal, &st.tool.trans, st.interpolation)
    } else {
        st.kin
            .ik_choose(goal, &st.tool.trans, from, st.arm, st.elbow)
            .map(|s| vec![s.joints])
    }
}

fn move_frame(
    cx: &mut Cx,
    st: &mut RobotState,
    service: &str,
    goal: Pose,
    o: MotionOpts,
) -> R<Option<Value>> {
    let from = st.robot.joints();
    let points = match frame_motion(st, &from, &goal) {
        Ok(p) => p,
        Err(e) => {
            st.refused = Some((cx.clock.now(), goal));
            return Err(kin_fail(st, service, &e));
        }
    };
    let duration = if st.straight {
        let d = path_duration(
            st,
            &from,
            &points,
            if o.time.is_some() { 100.0 } else { st.velocity },
        );
        match o.time {
            Some(t) if t + 1e-9 < d => {
                return Err(fail(
                    st,
                    service,
                    Exc::TimeInvalid,
                    format!("Time => {t:.3} s is shorter than the fastest straight line, {d:.3} s"),
                ));
            }
            Some(t) => t,
            None => d,
        }
    } else {
        let target = points[points.len() - 1];
        plan(st, service, &target, &o)?
    };
    perform(cx, st, service, &points, duration, &o)?;
    Ok(None)
}

// ---- services ----

fn init_robot(cx: &mut Cx, st: &mut RobotState, _a: &mut [Value]) -> R<Option<Value>> {
    // InitRobot moves (to the zero pose): like every motion it waits for a
    // `Control => True` motion still running.
    wait_for_control(cx, st, "InitRobot")?;
    let o = MotionOpts {
        time: None,
        time_arg: 0.0,
        control: false,
        realtime: false,
    };
    if let Err(e) = st.robot.init() {
        return Err(driver_fail(st, "InitRobot", e));
    }
    st.initialized = true;
    st.velocity = 50.0;
    st.straight = false;
    st.interpolation = 1.0;
    st.arm = Arm::None;
    st.elbow = Elbow::None;
    st.hand = 2;
    st.tool = standard_tool(&st.kin);
    st.base = Pose::identity();
    st.busy_until = cx.clock.now();
    if let Err(e) = st.robot.set_speed(st.velocity) {
        st.initialized = false;
        return Err(driver_fail(st, "InitRobot", e));
    }
    let zero = [0.0; 5];
    let d = plan(st, "InitRobot", &zero, &o)?;
    perform(cx, st, "InitRobot", &[zero], d, &o)?;
    let g = *st.kin.description().gripper();
    if let Err(e) = st.robot.move_gripper(g.opening_max, None) {
        return Err(driver_fail(st, "InitRobot", e));
    }
    st.force_setting = g.init_force;
    Ok(None)
}

fn end_robot(cx: &mut Cx, st: &mut RobotState, _a: &mut [Value]) -> R<Option<Value>> {
    if !st.initialized {
        return Err(fail(
            st,
            "EndRobot",
            Exc::SystemNotInitialized,
            "EndRobot before InitRobot".into(),
        ));
    }
    let now = cx.clock.now();
    if st.busy_until > now + 1e-12 {
        return Err(fail(
            st,
            "EndRobot",
            Exc::ControlCommandActive,
            format!(
                "a Control => True motion runs until t = {:.3} s (now {now:.3} s)",
                st.busy_until
            ),
        ));
    }
    // The nest (rest) position of the robot description (robots.md).
    let o = MotionOpts {
        time: None,
        time_arg: 0.0,
        control: false,
        realtime: false,
    };
    let nest = st.kin.description().nest();
    let d = plan(st, "EndRobot", &nest, &o)?;
    perform(cx, st, "EndRobot", &[nest], d, &o)?;
    st.initialized = false;
    st.tool = standard_tool(&st.kin);
    st.base = Pose::identity();
    Ok(None)
}

fn calibrate(cx: &mut Cx, st: &mut RobotState, _a: &mut [Value]) -> R<Option<Value>> {
    require_init(cx, st, "CalibrateRobot")?;
    if let Err(e) = st.robot.calibrate() {
        return Err(driver_fail(st, "CalibrateRobot", e));
    }
    Ok(None)
}

fn set_velocity(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let v = a[0].real();
    require_init(cx, st, "SetVelocity")?;
    if v <= 0.0 {
        return Err(fail(
            st,
            "SetVelocity",
            Exc::ConstraintError,
            format!(
                "velocity {v:.1} % would never arrive: give a velocity above 0.0 %, up to 100.0 %"
            ),
        ));
    }
    if let Err(e) = st.robot.set_speed(v) {
        return Err(driver_fail(st, "SetVelocity", e));
    }
    st.velocity = v;
    Ok(None)
}

fn set_move_mode(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let k = a[0].int();
    require_init(cx, st, "SetMoveMode")?;
    st.straight = k == 1;
    Ok(None)
}

fn set_interpolation(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let w = a[0].real();
    require_init(cx, st, "SetInterpolation")?;
    st.interpolation = w;
    Ok(None)
}

fn set_robot_config(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let (arm, elbow, hand) = (a[0].int(), a[1].int(), a[2].int());
    require_init(cx, st, "SetRobotConfig")?;
    st.arm = match arm {
        0 => Arm::Forward,
        1 => Arm::Backward,
        _ => Arm::None,
    };
    st.elbow = match elbow {
        0 => Elbow::Above,
        1 => Elbow::Below,
        _ => Elbow::None,
    };
    st.hand = hand;
    Ok(None)
}

fn value_robot_config(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    require_fresh_pose(cx, st, "ValueRobotConfig")?;
    let (arm, elbow) = st.kin.config_of(&st.robot.read_joints());
    a[0] = Value::Int(match arm {
        Arm::Forward => 0,
        Arm::Backward => 1,
        Arm::None => 2,
    });
    a[1] = Value::Int(match elbow {
        Elbow::Above => 0,
        Elbow::Below => 1,
        Elbow::None => 2,
    });
    // A 5-axis wrist never flips.
    a[2] = Value::Int(1);
    Ok(None)
}

fn set_tool(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let Value::Rec(rec) = &a[0] else {
        return Ok(None);
    };
    let trans = Pose::from_rows(frame_rows(&rec[0]));
    let (fmin, fmax, dmin, dmax) = (rec[1].real(), rec[2].real(), rec[4].real(), rec[5].real());
    require_init(cx, st, "SetTool")?;
    if let Err(e) = trans.check_rigid("tool transform") {
        return Err(kin_fail(st, "SetTool", &e));
    }
    if fmin > fmax {
        return Err(fail(
            st,
            "SetTool",
            Exc::ForceInvalid,
            format!("ForceMin {fmin:.1} N is above ForceMax {fmax:.1} N"),
        ));
    }
    if dmin > dmax {
        return Err(fail(
            st,
            "SetTool",
            Exc::DistanceInvalid,
            format!("DistMin {dmin:.1} mm is above DistMax {dmax:.1} mm"),
        ));
    }
    st.tool = Tool {
        trans,
        force_min: fmin,
        force_max: fmax,
        dist_min: dmin,
        dist_max: dmax,
    };
    Ok(None)
}

/// The gripper as every reader reports it (`ValueTool`, the trace, the
/// TeachBox): the opening, and the grip force. The grip force is the
/// handbook's *Greifkraft*, a setting: `InitToolForce` after `InitRobot`,
/// the `Force` of the last `MoveTool`; while the jaws press on something it
/// is the force they press with. Without a force sensor it reads 0.0.
pub fn grip_reading(st: &RobotState) -> crate::driver::GripperState {
    let mut g = st.robot.gripper();
    let t = &st.tool;
    g.force = if t.force_min == 0.0 && t.force_max == 0.0 {
        0.0
    } else if g.force > 0.0 {
        g.force
    } else {
        st.force_setting
    };
    g
}

fn tool_value(st: &RobotState) -> Value {
    let g = grip_reading(st);

    Value::Rec(Rc::new(smallvec::smallvec![
        frame_value(&st.tool.trans),
        Value::Real(st.tool.force_min),
        Value::Real(st.tool.force_max),
        Value::Real(g.force),
        Value::Real(st.tool.dist_min),
        Value::Real(st.tool.dist_max),
        Value::Real(g.opening),
    ]))
}

fn value_tool(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    require_init(cx, st, "ValueTool")?;
    a[0] = tool_value(st);
    Ok(None)
}

fn value_tool_f(cx: &mut Cx, st: &mut RobotState, _a: &mut [Value]) -> R<Option<Value>> {
    require_init(cx, st, "ValueTool")?;
    Ok(Some(tool_value(st)))
}

/// Gripper motion, with the handbook's fallbacks for missing sensors: without
/// a distance sensor (DistMin = DistMax = 0) any distance above 0.0 opens
/// fully and 0.0 closes; without a force sensor (ForceMin = ForceMax = 0)
/// only the distance counts. The distance wins over the force.
fn move_tool(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let (dist, force) = (a[0].real(), a[1].real());
    require_init(cx, st, "MoveTool")?;
    let t = st.tool;
    let has_dist = !(t.dist_min == 0.0 && t.dist_max == 0.0);
    let has_force = !(t.force_min == 0.0 && t.force_max == 0.0);
    if has_dist && (dist < t.dist_min || dist > t.dist_max) {
        return Err(fail(
            st,
            "MoveTool",
            Exc::DistanceInvalid,
            format!(
                "distance {dist:.1} mm outside {:.1} .. {:.1} mm",
                t.dist_min, t.dist_max
            ),
        ));
    }
    if has_force && (force < t.force_min || force > t.force_max) {
        return Err(fail(
            st,
            "MoveTool",
            Exc::ForceInvalid,
            format!(
                "force {force:.1} N outside {:.1} .. {:.1} N",
                t.force_min, t.force_max
            ),
        ));
    }
    let g = *st.kin.description().gripper();
    let target = if has_dist {
        dist
    } else if dist > 0.0 {
        g.opening_max
    } else {
        g.opening_min
    };
    let limit = if has_force { Some(force) } else { None };
    if has_force {
        st.force_setting = force;
    }
    let before = st.robot.gripper();
    // The simulated devices' objects (tasks.md): closing on one whose
    // centre is at the TCP picks it, opening puts it down there.
    let tcp = current_frame(st).translation;
    let at = [tcp.x, tcp.y, tcp.z];
    let closing = target < before.opening;
    let mut grasp = None;
    if closing
        && st.held.is_none()
        && let Some(w) = cx.world.as_deref()
        && let Some(o) = w.object_at(at, crate::devices::GRIP_TOLERANCE_MM)
        && o.width <= before.opening
        && let Some(sim) = st.robot.as_simulator()
        && sim.place_object(o.width).is_ok()
    {
        grasp = Some(o.name);
    }
    let moved = st.robot.move_gripper(target, limit);
    // The jaws move at 100 mm/s at full velocity.
    let jaw_time = |g: &crate::driver::GripperState| {
        (before.opening - g.opening).abs() / (100.0 * st.velocity / 100.0).max(1e-6)
    };
    if let (Some(name), Ok(g)) = (&grasp, &moved)
        && let Some(w) = cx.world.as_deref_mut()
    {
        let width = w
            .objects()
            .iter()
            .find(|o| &o.name == name)
            .map(|o| o.width);
        let closed_at = cx.clock.now() + jaw_time(g);
        if width.is_some_and(|x| (g.opening - x).abs() < 1e-6) && w.pick_at(name, closed_at).is_ok()
        {
            st.held = Some(name.clone());
        }
    }
    if !closing
        && let Ok(g) = &moved
        && let Some(name) = st.held.clone()
        && g.opening > before.opening
        && let Some(w) = cx.world.as_deref_mut()
    {
        let _ = w.put_down(&name, at);
        st.held = None;
        if let Some(sim) = st.robot.as_simulator() {
            let _ = sim.place_object(0.0);
        }
    }
    match moved {
        Ok(g2) => {
            let d = jaw_time(&g2);
            if !st.robot.real_time() {
                cx.clock.sleep(d);
            }
            record::point(st, cx.clock.now());
            let g2 = grip_reading(st);
            if let Some(tr) = &mut st.trace {
                let _ = writeln!(
                    tr,
                    "[t={:9.3} s] MoveTool at {}: opening {:.1} -> {:.1} mm, force {:.1} N",
                    cx.clock.now() - d,
                    cx.here(),
                    before.opening,
                    g2.opening,
                    g2.force
                );
            }
            Ok(None)
        }
        Err(e) => Err(driver_fail(st, "MoveTool", e)),
    }
}

fn move_axes_absolute(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let axes = axes_of(&a[0]);
    let o = opts(a, 1);
    require_motion(cx, st, "MoveAxesAbsolute", &o)?;
    let target = match st.kin.joint_target(&axes) {
        Ok(t) => t,
        Err(e) => {
            st.refused = Some((cx.clock.now(), st.kin.fk_tcp(&axes, &st.tool.trans)));
            return Err(kin_fail(st, "MoveAxesAbsolute", &e));
        }
    };
    let d = plan(st, "MoveAxesAbsolute", &target, &o)?;
    perform(cx, st, "MoveAxesAbsolute", &[target], d, &o)?;
    Ok(None)
}

fn move_axes_relative(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let delta = axes_of(&a[0]);
    let o = opts(a, 1);
    require_motion(cx, st, "MoveAxesRelative", &o)?;
    let current = st.robot.joints();
    let target = match st.kin.relative_joint_target(&current, &delta) {
        Ok(t) => t,
        Err(e) => {
            let mut goal = current;
            for (g, d) in goal.iter_mut().zip(delta) {
                *g += d;
            }
            st.refused = Some((cx.clock.now(), st.kin.fk_tcp(&goal, &st.tool.trans)));
            return Err(kin_fail(st, "MoveAxesRelative", &e));
        }
    };
    let d = plan(st, "MoveAxesRelative", &target, &o)?;
    perform(cx, st, "MoveAxesRelative", &[target], d, &o)?;
    Ok(None)
}

fn move_frame_absolute(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let goal = Pose::from_rows(frame_rows(&a[0]));
    let o = opts(a, 1);
    require_motion(cx, st, "MoveFrameAbsolute", &o)?;
    move_frame(cx, st, "MoveFrameAbsolute", goal, o)
}

fn move_frame_relative(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let goal = Pose::from_rows(frame_rows(&a[0]));
    let o = opts(a, 1);
    require_motion(cx, st, "MoveFrameRelative", &o)?;
    let g = st.base * goal;
    move_frame(cx, st, "MoveFrameRelative", g, o)
}

fn set_base(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let base = Pose::from_rows(frame_rows(&a[0]));
    require_init(cx, st, "SetBase")?;
    if let Err(e) = base.check_rigid("base frame") {
        return Err(kin_fail(st, "SetBase", &e));
    }
    st.base = base;
    Ok(None)
}

fn valid_frame(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let f = Pose::from_rows(frame_rows(&a[0]));
    require_init(cx, st, "ValidFrame")?;
    match st.kin.valid_frame(&f, &st.tool.trans) {
        Ok(v) => {
            a[0] = frame_value(&v);
            Ok(None)
        }
        Err(e) => Err(kin_fail(st, "ValidFrame", &e)),
    }
}

fn value_axes(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let v = value_axes_f(cx, st, a)?;
    a[0] = v.unwrap_or_default();
    Ok(None)
}

fn value_axes_f(cx: &mut Cx, st: &mut RobotState, _a: &mut [Value]) -> R<Option<Value>> {
    require_fresh_pose(cx, st, "ValueAxes")?;
    Ok(Some(axes_value(&st.robot.read_joints())))
}

/// The tool centre point at joints `q`, `(x, y, z)` in mm, for the trace.
fn tcp_mm(st: &RobotState, q: &Joints) -> String {
    let p = st.kin.fk_tcp(q, &st.tool.trans).translation;
    format!("({:.1}, {:.1}, {:.1})", p.x, p.y, p.z)
}

fn current_frame(st: &RobotState) -> Pose {
    st.kin.fk_tcp(&st.robot.read_joints(), &st.tool.trans)
}

fn value_frame_absolute(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    a[0] = value_frame_absolute_f(cx, st, a)?.unwrap_or_default();
    Ok(None)
}

fn value_frame_absolute_f(cx: &mut Cx, st: &mut RobotState, _a: &mut [Value]) -> R<Option<Value>> {
    require_fresh_pose(cx, st, "ValueFrameAbsolute")?;
    Ok(Some(frame_value(&current_frame(st))))
}

fn value_frame_relative(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    a[0] = value_frame_relative_f(cx, st, a)?.unwrap_or_default();
    Ok(None)
}

fn value_frame_relative_f(cx: &mut Cx, st: &mut RobotState, _a: &mut [Value]) -> R<Option<Value>> {
    require_fresh_pose(cx, st, "ValueFrameRelative")?;
    Ok(Some(frame_value(&(st.base.inverse() * current_frame(st)))))
}

fn value_error_status(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    a[0] = value_error_status_f(cx, st, a)?.unwrap_or_default();
    Ok(None)
}

fn value_error_status_f(cx: &mut Cx, st: &mut RobotState, _a: &mut [Value]) -> R<Option<Value>> {
    // Always answers, before InitRobot too: a handler must be able to ask
    // which service raised, SystemNotInitialized included.
    wait_for_control(cx, st, "ValueErrorStatus")?;
    Ok(Some(Value::Int(st.error_status)))
}

fn teach_box(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let text = a[0].text();
    let (refresh, clear) = (a[1].int() != 0, a[2].int() != 0);
    // The pendant shows the arm where it is (a real one may have been
    // moved by hand).
    require_fresh_pose(cx, st, "TeachBox")?;
    if text.chars().count() > 60 || text.chars().any(|c| c.is_control()) {
        let msg = match text.chars().position(|c| c.is_control()) {
            Some(i) => format!(
                "the text has a control character at position {} (none allowed)",
                i + 1
            ),
            None => format!(
                "the text has {} characters (at most 60)",
                text.chars().count()
            ),
        };
        return Err(fail(st, "TeachBox", Exc::UserInfoInvalid, msg));
    }
    if st.rehearsal {
        return Err(fail(
            st,
            "TeachBox",
            Exc::CommandNotSupported,
            "the TeachBox cannot be rehearsed: its jogs are the operator's (the REPL's :teach runs on the arm without a rehearsal, each jog checked against the limits before it is sent)".into(),
        ));
    }
    let Some(mut p) = st.pendant.take() else {
        return Err(fail(
            st,
            "TeachBox",
            Exc::CommandNotSupported,
            "the TeachBox needs an interactive terminal (run the program from a terminal, or use the REPL's :teach)".into(),
        ));
    };
    // Trace lines are held while the pendant has the screen, and written
    // when it has closed: written over the pendant they would corrupt what
    // it shows (a joint's value among them).
    let held = Held::default();
    let trace = st.trace.take();
    if trace.is_some() {
        st.trace = Some(Box::new(held.clone()));
    }
    let opened = cx.clock.now();
    let wall = std::time::Instant::now();
    let result = p.teach(st, &mut *cx.clock, &text, refresh, clear);
    st.pendant = Some(p);
    st.trace = trace;
    if let Some(t) = &mut st.trace {
        let _ = t.write_all(&held.0.borrow());
        let _ = t.flush();
    }
    // The box was open, on the program's clock, for as long as the
    // operator kept it open (and at least as long as its jogs take): with
    // tasks, another task that moves the arm meanwhile meets `RobotBusy`.
    let rest = wall.elapsed().as_secs_f64() - (cx.clock.now() - opened);
    if rest > 0.0 {
        cx.clock.sleep(rest);
    }
    st.teach_until = cx.clock.now();
    match result {
        Ok(()) => Ok(None),
        Err(msg) => Err(fail(st, "TeachBox", Exc::CommandNotSupported, msg)),
    }
}

fn place_object(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let w = a[0].real();
    // Like every service but `ValueErrorStatus`: not before `InitRobot`.
    require_init(cx, st, "PlaceObject")?;
    let result = match st.robot.as_simulator() {
        Some(sim) => sim.place_object(w).map_err(|m| (Exc::ConstraintError, m)),
        None => Err((
            Exc::CommandNotSupported,
            "PlaceObject exists only on the simulator: a real hand holds real objects (a rehearsal for a real arm refuses it as the arm would)".into(),
        )),
    };
    match result {
        Ok(()) => Ok(None),
        Err((exc, m)) => Err(fail(st, "PlaceObject", exc, m)),
    }
}
