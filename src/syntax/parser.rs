//! The chumsky parser: tokens -> AST, with error recovery so that one run
//! reports every syntax error of a file. Expressions use chumsky's Pratt
//! parser for the adding, multiplying and highest-precedence operators.

use super::ast::*;
use super::token::{Kw, Token};
use crate::diag::{Diagnostic, FileId, Span};
use chumsky::input::ValueInput;
use chumsky::pratt::{infix, left, none, prefix};
use chumsky::prelude::*;

/// A token and where it is.
pub type Tok = (Token, Span);

type Ex<'t> = extra::Err<Rich<'t, Token, Span>>;

/// Everything a parser function needs from its input.
pub trait TokIn<'t>: ValueInput<'t, Token = Token, Span = Span> {}
impl<'t, T: ValueInput<'t, Token = Token, Span = Span>> TokIn<'t> for T {}

macro_rules! kw {
    ($k:ident) => {
        just(Token::Kw(Kw::$k))
    };
}

fn ident<'t, I: TokIn<'t>>() -> impl Parser<'t, I, Ident, Ex<'t>> + Clone {
    select! { Token::Ident(s) = e => Ident::new(&s, e.span()) }.labelled("identifier")
}

fn semi<'t, I: TokIn<'t>>() -> impl Parser<'t, I, Token, Ex<'t>> + Clone {
    just(Token::Semi).labelled("`;`")
}

/// A reserved word that may be missing (`then`, `loop`): reported, and
/// parsing goes on as if it were there when a statement follows.
fn soft_kw<'t, I: TokIn<'t>>(k: Kw) -> impl Parser<'t, I, (), Ex<'t>> + Clone {
    let starts_stmt = select! {
        Token::Ident(_) => (),
        Token::Kw(Kw::If | Kw::For | Kw::While | Kw::Loop | Kw::Case | Kw::Return | Kw::Null | Kw::Raise | Kw::Exit | Kw::Declare | Kw::Begin | Kw::Delay) => (),
    };
    just(Token::Kw(k))
        .ignored()
        .or(starts_stmt.rewind().validate(move |_, e, emitter| {
            let sp: Span = e.span();
            emitter.emit(Rich::custom(
                Span {
                    start: sp.start,
                    end: sp.start,
                    context: sp.context,
                },
                format!("missing `{}`", k.as_str()),
            ));
        }))
}

/// The end of an `if`, `case` or `loop`: `end <word> <tail>;` (the tail's
/// output and None), or the place of a wrong end: a bare `end;` (taken as
/// this construct's end), or `end Name` (the end of the enclosing body, left
/// for it). Either way the statement is reported unclosed ([`UNCLOSED`])
/// and parsing goes on as if `end <word>;` had been there.
fn closing<'t, I: TokIn<'t>, O: Clone + Default + 't>(
    k: Kw,
    tail: impl Parser<'t, I, O, Ex<'t>> + Clone,
) -> impl Parser<'t, I, (O, Option<Span>), Ex<'t>> + Clone {
    let label = match k {
        Kw::Loop => "`end loop`",
        Kw::If => "`end if`",
        _ => "`end case`",
    };
    choice((
        just(Token::Kw(Kw::End))
            .ignore_then(just(Token::Kw(k)))
            .ignore_then(tail)
            .then_ignore(soft_semi())
            .map(|o| (o, None)),
        // A bare `end;` was meant for this construct: it is taken as its end.
        just(Token::Kw(Kw::End))
            .then(semi())
            .map_with(|_, e| (O::default(), Some(e.span()))),
        just(Token::Kw(Kw::End))
            .then_ignore(just(Token::Kw(k)).not())
            .map_with(|_, e| (O::default(), Some(e.span())))
            .rewind(),
        // The text ends first (an editor's unfinished text): the construct
        // is reported as unclosed and taken as ended. Failing instead made
        // the statement around it skip the rest of the text, level after
        // level: time quadratic in the nesting.
        end().map_with(|_, e| (O::default(), Some(e.span()))),
        // Another word that ends a statement sequence (`else`, `when`,
        // `exception`, ...): it belongs to what encloses the construct,
        // which is reported unclosed and taken as ended there, as for
        // `end Name` (failing made each enclosing level parse the rest again).
        seq_end()
            .and_is(just(Token::Kw(Kw::End)).not())
            .map_with(|_, e| (O::default(), Some(e.span())))
            .rewind(),
    ))
    .labelled(label)
}

/// The marker of the error [`closing`] leads to: `\u{1}WORD OFFSET` (the
/// construct's keyword and where its statement starts); `rich_to_diag`
/// turns it into the diagnostic.
const UNCLOSED: char = '\u{1}';

/// The `validate` step after [`closing`]: reports an unclosed `WORD`.
macro_rules! unclosed {
    ($word:literal) => {
        |(x, missing): (_, Option<Span>), e, emitter| {
            if let Some(at) = missing {
                let whole: Span = e.span();
                emitter.emit(Rich::custom(
                    at,
                    format!("{UNCLOSED}{} {}", $word, whole.start),
                ));
            }
            x
        }
    };
}

/// A `;` that may be missing: reports it, and parsing goes on as if it were
/// there, when the next token starts a new statement or declaration.
fn soft_semi<'t, I: TokIn<'t>>() -> impl Parser<'t, I, (), Ex<'t>> + Clone {
    let starts_next = select! {
        Token::Ident(_) => (),
        Token::Kw(Kw::Procedure | Kw::Function | Kw::Type | Kw::Subtype | Kw::Begin | Kw::End | Kw::If | Kw::For | Kw::While | Kw::Loop
            | Kw::Case | Kw::Return | Kw::Null | Kw::Raise | Kw::Exit | Kw::Declare | Kw::Package | Kw::Exception | Kw::Delay) => (),
    };
    just(Token::Semi)
        .ignored()
        .or(starts_next.rewind().validate(|_, e, emitter| {
            let sp: Span = e.span();
            emitter.emit(Rich::custom(
                Span {
                    start: sp.start,
                    end: sp.start,
                    context: sp.context,
                },
                "missing `;`",
            ));
        }))
}

/// `:=` before an initial value or a default; `=` there is a beginner's
/// slip, reported once and read as `:=`.
fn assign_or_eq<'t, I: TokIn<'t>>() -> impl Parser<'t, I, (), Ex<'t>> + Clone {
    just(Token::Assign)
        .ignored()
        .or(just(Token::Eq).validate(|_, e, emitter| {
            emitter.emit(Rich::custom(
                e.span(),
                "`=` compares; an initial value is given with `:=` (`V : Float := 50.0;`)",
            ));
        }))
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

/// An attribute designator: an identifier or one of the reserved words that
/// are also attribute names.
fn attr_name<'t, I: TokIn<'t>>() -> impl Parser<'t, I, Ident, Ex<'t>> + Clone {
    select! {
        Token::Ident(s) = e => Ident::new(&s, e.span()),
        Token::Kw(Kw::Range) = e => Ident::new("Range", e.span()),
        Token::Kw(Kw::Digits) = e => Ident::new("Digits", e.span()),
        Token::Kw(Kw::Access) = e => Ident::new("Access", e.span()),
        Token::Kw(Kw::Delta) = e => Ident::new("Delta", e.span()),
    }
    .labelled("attribute name")
}

/// The expression parser (and the name parser built from the same pieces).
pub fn expr<'t, I: TokIn<'t>>() -> Boxed<'t, 't, I, Expr, Ex<'t>> {
    recursive(|expr| {
        let expr: Boxed<'t, 't, I, Expr, Ex<'t>> = expr.boxed();
        let simple = simple_expr(expr.clone());
        let range_tail = just(Token::DotDot).ignore_then(simple.clone());
        let choice_p = kw!(Others)
            .map_with(|_, e| Choice::Others(e.span()))
            .or(simple
                .clone()
                .then(range_tail.clone().or_not())
                .map(|(a, b)| match b {
                    Some(b) => Choice::Range(a, b),
                    None => Choice::Expr(a),
                }))
            .boxed();
        let relop = select! {
            Token::Eq => BinOp::Eq, Token::Ne => BinOp::Ne, Token::Lt => BinOp::Lt,
            Token::Le => BinOp::Le, Token::Gt => BinOp::Gt, Token::Ge => BinOp::Ge,
        };
        #[derive(Clone)]
        enum Tail {
            Rel(BinOp, Expr),
            In(bool, Vec<Choice>),
        }
        let relation = simple
            .clone()
            .then(
                choice((
                    relop.then(simple.clone()).map(|(o, b)| Tail::Rel(o, b)),
                    kw!(Not)
                        .or_not()
                        .then_ignore(kw!(In))
                        .then(
                            choice_p
                                .clone()
                                .separated_by(just(Token::Bar))
                                .at_least(1)
                                .collect(),
                        )
                        .map(|(n, c)| Tail::In(n.is_some(), c)),
                ))
                .or_not(),
            )
            .map_with(|(a, t), e| match t {
                None => a,
                Some(Tail::Rel(o, b)) => {
                    mk(ExprKind::Binary(o, Box::new(a), Box::new(b)), e.span())
                }
                Some(Tail::In(negated, choices)) => mk(
                    ExprKind::Membership {
                        negated,
                        subject: Box::new(a),
                        choices,
                    },
                    e.span(),
                ),
            })
            .boxed();
        let logop = choice((
            kw!(And).then(kw!(Then)).to(BinOp::AndThen),
            kw!(Or).then(kw!(Else)).to(BinOp::OrElse),
            kw!(And).to(BinOp::And),
            kw!(Or).to(BinOp::Or),
            kw!(Xor).to(BinOp::Xor),
        ));
        // Ada: a chain of one logical operator only (`A and B or C` needs
        // parentheses).
        relation
            .clone()
            .then(
                logop
                    .map_with(|op, e| (op, e.span()))
                    .then(relation)
                    .repeated()
                    .collect::<Vec<_>>(),
            )
            .validate(|(first, rest), _, emitter| {
                if let Some(w) = rest.windows(2).find(|w| w[0].0.0 != w[1].0.0) {
                    let (a, b) = (w[0].0.0.symbol(), w[1].0.0.symbol());
                    emitter.emit(Rich::custom(
                        w[1].0.1,
                        format!(
                            "`{a}` and `{b}` mixed without parentheses: write `(X {a} Y) {b} Z`"
                        ),
                    ));
                }
                rest.into_iter().fold(first, |a, ((op, _), b)| {
                    let sp = join(a.span, b.span);
                    mk(ExprKind::Binary(op, Box::new(a), Box::new(b)), sp)
                })
            })
            .labelled("expression")
            .boxed()
    })
    .boxed()
}

