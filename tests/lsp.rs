//! `adair lsp` in process: one LSP session per feature (initialize,
//! didOpen, the requests, shutdown, exit) over `Connection::memory()`, the
//! server loop in a thread. Every test checks real contents: positions,
//! texts, names.

use adair::lsp::{self, Config};
use lsp_server::{Connection, Message, Notification, Request, RequestId, Response};
use lsp_types::notification::Notification as _;
use lsp_types::request::Request as _;
use lsp_types::{Position, Range, Uri};
use lsp_types::{notification as N, request as R};
use serde_json::{Value, json};
use std::path::PathBuf;
use std::str::FromStr;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::thread::JoinHandle;
use std::time::Duration;

const WAIT: Duration = Duration::from_secs(60);

struct Client {
    conn: Connection,
    server: Option<JoinHandle<Result<(), String>>>,
    next_id: i32,
    /// Notifications received while waiting for responses.
    pending: Vec<Notification>,
    stdlib_dir: PathBuf,
}

fn temp_dir() -> PathBuf {
    static N: AtomicUsize = AtomicUsize::new(0);
    let d = std::env::temp_dir().join(format!(
        "adair-lsp-test-{}-{}",
        std::process::id(),
        N.fetch_add(1, Ordering::SeqCst)
    ));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn uri(name: &str) -> Uri {
    Uri::from_str(&format!("file:///work/{name}")).unwrap()
}

impl Client {
    /// Queues the handshake and `before` (messages the server will find
    /// waiting when its loop starts), then starts the server.
    fn start_with(before: Vec<Message>) -> Client {
        Client::start_full(before, true)
    }

    /// As `start_with`; `snippets`: whether the client says it takes snippets.
    fn start_full(before: Vec<Message>, snippets: bool) -> Client {
        let (server_side, conn) = Connection::memory();
        let stdlib_dir = temp_dir();
        let mut c = Client {
            conn,
            server: None,
            next_id: 1,
            pending: Vec::new(),
            stdlib_dir: stdlib_dir.clone(),
        };
        let init = Request::new(
            RequestId::from(0),
            R::Initialize::METHOD.into(),
            json!({
                "capabilities": { "textDocument": { "completion": { "completionItem": { "snippetSupport": snippets } } } },
                "processId": null,
                "rootUri": null
            }),
        );
        c.conn.sender.send(init.into()).unwrap();
        c.conn
            .sender
            .send(Notification::new(N::Initialized::METHOD.into(), json!({})).into())
            .unwrap();
        for m in before {
            c.conn.sender.send(m).unwrap();
        }
        c.server = Some(std::thread::spawn(move || {
            lsp::run(
                &server_side,
                Config {
                    stdlib_dir: Some(stdlib_dir),
                    crash_request: true,
                },
            )
        }));
        match c.conn.receiver.recv_timeout(WAIT).unwrap() {
            Message::Response(r) => {
                assert_eq!(r.id, RequestId::from(0));
                let caps = &r.response_result.unwrap()["capabilities"];
                assert_eq!(caps["textDocumentSync"], json!(1), "full sync");
            }
            m => panic!("expected the initialize response, got {m:?}"),
        }
        c
    }

    fn start() -> Client {
        Client::start_with(Vec::new())
    }

    fn notify(&self, method: &str, params: Value) {
        self.conn
            .sender
            .send(Notification::new(method.into(), params).into())
            .unwrap();
    }

    fn open(&self, name: &str, text: &str) {
        open_uri(self, &uri(name), text);
    }

    fn change(&self, name: &str, version: i32, text: &str) {
        self.notify(
            N::DidChangeTextDocument::METHOD,
            change_params(name, version, text),
        );
    }

    /// Sends a request and waits for its response (keeping notifications).
    fn call(&mut self, method: &str, params: Value) -> Response {
        let id = RequestId::from(self.next_id);
        self.next_id += 1;
        self.conn
            .sender
            .send(Request::new(id.clone(), method.into(), params).into())
            .unwrap();
        loop {
            match self.conn.receiver.recv_timeout(WAIT).unwrap() {
                Message::Response(r) if r.id == id => return r,
                Message::Notification(n) => self.pending.push(n),
                m => panic!("unexpected {m:?}"),
            }
        }
    }

    fn result(&mut self, method: &str, params: Value) -> Value {
        let r = self.call(method, params);
        match r.response_result {
            Ok(v) => v,
            Err(e) => panic!("{method}: {e:?}"),
        }
    }

    /// The next diagnostics published for `name`.
    fn diagnostics(&mut self, name: &str) -> (Vec<lsp_types::Diagnostic>, Option<i32>) {
        self.diagnostics_at(&uri(name))
    }

    /// The next diagnostics published for the document `want`.
    fn diagnostics_at(&mut self, want: &Uri) -> (Vec<lsp_types::Diagnostic>, Option<i32>) {
        loop {
            let n = if self.pending.is_empty() {
                match self.conn.receiver.recv_timeout(WAIT).unwrap() {
                    Message::Notification(n) => n,
                    m => panic!("unexpected {m:?}"),
                }
            } else {
                self.pending.remove(0)
            };
            if n.method == N::PublishDiagnostics::METHOD {
                let p: lsp_types::PublishDiagnosticsParams =
                    serde_json::from_value(n.params).unwrap();
                if p.uri == *want {
                    return (p.diagnostics, p.version);
                }
            }
        }
    }

    /// shutdown, exit, and the server thread ends without error.
    fn finish(mut self) {
        let r = self.call(R::Shutdown::METHOD, Value::Null);
        assert!(r.response_result.is_ok());
        self.notify(N::Exit::METHOD, Value::Null);
        let server = self.server.take().unwrap();
        assert_eq!(server.join().unwrap(), Ok(()));
        let _ = std::fs::remove_dir_all(&self.stdlib_dir);
    }
}

fn change_params(name: &str, version: i32, text: &str) -> Value {
    json!({
        "textDocument": { "uri": uri(name), "version": version },
        "contentChanges": [ { "text": text } ]
    })
}

/// The position of the `n`th (0-based) occurrence of `needle` in `text`,
/// plus `plus` characters (ASCII texts only).
fn pos(text: &str, needle: &str, n: usize, plus: u32) -> Position {
    let at = text
        .match_indices(needle)
        .nth(n)
        .unwrap_or_else(|| panic!("`{needle}` #{n} not in the text"))
        .0;
    let line = text[..at].matches('\n').count() as u32;
    let col = (at - text[..at].rfind('\n').map_or(0, |i| i + 1)) as u32;
    Position::new(line, col + plus)
}

/// The range of the `n`th occurrence of `needle`.
fn range(text: &str, needle: &str, n: usize) -> Range {
    let p = pos(text, needle, n, 0);
    Range::new(p, Position::new(p.line, p.character + needle.len() as u32))
}

fn at(name: &str, p: Position) -> Value {
    json!({ "textDocument": { "uri": uri(name) }, "position": p })
}

const DEMO: &str = "\
with Ada.Text_IO; use Ada.Text_IO;
with AdaIR; use AdaIR;

procedure Demo is
   type Point is record
      X : Float;
      Y : Float;
   end record;
   Count : Integer := 0;
   P : Point := (X => 1.0, Y => 2.0);

   --  Doubles N.
   function Twice (N : Integer) return Integer is
   begin
      return N * 2;
   end Twice;

   procedure Move3 (A : Integer; B : Float; C : Integer) is
   begin
      Count := Count + A + C;
      P.X := B;
   end Move3;
begin
   InitRobot;
   Count := Twice (Count);
   P.X := P.Y;
   Move3 (1, 2.0, 3);
   MoveAxesAbsolute ((0.0, 0.5, 0.5, 0.0, 0.0));
   Put_Line (Integer'Image (Count));
end Demo;
";

fn demo() -> Client {
    let mut c = Client::start();
    c.open("demo.air", DEMO);
    let (d, _) = c.diagnostics("demo.air");
    assert!(d.is_empty(), "the demo checks: {d:?}");
    c
}

/// The outline (document symbols) of `demo.air`.
fn outline(c: &mut Client) -> Vec<lsp_types::DocumentSymbol> {
    let v = c.result(
        R::DocumentSymbolRequest::METHOD,
        json!({ "textDocument": { "uri": uri("demo.air") } }),
    );
    serde_json::from_value(v).unwrap()
}

fn hover_text(c: &mut Client, p: Position) -> (String, Option<Range>) {
    let v = c.result(R::HoverRequest::METHOD, at("demo.air", p));
    let h: lsp_types::Hover = serde_json::from_value(v).expect("a hover");
    let lsp_types::HoverContents::Markup(m) = h.contents else {
        panic!("markdown expected")
    };
    (m.value, h.range)
}

#[test]
fn diagnostics_on_open_and_change_are_the_checker_s_and_cleared_when_fixed() {
    let mut c = Client::start();
    let bad = DEMO.replace("Count := Twice (Count);", "Count := Twice (Countt);");
    c.open("demo.air", &bad);
    let (d, v) = c.diagnostics("demo.air");
    assert_eq!(v, Some(1));
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0].range, range(&bad, "Countt", 0));
    assert_eq!(
        d[0].message,
        "`Countt` is not declared\nHelp: did you mean `Count`?"
    );
    assert_eq!(d[0].severity, Some(lsp_types::DiagnosticSeverity::ERROR));
    // Its code, and a link to its `adair explain` page.
    assert_eq!(
        d[0].code,
        Some(lsp_types::NumberOrString::String("E0201".into()))
    );
    let href = d[0]
        .code_description
        .as_ref()
        .expect("a link")
        .href
        .as_str();
    assert!(
        href.starts_with("file://") && href.ends_with("/errors/E0201.md"),
        "{href}"
    );
    // The label is a related location at the same place.
    let rel = d[0].related_information.as_ref().unwrap();
    assert_eq!(rel[0].message, "undefined name");
    assert_eq!(rel[0].location.range, range(&bad, "Countt", 0));
    // The same message as the command line's.
    let mut s = adair::session::Session::new(Box::new(std::io::sink()));
    let cli = s.check_source("demo.air", &bad, false).unwrap_err();
    assert_eq!(cli[0].message, "`Countt` is not declared");
    assert_eq!(cli[0].hint.as_deref(), Some("did you mean `Count`?"));

    c.change("demo.air", 2, DEMO);
    let (d, v) = c.diagnostics("demo.air");
    assert_eq!(v, Some(2));
    assert!(d.is_empty(), "cleared when fixed: {d:?}");

    // A warning is a warning.
    let warn = DEMO.replace("   Count : Integer := 0;\n", "   Count : Integer := 0;\n   procedure Idle is\n      Unused : Integer;\n   begin\n      Unused := 1;\n   end Idle;\n");
    c.change("demo.air", 3, &warn);
    let (d, _) = c.diagnostics("demo.air");
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0].severity, Some(lsp_types::DiagnosticSeverity::WARNING));
    assert!(
        d[0].message.starts_with("variable `Unused` is never read"),
        "{}",
        d[0].message
    );
    assert_eq!(d[0].range, range(&warn, "Unused", 0));
    c.finish();
}

