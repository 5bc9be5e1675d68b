//! The layers of `src/`, enforced (issue 38, item 3).
//!
//! Every `.rs` file under `src/` is read; each path that names another
//! top-level module of the crate is an arrow from the file's module to that
//! one: `use crate::interp::Machine;`, an inline `crate::interp::vm::Part`,
//! each member of a group `use crate::{check::Checker, diag}`, a chain of
//! `super::` that climbs to the crate root and down again, and in
//! `src/main.rs` (the binary) a path `adair::...`. Comments, string and
//! character literals are left out (a doc comment may name any module).
//!
//! The table below is the layering; ARCHITECTURE.md holds the same table,
//! word for word (`the_table_is_the_one_in_architecture_md`). A module may
//! use the modules on its row and, through them, every module those may
//! use (the rows' closure): `interp  check` lets the engine name `syntax`
//! (which `check` may use) but never `services`. An arrow to any other
//! module fails the test, which lists each one as `file:line: from -> to`.
//!
//! Test code obeys the layers too: a `#[cfg(test)]` module inside a file,
//! and a test-only file (`src/kinematics/tests/`, `src/services/tests/`),
//! belong to the module whose folder holds them. A test that needs a whole `Session` (the
//! stdlib, the builtins and services bound, a program run) is an
//! integration test in `tests/` (`tests/services/`, `tests/engine.rs`,
//! `tests/checker.rs`), outside the layers; a unit test inside a layer
//! builds what its layer has (a `Checker`, a `Machine`, a description
//! parsed from text). `src/lib.rs`, the crate root, only declares the
//! modules.
//!
//! Besides the arrows: `kinematics` does no I/O, its tests included (no
//! `std::fs`, `std::io`, `std::env`, `std::net`, `std::process`, `std::os`,
//! no printing): a robot description is parsed from a `&str`, and the file
//! is read above it (`services::read_robot_file`).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The layering: each module and the modules it may use (with, through
/// them, what those may use). Kept word for word in ARCHITECTURE.md.
const LAYERS: &str = "\
module      may use (and, through them, what they may use)
diag        nothing
work        nothing
kinematics  nothing (and no I/O)
devices     diag
syntax      diag, work
check       syntax, devices
interp      check
driver      kinematics
simctl      kinematics
services    interp, driver
plot        services
session     services
view        session, plot
golden      view
lsp         session
repl        view
main        golden, lsp, repl, simctl
";

/// Arrows against the table that are allowed for now, each as (from, to,
/// reason), with a `TODO(...)` comment naming the work that removes it.
/// An allowed arrow that no code takes any more fails the test: remove it
/// here. (None now: `diag -> interp`, `interp::STOPPED_TASKS`, went with
/// the typed diagnostic codes.)
const ALLOWED: &[(&str, &str, &str)] = &[];

/// The modules whose code does no I/O, tests included.
const NO_IO: &[&str] = &["kinematics"];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The table's rows: module -> the modules on its row.
fn rows() -> BTreeMap<String, Vec<String>> {
    let mut rows = BTreeMap::new();
    for line in LAYERS.lines().skip(1) {
        let (module, uses) = line.split_once(' ').expect("a row: module uses");
        let uses = uses.trim();
        let uses = if uses.starts_with("nothing") {
            Vec::new()
        } else {
            uses.split(", ").map(str::to_string).collect()
        };
        assert!(
            rows.insert(module.to_string(), uses).is_none(),
            "{module} has two rows"
        );
    }
    rows
}

/// What each module may use: the closure of its row.
fn allowed() -> BTreeMap<String, BTreeSet<String>> {
    let rows = rows();
    let mut out = BTreeMap::new();
    for m in rows.keys() {
        let mut seen = BTreeSet::new();
        let mut todo = rows[m].clone();
        while let Some(u) = todo.pop() {
            if seen.insert(u.clone()) {
                todo.extend(rows.get(&u).cloned().unwrap_or_default());
            }
        }
        out.insert(m.clone(), seen);
    }
    out
}

