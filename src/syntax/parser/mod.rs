//! The chumsky parser: tokens -> AST, with error recovery so that one run
//! reports every syntax error of a file. This file: the entry points, the
//! grammar's assembly (`parsers`, `Common`) and the small parts every
//! grammar part uses. Expressions are in `expr.rs`, statements in
//! `stmt.rs`, declarations in `decl.rs`, error recovery and the diagnostics
//! in `errors.rs`, the nesting and operator-chain limits in `limits.rs`,
//! and what parses a long body's statements a part at a time in `lazy.rs`.

use super::ast::*;
use super::token::{Kw, Token};
use crate::diag::{Diagnostic, FileId, Span};
use chumsky::input::ValueInput;
use chumsky::prelude::*;

/// A token and where it is.
pub type Tok = (Token, Span);

type Ex<'t> = extra::Err<PErr<'t>>;

/// Everything a parser function needs from its input.
pub trait TokIn<'t>: ValueInput<'t, Token = Token, Span = Span> {}
impl<'t, T: ValueInput<'t, Token = Token, Span = Span>> TokIn<'t> for T {}

macro_rules! kw {
    ($k:ident) => {
        just(Token::Kw(Kw::$k))
    };
}

mod decl;
mod errors;
mod expr;
mod lazy;
mod lean;
mod limits;
mod stmt;

pub use errors::{OPENER_AT, is_unfinished};
pub use expr::{expr, name};
pub use lazy::{At, Cuts, Nesting, parse_stmts, statement_cuts};
pub use limits::{MAX_CHAIN, MAX_NESTING};

use decl::decl_grammar;
use errors::{decls_end, explain_unclosed, missing_after, rich_to_diag, seq_end};
use expr::{discrete_range, subtype_ind};
use lean::PErr;
use limits::too_deep;
use stmt::stmt_grammar;

fn ident<'t, I: TokIn<'t>>() -> impl Parser<'t, I, Ident, Ex<'t>> + Clone {
    select! { Token::Ident(s) = e => Ident::new(&s, e.span()) }.labelled("identifier")
}

fn semi<'t, I: TokIn<'t>>() -> impl Parser<'t, I, Token, Ex<'t>> + Clone {
    just(Token::Semi).labelled("`;`")
}

fn mk(kind: ExprKind, span: Span) -> Expr {
    Expr { kind, span }
}

/// A collected list at its exact size: the repeated parsers grow their
/// `Vec` by doubling, and a long program's syntax tree is mostly lists.
fn exact<T>(mut v: Vec<T>) -> Vec<T> {
    v.shrink_to_fit();
    v
}

/// The arms of an `if`: the first, then the `elsif`s.
fn first_and<C, B>(c: C, b: B, rest: Vec<(C, B)>) -> Vec<(C, B)> {
    let mut arms = Vec::with_capacity(rest.len() + 1);
    arms.push((c, b));
    arms.extend(rest);
    arms
}

fn join(a: Span, b: Span) -> Span {
    Span {
        start: a.start.min(b.start),
        end: a.end.max(b.end),
        context: a.context,
    }
}

/// The text of a (selected) name, for `end` names and messages.
pub fn expr_text(e: &Expr) -> String {
    match &e.kind {
        ExprKind::Name(i) => i.name.to_string(),
        ExprKind::Select(p, i) => format!("{}.{}", expr_text(p), i.name),
        _ => String::from("?"),
    }
}

struct Parsers<'t, I: TokIn<'t>> {
    stmt: Boxed<'t, 't, I, Stmt, Ex<'t>>,
}

