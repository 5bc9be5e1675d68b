//! The `adair` command line: the only place (with the REPL) that prints.
#![allow(clippy::print_stdout, clippy::print_stderr)]

use adair::session::Session;
use cli::{Cli, Command, TEST_GLOBALS, TestGlobals};
use std::io::IsTerminal;
use std::io::Write as _;
use std::path::PathBuf;
use std::process::ExitCode;

// This file's `println!`, `eprint!` and `eprintln!`: std's panic when the
// write fails (a full disk: exit 101); these write through [`Watched`],
// which remembers the failure for the exit status ([`finish`]).
macro_rules! println {
    ($($t:tt)*) => {{
        let _ = { use std::io::Write as _; writeln!($crate::Watched::out(), $($t)*) };
    }};
}
macro_rules! eprint {
    ($($t:tt)*) => {{
        let _ = { use std::io::Write as _; write!($crate::Watched::err(), $($t)*) };
    }};
}
macro_rules! eprintln {
    ($($t:tt)*) => {{
        let _ = { use std::io::Write as _; writeln!($crate::Watched::err(), $($t)*) };
    }};
}

// The binary's parts, in `src/main/` (a crate root's `mod x;` would look
// in `src/`, among the library's modules). The macros above are visible
// in them.
#[path = "main/cli.rs"]
mod cli;
#[path = "main/golden_tests.rs"]
mod golden_tests;
#[path = "main/run.rs"]
mod run;

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

fn color(choice: &str) -> bool {
    match choice {
        "always" => true,
        "never" => false,
        _ => std::env::var_os("NO_COLOR").is_none() && std::io::stderr().is_terminal(),
    }
}

/// A program file's text, shared with the session (held once).
pub(crate) fn read(path: &PathBuf) -> Result<std::rc::Rc<str>, ExitCode> {
    std::fs::read_to_string(path)
        .map(std::rc::Rc::from)
        .map_err(|e| {
            eprintln!("adair: cannot read {}: {e}", path.display());
            ExitCode::from(2)
        })
}

fn main() -> ExitCode {
    let args = adair::view::live::bare_view_flag(std::env::args_os().collect());
    let cli = match Cli::parse_args(cli::with_shorthand(args)) {
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
        cli.globals
            .max_memory
            .unwrap_or_else(adair::interp::memory::default_limit),
    );
    let devices = match &cli.globals.devices {
        None => None,
        Some(p) => match adair::devices::Devices::load(p) {
            Ok(d) => Some(d),
            Err(e) => {
                eprintln!("{e}");
                return ExitCode::from(2);
            }
        },
    };
    let color = color(&cli.globals.color);
    let _ = TEST_GLOBALS.set(TestGlobals::of(&cli));
    // Deeply nested text needs a big stack for the parser and the checker.
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
        Some(Command::Run(args)) => run::run(args, color, devices),
        Some(Command::Test(args)) => golden_tests::test(args, devices),
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
            let refuse = match refuse.as_deref().map(cli::parse_refuse) {
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
    }
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

    /// `adair run`'s quick parser reads what the whole grammar reads, and
    /// leaves to it what it cannot read (errors, `--help`, other commands).
    #[test]
    fn the_run_parser_agrees_with_the_whole_grammar() {
        use super::cli::{Cli, with_shorthand};
        use clap::Parser as _;
        let args = |line: &str| -> Vec<std::ffi::OsString> {
            with_shorthand(line.split_whitespace().map(Into::into).collect())
        };
        for line in [
            "adair run p.adb",
            "adair p.air",
            "adair --color never run p.adb --strict",
            "adair run p.adb --max-memory 512M --devices d.toml --color=always",
            "adair --max-memory 1G p.adb --robot rm-501 --trace --realtime",
            "adair run p.adb --port /dev/ttyUSB0 --baud 4800 --serial-timeout 3 --rehearse",
            "adair run p.adb --record r.txt --plot p.svg --view v.html --view-port 8080 --no-open",
            "adair run p.adb --view --robot-file r.toml",
            "adair run -- -p.adb",
            "adair run robots/p.adb",
            "adair run -",
        ] {
            let quick = Cli::parse_run(&args(line)).unwrap_or_else(|| panic!("{line}"));
            let whole = Cli::try_parse_from(args(line)).unwrap_or_else(|e| panic!("{line}: {e}"));
            assert_eq!(
                format!("{:?} {:?}", quick.globals, quick.command),
                format!("{:?} {:?}", whole.globals, whole.command),
                "{line}"
            );
        }
        for line in [
            "adair run",
            "adair run --help",
            "adair run p.adb --bogus",
            "adair run -p.adb",
            "adair run p.adb --rehearse",
            "adair --version run p.adb",
            "adair check p.adb",
            "adair p.txt",
            "adair",
            "adair --color never",
        ] {
            assert!(Cli::parse_run(&args(line)).is_none(), "{line}");
        }
    }

    #[test]
    fn the_shorthand_knows_every_global_option_with_a_value() {
        use clap::CommandFactory;
        let mut valued: Vec<String> = super::cli::Cli::command()
            .get_arguments()
            .filter(|a| a.is_global_set() && a.get_action().takes_values())
            .filter_map(|a| a.get_long().map(|l| format!("--{l}")))
            .collect();
        valued.sort();
        let mut ours: Vec<String> = super::cli::VALUED.iter().map(|s| s.to_string()).collect();
        ours.sort();
        assert_eq!(valued, ours);
    }
}
