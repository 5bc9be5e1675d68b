//! The REPL's session logic, testable without a terminal: one entry at a
//! time, checked before it runs, against kept state. The terminal front end
//! (`term.rs`, rustyline) and the piped mode only feed it lines.

mod jog;
pub mod teach;
pub mod term;
pub mod view;

use crate::check::types::{self, TypeId, TypeKind};
use crate::diag::{self, Diagnostic};
use crate::interp::Value;
use crate::kinematics::{RobotDescription, joints_to_deg};
use crate::services::exception_doc;
use crate::session::Session;
use std::io::Write;

/// Makes a fresh writer for program output and traces (stdout, or a buffer in tests).
pub type WriterFactory = Box<dyn Fn() -> Box<dyn Write>>;

/// What an entry did.
#[derive(Debug, Default, PartialEq)]
pub struct Reply {
    /// Messages for the user (values, diagnostics, command output).
    pub text: String,
    /// The entry failed (a check error or an unhandled exception).
    pub failed: bool,
    /// `:quit`.
    pub quit: bool,
}

/// How the REPL drives its robot (the options of `adair repl`).
#[derive(Clone, Default)]
pub struct Drive {
    /// The robot (`--robot`); None keeps rv-m1.
    pub robot: Option<String>,
    /// A real arm on this port instead of the simulator (`--port`).
    pub port: Option<crate::driver::serial::PortSettings>,
    /// With a port: each entry runs first on the simulator from the arm's
    /// pose, and moves the arm only when that rehearsal raises nothing
    /// (`--rehearse`).
    pub rehearse: bool,
    /// The simulated devices (`--devices`); None keeps the default set.
    pub devices: Option<crate::devices::Devices>,
    /// `--trace`: start with `:trace on`.
    pub trace: bool,
}

pub struct Repl {
    pub session: Session,
    make_out: WriterFactory,
    color: bool,
    robot: String,
    trace: bool,
    entries: usize,
    terminal: bool,
    /// A real arm to drive instead of the simulator (`--port`).
    port: Option<crate::driver::serial::PortSettings>,
    /// Rehearse each entry on the simulator before the arm moves.
    rehearse: bool,
    /// `--devices`, kept for `:reset`.
    devices: Option<crate::devices::Devices>,
    /// The live 3D view (`--view`): every motion goes to its pages.
    live: Option<std::sync::Arc<crate::view::live::Hub>>,
    /// The note that a one-line entry's missing `;` was added has been
    /// given (it is given once a session).
    semicolon_noted: bool,
}

const COMMANDS: &[(&str, &str)] = &[
    (
        ":help",
        "list the services by group; `:help NAME` explains one",
    ),
    (":load FILE", "check and run a file in this session"),
    (
        ":robot [rv-m1|rm-501]",
        "show or switch the simulated robot (starts it afresh)",
    ),
    (":where", "the joints and the tool-centre-point frame"),
    (
        ":jog J1 +10 | :jog z -5",
        "jog a joint (deg), or the TCP: x y z (mm), pitch roll (deg)",
    ),
    (":trace on|off", "print every motion"),
    (":teach", "the teach pendant"),
    (
        ":record FILE.csv|.json",
        "write every support point since the start (or :reset)",
    ),
    (
        ":plot FILE.svg",
        "draw the motions since the start (or :reset): joints, TCP path",
    ),
    (
        ":view FILE.html",
        "a 3D page of the motions since the start (or :reset)",
    ),
    (
        ":devices",
        "the simulated devices: registers, interrupts, objects",
    ),
    (
        ":irq ADDR",
        "raise the interrupt at ADDR (8#340#, 0o340, 224)",
    ),
    (
        ":set ADDR VALUE",
        "set the input register at ADDR (16#00FF#, 0xFF, 255)",
    ),
    (
        ":tasks",
        "the tasks of the last entry and what each waited for",
    ),
    (":reset", "forget everything declared and start again"),
    (":quit", "leave (Ctrl-D too)"),
];

/// The stdlib helpers by group, for `:help` (the services' groups come
/// from the service table).
const HELPER_GROUPS: &[(&str, &[&str])] = &[(
    "frames",
    &[
        "Identity", "Trans", "RotX", "RotY", "RotZ", "Inverse", "Deg", "Rad", "Put",
    ],
)];