/// A choice of a `case` alternative: `others`, a value or a range.
fn case_choice<'t, I: TokIn<'t>>(
    simple: impl Parser<'t, I, Expr, Ex<'t>> + Clone + 't,
) -> Boxed<'t, 't, I, Choice, Ex<'t>> {
    kw!(Others)
        .map_with(|_, e| Choice::Others(e.span()))
        .or(simple
            .clone()
            .then(just(Token::DotDot).ignore_then(simple.clone()).or_not())
            .map(|(a, b)| match b {
                Some(b) => Choice::Range(a, b),
                None => Choice::Expr(a),
            }))
        .boxed()
}

/// An `if` or `case` expression without its parentheses: they are those of
/// a parenthesised expression or, for the sole argument of a call, the
/// call's own (`Put_Line (if X then "a" else "b")`).
fn cond_expr<'t, I: TokIn<'t>>(
    expr: Boxed<'t, 't, I, Expr, Ex<'t>>,
    simple: impl Parser<'t, I, Expr, Ex<'t>> + Clone + 't,
) -> Boxed<'t, 't, I, Expr, Ex<'t>> {
    let choice_p = case_choice(simple);
    let if_expr = kw!(If)
        .ignore_then(expr.clone())
        .then_ignore(kw!(Then))
        .then(expr.clone())
        .then(
            kw!(Elsif)
                .ignore_then(expr.clone())
                .then_ignore(kw!(Then))
                .then(expr.clone())
                .repeated()
                .collect::<Vec<_>>(),
        )
        .then(kw!(Else).ignore_then(expr.clone()).or_not())
        .map_with(|(((c, t), rest), els), e| {
            mk(
                ExprKind::If {
                    arms: first_and(c, t, rest),
                    els: els.map(Box::new),
                },
                e.span(),
            )
        });
    let case_expr = kw!(Case)
        .ignore_then(expr.clone())
        .then_ignore(kw!(Is))
        .then(
            kw!(When)
                .ignore_then(
                    choice_p
                        .clone()
                        .separated_by(just(Token::Bar))
                        .at_least(1)
                        .collect(),
                )
                .then_ignore(just(Token::Arrow))
                .then(expr.clone())
                .map_with(|(choices, body), e| CaseArm {
                    choices,
                    body,
                    span: e.span(),
                })
                .separated_by(just(Token::Comma))
                .at_least(1)
                .collect(),
        )
        .map_with(|(s, arms), e| {
            mk(
                ExprKind::Case {
                    subject: Box::new(s),
                    arms,
                },
                e.span(),
            )
        });
    if_expr.or(case_expr).boxed()
}

/// A parenthesised part: `(expr)`, an aggregate, an `if`/`case` expression.
fn paren_part<'t, I: TokIn<'t>>(
    expr: Boxed<'t, 't, I, Expr, Ex<'t>>,
    simple: impl Parser<'t, I, Expr, Ex<'t>> + Clone + 't,
    cond: Boxed<'t, 't, I, Expr, Ex<'t>>,
) -> Boxed<'t, 't, I, Expr, Ex<'t>> {
    let choice_p = case_choice(simple.clone());
    let value = expr
        .clone()
        .or(just(Token::Box).map_with(|_, e| mk(ExprKind::Error, e.span())));
    // The first part of an association is parsed once (as a full expression,
    // or `others`), and only then is it decided whether it was a choice:
    // parsing it both ways would take time exponential in the nesting depth.
    let head = kw!(Others)
        .map_with(|_, e| Err::<Expr, Span>(e.span()))
        .or(expr.clone().map(Ok));
    let assoc = head
        .then(just(Token::DotDot).ignore_then(simple.clone()).or_not())
        .then(
            just(Token::Bar)
                .ignore_then(choice_p.clone())
                .repeated()
                .collect::<Vec<_>>(),
        )
        .then(just(Token::Arrow).ignore_then(value).or_not())
        .validate(|(((head, hi), more), value), e, emitter| {
            let span: Span = e.span();
            let first = match (head, hi) {
                (Err(s), _) => Choice::Others(s),
                (Ok(a), Some(b)) => Choice::Range(a, b),
                (Ok(a), None) => Choice::Expr(a),
            };
            match (value, first) {
                (Some(v), first) => {
                    let mut choices = vec![first];
                    choices.extend(more);
                    Assoc {
                        choices,
                        value: v,
                        span,
                    }
                }
                (None, Choice::Expr(a)) if more.is_empty() => Assoc {
                    choices: Vec::new(),
                    value: a,
                    span,
                },
                (None, _) => {
                    emitter.emit(Rich::custom(span, "a choice needs `=>` and a value"));
                    Assoc {
                        choices: Vec::new(),
                        value: mk(ExprKind::Error, span),
                        span,
                    }
                }
            }
        });
    choice((
        cond,
        assoc
            .separated_by(just(Token::Comma))
            .at_least(1)
            .collect::<Vec<_>>()
            .map_with(|mut items, e| {
                if items.len() == 1 && items[0].choices.is_empty() {
                    let v = items.remove(0).value;
                    mk(ExprKind::Paren(Box::new(v)), e.span())
                } else {
                    mk(ExprKind::Aggregate(items), e.span())
                }
            }),
    ))
    .delimited_by(just(Token::LParen), just(Token::RParen))
    .map_with(|mut x, e| {
        x.span = e.span();
        x
    })
    .boxed()
}

/// Names: identifiers followed by selections, `.all`, argument lists,
/// attributes and qualifications.
fn name_with<'t, I: TokIn<'t>>(
    expr: Boxed<'t, 't, I, Expr, Ex<'t>>,
    paren: Boxed<'t, 't, I, Expr, Ex<'t>>,
    cond: Boxed<'t, 't, I, Expr, Ex<'t>>,
) -> Boxed<'t, 't, I, Expr, Ex<'t>> {
    #[derive(Clone)]
    enum Suffix {
        Sel(Ident),
        All,
        Args(Vec<Arg>),
        Attr(Ident, Vec<Expr>),
        Qual(Expr),
    }
    let arg = ident()
        .then_ignore(just(Token::Arrow))
        .or_not()
        .then(
            expr.clone()
                .then(just(Token::DotDot).ignore_then(expr.clone()).or_not()),
        )
        .map_with(|(name, (v, hi)), e| {
            let value = match hi {
                // A slice `A (L .. H)`: kept as a one-element aggregate with a range choice.
                Some(hi) => {
                    let sp = join(v.span, hi.span);
                    mk(
                        ExprKind::Aggregate(vec![Assoc {
                            choices: vec![Choice::Range(v, hi)],
                            value: mk(ExprKind::Error, sp),
                            span: sp,
                        }]),
                        sp,
                    )
                }
                None => v,
            };
            Arg {
                name,
                value,
                span: e.span(),
            }
        });
    let op_symbol = select! { Token::Str(s) = e => Ident::new(&format!("\"{s}\""), e.span()) };
    let suffix = choice((
        just(Token::Dot).ignore_then(kw!(All)).to(Suffix::All),
        just(Token::Dot)
            .ignore_then(ident().or(op_symbol))
            .map(Suffix::Sel),
        just(Token::Tick)
            .ignore_then(paren.clone())
            .map(Suffix::Qual),
        just(Token::Tick)
            .ignore_then(attr_name())
            .then(
                // `T'Image (if X then 1 else 2)`: as for a call, an `if`/`case`
                // expression as the sole argument shares the parentheses.
                cond.clone()
                    .map(|c| vec![c])
                    .or(expr
                        .clone()
                        .separated_by(just(Token::Comma))
                        .at_least(1)
                        .collect::<Vec<_>>())
                    .delimited_by(just(Token::LParen), just(Token::RParen))
                    .or_not(),
            )
            .map(|(a, args)| Suffix::Attr(a, args.unwrap_or_default())),
        // An `if`/`case` expression as the sole argument shares the call's
        // parentheses; it starts with a keyword, so trying it first costs
        // one token.
        cond.map_with(|value, e| {
            vec![Arg {
                name: None,
                value,
                span: e.span(),
            }]
        })
        .or(arg
            .separated_by(just(Token::Comma))
            .at_least(1)
            .collect::<Vec<_>>()
            .map(exact))
        .delimited_by(just(Token::LParen), just(Token::RParen))
        .map(Suffix::Args),
    ));
    let head = ident().map(|i| {
        let sp = i.span;
        mk(ExprKind::Name(i), sp)
    });
    head.foldl_with(suffix.repeated(), |p, s, e| {
        let sp = e.span();
        let b = Box::new(p);
        match s {
            Suffix::Sel(i) => mk(ExprKind::Select(b, i), sp),
            Suffix::All => mk(ExprKind::Deref(b), sp),
            Suffix::Args(a) => mk(ExprKind::Apply(b, a), sp),
            Suffix::Attr(a, args) => mk(ExprKind::Attr(b, a, args), sp),
            Suffix::Qual(x) => mk(ExprKind::Qualified(b, Box::new(x)), sp),
        }
    })
    .labelled("name")
    .boxed()
}

