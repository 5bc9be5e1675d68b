//! The golden corpus: every `.air` under `tests/golden/` and `examples/` is
//! one named test, run in-process through the same runner as `adair test`,
//! in the compiled engine and again in the reference tree walker: both must
//! print the `.out` file (differential testing of the engines). Programs with
//! tasks run in the compiled engine only.
//! `BLESS=1 cargo test --test golden` rewrites the `.out` files.
#![allow(clippy::print_stdout, clippy::print_stderr)]

use adair::golden::{self, Verdict};
use libtest_mimic::{Arguments, Failed, Trial};
use std::path::PathBuf;

fn main() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    std::env::set_current_dir(&root).expect("crate root");
    let bless = std::env::var_os("BLESS").is_some();
    let dirs: Vec<PathBuf> = ["tests/golden", "examples"]
        .iter()
        .map(PathBuf::from)
        .filter(|p| p.exists())
        .collect();
    let scripts = golden::collect(&dirs).expect("golden corpus");
    let trials = scripts
        .into_iter()
        .map(|path| {
            let name = path.with_extension("").to_string_lossy().replace('/', "::");
            Trial::test(name, move || match on_big_stack(path.clone(), bless) {
                Verdict::Pass => walker_agrees(&path),
                Verdict::Blessed => Ok(()),
                Verdict::Missing => Err(Failed::from(format!(
                    "{} has no .out file (run with BLESS=1)",
                    path.display()
                ))),
                Verdict::Differs { expected, actual } => Err(Failed::from(format!(
                    "output differs (- expected, + actual):\n{}",
                    golden::diff(&expected, &actual)
                ))),
            })
        })
        .collect();
    libtest_mimic::run(&Arguments::from_args(), trials).exit();
}

/// The reference engine prints the `.out` file too (programs with tasks run
/// in the compiled engine only: the walker cannot suspend a task).
fn walker_agrees(path: &std::path::Path) -> Result<(), Failed> {
    let text = std::fs::read_to_string(path).unwrap_or_default();
    if golden::uses_tasks(&text) {
        return Ok(());
    }
    let p = path.to_path_buf();
    let actual = std::thread::Builder::new()
        .stack_size(512 << 20)
        .spawn(move || {
            golden::run_case_on(
                &p,
                &golden::Target {
                    engine: Some(adair::interp::vm::Engine::Walker),
                    ..golden::Target::default()
                },
            )
        })
        .expect("spawn a test thread")
        .join()
        .unwrap_or_else(|_| "the run panicked".into());
    let expected = std::fs::read_to_string(golden::expected_path(path)).unwrap_or_default();
    if expected == actual {
        Ok(())
    } else {
        Err(Failed::from(format!(
            "the tree walker (reference engine) differs from the .out (- expected, + walker):\n{}",
            golden::diff(&expected, &actual)
        )))
    }
}

/// Runs a case on a thread with the stack `adair` itself gives a program
/// (main.rs: 512 MiB, reserved lazily), so deep recursion behaves as on the
/// command line rather than overflowing the test runner's 2 MiB thread.
fn on_big_stack(path: PathBuf, bless: bool) -> Verdict {
    std::thread::Builder::new()
        .stack_size(512 << 20)
        .spawn(move || golden::check_case(&path, bless))
        .expect("spawn a test thread")
        .join()
        .unwrap_or_else(|_| Verdict::Differs {
            expected: String::new(),
            actual: "the run panicked".into(),
        })
}