impl Repl {
    pub fn new(make_out: WriterFactory, color: bool) -> Repl {
        let session = Session::new(make_out());
        let mut r = Repl {
            session,
            make_out,
            color,
            robot: "rv-m1".into(),
            trace: false,
            entries: 0,
            terminal: false,
            port: None,
            rehearse: false,
            devices: None,
            live: view::live_hub(),
            semicolon_noted: false,
        };
        r.install_robot();
        r.session.machine.input = Box::new(std::io::BufReader::new(std::io::empty()));
        // Tasks live on from one entry to the next.
        r.session.machine.keep_tasks = true;
        r.script_uses();
        r
    }

    /// Entries are script mode: the standard packages and AdaIR are visible.
    fn script_uses(&mut self) {
        // Entries may name any package of the stdlib without `with`.
        self.session.load_stdlib();
        for p in crate::session::SCRIPT_USES {
            self.session.front.checker.use_everywhere(p);
        }
    }

    /// Chooses the robot and how it is driven (`--robot`, `--port`,
    /// `--rehearse`). An unknown robot is an error naming the known ones.
    pub fn drive(&mut self, d: Drive) -> Result<(), String> {
        if let Some(r) = d.robot {
            let r = r.to_ascii_lowercase();
            RobotDescription::builtin(&r).map_err(|e| e.problems.join("; "))?;
            self.robot = r;
        }
        self.rehearse = d.rehearse && d.port.is_some();
        self.port = d.port;
        if let Some(devs) = d.devices {
            self.devices = Some(devs.clone());
            self.session.set_devices(devs);
        }
        self.install_robot();
        if d.trace {
            self.trace = true;
            self.set_trace();
        }
        Ok(())
    }

    /// With `--rehearse`: runs `f` first as a rehearsal on the simulator
    /// from the arm's pose; an exception there is the entry's reply, and
    /// the arm is not moved.
    fn rehearsed<T>(
        &mut self,
        f: impl Fn(&mut Session) -> Result<T, Box<crate::interp::Occurrence>>,
    ) -> Result<Result<T, Box<crate::interp::Occurrence>>, Reply> {
        if self.rehearse
            && let Err(o) = self.session.rehearsing(|s| f(s))
        {
            let mut reply = self.raised(&o);
            reply.text.push_str(
                "rehearsal on the simulator failed: the arm was not moved (a rehearsal cannot cover branches that depend on input)\n",
            );
            return Err(reply);
        }
        Ok(f(&mut self.session))
    }

    fn install_robot(&mut self) {
        if let Ok(desc) = RobotDescription::builtin(&self.robot) {
            let trace = self.trace.then(|| (self.make_out)());
            // On a real arm a simulator-only call is a warning as it is
            // checked, and `CommandNotSupported` when it runs.
            self.session.front.checker.options.simulator_only = match &self.port {
                None => &[],
                Some(_) => crate::services::SIMULATOR_ONLY,
            };
            match &self.port {
                None => self.session.set_robot(desc, trace, false),
                Some(p) => {
                    let d = crate::driver::serial::Serial::new(
                        desc.clone(),
                        p.clone(),
                        self.session.machine.interrupted.clone(),
                    );
                    self.session.set_driver(desc, Box::new(d), trace, false);
                }
            }
            if self.terminal {
                self.session
                    .install_pendant(Box::new(teach::TermPendant::new()));
            }
            // Kept for `:record` and `:plot`, and for `:view` the devices'
            // moments.
            self.session.start_recording();
            if let Some(w) = self.session.machine.world.as_mut() {
                w.keep_timeline();
            }
            self.rewatch();
        }
    }

    /// On a terminal, `TeachBox` and `:teach` open the screen teach pendant.
    pub fn use_terminal(&mut self) {
        self.terminal = true;
        self.session
            .install_pendant(Box::new(teach::TermPendant::new()));
    }

    /// Names for completion: keywords, visible names and commands.
    pub fn completions(&self) -> Vec<String> {
        let mut v: Vec<String> = crate::syntax::token::Kw::ALL
            .iter()
            .map(|(w, _)| w.to_string())
            .collect();
        v.extend(
            self.session
                .front
                .checker
                .completion_names()
                .iter()
                .map(|k| self.session.front.checker.spelled(k)),
        );
        v.extend(
            COMMANDS
                .iter()
                .map(|c| c.0.split(' ').next().unwrap_or("").to_string()),
        );
        v.sort();
        v.dedup();
        v
    }

    /// Is this text an unfinished entry (only "unexpected end of input")?
    pub fn is_unfinished(&self, text: &str) -> bool {
        term::unfinished(text)
    }