fn simple_expr<'t, I: TokIn<'t>>(
    expr: Boxed<'t, 't, I, Expr, Ex<'t>>,
) -> Boxed<'t, 't, I, Expr, Ex<'t>> {
    recursive(|simple| {
        let simple: Boxed<'t, 't, I, Expr, Ex<'t>> = simple.boxed();
        let cond = cond_expr(expr.clone(), simple.clone());
        let paren = paren_part(expr.clone(), simple.clone(), cond.clone());
        let name = name_with(expr.clone(), paren.clone(), cond);
        let literal = select! {
            Token::Int(i) = e => mk(ExprKind::Int(i), e.span()),
            Token::Real(r) = e => mk(ExprKind::Real(r), e.span()),
            Token::Char(c) = e => mk(ExprKind::Char(c), e.span()),
            Token::Str(s) = e => mk(ExprKind::Str(s.to_string()), e.span()),
            Token::Kw(Kw::Null) = e => mk(ExprKind::Null, e.span()),
            Token::Error = e => mk(ExprKind::Error, e.span()),
        };
        // An operator symbol used as a function name: `"*" (A, B)`,
        // `"abs" (X)`: the same as the operator, so predefined and user
        // operators resolve alike. Only a string that names an operator and
        // is followed by `(` is taken (a string literal cannot be called).
        let op_call = select! { Token::Str(s) = e => (s, e.span()) }
            .try_map(|(s, sp): (std::rc::Rc<str>, Span), _| {
                operator_of(&s).map(|o| (o, sp)).ok_or_else(|| Rich::custom(sp, "not an operator symbol"))
            })
            .then(
                expr.clone()
                    .separated_by(just(Token::Comma))
                    .at_least(1)
                    .at_most(2)
                    .collect::<Vec<_>>()
                    .delimited_by(just(Token::LParen), just(Token::RParen)),
            )
            .validate(|((op, _), mut args), e, emitter| {
                let sp: Span = e.span();
                match (op, args.len()) {
                    (OpSym::Bin(b), 2) => {
                        let r = args.pop().map(Box::new);
                        let l = args.pop().map(Box::new);
                        match (l, r) {
                            (Some(l), Some(r)) => mk(ExprKind::Binary(b, l, r), sp),
                            _ => mk(ExprKind::Error, sp),
                        }
                    }
                    (OpSym::Un(u), 1) | (OpSym::Both(_, u), 1) => {
                        mk(ExprKind::Unary(u, Box::new(args.remove(0))), sp)
                    }
                    (OpSym::Both(b, _), 2) => {
                        let r = Box::new(args.remove(1));
                        let l = Box::new(args.remove(0));
                        mk(ExprKind::Binary(b, l, r), sp)
                    }
                    _ => {
                        emitter.emit(Rich::custom(
                            sp,
                            "this operator takes a different number of operands",
                        ));
                        mk(ExprKind::Error, sp)
                    }
                }
            });
        let allocator = kw!(New).ignore_then(name.clone()).map_with(|n, e| {
            let sp = e.span();
            match n.kind {
                ExprKind::Qualified(t, v) => mk(ExprKind::Allocator(t, Some(v)), sp),
                _ => mk(ExprKind::Allocator(Box::new(n), None), sp),
            }
        });
        let primary = choice((op_call, literal, allocator, name, paren))
            .labelled("expression")
            .boxed();
        primary
            .pratt((
                infix(none(6), just(Token::StarStar), |a: Expr, _, b: Expr, e| {
                    mk(ExprKind::Binary(BinOp::Pow, Box::new(a), Box::new(b)), e.span())
                }),
                prefix(7, kw!(Abs), |_, a: Expr, e| mk(ExprKind::Unary(UnOp::Abs, Box::new(a)), e.span())),
                prefix(7, kw!(Not), |_, a: Expr, e| mk(ExprKind::Unary(UnOp::Not, Box::new(a)), e.span())),
                infix(
                    left(4),
                    select! { Token::Star => BinOp::Mul, Token::Slash => BinOp::Div, Token::Kw(Kw::Mod) => BinOp::Mod, Token::Kw(Kw::Rem) => BinOp::Rem },
                    |a: Expr, op, b: Expr, e| mk(ExprKind::Binary(op, Box::new(a), Box::new(b)), e.span()),
                ),
                prefix(3, just(Token::Minus), |_, a: Expr, e| mk(ExprKind::Unary(UnOp::Neg, Box::new(a)), e.span())),
                prefix(3, just(Token::Plus), |_, a: Expr, e| mk(ExprKind::Unary(UnOp::Plus, Box::new(a)), e.span())),
                infix(
                    left(2),
                    select! { Token::Plus => BinOp::Add, Token::Minus => BinOp::Sub, Token::Amp => BinOp::Cat },
                    |a: Expr, op, b: Expr, e| mk(ExprKind::Binary(op, Box::new(a), Box::new(b)), e.span()),
                ),
            ))
            .validate(|x, _, emitter| {
                unary_sign_first(&x, true, &mut |sp| {
                    emitter.emit(Rich::custom(
                        sp,
                        "a unary `-` or `+` only begins an expression: put this operand in parentheses (`2 * (-3)`)",
                    ))
                });
                x
            })
            .boxed()
    })
    .boxed()
}

/// Ada's simple expression: a unary `+`/`-` only at its start (`-A * B`,
/// `-A + B`), never after another operator (`2 * -3`, `A + -B`, `abs -3`,
/// `2 ** -1`). Walks the operators of one simple expression; parentheses,
/// calls and other primaries were checked as their own expressions.
fn unary_sign_first(e: &Expr, first: bool, bad: &mut impl FnMut(Span)) {
    // An operator called by its symbol (`"abs" (-4)`) is a primary: its
    // operands end before its closing parenthesis.
    let last = match &e.kind {
        ExprKind::Unary(_, a) | ExprKind::Binary(_, _, a) => a.span.end,
        _ => return,
    };
    if last != e.span.end {
        return;
    }
    match &e.kind {
        ExprKind::Unary(UnOp::Neg | UnOp::Plus, a) => {
            if !first {
                bad(e.span);
            }
            unary_sign_first(a, false, bad);
        }
        ExprKind::Unary(_, a) => unary_sign_first(a, false, bad),
        ExprKind::Binary(BinOp::Add | BinOp::Sub | BinOp::Cat, l, r) => {
            unary_sign_first(l, first, bad);
            unary_sign_first(r, false, bad);
        }
        ExprKind::Binary(BinOp::Mul | BinOp::Div | BinOp::Mod | BinOp::Rem | BinOp::Pow, l, r) => {
            unary_sign_first(l, false, bad);
            unary_sign_first(r, false, bad);
        }
        _ => {}
    }
}

/// A bare name (for `with`, `use`, subtype marks, exception choices).
pub fn name<'t, I: TokIn<'t>>() -> Boxed<'t, 't, I, Expr, Ex<'t>> {
    ident()
        .map(|i| {
            let sp = i.span;
            mk(ExprKind::Name(i), sp)
        })
        .foldl_with(
            just(Token::Dot).ignore_then(ident()).repeated(),
            |p, i, e| mk(ExprKind::Select(Box::new(p), i), e.span()),
        )
        .labelled("name")
        .boxed()
}

fn subtype_ind<'t, I: TokIn<'t>>(
    expr: Boxed<'t, 't, I, Expr, Ex<'t>>,
) -> Boxed<'t, 't, I, SubtypeInd, Ex<'t>> {
    let simple = expr.clone();
    let range_c = kw!(Range)
        .ignore_then(simple.clone())
        .then_ignore(just(Token::DotDot))
        .then(simple.clone())
        .map(|(a, b)| Constraint::Range(Box::new(a), Box::new(b)));
    let dr = discrete_range(expr.clone());
    let index_c = dr
        .separated_by(just(Token::Comma))
        .at_least(1)
        .collect()
        .delimited_by(just(Token::LParen), just(Token::RParen))
        .map(Constraint::Index);
    name()
        .then(range_c.or(index_c).or_not())
        .map_with(|(mark, constraint), e| SubtypeInd {
            mark,
            constraint,
            span: e.span(),
        })
        .labelled("subtype")
        .boxed()
}

