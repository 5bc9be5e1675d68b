//! `adair lsp`: a language server (LSP 3.17, full-text sync) on an
//! `lsp_server::Connection` (stdin/stdout in the binary, in memory in the
//! tests).
//!
//! Each document version is checked from scratch on a copy of a checker that
//! has checked the embedded stdlib once ([`analysis::Base`]); the features
//! read the checker's side tables (`check::index`). The loop takes every
//! message that has arrived before it works: a burst of edits records the
//! texts and the document is checked once, on the latest text. A request
//! whose handler panics gets an error reply; the server goes on.

pub mod analysis;
pub mod complete;
pub mod features;

use analysis::{Analysis, Base};
use lsp_server::{Connection, ErrorCode, Message, Notification, Request, Response};
use lsp_types::notification::Notification as _;
use lsp_types::request::Request as _;
use lsp_types::{Location, Range, Uri};
use lsp_types::{notification as N, request as R};
use std::collections::HashMap;
use std::path::Path;
use std::rc::Rc;
use std::str::FromStr;

/// Settings of one server.
pub struct Config {
    /// Where the stdlib sources are written for "go to definition" into the
    /// AdaIR package (`None`: [`Base::default_stdlib_dir`]).
    pub stdlib_dir: Option<std::path::PathBuf>,
    /// Answer the request `adair/crash` by panicking (the tests' way to
    /// show that a failing request does not end the server).
    pub crash_request: bool,
}

/// The capabilities this server announces.
pub fn capabilities() -> lsp_types::ServerCapabilities {
    use lsp_types::*;
    ServerCapabilities {
        position_encoding: Some(PositionEncodingKind::UTF16),
        text_document_sync: Some(TextDocumentSyncCapability::Kind(TextDocumentSyncKind::FULL)),
        hover_provider: Some(HoverProviderCapability::Simple(true)),
        completion_provider: Some(CompletionOptions {
            trigger_characters: Some(vec![".".into(), "'".into()]),
            ..Default::default()
        }),
        definition_provider: Some(OneOf::Left(true)),
        references_provider: Some(OneOf::Left(true)),
        document_symbol_provider: Some(OneOf::Left(true)),
        signature_help_provider: Some(SignatureHelpOptions {
            trigger_characters: Some(vec!["(".into(), ",".into()]),
            retrigger_characters: None,
            work_done_progress_options: Default::default(),
        }),
        rename_provider: Some(OneOf::Left(true)),
        ..Default::default()
    }
}

struct Doc {
    text: String,
    version: i32,
    /// The analysis of `text`, once made (`None`: the text changed since).
    analysis: Option<Rc<Analysis>>,
}

struct Server<'c> {
    conn: &'c Connection,
    base: Base,
    docs: HashMap<Uri, Doc>,
    shutdown: bool,
    crash_request: bool,
    /// The client inserts snippets (`$1` placeholders); else none are offered.
    snippets: bool,
}

/// Runs the server until `exit` (after the handshake). Errors are protocol
/// errors (the client went away).
pub fn run(conn: &Connection, config: Config) -> Result<(), String> {
    let caps = serde_json::to_value(capabilities()).map_err(|e| e.to_string())?;
    let (id, params) = conn.initialize_start().map_err(|e| e.to_string())?;
    let snippets = params
        .pointer("/capabilities/textDocument/completion/completionItem/snippetSupport")
        .and_then(serde_json::Value::as_bool)
        .unwrap_or(false);
    let stdlib_dir = config.stdlib_dir.or_else(Base::default_stdlib_dir);
    let base = Base::new(stdlib_dir.as_deref());
    let init = serde_json::json!({
        "capabilities": caps,
        "serverInfo": { "name": "adair", "version": env!("CARGO_PKG_VERSION") },
    });
    conn.initialize_finish(id, init)
        .map_err(|e| e.to_string())?;
    let mut server = Server {
        conn,
        base,
        docs: HashMap::new(),
        shutdown: false,
        crash_request: config.crash_request,
        snippets,
    };
    server.main_loop()
}

