//! The services' golden scripts (`tests/golden/services/`, and the task
//! scenarios and examples, where the gripper picks parts from a belt), run
//! by the services' tests as well: the first mutation pass over
//! `src/services/` (`scripts/mutants.sh`) runs the library's unit tests and
//! these (`cargo test --lib --test services`), and what most of the
//! service core's code decides (options, timing, printed poses, faults) is
//! pinned only by these scripts' expected output. `tests/golden.rs` runs
//! them too, in both engines, with every other script.

use adair::golden::{self, Verdict};
use std::path::PathBuf;

#[test]
fn the_services_and_task_golden_scripts_print_their_out_files() {
    // Relative paths, as the .out files name them: cargo runs a test
    // binary in the package root.
    let dirs = ["tests/golden/services", "tests/golden/tasks", "examples"];
    let scripts = golden::collect(&dirs.map(PathBuf::from)).expect("golden scripts");
    assert!(scripts.len() > 80, "{} scripts", scripts.len());
    // The runner's stack, as `adair` gives a program (main.rs).
    let failed = std::thread::Builder::new()
        .stack_size(256 << 20)
        .spawn(move || {
            let mut failed = Vec::new();
            for s in &scripts {
                // A script that opens a file beside it by its name runs in
                // its own folder (`adair test`, `tests/golden.rs`); here the
                // current directory is the package root, shared with the
                // other tests of this process.
                if names_a_file_beside_it(s) {
                    continue;
                }
                match golden::check_case(s, false) {
                    Verdict::Pass => {}
                    Verdict::Differs { expected, actual } => failed.push(format!(
                        "{}: (- expected, + actual)\n{}",
                        s.display(),
                        golden::diff(&expected, &actual)
                    )),
                    other => failed.push(format!("{}: {other:?}", s.display())),
                }
            }
            failed
        })
        .expect("spawn")
        .join()
        .expect("the scripts ran");
    assert!(failed.is_empty(), "{}", failed.join("\n"));
}

/// Whether the script's text names, in a string literal, a file or folder
/// of its own folder (`LoadPathSystem ("good.paths")`, `"."`).
fn names_a_file_beside_it(script: &std::path::Path) -> bool {
    let text = std::fs::read_to_string(script).unwrap_or_default();
    let dir = script.parent().unwrap_or(std::path::Path::new("."));
    text.split('"')
        .skip(1)
        .step_by(2)
        .any(|lit| !lit.is_empty() && !lit.starts_with('/') && dir.join(lit).exists())
}
