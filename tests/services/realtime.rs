//! Motions paced to the wall clock (`RealTime => True`, `--realtime`) and
//! the user's stop in the middle of one (the pieces of the service core
//! they use, `opts`, `interpolate`, the wall clock, are tested in
//! `src/services/tests/parts.rs`). The golden scripts run on virtual time
//! and never reach this code. Wall-clock figures are lower bounds only.

use adair::kinematics::RobotDescription;
use adair::session::{Outcome, Session};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

fn j1(s: &Session) -> f64 {
    s.robot_state().expect("robot").robot.joints()[0]
}

/// The user's stop (Ctrl-C) `ms` milliseconds from now, as the CLI's
/// signal handler gives it.
fn stop_after(s: &mut Session, ms: u64) -> std::thread::JoinHandle<()> {
    let flag = Arc::new(AtomicBool::new(false));
    s.machine.interrupted = Some(flag.clone());
    std::thread::spawn(move || {
        std::thread::sleep(Duration::from_millis(ms));
        flag.store(true, Ordering::SeqCst);
    })
}

#[test]
fn a_realtime_motion_takes_its_time_on_the_wall_clock_and_ends_where_it_was_sent() {
    // RealTime is the fourth argument (after Time and Control): a mix-up of
    // the option indices leaves the motion unpaced.
    let mut s = super::rv_m1_session();
    let start = Instant::now();
    let o = s.run_source(
        "rt.air",
        "InitRobot;\nMoveAxesRelative ((0.5, 0.0, 0.0, 0.0, 0.0), Time => 0.6, RealTime => True);\n",
    );
    assert!(matches!(o, Outcome::Ok), "{o:?}");
    assert!(
        start.elapsed() >= Duration::from_millis(590),
        "{:?}",
        start.elapsed()
    );
    assert!((j1(&s) - 0.5).abs() < 1e-9);
    // Control => True returns at once: it is not paced.
    let mut s = super::rv_m1_session();
    let start = Instant::now();
    let o = s.run_source(
        "rt.air",
        "InitRobot;\nMoveAxesRelative ((0.5, 0.0, 0.0, 0.0, 0.0), Time => 2.0, Control => True, RealTime => True);\n",
    );
    assert!(matches!(o, Outcome::Ok), "{o:?}");
    assert!(
        start.elapsed() < Duration::from_millis(1500),
        "{:?}",
        start.elapsed()
    );
}

#[test]
fn waiting_for_a_paced_control_motion_takes_its_rest_on_the_wall_clock() {
    // Control => True returns at once, but the motion is paced: the next
    // service that waits for it (ValueAxes, a motion, InitRobot) waits on
    // the wall clock too, with `RealTime => True` and with `--realtime`.
    for (realtime, opt) in [(false, ", RealTime => True"), (true, "")] {
        let mut s = super::rv_m1_session();
        s.robot_state_mut().unwrap().realtime = realtime;
        let start = Instant::now();
        let text = format!(
            "InitRobot;\nMoveAxesRelative ((0.5, 0.0, 0.0, 0.0, 0.0), Time => 0.5, Control => True{opt});\n\
             Put (ValueAxes (1));\nMoveAxesRelative ((0.1, 0.0, 0.0, 0.0, 0.0), Control => True{opt});\nInitRobot;\n"
        );
        let o = s.run_source("rt.air", &text);
        assert!(matches!(o, Outcome::Ok), "{o:?}");
        assert!(
            start.elapsed() >= Duration::from_millis(490),
            "{realtime}: {:?}",
            start.elapsed()
        );
        assert_eq!(s.take_stopped(), None, "nobody stopped the run");
    }
}

#[test]
fn a_stop_during_a_realtime_motion_leaves_the_arm_where_it_had_got_to() {
    let mut s = super::rv_m1_session();
    let setter = stop_after(&mut s, 200);
    let o = s.run_source(
        "rt.air",
        "InitRobot;\nMoveAxesRelative ((0.5, 0.0, 0.0, 0.0, 0.0), Time => 1.0, RealTime => True);\n",
    );
    setter.join().unwrap();
    // The run ends there (the caller reports where it stopped).
    assert!(matches!(o, Outcome::Ok), "{o:?}");
    let stopped = s.take_stopped().expect("where the run stopped");
    // "after T of 1.000 s": T is the fraction paced, and the joint, the
    // virtual clock and the message agree on it.
    let after: f64 = stopped
        .split("(after ")
        .nth(1)
        .and_then(|r| r.split(' ').next())
        .and_then(|t| t.parse().ok())
        .unwrap_or_else(|| panic!("{stopped}"));
    assert!(stopped.contains("of 1.000 s"), "{stopped}");
    assert!((0.15..0.95).contains(&after), "{stopped}");
    let q = j1(&s);
    assert!(
        (q - 0.5 * after).abs() < 0.5 * 0.002,
        "J1 {q} after {after} s"
    );
    let t = s.machine.clock.now();
    assert!(
        (t - after).abs() < 0.002,
        "virtual clock {t} after {after} s"
    );
}