/// The top-level modules of `src/`: `x.rs` and `x/mod.rs` (and `main`).
fn modules() -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for e in std::fs::read_dir(root().join("src")).unwrap() {
        let p = e.unwrap().path();
        let name = p.file_stem().unwrap().to_string_lossy().to_string();
        if p.is_dir() || (p.extension().is_some_and(|x| x == "rs") && name != "lib") {
            out.insert(name);
        }
    }
    out
}

/// Every `.rs` file under `dir`, in order.
fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// `text` with comments, string literals and character literals blanked
/// out (newlines kept, so lines still count).
fn code_only(text: &str) -> String {
    let c: Vec<char> = text.chars().collect();
    let mut out: Vec<char> = Vec::with_capacity(c.len());
    let blank = |out: &mut Vec<char>, ch: char| out.push(if ch == '\n' { '\n' } else { ' ' });
    let ident = |ch: char| ch.is_alphanumeric() || ch == '_';
    let mut i = 0;
    while i < c.len() {
        let at = |k: usize| c.get(i + k).copied().unwrap_or('\0');
        if at(0) == '/' && at(1) == '/' {
            while i < c.len() && c[i] != '\n' {
                blank(&mut out, c[i]);
                i += 1;
            }
        } else if at(0) == '/' && at(1) == '*' {
            let mut depth = 0;
            loop {
                if i >= c.len() {
                    break;
                }
                if c[i] == '/' && c.get(i + 1) == Some(&'*') {
                    depth += 1;
                    blank(&mut out, ' ');
                    blank(&mut out, ' ');
                    i += 2;
                } else if c[i] == '*' && c.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    blank(&mut out, ' ');
                    blank(&mut out, ' ');
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    blank(&mut out, c[i]);
                    i += 1;
                }
            }
        } else if (at(0) == 'r' || (at(0) == 'b' && at(1) == 'r'))
            && !out.last().is_some_and(|&p| ident(p))
            && {
                let s = if at(0) == 'r' { 1 } else { 2 };
                let mut k = s;
                while at(k) == '#' {
                    k += 1;
                }
                at(k) == '"'
            }
        {
            // A raw string: r"..", r#".."#, br#".."#.
            let s = if at(0) == 'r' { 1 } else { 2 };
            let mut hashes = 0;
            while at(s + hashes) == '#' {
                hashes += 1;
            }
            for _ in 0..s + hashes + 1 {
                blank(&mut out, ' ');
            }
            i += s + hashes + 1;
            while i < c.len() {
                if c[i] == '"' && (1..=hashes).all(|k| c.get(i + k) == Some(&'#')) {
                    for _ in 0..hashes + 1 {
                        blank(&mut out, ' ');
                    }
                    i += hashes + 1;
                    break;
                }
                blank(&mut out, c[i]);
                i += 1;
            }
        } else if at(0) == '"' {
            blank(&mut out, ' ');
            i += 1;
            while i < c.len() && c[i] != '"' {
                if c[i] == '\\' {
                    blank(&mut out, ' ');
                    i += 1;
                }
                if i < c.len() {
                    blank(&mut out, c[i]);
                    i += 1;
                }
            }
            blank(&mut out, ' ');
            i += 1;
        } else if at(0) == '\'' && (at(1) == '\\' || (at(1) != '\0' && at(2) == '\'')) {
            // A character literal ('x', '\n', '\u{1F600}'), not a lifetime.
            blank(&mut out, ' ');
            i += 1;
            if c[i] == '\\' {
                // The backslash and the character it escapes.
                blank(&mut out, ' ');
                blank(&mut out, ' ');
                i += 2;
            }
            while i < c.len() && c[i] != '\'' {
                blank(&mut out, c[i]);
                i += 1;
            }
            blank(&mut out, ' ');
            i += 1;
        } else {
            out.push(c[i]);
            i += 1;
        }
    }
    out.into_iter().collect()
}