/// The grammar. `lazy`: a subprogram body's statements are read but not
/// built (see [`Block::lazy`]).
fn parsers<'t, I: TokIn<'t>>(lazy: bool) -> Parsers<'t, I> {
    // Statements and declarations are mutually recursive. Each refers to
    // itself and to the other through chumsky's `recursive` handles, which
    // are weak inside their own definition: `Recursive::declare` and
    // `define` made a reference cycle, and every parse leaked the grammar.
    let expr = expr::<I>();
    let stmt = recursive(|stmt| {
        let stmt = stmt.boxed();
        // The shared parts are built once, inside the declaration's
        // definition; the statement's definition owns the declaration, so
        // their weak handle to it stays good.
        let mut shared = None;
        let decl = recursive(|decl| {
            let decl = decl.boxed();
            let c = common(&expr, &stmt, &decl, lazy);
            let g = decl_grammar(&c, &decl);
            shared = Some(c);
            g
        })
        .boxed();
        let c = shared.expect("the declaration's definition ran");
        stmt_grammar(&c, &decl)
    });
    Parsers { stmt: stmt.boxed() }
}

/// The parts of the grammar that statements and declarations share, built
/// over their handles.
struct Common<'t, I: TokIn<'t>> {
    expr: Boxed<'t, 't, I, Expr, Ex<'t>>,
    st_ind: Boxed<'t, 't, I, SubtypeInd, Ex<'t>>,
    drange: Boxed<'t, 't, I, DiscreteRange, Ex<'t>>,
    stmts: Boxed<'t, 't, I, Vec<Stmt>, Ex<'t>>,
    decls: Boxed<'t, 't, I, Vec<Decl>, Ex<'t>>,
    handler: Boxed<'t, 't, I, Handler, Ex<'t>>,
    block: Boxed<'t, 't, I, Block, Ex<'t>>,
    body_block: Boxed<'t, 't, I, Block, Ex<'t>>,
    end_name: Boxed<'t, 't, I, Option<(String, Span)>, Ex<'t>>,
}

fn common<'t, I: TokIn<'t>>(
    expr: &Boxed<'t, 't, I, Expr, Ex<'t>>,
    stmt: &Boxed<'t, 't, I, Stmt, Ex<'t>>,
    decl: &Boxed<'t, 't, I, Decl, Ex<'t>>,
    lazy: bool,
) -> Common<'t, I> {
    let expr = expr.clone();
    let st_ind = subtype_ind(expr.clone());
    let drange = discrete_range(expr.clone());

    // Statement sequences stop at the words that close them; a statement that
    // fails to parse is skipped up to its `;` so that later errors are found too.
    let stmts = seq_end()
        .not()
        .rewind()
        .ignore_then(stmt.clone())
        .repeated()
        .collect::<Vec<_>>()
        .map(exact)
        .boxed();
    let decls = decls_end()
        .not()
        .rewind()
        .ignore_then(decl.clone())
        .repeated()
        .collect::<Vec<_>>()
        .boxed();

    let handler = kw!(When)
        .ignore_then(ident().then_ignore(just(Token::Colon)).or_not())
        .then(
            kw!(Others)
                .to(None)
                .or(name().map(Some))
                .separated_by(just(Token::Bar))
                .at_least(1)
                .collect::<Vec<_>>(),
        )
        .then_ignore(just(Token::Arrow))
        .then(stmts.clone())
        .map_with(|((occurrence, choices), stmts), e| Handler {
            occurrence,
            choices,
            stmts,
            span: e.span(),
        });
    // A block's handlers, if it has an `exception` part.
    let handlers = kw!(Exception)
        .ignore_then(handler.clone().repeated().collect::<Vec<_>>())
        .or_not()
        .boxed();
    let block = kw!(Begin)
        .ignore_then(stmts.clone())
        .then(handlers.clone())
        .then_ignore(kw!(End))
        .map_with(|(stmts, handlers), e| Block {
            stmts: stmts.into(),
            handlers: handlers.unwrap_or_default(),
            span: e.span(),
            lazy: None,
        })
        .boxed();

    // When `lazy`, a subprogram body's statements are only recognised.
    let body_block = if lazy {
        lazy::unbuilt_body(stmt, &handlers)
    } else {
        block.clone()
    };
    let end_name = name()
        .map(|n: Expr| (expr_text(&n), n.span))
        .or(select! { Token::Str(s) = e => (format!("\"{s}\""), e.span()) })
        .or_not();

    // ---- statements ----
    Common {
        expr,
        st_ind,
        drange,
        stmts,
        decls,
        handler: handler.boxed(),
        block,
        body_block,
        end_name: end_name.boxed(),
    }
}

