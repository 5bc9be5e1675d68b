//! Statements: assignments and calls, `if`, `case`, loops, blocks,
//! `exit`, `return`, `raise`, `delay` and the tasking statements, and a
//! declaration in statement position (script mode).

use super::decl::params;
use super::errors::{UNCLOSED, closing, skip_to_semi, soft_kw, soft_semi, unclosed};
use super::{Common, Ex, PErr, TokIn, first_and, ident, name, semi};
use crate::diag::Span;
use crate::diag::codes;
use crate::syntax::ast::*;
use crate::syntax::diagnostics as D;
use crate::syntax::token::{Kw, Token};
use chumsky::prelude::*;

/// The statement, over the shared parts.
pub(super) fn stmt_grammar<'t, I: TokIn<'t>>(
    c: &Common<'t, I>,
    decl: &Boxed<'t, 't, I, Decl, Ex<'t>>,
) -> Boxed<'t, 't, I, Stmt, Ex<'t>> {
    let Common {
        expr,
        drange,
        stmts,
        decls,
        handler,
        block,
        ..
    } = c;

    let label = ident().then_ignore(just(Token::Colon));
    let choice_p = kw!(Others)
        .map_with(|_, e| Choice::Others(e.span()))
        .or(expr
            .clone()
            .then(just(Token::DotDot).ignore_then(expr.clone()).or_not())
            .map(|(a, b)| match b {
                Some(b) => Choice::Range(a, b),
                None => Choice::Expr(a),
            }))
        .boxed();
    let choices = choice_p
        .separated_by(just(Token::Bar))
        .at_least(1)
        .collect::<Vec<_>>()
        .boxed();

    let if_stmt = kw!(If)
        .ignore_then(expr.clone())
        .then_ignore(soft_kw(Kw::Then))
        .then(stmts.clone())
        .then(
            kw!(Elsif)
                .ignore_then(expr.clone())
                .then_ignore(soft_kw(Kw::Then))
                .then(stmts.clone())
                .repeated()
                .collect::<Vec<_>>(),
        )
        .then(kw!(Else).ignore_then(stmts.clone()).or_not())
        .then(closing(Kw::If, empty()).map(|((), missing)| missing))
        .validate(unclosed!("if"))
        .map(|(((c, t), rest), els)| StmtKind::If {
            arms: first_and(c, t, rest),
            els,
        })
        // As for blocks below: an unclosed compound statement is tried again
        // by the recovery of the statement around it; remembering each
        // attempt by its position makes nested unclosed ones polynomial,
        // not exponential (40 levels: 0.1 s, where 14 took 0.7 s).
        .memoized();
    // Only where an `if` starts: no memo entry at every statement.
    let if_stmt = kw!(If).rewind().ignore_then(if_stmt);
    let case_stmt = kw!(Case)
        .ignore_then(expr.clone())
        .then_ignore(kw!(Is))
        .then(
            kw!(When)
                .ignore_then(choices.clone())
                .then_ignore(just(Token::Arrow))
                .then(stmts.clone())
                .map_with(|(choices, body), e| CaseArm {
                    choices,
                    body,
                    span: e.span(),
                })
                .repeated()
                .at_least(1)
                .collect::<Vec<_>>(),
        )
        .then(closing(Kw::Case, empty()).map(|((), missing)| missing))
        .validate(unclosed!("case"))
        .map(|(subject, arms)| StmtKind::Case {
            subject: Box::new(subject),
            arms,
        })
        .memoized();
    let case_stmt = kw!(Case).rewind().ignore_then(case_stmt);
    let scheme = choice((
        kw!(While).ignore_then(expr.clone()).map(LoopScheme::While),
        kw!(For)
            .ignore_then(ident())
            .then_ignore(kw!(Of))
            .then(kw!(Reverse).or_not())
            .then(expr.clone())
            .map(|((var, rev), array)| LoopScheme::ForOf {
                var,
                reverse: rev.is_some(),
                array,
            }),
        kw!(For)
            .ignore_then(ident())
            .then_ignore(kw!(In))
            .then(kw!(Reverse).or_not())
            .then(drange.clone())
            .map(|((var, rev), range)| LoopScheme::For {
                var,
                reverse: rev.is_some(),
                range,
            }),
    ))
    .then_ignore(soft_kw(Kw::Loop))
    .or(kw!(Loop).to(LoopScheme::Plain));
    let loop_stmt = label
        .clone()
        .or_not()
        .then(scheme)
        .then(stmts.clone())
        .then(closing(Kw::Loop, ident().or_not()))
        .map(|(x, (end_label, missing))| ((x, end_label), missing))
        .validate(unclosed!("loop"))
        .map(|(((label, scheme), body), end_label)| StmtKind::Loop {
            label: label.map(Box::new),
            scheme: Box::new(scheme),
            body,
            end_label: end_label.map(Box::new),
        })
        .memoized();
    // Only where a loop can start (as for blocks: no memo entry at every
    // statement).
    let loop_stmt = choice((
        kw!(For).ignored(),
        kw!(While).ignored(),
        kw!(Loop).ignored(),
        label.clone().ignored(),
    ))
    .rewind()
    .ignore_then(loop_stmt);
    // A `declare` block whose `end` never comes (the text ends first) is
    // reported once, as unclosed, and taken as ended: trying it again as
    // something else, level after level, took time quadratic in the nesting.
    // (A bare `begin` at the end of the text may be a body's, and is left to
    // the recovery of what encloses it.)
    let open_block = kw!(Begin)
        .ignore_then(stmts.clone())
        .then(
            kw!(Exception)
                .ignore_then(handler.clone().repeated().collect::<Vec<_>>())
                .or_not(),
        )
        .then(
            kw!(End)
                .ignore_then(ident().or_not())
                .ignore_then(semi())
                .to(None)
                .or(end().map_with(|_, e| Some(e.span()))),
        )
        .map_with(|((stmts, handlers), missing), e| {
            (
                Block {
                    stmts: stmts.into(),
                    handlers: handlers.unwrap_or_default(),
                    span: e.span(),
                    lazy: None,
                },
                missing,
            )
        });
    let declare_block = kw!(Declare)
        .ignore_then(decls.clone())
        .then(open_block)
        .validate(|(decls, (body, missing)), e, emitter| {
            if let Some(at) = missing {
                let whole: Span = e.span();
                emitter.emit(PErr::custom(at, format!("{UNCLOSED}block {}", whole.start)));
            }
            (Some(decls), body)
        });
    let plain_block = block
        .clone()
        .then_ignore(ident().or_not())
        .then_ignore(semi())
        .map(|body| (None, body));
    let block_stmt = label
        .clone()
        .or_not()
        .then(declare_block.or(plain_block))
        .map(|(label, (decls, body))| ((label, decls), body))
        .map(|((label, decls), body)| StmtKind::Block {
            label: label.map(Box::new),
            decls: decls.unwrap_or_default(),
            body: Box::new(body),
        })
        // An unclosed block statement is tried again after the recovery of
        // the statement around it; remembering each attempt by its position
        // keeps nested unclosed blocks from taking exponential time.
        .memoized();
    // Only where a block can start: a memo entry at every statement of a
    // long program would cost more memory than the statements.
    let block_stmt = choice((
        kw!(Declare).ignored(),
        kw!(Begin).ignored(),
        label.clone().ignored(),
    ))
    .rewind()
    .ignore_then(block_stmt);
    let exit_stmt = kw!(Exit)
        .ignore_then(ident().or_not())
        .then(kw!(When).ignore_then(expr.clone()).or_not())
        .then_ignore(semi())
        .map(|(label, cond)| StmtKind::Exit {
            label: label.map(Box::new),
            cond: cond.map(Box::new),
        });
    let return_stmt = kw!(Return)
        .ignore_then(expr.clone().or_not())
        .then_ignore(semi())
        .map(|e: Option<Expr>| StmtKind::Return(e.map(Box::new)));
    let raise_stmt = kw!(Raise)
        .ignore_then(name().or_not())
        .then(kw!(With).ignore_then(expr.clone()).or_not())
        .then_ignore(semi())
        .map(|(name, message)| StmtKind::Raise {
            name: name.map(Box::new),
            message: message.map(Box::new),
        });
    let delay_stmt = kw!(Delay)
        .ignore_then(kw!(Until).or_not())
        .then(expr.clone())
        .then_ignore(semi())
        .map(|(until, d)| StmtKind::Delay(until.is_some(), Box::new(d)));
    let abort_stmt = kw!(Abort)
        .ignore_then(
            expr.clone()
                .separated_by(just(Token::Comma))
                .at_least(1)
                .collect::<Vec<_>>(),
        )
        .then_ignore(semi())
        .map(StmtKind::Abort);
    // `accept E (I) ...`: a member of an entry family. A parameter list
    // `(X : T)` does not parse as `(expression)`, so the index is tried
    // first.
    let accept = kw!(Accept)
        .ignore_then(ident())
        .then(
            just(Token::LParen)
                .ignore_then(expr.clone())
                .then_ignore(just(Token::RParen))
                .or_not(),
        )
        .then(params(expr.clone()))
        .then(
            kw!(Do)
                .ignore_then(stmts.clone())
                .then(
                    kw!(Exception)
                        .ignore_then(handler.clone().repeated().collect::<Vec<_>>())
                        .or_not(),
                )
                .then_ignore(kw!(End))
                .then_ignore(ident().or_not())
                .map_with(|(stmts, handlers), e| Block {
                    stmts: stmts.into(),
                    handlers: handlers.unwrap_or_default(),
                    span: e.span(),
                    lazy: None,
                })
                .or_not(),
        )
        .then_ignore(semi())
        .map_with(|(((entry, index), params), body), e| Stmt {
            kind: StmtKind::Accept {
                entry: Box::new(entry),
                index: index.map(Box::new),
                params,
                body: body.map(Box::new),
            },
            span: e.span(),
        })
        .boxed();
    let select_alt = kw!(When)
        .ignore_then(expr.clone())
        .then_ignore(just(Token::Arrow))
        .or_not()
        .then(choice((
            accept
                .clone()
                .then(stmts.clone())
                .map(|(a, s)| SelectKind::Accept(Box::new(a), s)),
            kw!(Delay)
                .ignore_then(kw!(Until).or_not())
                .then(expr.clone())
                .then_ignore(semi())
                .then(stmts.clone())
                .map(|((until, d), s)| SelectKind::Delay(until.is_some(), d, s)),
            kw!(Terminate).then(semi()).to(SelectKind::Terminate),
            // An entry call: the first alternative of a timed or
            // conditional entry call.
            expr.clone()
                .then_ignore(semi())
                .then(stmts.clone())
                .map(|(c, s)| SelectKind::Call(c, s)),
        )))
        .map_with(|(guard, kind), e| SelectAlt {
            guard,
            kind,
            span: e.span(),
        });
    let select_stmt = kw!(Select)
        .ignore_then(
            select_alt
                .clone()
                .separated_by(kw!(Or))
                .at_least(1)
                .collect::<Vec<_>>(),
        )
        .then(
            kw!(Else)
                .ignore_then(stmts.clone())
                .map_with(|s, e| SelectAlt {
                    guard: None,
                    kind: SelectKind::Else(s),
                    span: e.span(),
                })
                .or_not(),
        )
        // `select ... then abort ... end select;`: parsed whole, then
        // refused as unsupported (no cascade of syntax errors).
        .then(
            kw!(Then)
                .then(kw!(Abort))
                .ignore_then(stmts.clone())
                .or_not(),
        )
        .then_ignore(kw!(End).then(kw!(Select)))
        .then_ignore(semi())
        .map_with(|((mut alts, els), abortable), e| {
            if abortable.is_some() {
                return StmtKind::Decl(Box::new(unsupported(
                    e.span(),
                    "an asynchronous select (`select ... then abort`)",
                )));
            }
            alts.extend(els);
            StmtKind::Select(alts)
        });
    let requeue = kw!(Requeue)
        .ignore_then(expr.clone())
        .then(kw!(With).then(kw!(Abort)).or_not())
        .then_ignore(semi())
        .map(|(target, abort)| StmtKind::Requeue {
            target: Box::new(target),
            abort: abort.is_some(),
        });
    let goto = kw!(Goto)
        .then(ident())
        .then(semi())
        .map_with(|_, e| StmtKind::Decl(Box::new(unsupported(e.span(), "`goto`"))));
    // A statement label `<<L>>` (labels exist for `goto` only).
    let stmt_label = just(Token::Lt)
        .then(just(Token::Lt))
        .then(ident())
        .then(just(Token::Gt))
        .then(just(Token::Gt))
        .map_with(|_, e| StmtKind::Decl(Box::new(unsupported(e.span(), "a statement label"))));
    let simple_stmt = expr
        .clone()
        .then(just(Token::Assign).ignore_then(expr.clone()).or_not())
        .then_ignore(soft_semi())
        .validate(|(target, value), _, emitter| match (target, value) {
            (t, Some(v)) => StmtKind::Assign(Box::new(t), Box::new(v)),
            // `X = 5;` as a statement: a beginner's assignment. Say so, and
            // go on as if it were one, so that this is the only error.
            (
                Expr {
                    kind: ExprKind::Binary(BinOp::Eq, l, r),
                    span,
                },
                None,
            ) => {
                emitter.emit(PErr::custom(
                    span,
                    D::custom(
                        codes::E0104,
                        "`=` compares; an assignment is written `:=` (`X := 5;`)",
                    ),
                ));
                StmtKind::Assign(l, r)
            }
            (t, None) => StmtKind::Call(Box::new(t)),
        });

    // A declaration in statement position (script mode): `X : T := ...;` etc.
    let decl_stmt = decl.clone().map(|d| StmtKind::Decl(Box::new(d)));

    let stmt_kind = choice((
        kw!(Null).then(semi()).to(StmtKind::Null),
        if_stmt,
        case_stmt,
        // An address clause among statements (script mode): `for R use at
        // A;`, or another representation clause (`for T'Size use 8;`).
        kw!(For)
            .then(ident())
            .then(just(Token::Tick).then(ident()).or_not())
            .then(kw!(Use))
            .rewind()
            .ignore_then(decl_stmt.clone()),
        stmt_label,
        loop_stmt,
        block_stmt,
        exit_stmt,
        return_stmt,
        raise_stmt,
        delay_stmt,
        abort_stmt,
        accept.clone().map(|s| s.kind),
        select_stmt,
        requeue,
        goto,
        // Declarations that start with an identifier and a colon, or a keyword.
        ident()
            .then(just(Token::Comma).or(just(Token::Colon)))
            .rewind()
            .ignore_then(decl_stmt.clone()),
        select! { Token::Kw(Kw::Type | Kw::Subtype | Kw::Procedure | Kw::Function | Kw::Package | Kw::Use | Kw::Pragma | Kw::Task | Kw::Generic | Kw::Protected) => () }
            .rewind()
            .ignore_then(decl_stmt),
        simple_stmt,
    ))
    .labelled("statement");
    stmt_kind
        .map_with(|kind, e| Stmt {
            kind,
            span: e.span(),
        })
        // A statement that does not parse: skipped to its `;`, but not
        // past a word that ends the sequence around it (`end`, `else`,
        // ...), which then closes its construct as written.
        .recover_with(via_parser(skip_to_semi().map(|_| Stmt {
            kind: StmtKind::Error,
            span: Span {
                start: 0,
                end: 0,
                context: 0,
            },
        })))
        .boxed()
}

/// A statement AdaIR does not support, kept as an unsupported declaration.
fn unsupported(span: Span, what: &'static str) -> Decl {
    Decl {
        kind: DeclKind::Unsupported(what),
        span,
    }
}
