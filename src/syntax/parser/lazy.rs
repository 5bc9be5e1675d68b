//! The lazy-parse machinery: a subprogram body's statements recognised
//! but not built (see [`Block::lazy`]), the nesting that tells where they
//! end and where they may be cut into parts that parse alone ([`Nesting`],
//! [`Cuts`]), and the parse of one part ([`parse_stmts`]).

use super::errors::{rich_to_diag, seq_end};
use super::limits::too_deep;
use super::{Ex, TokIn, exact, parsers};
use crate::diag::{Diagnostic, FileId, Span};
use crate::syntax::ast::*;
use crate::syntax::token::{Kw, Token};
use chumsky::prelude::*;

/// A subprogram body whose statements are only recognised: chumsky
/// checks them without building them (`ignored`), and the block keeps
/// where they are.
pub(super) fn unbuilt_body<'t, I: TokIn<'t>>(
    stmt: &Boxed<'t, 't, I, Stmt, Ex<'t>>,
    handlers: &Boxed<'t, 't, I, Option<Vec<Handler>>, Ex<'t>>,
) -> Boxed<'t, 't, I, Block, Ex<'t>> {
    kw!(Begin)
        .ignore_then(
            select! { Token::Statements = e => e.span() }.or(seq_end()
                .not()
                .rewind()
                .ignore_then(stmt.clone())
                .repeated()
                .ignored()
                .map_with(|(), e| e.span())),
        )
        .then(handlers.clone())
        .then_ignore(kw!(End))
        .map_with(|(at, handlers), e| Block {
            stmts: Vec::new().into(),
            handlers: handlers.unwrap_or_default(),
            span: e.span(),
            lazy: Some(at),
        })
        .boxed()
}

/// Parses a list of statements: a part of a lazy body (see
/// [`Block::lazy`]), whose text ends at offset `end`.
pub fn parse_stmts(
    tokens: &[(Token, Span)],
    file: FileId,
    end: u32,
) -> (Option<Vec<Stmt>>, Vec<Diagnostic>) {
    let eoi = Span {
        start: end,
        end,
        context: file,
    };
    if let Some(d) = too_deep(tokens) {
        return (None, vec![d]);
    }
    let input = tokens.map(eoi, |(t, s)| {
        crate::work::tick();
        (t, s)
    });
    let grammar = parsers(false)
        .stmt
        .repeated()
        .collect::<Vec<_>>()
        .map(exact)
        .then_ignore(chumsky::primitive::end());
    // Leanly first (see `lean`): statements without errors are parsed once.
    let (out, errs) = super::lean::leanly(|| grammar.parse(input.clone()).into_output_errors());
    if errs.is_empty() {
        return (out, Vec::new());
    }
    let (out, errs) = grammar.parse(input).into_output_errors();
    let diags = errs
        .into_iter()
        .filter_map(super::PErr::rich)
        .map(|e| rich_to_diag(e, tokens))
        .collect();
    (out, diags)
}

/// What a token is to the statements of a body around it (see [`Nesting`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum At {
    /// Inside a statement (or between two).
    Inside,
    /// The `;` that ends one of the statements themselves.
    Semi,
    /// The `exception` or `end` after the statements: they are over.
    Close,
}

/// The nesting of a body's statements, token by token, as the words that
/// open and `end` close it: `if`, `case`, `loop`, `select`, `record` (not
/// after `end`, nor `null record`), `do`, `declare` (whose `begin`
/// continues it), `begin`, and the `is` of a unit declared in a block (a
/// package, task, protected unit, subprogram or entry body: not one that
/// is `new`, `separate`, `abstract`, `null`, `<>` or an expression
/// function), whose `begin` continues it too. Parentheses hide all.
/// A misjudged cut is safe (see [`statement_cuts`]); a misjudged end
/// makes the skeleton of `syntax::parse_source_lazy` fail, and the source
/// is then parsed as before.
#[derive(Clone, Debug, Default)]
pub struct Nesting {
    open: Vec<Kw>,
    paren: usize,
    /// The previous token was `end` (`end if`), `null` (`null record`).
    after_end: bool,
    after_null: bool,
    /// A unit's word was seen: its `is` opens it (cleared by `;`).
    unit: bool,
    /// The unit's `is` was the previous token: the next decides.
    is_pending: bool,
}