/// One path found in the code: its line, the word it starts with
/// (`crate`, `super`, `std`, `adair`), the number of `super`s, and the
/// first segment after them (or after the root).
#[derive(Debug)]
struct Found {
    line: usize,
    root: &'static str,
    supers: usize,
    /// How many inline `mod x { .. }` blocks are around it.
    inline: usize,
    first: String,
    text: String,
}

fn is_ident(ch: char) -> bool {
    ch.is_alphanumeric() || ch == '_'
}

/// Every path in `code` (already [`code_only`]) that starts with one of
/// `roots`: each member of a `{ .. }` group is one path.
fn paths(code: &str, roots: &[&'static str]) -> Vec<Found> {
    let c: Vec<char> = code.chars().collect();
    let mut out = Vec::new();
    // Brace depth, and the depths at which inline `mod x {` blocks opened.
    let mut depth = 0usize;
    let mut mods: Vec<usize> = Vec::new();
    let mut i = 0;
    let skip_ws = |mut k: usize| {
        while k < c.len() && c[k].is_whitespace() {
            k += 1;
        }
        k
    };
    let word_at = |k: usize| {
        let mut e = k;
        while e < c.len() && is_ident(c[e]) {
            e += 1;
        }
        (c[k..e].iter().collect::<String>(), e)
    };
    let line_of = |k: usize| 1 + c[..k].iter().filter(|&&x| x == '\n').count();
    while i < c.len() {
        let ch = c[i];
        if ch == '{' {
            depth += 1;
        }
        if ch == '}' {
            depth = depth.saturating_sub(1);
            while mods.last().is_some_and(|&d| d > depth) {
                mods.pop();
            }
        }
        if !is_ident(ch) || (i > 0 && (is_ident(c[i - 1]) || c[i - 1] == '$')) {
            i += 1;
            continue;
        }
        let (word, end) = word_at(i);
        if word == "mod" {
            let (name, e) = word_at(skip_ws(end));
            let k = skip_ws(e);
            if !name.is_empty() && c.get(k) == Some(&'{') {
                mods.push(depth + 1);
            }
        }
        let Some(&root) = roots.iter().find(|r| **r == word) else {
            i = end;
            continue;
        };
        // root (:: super)* :: (segment | { group })
        let mut k = skip_ws(end);
        if !(c.get(k) == Some(&':') && c.get(k + 1) == Some(&':')) {
            i = end;
            continue;
        }
        let mut supers = usize::from(root == "super");
        loop {
            k = skip_ws(k + 2);
            let (w, e) = word_at(k);
            let n = skip_ws(e);
            if w == "super" && c.get(n) == Some(&':') && c.get(n + 1) == Some(&':') {
                supers += 1;
                k = n;
                continue;
            }
            break;
        }
        // The path as written: up to the end of its group, or of its last
        // segment.
        let mut stop = (k..c.len())
            .find(|&e| !(is_ident(c[e]) || c[e] == ':'))
            .unwrap_or(c.len());
        if c.get(stop) == Some(&'{') {
            let mut d = 0;
            stop = (stop..c.len())
                .find(|&e| {
                    d += i32::from(c[e] == '{') - i32::from(c[e] == '}');
                    d == 0
                })
                .map_or(c.len(), |e| e + 1);
        }
        let text: String = c[i..stop].iter().collect();
        let text = text.split_whitespace().collect::<Vec<_>>().join(" ");
        let mut push = |first: String, at: usize| {
            out.push(Found {
                line: line_of(at),
                root,
                supers,
                inline: mods.len(),
                first,
                text: text.clone(),
            })
        };
        if c.get(k) == Some(&'{') {
            // A group: the first word of each member at depth 1.
            let mut d = 0;
            let mut e = k;
            let mut expect = true;
            while e < c.len() {
                match c[e] {
                    '{' => {
                        d += 1;
                        expect = d == 1;
                        e += 1;
                    }
                    '}' => {
                        d -= 1;
                        e += 1;
                        if d == 0 {
                            break;
                        }
                    }
                    ',' => {
                        expect = d == 1;
                        e += 1;
                    }
                    x if is_ident(x) && expect => {
                        let (w, we) = word_at(e);
                        push(w, e);
                        expect = false;
                        e = we;
                    }
                    _ => e += 1,
                }
            }
        } else {
            let (w, _) = word_at(k);
            if !w.is_empty() {
                push(w, k);
            }
        }
        i = k;
    }
    out
}

/// The module path of a file under `src/`: `check/ir.rs` -> [check, ir],
/// `check/mod.rs` -> [check], `main.rs` -> [main].
fn module_path(rel: &Path) -> Vec<String> {
    let mut parts: Vec<String> = rel
        .iter()
        .map(|s| s.to_string_lossy().to_string())
        .collect();
    let last = parts.pop().unwrap();
    if last != "mod.rs" {
        parts.push(last.trim_end_matches(".rs").to_string());
    }
    parts
}

/// One arrow: where, from which module, to which, and the path's text.
struct Arrow {
    at: String,
    from: String,
    to: String,
    text: String,
}

/// Every arrow in `src/` between two top-level modules.
fn arrows() -> Vec<Arrow> {
    let src = root().join("src");
    let mods = modules();
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let mut out = Vec::new();
    for f in files {
        let rel = f.strip_prefix(&src).unwrap().to_path_buf();
        if rel == Path::new("lib.rs") {
            continue;
        }
        let path = module_path(&rel);
        let from = path[0].clone();
        let code = code_only(&std::fs::read_to_string(&f).unwrap());
        // The binary names the library `adair`; its own `crate` is `main`.
        let roots: &[&'static str] = if from == "main" {
            &["adair"]
        } else {
            &["crate", "super"]
        };
        for p in paths(&code, roots) {
            let to = match p.root {
                "super" => {
                    // Inside `path` and `p.inline` inline modules: a chain
                    // of supers that climbs to the crate root names a
                    // top-level module next.
                    if p.supers == path.len() + p.inline {
                        p.first.clone()
                    } else {
                        continue;
                    }
                }
                _ => p.first.clone(),
            };
            if to == from || to == "self" || !mods.contains(&to) {
                continue;
            }
            out.push(Arrow {
                at: format!("src/{}:{}", rel.display(), p.line),
                from: from.clone(),
                to,
                text: p.text,
            });
        }
    }
    out
}

/// The table names every module of `src/`, each once, and only those; no
/// module reaches itself through the table (it is a layering).
#[test]
fn the_table_names_every_module_and_is_a_layering() {
    let rows = rows();
    let named: BTreeSet<String> = rows.keys().cloned().collect();
    assert_eq!(named, modules(), "the table's modules and src/'s");
    for (m, uses) in &rows {
        for u in uses {
            assert!(rows.contains_key(u), "{m} may use {u}, which is no module");
        }
    }
    for (m, reach) in allowed() {
        assert!(!reach.contains(&m), "{m} reaches itself through the table");
    }
}

/// The invariants ARCHITECTURE.md states hold in the table: an edit of the
/// table that breaks one fails here, not only in review.
#[test]
fn the_table_keeps_the_stated_invariants() {
    let may = allowed();
    let never = [
        // The checker is below the engine, the engine below the services.
        ("check", "interp"),
        ("interp", "services"),
        ("interp", "session"),
        ("services", "session"),
        // The language server never reaches the terminal REPL.
        ("lsp", "repl"),
        // The virtual controller is an oracle, not a copy of the driver.
        ("simctl", "driver"),
        ("simctl", "services"),
    ];
    for (from, to) in never {
        assert!(!may[from].contains(to), "{from} may reach {to}");
    }
    // Kinematics (no language), diag (the bottom) and work use nothing.
    for m in ["kinematics", "diag", "work"] {
        assert!(may[m].is_empty(), "{m} may use {:?}", may[m]);
    }
}

/// ARCHITECTURE.md states the same table, word for word.
#[test]
fn the_table_is_the_one_in_architecture_md() {
    let doc = std::fs::read_to_string(root().join("ARCHITECTURE.md")).unwrap();
    assert!(
        doc.contains(LAYERS),
        "ARCHITECTURE.md must hold the layering table of tests/layering.rs word for word:\n{LAYERS}"
    );
}

/// No arrow of `src/` goes against the table (but those in `ALLOWED`).
#[test]
fn every_arrow_follows_the_layers() {
    let allowed = allowed();
    let mut bad = Vec::new();
    let mut used = BTreeSet::new();
    let arrows = arrows();
    assert!(
        arrows.iter().any(|a| a.from == "interp" && a.to == "check"),
        "the scan finds the arrows (interp -> check, at least)"
    );
    for a in &arrows {
        if allowed[&a.from].contains(&a.to) {
            continue;
        }
        if let Some(x) = ALLOWED.iter().find(|x| x.0 == a.from && x.1 == a.to) {
            used.insert(x.0.to_string() + " -> " + x.1);
            continue;
        }
        bad.push(format!("{}: {} -> {} ({})", a.at, a.from, a.to, a.text));
    }
    for (from, to, why) in ALLOWED {
        let arrow = format!("{from} -> {to}");
        if !used.contains(&arrow) {
            bad.push(format!(
                "{arrow} is allowed ({why}) but no code takes it: remove it from ALLOWED"
            ));
        }
    }
    assert!(
        bad.is_empty(),
        "{} arrow(s) against the layering (tests/layering.rs, ARCHITECTURE.md):\n{}",
        bad.len(),
        bad.join("\n")
    );
}

/// The modules of `NO_IO` read no file, no environment, no network and
/// print nothing, their tests included.
#[test]
fn kinematics_does_no_io() {
    let mut bad = Vec::new();
    for m in NO_IO {
        let dir = root().join("src").join(m);
        let mut files = Vec::new();
        rust_files(&dir, &mut files);
        for f in files {
            let code = code_only(&std::fs::read_to_string(&f).unwrap());
            let rel = f.strip_prefix(root()).unwrap().display().to_string();
            for p in paths(&code, &["std"]) {
                if ["fs", "io", "env", "net", "process", "os"].contains(&p.first.as_str()) {
                    bad.push(format!("{rel}:{}: {}", p.line, p.text));
                }
            }
            for (n, l) in code.lines().enumerate() {
                for mac in ["print!", "println!", "eprint!", "eprintln!", "dbg!"] {
                    let hit = l
                        .match_indices(mac)
                        .any(|(k, _)| !l[..k].chars().next_back().is_some_and(is_ident));
                    if hit {
                        bad.push(format!("{rel}:{}: {mac}", n + 1));
                    }
                }
            }
        }
    }
    assert!(
        bad.is_empty(),
        "I/O in a module without I/O:\n{}",
        bad.join("\n")
    );
}

/// The scanner itself: groups, inline paths, supers, and what it leaves out.
#[test]
fn the_scan_reads_groups_inline_paths_and_skips_comments_and_strings() {
    let src = "use crate::{check::{Checker, ir}, diag};\n\
               // crate::repl in a comment\n\
               /* crate::lsp /* nested */ crate::view */\n\
               fn f<'a>(x: &'a str) -> char { let _ = \"crate::golden\"; let _ = r#\"crate::plot\"#; '{' }\n\
               type T = crate::interp::vm::Part;\n\
               mod inner { use super::super::session::Session; }\n\
               let q = '\\'';\n\
               use std::{fs, io::Write};\n";
    let code = code_only(src);
    let found = paths(&code, &["crate", "super", "std"]);
    let got: Vec<String> = found
        .iter()
        .map(|p| format!("{}:{}:{}:{}", p.line, p.root, p.supers, p.first))
        .collect();
    assert_eq!(
        got,
        [
            "1:crate:0:check",
            "1:crate:0:diag",
            "5:crate:0:interp",
            "6:super:2:session",
            "8:std:0:fs",
            "8:std:0:io"
        ],
        "{code}"
    );
    assert_eq!(found[3].inline, 1);
    assert_eq!(code.lines().count(), src.lines().count());
}
