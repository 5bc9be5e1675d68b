//! The services' plumbing: raising exceptions, the initialization and
//! fresh-pose checks, the user's stop, value conversions, the wall clock.

use super::*;

// ---- plumbing ----

/// Raises an AdaIR exception from a service, recording its command code.
pub(crate) fn fail(st: &mut RobotState, service: &str, exc: Exc, msg: String) -> ServiceFault {
    st.error_status = code_of(service);
    ServiceFault::Raise(st.excs.id(exc), msg)
}

pub(super) fn kin_fail(st: &mut RobotState, service: &str, e: &KinError) -> ServiceFault {
    fail(st, service, e.exception().into(), e.to_string())
}

pub(super) fn require_init(cx: &mut Cx, st: &mut RobotState, service: &str) -> R<()> {
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
pub(super) fn require_fresh_pose(cx: &mut Cx, st: &mut RobotState, service: &str) -> R<()> {
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
pub(super) fn wait_for_control(cx: &mut Cx, st: &mut RobotState, service: &str) -> R<()> {
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
pub(super) fn stop(cx: &mut Cx, st: &mut RobotState, service: &str, what: &str) -> ServiceFault {
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
    Value::Arr(Array::from_vals(data).with_bounds(&[(1, 3), (1, 4)]))
}

pub fn frame_rows(v: &Value) -> [[f64; 4]; 3] {
    let mut rows = [[0.0; 4]; 3];
    if let Value::Arr(a) = v {
        for (k, x) in a.data().iter().enumerate().take(12) {
            rows[k / 4][k % 4] = x.real();
        }
    }
    rows
}

pub(super) fn axes_value(j: &Joints) -> Value {
    Value::Arr(j.iter().map(|x| Value::Real(*x)).collect())
}

pub(super) fn axes_of(v: &Value) -> Joints {
    let mut j = [0.0; 5];
    if let Value::Arr(a) = v {
        for (k, x) in a.data().iter().enumerate().take(5) {
            j[k] = x.real();
        }
    }
    j
}

pub(super) fn deg5(j: &Joints) -> String {
    let d: Vec<String> = j
        .iter()
        .map(|x| format!("{:.2}", x.to_degrees() + 0.0))
        .collect();
    format!("({})", d.join(", "))
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
