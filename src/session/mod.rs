//! One session of adair: the sources, the checker state and the machine.
//! `adair run`, `adair check`, the golden runner and the REPL all go through it.

use crate::check::Checker;
use crate::check::ir::{FuncId, Stmt};
use crate::diag::{Diagnostic, FileId};

mod frontend;
use crate::interp::{Machine, Occurrence, builtins};
pub use frontend::{Checked, Disk, Frontend, Host, Loader, Mode, NoHost};
use std::io::Write;

/// One file of the predefined library and the packages it declares.
pub struct StdUnit {
    pub name: &'static str,
    pub text: &'static str,
    /// Its syntax tree, in `syntax::compact`'s form (`stdlib/parsed/`):
    /// a program pays for checking the library, not for parsing it
    /// (issue 32 item 4). `tests/startup.rs` keeps it equal to the text's.
    pub parsed: &'static [u8],
    pub provides: &'static [&'static str],
}

/// The predefined library, embedded so the binary needs no files beside it.
/// The first file (package Ada and Ada.Text_IO, which the others may name)
/// is checked when a session starts; the others when a program names one
/// of their packages in a `with` clause, or is a script (which may name any
/// package without `with`): a program pays only for the packages it uses
/// (issue 11: start-up).
pub const STDLIB: &[StdUnit] = &[
    StdUnit {
        name: "stdlib/ada.air",
        text: include_str!("../../stdlib/ada.air"),
        parsed: include_bytes!("../../stdlib/parsed/ada.bin"),
        provides: &["Ada", "Ada.Text_IO"],
    },
    StdUnit {
        name: "stdlib/text_io_numbers.air",
        text: include_str!("../../stdlib/text_io_numbers.air"),
        parsed: include_bytes!("../../stdlib/parsed/text_io_numbers.bin"),
        provides: &["Ada.Integer_Text_IO", "Ada.Float_Text_IO"],
    },
    StdUnit {
        name: "stdlib/numerics.air",
        text: include_str!("../../stdlib/numerics.air"),
        parsed: include_bytes!("../../stdlib/parsed/numerics.bin"),
        provides: &["Ada.Numerics", "Ada.Numerics.Elementary_Functions"],
    },
    StdUnit {
        name: "stdlib/exceptions.air",
        text: include_str!("../../stdlib/exceptions.air"),
        parsed: include_bytes!("../../stdlib/parsed/exceptions.bin"),
        provides: &["Ada.Exceptions"],
    },
    StdUnit {
        name: "stdlib/calendar.air",
        text: include_str!("../../stdlib/calendar.air"),
        parsed: include_bytes!("../../stdlib/parsed/calendar.bin"),
        provides: &["Ada.Calendar", "Ada.Real_Time"],
    },
    StdUnit {
        name: "stdlib/adair.air",
        text: include_str!("../../stdlib/adair.air"),
        parsed: include_bytes!("../../stdlib/parsed/adair.bin"),
        provides: &["AdaIR", "SERIAL_IO"],
    },
];

/// Packages visible without `with` in script mode and the REPL.
pub const SCRIPT_USES: &[&str] = &[
    "Ada.Text_IO",
    "Ada.Integer_Text_IO",
    "Ada.Float_Text_IO",
    "Ada.Numerics",
    "Ada.Numerics.Elementary_Functions",
    "AdaIR",
];

/// Every import name the runtime binds: the predefined library, then the services.
pub fn resolve(name: &str) -> Option<crate::interp::Binding> {
    builtins::lookup(name)
        .map(crate::interp::Binding::Native)
        .or_else(|| crate::services::lookup(name))
}

/// The text of a stdlib file as the session checks it: the AdaIR package's
/// service declarations are generated from the service table.
pub fn stdlib_text(text: &str) -> std::borrow::Cow<'_, str> {
    const MARKER: &str = "   --  @services\n";
    match text.find(MARKER) {
        Some(i) => std::borrow::Cow::Owned(format!(
            "{}{}{}",
            &text[..i],
            crate::services::table::spec_text(),
            &text[i + MARKER.len()..]
        )),
        None => std::borrow::Cow::Borrowed(text),
    }
}

pub(crate) fn known(name: &str) -> bool {
    resolve(name).is_some()
}

/// A program's text as a session takes it: borrowed (copied once into
/// the session's sources) or already shared (`adair run` and `check` read
/// a file into an `Rc<str>`, so a long program is held once, not twice).
pub trait SourceText {
    fn into_shared(self) -> std::rc::Rc<str>;
}

impl SourceText for &str {
    fn into_shared(self) -> std::rc::Rc<str> {
        self.into()
    }
}