impl Server<'_> {
    fn main_loop(&mut self) -> Result<(), String> {
        // The stdio transport hands over one message at a time (a rendezvous
        // channel): a thread takes each at once into an unbounded queue, so
        // that messages that come while a document is checked wait there,
        // and the loop below can take them all.
        // It forwards what is there together, as one batch.
        let (tx, queue) = std::sync::mpsc::channel::<Vec<Message>>();
        let rx = self.conn.receiver.clone();
        std::thread::spawn(move || {
            while let Ok(first) = rx.recv() {
                let mut batch = vec![first];
                batch.extend(rx.try_iter());
                if tx.send(batch).is_err() {
                    break;
                }
            }
        });
        while let Ok(mut batch) = queue.recv() {
            // Everything that has arrived: changes only record the text.
            batch.extend(queue.try_iter().flatten());
            let mut changed: Vec<Uri> = Vec::new();
            for m in batch {
                match m {
                    Message::Request(r) => self.request(r),
                    Message::Notification(n) => {
                        if n.method == N::Exit::METHOD {
                            // LSP: exit without shutdown is an error (status 1).
                            return if self.shutdown {
                                Ok(())
                            } else {
                                Err("exit before shutdown".into())
                            };
                        }
                        // A notification that panics is dropped, like a bad one.
                        let changed_uri =
                            std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                                self.notification(n)
                            }))
                            .ok()
                            .flatten();
                        if let Some(uri) = changed_uri
                            && !changed.contains(&uri)
                        {
                            changed.push(uri);
                        }
                    }
                    Message::Response(_) => {}
                }
            }
            for uri in changed.clone() {
                for dep in self.dependents(&uri) {
                    if !changed.contains(&dep) {
                        changed.push(dep);
                    }
                }
            }
            for uri in changed {
                let _ =
                    std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| self.publish(&uri)));
            }
        }
        Ok(())
    }

    fn send(&self, m: impl Into<Message>) {
        let _ = self.conn.sender.send(m.into());
    }

    /// Applies a notification; returns the document whose text changed.
    fn notification(&mut self, n: Notification) -> Option<Uri> {
        match n.method.as_str() {
            N::DidOpenTextDocument::METHOD => {
                let p: lsp_types::DidOpenTextDocumentParams =
                    serde_json::from_value(n.params).ok()?;
                let d = p.text_document;
                self.docs.insert(
                    d.uri.clone(),
                    Doc {
                        text: d.text,
                        version: d.version,
                        analysis: None,
                    },
                );
                Some(d.uri)
            }
            N::DidChangeTextDocument::METHOD => {
                let p: lsp_types::DidChangeTextDocumentParams =
                    serde_json::from_value(n.params).ok()?;
                let doc = self.docs.get_mut(&p.text_document.uri)?;
                // Full sync: a change holds the whole text; a client that
                // sends ranges anyway gets them applied in order.
                for ch in p.content_changes {
                    match ch.range {
                        None => doc.text = ch.text,
                        Some(r) => {
                            let lines = analysis::LineIndex::new(&doc.text);
                            let a = lines.offset(&doc.text, r.start);
                            let b = lines.offset(&doc.text, r.end).max(a);
                            doc.text.replace_range(a..b, &ch.text);
                        }
                    }
                }
                doc.version = p.text_document.version;
                doc.analysis = None;
                Some(p.text_document.uri)
            }
            N::DidCloseTextDocument::METHOD => {
                let p: lsp_types::DidCloseTextDocumentParams =
                    serde_json::from_value(n.params).ok()?;
                self.docs.remove(&p.text_document.uri);
                // Clear its diagnostics.
                self.send(Notification::new(
                    N::PublishDiagnostics::METHOD.into(),
                    lsp_types::PublishDiagnosticsParams::new(p.text_document.uri, Vec::new(), None),
                ));
                None
            }
            _ => None,
        }
    }

    /// The analysis of a document's current text, made if needed.
    fn analysis(&mut self, uri: &Uri) -> Option<Rc<Analysis>> {
        let doc = self.docs.get_mut(uri)?;
        if let Some(a) = &doc.analysis {
            return Some(a.clone());
        }
        let name = uri_file_name(uri);
        let path = uri_to_path(uri);
        let text = doc.text.clone();
        // `with`ed units come from the open documents first (unsaved
        // changes), then from the disk, as `adair run` would read them.
        let open = analysis::Open(
            self.docs
                .iter()
                .filter_map(|(u, d)| Some((uri_to_path(u)?, d.text.clone())))
                .collect(),
        );
        let a = Rc::new(Analysis::new(
            &self.base,
            &name,
            path.as_deref(),
            &text,
            Rc::new(open),
        ));
        self.docs.get_mut(uri)?.analysis = Some(a.clone());
        Some(a)
    }

    /// The open documents whose last analysis read the document `uri` as a
    /// `with`ed unit: their diagnostics change with it.
    fn dependents(&mut self, uri: &Uri) -> Vec<Uri> {
        let Some(path) = uri_to_path(uri) else {
            return Vec::new();
        };
        let mut out = Vec::new();
        for (u, d) in self.docs.iter_mut() {
            let reads = d
                .analysis
                .as_ref()
                .is_some_and(|a| a.with_files.iter().any(|(_, p)| *p == path));
            if u != uri && reads {
                d.analysis = None;
                out.push(u.clone());
            }
        }
        out
    }

    fn publish(&mut self, uri: &Uri) {
        let Some(a) = self.analysis(uri) else { return };
        let version = self.docs.get(uri).map(|d| d.version);
        let mut diags: Vec<lsp_types::Diagnostic> = a
            .diags
            .iter()
            .map(|d| self.to_lsp_diag(&a, uri, d))
            .collect();
        if let Some(msg) = &a.crashed {
            diags.push(lsp_types::Diagnostic {
                range: Range::default(),
                severity: Some(lsp_types::DiagnosticSeverity::ERROR),
                source: Some("adair".into()),
                message: format!(
                    "internal error: the checker panicked ({msg}); please report this text as a bug"
                ),
                ..Default::default()
            });
        }
        self.send(Notification::new(
            N::PublishDiagnostics::METHOD.into(),
            lsp_types::PublishDiagnosticsParams::new(uri.clone(), diags, version),
        ));
    }

    fn to_lsp_diag(
        &self,
        a: &Analysis,
        uri: &Uri,
        d: &crate::diag::Diagnostic,
    ) -> lsp_types::Diagnostic {
        let severity = if d.is_warning() {
            lsp_types::DiagnosticSeverity::WARNING
        } else {
            lsp_types::DiagnosticSeverity::ERROR
        };
        let mut message = d.message.clone();
        if let Some(h) = &d.hint {
            message.push_str("\nHelp: ");
            message.push_str(h);
        }
        let mut related = Vec::new();
        if !d.label.is_empty()
            && let Some(loc) = self.location(a, uri, d.span)
        {
            related.push(lsp_types::DiagnosticRelatedInformation {
                location: loc,
                message: d.label.clone(),
            });
        }
        for (s, text) in &d.notes {
            if let Some(loc) = self.location(a, uri, *s) {
                related.push(lsp_types::DiagnosticRelatedInformation {
                    location: loc,
                    message: text.clone(),
                });
            }
        }
        let range = if d.span.context == a.file {
            a.lines.range(&a.text, d.span)
        } else {
            Range::default()
        };
        lsp_types::Diagnostic {
            range,
            severity: Some(severity),
            source: Some("adair".into()),
            code: Some(lsp_types::NumberOrString::String(d.code.to_string())),
            code_description: self
                .base
                .error_pages
                .get(d.code.0)
                .and_then(|p| path_to_uri(p))
                .map(|href| lsp_types::CodeDescription { href }),
            message,
            related_information: (!related.is_empty()).then_some(related),
            ..Default::default()
        }
    }

    /// Where a span is, in the document or in a stdlib file.
    fn location(&self, a: &Analysis, uri: &Uri, s: crate::diag::Span) -> Option<Location> {
        if s.context == a.file {
            return Some(Location::new(uri.clone(), a.lines.range(&a.text, s)));
        }
        let (_, path) = self
            .base
            .stdlib_files
            .iter()
            .chain(&a.with_files)
            .find(|(id, _)| *id == s.context)?;
        let text = a.sources.text(s.context);
        let lines = analysis::LineIndex::new(text);
        Some(Location::new(path_to_uri(path)?, lines.range(text, s)))
    }

    fn request(&mut self, r: Request) {
        if self.shutdown && r.method != R::Shutdown::METHOD {
            self.send(Response::new_err(
                r.id,
                ErrorCode::InvalidRequest as i32,
                "the server is shutting down".into(),
            ));
            return;
        }
        let id = r.id.clone();
        let method = r.method.clone();
        let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| self.dispatch(r)));
        let resp = match result {
            Ok(Ok(v)) => Response::new_ok(id, v),
            Ok(Err((code, msg))) => Response::new_err(id, code as i32, msg),
            Err(p) => {
                let msg = p
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| p.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_default();
                Response::new_err(
                    id,
                    ErrorCode::InternalError as i32,
                    format!("adair lsp: internal error in {method}: {msg}"),
                )
            }
        };
        self.send(resp);
    }

    fn dispatch(&mut self, r: Request) -> Result<serde_json::Value, (ErrorCode, String)> {
        fn params<P: serde::de::DeserializeOwned>(
            v: serde_json::Value,
        ) -> Result<P, (ErrorCode, String)> {
            serde_json::from_value(v).map_err(|e| (ErrorCode::InvalidParams, e.to_string()))
        }
        fn json(v: impl serde::Serialize) -> Result<serde_json::Value, (ErrorCode, String)> {
            serde_json::to_value(v).map_err(|e| (ErrorCode::InternalError, e.to_string()))
        }
        match r.method.as_str() {
            R::Shutdown::METHOD => {
                self.shutdown = true;
                json(())
            }
            R::HoverRequest::METHOD => {
                let p: lsp_types::HoverParams = params(r.params)?;
                let Some((a, off)) = self.at(&p.text_document_position_params) else {
                    return json(None::<()>);
                };
                json(
                    features::hover(&a, off).map(|(text, span)| lsp_types::Hover {
                        contents: lsp_types::HoverContents::Markup(lsp_types::MarkupContent {
                            kind: lsp_types::MarkupKind::Markdown,
                            value: text,
                        }),
                        range: (span.context == a.file).then(|| a.lines.range(&a.text, span)),
                    }),
                )
            }
            R::GotoDefinition::METHOD => {
                let p: lsp_types::GotoDefinitionParams = params(r.params)?;
                let uri = p.text_document_position_params.text_document.uri.clone();
                let Some((a, off)) = self.at(&p.text_document_position_params) else {
                    return json(None::<()>);
                };
                let loc = features::definition(&a, off).and_then(|s| self.location(&a, &uri, s));
                json(loc.map(lsp_types::GotoDefinitionResponse::Scalar))
            }
            R::References::METHOD => {
                let p: lsp_types::ReferenceParams = params(r.params)?;
                let uri = p.text_document_position.text_document.uri.clone();
                let Some((a, off)) = self.at(&p.text_document_position) else {
                    return json(None::<()>);
                };
                let locs: Vec<Location> =
                    features::references(&a, off, p.context.include_declaration)
                        .into_iter()
                        .filter_map(|s| self.location(&a, &uri, s))
                        .collect();
                json(locs)
            }
            R::Rename::METHOD => {
                let p: lsp_types::RenameParams = params(r.params)?;
                let uri = p.text_document_position.text_document.uri.clone();
                let Some((a, off)) = self.at(&p.text_document_position) else {
                    return json(None::<()>);
                };
                let spans = features::rename(&a, off, &p.new_name)
                    .map_err(|m| (ErrorCode::InvalidParams, m))?;
                let edits: Vec<lsp_types::TextEdit> = spans
                    .into_iter()
                    .map(|s| {
                        lsp_types::TextEdit::new(a.lines.range(&a.text, s), p.new_name.clone())
                    })
                    .collect();
                json(lsp_types::WorkspaceEdit::new(HashMap::from([(uri, edits)])))
            }
            R::DocumentSymbolRequest::METHOD => {
                let p: lsp_types::DocumentSymbolParams = params(r.params)?;
                let Some(a) = self.analysis(&p.text_document.uri) else {
                    return json(None::<()>);
                };
                let syms: Vec<lsp_types::DocumentSymbol> = features::symbols(&a)
                    .iter()
                    .map(|s| features::to_document_symbol(&a.text, &a.lines, s))
                    .collect();
                json(lsp_types::DocumentSymbolResponse::Nested(syms))
            }
            R::Completion::METHOD => {
                let p: lsp_types::CompletionParams = params(r.params)?;
                let Some((a, off)) = self.at(&p.text_document_position) else {
                    return json(None::<()>);
                };
                let items: Vec<lsp_types::CompletionItem> = complete::completion(&a, off)
                    .iter()
                    .filter(|i| self.snippets || i.snippet.is_none())
                    .map(complete::Item::to_lsp)
                    .collect();
                json(lsp_types::CompletionResponse::Array(items))
            }
            R::SignatureHelpRequest::METHOD => {
                let p: lsp_types::SignatureHelpParams = params(r.params)?;
                let Some((a, off)) = self.at(&p.text_document_position_params) else {
                    return json(None::<()>);
                };
                json(complete::signature_help(&a, off).map(signature_help))
            }
            "adair/crash" if self.crash_request => panic!("adair/crash was asked for"),
            _ => Err((
                ErrorCode::MethodNotFound,
                format!("adair lsp does not handle {}", r.method),
            )),
        }
    }

    /// The analysis of a position's document and the position's byte offset.
    fn at(&mut self, p: &lsp_types::TextDocumentPositionParams) -> Option<(Rc<Analysis>, usize)> {
        let a = self.analysis(&p.text_document.uri)?;
        let off = a.lines.offset(&a.text, p.position);
        Some((a, off))
    }
}