fn compilation<'t, I: TokIn<'t>>(lazy: bool) -> Boxed<'t, 't, I, CompilationUnit, Ex<'t>> {
    let p = parsers::<I>(lazy);
    let with = kw!(Limited)
        .or_not()
        .ignore_then(kw!(With))
        .ignore_then(
            name()
                .separated_by(just(Token::Comma))
                .at_least(1)
                .collect::<Vec<_>>(),
        )
        .then_ignore(semi())
        .map_with(|n, e| TopItem::With(n, e.span()));
    // Statement position accepts declarations too (script mode), so one
    // parser serves both; library units come back as declarations.
    let item = choice((
        with,
        p.stmt.clone().map(|s| match s.kind {
            StmtKind::Decl(d) => TopItem::Decl(d),
            _ => TopItem::Stmt(s),
        }),
    ));
    item.repeated()
        .collect::<Vec<_>>()
        .then_ignore(end())
        .map(|items| CompilationUnit { items })
        .boxed()
}

/// Parses a token list. Returns the AST (possibly partial) and every syntax error.
pub fn parse(
    tokens: &[(Token, Span)],
    file: FileId,
    src_len: usize,
) -> (Option<CompilationUnit>, Vec<Diagnostic>) {
    parse_with(tokens, file, src_len, false)
}

/// [`parse`], the statements of subprogram bodies left unbuilt when `lazy`
/// (see [`Block::lazy`]).
pub fn parse_with(
    tokens: &[(Token, Span)],
    file: FileId,
    src_len: usize,
    lazy: bool,
) -> (Option<CompilationUnit>, Vec<Diagnostic>) {
    parse_passes(tokens, file, src_len, lazy, true)
}

/// [`parse_with`], leanly first (see `lean`) or, when not `lean_first`,
/// with rich errors only (the tests compare the two).
pub fn parse_passes(
    tokens: &[(Token, Span)],
    file: FileId,
    src_len: usize,
    lazy: bool,
    lean_first: bool,
) -> (Option<CompilationUnit>, Vec<Diagnostic>) {
    let src_len = crate::diag::offset(src_len);
    let eoi = Span {
        start: src_len,
        end: src_len,
        context: file,
    };
    if let Some(d) = too_deep(tokens) {
        return (None, vec![d]);
    }
    let input = tokens.map(eoi, |(t, s)| {
        crate::work::tick();
        (t, s)
    });
    // Leanly first (see `lean`): a text without errors is parsed once.
    let grammar = compilation(lazy);
    if lean_first {
        let (out, errs) = lean::leanly(|| grammar.parse(input.clone()).into_output_errors());
        if errs.is_empty() {
            return (out, Vec::new());
        }
    }
    let (out, errs) = grammar.parse(input).into_output_errors();
    let mut diags: Vec<Diagnostic> = errs
        .into_iter()
        .filter_map(PErr::rich)
        .map(|e| rich_to_diag(e, tokens))
        .collect();
    diags.dedup_by(|a, b| a.span == b.span);
    missing_after(&mut diags, tokens);
    explain_unclosed(&mut diags, tokens, src_len);
    (out, diags)
}

/// Parses a whole entry as one expression (optionally ending in `;`), for
/// the REPL. `None` if it is not exactly an expression.
pub fn parse_expr_entry(tokens: &[(Token, Span)], file: FileId, src_len: usize) -> Option<Expr> {
    let src_len = crate::diag::offset(src_len);
    let eoi = Span {
        start: src_len,
        end: src_len,
        context: file,
    };
    if too_deep(tokens).is_some() {
        return None;
    }
    let input = tokens.map(eoi, |(t, s)| {
        crate::work::tick();
        (t, s)
    });
    let p = expr()
        .then_ignore(just(Token::Semi).or_not())
        .then_ignore(end());
    // Its errors are not reported: a lean pass (see `lean`) is enough.
    lean::leanly(|| p.parse(input).into_result().ok())
}
