//! The `adair` command line: the only place (with the REPL) that prints.
#![allow(clippy::print_stdout, clippy::print_stderr)]

use adair::session::{Outcome, Session};
use clap::{Args, Parser, Subcommand};
use std::io::IsTerminal;
use std::io::Write as _;
use std::path::PathBuf;
use std::process::ExitCode;

// This file's `println!`, `eprint!` and `eprintln!`: std's panic when the
// write fails (a full disk: exit 101); these write through [`Watched`],
// which remembers the failure for the exit status ([`finish`]).
macro_rules! println {
    ($($t:tt)*) => {{
        let _ = writeln!(Watched::out(), $($t)*);
    }};
}
macro_rules! eprint {
    ($($t:tt)*) => {{
        let _ = write!(Watched::err(), $($t)*);
    }};
}
macro_rules! eprintln {
    ($($t:tt)*) => {{
        let _ = writeln!(Watched::err(), $($t)*);
    }};
}

/// The first write to standard output or error that failed, as a message.
static LOST: std::sync::OnceLock<String> = std::sync::OnceLock::new();

/// Standard output or error: a write that fails (a full disk, a closed
/// pipe) is remembered in [`LOST`] and returned to the writer, which may
/// ignore it (the interpreter's `Put_Line` does).
struct Watched<W> {
    w: W,
    name: &'static str,
}

impl Watched<std::io::Stdout> {
    fn out() -> Self {
        Watched {
            w: std::io::stdout(),
            name: "standard output",
        }
    }
}

impl Watched<std::io::Stderr> {
    fn err() -> Self {
        Watched {
            w: std::io::stderr(),
            name: "standard error",
        }
    }
}

impl<W: std::io::Write> Watched<W> {
    fn note<T>(&self, r: std::io::Result<T>) -> std::io::Result<T> {
        if let Err(e) = &r
            && e.kind() != std::io::ErrorKind::Interrupted
        {
            let _ = LOST.set(format!("cannot write the {}: {e}", self.name));
        }
        r
    }
}

impl<W: std::io::Write> std::io::Write for Watched<W> {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        let r = self.w.write(buf);
        self.note(r)
    }
    fn flush(&mut self) -> std::io::Result<()> {
        let r = self.w.flush();
        self.note(r)
    }
}

/// The exit status `code`, at least 1 when output was lost (said on
/// standard error, if that can still be written).
fn finish(code: u8) -> u8 {
    let _ = Watched::out().flush();
    match LOST.get() {
        None => code,
        Some(m) => {
            let _ = writeln!(std::io::stderr(), "adair: {m}");
            code.max(1)
        }
    }
}

#[derive(Parser)]
#[command(
    name = "adair",
    version,
    about = "AdaIR: Ada for industrial robots. Check, run and test robot programs.",
    after_help = "`adair FILE.air [OPTIONS]` is short for `adair run FILE.air [OPTIONS]`."
)]
struct Cli {
    /// Colours in diagnostics: auto (only on a terminal, and not with NO_COLOR), always, never.
    #[arg(long, global = true, default_value = "auto", value_parser = ["auto", "always", "never"])]
    color: String,
    /// Memory a program may use (512M, 2G, ...): past it, building a value raises
    /// Storage_Error where the program asked for it. Default: what the process
    /// can really have (the least of `ulimit -v`, the cgroup's memory.max and
    /// the physical memory, less adair's share), at most 4G.
    #[arg(long, global = true, value_name = "SIZE",
          value_parser = adair::interp::memory::parse_size)]
    max_memory: Option<usize>,
    /// The simulated devices: a TOML device file (see docs/tasks.md). Without it, the
    /// appendix C parallel port at 8#340#.
    #[arg(long, global = true, value_name = "FILE.toml")]
    devices: Option<PathBuf>,
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Args)]
struct RobotOpts {
    /// The simulated robot: rv-m1 (default) or rm-501.
    #[arg(long, default_value = "rv-m1")]
    robot: String,
    /// A robot description file (TOML) instead of a built-in robot.
    #[arg(long, value_name = "PATH")]
    robot_file: Option<PathBuf>,
    /// Print each motion (virtual time, service, joints before and after, duration, source line) to standard error.
    #[arg(long)]
    trace: bool,
    /// Pace the simulator to the wall clock.
    #[arg(long)]
    realtime: bool,
    #[command(flatten)]
    serial: SerialOpts,
    /// With --port: run the whole program on the simulator from the arm's pose
    /// first, and move the arm only if that run ends without an unhandled exception.
    #[arg(long, requires = "port")]
    rehearse: bool,
}

/// The serial port options of `run` and `repl`.
#[derive(Args)]
struct SerialOpts {
    /// Drive a real arm on this serial port instead of the simulator.
    #[arg(long, value_name = "PATH")]
    port: Option<String>,
    /// Baud rate of --port.
    #[arg(long, default_value_t = 9600, requires = "port")]
    baud: u32,
    /// Seconds a reply may take beyond a motion's expected time (0 to 3600).
    #[arg(long, value_name = "SECONDS", default_value_t = 2.0, requires = "port",
          value_parser = timeout_seconds)]
    serial_timeout: f64,
}