impl SourceText for &String {
    fn into_shared(self) -> std::rc::Rc<str> {
        self.as_str().into()
    }
}

impl SourceText for std::rc::Rc<str> {
    fn into_shared(self) -> std::rc::Rc<str> {
        self
    }
}

pub struct Session {
    /// The sources, the checker and the units loaded: the one check pipeline.
    pub front: Frontend,
    pub machine: Machine,
    /// Warnings of the last check that passed (tools.md: they never stop a
    /// run); the caller shows them, see [`Session::take_warnings`].
    pub warnings: Vec<Diagnostic>,
    /// `--strict`: a warning fails the check like an error.
    pub strict: bool,
    /// Where `run_source` shows the warnings before the program runs, and
    /// whether in colour (`adair run`: standard error).
    pub warnings_to: Option<(Box<dyn Write>, bool)>,
    /// The robot the services drive, owned here and lent to each run
    /// (None until one is chosen: a service call then raises
    /// `Program_Error`, never drives a default robot).
    pub robot: Option<crate::services::RobotState>,
    /// The robot `adair check` judges targets for when no robot is chosen
    /// (`--robot`, a script's `-- adair: --robot`; None: the RV-M1).
    pub check_robot: Option<crate::kinematics::RobotDescription>,
    /// A robot chosen but not built yet ([`Session::set_robot_lazily`]).
    pending_robot: Option<PendingRobot>,
}

/// The simulated robot of [`Session::set_robot_lazily`]: what builds its
/// description, the trace writer and the pacing.
struct PendingRobot {
    desc: Box<dyn FnOnce() -> crate::kinematics::RobotDescription>,
    trace: Option<Box<dyn Write>>,
    realtime: bool,
}

impl PendingRobot {
    /// The robot state, on the simulator.
    fn build(self, checker: &Checker) -> crate::services::RobotState {
        let desc = (self.desc)();
        let sim = Box::new(crate::driver::sim::Simulator::new(desc.clone()));
        let excs = crate::services::ExcIds::bind(checker)
            .unwrap_or_else(|_| crate::services::ExcIds::unbound());
        let mut st = crate::services::RobotState::with_driver(desc, excs, sim);
        st.trace = self.trace;
        st.realtime = self.realtime;
        st
    }
}

/// The engine's side of the pipeline: each source is shown to the
/// machine, each unit of the predefined library elaborates on it.
struct MachineHost<'a> {
    machine: &'a mut Machine,
    robot: &'a mut Option<crate::services::RobotState>,
    pending_robot: &'a mut Option<PendingRobot>,
}

impl Host for MachineHost<'_> {
    fn source_added(&mut self, id: FileId, name: &str, text: &str) {
        self.machine.add_source(id, name, text);
    }
    fn stdlib_checked(&mut self, checker: &Checker, stmts: &[Stmt], provides: &[&str]) {
        let _ = self.machine.run(checker.program(), stmts, None, None);
        // A program reaches the services through the AdaIR package only:
        // a robot chosen lazily is built now.
        if provides.contains(&"AdaIR")
            && let Some(p) = self.pending_robot.take()
        {
            *self.robot = Some(p.build(checker));
        }
        // The robot's exceptions are the AdaIR package's.
        if provides.contains(&"AdaIR")
            && let Some(st) = self.robot
            && let Ok(ids) = crate::services::ExcIds::bind(checker)
        {
            st.excs = ids;
        }
    }
}

/// How a run ended.
#[derive(Debug)]
pub enum Outcome {
    Ok,
    /// Check errors: nothing ran.
    CheckFailed(Vec<Diagnostic>),
    /// An exception left the program.
    Raised(Diagnostic),
}

impl Outcome {
    pub fn exit_code(&self) -> i32 {
        match self {
            Outcome::Ok => 0,
            Outcome::Raised(_) => 1,
            Outcome::CheckFailed(_) => 2,
        }
    }
}

impl Session {
    pub fn new(out: Box<dyn Write>) -> Session {
        let mut machine = Machine::new(out);
        machine.resolver = resolve;
        let mut robot = None;
        let front = Frontend::new(
            std::rc::Rc::new(Disk),
            &mut MachineHost {
                machine: &mut machine,
                robot: &mut robot,
                pending_robot: &mut None,
            },
        );
        Session {
            front,
            machine,
            warnings: Vec::new(),
            strict: false,
            warnings_to: None,
            robot,
            check_robot: None,
            pending_robot: None,
        }
    }

    /// Splits the session into its pipeline and the host that elaborates.
    fn parts(&mut self) -> (&mut Frontend, MachineHost<'_>) {
        (
            &mut self.front,
            MachineHost {
                machine: &mut self.machine,
                robot: &mut self.robot,
                pending_robot: &mut self.pending_robot,
            },
        )
    }

