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
        Server::start_env(name, |cmd, dir| {
            cmd.env("XDG_CACHE_HOME", dir);
        })
    }

    /// As `start`, with `env` setting the server's environment (given the
    /// test's own folder).
    fn start_env(name: &str, env: impl FnOnce(&mut Command, &std::path::Path)) -> Server {
        let dir =
            std::env::temp_dir().join(format!("adair-lsp-stdio-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let mut cmd = Command::new(env!("CARGO_BIN_EXE_adair"));
        env(&mut cmd, &dir);
        let mut child = cmd
            .arg("lsp")
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

/// The file "go to definition" of `InitRobot` opens (the server's copy of
/// the AdaIR package).
fn adair_package_file(s: &mut Server) -> std::path::PathBuf {
    let uri = "file:///work/def.air";
    s.send(&open(uri, "InitRobot;\n"));
    s.send(
        &json!({"jsonrpc": "2.0", "id": 7, "method": "textDocument/definition",
        "params": {"textDocument": {"uri": uri}, "position": {"line": 0, "character": 3}}}),
    );
    let r = s.response(7);
    let loc = if r["result"].is_array() {
        r["result"][0].clone()
    } else {
        r["result"].clone()
    };
    let target = loc["uri"].as_str().unwrap_or_else(|| panic!("{r}"));
    std::path::PathBuf::from(target.strip_prefix("file://").unwrap())
}

/// The user id of this process (of a file it creates).
fn my_uid() -> u32 {
    use std::os::unix::fs::MetadataExt;
    let probe = std::env::temp_dir().join(format!("adair-uid-probe-{}", std::process::id()));
    std::fs::write(&probe, "").unwrap();
    let u = std::fs::metadata(&probe).unwrap().uid();
    std::fs::remove_file(&probe).unwrap();
    u
}

/// Without `HOME` (and `XDG_CACHE_HOME`) the copy of the predefined library
/// goes under the shared temporary folder, where another user may have
/// planted a symbolic link by the name the server uses: it is not
/// followed (the server wrote through `TMPDIR/adair` into the link's
/// target). The server uses a folder of its own, created 0700 and ours,
/// and "go to definition" still opens the AdaIR package there. As root,
/// a real folder by that name that belongs to someone else is refused too.
#[test]
#[allow(clippy::print_stdout)] // says when it is skipped
fn the_library_copy_never_follows_a_planted_link() {
    use std::os::unix::fs::{MetadataExt, PermissionsExt};
    let me = my_uid();
    let mut planted = Vec::new();
    let mut s = Server::start_env("planted", |cmd, dir| {
        let tmp = dir.join("tmp");
        let victim = dir.join("victim");
        std::fs::create_dir_all(&tmp).unwrap();
        std::fs::create_dir_all(&victim).unwrap();
        for name in ["adair".to_string(), format!("adair-{me}")] {
            std::os::unix::fs::symlink(&victim, tmp.join(&name)).unwrap();
            planted.push(tmp.join(name));
        }
        cmd.env_remove("HOME")
            .env_remove("XDG_CACHE_HOME")
            .env("TMPDIR", &tmp);
    });
    let file = adair_package_file(&mut s);
    let dir = s.dir.clone();
    let victim: Vec<_> = std::fs::read_dir(dir.join("victim"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    let text = std::fs::read_to_string(&file).unwrap_or_default();
    // The folder the server made for itself, under the temporary folder.
    let own = file
        .ancestors()
        .find(|a| a.parent() == Some(&dir.join("tmp")))
        .map(|a| a.to_path_buf());
    let meta = own.as_ref().map(|o| std::fs::symlink_metadata(o).unwrap());
    let links_kept = planted.iter().all(|p| {
        std::fs::symlink_metadata(p)
            .unwrap()
            .file_type()
            .is_symlink()
    });
    let (code, err) = s.finish();
    assert!(victim.is_empty(), "the link was followed: {victim:?}");
    assert!(links_kept);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        text.contains("package AdaIR"),
        "{}: {text:.200}",
        file.display()
    );
    let meta = meta.unwrap_or_else(|| panic!("{} is not under TMPDIR", file.display()));
    assert!(meta.file_type().is_dir(), "{own:?}");
    assert_eq!(meta.uid(), me);
    assert_eq!(meta.permissions().mode() & 0o777, 0o700, "{own:?}");

    if me != 0 {
        println!("skipped: a folder owned by another user needs root (chown)");
        return;
    }
    let mut s = Server::start_env("foreign", |cmd, dir| {
        let tmp = dir.join("tmp");
        let theirs = tmp.join("adair-0");
        std::fs::create_dir_all(&theirs).unwrap();
        std::fs::set_permissions(&theirs, std::fs::Permissions::from_mode(0o777)).unwrap();
        std::os::unix::fs::chown(&theirs, Some(65534), Some(65534)).unwrap();
        cmd.env_remove("HOME")
            .env_remove("XDG_CACHE_HOME")
            .env("TMPDIR", &tmp);
    });
    let file = adair_package_file(&mut s);
    let dir = s.dir.clone();
    let theirs = std::fs::read_dir(dir.join("tmp").join("adair-0"))
        .unwrap()
        .count();
    let text = std::fs::read_to_string(&file).unwrap_or_default();
    let (code, err) = s.finish();
    assert_eq!(theirs, 0, "wrote into a folder of another user");
    assert!(!file.starts_with(dir.join("tmp").join("adair-0")));
    assert_eq!(code, Some(0), "{err}");
    assert!(text.contains("package AdaIR"), "{}", file.display());
}