impl SerialOpts {
    /// The port settings, when a port was given.
    fn settings(&self) -> Option<adair::driver::serial::PortSettings> {
        self.port
            .as_ref()
            .map(|path| adair::driver::serial::PortSettings {
                path: path.clone(),
                baud: self.baud,
                timeout: self.serial_timeout,
            })
    }
}

impl RobotOpts {
    fn description(&self) -> Result<adair::kinematics::RobotDescription, String> {
        let r = match &self.robot_file {
            Some(p) => adair::services::read_robot_file(p),
            None => adair::kinematics::RobotDescription::builtin(&self.robot),
        };
        r.map_err(|e| {
            if e.problems.len() == 1 {
                format!("{}: {}", e.source, e.problems[0])
            } else {
                format!("{}: {}", e.source, e.problems.join("; "))
            }
        })
    }
}

/// The 3D view's options (docs/view.md).
#[derive(Args)]
struct ViewOpts {
    /// The run in 3D in a browser: `--view FILE.html` writes a replay page
    /// (also after an exception); `--view` alone serves the page live on
    /// 127.0.0.1, paced to the wall clock.
    #[arg(long, value_name = "FILE.html", num_args = 0..=1, default_missing_value = "")]
    view: Option<String>,
    /// The live view's port on 127.0.0.1 (0: any free port).
    #[arg(long, value_name = "N", default_value_t = 0)]
    view_port: u16,
    /// Do not open the live view in a browser (print its address only).
    #[arg(long)]
    no_open: bool,
}

impl ViewOpts {
    /// `--view` alone: the live view.
    fn live(&self) -> bool {
        self.view.as_deref() == Some("")
    }
    /// `--view FILE.html`.
    fn file(&self) -> Option<PathBuf> {
        self.view
            .as_deref()
            .filter(|v| !v.is_empty())
            .map(PathBuf::from)
    }
    /// Starts the live view's server when asked; says where it listens.
    fn serve(&self) -> Result<Option<adair::view::live::Server>, String> {
        if !self.live() {
            return Ok(None);
        }
        let mut sv = adair::view::live::Server::start(self.view_port)?;
        eprintln!(
            "adair: 3D view at {} (listening on the loopback interface 127.0.0.1 only)",
            sv.url()
        );
        if !self.no_open {
            match adair::view::live::open_browser(&sv.url()) {
                Ok(()) => sv.opened = true,
                Err(e) => eprintln!("adair: no browser opened ({e}): open the address above"),
            }
        }
        Ok(Some(sv))
    }
}