    /// The reply for an entry that an exception left.
    fn raised(&self, o: &crate::interp::Occurrence) -> Reply {
        let d = self.session.exception_diag(o);
        Reply {
            text: self.render(&[d]),
            failed: true,
            quit: false,
        }
    }

    fn render(&self, d: &[Diagnostic]) -> String {
        diag::render(d, &self.session.front.sources, self.color)
    }

    /// Checks and runs one entry (`entry` in view.rs tells the live view).
    fn entry_inner(&mut self, text: &str) -> Reply {
        let trimmed = text.trim();
        // Nothing, or comments only: nothing to check or run.
        if trimmed.lines().all(|l| {
            let l = l.trim();
            l.is_empty() || l.starts_with("--")
        }) {
            return Reply::default();
        }
        if let Some(cmd) = trimmed.strip_prefix(':') {
            return self.command(cmd);
        }
        self.entries += 1;
        let name = format!("<entry {}>", self.entries);
        // An expression: print its value.
        let snapshot = self.session.front.checker.clone();
        let id = self.session.front.sources.add(name.clone(), text);
        self.session.machine.add_source(id, &name, text);
        self.session
            .front
            .checker
            .add_text(id, self.session.front.sources.shared(id));
        let (tokens, lex_diags) = crate::syntax::lexer::lex(text, id);
        let expr = if lex_diags.is_empty() {
            crate::syntax::parser::parse_expr_entry(&tokens, id, text.len())
        } else {
            None
        };
        let is_expr = expr.is_some();
        if let Some(e) = expr {
            let ex = self.session.front.checker.check_expr(&e);
            let diags = self.session.front.checker.take_diags();
            // An expression that cannot be a procedure call: its errors are the ones to show.
            // Nor can one whose name denotes functions only (`Trans (1, 2,
            // 3)`: integers where floats are expected, not "its result must
            // be used").
            use crate::syntax::ast::ExprKind;
            let callee = match &e.kind {
                ExprKind::Name(id) => Some(id),
                ExprKind::Apply(f, _) => match &f.kind {
                    ExprKind::Name(id) => Some(id),
                    _ => None,
                },
                _ => None,
            };
            let callable = match callee {
                Some(id) => self.session.front.checker.may_name_a_procedure(&id.key),
                None => matches!(e.kind, ExprKind::Select(..) | ExprKind::Apply(..)),
            };
            // Nor a component of a private type selected where it is hidden.
            let hidden = diags.iter().any(|d| d.code == crate::diag::codes::E0317);
            if !diags.is_empty() && (!callable || hidden) {
                self.session.front.checker = snapshot;
                return Reply {
                    text: self.render(&diags),
                    failed: true,
                    quit: false,
                };
            }
            if diags.is_empty() {
                let r = match self.rehearsed(|s| s.eval_checked(&ex)) {
                    Ok(r) => r,
                    Err(reply) => return reply,
                };
                return match r {
                    Ok(v) => Reply {
                        text: format!("{}\n", self.show(&v, ex.ty)),
                        ..Reply::default()
                    },
                    Err(o) => self.raised(&o),
                };
            }
            self.session.front.checker = snapshot.clone();
        }
        // Declarations and statements; a lone call, and any one-line entry
        // complete but for it, may leave out its `;` (said once).
        let owned;
        let mut note = String::new();
        let text = if is_expr && !text.trim_end().ends_with(';') {
            owned = format!("{};", text.trim_end());
            &owned
        } else if term::missing_only_semicolon(text) {
            if !self.semicolon_noted {
                self.semicolon_noted = true;
                note = "note: the `;` at the end of this entry was missing and is added (a one-line entry may leave it out)\n".into();
            }
            owned = format!("{};", text.trim_end());
            &owned
        } else {
            text
        };
        let mut reply = self.checked_entry(&name, text, snapshot);
        reply.text.insert_str(0, &note);
        reply
    }