fn signature_help(s: complete::Signatures) -> lsp_types::SignatureHelp {
    use lsp_types::*;
    SignatureHelp {
        signatures: s
            .list
            .into_iter()
            .map(|sig| SignatureInformation {
                label: sig.label,
                documentation: sig.doc.map(|d| {
                    Documentation::MarkupContent(MarkupContent {
                        kind: MarkupKind::Markdown,
                        value: d,
                    })
                }),
                parameters: Some(
                    sig.params
                        .into_iter()
                        .map(|(a, b)| ParameterInformation {
                            label: ParameterLabel::LabelOffsets([a as u32, b as u32]),
                            documentation: None,
                        })
                        .collect(),
                ),
                active_parameter: None,
            })
            .collect(),
        active_signature: Some(s.active as u32),
        active_parameter: Some(s.param as u32),
    }
}

/// The file name shown in messages for a document.
/// The file of a `file:` URI, absolute (`None` for other schemes).
fn uri_to_path(uri: &Uri) -> Option<std::path::PathBuf> {
    let scheme = uri.scheme()?;
    if !scheme.as_str().eq_ignore_ascii_case("file") {
        return None;
    }
    let path = std::path::PathBuf::from(percent_decode(uri.path().as_str()));
    path.is_absolute().then_some(path)
}