#[test]
fn diagnostics_carry_notes_as_related_locations() {
    let mut c = Client::start();
    let text = "procedure Main is\n   X : Integer := 1;\nbegin\n   case X is\n      when 1 => null;\n      when 1 => null;\n      when others => null;\n   end case;\nend Main;\n";
    c.open("notes.air", text);
    let (d, _) = c.diagnostics("notes.air");
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0].message, "this `case` choice is covered twice");
    assert_eq!(d[0].range.start, pos(text, "1 =>", 1, 0));
    let rel = d[0]
        .related_information
        .as_ref()
        .expect("related locations");
    assert_eq!(rel.len(), 1);
    assert_eq!(rel[0].message, "covered here already");
    assert_eq!(rel[0].location.uri, uri("notes.air"));
    assert_eq!(rel[0].location.range.start, pos(text, "1 =>", 0, 0));
    c.finish();
}

#[test]
fn an_edit_burst_is_checked_once_on_the_latest_text() {
    // The server finds the open and 50 changes waiting: one check, of the
    // last text, and one publication.
    let mut before = vec![Message::from(Notification::new(
        N::DidOpenTextDocument::METHOD.into(),
        json!({ "textDocument": { "uri": uri("burst.air"), "languageId": "adair", "version": 1, "text": "procedure" } }),
    ))];
    for v in 2..=51 {
        let text = if v == 51 {
            DEMO.to_string()
        } else {
            DEMO.replace(
                "Count := Twice (Count);",
                &format!("Count := Twice (X{v});"),
            )
        };
        before.push(
            Notification::new(
                N::DidChangeTextDocument::METHOD.into(),
                change_params("burst.air", v, &text),
            )
            .into(),
        );
    }
    let mut c = Client::start_with(before);
    let (d, v) = c.diagnostics("burst.air");
    assert_eq!(v, Some(51));
    assert!(d.is_empty(), "{d:?}");
    // Nothing else was published before the next answer.
    let r = c.call(
        R::DocumentSymbolRequest::METHOD,
        json!({ "textDocument": { "uri": uri("burst.air") } }),
    );
    assert!(r.response_result.is_ok());
    assert!(
        !c.pending
            .iter()
            .any(|n| n.method == N::PublishDiagnostics::METHOD),
        "{:?}",
        c.pending
    );
    c.finish();
}

#[test]
fn hover_on_a_service_shows_signature_code_meaning_and_exceptions_from_the_table() {
    let mut c = demo();
    let (text, r) = hover_text(&mut c, pos(DEMO, "MoveAxesAbsolute", 0, 3));
    let svc = adair::services::table::by_name("MoveAxesAbsolute").unwrap();
    assert!(
        text.contains("procedure MoveAxesAbsolute (Axes : AxesVector"),
        "{text}"
    );
    assert!(
        text.contains(&format!("command code {}", svc.code)),
        "{text}"
    );
    assert!(text.contains(svc.doc.lines().next().unwrap()), "{text}");
    assert!(text.contains("Raises: OutOfReach, TimeInvalid"), "{text}");
    assert_eq!(r, Some(range(DEMO, "MoveAxesAbsolute", 0)));
    let (text, _) = hover_text(&mut c, pos(DEMO, "InitRobot", 0, 0));
    assert!(text.contains("command code 150"), "{text}");
    c.finish();
}

