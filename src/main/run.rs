//! `adair run`: check the whole program, then run it on the simulator or
//! a real arm, with its recording, plot and 3D view.

use crate::cli::RunArgs;
use crate::{Watched, finish};
use adair::session::{Outcome, Session};
use std::io::IsTerminal;
use std::io::Write as _;

/// `adair run`: the exit status (the process ends here when the program
/// ran: see the end).
pub fn run(args: RunArgs, color: bool, devices: Option<adair::devices::Devices>) -> u8 {
    let RunArgs {
        file,
        robot,
        record,
        plot,
        view,
        strict,
    } = args;
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
    // A built-in robot on the simulator, with nothing that reads the robot
    // before the program names the AdaIR package, is built only then: a
    // program that never moves the arm does not read its description
    // (start-up, issue 32). A description file is read now, for its errors.
    let lazy = robot.robot_file.is_none()
        && robot.serial.port.is_none()
        && record.is_none()
        && plot.is_none()
        && view.view.is_none()
        && adair::kinematics::RobotDescription::builtin_text(&robot.robot).is_some();
    let desc = if lazy {
        None
    } else {
        match robot.description() {
            Ok(d) => Some(d),
            Err(e) => {
                eprintln!("adair: {e}");
                return 2;
            }
        }
    };
    let text = match crate::read(&file) {
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
    match (robot.serial.settings(), desc) {
        (_, None) => {
            let name = robot.robot.clone();
            s.set_robot_lazily(
                Box::new(move || {
                    adair::kinematics::RobotDescription::builtin(&name)
                        .expect("a built-in robot's description is valid")
                }),
                trace(),
                robot.realtime,
            )
        }
        (None, Some(desc)) => s.set_robot(desc, trace(), robot.realtime || view.live()),
        (Some(settings), Some(desc)) => {
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
            let driver = adair::driver::serial::Serial::new(desc.clone(), settings, Some(flag));
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
