//! The robot state the services keep between calls, and its
//! construction (the simulator, a driver, a rehearsal's stand-in).

use super::*;

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

pub(super) fn standard_tool(kin: &Kinematics) -> Tool {
    let g = *kin.description().gripper();
    Tool {
        trans: kin.standard_tool(),
        force_min: g.force_min,
        force_max: g.force_max,
        dist_min: g.opening_min,
        dist_max: g.opening_max,
    }
}
