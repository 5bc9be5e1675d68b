//! The editor package without npm: the TextMate grammar in `grammar/`
//! parses and highlights exactly the services of the table and the reserved
//! words of the lexer, and the VS Code extension's manifest is valid JSON
//! that points at that grammar.

use serde_json::Value;
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn json(path: &Path) -> Value {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The alternatives of a `(?i)\b(?:a|b|c)\b` pattern.
fn words(pattern: &str) -> BTreeSet<String> {
    let inner = pattern
        .strip_prefix("(?i)\\b(?:")
        .and_then(|p| p.strip_suffix(")\\b"))
        .unwrap_or_else(|| panic!("not a word list: {pattern}"));
    inner.split('|').map(str::to_string).collect()
}

fn grammar() -> Value {
    json(&root().join("grammar/adair.tmLanguage.json"))
}

#[test]
fn the_grammar_highlights_exactly_the_services_of_the_table_as_functions() {
    let g = grammar();
    assert_eq!(g["scopeName"], "source.adair");
    let svc = &g["repository"]["service"];
    assert_eq!(svc["name"], "support.function.service.adair");
    let in_grammar = words(svc["match"].as_str().unwrap());
    let in_table: BTreeSet<String> = adair::services::table::SERVICES
        .iter()
        .map(|s| s.name.to_string())
        .collect();
    assert_eq!(in_grammar, in_table);
    // Every repository entry is used by the top-level patterns.
    let used: BTreeSet<&str> = g["patterns"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["include"].as_str().unwrap().trim_start_matches('#'))
        .collect();
    let defined: BTreeSet<&str> = g["repository"]
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    assert_eq!(used, defined);
}

#[test]
fn the_grammar_knows_every_reserved_word_of_the_lexer() {
    let g = grammar();
    let mut in_grammar = BTreeSet::new();
    for group in ["control", "operator-word", "keyword"] {
        let w = words(g["repository"][group]["match"].as_str().unwrap());
        assert!(w.is_disjoint(&in_grammar), "{group} repeats a word");
        in_grammar.extend(w);
    }
    let in_lexer: BTreeSet<String> = adair::syntax::token::Kw::ALL
        .iter()
        .map(|(w, _)| w.to_string())
        .collect();
    assert_eq!(in_grammar, in_lexer);
}

#[test]
fn the_vscode_manifest_starts_the_server_and_references_the_grammar() {
    let dir = root().join("editors/vscode");
    let pkg = json(&dir.join("package.json"));
    let lang = &pkg["contributes"]["languages"][0];
    assert_eq!(lang["id"], "adair");
    assert_eq!(lang["extensions"][0], ".air");
    json(&dir.join(lang["configuration"].as_str().unwrap()));
    let gr = &pkg["contributes"]["grammars"][0];
    assert_eq!(gr["language"], "adair");
    assert_eq!(gr["scopeName"], grammar()["scopeName"]);
    let path = dir.join(gr["path"].as_str().unwrap());
    assert_eq!(
        path.canonicalize().unwrap(),
        root()
            .join("grammar/adair.tmLanguage.json")
            .canonicalize()
            .unwrap(),
        "the extension uses the grammar kept in grammar/, not a copy"
    );
    let main = std::fs::read_to_string(dir.join(pkg["main"].as_str().unwrap())).unwrap();
    assert!(
        main.contains("args: [\"lsp\"]"),
        "the client starts `adair lsp`"
    );
    assert!(pkg["dependencies"]["vscode-languageclient"].is_string());
}

/// The name a line's declaration gives, and its scope, as the grammar's
/// `declaration` patterns capture them (the first pattern that matches, as
/// a TextMate engine takes it).
fn declared(line: &str) -> Option<(String, String)> {
    let g = grammar();
    for p in g["repository"]["declaration"]["patterns"]
        .as_array()
        .unwrap()
    {
        let re = regex::Regex::new(p["match"].as_str().unwrap()).unwrap();
        if let Some(c) = re.captures(line) {
            let scope = p["captures"]["2"]["name"].as_str().unwrap();
            return Some((c[2].to_string(), scope.to_string()));
        }
    }
    None
}

#[test]
fn the_grammar_names_what_each_kind_of_declaration_declares() {
    let cases = [
        ("procedure Home;", "Home", "entity.name.function.adair"),
        (
            "procedure Feed (Id : Part_Id) renames Queue.Put;",
            "Feed",
            "entity.name.function.adair",
        ),
        (
            "function \"+\" (L, R : Pose) return Pose renames Add;",
            "",
            "",
        ),
        ("type Word is mod 2**16;", "Word", "entity.name.type.adair"),
        (
            "type Handle is limited private;",
            "Handle",
            "entity.name.type.adair",
        ),
        (
            "type Gripper (Kind : Tool_Kind := Vacuum) is record",
            "Gripper",
            "entity.name.type.adair",
        ),
        (
            "task type Cell (Id : Positive) is",
            "Cell",
            "entity.name.type.adair",
        ),
        ("task body Loader is", "Loader", "entity.name.type.adair"),
        (
            "protected type Buffer (Size : Positive) is",
            "Buffer",
            "entity.name.type.adair",
        ),
        ("PROTECTED BODY Queue is", "Queue", "entity.name.type.adair"),
        (
            "entry Slot (Station) (Part : out Part_Id) when Ready (Station) is",
            "Slot",
            "entity.name.function.adair",
        ),
        (
            "package body Cell_Io is",
            "Cell_Io",
            "entity.name.namespace.adair",
        ),
    ];
    for (line, name, scope) in cases {
        let got = declared(line);
        if name.is_empty() {
            assert_eq!(got, None, "{line}");
        } else {
            assert_eq!(got, Some((name.to_string(), scope.to_string())), "{line}");
        }
    }
}
