//! The command line's grammar (clap): the global options, each command's
//! options, and the value parsers they use.

use clap::{Args, Parser, Subcommand};
use std::io::IsTerminal;
use std::path::PathBuf;

#[derive(Parser)]
#[command(
    name = "adair",
    version,
    about = "AdaIR: Ada for industrial robots. Check, run and test robot programs.",
    after_help = "`adair FILE.air [OPTIONS]` is short for `adair run FILE.air [OPTIONS]`."
)]
pub struct Cli {
    #[command(flatten)]
    pub globals: Globals,
    #[command(subcommand)]
    pub command: Option<Command>,
}

/// The options every command takes (`global`).
#[derive(Args, Debug)]
pub struct Globals {
    /// Colours in diagnostics: auto (only on a terminal, and not with NO_COLOR), always, never.
    #[arg(long, global = true, default_value = "auto", value_parser = ["auto", "always", "never"])]
    pub color: String,
    /// Memory a program may use (512M, 2G, ...): past it, building a value raises
    /// Storage_Error where the program asked for it. Default: what the process
    /// can really have (the least of `ulimit -v`, the cgroup's memory.max and
    /// the physical memory, less adair's share), at most 4G.
    #[arg(long, global = true, value_name = "SIZE",
          value_parser = adair::interp::memory::parse_size)]
    pub max_memory: Option<usize>,
    /// The simulated devices: a TOML device file (see docs/tasks.md). Without it, the
    /// appendix C parallel port at 8#340#.
    #[arg(long, global = true, value_name = "FILE.toml")]
    pub devices: Option<PathBuf>,
}

impl Cli {
    /// The command line `args` (shorthand applied), read by clap.
    /// `adair run ...` is read first by a parser of the global options and
    /// `run`'s alone: building the whole grammar (every command's options)
    /// cost more than checking a short program (issue 32 item 4,
    /// start-up). Whatever that parser refuses (an error, `--help`) is read
    /// again by the whole grammar, whose messages are the ones shown.
    pub fn parse_args(args: Vec<std::ffi::OsString>) -> Result<Cli, clap::Error> {
        if let Some(cli) = Cli::parse_run(&args) {
            return Ok(cli);
        }
        Cli::try_parse_from(args)
    }

    /// [`Cli::parse_args`]'s quick reading of `adair run ...` (`None`: not
    /// `run`, or not read).
    pub fn parse_run(args: &[std::ffi::OsString]) -> Option<Cli> {
        use clap::FromArgMatches;
        if args[command_at(args)?] != "run" {
            return None;
        }
        if let [_, _, file] = args
            && !file.is_empty()
            && !file.to_string_lossy().starts_with('-')
        {
            return Some(Cli::plain_run(file.into()));
        }
        let grammar = Globals::augment_args(clap::Command::new("adair"))
            .subcommand(RunArgs::augment_args(clap::Command::new("run")));
        let m = grammar.try_get_matches_from(args).ok()?;
        let globals = Globals::from_arg_matches(&m).ok()?;
        let run = RunArgs::from_arg_matches(m.subcommand_matches("run")?).ok()?;
        Some(Cli {
            globals,
            command: Some(Command::Run(run)),
        })
    }
}

impl Cli {
    /// `adair run FILE` without options (the usual command), as clap reads
    /// it: even the small grammar of [`Cli::parse_run`] cost 150k
    /// instructions to build and run. The defaults are the grammar's
    /// (`the_run_parser_agrees_with_the_whole_grammar` compares them).
    fn plain_run(file: PathBuf) -> Cli {
        Cli {
            globals: Globals {
                color: "auto".into(),
                max_memory: None,
                devices: None,
            },
            command: Some(Command::Run(RunArgs {
                file,
                robot: RobotOpts {
                    robot: "rv-m1".into(),
                    robot_file: None,
                    trace: false,
                    realtime: false,
                    serial: SerialOpts {
                        port: None,
                        baud: 9600,
                        serial_timeout: 2.0,
                    },
                    rehearse: false,
                },
                record: None,
                plot: None,
                view: ViewOpts {
                    view: None,
                    view_port: 0,
                    no_open: false,
                },
                strict: false,
            })),
        }
    }
}