#[test]
fn a_straight_line_may_be_given_exactly_its_fastest_time() {
    // At full velocity a straight line takes its fastest time; the same
    // line back with `Time =>` that time is accepted (a tolerance of 1 ns
    // for the rounding of the clock), and a shorter one is TimeInvalid.
    let mut s = super::rv_m1_session();
    let text = "\
InitRobot;
SetVelocity (100.0);
MoveFrameAbsolute (((-1.0, 0.0, 0.0, 250.0), (0.0, 1.0, 0.0, -50.0), (0.0, 0.0, -1.0, 200.0)));
SetMoveMode (StraightLine);
declare
   T0 : constant Duration := Ada.Calendar.Seconds (Ada.Calendar.Clock);
   D : Duration;
begin
   MoveFrameAbsolute (((-1.0, 0.0, 0.0, 250.0), (0.0, 1.0, 0.0, 50.0), (0.0, 0.0, -1.0, 200.0)));
   D := Ada.Calendar.Seconds (Ada.Calendar.Clock) - T0;
   MoveFrameAbsolute (((-1.0, 0.0, 0.0, 250.0), (0.0, 1.0, 0.0, -50.0), (0.0, 0.0, -1.0, 200.0)), Time => D);
   Put_Line (\"exact time accepted\");
   MoveFrameAbsolute (((-1.0, 0.0, 0.0, 250.0), (0.0, 1.0, 0.0, 50.0), (0.0, 0.0, -1.0, 200.0)), Time => D * 0.99);
exception
   when TimeInvalid => Put_Line (\"shorter refused\");
end;
";
    let out = adair::golden::SharedBuf::default();
    s.machine.out = Box::new(out.clone());
    let o = s.run_source("fast.air", text);
    assert!(matches!(o, Outcome::Ok), "{o:?}");
    assert_eq!(out.take(), "exact time accepted\nshorter refused\n");
}

#[test]
fn a_path_may_be_given_exactly_its_fastest_time() {
    // As a straight line: MovePath at full velocity takes its fastest time;
    // the same path from the same start with `Time =>` that time is
    // accepted, a shorter one is TimeInvalid.
    let mut s = super::rv_m1_session();
    let text = "\
InitRobot;
SetVelocity (100.0);
CreatePath (1);
InsertPosition (1, 1, ((-1.0, 0.0, 0.0, 300.0), (0.0, 1.0, 0.0, 0.0), (0.0, 0.0, -1.0, 250.0)));
InsertPosition (1, 2, ((-1.0, 0.0, 0.0, 250.0), (0.0, 1.0, 0.0, -50.0), (0.0, 0.0, -1.0, 100.0)));
declare
   T0 : constant Duration := Ada.Calendar.Seconds (Ada.Calendar.Clock);
   D : Duration;
begin
   MovePath (1);
   D := Ada.Calendar.Seconds (Ada.Calendar.Clock) - T0;
   MoveAxesAbsolute ((0.0, 0.0, 0.0, 0.0, 0.0));
   MovePath (1, Time => D);
   Put_Line (\"exact time accepted\");
   MoveAxesAbsolute ((0.0, 0.0, 0.0, 0.0, 0.0));
   MovePath (1, Time => D * 0.99);
exception
   when TimeInvalid => Put_Line (\"shorter refused\");
end;
";
    let out = adair::golden::SharedBuf::default();
    s.machine.out = Box::new(out.clone());
    let o = s.run_source("path.air", text);
    assert!(matches!(o, Outcome::Ok), "{o:?}");
    assert_eq!(out.take(), "exact time accepted\nshorter refused\n");
}

/// A stand-in for a real arm: the simulator's motions, but taking "wall
/// clock" time in the driver (`real_time`), with the waits counted.
struct FakeArm {
    sim: adair::driver::sim::Simulator,
    pending: bool,
    waits: std::rc::Rc<std::cell::Cell<u32>>,
}

impl adair::driver::Robot for FakeArm {
    fn description(&self) -> &RobotDescription {
        self.sim.description()
    }
    fn joints(&self) -> adair::kinematics::Joints {
        self.sim.joints()
    }
    fn read_joints(&self) -> adair::kinematics::Joints {
        self.sim.read_joints()
    }
    fn real_time(&self) -> bool {
        true
    }
    fn start_motion(
        &mut self,
        points: &[adair::kinematics::Joints],
        duration: f64,
    ) -> Result<(), adair::driver::DriverError> {
        self.pending = true;
        self.sim.start_motion(points, duration)
    }
    fn wait_motion(&mut self) -> Result<(), adair::driver::DriverError> {
        if self.pending {
            self.waits.set(self.waits.get() + 1);
            self.pending = false;
        }
        Ok(())
    }
    fn motion_pending(&self) -> bool {
        self.pending
    }
    fn calibrate(&mut self) -> Result<(), adair::driver::DriverError> {
        self.sim.calibrate()
    }
    fn gripper(&self) -> adair::driver::GripperState {
        self.sim.gripper()
    }
    fn move_gripper(
        &mut self,
        opening: f64,
        force_limit: Option<f64>,
    ) -> Result<adair::driver::GripperState, adair::driver::DriverError> {
        self.sim.move_gripper(opening, force_limit)
    }
}

#[test]
fn on_a_real_arm_a_motion_waits_for_the_arm_unless_control_is_true() {
    let desc = RobotDescription::builtin("rv-m1").unwrap();
    let waits = std::rc::Rc::new(std::cell::Cell::new(0));
    let arm = FakeArm {
        sim: adair::driver::sim::Simulator::new(desc.clone()),
        pending: false,
        waits: waits.clone(),
    };
    let mut s = Session::new(Box::new(std::io::sink()));
    s.set_driver(desc, Box::new(arm), None, false);
    let run = |s: &mut Session, text: &str| {
        let o = s.run_source("arm.air", text);
        assert!(matches!(o, Outcome::Ok), "{text}: {o:?}");
    };
    run(&mut s, "InitRobot;\n");
    let w0 = waits.get();
    run(&mut s, "MoveAxesRelative ((0.1, 0.0, 0.0, 0.0, 0.0));\n");
    assert_eq!(waits.get(), w0 + 1, "a motion waits for the arm's reply");
    run(
        &mut s,
        "MoveAxesRelative ((0.1, 0.0, 0.0, 0.0, 0.0), Control => True);\n",
    );
    assert_eq!(waits.get(), w0 + 1, "Control => True returns at once");
    // The next motion waits for that one first, then for its own end.
    run(&mut s, "MoveAxesRelative ((-0.2, 0.0, 0.0, 0.0, 0.0));\n");
    assert_eq!(waits.get(), w0 + 3);
    assert!(j1(&s).abs() < 1e-9);
}

#[test]
fn a_stop_while_waiting_for_a_paced_control_motion_leaves_the_arm_where_it_had_got_to() {
    let mut s = super::rv_m1_session();
    let setter = stop_after(&mut s, 300);
    // An unpaced motion of 0.4 s first: the paced one starts at 0.4 s of
    // virtual time and takes 1.5 s.
    let o = s.run_source(
        "rt.air",
        "InitRobot;\nMoveAxesRelative ((0.0, 0.0, 0.2, 0.0, 0.0), Time => 0.4);\n\
         MoveAxesRelative ((0.5, 0.0, 0.0, 0.0, 0.0), Time => 1.5, Control => True, RealTime => True);\n\
         Put (ValueAxes (1));\n",
    );
    setter.join().unwrap();
    assert!(matches!(o, Outcome::Ok), "{o:?}");
    let stopped = s.take_stopped().expect("where the run stopped");
    assert!(
        stopped.contains("in ValueAxes (waiting for a Control => True motion)"),
        "{stopped}"
    );
    // The virtual clock stopped with the wall clock, and the arm with it:
    // J1 is the same fraction of its way.
    let t = s.machine.clock.now() - 0.4;
    assert!(
        (0.2..1.4).contains(&t),
        "virtual clock {t} s into the motion"
    );
    let q = j1(&s);
    assert!((q - 0.5 * t / 1.5).abs() < 0.5 * 0.002, "J1 {q} at {t} s");
}

/// `--record` of a motion the user stopped (Ctrl-C), paced to the wall
/// clock or a `Control => True` one being waited for: the recording holds
/// the motion up to where the arm stopped, every 20 ms, and nothing after
/// it; its last sample is the arm's pose at the stop.
#[test]
fn a_stopped_motion_is_recorded_up_to_where_the_arm_stopped() {
    for control in [false, true] {
        let mut s = super::rv_m1_session();
        s.robot_state_mut().unwrap().record = Some(Vec::new());
        let setter = stop_after(&mut s, 300);
        let opts = if control {
            "Control => True, RealTime => True);\nPut (ValueAxes (1));\n"
        } else {
            "RealTime => True);\n"
        };
        // An unpaced motion of 0.4 s first, then the paced one of 1.5 s.
        let text = format!(
            "InitRobot;\nMoveAxesRelative ((0.0, 0.0, 0.2, 0.0, 0.0), Time => 0.4);\n\
             MoveAxesRelative ((0.5, 0.0, 0.0, 0.0, 0.0), Time => 1.5, {opts}"
        );
        let o = s.run_source("rt.air", &text);
        setter.join().unwrap();
        assert!(matches!(o, Outcome::Ok), "{o:?}");
        assert!(s.take_stopped().is_some(), "{control}: not stopped");
        let t = s.machine.clock.now();
        let st = s.robot_state().unwrap();
        let r = st.record.as_ref().unwrap();
        let last = r.last().unwrap();
        assert!(
            (last.t - t).abs() < 1e-9,
            "{control}: ends at {} not {t}",
            last.t
        );
        assert_eq!(last.joints, st.robot.joints(), "{control}");
        assert!(last.joints[0] > 0.01 && last.joints[0] < 0.49, "{control}");
        let during: Vec<_> = r.iter().filter(|x| x.t > 0.4 + 1e-9).collect();
        assert!(
            during.len() + 1 >= ((t - 0.4) / 0.02) as usize,
            "{control}: {} samples in {} s",
            during.len(),
            t - 0.4
        );
        for w in r.windows(2) {
            assert!(w[1].t >= w[0].t, "{control}: time goes back {w:?}");
        }
        for w in during.windows(2) {
            assert!(w[1].joints[0] > w[0].joints[0], "{control}: {w:?}");
        }
    }
}

/// A stand-in real arm whose wait for a motion is interrupted (Ctrl-C).
struct InterruptedArm(FakeArm);

impl adair::driver::Robot for InterruptedArm {
    fn description(&self) -> &RobotDescription {
        self.0.description()
    }
    fn joints(&self) -> adair::kinematics::Joints {
        self.0.joints()
    }
    fn read_joints(&self) -> adair::kinematics::Joints {
        self.0.read_joints()
    }
    fn real_time(&self) -> bool {
        true
    }
    fn start_motion(
        &mut self,
        points: &[adair::kinematics::Joints],
        duration: f64,
    ) -> Result<(), adair::driver::DriverError> {
        self.0.start_motion(points, duration)
    }
    fn wait_motion(&mut self) -> Result<(), adair::driver::DriverError> {
        self.0.wait_motion()?;
        Err(adair::driver::DriverError::Interrupted)
    }
    fn motion_pending(&self) -> bool {
        self.0.motion_pending()
    }
    fn calibrate(&mut self) -> Result<(), adair::driver::DriverError> {
        self.0.calibrate()
    }
    fn gripper(&self) -> adair::driver::GripperState {
        self.0.gripper()
    }
    fn move_gripper(
        &mut self,
        opening: f64,
        force_limit: Option<f64>,
    ) -> Result<adair::driver::GripperState, adair::driver::DriverError> {
        self.0.move_gripper(opening, force_limit)
    }
}

#[test]
fn a_stopped_motion_of_a_real_arm_is_recorded_up_to_the_stop() {
    let desc = RobotDescription::builtin("rv-m1").unwrap();
    let arm = InterruptedArm(FakeArm {
        sim: adair::driver::sim::Simulator::new(desc.clone()),
        pending: false,
        waits: Default::default(),
    });
    let mut s = Session::new(Box::new(std::io::sink()));
    s.set_driver(desc, Box::new(arm), None, false);
    let st = s.robot_state_mut().unwrap();
    st.record = Some(Vec::new());
    // InitRobot's own motion would be the one interrupted.
    st.initialized = true;
    let o = s.run_source(
        "arm.air",
        "MoveAxesRelative ((0.5, 0.0, 0.0, 0.0, 0.0), Time => 30.0);\n",
    );
    assert!(matches!(o, Outcome::Ok), "{o:?}");
    let stopped = s.take_stopped().expect("stopped");
    assert!(stopped.contains("into the motion"), "{stopped}");
    let st = s.robot_state().unwrap();
    let r = st.record.as_ref().unwrap();
    assert!(!r.is_empty(), "nothing recorded");
    let last = r.last().unwrap();
    // Stopped at once: no sample of the 30 s plan after the stop, and the
    // last is where the driver says the arm ends (its line's target).
    assert!(last.t < 1.0, "{stopped}: recorded to {}", last.t);
    assert_eq!(last.joints, st.robot.joints());
}