fn discrete_range<'t, I: TokIn<'t>>(
    expr: Boxed<'t, 't, I, Expr, Ex<'t>>,
) -> Boxed<'t, 't, I, DiscreteRange, Ex<'t>> {
    // `A .. B`, `T range A .. B`, `T`, `X'Range`: parse an expression first.
    expr.clone()
        .then(
            choice((
                just(Token::DotDot)
                    .ignore_then(expr.clone())
                    .map(|b| (Some(b), None)),
                kw!(Range)
                    .ignore_then(expr.clone())
                    .then_ignore(just(Token::DotDot))
                    .then(expr.clone())
                    .map(|(a, b)| (Some(a), Some(b))),
            ))
            .or_not(),
        )
        .map_with(|(a, rest), e| match rest {
            Some((Some(b), None)) => DiscreteRange::Range(a, b),
            Some((Some(lo), Some(hi))) => DiscreteRange::Subtype(SubtypeInd {
                mark: a,
                constraint: Some(Constraint::Range(Box::new(lo), Box::new(hi))),
                span: e.span(),
            }),
            _ => match &a.kind {
                ExprKind::Attr(_, at, _) if &*at.key == "range" => DiscreteRange::Attr(a),
                _ => DiscreteRange::Subtype(SubtypeInd {
                    mark: a,
                    constraint: None,
                    span: e.span(),
                }),
            },
        })
        .boxed()
}

/// The recovery of a statement or declaration that does not parse: the
/// tokens up to and with its `;`, or up to (without) a word that ends a
/// statement sequence or a declarative part.
fn skip_to_semi<'t, I: TokIn<'t>>() -> impl Parser<'t, I, (), Ex<'t>> + Clone {
    any()
        .and_is(choice((just(Token::Semi).ignored(), seq_end(), decls_end())).not())
        .repeated()
        .at_least(1)
        .then(just(Token::Semi).or_not())
        .ignored()
}

/// Tokens that end a statement sequence (never the start of a statement).
fn seq_end<'t, I: TokIn<'t>>() -> impl Parser<'t, I, (), Ex<'t>> + Clone {
    choice((
        select! {
            Token::Kw(Kw::End) => (), Token::Kw(Kw::Elsif) => (), Token::Kw(Kw::Else) => (),
            Token::Kw(Kw::When) => (), Token::Kw(Kw::Exception) => (), Token::Kw(Kw::Or) => (),
        },
        // `select ... then abort` (a lone `then` is a broken `if`'s: the
        // statement's recovery skips it).
        just(Token::Kw(Kw::Then))
            .then(just(Token::Kw(Kw::Abort)))
            .ignored(),
    ))
}

/// Tokens that end a declarative part.
fn decls_end<'t, I: TokIn<'t>>() -> impl Parser<'t, I, (), Ex<'t>> + Clone {
    select! {
        Token::Kw(Kw::End) => (), Token::Kw(Kw::Begin) => (), Token::Kw(Kw::Private) => (),
    }
}

fn params<'t, I: TokIn<'t>>(
    expr: Boxed<'t, 't, I, Expr, Ex<'t>>,
) -> Boxed<'t, 't, I, Vec<Param>, Ex<'t>> {
    let mode = choice((
        kw!(In).then(kw!(Out)).to(Mode::InOut),
        select! { Token::Ident(s) if s.eq_ignore_ascii_case("inout") => () }
            .then(ident().rewind())
            .validate(|_, e, emitter| {
                emitter.emit(Rich::custom(
                    e.span(),
                    "`inout` is not a parameter mode: write `in out`",
                ));
            })
            .to(Mode::InOut),
        kw!(In).to(Mode::In),
        kw!(Out).to(Mode::Out),
    ))
    .or_not()
    .map(|m| m.unwrap_or(Mode::In));
    ident()
        .separated_by(just(Token::Comma))
        .at_least(1)
        .collect::<Vec<_>>()
        .then_ignore(just(Token::Colon))
        .then(mode)
        .then(kw!(Access).or_not().ignore_then(name()))
        .then(assign_or_eq().ignore_then(expr).or_not())
        .map_with(|(((names, mode), ty), default), e| Param {
            names,
            mode,
            ty,
            default,
            span: e.span(),
        })
        .separated_by(semi())
        .at_least(1)
        .collect::<Vec<_>>()
        .delimited_by(just(Token::LParen), just(Token::RParen))
        .or_not()
        .map(|p| p.unwrap_or_default())
        .boxed()
}