/// Where the first argument after the global options is (the command's
/// name, or a program file for the shorthand).
fn command_at(args: &[std::ffi::OsString]) -> Option<usize> {
    let mut i = 1;
    while i < args.len() {
        let a = args[i].to_string_lossy();
        if VALUED.contains(&a.as_ref()) {
            i += 2;
        } else if a.starts_with('-') {
            i += 1;
        } else {
            return Some(i);
        }
    }
    None
}

#[derive(Args, Debug)]
pub struct RobotOpts {
    /// The simulated robot: rv-m1 (default) or rm-501.
    #[arg(long, default_value = "rv-m1")]
    pub robot: String,
    /// A robot description file (TOML) instead of a built-in robot.
    #[arg(long, value_name = "PATH")]
    pub robot_file: Option<PathBuf>,
    /// Print each motion (virtual time, service, joints before and after, duration, source line) to standard error.
    #[arg(long)]
    pub trace: bool,
    /// Pace the simulator to the wall clock.
    #[arg(long)]
    pub realtime: bool,
    #[command(flatten)]
    pub serial: SerialOpts,
    /// With --port: run the whole program on the simulator from the arm's pose
    /// first, and move the arm only if that run ends without an unhandled exception.
    #[arg(long, requires = "port")]
    pub rehearse: bool,
}

/// The serial port options of `run` and `repl`.
#[derive(Args, Debug)]
pub struct SerialOpts {
    /// Drive a real arm on this serial port instead of the simulator.
    #[arg(long, value_name = "PATH")]
    pub port: Option<String>,
    /// Baud rate of --port.
    #[arg(long, default_value_t = 9600, requires = "port")]
    pub baud: u32,
    /// Seconds a reply may take beyond a motion's expected time (0 to 3600).
    #[arg(long, value_name = "SECONDS", default_value_t = 2.0, requires = "port",
          value_parser = timeout_seconds)]
    pub serial_timeout: f64,
}