fn uri_file_name(uri: &Uri) -> String {
    let path = uri.path().as_str();
    let last = path.rsplit('/').next().unwrap_or(path);
    if last.is_empty() {
        uri.as_str().to_string()
    } else {
        percent_decode(last)
    }
}

fn percent_decode(s: &str) -> String {
    let b = s.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'%'
            && i + 2 < b.len()
            && let Some(v) = std::str::from_utf8(&b[i + 1..i + 3])
                .ok()
                .and_then(|h| u8::from_str_radix(h, 16).ok())
        {
            out.push(v);
            i += 3;
            continue;
        }
        out.push(b[i]);
        i += 1;
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// A `file:` URI for a path (bytes outside the unreserved set escaped).
pub fn path_to_uri(path: &Path) -> Option<Uri> {
    let abs = if path.is_absolute() {
        path.to_path_buf()
    } else {
        std::env::current_dir().ok()?.join(path)
    };
    let mut s = String::from("file://");
    let text = abs.to_string_lossy();
    for seg in text.strip_prefix('/').unwrap_or(&text).split('/') {
        s.push('/');
        for b in seg.bytes() {
            if b.is_ascii_alphanumeric() || b"-._~".contains(&b) {
                s.push(b as char);
            } else {
                s.push_str(&format!("%{b:02X}"));
            }
        }
    }
    Uri::from_str(&s).ok()
}

/// `adair lsp`: serves on standard input and output until the client exits.
pub fn serve_stdio() -> Result<(), String> {
    let (conn, reader, writer) = stdio_connection();
    run(
        &conn,
        Config {
            stdlib_dir: None,
            crash_request: false,
        },
    )?;
    drop(conn);
    let joined = |h: std::thread::JoinHandle<std::io::Result<()>>| match h.join() {
        Ok(r) => r.map_err(|e| e.to_string()),
        Err(_) => Err("the message thread failed".to_string()),
    };
    joined(reader)?;
    joined(writer)
}

/// The largest message the server reads (its `Content-Length`): a document
/// of this size is far beyond what the checker is for, and a length the
/// client sends is not allocated before it is checked.
pub const MAX_MESSAGE: usize = 64 << 20;

/// The longest header line taken (`Content-Length: N` and
/// `Content-Type: ...` are a few dozen bytes).
const MAX_HEADER_LINE: u64 = 1024;

/// What the reader found in the input.
enum Frame {
    /// A message's text.
    Body(Vec<u8>),
    /// The header of a message over [`MAX_MESSAGE`]: its length. The
    /// body is still to be read past ([`skip`]).
    TooLong(u64),
    /// The input ended between messages.
    End,
}

/// Reads one framed message (`Content-Length` header, blank line, body)
/// from `inp`, keeping at most [`MAX_MESSAGE`] bytes: a longer one is read
/// past. Errors are malformed headers and an input that ends inside a
/// message: the framing is lost, the connection ends.
fn read_frame(inp: &mut impl std::io::BufRead) -> std::io::Result<Frame> {
    use std::io::{BufRead as _, Read as _};
    let bad = |m: String| std::io::Error::new(std::io::ErrorKind::InvalidData, m);
    let mut size: Option<u64> = None;
    let mut first = true;
    loop {
        let mut line = Vec::new();
        (&mut *inp)
            .take(MAX_HEADER_LINE)
            .read_until(b'\n', &mut line)?;
        if line.is_empty() && first {
            return Ok(Frame::End);
        }
        first = false;
        let Some(text) = line.strip_suffix(b"\r\n") else {
            let shown = String::from_utf8_lossy(&line[..line.len().min(80)]).into_owned();
            return Err(bad(if line.len() as u64 >= MAX_HEADER_LINE {
                format!("a header line longer than {MAX_HEADER_LINE} bytes: {shown:?}...")
            } else {
                format!("malformed header (or the input ended): {shown:?}")
            }));
        };
        if text.is_empty() {
            break;
        }
        let text = String::from_utf8_lossy(text);
        let (name, value) = text
            .split_once(": ")
            .ok_or_else(|| bad(format!("malformed header: {text:?}")))?;
        if name.eq_ignore_ascii_case("Content-Length") {
            size = Some(
                value
                    .trim()
                    .parse()
                    .map_err(|_| bad(format!("malformed Content-Length: {value:?}")))?,
            );
        }
    }
    let size = size.ok_or_else(|| bad("a message without Content-Length".into()))?;
    if size > MAX_MESSAGE as u64 {
        return Ok(Frame::TooLong(size));
    }
    let mut body = vec![0; size as usize];
    inp.read_exact(&mut body)?;
    Ok(Frame::Body(body))
}

/// Reads past the `size` bytes of a message that is not kept.
fn skip(inp: &mut impl std::io::BufRead, size: u64) -> std::io::Result<()> {
    use std::io::Read as _;
    let read = std::io::copy(&mut (&mut *inp).take(size), &mut std::io::sink())?;
    if read < size {
        return Err(std::io::Error::new(
            std::io::ErrorKind::UnexpectedEof,
            format!("the input ended inside a message of {size} bytes"),
        ));
    }
    Ok(())
}

/// An error the client should see: on standard error (the editor's log of
/// the server) and as a `window/logMessage` notification (`send`).
fn log_error(send: &impl Fn(Message), text: &str) {
    use std::io::Write as _;
    let _ = writeln!(std::io::stderr(), "adair lsp: {text}");
    send(Message::Notification(Notification::new(
        N::LogMessage::METHOD.to_string(),
        lsp_types::LogMessageParams {
            typ: lsp_types::MessageType::ERROR,
            message: text.to_string(),
        },
    )));
}

/// A connection on standard input and output, as
/// `lsp_server::Connection::stdio` but with every length bounded: that
/// one allocates whatever `Content-Length` says (`1000000000000` aborted
/// the server) and reads header lines of any length. A message over
/// [`MAX_MESSAGE`] or one that is not JSON-RPC is logged and skipped; a
/// malformed header ends the connection with an error. The server's side
/// is one end of an in-memory connection; two threads carry the other
/// end's messages to and from the standard streams.
fn stdio_connection() -> (
    Connection,
    std::thread::JoinHandle<std::io::Result<()>>,
    std::thread::JoinHandle<std::io::Result<()>>,
) {
    let (server, client) = Connection::memory();
    let Connection { sender, receiver } = client;
    // The reader's errors go to the client, as the server's messages do.
    let to_client = server.sender.clone();
    let writer = std::thread::spawn(move || {
        let stdout = std::io::stdout();
        let mut stdout = stdout.lock();
        receiver.into_iter().try_for_each(|m| m.write(&mut stdout))
    });
    let reader = std::thread::spawn(move || {
        let log = move |m: Message| {
            let _ = to_client.send(m);
        };
        let stdin = std::io::stdin();
        let mut stdin = stdin.lock();
        loop {
            let frame = read_frame(&mut stdin).inspect_err(|e| {
                log_error(&log, &format!("protocol error, the connection ends: {e}"));
            })?;
            let body = match frame {
                Frame::End => return Ok(()),
                Frame::TooLong(n) => {
                    log_error(
                        &log,
                        &format!(
                            "a message of {n} bytes (Content-Length: {n}) is over the limit of \
                             {} MiB: read past and ignored",
                            MAX_MESSAGE >> 20
                        ),
                    );
                    skip(&mut stdin, n).inspect_err(|e| {
                        log_error(&log, &format!("protocol error, the connection ends: {e}"));
                    })?;
                    continue;
                }
                Frame::Body(b) => b,
            };
            let msg: Message = match serde_json::from_slice(&body) {
                Ok(m) => m,
                Err(e) => {
                    log_error(
                        &log,
                        &format!("a message that is not JSON-RPC: {e}; ignored"),
                    );
                    continue;
                }
            };
            let exit = matches!(&msg, Message::Notification(n) if n.method == N::Exit::METHOD);
            if sender.send(msg).is_err() || exit {
                return Ok(());
            }
        }
    });
    (server, reader, writer)
}