#[derive(Subcommand)]
enum Command {
    /// Check the whole program, then run it. Exit 0; 1 on an unhandled exception; 2 on a check error.
    Run {
        /// The program (.air or .adb).
        file: PathBuf,
        #[command(flatten)]
        robot: RobotOpts,
        /// Write every support point of every motion to FILE.csv or FILE.json
        /// (t, j1..j5, x, y, z, grip), also when the run ends with an exception.
        #[arg(long, value_name = "FILE")]
        record: Option<PathBuf>,
        /// Draw the run into FILE.svg: joints against time, and the TCP path from
        /// above and from the side with the arm's reach (also after an exception).
        #[arg(long, value_name = "FILE.svg")]
        plot: Option<PathBuf>,
        #[command(flatten)]
        view: ViewOpts,
        /// Treat warnings as errors: nothing runs, exit 2.
        #[arg(long)]
        strict: bool,
    },
    /// Parse and check only; report every diagnostic (errors and warnings); nothing runs.
    Check {
        #[arg(required = true)]
        files: Vec<PathBuf>,
        /// Treat warnings as errors (exit 2).
        #[arg(long)]
        strict: bool,
    },
    /// The interactive REPL (script mode, one entry at a time). Reads piped input without a terminal.
    Repl {
        /// With piped input: exit 1 if an entry failed.
        #[arg(long)]
        strict: bool,
        /// The robot: rv-m1 (default) or rm-501 (`:robot` switches later).
        #[arg(long, default_value = "rv-m1")]
        robot: String,
        #[command(flatten)]
        serial: SerialOpts,
        /// With --port: run each entry on the simulator from the arm's pose
        /// first, and move the arm only if that rehearsal raises nothing.
        #[arg(long, requires = "port")]
        rehearse: bool,
        /// Start with `:trace on`: every motion with its virtual time, task
        /// switches, device events and interrupts.
        #[arg(long)]
        trace: bool,
        #[command(flatten)]
        view: ViewOpts,
    },
    /// A virtual RV-M1 (or RM-501) controller on a pseudo-terminal; prints the device path to give to --port.
    SimController {
        /// The unit: rv-m1 (D/U-M1, default) or rm-501 (Movemaster II).
        #[arg(long, default_value = "rv-m1")]
        robot: String,
        /// Log every byte each way, timestamped, to this file.
        #[arg(long, value_name = "FILE")]
        log: Option<PathBuf>,
        /// Fault: answer nothing after N commands.
        #[arg(long, value_name = "N")]
        silent_after: Option<u64>,
        /// Fault: garble the reply to the Nth command.
        #[arg(long, value_name = "N")]
        corrupt: Option<u64>,
        /// Fault: hang up after N commands.
        #[arg(long, value_name = "N")]
        hangup_after: Option<u64>,
        /// Fault: refuse the Nth command with error mode 1 or 2 (N:MODE).
        #[arg(long, value_name = "N:MODE")]
        refuse: Option<String>,
        /// Fault: wait this many seconds before every reply.
        #[arg(long, value_name = "SECONDS", default_value_t = 0.0)]
        slow: f64,
        /// Multiply motion times by this factor (tests use a small one).
        #[arg(long, value_name = "F", default_value_t = 1.0)]
        time_scale: f64,
        /// Hand jog: after the Nth command has been executed, move the arm
        /// by these controller degrees per joint (repeatable; each joint
        /// stops at its limit).
        #[arg(long, value_name = "N:D1,D2,D3,D4,D5")]
        jog_after: Vec<String>,
        /// Poll this file or FIFO for `jog D1,D2,D3,D4,D5` lines (hand jogs
        /// at a moment a test chooses); created when missing.
        #[arg(long, value_name = "FILE")]
        control: Option<PathBuf>,
    },
    /// List the serial ports of this machine.
    Ports,
    /// Explain a diagnostic code (`adair explain E0201`): what it means, a
    /// wrong and a right example. Without a code: the list of codes.
    Explain {
        /// A code as a diagnostic's first line shows it, e.g. E0201 or W0001.
        code: Option<String>,
    },
    /// A language server (LSP 3.17) on standard input and output, for editors (see docs/editors.md).
    Lsp,
    /// Golden tests: run each X.air and compare its output with X.out beside it.
    Test {
        /// Scripts or directories (default: the current directory); each
        /// script runs once, and no folder is walked twice (a link back to
        /// one, `up -> ..`, is not followed again).
        paths: Vec<PathBuf>,
        /// Write the actual output into the .out files (with --port: what the arm did).
        #[arg(long)]
        bless: bool,
        /// The simulated robot of scripts that name none in a `-- adair: --robot R` first
        /// line: rv-m1 (default) or rm-501.
        #[arg(long, value_parser = ["rv-m1", "rm-501"])]
        robot: Option<String>,
        /// Every script's motion trace in its output (also in what --bless writes).
        #[arg(long)]
        trace: bool,
        #[command(flatten)]
        serial: SerialOpts,
        /// With --port: rehearse each script on the simulator from the arm's
        /// pose first; a script whose rehearsal fails does not move the arm.
        #[arg(long, requires = "port")]
        rehearse: bool,
        /// Each script's time limit in seconds of wall clock (0: none); a
        /// script's first line `-- adair: --timeout N` sets its own.
        #[arg(long, value_name = "SECONDS", default_value_t = adair::golden::DEFAULT_TIMEOUT,
              value_parser = adair::golden::timeout_seconds)]
        timeout: f64,
        /// Scripts run at once (default: the number of cores; 1 with --port).
        #[arg(short = 'j', long, value_name = "N",
              value_parser = clap::value_parser!(u16).range(1..))]
        jobs: Option<u16>,
        /// Also write a JUnit XML report (for CI and learning platforms).
        #[arg(long, value_name = "FILE.xml")]
        junit: Option<PathBuf>,
        /// Write each script's run in 3D, a replay page X.view.html for
        /// X.air: `--view` beside each script, `--view=FOLDER` into FOLDER
        /// (docs/view.md).
        #[arg(long, value_name = "FOLDER", num_args = 0..=1, require_equals = true,
              default_missing_value = "")]
        view: Option<String>,
        /// Run one script in this process and print its golden text (how
        /// `adair test` runs each script, in the script's folder).
        #[arg(long, hide = true)]
        child: bool,
    },
}

/// What `adair test` passes on to the child process of each script (the
/// global options), and whether its report is coloured.
struct TestGlobals {
    forward: Vec<std::ffi::OsString>,
    paint: bool,
}

static TEST_GLOBALS: std::sync::OnceLock<TestGlobals> = std::sync::OnceLock::new();

impl TestGlobals {
    fn of(cli: &Cli) -> TestGlobals {
        let mut forward = Vec::new();
        if let Some(p) = &cli.devices {
            // The child runs in the script's folder.
            let abs = std::env::current_dir().map_or(p.clone(), |d| d.join(p));
            forward.extend(["--devices".into(), abs.into_os_string()]);
        }
        if let Some(m) = cli.max_memory {
            forward.extend(["--max-memory".into(), m.to_string().into()]);
        }
        // The report goes to standard output: colour when that is a terminal.
        let paint = match cli.color.as_str() {
            "always" => true,
            "never" => false,
            _ => std::env::var_os("NO_COLOR").is_none() && std::io::stdout().is_terminal(),
        };
        TestGlobals { forward, paint }
    }
}

