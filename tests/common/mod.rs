//! Shared by the test binaries that run without libtest's harness.

use libtest_mimic::{Arguments, Failed, Trial};

/// Runs plain test functions (a panic fails the test) under libtest-mimic;
/// with `ignore`, every test is reported as ignored (the caller has said why).
pub fn run_fns(tests: &[(&'static str, fn())], ignore: bool) -> ! {
    let trials = tests
        .iter()
        .map(|&(name, f)| {
            Trial::test(name, move || {
                std::panic::catch_unwind(f).map_err(|e| {
                    Failed::from(
                        e.downcast_ref::<String>()
                            .cloned()
                            .or_else(|| e.downcast_ref::<&str>().map(|s| s.to_string()))
                            .unwrap_or_else(|| "panicked".into()),
                    )
                })
            })
            .with_ignored_flag(ignore)
        })
        .collect();
    libtest_mimic::run(&Arguments::from_args(), trials).exit()
}