fn subprogram_spec<'t, I: TokIn<'t>>(
    expr: Boxed<'t, 't, I, Expr, Ex<'t>>,
) -> Boxed<'t, 't, I, SubprogramSpec, Ex<'t>> {
    let designator = ident()
        .map(Designator::Ident)
        .or(select! { Token::Str(s) = e => Designator::Op(s.to_string(), e.span()) });
    let proc = kw!(Procedure)
        .ignore_then(designator.clone())
        .then(params(expr.clone()))
        .map_with(|(name, params), e| SubprogramSpec {
            name,
            params,
            ret: None,
            span: e.span(),
        });
    let func = kw!(Function)
        .ignore_then(designator)
        .then(params(expr))
        .then_ignore(kw!(Return))
        .then(name())
        .map_with(|((name, params), ret), e| SubprogramSpec {
            name,
            params,
            ret: Some(ret),
            span: e.span(),
        });
    proc.or(func).boxed()
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

    // A subprogram body whose statements are only recognised: chumsky
    // checks them without building them (`ignored`), and the block keeps
    // where they are.
    let body_block = if lazy {
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

/// The statement, over the shared parts.
fn stmt_grammar<'t, I: TokIn<'t>>(
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
                emitter.emit(Rich::custom(at, format!("{UNCLOSED}block {}", whole.start)));
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
    // `accept E (I) ...` of an entry family: refused as unsupported (once
    // more if the declaration was), and the rest read on (no cascade).
    let accept = kw!(Accept)
        .ignore_then(ident())
        .then_ignore(
            just(Token::LParen)
                .then(expr.clone())
                .then(just(Token::RParen))
                .validate(|_, e, emitter| {
                    emitter.emit(Rich::custom(
                        e.span(),
                        "an entry family is not supported by AdaIR (see docs/differences.md)",
                    ))
                })
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
        .map_with(|((entry, params), body), e| Stmt {
            kind: StmtKind::Accept {
                entry: Box::new(entry),
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
        .then(expr.clone())
        .then(kw!(With).then(kw!(Abort)).or_not())
        .then(semi())
        .map_with(|_, e| StmtKind::Decl(Box::new(unsupported(e.span(), "`requeue`"))));
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
                emitter.emit(Rich::custom(
                    span,
                    "`=` compares; an assignment is written `:=` (`X := 5;`)",
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

/// The declaration, over the shared parts.
fn decl_grammar<'t, I: TokIn<'t>>(
    c: &Common<'t, I>,
    decl: &Boxed<'t, 't, I, Decl, Ex<'t>>,
) -> Boxed<'t, 't, I, Decl, Ex<'t>> {
    let Common {
        expr,
        st_ind,
        drange,
        stmts,
        decls,
        handler,
        block,
        body_block,
        end_name,
    } = c;

    // ---- declarations ----
    let names = ident()
        .separated_by(just(Token::Comma))
        .at_least(1)
        .collect::<Vec<_>>()
        .boxed();
    let init = assign_or_eq().ignore_then(expr.clone()).or_not();
    let enum_lit = ident()
        .map(EnumLit::Ident)
        .or(select! { Token::Char(c) = e => EnumLit::Char(c, e.span()) });
    let array_def = kw!(Array)
        .ignore_then(
            choice((
                name()
                    .then_ignore(kw!(Range))
                    .then_ignore(just(Token::Box))
                    .separated_by(just(Token::Comma))
                    .at_least(1)
                    .collect::<Vec<_>>()
                    .map(ArrayIndex::Unconstrained),
                drange
                    .clone()
                    .separated_by(just(Token::Comma))
                    .at_least(1)
                    .collect::<Vec<_>>()
                    .map(ArrayIndex::Constrained),
            ))
            .delimited_by(just(Token::LParen), just(Token::RParen)),
        )
        .then_ignore(kw!(Of))
        .then_ignore(kw!(Aliased).or_not())
        .then(st_ind.clone())
        .map(|(index, elem)| TypeDef::Array { index, elem })
        .boxed();
    let component = names
        .clone()
        .then_ignore(just(Token::Colon))
        .then_ignore(kw!(Aliased).or_not())
        .then(st_ind.clone())
        .then(init.clone())
        .then_ignore(semi())
        .map_with(|((names, ty), default), e| Component {
            names,
            ty,
            default,
            span: e.span(),
        });
    let record_body = kw!(Null)
        .then(semi())
        .to(Vec::new())
        .or(component.repeated().at_least(1).collect::<Vec<_>>())
        .delimited_by(kw!(Record), kw!(End).then(kw!(Record)))
        .or(kw!(Null).then(kw!(Record)).to(Vec::new()));
    let type_def = choice((
        enum_lit
            .separated_by(just(Token::Comma))
            .at_least(1)
            .collect::<Vec<_>>()
            .delimited_by(just(Token::LParen), just(Token::RParen))
            .map(TypeDef::Enum),
        kw!(Range)
            .ignore_then(expr.clone())
            .then_ignore(just(Token::DotDot))
            .then(expr.clone())
            .map(|(a, b)| TypeDef::IntRange(a, b)),
        kw!(Digits)
            .ignore_then(expr.clone())
            .then(
                kw!(Range)
                    .ignore_then(expr.clone())
                    .then_ignore(just(Token::DotDot))
                    .then(expr.clone())
                    .or_not(),
            )
            .map(|(digits, range)| TypeDef::Float { digits, range }),
        // `new Shape with record ... end record` (or `with null record`,
        // `with private`): an extension of a tagged type.
        kw!(New)
            .then(st_ind.clone())
            .then(kw!(With))
            .then(choice((
                record_body.clone().ignored(),
                kw!(Private).ignored(),
            )))
            .to(TypeDef::Unsupported(
                "a type extension (`new T with record`)",
            )),
        kw!(New).ignore_then(st_ind.clone()).map(TypeDef::Derived),
        array_def.clone(),
        record_body.clone().map(TypeDef::Record),
        kw!(Tagged)
            .then(record_body.clone())
            .to(TypeDef::Unsupported("a tagged type")),
        kw!(Abstract)
            .then(kw!(Tagged))
            .then(record_body.clone())
            .to(TypeDef::Unsupported("an abstract tagged type")),
        kw!(Limited)
            .then(kw!(Private))
            .to(TypeDef::Unsupported("a private type")),
        kw!(Private).to(TypeDef::Unsupported("a private type")),
        kw!(Mod)
            .ignore_then(expr.clone())
            .to(TypeDef::Unsupported("a modular type")),
        kw!(Delta)
            .ignore_then(expr.clone())
            .then(
                kw!(Range)
                    .then(expr.clone())
                    .then(just(Token::DotDot))
                    .then(expr.clone())
                    .or_not(),
            )
            .to(TypeDef::Unsupported("a fixed-point type")),
        kw!(Access)
            .ignore_then(kw!(All).or(kw!(Constant)).or_not())
            .ignore_then(st_ind.clone())
            .map(TypeDef::Access),
    ));
    // `type R (N : Integer) is ...`, `task type T (Id : Integer) is ...`:
    // said once, and the rest of the declaration is read as without them.
    let discriminants = params(expr.clone()).validate(|ps, e, emitter| {
        if !ps.is_empty() {
            emitter.emit(Rich::custom(
                e.span(),
                "discriminants are not supported by AdaIR (see docs/differences.md)",
            ));
        }
    });
    let type_decl = kw!(Type)
        .ignore_then(ident())
        .then_ignore(discriminants.clone())
        .then(kw!(Is).ignore_then(type_def).or_not())
        .then_ignore(semi())
        .map(|(name, def)| DeclKind::Type {
            name,
            def: def.unwrap_or(TypeDef::Incomplete),
        });
    let subtype_decl = kw!(Subtype)
        .ignore_then(ident())
        .then_ignore(kw!(Is))
        .then(st_ind.clone())
        .then_ignore(semi())
        .map(|(name, ind)| DeclKind::Subtype { name, ind });
    #[derive(Clone)]
    enum ObjTail {
        Exception,
        Number(Expr),
        Object(bool, SubtypeInd, Option<Expr>),
        AnonArray(bool, TypeDef, Span, Option<Expr>),
        Renames,
    }
    let object_decl = names
        .clone()
        .then_ignore(just(Token::Colon))
        .then(choice((
            kw!(Exception).to(ObjTail::Exception),
            kw!(Constant)
                .ignore_then(just(Token::Assign))
                .ignore_then(expr.clone())
                .map(ObjTail::Number),
            kw!(Constant)
                .or_not()
                .then_ignore(kw!(Aliased).or_not())
                .then(array_def.clone().map_with(|d, e| (d, e.span())))
                .then(init.clone())
                .map(|((c, (d, sp)), i)| ObjTail::AnonArray(c.is_some(), d, sp, i)),
            kw!(Aliased)
                .or_not()
                .ignore_then(kw!(Constant).or_not())
                .then_ignore(kw!(Aliased).or_not())
                .then(st_ind.clone())
                .then(kw!(Renames).then(expr.clone()).or_not())
                .then(init.clone())
                .map(|(((c, t), ren), i)| {
                    if ren.is_some() {
                        ObjTail::Renames
                    } else {
                        ObjTail::Object(c.is_some(), t, i)
                    }
                }),
        )))
        .then_ignore(soft_semi())
        .map(|(names, tail)| match tail {
            ObjTail::Exception => DeclKind::Exception { names },
            ObjTail::Number(value) => DeclKind::Number { names, value },
            ObjTail::Object(constant, ty, init) => DeclKind::Object {
                names,
                constant,
                ty,
                init,
                anon: None,
            },
            ObjTail::AnonArray(constant, def, sp, init) => {
                // An anonymous array type gets a hidden name of its own.
                let tyname = Ident::new(&format!("{}'Type", names[0].name), sp);
                DeclKind::Object {
                    names,
                    constant,
                    ty: SubtypeInd {
                        mark: mk(ExprKind::Name(tyname), sp),
                        constraint: None,
                        span: sp,
                    },
                    init,
                    anon: Some(Box::new(def)),
                }
            }
            ObjTail::Renames => DeclKind::Unsupported("a renaming declaration"),
        });
    let import_aspect = kw!(With)
        .ignore_then(
            ident()
                .then(just(Token::Arrow).ignore_then(expr.clone()).or_not())
                .separated_by(just(Token::Comma))
                .at_least(1)
                .collect::<Vec<_>>(),
        )
        .map(|aspects: Vec<(Ident, Option<Expr>)>| {
            aspects
                .into_iter()
                .find_map(|(k, v)| match (k.key.as_ref(), v) {
                    (
                        "external_name",
                        Some(Expr {
                            kind: ExprKind::Str(s),
                            ..
                        }),
                    ) => Some(s),
                    _ => None,
                })
        });
    #[derive(Clone)]
    enum TaskItem {
        Entry(EntryDecl),
        Address(DeclKind),
        Pragma(DeclKind),
    }
    #[derive(Clone)]
    enum SubTail {
        Unsupported(&'static str),
        Decl(Option<String>),
        /// Declarations, statements, the name after `end`, and where the
        /// text ended when it ended before the body's `end`.
        Body(Vec<Decl>, Block, Option<(String, Span)>, Option<Span>),
    }
    let spec = subprogram_spec(expr.clone());
    let subprogram = spec
        .clone()
        .then(choice((
            kw!(Is)
                .ignore_then(kw!(Separate).or(kw!(Abstract)))
                .then_ignore(semi())
                .to(SubTail::Unsupported("a separate or abstract subprogram")),
            kw!(Is)
                .ignore_then(kw!(New))
                .then(name())
                .then(any().and_is(semi().not()).repeated())
                .then_ignore(semi())
                .to(SubTail::Unsupported("a generic instantiation")),
            // An expression function (Ada 2012): `is (Expression);`, a body
            // that returns the parenthesized expression (or aggregate).
            kw!(Is)
                .ignore_then(just(Token::LParen).rewind())
                .ignore_then(expr.clone())
                .validate(|x: Expr, _, emitter| {
                    if !matches!(
                        x.kind,
                        ExprKind::Paren(_)
                            | ExprKind::Aggregate(_)
                            | ExprKind::If { .. }
                            | ExprKind::Case { .. }
                    ) {
                        emitter.emit(Rich::custom(
                            x.span,
                            "the body of an expression function is one parenthesized expression: `is (...)`",
                        ));
                    }
                    x
                })
                .then_ignore(semi())
                .map(|x: Expr| {
                    let span = x.span;
                    let ret = Stmt {
                        kind: StmtKind::Return(Some(Box::new(x))),
                        span,
                    };
                    SubTail::Body(
                        Vec::new(),
                        Block {
                            stmts: vec![ret].into(),
                            handlers: Vec::new(),
                            span,
                            lazy: None,
                        },
                        None,
                        None,
                    )
                }),
            kw!(Is)
                .ignore_then(decls.clone())
                .then(choice((
                    body_block
                        .clone()
                        .then(end_name.clone())
                        .then_ignore(semi())
                        .map(|(b, n)| (b, n, None)),
                    // The text ends before the body's `end`: reported once
                    // (below), and the body is taken as ended, so that what
                    // it holds is not parsed again as something else.
                    kw!(Begin)
                        .ignore_then(stmts.clone())
                        .then(
                            kw!(Exception)
                                .ignore_then(handler.clone().repeated().collect::<Vec<_>>())
                                .or_not(),
                        )
                        .then(end().map_with(|_, e| e.span()))
                        .map_with(|((stmts, handlers), at), e| {
                            let b = Block {
                                stmts: stmts.into(),
                                handlers: handlers.unwrap_or_default(),
                                span: e.span(),
                                lazy: None,
                            };
                            (b, None, Some(at))
                        }),
                )))
                .map(|(d, (b, n, missing))| SubTail::Body(d, b, n, missing)),
            import_aspect
                .or_not()
                .then_ignore(semi())
                .map(|imp| SubTail::Decl(imp.flatten())),
        )))
        .validate(|(spec, rest), e, emitter| match rest {
            SubTail::Unsupported(what) => DeclKind::UnsupportedNamed(
                what,
                match &spec.name {
                    Designator::Ident(i) => vec![i.clone()],
                    _ => Vec::new(),
                },
            ),
            SubTail::Decl(import) => DeclKind::SubprogramDecl { spec, import },
            SubTail::Body(decls, body, end_name, missing) => {
                if let Some(at) = missing {
                    let whole: Span = e.span();
                    emitter.emit(Rich::custom(
                        at,
                        format!("{UNCLOSED}body {}", whole.start),
                    ));
                }
                DeclKind::SubprogramBody(Box::new(SubprogramBody {
                    spec,
                    decls,
                    body,
                    end_name,
                }))
            }
        });
    let package = kw!(Package).ignore_then(choice((
        kw!(Body)
            .ignore_then(name())
            .then_ignore(kw!(Is))
            .then(decls.clone())
            .then(
                kw!(Begin)
                    .ignore_then(stmts.clone())
                    .then(
                        kw!(Exception)
                            .ignore_then(handler.clone().repeated().collect::<Vec<_>>())
                            .or_not(),
                    )
                    .map_with(|(stmts, handlers), e| Block {
                        stmts: stmts.into(),
                        handlers: handlers.unwrap_or_default(),
                        span: e.span(),
                        lazy: None,
                    })
                    .or_not(),
            )
            .then_ignore(kw!(End))
            .then_ignore(name().or_not())
            .then_ignore(semi())
            .map_with(|((name, decls), init), e| {
                DeclKind::PackageBody(Box::new(PackageBody {
                    name,
                    decls,
                    init,
                    span: e.span(),
                }))
            }),
        ident()
            .then_ignore(kw!(Is))
            .then_ignore(kw!(New))
            .then_ignore(any().and_is(semi().not()).repeated())
            .then_ignore(semi())
            .map(|n| DeclKind::UnsupportedNamed("a generic instantiation", vec![n])),
        name()
            .then_ignore(kw!(Is))
            .then(decls.clone())
            .then(kw!(Private).ignore_then(decls.clone()).or_not())
            .then_ignore(kw!(End))
            .then_ignore(name().or_not())
            .then_ignore(semi())
            .map_with(|((name, decls), private), e| {
                DeclKind::PackageSpec(Box::new(PackageSpec {
                    name,
                    decls,
                    private: private.unwrap_or_default(),
                    span: e.span(),
                }))
            }),
    )));
    let use_decl = kw!(Use)
        .ignore_then(
            kw!(Type)
                .or(kw!(All).then(kw!(Type)).to(Token::Semi))
                .or_not(),
        )
        .ignore_then(
            name()
                .separated_by(just(Token::Comma))
                .at_least(1)
                .collect::<Vec<_>>(),
        )
        .then_ignore(semi())
        .map(DeclKind::Use);
    let pragma = kw!(Pragma)
        .ignore_then(ident())
        .then(
            ident()
                .then(just(Token::Arrow))
                .or_not()
                .ignore_then(expr.clone())
                .separated_by(just(Token::Comma))
                .collect::<Vec<_>>()
                .delimited_by(just(Token::LParen), just(Token::RParen))
                .or_not(),
        )
        .then_ignore(semi())
        .map(|(name, args)| DeclKind::Pragma {
            name,
            args: args.unwrap_or_default(),
        });
    // `entry E (1 .. 3) (...)`: an entry family, parsed and refused.
    let family = just(Token::LParen)
        .ignore_then(expr.clone())
        .then_ignore(just(Token::DotDot).then(expr.clone()).or_not())
        .then_ignore(just(Token::RParen))
        .validate(|_, e, emitter| {
            emitter.emit(Rich::custom(
                e.span(),
                "an entry family is not supported by AdaIR (see docs/differences.md)",
            ))
        });
    let entry_decl = kw!(Entry)
        .ignore_then(ident())
        .then_ignore(family.or_not())
        .then(params(expr.clone()))
        .then_ignore(semi())
        .map_with(|(name, params), e| EntryDecl {
            name,
            params,
            span: e.span(),
        });
    let interrupt_use = kw!(For)
        .ignore_then(ident())
        .then_ignore(kw!(Use))
        .then_ignore(kw!(At))
        .then(expr.clone())
        .then_ignore(semi())
        .map(|(entry, address)| DeclKind::InterruptUse { entry, address });
    // Representation clauses other than `use at`: read whole (a record
    // representation to its `end record;`) and refused.
    let rep_clause = kw!(For)
        .ignore_then(ident())
        .then_ignore(just(Token::Tick).then(ident()).or_not())
        .then_ignore(kw!(Use))
        .then_ignore(kw!(At).not().rewind())
        .then_ignore(choice((
            kw!(Record)
                .then(any().and_is(kw!(End).then(kw!(Record)).not()).repeated())
                .then(kw!(End))
                .then(kw!(Record))
                .then(semi())
                .ignored(),
            skip_to_semi(),
        )))
        .to(DeclKind::Unsupported("a representation clause"));
    // `package body P is separate;` (and of a task or protected unit).
    let separate_body = choice((kw!(Package), kw!(Task), kw!(Protected)))
        .then(kw!(Body))
        .then(ident().separated_by(just(Token::Dot)).at_least(1))
        .then(kw!(Is))
        .then(kw!(Separate))
        .then(semi())
        .to(DeclKind::Unsupported("a separate body"));
    let task = kw!(Task).ignore_then(choice((
        kw!(Body)
            .ignore_then(ident())
            .then_ignore(kw!(Is))
            .then(decls.clone())
            .then(block.clone())
            .then_ignore(ident().or_not())
            .then_ignore(semi())
            .map(|((name, decls), body)| {
                DeclKind::TaskBody(Box::new(TaskBody { name, decls, body }))
            }),
        kw!(Type)
            .or_not()
            .then(ident())
            .then_ignore(discriminants.clone())
            .then(
                kw!(Is)
                    .ignore_then(
                        choice((
                            entry_decl.clone().map(TaskItem::Entry),
                            interrupt_use.clone().map(TaskItem::Address),
                            pragma.clone().map(TaskItem::Pragma),
                        ))
                        .repeated()
                        .collect::<Vec<_>>(),
                    )
                    .then_ignore(kw!(End))
                    .then_ignore(ident().or_not())
                    .or_not(),
            )
            .then_ignore(semi())
            .map(|((is_type, name), items)| {
                let mut spec = TaskSpec {
                    name,
                    entries: Vec::new(),
                    is_type: is_type.is_some(),
                    addresses: Vec::new(),
                    priority: None,
                };
                for item in items.unwrap_or_default() {
                    match item {
                        TaskItem::Entry(e) => spec.entries.push(e),
                        TaskItem::Address(DeclKind::InterruptUse { entry, address }) => {
                            spec.addresses.push((entry, address))
                        }
                        TaskItem::Pragma(DeclKind::Pragma { name, mut args })
                            if &*name.key == "priority" && args.len() == 1 =>
                        {
                            spec.priority = args.pop()
                        }
                        _ => {}
                    }
                }
                DeclKind::TaskSpec(Box::new(spec))
            }),
    )));
    // A generic unit: refused, with the names of its formal types and
    // objects and of the unit itself kept (see `UnsupportedNamed`).
    let generic = kw!(Generic)
        .ignore_then(
            any()
                .and_is(
                    select! { Token::Kw(Kw::Procedure | Kw::Function | Kw::Package) => () }.not(),
                )
                .map_with(|t, e| (t, e.span()))
                .repeated()
                .collect::<Vec<(Token, Span)>>(),
        )
        .then(decl.clone())
        .map(|(formals, unit)| {
            let mut names = Vec::new();
            for (k, w) in formals.windows(2).enumerate() {
                let is_type = matches!(w[0].0, Token::Kw(Kw::Type));
                let before_colon = matches!(w[1].0, Token::Colon)
                    && !matches!(
                        formals.get(k.wrapping_sub(1)),
                        Some((Token::Kw(Kw::Type), _))
                    );
                let (t, sp) = if is_type { &w[1] } else { &w[0] };
                if (is_type || before_colon)
                    && let Token::Ident(n) = t
                {
                    names.push(Ident::new(n, *sp));
                }
            }
            if let DeclKind::SubprogramDecl { spec, .. } = &unit.kind
                && let Designator::Ident(i) = &spec.name
            {
                names.push(i.clone());
            }
            DeclKind::UnsupportedNamed("a generic unit", names)
        });
    let prot_op = choice((
        entry_decl.clone().map(|e| Some(ProtOp::Entry(e))),
        spec.clone()
            .then_ignore(semi())
            .map(|s| Some(ProtOp::Sub(s))),
        pragma.clone().to(None),
    ));
    let protected = kw!(Protected).ignore_then(choice((
        kw!(Body)
            .ignore_then(ident())
            .then_ignore(kw!(Is))
            .then(decls.clone())
            .then_ignore(kw!(End))
            .then_ignore(ident().or_not())
            .then_ignore(semi())
            .map_with(|(name, decls), e| {
                DeclKind::ProtectedBody(Box::new(ProtectedBody {
                    name,
                    decls,
                    span: e.span(),
                }))
            }),
        kw!(Type)
            .or_not()
            .then(ident())
            .then_ignore(discriminants.clone())
            .then_ignore(kw!(Is))
            .then(prot_op.repeated().collect::<Vec<_>>())
            .then(kw!(Private).ignore_then(decls.clone()).or_not())
            .then_ignore(kw!(End))
            .then_ignore(ident().or_not())
            .then_ignore(semi())
            .map_with(|(((is_type, name), ops), private), e| {
                DeclKind::ProtectedSpec(Box::new(ProtectedSpec {
                    name,
                    is_type: is_type.is_some(),
                    ops: ops.into_iter().flatten().collect(),
                    private: private.unwrap_or_default(),
                    span: e.span(),
                }))
            }),
    )));
    let entry_body = kw!(Entry)
        .ignore_then(ident())
        .then(params(expr.clone()))
        .then_ignore(kw!(When))
        .then(expr.clone())
        .then_ignore(kw!(Is))
        .then(decls.clone())
        .then(block.clone())
        .then_ignore(ident().or_not())
        .then_ignore(semi())
        .map_with(|((((name, params), barrier), decls), body), e| {
            DeclKind::EntryBody(Box::new(EntryBody {
                name,
                params,
                barrier,
                decls,
                body,
                span: e.span(),
            }))
        });

    choice((
        separate_body,
        type_decl,
        subtype_decl,
        object_decl,
        subprogram,
        package,
        use_decl,
        pragma,
        task,
        interrupt_use,
        rep_clause,
        generic,
        protected,
        entry_body,
    ))
    .map_with(|kind, e| Decl {
        kind,
        span: e.span(),
    })
    .labelled("declaration")
    // Likewise a declaration, not past the `begin`, `end` or `private`
    // that ends the declarative part.
    .recover_with(via_parser(skip_to_semi().map(|_| Decl {
        kind: DeclKind::Unsupported("<error>"),
        span: Span {
            start: 0,
            end: 0,
            context: 0,
        },
    })))
    .boxed()
}

fn unsupported(span: Span, what: &'static str) -> Decl {
    Decl {
        kind: DeclKind::Unsupported(what),
        span,
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
    let (out, errs) = compilation(lazy).parse(input).into_output_errors();
    let mut diags: Vec<Diagnostic> = errs.into_iter().map(|e| rich_to_diag(e, tokens)).collect();
    diags.dedup_by(|a, b| a.span == b.span);
    // Report a missing `;` at the end of the token it should follow.
    for d in &mut diags {
        if d.message.starts_with("missing `")
            && let Some((_, p)) = tokens.iter().rev().find(|(_, s)| s.end <= d.span.start)
        {
            d.span = Span {
                start: p.end,
                end: p.end,
                context: p.context,
            };
            // The word that is missing (`;`, `then`, `loop`, ...).
            let word = d.message["missing ".len()..]
                .split(' ')
                .next()
                .unwrap_or("`;`")
                .to_string();
            d.label = format!("expected {word} here");
        }
    }
    explain_unclosed(&mut diags, tokens, src_len);
    (out, diags)
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
    let (out, errs) = parsers(false)
        .stmt
        .repeated()
        .collect::<Vec<_>>()
        .map(exact)
        .then_ignore(chumsky::primitive::end())
        .parse(input)
        .into_output_errors();
    let diags = errs.into_iter().map(|e| rich_to_diag(e, tokens)).collect();
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

/// The file ended inside a `loop`, `if` or `case`: name the construct and
/// point at it rather than at the end of the file.
fn explain_unclosed(diags: &mut [Diagnostic], tokens: &[(Token, Span)], src_len: u32) {
    let Some(d) = diags
        .iter_mut()
        .find(|d| d.span.start >= src_len && d.label == "end of input")
    else {
        return;
    };
    // Open constructs at parenthesis depth 0 (an `if` or `case` inside
    // parentheses is an expression and has no `end`).
    let mut open: Vec<(Kw, Span)> = Vec::new();
    let mut depth = 0usize;
    let mut prev_end = false;
    for (t, sp) in tokens {
        match t {
            Token::LParen => depth += 1,
            Token::RParen => depth = depth.saturating_sub(1),
            Token::Kw(k @ (Kw::Loop | Kw::If | Kw::Case)) if depth == 0 => {
                if prev_end {
                    if let Some(i) = open.iter().rposition(|(o, _)| o == k) {
                        open.truncate(i);
                    }
                } else {
                    open.push((*k, *sp));
                }
            }
            _ => {}
        }
        prev_end = matches!(t, Token::Kw(Kw::End));
    }
    let Some((k, at)) = open.last().copied() else {
        return;
    };
    let word = match k {
        Kw::Loop => "loop",
        Kw::If => "if",
        _ => "case",
    };
    let end_of_input = d.span;
    d.message = format!("this `{word}` has no `end {word};`");
    d.span = at;
    d.label = format!("this `{word}` is never closed");
    d.hint = Some(format!(
        "end it with `end {word};` after its last statement"
    ));
    d.notes.push((end_of_input, UNFINISHED_NOTE.to_string()));
}

/// Where an unclosed construct's line and column go in its message; filled
/// in by `syntax::parse_source`, which has the text.
pub const OPENER_AT: &str = "{opener}";

/// The note at the end of the input of an unclosed construct.
const UNFINISHED_NOTE: &str = "the text ends here";

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
    p.parse(input).into_result().ok()
}

/// True if the error list only says the input ended too early (for the REPL's
/// continuation prompt).
pub fn is_unfinished(diags: &[Diagnostic], src_len: usize) -> bool {
    let src_len = crate::diag::offset(src_len);
    // The input ran out inside a construct; other errors it caused on the
    // way (after recovery) do not make it finished.
    diags.iter().any(|d| {
        d.phase == crate::diag::Phase::Syntax
            && ((d.span.start >= src_len && d.label == "end of input")
                || d.notes
                    .iter()
                    .any(|(s, n)| s.start >= src_len && n == UNFINISHED_NOTE))
    })
}

fn rich_to_diag(e: Rich<'_, Token, Span>, tokens: &[(Token, Span)]) -> Diagnostic {
    use chumsky::error::RichReason;
    let span = *e.span();
    let found = match e.found() {
        Some(t) => t.to_string(),
        None => "end of input".to_string(),
    };
    let label = if e.found().is_none() {
        "end of input".to_string()
    } else {
        format!("unexpected {found}")
    };
    match e.reason() {
        // An `if`, `case` or `loop` closed by the `end` of what encloses it.
        RichReason::Custom(msg) if msg.starts_with(UNCLOSED) => {
            let mut words = msg[UNCLOSED.len_utf8()..].split(' ');
            let word = words.next().unwrap_or("loop").to_string();
            let start: u32 = words.next().and_then(|w| w.parse().ok()).unwrap_or(0);
            // The construct's own keyword (after a label, `for ... `, `while ...`).
            // (Tokens are in order: binary searches, not scans, as there
            // may be one such error per level of a deep nest.)
            let at = tokens.partition_point(|(_, s)| s.start < span.start);
            let opener = tokens[tokens.partition_point(|(_, s)| s.start < start)..]
                .iter()
                .take_while(|(_, s)| s.start < span.start)
                .find(|(t, _)| match word.as_str() {
                    "if" => *t == Token::Kw(Kw::If),
                    "case" => *t == Token::Kw(Kw::Case),
                    "block" => matches!(t, Token::Kw(Kw::Declare | Kw::Begin)),
                    "body" => matches!(t, Token::Kw(Kw::Procedure | Kw::Function)),
                    _ => matches!(t, Token::Kw(Kw::Loop | Kw::For | Kw::While)),
                })
                .map(|(_, s)| *s)
                .unwrap_or(Span {
                    start,
                    end: start,
                    context: span.context,
                });
            // A block or a body that the text ends inside (taken as ended).
            let ended = match word.as_str() {
                "body" => Some((
                    "the text ends inside the body of the subprogram",
                    "end the body with `end NAME;` after its last statement",
                    "this subprogram's body is not closed",
                )),
                "block" => Some((
                    "`end;` expected to close the block",
                    "end the block with `end;` after its last statement",
                    "this block is not closed",
                )),
                _ => None,
            };
            // The text ends before the construct's `end`: one diagnostic at
            // the end of the input, which `explain_unclosed` words.
            if ended.is_none() && at == tokens.len() {
                return Diagnostic::syntax(span, format!("the text ends inside the `{word}`"))
                    .with_label("end of input");
            }
            if let Some((message, hint, note)) = ended {
                let mut d = Diagnostic::syntax(span, format!("{message} at {OPENER_AT}"))
                    .with_label("end of input")
                    .with_hint(hint);
                d.notes.push((opener, note.to_string()));
                return d;
            }
            // A bare `end;` was taken as the construct's end; `end Name`
            // belongs to the body around it.
            let bare = tokens.get(at + 1).is_some_and(|(t, _)| *t == Token::Semi);
            let other = tokens
                .get(at)
                .filter(|(t, _)| *t != Token::Kw(Kw::End))
                .map(|(t, _)| t.to_string());
            let (label, hint) = if let Some(other) = other {
                (
                    format!("{other} comes before the `{word}` is closed"),
                    format!("add `end {word};` before this line"),
                )
            } else if bare {
                (
                    format!("this should be `end {word};`"),
                    format!("write `end {word};`"),
                )
            } else {
                (
                    format!("this `end` closes what encloses the `{word}`"),
                    format!("add `end {word};` before this line"),
                )
            };
            let mut d = Diagnostic::syntax(
                span,
                format!("`end {word};` expected to close the `{word}` at {OPENER_AT}"),
            )
            .with_label(label)
            .with_hint(hint);
            d.notes
                .push((opener, format!("this `{word}` is not closed")));
            d
        }
        // A custom error explains itself; it has no token of its own to show.
        RichReason::Custom(msg) => Diagnostic::syntax(span, msg.clone()),
        _ => {
            let mut expected: Vec<String> = e
                .expected()
                .map(|p| match p {
                    chumsky::error::RichPattern::Token(t) => t.to_string(),
                    chumsky::error::RichPattern::Label(l) => l.to_string(),
                    chumsky::error::RichPattern::EndOfInput => "end of input".to_string(),
                    other => other.to_string(),
                })
                .collect();
            expected.sort();
            expected.dedup();
            // A missing `;` is the most common slip: say so, at the end of
            // the token it should follow.
            // A `)` that closes no `(` (counted back to the statement's
            // start) is the slip, not a missing `;`.
            if matches!(e.found(), Some(Token::RParen)) {
                let mut depth = 0i64;
                for (t, _) in tokens
                    .iter()
                    .rev()
                    .skip_while(|(_, s)| s.start >= span.start)
                {
                    match t {
                        Token::Semi
                        | Token::Kw(Kw::Begin | Kw::Is | Kw::Then | Kw::Else | Kw::Loop) => break,
                        Token::RParen => depth += 1,
                        Token::LParen => depth -= 1,
                        _ => {}
                    }
                }
                if depth >= 0 {
                    return Diagnostic::syntax(span, "unexpected `)` without a matching `(`")
                        .with_label("this `)` closes nothing")
                        .with_hint("remove it, or add the `(` it should close");
                }
            }
            if expected.iter().any(|x| x == "`;`") && e.found().is_some() {
                let prev = tokens
                    .iter()
                    .rev()
                    .find(|(_, s)| s.end <= span.start)
                    .map(|(_, s)| *s);
                let at = prev
                    .map(|p| Span {
                        start: p.end,
                        end: p.end,
                        context: p.context,
                    })
                    .unwrap_or(span);
                return Diagnostic::syntax(at, format!("missing `;` before {found}"))
                    .with_label("expected `;` here")
                    .with_hint("a statement or declaration ends with `;`");
            }
            // Operators that could continue an expression are rarely what was meant.
            const CONT: &[&str] = &[
                "`**`",
                "`and`",
                "`in`",
                "`not`",
                "`or`",
                "`xor`",
                "`..`",
                "`mod`",
                "`rem`",
                "something else",
                "`limited`",
                "`with`",
            ];
            let filtered: Vec<String> = expected
                .iter()
                .filter(|x| !CONT.contains(&x.as_str()))
                .cloned()
                .collect();
            if !filtered.is_empty() {
                expected = filtered;
            }
            let exp = match expected.len() {
                0 => String::new(),
                1 => format!(", expected {}", expected[0]),
                _ => format!(", expected one of {}", expected.join(", ")),
            };
            let d = Diagnostic::syntax(span, format!("unexpected {found}{exp}")).with_label(label);
            // `...` (`..` then `.`): a placeholder copied from a text, as in
            // the handbook's demo (`F := ... -- Hier Code zur
            // Stellungsanpassung`).
            let placeholder = matches!(e.found(), Some(Token::DotDot))
                && tokens
                    .iter()
                    .skip_while(|(_, s)| s.start < span.start)
                    .nth(1)
                    .is_some_and(|(t, s)| *t == Token::Dot && s.start == span.end);
            if placeholder {
                return d.with_hint(
                    "`...` is a placeholder, not Ada: write the expression (the handbook's demo adapts a frame the arm cannot reach with `ValidFrame (F);`)",
                );
            }
            d
        }
    }
}

/// What an operator symbol string names, for `"+" (A, B)`.
#[derive(Clone, Copy)]
enum OpSym {
    Bin(BinOp),
    Un(UnOp),
    /// `"+"` and `"-"`: binary with two operands, unary with one.
    Both(BinOp, UnOp),
}

fn operator_of(s: &str) -> Option<OpSym> {
    use OpSym::*;
    Some(match s.to_ascii_lowercase().as_str() {
        "+" => Both(BinOp::Add, UnOp::Plus),
        "-" => Both(BinOp::Sub, UnOp::Neg),
        "abs" => Un(UnOp::Abs),
        "not" => Un(UnOp::Not),
        "and" => Bin(BinOp::And),
        "or" => Bin(BinOp::Or),
        "xor" => Bin(BinOp::Xor),
        "=" => Bin(BinOp::Eq),
        "/=" => Bin(BinOp::Ne),
        "<" => Bin(BinOp::Lt),
        "<=" => Bin(BinOp::Le),
        ">" => Bin(BinOp::Gt),
        ">=" => Bin(BinOp::Ge),
        "&" => Bin(BinOp::Cat),
        "*" => Bin(BinOp::Mul),
        "/" => Bin(BinOp::Div),
        "mod" => Bin(BinOp::Mod),
        "rem" => Bin(BinOp::Rem),
        "**" => Bin(BinOp::Pow),
        _ => return None,
    })
}

/// The deepest nesting the parser accepts, of parentheses and of block
/// constructs each. Parsing is recursive: each level costs stack and about
/// 10 KB of memory, so 10,000 levels stay near 100 MB while no program a
/// person writes comes close.
pub const MAX_NESTING: usize = 10_000;

/// The most operators one expression may chain without parentheses
/// (`1 + 1 + ...`). An operator chain is a tree as deep as it is long, which
/// the checker and the engine walk recursively: 150,000 `+` overflowed the
/// native stack.
pub const MAX_CHAIN: usize = 50_000;

/// A program nested deeper than [`MAX_NESTING`] (parentheses, blocks, or
/// parentheses and runs of unary operators together), or with an expression
/// chaining more than [`MAX_CHAIN`] operators: one error at the first token
/// past the limit, found by counting before parsing (a million nested
/// parentheses used 11 GB of memory and 14 s before this check).
fn too_deep(tokens: &[(Token, Span)]) -> Option<Diagnostic> {
    let (mut parens, mut blocks) = (0usize, 0usize);
    let mut after_end = false;
    // Operators chained at each level of parentheses.
    let mut chain: Vec<usize> = vec![0];
    // Levels of parentheses and unary operators: the run of unary
    // operators just read (each one's operand is the rest of the run, so
    // the parser recurses once an operator), and for each open parenthesis
    // the run before it (still open until its `)`).
    let (mut levels, mut run) = (0usize, 0usize);
    let mut runs: Vec<usize> = Vec::new();
    for (t, sp) in tokens {
        let was_end = std::mem::replace(&mut after_end, false);
        let what = match t {
            Token::Plus
            | Token::Minus
            | Token::Star
            | Token::StarStar
            | Token::Slash
            | Token::Amp
            | Token::Eq
            | Token::Ne
            | Token::Lt
            | Token::Le
            | Token::Gt
            | Token::Ge
            | Token::Kw(Kw::And | Kw::Or | Kw::Xor | Kw::Mod | Kw::Rem) => {
                let n = chain.last_mut().expect("a level");
                *n += 1;
                if *n > MAX_CHAIN {
                    return Some(
                        Diagnostic::syntax(
                            *sp,
                            format!(
                                "expression too long: more than {MAX_CHAIN} operators in a row"
                            ),
                        )
                        .with_label("this operator is one too many")
                        .with_hint("split the expression into several statements"),
                    );
                }
                None
            }
            Token::Semi | Token::Comma | Token::Arrow | Token::Assign | Token::DotDot => {
                *chain.last_mut().expect("a level") = 0;
                None
            }
            Token::LParen => {
                parens += 1;
                chain.push(0);
                (parens > MAX_NESTING).then_some("parentheses")
            }
            Token::RParen => {
                parens = parens.saturating_sub(1);
                if chain.len() > 1 {
                    chain.pop();
                }
                None
            }
            Token::Kw(Kw::End) => {
                blocks = blocks.saturating_sub(1);
                after_end = true;
                None
            }
            Token::Kw(Kw::Begin | Kw::Loop | Kw::If | Kw::Case | Kw::Record | Kw::Select)
                if !was_end && parens == 0 =>
            {
                blocks += 1;
                (blocks > MAX_NESTING).then_some("blocks, loops and `if`s")
            }
            _ => None,
        };
        if let Some(what) = what {
            return Some(
                Diagnostic::syntax(
                    *sp,
                    format!("nesting too deep: more than {MAX_NESTING} levels of {what}"),
                )
                .with_label("this level is one too many")
                .with_hint("split the expression or the statements into subprograms"),
            );
        }
        match t {
            Token::Kw(Kw::Not | Kw::Abs) | Token::Plus | Token::Minus => run += 1,
            Token::LParen => {
                runs.push(run);
                levels += run + 1;
                run = 0;
            }
            Token::RParen => {
                levels = levels.saturating_sub(runs.pop().map_or(0, |r| r + 1));
                run = 0;
            }
            _ => run = 0,
        }
        if levels + run > MAX_NESTING {
            return Some(
                Diagnostic::syntax(
                    *sp,
                    format!(
                        "nesting too deep: more than {MAX_NESTING} levels of parentheses \
                         and unary operators"
                    ),
                )
                .with_label("this level is one too many")
                .with_hint("split the expression into several statements"),
            );
        }
    }
    None
}