    /// Checks and runs the declarations and statements of an entry; a
    /// refused one leaves the checker as `snapshot` holds it.
    fn checked_entry(&mut self, name: &str, text: &str, snapshot: crate::check::Checker) -> Reply {
        match self.session.check_source(name, text, true) {
            Ok((stmts, _)) => {
                let warnings = self.session.take_warnings();
                let warned = if warnings.is_empty() {
                    String::new()
                } else {
                    self.render(&warnings)
                };
                let r = match self.rehearsed(|s| s.run_checked(&stmts, None)) {
                    Ok(r) => r,
                    Err(mut reply) => {
                        // Nothing of a refused entry is kept.
                        self.session.front.checker = snapshot;
                        reply.text.insert_str(0, &warned);
                        return reply;
                    }
                };
                let mut reply = match r {
                    Ok(()) => match self.session.take_stopped() {
                        // Ctrl-C stopped the motion: say where, raise nothing.
                        Some(m) => Reply {
                            text: format!("{m}\n"),
                            failed: true,
                            quit: false,
                        },
                        None => Reply::default(),
                    },
                    Err(o) => self.raised(&o),
                };
                reply.text.insert_str(0, &warned);
                reply
            }
            Err(d) => {
                // Nothing of a failed entry is kept.
                self.session.front.checker = snapshot;
                Reply {
                    text: self.render(&d),
                    failed: true,
                    quit: false,
                }
            }
        }
    }

