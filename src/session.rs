//! One session of adair: the sources, the checker state and the machine.
//! `adair run`, `adair check`, the golden runner and the REPL all go through it.

use crate::check::Checker;
use crate::check::ir::{FuncId, Stmt};
use crate::diag::{Diagnostic, Phase, Sources, Span};
use crate::interp::{Machine, Occurrence, builtins};
use std::io::Write;

/// One file of the predefined library and the packages it declares.
pub struct StdUnit {
    pub name: &'static str,
    pub text: &'static str,
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
        text: include_str!("../stdlib/ada.air"),
        provides: &["Ada", "Ada.Text_IO"],
    },
    StdUnit {
        name: "stdlib/text_io_numbers.air",
        text: include_str!("../stdlib/text_io_numbers.air"),
        provides: &["Ada.Integer_Text_IO", "Ada.Float_Text_IO"],
    },
    StdUnit {
        name: "stdlib/numerics.air",
        text: include_str!("../stdlib/numerics.air"),
        provides: &["Ada.Numerics", "Ada.Numerics.Elementary_Functions"],
    },
    StdUnit {
        name: "stdlib/exceptions.air",
        text: include_str!("../stdlib/exceptions.air"),
        provides: &["Ada.Exceptions"],
    },
    StdUnit {
        name: "stdlib/calendar.air",
        text: include_str!("../stdlib/calendar.air"),
        provides: &["Ada.Calendar", "Ada.Real_Time"],
    },
    StdUnit {
        name: "stdlib/adair.air",
        text: include_str!("../stdlib/adair.air"),
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

fn known(name: &str) -> bool {
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
    pub sources: Sources,
    pub checker: Checker,
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
    /// Which stdlib files are checked (see [`STDLIB`]).
    loaded: Vec<bool>,
    /// A stdlib file is being checked.
    in_stdlib: bool,
    /// Files of packages named by `with` that are loaded (or being loaded).
    with_files: Vec<std::path::PathBuf>,
    /// Their elaboration, to run before the program that names them.
    elaboration: Vec<Stmt>,
    /// Such a file is being checked (a library unit: never a script).
    in_with_file: bool,
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
        let mut s = Session {
            sources: Sources::default(),
            checker: Checker::new(known),
            machine: Machine::new(out),
            warnings: Vec::new(),
            strict: false,
            warnings_to: None,
            robot: None,
            with_files: Vec::new(),
            elaboration: Vec::new(),
            in_with_file: false,
            loaded: Vec::new(),
            in_stdlib: false,
        };
        s.machine.resolver = resolve;
        s.checker
            .set_import_profiles(crate::services::import_profile);
        s.load_unit(0);
        s
    }

    /// Checks and elaborates the stdlib file `i` (once).
    fn load_unit(&mut self, i: usize) {
        if self.loaded.len() <= i {
            self.loaded.resize(STDLIB.len(), false);
        }
        if self.loaded[i] {
            return;
        }
        self.loaded[i] = true;
        let u = &STDLIB[i];
        let outer = std::mem::replace(&mut self.in_stdlib, true);
        let checked = self.check_source(u.name, &*stdlib_text(u.text), false);
        self.in_stdlib = outer;
        let stmts = match checked {
            Ok((stmts, _)) => stmts,
            // The embedded library is tested: it checks in a fresh session.
            // Checked later in a session whose program clashes with it, it
            // may not; the program then meets the missing names.
            Err(_) if i > 0 => return,
            Err(d) => panic!("stdlib does not check: {d:?}"),
        };
        let _ = self.machine.run(self.checker.program(), &stmts, None, None);
        for pkg in u.provides {
            if matches!(*pkg, "AdaIR" | "Ada.Text_IO") {
                for e in ["Name_Error", "Use_Error", "Data_Error", "End_Error"] {
                    self.checker.export(pkg, e, "Ada.IO_Exceptions");
                }
            }
        }
        // The robot's exceptions are the AdaIR package's.
        if u.provides.contains(&"AdaIR")
            && let Some(st) = &mut self.robot
            && let Ok(ids) = crate::services::ExcIds::bind(&self.checker)
        {
            st.excs = ids;
        }
    }

    /// Makes the package `name` of the stdlib visible to later checks
    /// (nothing when no stdlib file declares it); whether one does.
    pub fn need_package(&mut self, name: &str) -> bool {
        let Some(i) = STDLIB
            .iter()
            .position(|u| u.provides.iter().any(|p| p.eq_ignore_ascii_case(name)))
        else {
            return false;
        };
        self.load_unit(i);
        true
    }

    /// Checks every stdlib file (the language server offers all of them).
    pub fn load_stdlib(&mut self) {
        for i in 0..STDLIB.len() {
            self.load_unit(i);
        }
    }

    /// Chooses the simulated devices (`--devices FILE.toml`; the default is
    /// the appendix C parallel port at 8#340#): address clauses are checked
    /// against them and programs run against a fresh world of them.
    pub fn set_devices(&mut self, d: crate::devices::Devices) {
        self.checker.devices = std::rc::Rc::new(d.clone());
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
        let excs = crate::services::ExcIds::bind(&self.checker)
            .unwrap_or_else(|_| crate::services::ExcIds::unbound());
        if driver.real_time() {
            self.machine.clock = Box::new(crate::services::WallClock::default());
        }
        // A wall clock takes its time already.
        self.machine.realtime = realtime && !driver.real_time();
        let mut st = crate::services::RobotState::with_driver(desc, excs, driver);
        st.trace = trace;
        st.realtime = realtime;
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
        if let Some(st) = &mut self.robot {
            st.record = Some(Vec::new());
        }
    }

    /// Installs the screen teach pendant behind `TeachBox`.
    pub fn install_pendant(&mut self, pendant: Box<dyn crate::services::Pendant>) {
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
        self.machine.run(self.checker.program(), stmts, main, svc)
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
        self.machine.eval_expr(self.checker.program(), e, svc)
    }

    /// For a program that is checked and run once (`adair run`): a long
    /// subprogram body is compiled a part at a time as it is checked, so
    /// that its checked form is never held whole (see
    /// `Checker::compile_parts`). Its code is then used up by its run.
    pub fn compile_as_checked(&mut self) {
        self.checker.compile_parts = self.machine.part_compiler();
    }

    pub fn check_source(
        &mut self,
        name: &str,
        text: impl SourceText,
        script: bool,
    ) -> Result<(Vec<Stmt>, Option<FuncId>), Vec<Diagnostic>> {
        let shared = text.into_shared();
        let text: &str = &shared;
        let id = self.sources.add_shared(name, shared.clone());
        self.machine.add_source(id, name, text);
        self.checker.add_text(id, self.sources.shared(id));
        // A long program's bodies are parsed as they are checked (the
        // stdlib's are short).
        let (unit, mut diags) = if self.in_stdlib {
            crate::syntax::parse_source(text, id)
        } else {
            crate::syntax::parse_source_lazy(text, id)
        };
        let Some(unit) = unit else { return Err(diags) };
        use crate::syntax::ast::TopItem;
        let is_script = script || is_script_unit(&unit, self.in_stdlib || self.in_with_file);
        // The stdlib files this unit names, and the files of the other
        // packages it names (beside it, unless the unit declares them).
        for item in &unit.items {
            if let TopItem::With(names, _) = item {
                for n in names {
                    let pkg = crate::syntax::parser::expr_text(n);
                    if !self.need_package(&pkg)
                        && !self.in_stdlib
                        && !declares_package(&unit, &pkg)
                        && let Err(d) = self.load_with_file(name, &pkg, n.span)
                    {
                        diags.extend(d);
                    }
                }
            }
        }
        if is_script {
            // A script names any stdlib package without `with`.
            self.load_stdlib();
            for p in SCRIPT_USES {
                self.checker.use_everywhere(p);
            }
        }
        // Only the program being run is compiled as it is checked: the
        // walker may run a unit it names (from an expression it evaluates),
        // and the walker runs checked statements.
        let parts = if self.in_stdlib || self.in_with_file {
            self.checker.compile_parts.take()
        } else {
            None
        };
        let (stmts, main) = self.checker.check_unit_consuming(&unit);
        if parts.is_some() {
            self.checker.compile_parts = parts;
        }
        diags.extend(self.checker.take_diags());
        // A name from a stdlib package that was not checked (no `with`):
        // check the rest of the stdlib to say where it is declared.
        // (`X` is not declared; `X` is not declared in `P`: name X, prefix P.)
        let undeclared = |d: &Diagnostic| {
            // A guess from the names in view gives way to the package that
            // declares the name.
            let guessed = d
                .hint
                .as_ref()
                .is_some_and(|h| h.starts_with("did you mean"));
            let m = d
                .message
                .strip_prefix('`')
                .filter(|_| d.hint.is_none() || guessed)?;
            if let Some(n) = m.strip_suffix("` is not declared") {
                return Some((n.to_string(), None));
            }
            let (n, p) = m.strip_suffix('`')?.split_once("` is not declared in `")?;
            Some((n.to_string(), Some(p.to_string())))
        };
        if !self.in_stdlib
            && self.loaded.iter().any(|l| !l)
            && diags.iter().any(|d| undeclared(d).is_some())
        {
            // In a fresh session: this one's scope now holds the program's
            // declarations, which the stdlib must not see.
            let mut full = Session::new(Box::new(std::io::sink()));
            full.load_stdlib();
            for d in diags.iter_mut() {
                let hint = match undeclared(d) {
                    Some((n, None)) => full.checker.with_hint(&n),
                    Some((n, Some(p))) => full.checker.qualified_with_hint(&p, &n),
                    None => None,
                };
                if hint.is_some() {
                    d.hint = hint;
                }
            }
        }
        diags.sort_by_key(|d| (d.span.context, d.span.start));
        // With errors, every diagnostic but a variable "never read": that
        // one is often their echo (its use did not check).
        if diags.iter().any(|d| !d.is_warning()) {
            diags.retain(|d| !d.is_warning() || !d.message.ends_with(" is never read"));
            return Err(diags);
        }
        if self.strict && !diags.is_empty() {
            return Err(diags);
        }
        self.warnings = diags;
        // The packages this unit names elaborate first.
        // (A stdlib file elaborates when loaded: not theirs.) In place: the
        // program's statements may be many, theirs are few.
        let mut stmts = stmts;
        if !self.in_stdlib && !self.elaboration.is_empty() {
            stmts.splice(0..0, std::mem::take(&mut self.elaboration));
        }
        Ok((stmts, if is_script { None } else { main }))
    }

    /// Checks the file of package `pkg` named by `with` in the program
    /// `program`: `pkg.air` beside it (lower case, `-` for `.` as GNAT
    /// names files), else GNAT's `pkg.ads` and `pkg.adb`. Its elaboration
    /// joins [`Session::elaboration`]. No file: nothing (the checker says
    /// that no such unit exists).
    fn load_with_file(
        &mut self,
        program: &str,
        pkg: &str,
        at: Span,
    ) -> Result<(), Vec<Diagnostic>> {
        let dir = std::path::Path::new(program)
            .parent()
            .unwrap_or(std::path::Path::new(""));
        let stem = pkg.to_lowercase().replace('.', "-");
        let air = dir.join(format!("{stem}.air"));
        let files: Vec<std::path::PathBuf> = if air.is_file() {
            vec![air]
        } else {
            ["ads", "adb"]
                .iter()
                .map(|e| dir.join(format!("{stem}.{e}")))
                .filter(|p| p.is_file())
                .collect()
        };
        for f in files {
            if self.with_files.contains(&f) {
                continue;
            }
            self.with_files.push(f.clone());
            let shown = f.to_string_lossy().replace('\\', "/");
            let text = std::fs::read_to_string(&f).map_err(|e| {
                vec![Diagnostic::syntax(
                    at,
                    format!("cannot read {shown} (the file of package {pkg}): {e}"),
                )]
            })?;
            let outer = std::mem::replace(&mut self.in_with_file, true);
            let checked = self.check_source(&shown, &text, false);
            self.in_with_file = outer;
            let (stmts, _) = checked?;
            self.elaboration = stmts;
        }
        Ok(())
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
            let text = crate::diag::render(&self.warnings, &self.sources, *color);
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
        if let Some(rest) = o.message.strip_prefix(crate::interp::tasking::DEADLOCK) {
            // One note per task: what it waits for, where.
            let mut d = Diagnostic::new(Phase::Runtime, o.span, crate::interp::tasking::DEADLOCK)
                .with_label("blocked here")
                .with_hint("a task waits forever when nobody calls the entry it accepts, or calls an entry nobody accepts: check that every call has its accept");
            for (line, s) in rest.lines().skip(1).zip(&o.chain) {
                d = d.with_note(*s, line.to_string());
            }
            return d;
        }
        if let Some(rest) = o.message.strip_prefix(crate::interp::STOPPED_TASKS) {
            // Where the main program was, then one note per task.
            let mut d = Diagnostic::new(Phase::Runtime, o.span, crate::interp::STOPPED_TASKS)
                .with_label("the main program was here");
            for (line, s) in rest.lines().skip(1).zip(&o.chain) {
                d = d.with_note(*s, line.to_string());
            }
            return d;
        }
        let name = &self.checker.excs[o.exc as usize].name;
        let msg = if o.message.is_empty() {
            format!("raised {name}")
        } else {
            format!("raised {name} : {}", o.message)
        };
        let mut d =
            Diagnostic::new(Phase::Runtime, o.span, msg).with_label(format!("{name} raised here"));
        for s in &o.reraised {
            d = d.with_note(*s, "re-raised here by `raise;`");
        }
        let real = |s: &Span| !(s.start == 0 && s.end == 0);
        // Consecutive calls from one place (recursion) are one note.
        let mut runs: Vec<(Span, usize)> = Vec::new();
        for s in o.chain.iter().filter(|s| real(s) && **s != o.span) {
            match runs.last_mut() {
                Some((last, n)) if last == s => *n += 1,
                _ => runs.push((*s, 1)),
            }
        }
        let note = |(s, n): (Span, usize), more: usize| {
            let mut text = if n == 1 {
                "called from here".to_string()
            } else {
                format!("called from here {n} times in a row")
            };
            if more > 0 {
                text.push_str(&format!(", and {more} more calls not shown"));
            }
            (s, text)
        };
        // A deep chain shows its innermost and outermost places only (an
        // exception 20,000 calls deep is one screen, built in linear time).
        const INNER: usize = 6;
        const OUTER: usize = 3;
        let notes: Vec<(Span, String)> = if runs.len() > INNER + OUTER + 1 {
            let hidden: usize = runs[INNER + 1..runs.len() - OUTER]
                .iter()
                .map(|r| r.1)
                .sum();
            let mut v: Vec<(Span, String)> = runs[..INNER].iter().map(|r| note(*r, 0)).collect();
            v.push(note(runs[INNER], hidden));
            v.extend(runs[runs.len() - OUTER..].iter().map(|r| note(*r, 0)));
            v
        } else {
            runs.iter().map(|r| note(*r, 0)).collect()
        };
        for (s, text) in notes {
            d = d.with_note(s, text);
        }
        d
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
    s.checker.simulator_only = crate::services::SIMULATOR_ONLY;
    let outcome = s.run_source(name, text);
    // A failed rehearsal ends the run before the real one is checked: its
    // warnings (a simulator-only service) are shown with its failure.
    let warned = crate::diag::render(&s.take_warnings(), &s.sources, color);
    let shown = match &outcome {
        Outcome::Ok => return Ok(()),
        Outcome::CheckFailed(d) => crate::diag::render(d, &s.sources, color),
        Outcome::Raised(d) => {
            warned + &crate::diag::render(std::slice::from_ref(d), &s.sources, color)
        }
    };
    Err((
        format!("{shown}adair: the rehearsal on the simulator failed: the arm was not moved\n"),
        outcome.exit_code(),
    ))
}

/// What `adair run --rehearse` says on stderr before it moves the arm.
pub const REHEARSED: &str = "adair: the rehearsal on the simulator ended without an unhandled exception; moving the arm now (a rehearsal cannot cover branches that depend on input)";

/// Whether `unit` declares the package `name` itself.
fn declares_package(unit: &crate::syntax::ast::CompilationUnit, name: &str) -> bool {
    use crate::syntax::ast::{DeclKind, TopItem};
    unit.items.iter().any(|i| match i {
        TopItem::Decl(d) => match &d.kind {
            DeclKind::PackageSpec(p) => {
                crate::syntax::parser::expr_text(&p.name).eq_ignore_ascii_case(name)
            }
            _ => false,
        },
        _ => false,
    })
}

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