fn color(choice: &str) -> bool {
    match choice {
        "always" => true,
        "never" => false,
        _ => std::env::var_os("NO_COLOR").is_none() && std::io::stderr().is_terminal(),
    }
}

/// A program file's text, shared with the session (held once).
fn read(path: &PathBuf) -> Result<std::rc::Rc<str>, ExitCode> {
    std::fs::read_to_string(path)
        .map(std::rc::Rc::from)
        .map_err(|e| {
            eprintln!("adair: cannot read {}: {e}", path.display());
            ExitCode::from(2)
        })
}

/// Global options that take a value in the next argument (kept equal to
/// `Cli`'s by a test; read without building the parser twice at start-up).
const VALUED: [&str; 3] = ["--color", "--max-memory", "--devices"];

/// The arguments with `adair FILE.air ...` read as `adair run FILE.air ...`:
/// a first argument (after the global options) naming a program file.
fn with_shorthand(mut args: Vec<std::ffi::OsString>) -> Vec<std::ffi::OsString> {
    let mut i = 1;
    while i < args.len() {
        let a = args[i].to_string_lossy();
        if VALUED.contains(&a.as_ref()) {
            i += 2;
        } else if a.starts_with('-') {
            i += 1;
        } else {
            if a.ends_with(".air") || a.ends_with(".adb") {
                args.insert(i, "run".into());
            }
            break;
        }
    }
    args
}

fn main() -> ExitCode {
    let args = adair::view::live::bare_view_flag(std::env::args_os().collect());
    let cli = match Cli::try_parse_from(with_shorthand(args)) {
        Ok(c) => c,
        Err(e) => {
            if !e.use_stderr() {
                // --help and --version.
                if let Err(err) = e.print() {
                    let _ = LOST.set(format!("cannot write the standard output: {err}"));
                    return ExitCode::from(finish(2));
                }
                return ExitCode::SUCCESS;
            }
            // A usage error is one line.
            let text = e.kind().to_string();
            let detail = e.to_string();
            let mut lines = detail.lines().map(str::trim).filter(|l| !l.is_empty());
            let mut first = lines
                .next()
                .unwrap_or(&text)
                .trim_start_matches("error: ")
                .to_string();
            if first.ends_with(':')
                && let Some(next) = lines.next()
            {
                first = format!("{first} {next}");
            }
            eprintln!("adair: {first} (try `adair --help`)");
            return ExitCode::from(2);
        }
    };
    adair::interp::memory::set_limit(
        cli.max_memory
            .unwrap_or_else(adair::interp::memory::default_limit),
    );
    let devices = match &cli.devices {
        None => None,
        Some(p) => match adair::devices::Devices::load(p) {
            Ok(d) => Some(d),
            Err(e) => {
                eprintln!("{e}");
                return ExitCode::from(2);
            }
        },
    };
    let color = color(&cli.color);
    let _ = TEST_GLOBALS.set(TestGlobals::of(&cli));
    // Deep recursion in user programs needs a big stack for the tree walker.
    let child = std::thread::Builder::new()
        .stack_size(512 << 20)
        .spawn(move || real_main(cli.command, color, devices));
    match child.map(|h| h.join()) {
        Ok(Ok(code)) => ExitCode::from(finish(code)),
        _ => {
            eprintln!("adair: internal error");
            ExitCode::from(3)
        }
    }
}