    fn command(&mut self, cmd: &str) -> Reply {
        let mut words = cmd.split_whitespace();
        let head = words.next().unwrap_or("");
        let arg = words.next();
        let ok = |text: String| Reply {
            text,
            ..Reply::default()
        };
        let fail = |text: String| Reply {
            text,
            failed: true,
            quit: false,
        };
        match head {
            "quit" | "q" | "exit" => Reply {
                quit: true,
                ..Reply::default()
            },
            "help" | "h" => match arg {
                None => ok(self.help()),
                Some(n) => match self.help_on(n) {
                    Some(t) => ok(t),
                    None => fail(format!(
                        "no service, subprogram, type, exception or other declaration named `{n}`; `:help` lists them\n"
                    )),
                },
            },
            "load" => match arg {
                None => fail(":load needs a file name\n".into()),
                Some(f) => match std::fs::read_to_string(f) {
                    Err(e) => fail(format!("cannot read {f}: {e}\n")),
                    Ok(text) => match self.session.check_source(f, &text, false) {
                        Err(d) => fail(self.render(&d)),
                        Ok((stmts, main)) => match self.session.run_checked(&stmts, main) {
                            Ok(()) => ok(format!("loaded {f}\n")),
                            Err(o) => self.raised(&o),
                        },
                    },
                },
            },
            "robot" => match arg {
                None => ok(format!("robot: {}\n", self.robot)),
                Some(r) => match RobotDescription::builtin(r) {
                    Ok(_) => {
                        self.robot = r.to_ascii_lowercase();
                        self.install_robot();
                        ok(format!(
                            "robot: {} (not initialised: call InitRobot)\n",
                            self.robot
                        ))
                    }
                    Err(e) => fail(format!("{}\n", e.problems.join("; "))),
                },
            },
            "where" => ok(self.where_text()),
            "jog" => {
                let rest = cmd.trim_start().strip_prefix(head).unwrap_or("").trim();
                self.jog_command(rest)
            }
            "record" | "plot" => match arg {
                Some(path) => match self.save_run(head == "plot", std::path::Path::new(path)) {
                    Ok(t) => ok(t),
                    Err(e) => fail(format!(":{head} {path}: {e}\n")),
                },
                None if head == "plot" => fail(":plot FILE.svg\n".into()),
                None => fail(":record FILE.csv or :record FILE.json\n".into()),
            },
            "view" => match arg {
                Some(path) => match self.save_view(std::path::Path::new(path)) {
                    Ok(t) => ok(t),
                    Err(e) => fail(format!(":view {path}: {e}\n")),
                },
                None => fail(":view FILE.html\n".into()),
            },
            "trace" => match arg {
                Some("on") => {
                    self.trace = true;
                    self.set_trace();
                    ok("trace on\n".into())
                }
                Some("off") => {
                    self.trace = false;
                    self.set_trace();
                    ok("trace off\n".into())
                }
                _ => fail(":trace on or :trace off\n".into()),
            },
            // `:teach [TEXT]` is the `TeachBox` service with the user's text,
            // run as an entry: the same pendant, limits, trace and clock.
            // With `--rehearse` it is not rehearsed (the operator's jogs
            // cannot be): it runs on the arm, and each jog is checked
            // against the limits before it is sent, one by one.
            "teach" => {
                let rest = cmd.trim_start().strip_prefix(head).unwrap_or("").trim();
                let text = if rest.is_empty() {
                    "REPL: jog, store, x returns"
                } else {
                    rest
                };
                let rehearse = std::mem::replace(&mut self.rehearse, false);
                let reply = self.entry(&format!("TeachBox (\"{}\");", text.replace('"', "\"\"")));
                self.rehearse = rehearse;
                reply
            }
            "devices" => match &self.session.machine.world {
                Some(w) => ok(w.describe()),
                None => ok("no devices\n".into()),
            },
            "irq" => match arg.map(parse_number) {
                Some(Some(a)) => {
                    let r = match self.session.machine.world.as_mut() {
                        Some(w) => w.raise_interrupt(a as u32).map_err(|e| e.to_string()),
                        None => Err("no devices".into()),
                    };
                    match r {
                        Ok(Some(i)) => {
                            // Delivered to its entry; the tasks run until
                            // they block again.
                            self.session.machine.pending_irqs.push((i.address, i.time));
                            let lost = self.session.machine.lost_interrupts;
                            let mut reply = self.entry("delay 0.0;");
                            if !reply.failed {
                                let at = crate::devices::ada_address(a as u32);
                                reply.text = if self.session.machine.lost_interrupts > lost {
                                    format!(
                                        "interrupt {at} lost: no task has an entry bound to it\n"
                                    )
                                } else {
                                    format!("interrupt {at} raised\n")
                                };
                            }
                            reply
                        }
                        Ok(None) => ok(format!(
                            "interrupt {} dropped: its device has interrupts disabled\n",
                            crate::devices::ada_address(a as u32)
                        )),
                        Err(e) => fail(format!(":irq: {e}\n")),
                    }
                }
                _ => fail(":irq ADDR (8#340#, 0o340 or 224)\n".into()),
            },
            "set" => match (
                arg.and_then(parse_number),
                words.next().and_then(parse_number),
            ) {
                (Some(a), Some(v)) if v <= u16::MAX as i64 => {
                    let r = match self.session.machine.world.as_mut() {
                        Some(w) => w.set_input(a as u32, v as u16).map_err(|e| e.to_string()),
                        None => Err("no devices".into()),
                    };
                    match r {
                        Ok(irq) => {
                            let text = format!(
                                "{} := {}\n",
                                crate::devices::ada_address(a as u32),
                                crate::devices::ada_word(v as u16)
                            );
                            // A light barrier's rising edge interrupts: its
                            // task runs now.
                            let Some(i) = irq else { return ok(text) };
                            self.session.machine.pending_irqs.push((i.address, i.time));
                            let mut reply = self.entry("delay 0.0;");
                            if !reply.failed {
                                reply.text = text;
                            }
                            reply
                        }
                        Err(e) => fail(format!(":set: {e}\n")),
                    }
                }
                _ => fail(":set ADDR VALUE (a 16-bit value: 16#00FF#, 0xFF or 255)\n".into()),
            },
            "tasks" => {
                let t = self
                    .session
                    .machine
                    .describe_tasks(self.session.front.checker.program());
                let t: Vec<&String> = t.iter().skip(1).collect();
                if t.is_empty() {
                    ok("no tasks\n".into())
                } else {
                    ok(t.iter().map(|l| format!("{l}\n")).collect())
                }
            }
            "reset" => {
                self.session = Session::new((self.make_out)());
                self.session.machine.input = Box::new(std::io::BufReader::new(std::io::empty()));
                self.session.machine.keep_tasks = true;
                if let Some(d) = self.devices.clone() {
                    self.session.set_devices(d);
                }
                self.install_robot();
                self.script_uses();
                ok("reset: everything declared is forgotten\n".into())
            }
            other => fail(format!(
                "unknown command `:{other}`; `:help` lists the commands\n"
            )),
        }
    }

    /// `:record` and `:plot`: what the robot did since the REPL started (or
    /// since `:reset`), as CSV/JSON support points or as an SVG picture.
    fn save_run(&self, plot: bool, path: &std::path::Path) -> Result<String, String> {
        let st = self.session.robot_state().ok_or("no robot")?;
        match (
            plot,
            path.extension().and_then(|e| e.to_str()).unwrap_or(""),
        ) {
            (true, "svg") | (false, "csv" | "json") => {}
            (true, _) => return Err("the file must end in .svg".into()),
            (false, _) => return Err("the file must end in .csv or .json".into()),
        }
        let n = crate::plot::write_run(path, st, "REPL session")?;
        Ok(format!("wrote {} ({n} support points)\n", path.display()))
    }

