//! The `adair` command line: the only place (with the REPL) that prints.
#![allow(clippy::print_stdout, clippy::print_stderr)]

use adair::session::{Outcome, Session};
use clap::{Parser, Subcommand};
use std::io::IsTerminal;
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "adair",
    version,
    about = "AdaIR: Ada for industrial robots. Check, run and test robot programs."
)]
struct Cli {
    /// Colours in diagnostics: auto (only on a terminal, and not with NO_COLOR), always, never.
    #[arg(long, global = true, default_value = "auto", value_parser = ["auto", "always", "never"])]
    color: String,
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(clap::Args)]
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
}

impl RobotOpts {
    fn description(&self) -> Result<adair::kinematics::RobotDescription, String> {
        let r = match &self.robot_file {
            Some(p) => adair::kinematics::RobotDescription::from_file(p),
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

#[derive(Subcommand)]
enum Command {
    /// Check the whole program, then run it. Exit 0; 1 on an unhandled exception; 2 on a check error.
    Run {
        /// The program (.air or .adb).
        file: PathBuf,
        #[command(flatten)]
        robot: RobotOpts,
    },
    /// Parse and check only; report every diagnostic; nothing runs.
    Check {
        #[arg(required = true)]
        files: Vec<PathBuf>,
    },
    /// The interactive REPL (script mode, one entry at a time). Reads piped input without a terminal.
    Repl {
        /// With piped input: exit 1 if an entry failed.
        #[arg(long)]
        strict: bool,
    },
    /// Golden tests: run each X.air and compare its output with X.out beside it.
    Test {
        /// Scripts or directories (default: the current directory).
        paths: Vec<PathBuf>,
        /// Write the actual output into the .out files.
        #[arg(long)]
        bless: bool,
    },
}

fn color(choice: &str) -> bool {
    match choice {
        "always" => true,
        "never" => false,
        _ => std::env::var_os("NO_COLOR").is_none() && std::io::stderr().is_terminal(),
    }
}

fn read(path: &PathBuf) -> Result<String, ExitCode> {
    std::fs::read_to_string(path).map_err(|e| {
        eprintln!("adair: cannot read {}: {e}", path.display());
        ExitCode::from(2)
    })
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            if !e.use_stderr() {
                // --help and --version.
                let _ = e.print();
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
    let color = color(&cli.color);
    // Deep recursion in user programs needs a big stack for the tree walker.
    let child = std::thread::Builder::new()
        .stack_size(512 << 20)
        .spawn(move || real_main(cli.command, color));
    match child.map(|h| h.join()) {
        Ok(Ok(code)) => ExitCode::from(code),
        _ => {
            eprintln!("adair: internal error");
            ExitCode::from(3)
        }
    }
}

fn real_main(command: Option<Command>, color: bool) -> u8 {
    match command {
        None if std::io::stdin().is_terminal() => adair::repl::term::interactive(color) as u8,
        None => {
            eprintln!(
                "adair: no command given; try `adair run FILE.air`, `adair repl` or `adair --help`"
            );
            2
        }
        Some(Command::Repl { strict }) => {
            if std::io::stdin().is_terminal() {
                adair::repl::term::interactive(color) as u8
            } else {
                let stdin = std::io::stdin();
                adair::repl::term::piped(stdin.lock(), &mut std::io::stdout(), strict) as u8
            }
        }
        Some(Command::Run { file, robot }) => {
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
            let mut s = Session::new(Box::new(std::io::LineWriter::new(std::io::stdout())));
            let trace: Option<Box<dyn std::io::Write>> = if robot.trace {
                Some(Box::new(std::io::stderr()))
            } else {
                None
            };
            s.set_robot(desc, trace, robot.realtime);
            if std::io::stdin().is_terminal() && std::io::stdout().is_terminal() {
                s.install_pendant(Box::new(adair::repl::teach::TermPendant::new()));
            }
            let outcome = s.run_source(&file.to_string_lossy(), &text);
            match &outcome {
                Outcome::Ok => {}
                Outcome::CheckFailed(d) => eprint!("{}", adair::diag::render(d, &s.sources, color)),
                Outcome::Raised(d) => eprint!(
                    "{}",
                    adair::diag::render(std::slice::from_ref(d), &s.sources, color)
                ),
            }
            outcome.exit_code() as u8
        }
        Some(Command::Check { files }) => {
            let mut worst = 0;
            for f in &files {
                // A file that cannot be read is one problem among the others:
                // report it and check the rest.
                let Ok(text) = read(f) else {
                    worst = 2;
                    continue;
                };
                let mut s = Session::new(Box::new(std::io::sink()));
                if let Err(d) = s.check_source(&f.to_string_lossy(), &text, false) {
                    eprint!("{}", adair::diag::render(&d, &s.sources, color));
                    worst = 2;
                }
            }
            worst
        }
        Some(Command::Test { paths, bless }) => {
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
            let (mut pass, mut fail) = (0, 0);
            for s in &scripts {
                match adair::golden::check_case(s, bless) {
                    adair::golden::Verdict::Pass => pass += 1,
                    adair::golden::Verdict::Blessed => {
                        println!("blessed {}", s.display());
                        pass += 1;
                    }
                    adair::golden::Verdict::Missing => {
                        println!(
                            "FAIL {}: no {} (run with --bless to create it)",
                            s.display(),
                            adair::golden::expected_path(s).display()
                        );
                        fail += 1;
                    }
                    adair::golden::Verdict::Differs { expected, actual } => {
                        println!(
                            "FAIL {}\n{}",
                            s.display(),
                            adair::golden::diff(&expected, &actual)
                        );
                        fail += 1;
                    }
                }
            }
            println!("{pass} passed, {fail} failed");
            if fail > 0 { 1 } else { 0 }
        }
    }
}