fn real_main(
    command: Option<Command>,
    color: bool,
    devices: Option<adair::devices::Devices>,
) -> u8 {
    match command {
        None if std::io::stdin().is_terminal() => adair::repl::term::interactive(color) as u8,
        None => {
            eprintln!(
                "adair: no command given; try `adair run FILE.air`, `adair repl` or `adair --help`"
            );
            2
        }
        Some(Command::Repl {
            strict,
            robot,
            serial,
            rehearse,
            trace,
            view,
        }) => {
            if let Err(e) = adair::kinematics::RobotDescription::builtin(&robot) {
                eprintln!("adair: --robot: {}", e.problems.join("; "));
                return 2;
            }
            if view.file().is_some() {
                eprintln!("adair: --view: the REPL writes a page with `:view FILE.html`");
                return 2;
            }
            match view.serve() {
                Ok(Some(sv)) => adair::repl::view::serve_live(sv.hub.clone()),
                Ok(None) => {}
                Err(e) => {
                    eprintln!("adair: --view: {e}");
                    return 2;
                }
            }
            let drive = adair::repl::Drive {
                robot: Some(robot),
                port: serial.settings(),
                rehearse,
                devices: devices.clone(),
                trace,
            };
            if std::io::stdin().is_terminal() {
                adair::repl::term::interactive_on(color, drive) as u8
            } else {
                let stdin = std::io::stdin();
                adair::repl::term::piped_on(
                    stdin.lock(),
                    Box::new(|| Box::new(Watched::out()) as Box<dyn std::io::Write>),
                    &mut Watched::out(),
                    strict,
                    drive,
                ) as u8
            }
        }
        Some(Command::Run {
            file,
            robot,
            record,
            plot,
            view,
            strict,
        }) => {
            if let Some(p) = view.file()
                && let Err(e) = adair::view::check_target(&p)
            {
                eprintln!("adair: --view {}: {e}", p.display());
                return 2;
            }
            if let Some(p) = &record
                && let Err(e) = output_target(p, &["csv", "json"], ".csv or .json")
            {
                eprintln!("adair: --record {}: {e}", p.display());
                return 2;
            }
            if let Some(p) = &plot
                && let Err(e) = output_target(p, &["svg"], ".svg")
            {
                eprintln!("adair: --plot {}: {e}", p.display());
                return 2;
            }
            let desc = match robot.description() {
                Ok(d) => d,
                Err(e) => {
                    eprintln!("adair: {e}");
                    return 2;
                }
            };
            let text = match read(&file) {
                Ok(t) => t,
                Err(_) => return 2,
            };
            let trace = || -> Option<Box<dyn std::io::Write>> {
                if robot.trace {
                    Some(Box::new(Watched::err()))
                } else {
                    None
                }
            };
            let mut s = Session::new(Box::new(std::io::LineWriter::new(Watched::out())));
            // No tool reads the uses and types of this run.
            s.front.checker.index.uses = false;
            // It runs once: a long body is compiled as it is checked.
            s.compile_as_checked();
            s.strict = strict;
            s.warnings_to = Some((Box::new(Watched::err()), color));
            if let Some(d) = &devices {
                s.set_devices(d.clone());
            }
            if robot.trace {
                s.machine.trace = Some(Box::new(Watched::err()));
            }
            // Ctrl-C stops the motion and ends the program (exit 130).
            let flag = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
            let seen = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
            // A signal handler that sets the flags (no thread to start:
            // start-up time counts for short scripts). Ctrl-C always wins:
            // a second one ends the process at once with exit 130, whatever
            // the program caught of the first (registered first, so it
            // sees `seen` as the first Ctrl-C left it).
            let _ = signal_hook::flag::register_conditional_shutdown(
                signal_hook::consts::SIGINT,
                130,
                seen.clone(),
            );
            for f in [&flag, &seen] {
                let _ = signal_hook::flag::register(signal_hook::consts::SIGINT, f.clone());
            }
            s.machine.interrupted = Some(flag.clone());
            // The live view is paced to the wall clock.
            match robot.serial.settings() {
                None => s.set_robot(desc, trace(), robot.realtime || view.live()),
                Some(settings) => {
                    s.front.checker.options.simulator_only = adair::services::SIMULATOR_ONLY;
                    if robot.rehearse {
                        let name = file.to_string_lossy();
                        match adair::session::rehearse(&desc, &settings, &name, &text, color) {
                            Ok(()) => eprintln!("{}", adair::session::REHEARSED),
                            Err((shown, code)) => {
                                eprint!("{shown}");
                                return code as u8;
                            }
                        }
                    }
                    let driver =
                        adair::driver::serial::Serial::new(desc.clone(), settings, Some(flag));
                    s.set_driver(desc, Box::new(driver), trace(), false);
                }
            }
            if std::io::stdin().is_terminal() && std::io::stdout().is_terminal() {
                s.install_pendant(Box::new(adair::repl::teach::TermPendant::new()));
            }
            if record.is_some() || plot.is_some() || view.file().is_some() {
                s.start_recording();
            }
            // The replay page places the devices' objects by their moments.
            if view.file().is_some()
                && let Some(w) = s.machine.world.as_mut()
            {
                w.keep_timeline();
            }
            let title = file
                .file_name()
                .map(|n| n.to_string_lossy().into_owned())
                .unwrap_or_default();
            let live = match view.serve() {
                Ok(sv) => sv,
                Err(e) => {
                    eprintln!("adair: --view: {e}");
                    return 2;
                }
            };
            if let Some(sv) = &live {
                adair::view::live::attach(sv, &mut s, &title, sv.opened);
            }
            let outcome = s.run_source(&file.to_string_lossy(), text.clone());
            let stopped = s.take_stopped();
            if stopped.is_none() {
                report(&outcome, &s, color);
            }
            // Nothing ran after a check error: an existing file stays.
            let ran = !matches!(outcome, Outcome::CheckFailed(_));
            if let Some(p) = record.as_ref().filter(|_| ran)
                && let Err(e) = write_run(p, &s, &file)
            {
                eprintln!("adair: --record {}: {e}", p.display());
                return 2;
            }
            if let Some(p) = plot.as_ref().filter(|_| ran)
                && let Err(e) = write_run(p, &s, &file)
            {
                eprintln!("adair: --plot {}: {e}", p.display());
                return 2;
            }
            if let Some(st) = s.robot_state() {
                let ending = adair::view::ending(&s, &outcome);
                if let Some(p) = view.file().filter(|_| ran)
                    && let Err(e) =
                        adair::view::write_replay(&p, st, s.machine.world.as_ref(), &title, &ending)
                {
                    eprintln!("adair: --view {}: {e}", p.display());
                    return 2;
                }
                if let Some(sv) = &live {
                    adair::view::live::publish_state(&sv.hub, st, &ending, true);
                    sv.hub.finish(std::time::Duration::from_secs(2));
                }
            }
            if let Some(m) = stopped {
                eprintln!("adair: {m}");
                return 130;
            }
            if seen.load(std::sync::atomic::Ordering::SeqCst) {
                eprintln!("adair: interrupted (Ctrl-C)");
                return 130;
            }
            let code = outcome.exit_code() as u8;
            // The process ends here and its memory with it: the session is
            // not taken apart piece by piece, nor this thread's 512 MiB
            // stack (a short script's start-up, issue 11). Its output is
            // flushed; files a program writes are written whole as it
            // writes them, and recordings above.
            let _ = s.machine.out.flush();
            std::process::exit(finish(code).into())
        }
        Some(Command::SimController {
            robot,
            log,
            silent_after,
            corrupt,
            hangup_after,
            refuse,
            slow,
            time_scale,
            jog_after,
            control,
        }) => {
            let desc = match adair::kinematics::RobotDescription::builtin(&robot) {
                Ok(d) => d,
                Err(e) => {
                    eprintln!("adair: {e}");
                    return 2;
                }
            };
            let refuse = match refuse.as_deref().map(parse_refuse) {
                None => None,
                Some(Ok(r)) => Some(r),
                Some(Err(e)) => {
                    eprintln!("adair: --refuse {e}");
                    return 2;
                }
            };
            let log = match log.map(std::fs::File::create) {
                None => None,
                Some(Ok(f)) => Some(f),
                Some(Err(e)) => {
                    eprintln!("adair: cannot write the log: {e}");
                    return 2;
                }
            };
            let mut jogs = Vec::new();
            for j in &jog_after {
                match adair::simctl::parse_jog_after(j) {
                    Ok(jog) => jogs.push(jog),
                    Err(e) => {
                        eprintln!("adair: --jog-after {e}");
                        return 2;
                    }
                }
            }
            let faults = adair::simctl::Faults {
                silent_after,
                corrupt,
                hangup_after,
                refuse,
                slow,
                time_scale,
                jog_after: jogs,
                control,
            };
            if let Err(e) = faults.check() {
                eprintln!("adair: {e}");
                return 2;
            }
            match adair::simctl::serve(desc, faults, log, &mut std::io::stdout()) {
                Ok(()) => 0,
                Err(e) => {
                    eprintln!("adair: sim-controller: {e}");
                    1
                }
            }
        }
        Some(Command::Lsp) => match adair::lsp::serve_stdio() {
            Ok(()) => 0,
            Err(e) => {
                eprintln!("adair lsp: {e}");
                1
            }
        },
        Some(Command::Explain { code }) => match code {
            None => {
                for e in adair::diag::codes::ALL {
                    println!("{}  {}", e.code, e.title);
                }
                0
            }
            Some(c) => match adair::diag::codes::lookup(&c) {
                Some(e) => {
                    print!("{}", e.page);
                    0
                }
                None => {
                    eprintln!(
                        "adair explain: no code `{c}`; `adair explain` lists them (E0201, W0001, ...)"
                    );
                    2
                }
            },
        },
        Some(Command::Ports) => match list_ports(std::path::Path::new(TTY_CLASS)) {
            Ok(lines) if lines.is_empty() => {
                println!("no serial ports found");
                0
            }
            Ok(lines) => {
                for l in lines {
                    println!("{l}");
                }
                0
            }
            Err(e) => {
                eprintln!("adair: cannot list the serial ports: {e}");
                1
            }
        },
        Some(Command::Check { files, strict }) => {
            let mut worst = 0;
            for f in &files {
                // A file that cannot be read is one problem among the others:
                // report it and check the rest.
                let Ok(text) = read(f) else {
                    worst = 2;
                    continue;
                };
                let mut s = Session::new(Box::new(std::io::sink()));
                s.front.checker.index.uses = false;
                // Nothing runs: a long program's checked form is not kept.
                s.front.checker.options.diagnostics_only = true;
                // A script may be meant for a real arm: say where it cannot be.
                s.front.checker.options.simulator_only = adair::services::SIMULATOR_ONLY;
                s.strict = strict;
                if let Some(d) = &devices {
                    s.set_devices(d.clone());
                }
                // Targets are judged for the robot a script names in its
                // `-- adair: --robot` line (else the RV-M1).
                s.check_robot = adair::golden::directives(&text)
                    .ok()
                    .and_then(|d| d.robot)
                    .and_then(|r| adair::kinematics::RobotDescription::builtin(&r).ok());
                match s.check_source(&f.to_string_lossy(), text.clone(), false) {
                    Err(d) => {
                        eprint!("{}", adair::diag::render(&d, &s.front.sources, color));
                        worst = 2;
                    }
                    Ok(_) => eprint!(
                        "{}",
                        adair::diag::render(&s.warnings, &s.front.sources, color)
                    ),
                }
            }
            worst
        }
        Some(Command::Test {
            paths,
            bless,
            robot,
            trace,
            serial,
            rehearse,
            timeout,
            jobs,
            junit,
            view,
            child,
        }) => {
            let mut target = adair::golden::Target {
                port: serial.settings(),
                rehearse,
                devices: devices.clone(),
                robot: robot.clone(),
                trace,
                ..Default::default()
            };
            if child {
                // `--view=` (beside the script: the child runs in its
                // folder) or `--view=/absolute/folder`.
                if let (Some(v), [file]) = (&view, paths.as_slice()) {
                    let folder = (!v.is_empty()).then(|| std::path::Path::new(v.as_str()));
                    target.view = Some(adair::golden::view_page(file, folder));
                }
                return test_child(&paths, target, timeout);
            }
            let paths = if paths.is_empty() {
                vec![PathBuf::from(".")]
            } else {
                paths
            };
            let scripts = match adair::golden::collect(&paths) {
                Ok(s) => s,
                Err(e) => {
                    eprintln!("adair: {e}");
                    return 2;
                }
            };
            let globals = TEST_GLOBALS.get();
            let exe = match std::env::current_exe() {
                Ok(e) => e,
                Err(e) => {
                    eprintln!("adair: cannot find the adair binary to run the scripts: {e}");
                    return 2;
                }
            };
            // What each script's child process is told.
            let mut args: Vec<std::ffi::OsString> = Vec::new();
            if let Some(r) = &robot {
                args.extend(["--robot".into(), r.into()]);
            }
            if trace {
                args.push("--trace".into());
            }
            if let Some(p) = target.port.take() {
                args.extend([
                    "--port".into(),
                    p.path.into(),
                    "--baud".into(),
                    p.baud.to_string().into(),
                    "--serial-timeout".into(),
                    p.timeout.to_string().into(),
                ]);
                if rehearse {
                    args.push("--rehearse".into());
                }
            }
            // The replay pages: beside each script, or in one folder (made
            // absolute: each child runs in its script's folder).
            if let Some(v) = &view {
                let folder = if v.is_empty() {
                    String::new()
                } else {
                    let f = std::path::Path::new(v.as_str());
                    if !f.is_dir() {
                        eprintln!("adair: --view={v}: not a directory");
                        return 2;
                    }
                    if let Some((a, b)) = adair::golden::same_page(&scripts) {
                        eprintln!(
                            "adair: --view={v}: {} and {} would write the same page; \
                             write the pages beside the scripts with --view",
                            a.display(),
                            b.display()
                        );
                        return 2;
                    }
                    let abs = std::env::current_dir().map_or(f.to_path_buf(), |d| d.join(f));
                    abs.to_string_lossy().into_owned()
                };
                args.push(format!("--view={folder}").into());
            }
            // One arm: one script at a time.
            let jobs = if serial.port.is_some() {
                1
            } else {
                jobs.map_or_else(adair::golden::default_jobs, usize::from)
            };
            let mut global = globals.map(|g| g.forward.clone()).unwrap_or_default();
            if jobs > 1 && !global.iter().any(|a| a == "--max-memory") {
                // Scripts run at once share the memory: each has its part.
                let part = adair::interp::memory::default_limit() / jobs;
                global.extend(["--max-memory".into(), part.to_string().into()]);
            }
            let runner = adair::golden::Isolated {
                exe,
                global,
                args,
                env: Vec::new(),
                timeout,
            };
            let paint = globals.is_some_and(|g| g.paint);
            let results = adair::golden::run_all(
                &scripts,
                jobs,
                |s| runner.check(s, bless),
                |r| {
                    let _ = write!(Watched::out(), "{}", adair::golden::progress(r, paint));
                    let _ = Watched::out().flush();
                },
            );
            let pass = results.iter().filter(|r| r.verdict.passed()).count();
            let fail = results.len() - pass;
            println!("{pass} passed, {fail} failed");
            if let Some(f) = &junit
                && let Err(e) = std::fs::write(f, adair::golden::junit(&results, "adair test"))
            {
                eprintln!("adair: --junit {}: {e}", f.display());
                return 2;
            }
            if fail > 0 { 1 } else { 0 }
        }
    }
}

