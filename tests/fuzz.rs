//! A fuzz target that runs on stable Rust inside `cargo test`: programs from
//! the corpus, mutated (bytes deleted or replaced, tokens inserted, lines
//! duplicated, swapped, dropped or spliced in from another program), go
//! through the lexer, parser and checker, and those that check are run on
//! the simulator with a time budget. Nothing may panic. proptest shrinks a
//! failure to the fewest mutations, and the test prints the input.
//!
//! Corpus: `tests/fuzz/corpus/*.air` (add every crash found here, once
//! fixed), plus the examples and the golden scripts.
//! `ADAIR_FUZZ_CASES` sets the number of mutated programs (default 300;
//! `.ci/run` asks for more).
#![allow(clippy::print_stderr)]

use adair::session::Session;
use proptest::prelude::*;
use std::path::Path;
use std::sync::OnceLock;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};

fn collect(dir: &Path, out: &mut Vec<String>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let mut paths: Vec<_> = entries.flatten().map(|e| e.path()).collect();
    paths.sort();
    for p in paths {
        if p.is_dir() {
            collect(&p, out);
        } else if p.extension().is_some_and(|e| e == "air")
            && let Ok(text) = std::fs::read_to_string(&p)
        {
            out.push(text);
        }
    }
}

fn corpus() -> &'static [String] {
    static CORPUS: OnceLock<Vec<String>> = OnceLock::new();
    CORPUS.get_or_init(|| {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let mut v = Vec::new();
        for dir in ["tests/fuzz/corpus", "examples", "tests/golden"] {
            collect(&root.join(dir), &mut v);
        }
        v
    })
}

/// Tokens a mutation inserts.
const TOKENS: &[&str] = &[
    "begin",
    "end",
    "end if;",
    "end loop;",
    "loop",
    "if",
    "then",
    "else",
    "declare",
    "is",
    ";",
    ":=",
    "(",
    ")",
    ",",
    "..",
    "'",
    "'Range",
    "'Last",
    "=>",
    "others",
    "when",
    "case",
    "X",
    "Integer",
    "Float",
    "String",
    "0",
    "2_147_483_647",
    "1.0E308",
    "-",
    "*",
    "**",
    "/",
    "mod",
    "&",
    "\"",
    "\"text\"",
    "'c'",
    "null;",
    "raise;",
    "return",
    "new",
    "access",
    "all",
    "record",
    "array",
    "of",
    "range",
    "exit",
    "for",
    "in",
    "reverse",
    "while",
    "with",
    "use",
    "package",
    "body",
    "function",
    "procedure",
    "exception",
    "Constraint_Error",
    "InitRobot;",
    "MoveAxesAbsolute",
    "Trans (1.0, 2.0, 3.0)",
    "ä",
    "\u{feff}",
    "--",
    "\t",
    "\n",
];

/// One mutation: what, and two numbers it picks its places with.
type Mutation = (u8, u32, u32);

fn boundary(s: &str, i: u32) -> usize {
    if s.is_empty() {
        return 0;
    }
    let i = i as usize % (s.len() + 1);
    (0..=i).rev().find(|&j| s.is_char_boundary(j)).unwrap_or(0)
}

fn mutate(src: &str, muts: &[Mutation], other: &str) -> String {
    let mut s = src.to_string();
    for &(kind, a, b) in muts {
        let lines: Vec<&str> = s.lines().collect();
        let line = |i: u32| {
            lines
                .get(i as usize % lines.len().max(1))
                .copied()
                .unwrap_or("")
        };
        s = match kind % 8 {
            0 => {
                let i = boundary(&s, a);
                let j = boundary(&s, (i as u32).saturating_add(b % 24)).max(i);
                format!("{}{}", &s[..i], &s[j..])
            }
            1 => {
                let i = boundary(&s, a);
                let t = TOKENS[b as usize % TOKENS.len()];
                format!("{} {t} {}", &s[..i], &s[i..])
            }
            2 => {
                let l = line(a);
                let i = boundary(&s, b);
                format!("{}\n{l}\n{}", &s[..i], &s[i..])
            }
            3 => {
                let (x, y) = (
                    a as usize % lines.len().max(1),
                    b as usize % lines.len().max(1),
                );
                let mut ls = lines.clone();
                if !ls.is_empty() {
                    ls.swap(x, y);
                }
                ls.join("\n")
            }
            4 => {
                let i = boundary(&s, a);
                let c = char::from(b'!' + (b % 94) as u8);
                let j = s[i..].chars().next().map_or(i, |ch| i + ch.len_utf8());
                format!("{}{c}{}", &s[..i], &s[j..])
            }
            5 => {
                let ol: Vec<&str> = other.lines().collect();
                let l = ol.get(a as usize % ol.len().max(1)).copied().unwrap_or("");
                let i = boundary(&s, b);
                format!("{}\n{l}\n{}", &s[..i], &s[i..])
            }
            6 => s[..boundary(&s, a)].to_string(),
            _ => {
                let x = a as usize % lines.len().max(1);
                let mut ls = lines.clone();
                if !ls.is_empty() {
                    ls.remove(x);
                }
                ls.join("\n")
            }
        };
    }
    s
}

