//! `adair lsp` through the real binary over standard input and output: the
//! framing (`Content-Length` headers) and what a hostile or broken client
//! can send (issue 35): a length too large to allocate, a message over the
//! server's bound, a document nested past the parser's limits. The server
//! must answer or end cleanly, never abort.

use serde_json::{Value, json};
use std::io::{BufRead, BufReader, Read, Write};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{Receiver, channel};
use std::time::Duration;

const WAIT: Duration = Duration::from_secs(60);

struct Server {
    child: Child,
    stdin: Option<ChildStdin>,
    /// Messages the server wrote, parsed, in order.
    out: Receiver<Value>,
    stderr: std::thread::JoinHandle<String>,
    dir: std::path::PathBuf,
}

fn frame(v: &Value) -> Vec<u8> {
    let body = v.to_string();
    let mut m = format!("Content-Length: {}\r\n\r\n", body.len()).into_bytes();
    m.extend(body.as_bytes());
    m
}

impl Server {
    /// Starts `adair lsp` (its stdlib copy in a folder of its own) and does
    /// the handshake.
    fn start(name: &str) -> Server {
        let dir =
            std::env::temp_dir().join(format!("adair-lsp-stdio-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let mut child = Command::new(env!("CARGO_BIN_EXE_adair"))
            .arg("lsp")
            .env("XDG_CACHE_HOME", &dir)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let stdout = child.stdout.take().unwrap();
        let (tx, out) = channel();
        std::thread::spawn(move || {
            let mut r = BufReader::new(stdout);
            loop {
                let mut len = None;
                loop {
                    let mut line = String::new();
                    if r.read_line(&mut line).unwrap_or(0) == 0 {
                        return;
                    }
                    let line = line.trim_end();
                    if line.is_empty() {
                        break;
                    }
                    if let Some(v) = line.strip_prefix("Content-Length: ") {
                        len = v.parse::<usize>().ok();
                    }
                }
                let mut body = vec![0; len.expect("a Content-Length")];
                if r.read_exact(&mut body).is_err() {
                    return;
                }
                if tx.send(serde_json::from_slice(&body).unwrap()).is_err() {
                    return;
                }
            }
        });
        let mut stderr = child.stderr.take().unwrap();
        let stderr = std::thread::spawn(move || {
            let mut s = String::new();
            let _ = stderr.read_to_string(&mut s);
            s
        });
        let stdin = child.stdin.take();
        let mut s = Server {
            child,
            stdin,
            out,
            stderr,
            dir,
        };
        s.send(&json!({"jsonrpc": "2.0", "id": 1, "method": "initialize",
            "params": {"capabilities": {}}}));
        s.response(1);
        s.send(&json!({"jsonrpc": "2.0", "method": "initialized", "params": {}}));
        s
    }

    fn send_raw(&mut self, bytes: &[u8]) {
        let _ = self.stdin.as_mut().unwrap().write_all(bytes);
        let _ = self.stdin.as_mut().unwrap().flush();
    }

    fn send(&mut self, v: &Value) {
        self.send_raw(&frame(v));
    }

    /// The next message the predicate takes (others are skipped).
    fn wait_for(&self, what: &str, mut take: impl FnMut(&Value) -> bool) -> Value {
        let end = std::time::Instant::now() + WAIT;
        loop {
            let left = end.saturating_duration_since(std::time::Instant::now());
            match self.out.recv_timeout(left) {
                Ok(m) if take(&m) => return m,
                Ok(_) => {}
                Err(_) => panic!("no {what} from the server"),
            }
        }
    }

    fn response(&self, id: i64) -> Value {
        self.wait_for(&format!("response {id}"), |m| m["id"] == id)
    }

    /// Shuts the server down: its exit status and standard error.
    fn finish(mut self) -> (Option<i32>, String) {
        self.send(&json!({"jsonrpc": "2.0", "id": 99, "method": "shutdown"}));
        self.response(99);
        self.send(&json!({"jsonrpc": "2.0", "method": "exit"}));
        self.end()
    }

    /// Closes the server's input and waits for it (killed after a minute).
    fn end(mut self) -> (Option<i32>, String) {
        drop(self.stdin.take());
        let start = std::time::Instant::now();
        let status = loop {
            if let Some(s) = self.child.try_wait().unwrap() {
                break s;
            }
            if start.elapsed() > WAIT {
                let _ = self.child.kill();
                panic!("the server did not end");
            }
            std::thread::sleep(Duration::from_millis(20));
        };
        let _ = std::fs::remove_dir_all(&self.dir);
        (status.code(), self.stderr.join().unwrap())
    }
}

fn open(uri: &str, text: &str) -> Value {
    json!({"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument":
        {"uri": uri, "languageId": "adair", "version": 1, "text": text}}})
}

/// A document of 400,000 `not` (and of `abs`, `-`) gets the "nesting too
/// deep" diagnostic; the server overflowed its stack and died with the
/// user's document open.
#[test]
fn a_unary_chain_past_the_limit_is_a_diagnostic_and_the_server_lives() {
    let mut s = Server::start("unary");
    for (k, (op, lit)) in [("not ", "True"), ("abs ", "1"), ("- ", "1")]
        .into_iter()
        .enumerate()
    {
        let uri = format!("file:///work/unary{k}.air");
        s.send(&open(
            &uri,
            &format!("X : constant := {}{lit};\n", op.repeat(400_000)),
        ));
        let d = s.wait_for("diagnostics", |m| {
            m["method"] == "textDocument/publishDiagnostics" && m["params"]["uri"] == uri.as_str()
        });
        let msgs: Vec<&str> = d["params"]["diagnostics"]
            .as_array()
            .unwrap()
            .iter()
            .filter_map(|d| d["message"].as_str())
            .collect();
        assert!(
            msgs.iter().any(|m| m.contains("nesting too deep")),
            "{op}: {msgs:?}"
        );
    }
    let (code, err) = s.finish();
    assert_eq!(code, Some(0), "{err}");
}

/// `Content-Length: 1000000000000` is refused as over the bound (said on
/// standard error), not allocated: the server aborted.
#[test]
fn a_huge_content_length_is_refused_not_allocated() {
    let mut s = Server::start("huge");
    s.send_raw(b"Content-Length: 1000000000000\r\n\r\n{\"jsonrpc\": \"2.0\"");
    let (code, err) = s.end();
    assert!(code.is_some(), "the server died of a signal: {err}");
    assert!(
        err.contains("1000000000000") && err.contains("64 MiB"),
        "say what was refused: {err}"
    );
}

/// A message over the bound (64 MiB) is skipped with an error logged (to
/// the client's log and standard error); the next message is answered.
#[test]
fn an_oversized_message_is_skipped_and_the_server_goes_on() {
    let mut s = Server::start("oversized");
    let n = (64 << 20) + 1;
    let mut big = format!("Content-Length: {n}\r\n\r\n").into_bytes();
    big.resize(big.len() + n, b' ');
    s.send_raw(&big);
    let log = s.wait_for("log message", |m| m["method"] == "window/logMessage");
    let text = log["params"]["message"].as_str().unwrap_or("");
    assert!(text.contains("64 MiB"), "{log}");
    let (code, err) = s.finish();
    assert_eq!(code, Some(0), "{err}");
}