    /// Makes the package `name` of the stdlib visible to later checks
    /// (nothing when no stdlib file declares it); whether one does.
    pub fn need_package(&mut self, name: &str) -> bool {
        let (front, mut host) = self.parts();
        front.need_package(name, &mut host)
    }

    /// Checks every stdlib file (a script or the REPL names any).
    pub fn load_stdlib(&mut self) {
        let (front, mut host) = self.parts();
        front.load_stdlib(&mut host)
    }

    /// Chooses the simulated devices (`--devices FILE.toml`; the default is
    /// the appendix C parallel port at 8#340#): address clauses are checked
    /// against them and programs run against a fresh world of them.
    pub fn set_devices(&mut self, d: crate::devices::Devices) {
        self.front.checker.devices = std::rc::Rc::new(d.clone());
        self.machine.world = Some(crate::devices::World::new(d));
    }

    /// Chooses the robot the services drive (the simulator of `desc`), the
    /// writer that receives the motion trace, and real-time pacing.
    pub fn set_robot(
        &mut self,
        desc: crate::kinematics::RobotDescription,
        trace: Option<Box<dyn Write>>,
        realtime: bool,
    ) {
        let sim = Box::new(crate::driver::sim::Simulator::new(desc.clone()));
        self.set_driver(desc, sim, trace, realtime);
    }

    /// As [`Session::set_robot`], but the robot (and its description,
    /// which `desc` gives) is built only when a program names the AdaIR
    /// package, the only way to a service, or when the pendant or a
    /// recording needs it: a program that never moves the arm does not
    /// pay for its kinematics (`adair run`'s start-up, issue 32). Until
    /// then [`Session::robot_state`] is `None`.
    pub fn set_robot_lazily(
        &mut self,
        desc: Box<dyn FnOnce() -> crate::kinematics::RobotDescription>,
        trace: Option<Box<dyn Write>>,
        realtime: bool,
    ) {
        self.robot = None;
        self.machine.realtime = realtime;
        self.pending_robot = Some(PendingRobot {
            desc,
            trace,
            realtime,
        });
        if self.front.stdlib_loaded("AdaIR") {
            self.build_pending_robot();
        }
    }

    /// Builds the robot of [`Session::set_robot_lazily`] now, if pending.
    fn build_pending_robot(&mut self) {
        if let Some(p) = self.pending_robot.take() {
            self.robot = Some(p.build(&self.front.checker));
        }
    }

    /// As [`Session::set_robot`] with any driver; a driver whose motions take
    /// real time (a real arm) brings the wall clock with it.
    pub fn set_driver(
        &mut self,
        desc: crate::kinematics::RobotDescription,
        driver: Box<dyn crate::driver::Robot>,
        trace: Option<Box<dyn Write>>,
        realtime: bool,
    ) {
        // Bound again when the AdaIR package is checked (`load_unit`): a
        // program without it calls no service.
        let excs = crate::services::ExcIds::bind(&self.front.checker)
            .unwrap_or_else(|_| crate::services::ExcIds::unbound());
        if driver.real_time() {
            self.machine.clock = Box::new(crate::services::WallClock::default());
        }
        // A wall clock takes its time already.
        self.machine.realtime = realtime && !driver.real_time();
        let mut st = crate::services::RobotState::with_driver(desc, excs, driver);
        st.trace = trace;
        st.realtime = realtime;
        self.pending_robot = None;
        self.robot = Some(st);
    }

    /// The services' robot state, once a robot is chosen.
    pub fn robot_state(&self) -> Option<&crate::services::RobotState> {
        self.robot.as_ref()
    }

    /// The robot state, to change it between runs (REPL, TeachBox).
    pub fn robot_state_mut(&mut self) -> Option<&mut crate::services::RobotState> {
        self.robot.as_mut()
    }

    /// Where the user stopped the last run (Ctrl-C), once.
    pub fn take_stopped(&mut self) -> Option<String> {
        self.robot.as_mut().and_then(|st| st.stopped.take())
    }

    /// Records every motion's support points from now on (`--record`, `--plot`).
    pub fn start_recording(&mut self) {
        self.build_pending_robot();
        if let Some(st) = &mut self.robot {
            st.record = Some(Vec::new());
        }
    }

    /// Installs the screen teach pendant behind `TeachBox`.
    pub fn install_pendant(&mut self, pendant: Box<dyn crate::services::Pendant>) {
        self.build_pending_robot();
        if let Some(st) = &mut self.robot {
            st.pendant = Some(pendant);
        }
    }

