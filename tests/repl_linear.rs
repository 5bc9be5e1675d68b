//! Piped REPL entries take work linear in their number (issue 35: 10,000
//! one-line declarations took 26 s, because each entry copied every table
//! of the session to be able to roll a refused entry back).
//!
//! The work is counted as the bytes the entries allocate (the process's
//! allocator counts them in the tests' build), not timed: a copy of the
//! session's tables per entry makes the count grow four times when the
//! number of entries doubles. This file holds one test, so that no other
//! test allocates while it counts.

use adair::interp::memory::ALLOC;
use adair::repl::Repl;

/// The bytes allocated by a REPL session of `n` entries: one-line
/// declarations of variables, functions and types, and every tenth entry
/// also one the checker refuses (it is rolled back) and an expression.
/// (The refused entry is a type error: a misspelt name's "did you mean"
/// looks at every visible name, as a compiler's does, which is work in
/// the size of the session for each typo.)
fn repl_bytes(n: usize) -> usize {
    let mut repl = Repl::new(Box::new(|| Box::new(std::io::sink())), false);
    let before = ALLOC.total_allocated();
    for i in 0..n {
        let decl = match i % 3 {
            0 => format!("X{i} : Integer := {i};"),
            1 => format!(
                "X{i} : Integer := {i}; function F{i} (A : Integer) return Integer is (A + {i});"
            ),
            _ => format!("X{i} : Integer := {i}; type T{i} is range 0 .. {i};"),
        };
        let r = repl.entry(&decl);
        assert!(!r.failed, "{}", r.text);
        if i % 10 == 0 {
            let r = repl.entry(&format!("Y{i} : Integer := True;"));
            assert!(r.failed, "a refused entry: {}", r.text);
            let r = repl.entry(&format!("X{i} + 1"));
            assert_eq!(r.text, format!("{}\n", i + 1));
        }
    }
    // The session still knows every entry that was not refused.
    let r = repl.entry(&format!("X{}", n - 1));
    assert_eq!(r.text, format!("{}\n", n - 1));
    ALLOC.total_allocated() - before
}

#[test]
fn piped_repl_entries_take_linear_work() {
    let sizes = [200, 400, 800];
    let b: Vec<usize> = sizes.iter().map(|&n| repl_bytes(n)).collect();
    let (d1, d2) = (b[1] - b[0], b[2] - b[1]);
    assert!(
        d2 <= d1 * 5 / 2,
        "bytes allocated at {sizes:?} entries: {b:?} (growth {d1} then {d2}: not linear)"
    );
}