/// `adair test --child FILE`: runs one script in this process (in the
/// folder the parent chose) and prints its golden text; exit status 0, or
/// 2 for a configuration error (printed as `adair run` prints it), or 124
/// when the time limit stopped the program (what it printed until then).
fn test_child(paths: &[PathBuf], mut target: adair::golden::Target, timeout: f64) -> u8 {
    let [file] = paths else {
        eprintln!("adair: test --child takes one script");
        return 3;
    };
    let flag = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    let timed_out = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    if timeout > 0.0 {
        let (flag, timed_out) = (flag.clone(), timed_out.clone());
        std::thread::spawn(move || {
            std::thread::sleep(std::time::Duration::from_secs_f64(timeout));
            timed_out.store(true, std::sync::atomic::Ordering::SeqCst);
            flag.store(true, std::sync::atomic::Ordering::SeqCst);
            // A program that does not stop is killed by the parent after
            // the grace; without a parent (killed itself), it ends here.
            std::thread::sleep(2 * adair::golden::GRACE);
            std::process::exit(adair::golden::TIMED_OUT_STATUS);
        });
    }
    target.interrupt = Some(flag);
    match adair::golden::run_case_checked(file, &target) {
        Ok(text) => {
            let _ = write!(Watched::out(), "{text}");
            if timed_out.load(std::sync::atomic::Ordering::SeqCst) {
                adair::golden::TIMED_OUT_STATUS as u8
            } else {
                0
            }
        }
        Err(e) => {
            eprintln!("{e}");
            adair::golden::CONFIG_STATUS as u8
        }
    }
}