    /// Runs `f` as a rehearsal: on a simulated copy of the robot (same
    /// pose and settings), on a deep copy of the program's data, on virtual
    /// time, with output discarded and no input; afterwards the robot, the
    /// data, the clock and the output are the ones from before, untouched.
    pub fn rehearsing<T>(&mut self, f: impl FnOnce(&mut Session) -> T) -> T {
        let copy = self.machine.copy_globals();
        let globals = self.machine.swap_globals(copy);
        let out = std::mem::replace(&mut self.machine.out, Box::new(std::io::sink()));
        let input = std::mem::replace(
            &mut self.machine.input,
            Box::new(std::io::BufReader::new(std::io::empty())),
        );
        let t = self.machine.clock.now();
        let clock = std::mem::replace(
            &mut self.machine.clock,
            Box::new(crate::interp::VirtualClock { t }),
        );
        let col = self.machine.col;
        let stand_in = self.robot.as_ref().map(|r| r.rehearsal());
        let robot = std::mem::replace(&mut self.robot, stand_in);
        // The tasks of earlier entries and the devices are rehearsed on
        // copies too.
        let tasks = self.machine.sched.clone();
        let world = self.machine.world.clone();
        // The live view is not told what the rehearsal's devices do.
        if let Some(w) = self.machine.world.as_mut() {
            w.set_sink(None);
        }
        let result = f(self);
        self.machine.world = world;
        self.machine.sched = tasks;
        self.robot = robot;
        self.machine.col = col;
        self.machine.clock = clock;
        self.machine.input = input;
        self.machine.out = out;
        self.machine.swap_globals(globals);
        result
    }

    /// Runs checked statements (and the main subprogram) with the robot lent.
    pub fn run_checked(
        &mut self,
        stmts: &[Stmt],
        main: Option<FuncId>,
    ) -> Result<(), Box<Occurrence>> {
        let svc = self
            .robot
            .as_mut()
            .map(|r| r as &mut dyn crate::interp::Services);
        self.machine
            .run(self.front.checker.program(), stmts, main, svc)
    }

    /// Evaluates a checked expression (a REPL entry) with the robot lent.
    pub fn eval_checked(
        &mut self,
        e: &crate::check::ir::Ex,
    ) -> Result<crate::interp::Value, Box<Occurrence>> {
        let svc = self
            .robot
            .as_mut()
            .map(|r| r as &mut dyn crate::interp::Services);
        self.machine.eval_expr(self.front.checker.program(), e, svc)
    }

    /// For a program that is checked and run once (`adair run`): a long
    /// subprogram body is compiled a part at a time as it is checked, so
    /// that its checked form is never held whole (see
    /// `Checker::compile_parts`). Its code is then used up by its run.
    pub fn compile_as_checked(&mut self) {
        self.front.checker.options.compile_parts = self.machine.part_compiler();
    }

    /// Checks a program (`script`: a REPL entry, statements at the top)
    /// through the pipeline; its statements (after those of the packages
    /// it names) and its main subprogram, or its diagnostics. Its warnings
    /// are kept in [`Session::warnings`].
    pub fn check_source(
        &mut self,
        name: &str,
        text: impl SourceText,
        script: bool,
    ) -> Result<(Vec<Stmt>, Option<FuncId>), Vec<Diagnostic>> {
        let strict = self.strict;
        let (front, mut host) = self.parts();
        let mut checked = front.check(name, text.into_shared(), script, Mode::Run, None, &mut host);
        // A whole program (not a REPL entry, whose robot earlier entries
        // set up) is also read for the robot faults it certainly has.
        if !script && checked.passes(false) {
            let lint = self.lint(&checked);
            checked.diags.extend(lint);
            checked
                .diags
                .sort_by_key(|d| (d.span.context, d.span.start));
        }
        if !checked.passes(strict) {
            return Err(checked.diags);
        }
        self.warnings = checked.diags;
        Ok((checked.stmts, checked.main))
    }

    /// W0005 and W0006 (see `services::lint`) for a checked program.
    fn lint(&self, checked: &Checked) -> Vec<Diagnostic> {
        // A program reaches the services through the AdaIR package only:
        // without it there is nothing to warn about, and no robot
        // description to read.
        if !self.front.stdlib_loaded("AdaIR") {
            return Vec::new();
        }
        let chosen = self
            .robot
            .as_ref()
            .map(|r| r.robot.description().clone())
            .or_else(|| self.check_robot.clone());
        let Some(robot) =
            chosen.or_else(|| crate::kinematics::RobotDescription::builtin("rv-m1").ok())
        else {
            return Vec::new();
        };
        crate::services::lint::warnings(
            self.front.checker.program(),
            &checked.stmts,
            checked.main,
            &robot,
        )
    }