    /// `:trace on|off`: the motions, and as `run --trace` the task
    /// switches, device events and interrupts.
    fn set_trace(&mut self) {
        let w = self.trace.then(|| (self.make_out)());
        if let Some(st) = self.session.robot_state_mut() {
            st.trace = w;
        }
        self.session.machine.trace = self.trace.then(|| (self.make_out)());
        if let Some(w) = self.session.machine.world.as_mut() {
            w.set_logging(self.trace);
        }
    }

    fn help(&self) -> String {
        let mut s = String::from("AdaIR services and helpers (`:help NAME` for one):\n");
        for g in crate::services::Group::ALL {
            let names: Vec<&str> = crate::services::SERVICES
                .iter()
                .filter(|x| x.group == g && !x.function)
                .map(|x| x.name)
                .collect();
            s.push_str(&format!("  {:<15} {}\n", g.title(), names.join(", ")));
        }
        for (g, names) in HELPER_GROUPS {
            s.push_str(&format!("  {g:<15} {}\n", names.join(", ")));
        }
        s.push_str(
            "  types           Frame, AxesVector, ToolDescriptor, Motion, ArmConfig, ElbowConfig,\n                  HandConfig, RobotVelocity, Interpolation, ToolForce, ToolDistance, ...\n  exceptions      OutOfReach, FrameInvalid, TimeInvalid, ... (`:help OutOfReach`)\n",
        );
        s.push_str("Commands:\n");
        for (c, d) in COMMANDS {
            s.push_str(&format!("  {c:<24} {d}\n"));
        }
        s
    }

    /// Signature, command code and the comment written above the declaration
    /// in `stdlib/adair.air` (the text lives next to the definition).
    pub fn help_on(&self, name: &str) -> Option<String> {
        let c = &self.session.front.checker;
        let key = name.to_ascii_lowercase();
        let funcs: Vec<u32> = (0..c.tables.funcs.len() as u32)
            .filter(|f| c.tables.funcs[*f as usize].name.eq_ignore_ascii_case(&key))
            .collect();
        if funcs.is_empty() {
            return stdlib_type_doc(name)
                .or_else(|| exception_doc(name))
                .or_else(|| self.declared_doc(&key));
        }
        let mut s = String::new();
        for f in &funcs {
            // A renaming (`procedure Feed (Id : Part_Id) renames Queue.Put;`)
            // is shown as written: it says what it renames.
            match c.index.def_of_func(*f).filter(|d| d.renames.is_some()) {
                Some(d) => s.push_str(&self.declaration(d)),
                None => s.push_str(&c.signature(*f)),
            }
            s.push('\n');
        }
        let svc = crate::services::table::by_name(name);
        if let Some(svc) = svc.filter(|x| x.code > 0) {
            s.push_str(&format!("command code {}\n", svc.code));
        }
        let doc = match svc {
            Some(svc) => svc.doc.lines().map(|l| format!("{l}\n")).collect(),
            None => stdlib_doc(name),
        };
        if !doc.is_empty() {
            s.push_str(&doc);
        }
        Some(s)
    }

    /// What `:help` says of a name declared in a program or an entry (a
    /// type, an object, a task, a protected object, a package, an
    /// exception): its declarations as written, and where.
    fn declared_doc(&self, key: &str) -> Option<String> {
        let c = &self.session.front.checker;
        let mut s = String::new();
        for e in c.entities_of(key) {
            if let Some(d) = c.def_named(key, &e) {
                s.push_str(&self.declaration(d));
                s.push_str(&format!(
                    "\n  -- declared in {}\n",
                    self.session.front.sources.name(d.span.context)
                ));
            }
        }
        (!s.is_empty()).then_some(s)
    }

    fn declaration(&self, d: &crate::check::index::Def) -> String {
        let src = self.session.front.sources.text(d.decl.context);
        crate::check::index::declaration_text(src, d.decl)
    }

    /// Which arm the REPL drives and how: `simulated RV-M1`, or `RV-M1 on
    /// /dev/ttyUSB0 (serial, 9600 baud)` and `--rehearse` when it is on
    /// (`long`: with what it means, for the banner).
    pub fn arm(&self, long: bool) -> String {
        let name = match self.session.robot_state() {
            Some(st) => st.kin.description().name().to_string(),
            None => self.robot.to_ascii_uppercase(),
        };
        match &self.port {
            None => format!("simulated {name}"),
            Some(p) => {
                let rehearse = match (self.rehearse, long) {
                    (false, _) => "",
                    (true, false) => ", --rehearse",
                    (true, true) => {
                        ", --rehearse: each entry runs on the simulator first, and moves the arm only if that raises nothing"
                    }
                };
                format!("{name} on {} (serial, {} baud){rehearse}", p.path, p.baud)
            }
        }
    }