fn report(outcome: &Outcome, s: &Session, color: bool) {
    match outcome {
        Outcome::Ok => {}
        Outcome::CheckFailed(d) => eprint!("{}", adair::diag::render(d, &s.front.sources, color)),
        Outcome::Raised(d) => eprint!(
            "{}",
            adair::diag::render(std::slice::from_ref(d), &s.front.sources, color)
        ),
    }
}

/// A number of seconds for a timeout: finite, 0 to 3600 (NaN, an infinity
/// or a negative number would make every wait wrong, or panic).
fn timeout_seconds(text: &str) -> Result<f64, String> {
    let x: f64 = text
        .trim()
        .parse()
        .map_err(|_| format!("`{text}` is not a number of seconds"))?;
    if !x.is_finite() || !(0.0..=3600.0).contains(&x) {
        return Err(format!(
            "`{text}`: a number of seconds from 0 to 3600 (not NaN or infinite)"
        ));
    }
    Ok(x)
}

/// Where Linux lists its terminals, serial ports among them.
const TTY_CLASS: &str = "/sys/class/tty";

/// The serial ports, one line each (name, and USB ids where known).
/// `tty_class` is where the system lists them (`/sys/class/tty` on Linux),
/// which a container may not have: that is an error saying so (the
/// `serialport` crate panics without it).
fn list_ports(tty_class: &std::path::Path) -> Result<Vec<String>, String> {
    if cfg!(target_os = "linux") && !tty_class.is_dir() {
        return Err(format!(
            "{} does not exist here (a container without sysfs?); give the port's \
             device to --port, e.g. --port /dev/ttyUSB0",
            tty_class.display()
        ));
    }
    let ports = serialport::available_ports().map_err(|e| e.to_string())?;
    Ok(ports
        .into_iter()
        .map(|p| match p.port_type {
            serialport::SerialPortType::UsbPort(u) => format!(
                "{}  USB {:04x}:{:04x}{}",
                p.port_name,
                u.vid,
                u.pid,
                u.product.map(|s| format!(" {s}")).unwrap_or_default()
            ),
            _ => p.port_name,
        })
        .collect())
}