    /// The warnings of the last successful check, taken.
    pub fn take_warnings(&mut self) -> Vec<Diagnostic> {
        std::mem::take(&mut self.warnings)
    }

    /// Checks and runs a whole program.
    pub fn run_source(&mut self, name: &str, text: impl SourceText) -> Outcome {
        let (stmts, main) = match self.check_source(name, text, false) {
            Ok(x) => x,
            Err(d) => return Outcome::CheckFailed(d),
        };
        if !self.warnings.is_empty()
            && let Some((w, color)) = &mut self.warnings_to
        {
            let text = crate::diag::render(&self.warnings, &self.front.sources, *color);
            let _ = w.write_all(text.as_bytes());
            let _ = w.flush();
        }
        let r = self.run_checked(&stmts, main);
        self.machine.finish();
        match r {
            Ok(()) => Outcome::Ok,
            Err(o) => Outcome::Raised(self.exception_diag(&o)),
        }
    }

    /// The diagnostic for an exception that left the program.
    pub fn exception_diag(&self, o: &Occurrence) -> Diagnostic {
        let name = &self.front.checker.tables.excs[o.exc as usize].name;
        crate::interp::diagnostics::left_the_program(o, name)
    }
}

/// `--rehearse`: reads the arm's pose over `settings` (`WH` only, no
/// motion), runs the whole program `text` on the simulator from there, and
/// answers whether the real arm may run it. A failed rehearsal gives the
/// run's diagnostics (rendered) and its exit status; nothing was sent to
/// move the arm.
pub fn rehearse(
    desc: &crate::kinematics::RobotDescription,
    settings: &crate::driver::serial::PortSettings,
    name: &str,
    text: &str,
    color: bool,
) -> Result<(), (String, i32)> {
    let mut probe = crate::driver::serial::Serial::new(desc.clone(), settings.clone(), None);
    let pose = probe.read_pose().map_err(|e| {
        (
            format!("adair: rehearsal: cannot read the arm's pose: {e}\n"),
            1,
        )
    })?;
    drop(probe);
    let mut sim = crate::driver::sim::Simulator::new(desc.clone());
    sim.stand_in_for_real_arm();
    sim.set_joints(pose);
    let mut s = Session::new(Box::new(std::io::sink()));
    // The rehearsal must not eat the real run's input: it reads none.
    s.machine.input = Box::new(std::io::BufReader::new(std::io::empty()));
    s.set_driver(desc.clone(), Box::new(sim), None, false);
    if let Some(st) = s.robot_state_mut() {
        // A `TeachBox` cannot be rehearsed: it says so.
        st.rehearsal = true;
    }
    s.front.checker.options.simulator_only = crate::services::SIMULATOR_ONLY;
    let outcome = s.run_source(name, text);
    // A failed rehearsal ends the run before the real one is checked: its
    // warnings (a simulator-only service) are shown with its failure.
    let warned = crate::diag::render(&s.take_warnings(), &s.front.sources, color);
    let shown = match &outcome {
        Outcome::Ok => return Ok(()),
        Outcome::CheckFailed(d) => crate::diag::render(d, &s.front.sources, color),
        Outcome::Raised(d) => {
            warned + &crate::diag::render(std::slice::from_ref(d), &s.front.sources, color)
        }
    };
    Err((
        format!("{shown}adair: the rehearsal on the simulator failed: the arm was not moved\n"),
        outcome.exit_code(),
    ))
}

/// What `adair run --rehearse` says on stderr before it moves the arm.
pub const REHEARSED: &str = "adair: the rehearsal on the simulator ended without an unhandled exception; moving the arm now (a rehearsal cannot cover branches that depend on input)";

/// Whether `unit` is a script: statements at the top, or (unless it is a
/// `library` unit: the stdlib, a package file named by `with`) only
/// declarations without a `with` and without a main procedure (tasks that
/// do the work).
pub fn is_script_unit(unit: &crate::syntax::ast::CompilationUnit, library: bool) -> bool {
    use crate::syntax::ast::{DeclKind, TopItem};
    let main_candidate = unit.items.iter().any(|i| {
        matches!(i, TopItem::Decl(d) if matches!(&d.kind,
            DeclKind::SubprogramBody(b) if b.spec.params.is_empty() && b.spec.ret.is_none()))
    });
    let withs = unit.items.iter().any(|i| matches!(i, TopItem::With(..)));
    unit.items.iter().any(|i| matches!(i, TopItem::Stmt(_)))
        || (!withs && !main_candidate && !library)
}