impl Nesting {
    pub fn step(&mut self, t: &Token) -> At {
        let was_end = std::mem::replace(&mut self.after_end, false);
        let was_null = std::mem::replace(&mut self.after_null, false);
        if std::mem::replace(&mut self.is_pending, false)
            && !matches!(
                t,
                Token::Kw(Kw::New | Kw::Separate | Kw::Abstract | Kw::Null)
                    | Token::LParen
                    | Token::Box
            )
        {
            self.open.push(Kw::Is);
        }
        match t {
            Token::LParen => self.paren += 1,
            Token::RParen => self.paren = self.paren.saturating_sub(1),
            _ if self.paren > 0 => {}
            Token::Kw(Kw::End) => {
                if self.open.pop().is_none() {
                    return At::Close;
                }
                self.after_end = true;
            }
            Token::Kw(Kw::Exception) if self.open.is_empty() => return At::Close,
            Token::Kw(Kw::Null) => self.after_null = true,
            // `end if`, `end loop`, ...: the word names what ends.
            Token::Kw(k @ (Kw::If | Kw::Case | Kw::Loop | Kw::Select)) if !was_end => {
                self.open.push(*k)
            }
            Token::Kw(Kw::Record) if !was_end && !was_null => self.open.push(Kw::Record),
            Token::Kw(k @ (Kw::Do | Kw::Declare)) => self.open.push(*k),
            Token::Kw(
                Kw::Package | Kw::Task | Kw::Protected | Kw::Procedure | Kw::Function | Kw::Entry,
            ) if !was_end => self.unit = true,
            Token::Kw(Kw::Is) if std::mem::take(&mut self.unit) => self.is_pending = true,
            // A declare block's (a unit's) `begin` continues it.
            Token::Kw(Kw::Begin) => match self.open.last_mut() {
                Some(k @ (Kw::Declare | Kw::Is)) => *k = Kw::Begin,
                _ => self.open.push(Kw::Begin),
            },
            Token::Semi => {
                self.unit = false;
                if self.open.is_empty() {
                    return At::Semi;
                }
            }
            _ => {}
        }
        At::Inside
    }
}

/// Where the statements of a lazy body (tokens `tokens`, given a window at
/// a time) may be cut into parts that parse alone: the ends of its own
/// statements' `;`, about one every `every` tokens. The nesting is
/// followed by a [`Nesting`]; a cut it misjudges makes a part that does not
/// parse, which is then parsed joined with the next (see
/// `syntax::lazy_stmts`).
#[derive(Debug)]
pub struct Cuts {
    pub cuts: Vec<u32>,
    /// The body's own statements, as far as the nesting was followed.
    pub count: usize,
    nesting: Nesting,
    every: usize,
    since: usize,
}

impl Cuts {
    pub fn new(every: usize) -> Cuts {
        Cuts {
            cuts: Vec::new(),
            count: 0,
            nesting: Nesting::default(),
            every,
            since: 0,
        }
    }

    pub fn feed(&mut self, tokens: &[(Token, Span)]) {
        for (t, s) in tokens {
            self.since += 1;
            if self.nesting.step(t) == At::Semi {
                self.count += 1;
                if self.since >= self.every {
                    self.cuts.push(s.end);
                    self.since = 0;
                }
            }
        }
    }
}

/// [`Cuts`] of a whole token list: the cuts and the count.
pub fn statement_cuts(tokens: &[(Token, Span)], every: usize) -> (Vec<u32>, usize) {
    let mut c = Cuts::new(every);
    c.feed(tokens);
    (c.cuts, c.count)
}
