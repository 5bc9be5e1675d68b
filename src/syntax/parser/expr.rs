//! Expressions and names: chumsky's Pratt parser for the adding,
//! multiplying and highest-precedence operators, relations and logical
//! operators folded by hand, aggregates, `if`/`case` expressions, subtype
//! indications and discrete ranges.

use super::{Ex, PErr, TokIn, exact, first_and, ident, join, mk};
use crate::diag::Span;
use crate::diag::codes;
use crate::syntax::ast::*;
use crate::syntax::diagnostics as D;
use crate::syntax::token::{Kw, Token};
use chumsky::pratt::{infix, left, none, prefix};
use chumsky::prelude::*;

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
                    emitter.emit(PErr::custom(
                        w[1].0.1,
                        D::custom(
                            codes::E0106,
                            format!(
                                "`{a}` and `{b}` mixed without parentheses: write `(X {a} Y) {b} Z`"
                            ),
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
                    emitter.emit(PErr::custom(
                        span,
                        D::custom(codes::E0106, "a choice needs `=>` and a value"),
                    ));
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
                operator_of(&s).map(|o| (o, sp)).ok_or_else(|| PErr::custom(sp, D::custom(codes::E0106, "not an operator symbol")))
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
                        emitter.emit(PErr::custom(
                            sp,
                            D::custom(
                                codes::E0106,
                                "this operator takes a different number of operands",
                            ),
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
                    emitter.emit(PErr::custom(
                        sp,
                        D::custom(
                            codes::E0106,
                            "a unary `-` or `+` only begins an expression: put this operand in parentheses (`2 * (-3)`)",
                        ),
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

pub(super) fn subtype_ind<'t, I: TokIn<'t>>(
    expr: Boxed<'t, 't, I, Expr, Ex<'t>>,
) -> Boxed<'t, 't, I, SubtypeInd, Ex<'t>> {
    let simple = expr.clone();
    let range_c = kw!(Range)
        .ignore_then(simple.clone())
        .then_ignore(just(Token::DotDot))
        .then(simple.clone())
        .map(|(a, b)| Constraint::Range(Box::new(a), Box::new(b)));
    let dr = discrete_range(expr.clone());
    // An index constraint, or a discriminant constraint: positional values
    // parse as ranges (the checker tells them apart by the type), named
    // ones make it a discriminant constraint.
    let named = ident()
        .then_ignore(just(Token::Arrow))
        .then(expr.clone())
        .map_with(|(n, value), e| Arg {
            name: Some(n),
            value,
            span: e.span(),
        });
    #[derive(Clone)]
    enum Item {
        Named(Arg),
        Range(Box<DiscreteRange>, Span),
    }
    let index_c = named
        .map(Item::Named)
        .or(dr.map_with(|r, e| Item::Range(Box::new(r), e.span())))
        .separated_by(just(Token::Comma))
        .at_least(1)
        .collect::<Vec<Item>>()
        .delimited_by(just(Token::LParen), just(Token::RParen))
        .validate(|items, _, emitter| {
            if items.iter().all(|i| matches!(i, Item::Range(..))) {
                return Constraint::Index(
                    items
                        .into_iter()
                        .filter_map(|i| match i {
                            Item::Range(r, _) => Some(*r),
                            Item::Named(_) => None,
                        })
                        .collect(),
                );
            }
            let mut args = Vec::with_capacity(items.len());
            let mut named = false;
            for item in items {
                match item {
                    Item::Named(a) => {
                        named = true;
                        args.push(a);
                    }
                    Item::Range(r, span) => {
                        let value = match *r {
                            DiscreteRange::Subtype(SubtypeInd {
                                mark,
                                constraint: None,
                                ..
                            }) if !named => mark,
                            _ => {
                                let what = if named {
                                    "a positional discriminant value after a named one"
                                } else {
                                    "a range among discriminant values"
                                };
                                emitter.emit(PErr::custom(
                                    span,
                                    D::custom(codes::E0106, format!("{what} is not allowed")),
                                ));
                                continue;
                            }
                        };
                        args.push(Arg {
                            name: None,
                            value,
                            span,
                        });
                    }
                }
            }
            Constraint::Discriminants(args)
        });
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

pub(super) fn discrete_range<'t, I: TokIn<'t>>(
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