/// A session on the simulated RV-M1 whose output goes nowhere.
fn session() -> Session {
    let mut s = Session::new(Box::new(std::io::sink()));
    s.set_robot(
        adair::kinematics::RobotDescription::builtin("rv-m1").expect("robot"),
        None,
        false,
    );
    s
}

/// Runs what a user could: check, then (when it checks, and it touches no
/// files) run on the simulator, interrupted after a second of work, on the
/// command line's 512 MiB stack.
fn exercise(src: String) -> bool {
    let touches_files = ["Save", "Load", "Create", "Open", "Delete_File"]
        .iter()
        .any(|w| src.contains(w));
    std::thread::Builder::new()
        .stack_size(512 << 20)
        .spawn(move || {
            let mut s = session();
            let Ok((stmts, main)) = s.check_source("fuzz.air", &src, false) else {
                return false;
            };
            if touches_files {
                return false;
            }
            let stop = Arc::new(AtomicBool::new(false));
            s.machine.interrupted = Some(stop.clone());
            let done = Arc::new(Mutex::new(false));
            let watchdog = {
                let (stop, done) = (stop.clone(), done.clone());
                std::thread::spawn(move || {
                    for _ in 0..100 {
                        std::thread::sleep(std::time::Duration::from_millis(10));
                        if *done.lock().expect("lock") {
                            return;
                        }
                    }
                    stop.store(true, Ordering::SeqCst);
                })
            };
            let _ = s.run_checked(&stmts, main);
            s.machine.finish();
            *done.lock().expect("lock") = true;
            let _ = watchdog.join();
            true
        })
        .expect("thread")
        .join()
        .unwrap_or_else(|p| std::panic::resume_unwind(p))
}

fn cases() -> u32 {
    std::env::var("ADAIR_FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(300)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), ..ProptestConfig::default() })]

    #[test]
    fn mutated_corpus_programs_never_panic(
        pick in any::<u32>(),
        splice in any::<u32>(),
        muts in proptest::collection::vec((any::<u8>(), any::<u32>(), any::<u32>()), 1..6),
    ) {
        let c = corpus();
        let base = &c[pick as usize % c.len()];
        let other = &c[splice as usize % c.len()];
        let src = mutate(base, &muts, other);
        let shown = src.clone();
        let r = std::panic::catch_unwind(move || exercise(src));
        prop_assert!(r.is_ok(), "adair panicked on this input:\n{}", shown);
    }
}

/// The corpus is there and the programs in it check and run as written: a
/// fuzz run over an empty or broken corpus would test nothing.
#[test]
fn the_corpus_is_present_and_its_own_seeds_run() {
    assert!(corpus().len() > 100, "corpus: {} programs", corpus().len());
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fuzz/corpus");
    let mut seeds = Vec::new();
    collect(&dir, &mut seeds);
    assert!(seeds.len() >= 3);
    for seed in seeds {
        let mut s = session();
        let outcome = s.run_source("seed.air", &seed);
        assert_eq!(outcome.exit_code(), 0, "{outcome:?}\n{seed}");
    }
}

#[test]
fn mutations_change_the_text() {
    let src = "procedure P is\nbegin\n   null;\nend P;\n";
    let mut changed = 0;
    for kind in 0..8u8 {
        if mutate(src, &[(kind, 17, 5)], "X := 1;") != src {
            changed += 1;
        }
    }
    assert!(changed >= 7, "{changed} of 8 mutations changed the text");
}

/// Enough mutated programs still check that the interpreter is fuzzed too,
/// not only the front end.
#[test]
fn some_mutated_programs_reach_the_interpreter() {
    let c = corpus();
    let mut ran = 0;
    for i in 0..200u32 {
        let muts = [(i as u8, i.wrapping_mul(2_654_435_761), i)];
        let src = mutate(&c[i as usize % c.len()], &muts, &c[0]);
        if exercise(src) {
            ran += 1;
        }
    }
    assert!(ran >= 20, "only {ran} of 200 mutated programs ran");
}