#[test]
fn hover_on_a_modular_register_shows_its_type_s_declaration() {
    let src = "\
type Word is mod 2**16;
Status : Word := 0;
Status := (Status or 16#0004#) and not 16#0001#;
Put_Line (Word'Image (Status));
";
    let mut c = Client::start();
    c.open("demo.air", src);
    let (d, _) = c.diagnostics("demo.air");
    assert!(d.is_empty(), "a modular type checks: {d:?}");
    let p = pos(src, "Status or", 0, 1);
    let v = c.result(R::HoverRequest::METHOD, at("demo.air", p));
    let h: lsp_types::Hover = serde_json::from_value(v).expect("a hover");
    let lsp_types::HoverContents::Markup(m) = h.contents else {
        panic!("markdown expected")
    };
    assert!(m.value.contains("Status : Word"), "{}", m.value);
    assert!(m.value.contains("type Word is mod 2**16;"), "{}", m.value);
    c.finish();
}

#[test]
fn hover_on_a_variable_shows_its_type_and_on_a_type_its_definition() {
    let mut c = demo();
    let (text, r) = hover_text(&mut c, pos(DEMO, "Count := Twice", 0, 1));
    assert!(text.contains("Count : Integer"), "{text}");
    assert_eq!(r, Some(range(DEMO, "Count", 3)));
    let (text, _) = hover_text(&mut c, pos(DEMO, "P.X := P.Y", 0, 0));
    assert!(text.contains("P : Point"), "{text}");
    assert!(text.contains("type Point is record"), "{text}");
    let (text, _) = hover_text(&mut c, pos(DEMO, "P.X := P.Y", 0, 2));
    assert!(text.contains("X : Float"), "{text}");
    let (text, _) = hover_text(&mut c, pos(DEMO, "Point :=", 0, 1));
    assert!(
        text.contains("type Point is record\n   X : Float;\n   Y : Float;\nend record;"),
        "{text}"
    );
    // An expression that is not a name: its type.
    let (text, r) = hover_text(&mut c, pos(DEMO, "N * 2", 0, 2));
    assert!(text.contains("N * 2 : Integer"), "{text}");
    assert_eq!(r, Some(range(DEMO, "N * 2", 0)));
    let (text, _) = hover_text(&mut c, pos(DEMO, "(Count);", 0, 0));
    assert!(text.contains("Twice (Count) : Integer"), "{text}");
    // A user subprogram: its profile and the comment above it.
    let (text, _) = hover_text(&mut c, pos(DEMO, "Twice (Count)", 0, 0));
    assert!(
        text.contains("function Twice (N : Integer) return Integer"),
        "{text}"
    );
    assert!(text.contains("Doubles N."), "{text}");
    c.finish();
}

fn completion_at(c: &mut Client, name: &str, p: Position) -> Vec<lsp_types::CompletionItem> {
    let v = c.result(R::Completion::METHOD, at(name, p));
    match serde_json::from_value::<lsp_types::CompletionResponse>(v).unwrap() {
        lsp_types::CompletionResponse::Array(a) => a,
        lsp_types::CompletionResponse::List(l) => l.items,
    }
}

fn labels(items: &[lsp_types::CompletionItem]) -> Vec<String> {
    items.iter().map(|i| i.label.clone()).collect()
}

#[test]
fn completion_offers_keywords_services_names_in_scope_and_snippets() {
    let mut c = demo();
    // Inside Move3: its parameters are in scope; Twice's `N` is not.
    let items = completion_at(&mut c, "demo.air", pos(DEMO, "      P.X := B;", 0, 6));
    let l = labels(&items);
    for want in [
        "loop",
        "MoveAxesAbsolute",
        "Count",
        "Twice",
        "A",
        "C",
        "Put_Line",
        "InitRobot",
    ] {
        assert!(l.iter().any(|x| x == want), "{want} missing from {l:?}");
    }
    assert!(
        !l.iter().any(|x| x == "N"),
        "Twice's parameter is not visible here"
    );
    // Nor the parameter of a declaration without a body here.
    let text = DEMO.replace("   Count : Integer", "   procedure Later (Q : Integer);\n   procedure Later (Q : Integer) is begin null; end Later;\n   Count : Integer");
    c.change("demo.air", 2, &text);
    let (d, _) = c.diagnostics("demo.air");
    assert!(d.is_empty(), "{d:?}");
    let l = labels(&completion_at(
        &mut c,
        "demo.air",
        pos(&text, "   InitRobot;", 0, 3),
    ));
    assert!(
        l.iter().any(|x| x == "Later") && l.iter().any(|x| x == "Count"),
        "{l:?}"
    );
    assert!(!l.iter().any(|x| x == "Q" || x == "A" || x == "N"), "{l:?}");
    let l = labels(&completion_at(
        &mut c,
        "demo.air",
        pos(&text, "null; end Later", 0, 0),
    ));
    assert!(l.iter().any(|x| x == "Q"), "{l:?}");
    let items = completion_at(&mut c, "demo.air", pos(&text, "      P.X := B;", 0, 6));
    let svc = items
        .iter()
        .find(|i| i.label == "MoveAxesAbsolute")
        .unwrap();
    assert_eq!(svc.kind, Some(lsp_types::CompletionItemKind::FUNCTION));
    assert!(
        svc.detail
            .as_deref()
            .unwrap()
            .starts_with("procedure MoveAxesAbsolute (Axes")
    );
    let count = items.iter().find(|i| i.label == "Count").unwrap();
    assert_eq!(count.detail.as_deref(), Some("Integer"));
    for (label, body) in [
        ("for ... loop", "for ${1:I} in"),
        (
            "procedure ... is begin ... end",
            "procedure ${1:Name} is\nbegin",
        ),
        ("exception when ... =>", "exception\n   when ${1:E}"),
    ] {
        let s = items
            .iter()
            .find(|i| i.label == label)
            .unwrap_or_else(|| panic!("{label}"));
        assert_eq!(
            s.insert_text_format,
            Some(lsp_types::InsertTextFormat::SNIPPET)
        );
        assert!(s.insert_text.as_deref().unwrap().starts_with(body), "{s:?}");
    }
    c.finish();
}

#[test]
fn completion_of_record_fields_attributes_and_package_members() {
    let mut c = Client::start();
    // Half-typed: `P.` does not parse, the rest keeps its names.
    let text = DEMO.replace("   P.X := P.Y;\n", "   P.\n   Integer'\n   Ada.Text_IO.\n");
    c.open("t.air", &text);
    let _ = c.diagnostics("t.air");
    let items = completion_at(&mut c, "t.air", pos(&text, "   P.\n", 0, 5));
    assert_eq!(labels(&items), ["X", "Y"]);
    assert_eq!(items[0].detail.as_deref(), Some("Float"));
    let items = completion_at(&mut c, "t.air", pos(&text, "Integer'\n", 0, 8));
    let l = labels(&items);
    assert!(
        l.contains(&"First".to_string()) && l.contains(&"Image".to_string()),
        "{l:?}"
    );
    assert!(!l.contains(&"loop".to_string()));
    let items = completion_at(&mut c, "t.air", pos(&text, "Ada.Text_IO.\n", 0, 12));
    let l = labels(&items);
    assert!(l.contains(&"Put_Line".to_string()), "{l:?}");
    assert!(!l.contains(&"MoveAxesAbsolute".to_string()), "{l:?}");
    c.finish();
}

fn definition(c: &mut Client, p: Position) -> lsp_types::Location {
    let v = c.result(R::GotoDefinition::METHOD, at("demo.air", p));
    match serde_json::from_value::<lsp_types::GotoDefinitionResponse>(v).expect("a definition") {
        lsp_types::GotoDefinitionResponse::Scalar(l) => l,
        r => panic!("{r:?}"),
    }
}

#[test]
fn go_to_definition_of_subprograms_variables_and_types() {
    let mut c = demo();
    let l = definition(&mut c, pos(DEMO, "Twice (Count)", 0, 2));
    assert_eq!(l.uri, uri("demo.air"));
    assert_eq!(l.range, range(DEMO, "Twice", 0));
    let l = definition(&mut c, pos(DEMO, "Twice (Count)", 0, 8));
    assert_eq!(l.range, range(DEMO, "Count", 0));
    let l = definition(&mut c, pos(DEMO, "P : Point", 0, 5));
    assert_eq!(l.range, range(DEMO, "Point", 0));
    let l = definition(&mut c, pos(DEMO, "P.X := P.Y", 0, 9));
    assert_eq!(l.range, range(DEMO, "Y", 0), "a record component");
    let l = definition(&mut c, pos(DEMO, "Y => 2.0", 0, 0));
    assert_eq!(
        l.range,
        range(DEMO, "Y", 0),
        "a component named in an aggregate"
    );
    let l = definition(&mut c, pos(DEMO, "return N", 0, 7));
    assert_eq!(l.range.start, pos(DEMO, "N : Integer", 0, 0), "a parameter");
    assert_eq!(l.range.end, pos(DEMO, "N : Integer", 0, 1));
    c.finish();
}

/// Named associations refer to the parameter: of a user subprogram (its
/// references include them) and of a service (hover gives its type).
#[test]
fn named_associations_refer_to_their_parameters() {
    let text = DEMO.replace(
        "   Move3 (1, 2.0, 3);\n",
        "   Move3 (C => 3, A => 1, B => 2.0);\n   MoveTool (Distance => 20.0, Force => 5.0);\n",
    );
    let mut c = Client::start();
    c.open("n.air", &text);
    let (d, _) = c.diagnostics("n.air");
    assert!(d.is_empty(), "{d:?}");
    let v = c.result(
        R::References::METHOD,
        json!({ "textDocument": { "uri": uri("n.air") }, "position": pos(&text, "C : Integer", 0, 0), "context": { "includeDeclaration": true } }),
    );
    let locs: Vec<lsp_types::Location> = serde_json::from_value(v).unwrap();
    let got: Vec<Range> = locs.iter().map(|l| l.range).collect();
    // The declaration, the use in the body, the named association.
    let one = |needle: &str, plus: u32| {
        let p = pos(&text, needle, 0, plus);
        Range::new(p, Position::new(p.line, p.character + 1))
    };
    assert_eq!(
        got,
        vec![one("C : Integer", 0), one("+ C;", 2), one("C => 3", 0)]
    );
    let v = c.result(
        R::HoverRequest::METHOD,
        at("n.air", pos(&text, "Distance =>", 0, 2)),
    );
    let h: lsp_types::Hover = serde_json::from_value(v).expect("a hover on a named association");
    let lsp_types::HoverContents::Markup(m) = h.contents else {
        panic!()
    };
    assert!(m.value.contains("Distance : ToolDistance"), "{}", m.value);
    c.finish();
}

#[test]
fn go_to_definition_into_the_adair_package() {
    let mut c = demo();
    let l = definition(&mut c, pos(DEMO, "MoveAxesAbsolute", 0, 1));
    assert!(l.uri.as_str().ends_with("/adair.air"), "{}", l.uri.as_str());
    let path = PathBuf::from(l.uri.path().as_str());
    let file = std::fs::read_to_string(&path).expect("the stdlib file is written");
    let line = file.lines().nth(l.range.start.line as usize).unwrap();
    let name = &line[l.range.start.character as usize..l.range.end.character as usize];
    assert_eq!(name, "MoveAxesAbsolute");
    assert!(
        line.trim_start().starts_with("procedure MoveAxesAbsolute"),
        "{line}"
    );
    // A type of the package too.
    let text = "with AdaIR; use AdaIR;\nprocedure T is\n   F : Frame;\nbegin\n   null;\nend T;\n";
    c.open("t.air", text);
    let _ = c.diagnostics("t.air");
    let v = c.result(
        R::GotoDefinition::METHOD,
        at("t.air", pos(text, "Frame", 0, 1)),
    );
    let l: lsp_types::Location = serde_json::from_value(v).unwrap();
    let line = file.lines().nth(l.range.start.line as usize).unwrap();
    assert!(line.to_lowercase().contains("type frame"), "{line}");
    c.finish();
}

#[test]
fn find_references_of_a_variable_and_a_subprogram() {
    let mut c = demo();
    let v = c.result(
        R::References::METHOD,
        json!({ "textDocument": { "uri": uri("demo.air") }, "position": pos(DEMO, "Count", 2, 0), "context": { "includeDeclaration": true } }),
    );
    let locs: Vec<lsp_types::Location> = serde_json::from_value(v).unwrap();
    let got: Vec<Range> = locs.iter().map(|l| l.range).collect();
    let want: Vec<Range> = (0..6).map(|i| range(DEMO, "Count", i)).collect();
    assert_eq!(got, want);
    let v = c.result(
        R::References::METHOD,
        json!({ "textDocument": { "uri": uri("demo.air") }, "position": pos(DEMO, "Move3", 0, 0), "context": { "includeDeclaration": false } }),
    );
    let locs: Vec<lsp_types::Location> = serde_json::from_value(v).unwrap();
    let got: Vec<Range> = locs.iter().map(|l| l.range).collect();
    // `end Move3;` and the call.
    assert_eq!(got, vec![range(DEMO, "Move3", 1), range(DEMO, "Move3", 2)]);
    c.finish();
}

#[test]
fn document_symbols_give_the_outline() {
    let mut c = demo();
    let syms = outline(&mut c);
    assert_eq!(syms.len(), 1);
    assert_eq!(syms[0].name, "Demo");
    assert_eq!(syms[0].selection_range, range(DEMO, "Demo", 0));
    let kids: Vec<(&str, lsp_types::SymbolKind)> = syms[0]
        .children
        .as_ref()
        .unwrap()
        .iter()
        .map(|s| (s.name.as_str(), s.kind))
        .collect();
    use lsp_types::SymbolKind as K;
    assert_eq!(
        kids,
        [
            ("Point", K::STRUCT),
            ("Count", K::VARIABLE),
            ("P", K::VARIABLE),
            ("Twice", K::FUNCTION),
            ("Move3", K::METHOD)
        ]
    );
    let point = &syms[0].children.as_ref().unwrap()[0];
    let fields: Vec<&str> = point
        .children
        .as_ref()
        .unwrap()
        .iter()
        .map(|s| s.name.as_str())
        .collect();
    assert_eq!(fields, ["X", "Y"]);
    assert_eq!(point.range.start, pos(DEMO, "type Point", 0, 0));
    c.finish();
}

#[test]
fn signature_help_marks_the_active_parameter() {
    let mut c = Client::start();
    let text = DEMO.replace("   Move3 (1, 2.0, 3);\n", "   Move3 (1, 2.0, \n");
    c.open("s.air", &text);
    let _ = c.diagnostics("s.air");
    let v = c.result(
        R::SignatureHelpRequest::METHOD,
        at("s.air", pos(&text, "Move3 (1, 2.0, ", 0, 15)),
    );
    let h: lsp_types::SignatureHelp = serde_json::from_value(v).expect("signature help");
    assert_eq!(h.signatures.len(), 1);
    let s = &h.signatures[0];
    assert_eq!(s.label, "Move3 (A : Integer; B : Float; C : Integer)");
    assert_eq!(h.active_parameter, Some(2));
    let lsp_types::ParameterLabel::LabelOffsets([a, b]) = s.parameters.as_ref().unwrap()[2].label
    else {
        panic!()
    };
    assert_eq!(&s.label[a as usize..b as usize], "C : Integer");
    // A named association picks its parameter; a service brings its doc.
    let text2 = DEMO.replace("   Move3 (1, 2.0, 3);\n", "   MoveTool (Force => \n");
    c.change("s.air", 2, &text2);
    let _ = c.diagnostics("s.air");
    let v = c.result(
        R::SignatureHelpRequest::METHOD,
        at("s.air", pos(&text2, "Force => ", 0, 9)),
    );
    let h: lsp_types::SignatureHelp = serde_json::from_value(v).unwrap();
    let s = &h.signatures[h.active_signature.unwrap() as usize];
    let p = h.active_parameter.unwrap() as usize;
    let lsp_types::ParameterLabel::LabelOffsets([a, b]) = s.parameters.as_ref().unwrap()[p].label
    else {
        panic!()
    };
    assert!(
        s.label[a as usize..b as usize].starts_with("Force : "),
        "{}",
        s.label
    );
    assert!(s.documentation.is_some());
    c.finish();
}

#[test]
fn rename_a_local_name_and_refuse_others() {
    let mut c = demo();
    let v = c.result(
        R::Rename::METHOD,
        json!({ "textDocument": { "uri": uri("demo.air") }, "position": pos(DEMO, "Count", 4, 2), "newName": "Total" }),
    );
    let e: lsp_types::WorkspaceEdit = serde_json::from_value(v).unwrap();
    let edits = &e.changes.unwrap()[&uri("demo.air")];
    let got: Vec<Range> = edits.iter().map(|t| t.range).collect();
    assert_eq!(
        got,
        (0..6).map(|i| range(DEMO, "Count", i)).collect::<Vec<_>>()
    );
    assert!(edits.iter().all(|t| t.new_text == "Total"));
    // A service of the AdaIR package is not this file's to rename.
    let r = c.call(
        R::Rename::METHOD,
        json!({ "textDocument": { "uri": uri("demo.air") }, "position": pos(DEMO, "InitRobot", 0, 0), "newName": "Go" }),
    );
    assert!(r.response_result.unwrap_err().message.contains("adair.air"));
    let r = c.call(
        R::Rename::METHOD,
        json!({ "textDocument": { "uri": uri("demo.air") }, "position": pos(DEMO, "Count", 4, 2), "newName": "loop" }),
    );
    assert!(
        r.response_result
            .unwrap_err()
            .message
            .contains("not an Ada identifier")
    );
    // Not while the file has errors (a use that does not check is unknown).
    let bad = DEMO.replace("P.X := P.Y;", "P.X := P.Y + Count;");
    c.change("demo.air", 2, &bad);
    let (d, _) = c.diagnostics("demo.air");
    assert_eq!(d.len(), 1, "{d:?}");
    let r = c.call(
        R::Rename::METHOD,
        json!({ "textDocument": { "uri": uri("demo.air") }, "position": pos(&bad, "Count", 0, 0), "newName": "Total" }),
    );
    assert!(
        r.response_result
            .unwrap_err()
            .message
            .contains("the file has errors")
    );
    c.finish();
}

#[test]
fn half_typed_text_keeps_what_parses() {
    let mut c = Client::start();
    let text = DEMO.replace("   P.X := P.Y;\n", "   P.X := P.\n   if Count > then\n");
    c.open("h.air", &text);
    let (d, _) = c.diagnostics("h.air");
    assert!(!d.is_empty());
    let v = c.result(
        R::HoverRequest::METHOD,
        at("h.air", pos(&text, "Twice (Count)", 0, 8)),
    );
    let h: lsp_types::Hover = serde_json::from_value(v).expect("a hover on a name that checked");
    let lsp_types::HoverContents::Markup(m) = h.contents else {
        panic!()
    };
    assert!(m.value.contains("Count : Integer"), "{}", m.value);
    c.finish();
}

#[test]
fn a_panicking_request_gets_an_error_and_the_server_goes_on() {
    let mut c = demo();
    let r = c.call("adair/crash", Value::Null);
    let e = r.response_result.expect_err("an error reply");
    assert_eq!(e.code, lsp_server::ErrorCode::InternalError as i32);
    assert!(e.message.contains("adair/crash"), "{}", e.message);
    // Still serving.
    let (text, _) = hover_text(&mut c, pos(DEMO, "Count := Twice", 0, 1));
    assert!(text.contains("Count : Integer"));
    c.finish();
}

/// Every text of the fuzz corpus, the examples and the golden scripts, and
/// prefixes of each (text being typed), through the analysis and every
/// feature at many offsets: nothing panics, and the checker never does.
#[test]
fn analysis_and_features_never_panic_on_the_corpus_and_its_prefixes() {
    use adair::lsp::{analysis, complete, features};
    fn collect(dir: &std::path::Path, out: &mut Vec<(PathBuf, String)>) {
        let Ok(entries) = std::fs::read_dir(dir) else {
            return;
        };
        let mut paths: Vec<PathBuf> = entries.flatten().map(|e| e.path()).collect();
        paths.sort();
        for p in paths {
            if p.is_dir() {
                collect(&p, out);
            } else if p.extension().is_some_and(|e| e == "air")
                && let Ok(t) = std::fs::read_to_string(&p)
            {
                out.push((p, t));
            }
        }
    }
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut texts = Vec::new();
    for dir in ["tests/fuzz/corpus", "examples", "tests/golden"] {
        collect(&root.join(dir), &mut texts);
    }
    assert!(texts.len() > 100, "the corpus is there");
    let base = analysis::Base::new(None);
    // `ADAIR_LSP_CUTS=N`: cut each text into N prefixes (8 by default).
    let parts: usize = std::env::var("ADAIR_LSP_CUTS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(8)
        .max(1);
    let mut checked = 0;
    for (path, text) in &texts {
        let n = text.len();
        let mut cuts: Vec<usize> = (1..parts).map(|k| n * k / parts).collect();
        cuts.push(n);
        for cut in cuts {
            let mut cut = cut;
            while !text.is_char_boundary(cut) {
                cut -= 1;
            }
            let t = &text[..cut];
            let a = analysis::Analysis::new(
                &base,
                "t.air",
                None,
                t,
                std::rc::Rc::new(adair::session::Disk),
            );
            assert!(
                a.crashed.is_none(),
                "{}: the checker panicked on the first {cut} bytes: {:?}",
                path.display(),
                a.crashed
            );
            let mut off = 0;
            while off <= t.len() {
                let _ = features::hover(&a, off);
                let _ = features::definition(&a, off);
                let _ = features::references(&a, off, true);
                let _ = features::rename(&a, off, "Renamed");
                let _ = complete::completion(&a, off);
                let _ = complete::signature_help(&a, off);
                let p = a.lines.position(&a.text, off);
                if t.is_char_boundary(off) {
                    assert_eq!(
                        a.lines.offset(&a.text, p),
                        off,
                        "{}: offset {off}",
                        path.display()
                    );
                }
                off += 61;
            }
            let syms = features::symbols(&a);
            for s in &syms {
                let _ = features::to_document_symbol(&a.text, &a.lines, s);
            }
            checked += 1;
        }
    }
    assert!(checked > 800);
}

/// The binary over real standard input and output: the handshake, a
/// document with an error, its diagnostic, shutdown and exit with status 0.
#[test]
fn the_binary_serves_on_stdio() {
    use std::io::{BufRead, BufReader, Read, Write};
    let cache = temp_dir();
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_adair"))
        .arg("lsp")
        .env("XDG_CACHE_HOME", &cache)
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut input = child.stdin.take().unwrap();
    let mut output = BufReader::new(child.stdout.take().unwrap());
    let mut send = |v: Value| {
        let body = v.to_string();
        write!(input, "Content-Length: {}\r\n\r\n{body}", body.len()).unwrap();
        input.flush().unwrap();
    };
    let mut recv = || -> Value {
        let mut len = 0;
        loop {
            let mut line = String::new();
            output.read_line(&mut line).unwrap();
            let line = line.trim_end();
            if line.is_empty() {
                break;
            }
            if let Some(n) = line.strip_prefix("Content-Length: ") {
                len = n.parse().unwrap();
            }
        }
        let mut body = vec![0; len];
        output.read_exact(&mut body).unwrap();
        serde_json::from_slice(&body).unwrap()
    };
    send(
        json!({"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {}}}),
    );
    let r = recv();
    assert_eq!(r["id"], 1);
    assert_eq!(r["result"]["serverInfo"]["name"], "adair");
    send(json!({"jsonrpc": "2.0", "method": "initialized", "params": {}}));
    let text = "Put_Line (Undeclared_Thing);\n";
    send(
        json!({"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {"uri": "file:///tmp/x.air", "languageId": "adair", "version": 1, "text": text}}}),
    );
    let d = recv();
    assert_eq!(d["method"], "textDocument/publishDiagnostics");
    assert_eq!(
        d["params"]["diagnostics"][0]["message"],
        "`Undeclared_Thing` is not declared"
    );
    assert_eq!(
        d["params"]["diagnostics"][0]["range"]["start"],
        json!({"line": 0, "character": 10})
    );
    send(json!({"jsonrpc": "2.0", "id": 2, "method": "shutdown"}));
    assert_eq!(recv()["id"], 2);
    send(json!({"jsonrpc": "2.0", "method": "exit"}));
    drop(input);
    assert!(child.wait().unwrap().success());
    assert!(
        cache.join("adair").exists(),
        "the stdlib went to the cache directory"
    );
    let _ = std::fs::remove_dir_all(&cache);
}

/// An overloaded name goes to the declaration overload resolution chose.
#[test]
fn go_to_definition_picks_the_overload_the_checker_chose() {
    let text = "\
procedure Over is
   procedure Show (X : Integer) is begin null; end Show;
   procedure Show (X : Float) is begin null; end Show;
   function Half (X : Integer) return Integer is begin return X / 2; end Half;
   function Half (X : Float) return Float is begin return X / 2.0; end Half;
   I : Integer;
   F : Float;
begin
   Show (2.0);
   Show (1);
   I := Half (4);
   F := Half (4.0);
   Show (I + Integer (F));
end Over;
";
    let mut c = Client::start();
    c.open("o.air", text);
    let (d, _) = c.diagnostics("o.air");
    assert!(d.is_empty(), "{d:?}");
    let mut def = |needle: &str, n: usize| -> Range {
        let v = c.result(
            R::GotoDefinition::METHOD,
            at("o.air", pos(text, needle, n, 0)),
        );
        serde_json::from_value::<lsp_types::Location>(v)
            .unwrap()
            .range
    };
    // `Show` #0/#2 are the declarations of the Integer/Float versions
    // (#1/#3 their `end Show`).
    assert_eq!(def("Show (2.0)", 0), range(text, "Show", 2));
    assert_eq!(def("Show (1)", 0), range(text, "Show", 0));
    assert_eq!(def("Half (4)", 0), range(text, "Half", 0));
    assert_eq!(def("Half (4.0)", 0), range(text, "Half", 2));
    assert_eq!(def("Show (I", 0), range(text, "Show", 0));
    c.finish();
}

/// A client without snippet support gets no snippets; incremental changes
/// (sent although the server asks for full text) are applied.
#[test]
fn no_snippets_for_a_client_without_them_and_ranged_changes_apply() {
    let mut c = Client::start_full(Vec::new(), false);
    c.open("demo.air", DEMO);
    let _ = c.diagnostics("demo.air");
    let items = completion_at(&mut c, "demo.air", pos(DEMO, "      P.X := B;", 0, 6));
    assert!(items.iter().any(|i| i.label == "Count"));
    assert!(
        items
            .iter()
            .all(|i| i.insert_text_format != Some(lsp_types::InsertTextFormat::SNIPPET))
    );
    // Replace `Twice (Count)` by `Twice (Countt)`: an error at that place.
    let r = range(DEMO, "Count);", 0);
    c.notify(
        N::DidChangeTextDocument::METHOD,
        json!({
            "textDocument": { "uri": uri("demo.air"), "version": 2 },
            "contentChanges": [ { "range": { "start": r.start, "end": Position::new(r.start.line, r.start.character + 5) }, "text": "Countt" } ]
        }),
    );
    let (d, v) = c.diagnostics("demo.air");
    assert_eq!(v, Some(2));
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0].range.start, r.start);
    assert!(d[0].message.starts_with("`Countt` is not declared"));
    c.finish();
}

/// `exit` without `shutdown` ends the server with an error (the binary
/// then exits with status 1, as LSP asks).
#[test]
fn exit_without_shutdown_is_an_error() {
    let mut c = Client::start();
    c.notify(N::Exit::METHOD, Value::Null);
    let r = c.server.take().unwrap().join().unwrap();
    assert_eq!(r, Err("exit before shutdown".to_string()));
}

/// Hover on an AdaIR exception says when adair raises it; on a type of the
/// package, its declaration and the comment beside it.
#[test]
fn hover_on_an_exception_and_a_package_type() {
    let text = "with AdaIR; use AdaIR;\nprocedure E is\n   A : AxesVector := (others => 0.0);\nbegin\n   MoveAxesAbsolute (A);\nexception\n   when OutOfReach =>\n      null;\nend E;\n";
    let mut c = Client::start();
    c.open("e.air", text);
    let (d, _) = c.diagnostics("e.air");
    assert!(d.is_empty(), "{d:?}");
    let v = c.result(
        R::HoverRequest::METHOD,
        at("e.air", pos(text, "OutOfReach", 0, 2)),
    );
    let h: lsp_types::Hover = serde_json::from_value(v).unwrap();
    let lsp_types::HoverContents::Markup(m) = h.contents else {
        panic!()
    };
    assert!(m.value.contains("OutOfReach : exception"), "{}", m.value);
    assert!(
        m.value
            .contains("raised when the goal is outside the arm's reach"),
        "{}",
        m.value
    );
    let v = c.result(
        R::HoverRequest::METHOD,
        at("e.air", pos(text, "AxesVector", 0, 2)),
    );
    let h: lsp_types::Hover = serde_json::from_value(v).unwrap();
    let lsp_types::HoverContents::Markup(m) = h.contents else {
        panic!()
    };
    assert!(
        m.value
            .contains("type AxesVector is array (1 .. MaxJoint) of Float;"),
        "{}",
        m.value
    );
    assert!(m.value.contains("radians"), "{}", m.value);
    assert!(
        m.value.contains("declared in stdlib/adair.air"),
        "{}",
        m.value
    );
    c.finish();
}

#[test]
fn text_ending_in_a_half_typed_line_keeps_its_names() {
    // The whole text does not parse (it ends inside a declaration): what
    // comes before still gives hover, definition, symbols and completion.
    let mut c = Client::start();
    let text = "X : Integer := 3;\nT : ToolDescriptor;\nY : Integer := X + 1;\nZ : Float := T.";
    c.open("t.air", text);
    let (d, _) = c.diagnostics("t.air");
    assert_eq!(d.len(), 1, "only the syntax error: {d:?}");
    let v = c.result(
        R::HoverRequest::METHOD,
        at("t.air", pos(text, "X + 1", 0, 0)),
    );
    let h: lsp_types::Hover = serde_json::from_value(v).expect("a hover on X");
    let lsp_types::HoverContents::Markup(m) = h.contents else {
        panic!()
    };
    assert!(m.value.contains("X : Integer"), "{}", m.value);
    let v = c.result(
        R::GotoDefinition::METHOD,
        at("t.air", pos(text, "X + 1", 0, 0)),
    );
    let l = match serde_json::from_value::<lsp_types::GotoDefinitionResponse>(v)
        .expect("a definition")
    {
        lsp_types::GotoDefinitionResponse::Scalar(l) => l,
        r => panic!("{r:?}"),
    };
    assert_eq!(l.range.start.line, 0);
    let items = completion_at(&mut c, "t.air", pos(text, "T.", 0, 2));
    assert!(
        labels(&items)
            .iter()
            .any(|l| l.eq_ignore_ascii_case("CurrForce")),
        "the fields of ToolDescriptor: {:?}",
        labels(&items)
    );
    c.finish();
}

#[test]
fn a_script_of_declarations_sees_the_adair_package_as_adair_check_does() {
    let mut c = Client::start();
    c.open(
        "s.air",
        "T : ToolDescriptor;\nF : Frame := Trans (0.0, 0.0, 1.0);\n",
    );
    let (d, _) = c.diagnostics("s.air");
    assert!(d.is_empty(), "{d:?}");
    c.finish();
}

/// The text of `uri` opened in the editor.
fn open_uri(c: &Client, uri: &Uri, text: &str) {
    c.notify(
        N::DidOpenTextDocument::METHOD,
        json!({ "textDocument": { "uri": uri, "languageId": "adair", "version": 1, "text": text } }),
    );
}

/// The next diagnostics published for `uri`.
fn diagnostics_of(c: &mut Client, uri: &Uri) -> Vec<lsp_types::Diagnostic> {
    c.diagnostics_at(uri).0
}

const GEO: &str = "package Geo is\n   function Answer return Integer;\nend Geo;\n\npackage body Geo is\n   function Answer return Integer is\n   begin\n      return 42;\n   end Answer;\nend Geo;\n";
const GEO_MAIN: &str = "with Ada.Text_IO; use Ada.Text_IO;\nwith Geo;\n\nprocedure Main is\nbegin\n   Put_Line (Integer'Image (Geo.Answer));\nend Main;\n";

/// Issue 38: the editor checks a program as `adair run` does, with the
/// packages it names from the files beside it, and an unsaved change to
/// such a file is seen by the program's diagnostics.
#[test]
fn a_with_ed_unit_beside_the_file_is_read_and_its_unsaved_changes_seen() {
    let dir = temp_dir();
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("geo.air"), GEO).unwrap();
    std::fs::write(dir.join("main.adb"), GEO_MAIN).unwrap();
    // The command line runs it.
    let mut s = adair::session::Session::new(Box::new(std::io::sink()));
    let main_path = dir.join("main.adb");
    assert!(
        s.check_source(&main_path.to_string_lossy(), GEO_MAIN, false)
            .is_ok()
    );
    let file_uri =
        |name: &str| Uri::from_str(&format!("file://{}", dir.join(name).display())).unwrap();
    let (main, geo) = (file_uri("main.adb"), file_uri("geo.air"));
    let mut c = Client::start();
    open_uri(&c, &main, GEO_MAIN);
    let d = diagnostics_of(&mut c, &main);
    assert!(
        d.is_empty(),
        "the program checks as on the command line: {d:?}"
    );
    // Hover on `Answer` knows the package's function.
    let p = pos(GEO_MAIN, "Answer", 0, 1);
    let v = c.result(
        R::HoverRequest::METHOD,
        json!({ "textDocument": { "uri": main }, "position": p }),
    );
    assert!(v.to_string().contains("Answer"), "{v}");
    // The package is opened and changed without saving: `Answer` is gone.
    open_uri(&c, &geo, GEO);
    assert!(diagnostics_of(&mut c, &geo).is_empty());
    // Opened, its text is the editor's: the program is checked again.
    assert!(diagnostics_of(&mut c, &main).is_empty());
    c.notify(
        N::DidChangeTextDocument::METHOD,
        json!({
            "textDocument": { "uri": geo, "version": 2 },
            "contentChanges": [ { "text": GEO.replace("Answer", "Reply") } ]
        }),
    );
    let d = diagnostics_of(&mut c, &main);
    assert_eq!(d.len(), 1, "{d:?}");
    assert!(
        d[0].message
            .starts_with("`Answer` is not declared in `Geo`"),
        "{}",
        d[0].message
    );
    assert_eq!(d[0].range, range(GEO_MAIN, "Answer", 0));
    // The disk still has the old text.
    assert_eq!(std::fs::read_to_string(dir.join("geo.air")).unwrap(), GEO);
    c.finish();
    let _ = std::fs::remove_dir_all(&dir);
}

const RENAMINGS: &str = "\
with Ada.Text_IO; use Ada.Text_IO;
with AdaIR; use AdaIR;

procedure Cell is
   type Pose is record
      X, Z : Float;
   end record;
   Tool : Pose := (X => 0.0, Z => 120.0);
   Tool_Tip : Float renames Tool.Z;
   Reach : exception renames OutOfReach;
   package IO renames Ada.Text_IO;

   procedure Move_To (Target : Pose) is
   begin
      Tool := Target;
   end Move_To;
   procedure Go (Goal : Pose) renames Move_To;
begin
   Tool_Tip := Tool_Tip - 20.0;
   Go (Tool);
   Go (Goal => Tool);
   Move_To (Target => Tool);
   IO.Put_Line (Float'Image (Tool_Tip));
exception
   when Reach => Put_Line (\"too far\");
   when OutOfReach => null;
end Cell;
";

/// A renaming: hover shows what it renames, a use of the new name goes to
/// the renaming (a use of the old one to the old declaration), and the
/// parts of the renamed name resolve.
#[test]
fn renamings_hover_and_go_to_definition() {
    let mut c = Client::start();
    c.open("demo.air", RENAMINGS);
    let (d, _) = c.diagnostics("demo.air");
    assert!(d.is_empty(), "the renamings check: {d:?}");
    let src = RENAMINGS;
    // Hover on a use of an object renaming: its declaration.
    let (text, _) = hover_text(&mut c, pos(src, "Tool_Tip :=", 0, 2));
    assert!(text.contains("Tool_Tip : Float renames Tool.Z;"), "{text}");
    // An exception renaming: its declaration and the renamed one's doc.
    let (text, _) = hover_text(&mut c, pos(src, "when Reach", 0, 6));
    assert!(
        text.contains("Reach : exception renames OutOfReach;"),
        "{text}"
    );
    assert!(
        text.contains("raised when the goal is outside the arm's reach"),
        "{text}"
    );
    let (text, _) = hover_text(&mut c, pos(src, "Go (Tool)", 0, 0));
    assert!(
        text.contains("procedure Go (Goal : Pose) renames Move_To;"),
        "{text}"
    );
    let (text, _) = hover_text(&mut c, pos(src, "IO.Put_Line", 0, 0));
    assert!(text.contains("package IO renames Ada.Text_IO;"), "{text}");
    // Go to definition: the renaming for its own name...
    let l = definition(&mut c, pos(src, "Tool_Tip - 20.0", 0, 1));
    assert_eq!(l.range, range(src, "Tool_Tip", 0));
    let l = definition(&mut c, pos(src, "when Reach", 0, 6));
    assert_eq!(l.range, range(src, "Reach", 0));
    let l = definition(&mut c, pos(src, "Go (Tool)", 0, 0));
    assert_eq!(l.range, range(src, "Go", 0));
    let l = definition(&mut c, pos(src, "IO.Put_Line", 0, 0));
    assert_eq!(l.range.start, pos(src, "IO renames", 0, 0));
    // ... and the renamed declaration for the old name and the renamed
    // name's parts.
    let l = definition(&mut c, pos(src, "Move_To (Target", 0, 1));
    assert_eq!(l.range, range(src, "Move_To", 0));
    let l = definition(&mut c, pos(src, "renames Move_To", 0, 9));
    assert_eq!(l.range, range(src, "Move_To", 0));
    let l = definition(&mut c, pos(src, "renames Tool.Z", 0, 9));
    assert_eq!(l.range, range(src, "Tool", 0));
    let l = definition(&mut c, pos(src, "Tool.Z;", 0, 5));
    assert_eq!(l.range, range(src, "Z", 0), "a record component");
    // Named association through the renaming: its own parameter name.
    let l = definition(&mut c, pos(src, "Goal => Tool", 0, 0));
    assert_eq!(l.range, range(src, "Goal", 0));
    // Completion offers the renamings, and a renamed package's names.
    let l = labels(&completion_at(
        &mut c,
        "demo.air",
        pos(src, "   Go (Tool);", 0, 3),
    ));
    for want in ["Tool_Tip", "Reach", "IO", "Go", "Move_To"] {
        assert!(l.iter().any(|x| x == want), "{want} missing from {l:?}");
    }
    let text = src.replace("   Go (Tool);\n", "   Go (Tool);\n   IO.\n");
    c.change("demo.air", 2, &text);
    let _ = c.diagnostics("demo.air");
    let l = labels(&completion_at(
        &mut c,
        "demo.air",
        pos(&text, "   IO.\n", 0, 6),
    ));
    assert!(l.iter().any(|x| x == "Put_Line"), "{l:?}");
    c.change("demo.air", 3, src);
    let _ = c.diagnostics("demo.air");
    // The outline shows each renaming and what it renames.
    let syms = outline(&mut c);
    let kids: Vec<(String, Option<String>)> = syms[0]
        .children
        .as_ref()
        .unwrap()
        .iter()
        .map(|s| (s.name.clone(), s.detail.clone()))
        .collect();
    for (name, detail) in [
        ("Tool_Tip", "Float renames Tool.Z"),
        ("Reach", "renames OutOfReach"),
        ("IO", "renames Ada.Text_IO"),
        ("Go", "renames Move_To"),
    ] {
        assert!(
            kids.iter()
                .any(|(n, d)| n == name && d.as_deref() == Some(detail)),
            "{name}: {kids:?}"
        );
    }
    c.finish();
}

const PRIVATE_TYPES: &str = "\
with Ada.Text_IO; use Ada.Text_IO;

procedure Cell is
   package Axes is
      type Axis_Handle is private;
      type Gripper is limited private;
      Home : constant Axis_Handle;
      function Make (Joint : Positive) return Axis_Handle;
      procedure Close (G : in out Gripper);
   private
      type Axis_Handle is record
         Joint : Positive := 1;
         Angle : Float := 0.0;
      end record;
      type Gripper is record
         Closed : Boolean := False;
      end record;
      Home : constant Axis_Handle := (Joint => 1, Angle => 0.0);
   end Axes;

   package body Axes is
      function Make (Joint : Positive) return Axis_Handle is
         H : Axis_Handle;
      begin
         H.Joint := Joint;
         return H;
      end Make;
      procedure Close (G : in out Gripper) is
      begin
         G.Closed := True;
      end Close;
   end Axes;

   use Axes;
   Shoulder : Axis_Handle := Make (2);
   Hand : Gripper;
begin
   Close (Hand);
   if Shoulder = Home then
      Put_Line (\"home\");
   end if;
end Cell;
";

/// Private types in the tools: hover on the type shows its partial view
/// (not the full declaration), go to definition goes there from a client
/// and from the full declaration, a deferred constant hovers as a
/// constant, completion after a dot offers the components inside the
/// package only, and the outline lists both views.
#[test]
fn private_types_in_hover_definition_completion_and_outline() {
    let mut c = Client::start();
    c.open("demo.air", PRIVATE_TYPES);
    let (d, _) = c.diagnostics("demo.air");
    assert!(d.is_empty(), "the private types check: {d:?}");
    let src = PRIVATE_TYPES;
    // Hover on a client's use of the type: its partial view.
    let (text, _) = hover_text(&mut c, pos(src, "Axis_Handle := Make", 0, 1));
    assert!(text.contains("type Axis_Handle is private;"), "{text}");
    assert!(!text.contains("Angle"), "the full view is hidden: {text}");
    let (text, _) = hover_text(&mut c, pos(src, "Hand : Gripper", 0, 8));
    assert!(text.contains("type Gripper is limited private;"), "{text}");
    // On an object of it: its type, and the type's partial view.
    let (text, _) = hover_text(&mut c, pos(src, "Close (Hand)", 0, 8));
    assert!(text.contains("Hand : Gripper"), "{text}");
    assert!(text.contains("type Gripper is limited private;"), "{text}");
    // A deferred constant.
    let (text, _) = hover_text(&mut c, pos(src, "= Home", 0, 3));
    assert!(text.contains("Home : constant Axis_Handle"), "{text}");
    // Go to definition: the partial view, from a client and from the
    // full declaration's name.
    let l = definition(&mut c, pos(src, "Axis_Handle := Make", 0, 1));
    assert_eq!(l.range, range(src, "Axis_Handle", 0));
    let l = definition(&mut c, pos(src, "type Axis_Handle is record", 0, 6));
    assert_eq!(l.range, range(src, "Axis_Handle", 0));
    let l = definition(&mut c, pos(src, "= Home", 0, 3));
    assert_eq!(l.range, range(src, "Home", 0));
    // A component inside the body goes to the full declaration's.
    let l = definition(&mut c, pos(src, "H.Joint", 0, 3));
    assert_eq!(l.range, range(src, "Joint", 1));
    // Completion after a dot: the components inside the package...
    let inside = src.replace("H.Joint := Joint;", "H.Joint := Joint;\n         H.");
    c.change("demo.air", 2, &inside);
    let _ = c.diagnostics("demo.air");
    let l = labels(&completion_at(
        &mut c,
        "demo.air",
        pos(&inside, "H.\n", 0, 2),
    ));
    assert!(l.iter().any(|x| x == "Angle"), "{l:?}");
    // ... none in a client.
    let outside = src.replace("   end if;\nend Cell", "   end if;\n   Shoulder.\nend Cell");
    c.change("demo.air", 3, &outside);
    let _ = c.diagnostics("demo.air");
    let l = labels(&completion_at(
        &mut c,
        "demo.air",
        pos(&outside, "Shoulder.\n", 0, 9),
    ));
    assert!(!l.iter().any(|x| x == "Angle" || x == "Joint"), "{l:?}");
    c.change("demo.air", 4, src);
    let _ = c.diagnostics("demo.air");
    // The outline: the package lists the partial views and the full
    // declarations.
    let syms = outline(&mut c);
    let pkg = syms[0]
        .children
        .as_ref()
        .unwrap()
        .iter()
        .find(|s| s.name == "Axes")
        .expect("the package in the outline");
    let kids: Vec<(String, Option<String>)> = pkg
        .children
        .as_ref()
        .unwrap()
        .iter()
        .map(|s| (s.name.clone(), s.detail.clone()))
        .collect();
    for (name, detail) in [
        ("Axis_Handle", "private type"),
        ("Gripper", "limited private type"),
        ("Axis_Handle", "type"),
        ("Home", "Axis_Handle"),
    ] {
        assert!(
            kids.iter()
                .any(|(n, d)| n == name && d.as_deref() == Some(detail)),
            "{name}: {kids:?}"
        );
    }
    c.finish();
}

const PRIVATE_DISCRIMINANTS: &str = "\
with Ada.Text_IO; use Ada.Text_IO;

procedure Cell is
   package Samples is
      type Buffer (Size : Positive) is private;
      function Make (N : Positive) return Buffer;
   private
      type Buffer (Size : Positive) is record
         Count : Natural := 0;
      end record;
   end Samples;

   package body Samples is
      function Make (N : Positive) return Buffer is ((Size => N, Count => 0));
   end Samples;

   use Samples;
   Trace : Buffer (8);
begin
   Trace := Make (8);
   Put_Line (Positive'Image (Trace.Size));
end Cell;
";

/// A private type with discriminants: hover on a client's use shows the
/// partial view with its discriminant part; a discriminant read outside
/// the package goes to the partial view's, which the full declaration's
/// names too; completion after a dot outside offers the discriminants
/// only.
#[test]
fn private_type_discriminants_in_hover_definition_and_completion() {
    let mut c = Client::start();
    c.open("demo.air", PRIVATE_DISCRIMINANTS);
    let (d, _) = c.diagnostics("demo.air");
    assert!(d.is_empty(), "the program checks: {d:?}");
    let src = PRIVATE_DISCRIMINANTS;
    let (text, _) = hover_text(&mut c, pos(src, "Buffer (8)", 0, 1));
    assert!(
        text.contains("type Buffer (Size : Positive) is private;"),
        "{text}"
    );
    assert!(!text.contains("Count"), "the full view is hidden: {text}");
    let (text, _) = hover_text(&mut c, pos(src, "Trace.Size", 0, 7));
    assert!(text.contains("Size : Positive"), "{text}");
    let l = definition(&mut c, pos(src, "Trace.Size", 0, 7));
    assert_eq!(l.range, range(src, "Size", 0));
    let l = definition(&mut c, pos(src, "Size : Positive) is record", 0, 1));
    assert_eq!(l.range, range(src, "Size", 0));
    let outside = src.replace("Trace.Size));", "Trace.Size));\n   Trace.");
    c.change("demo.air", 2, &outside);
    let _ = c.diagnostics("demo.air");
    let l = labels(&completion_at(
        &mut c,
        "demo.air",
        pos(&outside, "Trace.\n", 0, 6),
    ));
    assert!(l.iter().any(|x| x == "Size"), "{l:?}");
    assert!(!l.iter().any(|x| x == "Count"), "{l:?}");
    c.finish();
}

const CELL: &str = "\
with Ada.Text_IO; use Ada.Text_IO;

procedure Cell is
   type Station is range 1 .. 3;
   type Word is mod 2**16;

   --  The part buffer of the three stations.
   protected Loader is
      entry Load (Station) (Part : Natural);
      entry Retry (Part : Natural);
      function Total return Natural;
   private
      Sum : Natural := 0;
   end Loader;

   protected body Loader is
      entry Load (for S in Station) (Part : Natural) when S /= 2 is
      begin
         Sum := Sum + Part;
      end Load;
      entry Retry (Part : Natural) when True is
      begin
         requeue Load (1);
      end Retry;
      function Total return Natural is
      begin
         return Sum;
      end Total;
   end Loader;

   task Press is
      entry Stroke (Station) (Force : Word);
   end Press;

   task body Press is
   begin
      accept Stroke (1) (Force : Word) do
         Put_Line (Word'Image (Force));
      end Stroke;
   end Press;

   procedure Load_Last (Part : Natural) renames Loader.Load (3);
begin
   Loader.Load (1) (10);
   Load_Last (5);
   Press.Stroke (1) (16#FF#);
   Put_Line (Natural'Image (Loader.Total));
end Cell;
";

/// Tasks, protected objects, entry families and `requeue`: hover, go to
/// definition, completion after the object's name, and the outline.
#[test]
fn entry_families_and_requeue_in_hover_definition_completion_and_outline() {
    let mut c = Client::start();
    c.open("demo.air", CELL);
    let (d, _) = c.diagnostics("demo.air");
    assert!(d.is_empty(), "the cell checks: {d:?}");
    let src = CELL;
    // Hover on a call of a family member: the entry's declaration.
    let (text, _) = hover_text(&mut c, pos(src, "Load (1) (10)", 0, 1));
    assert!(
        text.contains("entry Load (Station) (Part : Natural)"),
        "{text}"
    );
    let (text, _) = hover_text(&mut c, pos(src, "Stroke (1) (16#FF#)", 0, 1));
    assert!(
        text.contains("entry Stroke (Station) (Force : Word)"),
        "{text}"
    );
    let (text, _) = hover_text(&mut c, pos(src, "Loader.Load (1) (10)", 0, 1));
    assert!(text.contains("protected Loader"), "{text}");
    // Go to definition: of the entry from a call, from `requeue` and
    // from the renaming; of the protected object and the task.
    let load = {
        let p = pos(src, "entry Load", 0, 6);
        Range::new(p, Position::new(p.line, p.character + 4))
    };
    let l = definition(&mut c, pos(src, "Load (1) (10)", 0, 1));
    assert_eq!(l.range, load);
    let l = definition(&mut c, pos(src, "requeue Load", 0, 9));
    assert_eq!(l.range, load);
    let l = definition(&mut c, pos(src, "Loader.Load (3)", 0, 8));
    assert_eq!(l.range, load);
    let l = definition(&mut c, pos(src, "Press.Stroke (1)", 0, 1));
    assert_eq!(l.range, range(src, "Press", 0));
    let l = definition(&mut c, pos(src, "Load_Last (5)", 0, 1));
    assert_eq!(l.range, range(src, "Load_Last", 0));
    // Completion after the protected object's name: its operations.
    let text = src.replace("   Load_Last (5);\n", "   Load_Last (5);\n   Loader.\n");
    c.change("demo.air", 2, &text);
    let _ = c.diagnostics("demo.air");
    let l = labels(&completion_at(
        &mut c,
        "demo.air",
        pos(&text, "   Loader.\n", 0, 10),
    ));
    for want in ["Load", "Retry", "Total"] {
        assert!(l.iter().any(|x| x == want), "{want} missing from {l:?}");
    }
    c.change("demo.air", 3, src);
    let _ = c.diagnostics("demo.air");
    // The outline: the protected object and the task with their entries.
    let syms = outline(&mut c);
    let kids = syms[0].children.as_ref().unwrap();
    let names = |s: &lsp_types::DocumentSymbol| -> Vec<String> {
        s.children
            .iter()
            .flatten()
            .map(|k| k.name.clone())
            .collect()
    };
    let loader = kids.iter().find(|s| s.name == "Loader").expect("Loader");
    let press = kids.iter().find(|s| s.name == "Press").expect("Press");
    for want in ["Load", "Retry", "Total"] {
        assert!(
            names(loader).iter().any(|x| x == want),
            "{:?}",
            names(loader)
        );
    }
    assert!(
        names(press).iter().any(|x| x == "Stroke"),
        "{:?}",
        names(press)
    );
    assert!(
        kids.iter().any(|s| s.name == "Load_Last"),
        "{:?}",
        kids.iter().map(|s| &s.name).collect::<Vec<_>>()
    );
    c.finish();
}

/// A discriminant of a task or protected type, named in a constraint or
/// selected from an object, goes to its declaration in the discriminant part.
#[test]
fn go_to_definition_of_task_and_protected_discriminants() {
    let src = "\
task type Axis_Controller (Axis : Positive) is
   entry Go;
end Axis_Controller;
task body Axis_Controller is
begin
   accept Go;
end Axis_Controller;
protected type Part_Buffer (Size : Positive) is
   function Free return Natural;
end Part_Buffer;
protected body Part_Buffer is
   function Free return Natural is
   begin
      return Size;
   end Free;
end Part_Buffer;
Shoulder : Axis_Controller (Axis => 2);
Belt : Part_Buffer (Size => 3);
Put_Line (Positive'Image (Shoulder.Axis) & Positive'Image (Belt.Size));
Shoulder.Go;
";
    let mut c = Client::start();
    c.open("demo.air", src);
    let (d, _) = c.diagnostics("demo.air");
    assert!(
        d.is_empty(),
        "task and protected discriminants check: {d:?}"
    );
    let axis = range(src, "Axis :", 0);
    let axis = Range::new(
        axis.start,
        Position::new(axis.start.line, axis.start.character + 4),
    );
    let size = range(src, "Size :", 0);
    let size = Range::new(
        size.start,
        Position::new(size.start.line, size.start.character + 4),
    );
    let l = definition(&mut c, pos(src, "Shoulder.Axis", 0, 10));
    assert_eq!(
        l.range, axis,
        "a task's discriminant selected from an object"
    );
    let l = definition(&mut c, pos(src, "Axis => 2", 0, 1));
    assert_eq!(l.range, axis, "named in a constraint");
    let l = definition(&mut c, pos(src, "Belt.Size", 0, 6));
    assert_eq!(l.range, size, "a protected object's discriminant");
    let l = definition(&mut c, pos(src, "Size => 3", 0, 1));
    assert_eq!(l.range, size, "named in a constraint");
    c.finish();
}