fn parse_refuse(s: &str) -> Result<(u64, u8), String> {
    let (n, m) = s
        .split_once(':')
        .ok_or_else(|| format!("`{s}`: expected N:MODE, e.g. 3:2"))?;
    let n: u64 = n.parse().map_err(|_| format!("`{s}`: N is not a number"))?;
    match m {
        "1" => Ok((n, 1)),
        "2" => Ok((n, 2)),
        _ => Err(format!("`{s}`: MODE is 1 or 2")),
    }
}

/// Checks a `--record` or `--plot` path before the run: one of the
/// extensions `exts` (`what` names them) in an existing directory.
fn output_target(p: &std::path::Path, exts: &[&str], what: &str) -> Result<(), String> {
    if !p
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| exts.contains(&e))
    {
        return Err(format!("the file must end in {what}"));
    }
    adair::plot::check_target(p)?;
    match p.parent() {
        Some(d) if !d.as_os_str().is_empty() && !d.is_dir() => {
            Err(format!("the directory {} does not exist", d.display()))
        }
        _ => Ok(()),
    }
}

/// Writes what `--record` or `--plot` asked for when the run has ended.
fn write_run(p: &std::path::Path, s: &Session, file: &std::path::Path) -> Result<(), String> {
    let st = s.robot_state().ok_or("no robot")?;
    let title = file
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    adair::plot::write_run(p, st, &title).map(|_| ())
}

#[cfg(test)]
mod tests {
    /// Without `/sys/class/tty` (a container) `adair ports` says so; the
    /// serialport crate panics there.
    #[test]
    fn ports_without_the_tty_class_folder_is_an_error_not_a_panic() {
        let missing =
            std::env::temp_dir().join(format!("adair_no_sysfs_{}/class/tty", std::process::id()));
        let e = super::list_ports(&missing).unwrap_err();
        assert!(
            e.contains(&missing.display().to_string()) && e.contains("--port"),
            "{e}"
        );
    }

    #[test]
    fn the_shorthand_knows_every_global_option_with_a_value() {
        use clap::CommandFactory;
        let mut valued: Vec<String> = super::Cli::command()
            .get_arguments()
            .filter(|a| a.is_global_set() && a.get_action().takes_values())
            .filter_map(|a| a.get_long().map(|l| format!("--{l}")))
            .collect();
        valued.sort();
        let mut ours: Vec<String> = super::VALUED.iter().map(|s| s.to_string()).collect();
        ours.sort();
        assert_eq!(valued, ours);
    }
}