impl SerialOpts {
    /// The port settings, when a port was given.
    pub fn settings(&self) -> Option<adair::driver::serial::PortSettings> {
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
    pub fn description(&self) -> Result<adair::kinematics::RobotDescription, String> {
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
#[derive(Args, Debug)]
pub struct ViewOpts {
    /// The run in 3D in a browser: `--view FILE.html` writes a replay page
    /// (also after an exception); `--view` alone serves the page live on
    /// 127.0.0.1, paced to the wall clock.
    #[arg(long, value_name = "FILE.html", num_args = 0..=1, default_missing_value = "")]
    pub view: Option<String>,
    /// The live view's port on 127.0.0.1 (0: any free port).
    #[arg(long, value_name = "N", default_value_t = 0)]
    pub view_port: u16,
    /// Do not open the live view in a browser (print its address only).
    #[arg(long)]
    pub no_open: bool,
}

impl ViewOpts {
    /// `--view` alone: the live view.
    pub fn live(&self) -> bool {
        self.view.as_deref() == Some("")
    }
    /// `--view FILE.html`.
    pub fn file(&self) -> Option<PathBuf> {
        self.view
            .as_deref()
            .filter(|v| !v.is_empty())
            .map(PathBuf::from)
    }
    /// Starts the live view's server when asked; says where it listens.
    pub fn serve(&self) -> Result<Option<adair::view::live::Server>, String> {
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

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Check the whole program, then run it. Exit 0; 1 on an unhandled exception; 2 on a check error.
    Run(RunArgs),
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
    Test(TestArgs),
}

/// What `adair test` passes on to the child process of each script (the
/// global options), and whether its report is coloured.
pub struct TestGlobals {
    pub forward: Vec<std::ffi::OsString>,
    pub paint: bool,
}

pub static TEST_GLOBALS: std::sync::OnceLock<TestGlobals> = std::sync::OnceLock::new();

impl TestGlobals {
    pub fn of(cli: &Cli) -> TestGlobals {
        let mut forward = Vec::new();
        if let Some(p) = &cli.globals.devices {
            // The child runs in the script's folder.
            let abs = std::env::current_dir().map_or(p.clone(), |d| d.join(p));
            forward.extend(["--devices".into(), abs.into_os_string()]);
        }
        if let Some(m) = cli.globals.max_memory {
            forward.extend(["--max-memory".into(), m.to_string().into()]);
        }
        // The report goes to standard output: colour when that is a terminal.
        let paint = match cli.globals.color.as_str() {
            "always" => true,
            "never" => false,
            _ => std::env::var_os("NO_COLOR").is_none() && std::io::stdout().is_terminal(),
        };
        TestGlobals { forward, paint }
    }
}

/// Global options that take a value in the next argument (kept equal to
/// `Cli`'s by a test; read without building the parser twice at start-up).
pub const VALUED: [&str; 3] = ["--color", "--max-memory", "--devices"];

/// The arguments with `adair FILE.air ...` read as `adair run FILE.air ...`:
/// a first argument (after the global options) naming a program file.
pub fn with_shorthand(mut args: Vec<std::ffi::OsString>) -> Vec<std::ffi::OsString> {
    if let Some(i) = command_at(&args) {
        let a = args[i].to_string_lossy();
        if a.ends_with(".air") || a.ends_with(".adb") {
            args.insert(i, "run".into());
        }
    }
    args
}

/// A number of seconds for a timeout: finite, 0 to 3600 (NaN, an infinity
/// or a negative number would make every wait wrong, or panic).
pub fn timeout_seconds(text: &str) -> Result<f64, String> {
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

pub fn parse_refuse(s: &str) -> Result<(u64, u8), String> {
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

// The options of `adair run` (its help text is the variant's).
#[derive(Args, Debug)]
pub struct RunArgs {
    /// The program (.air or .adb).
    pub file: PathBuf,
    #[command(flatten)]
    pub robot: RobotOpts,
    /// Write every support point of every motion to FILE.csv or FILE.json
    /// (t, j1..j5, x, y, z, grip), also when the run ends with an exception.
    #[arg(long, value_name = "FILE")]
    pub record: Option<PathBuf>,
    /// Draw the run into FILE.svg: joints against time, and the TCP path from
    /// above and from the side with the arm's reach (also after an exception).
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,
    #[command(flatten)]
    pub view: ViewOpts,
    /// Treat warnings as errors: nothing runs, exit 2.
    #[arg(long)]
    pub strict: bool,
}

// The options of `adair test` (its help text is the variant's).
#[derive(Args, Debug)]
pub struct TestArgs {
    /// Scripts or directories (default: the current directory); each
    /// script runs once, and no folder is walked twice (a link back to
    /// one, `up -> ..`, is not followed again).
    pub paths: Vec<PathBuf>,
    /// Write the actual output into the .out files (with --port: what the arm did).
    #[arg(long)]
    pub bless: bool,
    /// The simulated robot of scripts that name none in a `-- adair: --robot R` first
    /// line: rv-m1 (default) or rm-501.
    #[arg(long, value_parser = ["rv-m1", "rm-501"])]
    pub robot: Option<String>,
    /// Every script's motion trace in its output (also in what --bless writes).
    #[arg(long)]
    pub trace: bool,
    #[command(flatten)]
    pub serial: SerialOpts,
    /// With --port: rehearse each script on the simulator from the arm's
    /// pose first; a script whose rehearsal fails does not move the arm.
    #[arg(long, requires = "port")]
    pub rehearse: bool,
    /// Each script's time limit in seconds of wall clock (0: none); a
    /// script's first line `-- adair: --timeout N` sets its own.
    #[arg(long, value_name = "SECONDS", default_value_t = adair::golden::DEFAULT_TIMEOUT,
          value_parser = adair::golden::timeout_seconds)]
    pub timeout: f64,
    /// Scripts run at once (default: the number of cores; 1 with --port).
    #[arg(short = 'j', long, value_name = "N",
          value_parser = clap::value_parser!(u16).range(1..))]
    pub jobs: Option<u16>,
    /// Also write a JUnit XML report (for CI and learning platforms).
    #[arg(long, value_name = "FILE.xml")]
    pub junit: Option<PathBuf>,
    /// Write each script's run in 3D, a replay page X.view.html for
    /// X.air: `--view` beside each script, `--view=FOLDER` into FOLDER
    /// (docs/view.md).
    #[arg(long, value_name = "FOLDER", num_args = 0..=1, require_equals = true,
          default_missing_value = "")]
    pub view: Option<String>,
    /// Run one script in this process and print its golden text (how
    /// `adair test` runs each script, in the script's folder).
    #[arg(long, hide = true)]
    pub child: bool,
}
