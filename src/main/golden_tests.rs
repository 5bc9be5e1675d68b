//! `adair test`: golden tests, each script in its own child process
//! (`adair test --child`), compared with the `.out` beside it.

use crate::Watched;
use crate::cli::{TEST_GLOBALS, TestArgs};
use std::io::Write as _;
use std::path::PathBuf;

/// `adair test`: 0 when every script passed, 1 when one failed, 2 for a
/// usage error.
pub fn test(args: TestArgs, devices: Option<adair::devices::Devices>) -> u8 {
    let TestArgs {
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
    } = args;
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