    /// The first line of the interactive REPL.
    pub fn banner(&self) -> String {
        let arm = self.arm(true);
        let on = if self.port.is_some() {
            format!("the {arm}")
        } else {
            format!("a {arm}")
        };
        format!(
            "adair {}: AdaIR on {on}. :help lists the services, :quit leaves.",
            env!("CARGO_PKG_VERSION")
        )
    }

    fn where_text(&self) -> String {
        let Some(st) = self.session.robot_state() else {
            return "no robot\n".into();
        };
        let q = st.robot.read_joints();
        let mut s = format!(
            "robot: {}{}\n",
            self.arm(false),
            if st.initialized {
                ""
            } else {
                " (not initialised)"
            }
        );
        let d = joints_to_deg(&q);
        for (i, (r, dg)) in q.iter().zip(d).enumerate() {
            s.push_str(&format!("  J{} = {r:9.4} rad {dg:9.3} deg\n", i + 1));
        }
        let f = st.kin.fk_tcp(&q, &st.tool.trans).to_rows();
        s.push_str("TCP frame:\n");
        for row in f {
            s.push_str(&format!(
                "  {:10.4} {:10.4} {:10.4} {:10.3}\n",
                row[0], row[1], row[2], row[3]
            ));
        }
        s
    }

    /// A value, readably: joints in radians and degrees, frames as matrices,
    /// records by field.
    pub fn show(&self, v: &Value, t: TypeId) -> String {
        self.show_in(v, t, 0)
    }

    /// Objects `SHOWN_ACCESSES` accesses away are not shown (a long or
    /// circular list would print without end, in a recursion without end).
    fn show_in(&self, v: &Value, t: TypeId, accesses: usize) -> String {
        const SHOWN_ACCESSES: usize = 3;
        let ty = &self.session.front.checker.tables.types;
        let name = ty.name(t).to_ascii_lowercase();
        match (v, ty.kind(t)) {
            (Value::Int(i), TypeKind::Enum(lits)) => {
                if ty.base(t) == types::CHARACTER {
                    types::char_image(char::from_u32(*i as u32).unwrap_or('?'))
                } else {
                    let lit = lits.get(*i as usize).cloned().unwrap_or_default();
                    self.session
                        .front
                        .checker
                        .spelled(&lit.to_ascii_lowercase())
                }
            }
            (Value::Int(i), _) => i.to_string(),
            (Value::Real(r), _) => format!("{r:?}"),
            (Value::Arr(a), TypeKind::Array { elem, .. }) => {
                if ty.base(*elem) == types::CHARACTER {
                    return format!("{:?}", a.to_string_lossy());
                }
                if name == "axesvector" {
                    let mut s = String::new();
                    for (k, x) in a.data().iter().enumerate() {
                        let r = x.real();
                        s.push_str(&format!(
                            "J{} = {r:9.4} rad {:9.3} deg\n",
                            k + 1,
                            r.to_degrees()
                        ));
                    }
                    s.pop();
                    return s;
                }
                if a.bounds().len() == 2 {
                    let cols = a.len(1) as usize;
                    let all: Vec<Value> = a.data().iter().collect();
                    let rows: Vec<String> = all
                        .chunks(cols.max(1))
                        .map(|row| {
                            row.iter()
                                .map(|x| format!("{:10.4}", x.real()))
                                .collect::<Vec<_>>()
                                .join(" ")
                        })
                        .collect();
                    return rows.join("\n");
                }
                let items: Vec<String> = a
                    .data()
                    .iter()
                    .map(|x| self.show_in(&x, *elem, accesses))
                    .collect();
                format!("({})", items.join(", "))
            }
            (v, TypeKind::Record(fields)) if v.is_record() => {
                let r = v.fields().unwrap_or_default();
                let mut s = String::new();
                // Only the components of the variant the discriminants choose.
                let present = fields.iter().zip(r.iter()).filter(|(f, _)| {
                    f.variant
                        .as_ref()
                        .is_none_or(|v| crate::interp::value::variant_holds(r, v))
                });
                for (f, x) in present {
                    let shown = self.show_in(x, f.ty, accesses);
                    if shown.contains('\n') {
                        s.push_str(&format!("{}:\n  {}\n", f.name, shown.replace('\n', "\n  ")));
                    } else {
                        s.push_str(&format!("{} => {shown}\n", f.name));
                    }
                }
                s.pop();
                s
            }
            (Value::Ptr(None), _) => "null".into(),
            (Value::Ptr(Some(_)), TypeKind::Access(_)) if accesses == SHOWN_ACCESSES => {
                "access to ...".into()
            }
            (Value::Ptr(Some(p)), TypeKind::Access(d)) => {
                format!("access to {}", self.show_in(&p.get(), *d, accesses + 1))
            }
            (Value::Ptr(Some(_)), _) => "access".into(),
            (Value::Occ(o), _) => self.session.front.checker.tables.excs[o.exc as usize]
                .name
                .clone(),
            (Value::Undef, _) => "(no value)".into(),
            _ => format!("{v:?}"),
        }
    }
}

/// The comment lines right above a declaration of `name` in the embedded
/// AdaIR package.
fn stdlib_doc(name: &str) -> String {
    let lines = adair_lines();
    let needle_p = format!("procedure {}", name.to_ascii_lowercase());
    let needle_f = format!("function {}", name.to_ascii_lowercase());
    for (i, l) in lines.iter().enumerate() {
        let low = l.trim().to_ascii_lowercase();
        let starts = |n: &str| low.starts_with(n) && low[n.len()..].starts_with([' ', '(', ';']);
        if starts(&needle_p) || starts(&needle_f) {
            return lines[comment_start(&lines, i)..i]
                .iter()
                .map(|d| format!("{}\n", d.trim().trim_start_matches("--").trim()))
                .collect();
        }
    }
    String::new()
}

/// The lines of `stdlib/adair.air`, where the services' helpers and types
/// are declared with their comments.
fn adair_lines() -> Vec<&'static str> {
    crate::session::STDLIB
        .iter()
        .find(|u| u.name.ends_with("adair.air"))
        .map_or("", |u| u.text)
        .lines()
        .collect()
}

/// The first line of the comment block right above line `i`.
fn comment_start(lines: &[&str], i: usize) -> usize {
    let mut start = i;
    while start > 0 && lines[start - 1].trim().starts_with("--") {
        start -= 1;
    }
    start
}

/// `:help` on a type or subtype of the AdaIR package: its declaration as
/// written in `stdlib/adair.air` (with the comment beside or above it).
fn stdlib_type_doc(name: &str) -> Option<String> {
    let lines = adair_lines();
    let key = name.to_ascii_lowercase();
    let i = lines.iter().position(|l| {
        let low = l.trim().to_ascii_lowercase();
        ["type ", "subtype "].iter().any(|k| {
            low.strip_prefix(k)
                .and_then(|rest| rest.strip_prefix(key.as_str()))
                .is_some_and(|rest| rest.starts_with([' ', ';', '(']))
        })
    })?;
    let start = comment_start(&lines, i);
    let mut end = i;
    if lines[i].to_ascii_lowercase().contains(" record") && !lines[i].contains("null record") {
        while end + 1 < lines.len() && !lines[end].to_ascii_lowercase().contains("end record") {
            end += 1;
        }
    } else {
        while end + 1 < lines.len() && !lines[end].contains(';') {
            end += 1;
        }
    }
    let mut s = String::from("declared in package AdaIR:\n");
    for l in &lines[start..=end] {
        s.push_str(l.strip_prefix("   ").unwrap_or(l));
        s.push('\n');
    }
    Some(s)
}

/// An address or register value as the REPL takes it: Ada based literals
/// (`8#340#`, `16#00FF#`), Rust-style `0o340`, `0xFF`, `0b1`, or decimal.
pub fn parse_number(text: &str) -> Option<i64> {
    let t = text.replace('_', "");
    if let Some((base, rest)) = t.split_once('#') {
        let digits = rest.strip_suffix('#')?;
        return i64::from_str_radix(digits, base.parse().ok()?).ok();
    }
    let lower = t.to_ascii_lowercase();
    for (p, radix) in [("0x", 16), ("0o", 8), ("0b", 2)] {
        if let Some(d) = lower.strip_prefix(p) {
            return i64::from_str_radix(d, radix).ok();
        }
    }
    t.parse().ok()
}
