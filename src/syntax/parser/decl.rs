//! Declarations: objects, types and subtypes, subprograms, packages,
//! `use` and pragmas, the tasking units (tasks, protected units, entries)
//! and the constructs AdaIR reads only to refuse (generics, representation
//! clauses, separate bodies). `decl_grammar` chooses among the parts.

use super::errors::{UNCLOSED, assign_or_eq, decls_end, skip_to_semi, soft_semi};
use super::{Common, Ex, PErr, TokIn, ident, mk, name, semi};
use crate::diag::Span;
use crate::diag::codes;
use crate::syntax::ast::*;
use crate::syntax::diagnostics as D;
use crate::syntax::token::{Kw, Token};
use chumsky::prelude::*;

/// The declaration, over the shared parts.
pub(super) fn decl_grammar<'t, I: TokIn<'t>>(
    c: &Common<'t, I>,
    decl: &Boxed<'t, 't, I, Decl, Ex<'t>>,
) -> Boxed<'t, 't, I, Decl, Ex<'t>> {
    choice((
        separate_body(),
        type_decl(c),
        subtype_decl(c),
        object_decl(c),
        subprogram(c),
        package(c),
        use_decl(),
        pragma(&c.expr),
        task(c),
        interrupt_use(&c.expr),
        rep_clause(),
        generic(decl),
        protected(c, decl),
        entry_body(c),
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

/// One or more names, separated by commas.
fn names<'t, I: TokIn<'t>>() -> Boxed<'t, 't, I, Vec<Ident>, Ex<'t>> {
    ident()
        .separated_by(just(Token::Comma))
        .at_least(1)
        .collect::<Vec<_>>()
        .boxed()
}

/// An initial value or a default, if there is one.
fn init<'t, I: TokIn<'t>>(
    expr: &Boxed<'t, 't, I, Expr, Ex<'t>>,
) -> impl Parser<'t, I, Option<Expr>, Ex<'t>> + Clone + use<'t, I> {
    assign_or_eq().ignore_then(expr.clone()).or_not()
}

/// `type T is ...;` (or `type T;`, a type completed later).
fn type_decl<'t, I: TokIn<'t>>(c: &Common<'t, I>) -> Boxed<'t, 't, I, DeclKind, Ex<'t>> {
    let Common { expr, .. } = c;
    // `(<>)`: unknown discriminants.
    let unknown = just(Token::LParen)
        .then(just(Token::Box))
        .then(just(Token::RParen))
        .map_with(|_, e| e.span());
    kw!(Type)
        .ignore_then(ident())
        .then(
            unknown
                .map(|s| (Vec::new(), Some(s)))
                .or(params(expr.clone()).map(|p| (p, None))),
        )
        .then(kw!(Is).ignore_then(type_def(c)).or_not())
        .then_ignore(semi())
        .map(
            |((name, (discriminants, unknown_discriminants)), def)| DeclKind::Type {
                name,
                discriminants,
                unknown_discriminants,
                def: def.unwrap_or(TypeDef::Incomplete),
            },
        )
        .boxed()
}

/// What follows `type T is`.
fn type_def<'t, I: TokIn<'t>>(c: &Common<'t, I>) -> Boxed<'t, 't, I, TypeDef, Ex<'t>> {
    let Common { expr, st_ind, .. } = c;
    let enum_lit = ident()
        .map(EnumLit::Ident)
        .or(select! { Token::Char(c) = e => EnumLit::Char(c, e.span()) });
    let record_body = record_body(c);
    choice((
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
        array_def(c),
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
            .to(TypeDef::Private { limited: true }),
        kw!(Private).to(TypeDef::Private { limited: false }),
        kw!(Mod).ignore_then(expr.clone()).map(TypeDef::Modular),
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
    ))
    .boxed()
}

/// `array (...) of T`.
fn array_def<'t, I: TokIn<'t>>(c: &Common<'t, I>) -> Boxed<'t, 't, I, TypeDef, Ex<'t>> {
    let Common { drange, st_ind, .. } = c;
    kw!(Array)
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
        .boxed()
}

/// `record ... end record` or `null record`: the components.
fn record_body<'t, I: TokIn<'t>>(c: &Common<'t, I>) -> Boxed<'t, 't, I, ComponentList, Ex<'t>> {
    component_list(c)
        .delimited_by(kw!(Record), kw!(End).then(kw!(Record)))
        .or(kw!(Null).then(kw!(Record)).to(ComponentList::default()))
        .boxed()
}

/// The components of a record or of a variant (RM 3.8): components, then
/// a variant part (`case D is when ... => ...; end case;`) whose arms are
/// component lists again; or `null;`.
fn component_list<'t, I: TokIn<'t>>(c: &Common<'t, I>) -> Boxed<'t, 't, I, ComponentList, Ex<'t>> {
    let Common { expr, st_ind, .. } = c;
    let component = names()
        .then_ignore(just(Token::Colon))
        .then_ignore(kw!(Aliased).or_not())
        .then(st_ind.clone())
        .then(init(expr))
        .then_ignore(semi())
        .map_with(|((names, ty), default), e| Component {
            names,
            ty,
            default,
            span: e.span(),
        });
    let choice_p = kw!(Others)
        .map_with(|_, e| Choice::Others(e.span()))
        .or(expr
            .clone()
            .then(just(Token::DotDot).ignore_then(expr.clone()).or_not())
            .map(|(a, b)| match b {
                Some(b) => Choice::Range(a, b),
                None => Choice::Expr(a),
            }));
    let choices = choice_p
        .separated_by(just(Token::Bar))
        .at_least(1)
        .collect::<Vec<_>>();
    recursive(|list| {
        let variant_part = kw!(Case)
            .ignore_then(ident())
            .then_ignore(kw!(Is))
            .then(
                kw!(When)
                    .ignore_then(choices.clone())
                    .then_ignore(just(Token::Arrow))
                    .then(list)
                    .map_with(|(choices, body), e| CaseArm {
                        choices,
                        body,
                        span: e.span(),
                    })
                    .repeated()
                    .at_least(1)
                    .collect::<Vec<_>>(),
            )
            .then_ignore(kw!(End))
            .then_ignore(kw!(Case))
            .then_ignore(semi())
            .map_with(|(discriminant, arms), e| VariantPart {
                discriminant,
                arms,
                span: e.span(),
            });
        let null = kw!(Null).then(semi()).to(ComponentList::default());
        let variant_part = variant_part.map(Box::new);
        choice((
            null,
            component
                .clone()
                .repeated()
                .at_least(1)
                .collect::<Vec<_>>()
                .then(variant_part.clone().or_not())
                .map(|(components, variants)| ComponentList {
                    components,
                    variants,
                }),
            variant_part.map(|v| ComponentList {
                components: Vec::new(),
                variants: Some(v),
            }),
        ))
    })
    .boxed()
}

/// `subtype S is ...;`.
fn subtype_decl<'t, I: TokIn<'t>>(c: &Common<'t, I>) -> Boxed<'t, 't, I, DeclKind, Ex<'t>> {
    let Common { st_ind, .. } = c;
    kw!(Subtype)
        .ignore_then(ident())
        .then_ignore(kw!(Is))
        .then(st_ind.clone())
        .then_ignore(semi())
        .map(|(name, ind)| DeclKind::Subtype { name, ind })
        .boxed()
}

/// Objects, numbers, exceptions and renamings: `X, Y : ...;`.
fn object_decl<'t, I: TokIn<'t>>(c: &Common<'t, I>) -> Boxed<'t, 't, I, DeclKind, Ex<'t>> {
    let Common { expr, st_ind, .. } = c;
    #[derive(Clone)]
    enum ObjTail {
        Exception(Option<Expr>),
        Number(Expr),
        Object(bool, SubtypeInd, Option<Expr>),
        AnonArray(bool, TypeDef, Span, Option<Expr>),
        /// Where `constant` is, the subtype, the renamed name, an initial value.
        Renames(Option<Span>, SubtypeInd, Expr, Option<Expr>),
    }
    names()
        .map_with(|n, e| (n, e.span()))
        .then_ignore(just(Token::Colon))
        .then(choice((
            kw!(Exception)
                .ignore_then(kw!(Renames).ignore_then(expr.clone()).or_not())
                .map(ObjTail::Exception),
            kw!(Constant)
                .ignore_then(just(Token::Assign))
                .ignore_then(expr.clone())
                .map(ObjTail::Number),
            kw!(Constant)
                .or_not()
                .then_ignore(kw!(Aliased).or_not())
                .then(array_def(c).map_with(|d, e| (d, e.span())))
                .then(init(expr))
                .map(|((c, (d, sp)), i)| ObjTail::AnonArray(c.is_some(), d, sp, i)),
            kw!(Aliased)
                .or_not()
                .ignore_then(kw!(Constant).map_with(|_, e| e.span()).or_not())
                .then_ignore(kw!(Aliased).or_not())
                .then(st_ind.clone())
                .then(kw!(Renames).ignore_then(expr.clone()).or_not())
                .then(init(expr))
                .map(|(((c, t), ren), i)| match ren {
                    Some(r) => ObjTail::Renames(c, t, r, i),
                    None => ObjTail::Object(c.is_some(), t, i),
                }),
        )))
        .then_ignore(soft_semi())
        .validate(|((names, names_span), tail), _, emitter| {
            let mut refuse = |at: Span, msg: &str| {
                emitter.emit(PErr::custom(at, D::custom(codes::E0106, msg)));
            };
            let renaming = matches!(tail, ObjTail::Renames(..) | ObjTail::Exception(Some(_)));
            if renaming && names.len() > 1 {
                refuse(
                    names_span,
                    "a renaming declares one name: write one renaming for each",
                );
            }
            if let ObjTail::Renames(constant, ty, _, init) = &tail {
                if let Some(at) = constant {
                    refuse(
                        *at,
                        "`constant` is not allowed in a renaming: the renaming of a constant is a constant",
                    );
                }
                if ty.constraint.is_some() {
                    refuse(
                        ty.span,
                        "a renaming names its subtype without a constraint: the renamed object's subtype applies",
                    );
                }
                if let Some(i) = init {
                    refuse(
                        i.span,
                        "a renaming has no initial value: it is another name for an existing object",
                    );
                }
            }
            (names, tail)
        })
        .map(|(mut names, tail)| match tail {
            ObjTail::Exception(None) => DeclKind::Exception { names },
            ObjTail::Exception(Some(renamed)) => DeclKind::Renaming(Box::new(Renaming {
                what: Renamed::Exception(names.swap_remove(0)),
                renamed,
            })),
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
            ObjTail::Renames(_, ty, renamed, _) => DeclKind::Renaming(Box::new(Renaming {
                what: Renamed::Object {
                    name: names.swap_remove(0),
                    ty: ty.mark,
                },
                renamed,
            })),
        })
        .boxed()
}

/// A subprogram: its declaration, body, or what AdaIR refuses of it.
fn subprogram<'t, I: TokIn<'t>>(c: &Common<'t, I>) -> Boxed<'t, 't, I, DeclKind, Ex<'t>> {
    let Common { expr, .. } = c;
    subprogram_spec(expr.clone())
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
            kw!(Renames)
                .ignore_then(expr.clone())
                .then_ignore(semi())
                .map(SubTail::Renames),
            expression_function(expr),
            subprogram_body(c),
            import_aspect(expr)
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
            SubTail::Renames(renamed) => DeclKind::Renaming(Box::new(Renaming {
                what: Renamed::Subprogram(spec),
                renamed,
            })),
            SubTail::Body(decls, body, end_name, missing) => {
                if let Some(at) = missing {
                    let whole: Span = e.span();
                    emitter.emit(PErr::custom(at, format!("{UNCLOSED}body {}", whole.start)));
                }
                DeclKind::SubprogramBody(Box::new(SubprogramBody {
                    spec,
                    decls,
                    body,
                    end_name,
                }))
            }
        })
        .boxed()
}

/// `procedure P (...)` or `function F (...) return T`.
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

/// A parameter list, if there is one (for subprograms, entries, accepts
/// and discriminants).
pub(super) fn params<'t, I: TokIn<'t>>(
    expr: Boxed<'t, 't, I, Expr, Ex<'t>>,
) -> Boxed<'t, 't, I, Vec<Param>, Ex<'t>> {
    let mode = choice((
        kw!(In).then(kw!(Out)).to(Mode::InOut),
        select! { Token::Ident(s) if s.eq_ignore_ascii_case("inout") => () }
            .then(ident().rewind())
            .validate(|_, e, emitter| {
                emitter.emit(PErr::custom(
                    e.span(),
                    D::custom(
                        codes::E0104,
                        "`inout` is not a parameter mode: write `in out`",
                    ),
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

/// What follows a subprogram's specification.
#[derive(Clone)]
enum SubTail {
    Unsupported(&'static str),
    Decl(Option<String>),
    /// `renames Name;`
    Renames(Expr),
    /// Declarations, statements, the name after `end`, and where the
    /// text ended when it ended before the body's `end`.
    Body(Vec<Decl>, Block, Option<(String, Span)>, Option<Span>),
}

/// An expression function (Ada 2012): `is (Expression);`, a body
/// that returns the parenthesized expression (or aggregate).
fn expression_function<'t, I: TokIn<'t>>(
    expr: &Boxed<'t, 't, I, Expr, Ex<'t>>,
) -> Boxed<'t, 't, I, SubTail, Ex<'t>> {
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
                emitter.emit(PErr::custom(
                    x.span,
                    D::custom(
                        codes::E0106,
                        "the body of an expression function is one parenthesized expression: `is (...)`",
                    ),
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
        })
        .boxed()
}

/// `is` declarations, `begin` statements, `end NAME;`: a body.
fn subprogram_body<'t, I: TokIn<'t>>(c: &Common<'t, I>) -> Boxed<'t, 't, I, SubTail, Ex<'t>> {
    let Common {
        decls,
        stmts,
        handler,
        body_block,
        end_name,
        ..
    } = c;
    kw!(Is)
        .ignore_then(decls.clone())
        .then(choice((
            body_block
                .clone()
                .then(end_name.clone())
                .then_ignore(semi())
                .map(|(b, n)| (b, n, None)),
            // The text ends before the body's `end`: reported once
            // (by `subprogram`), and the body is taken as ended, so that what
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
        .map(|(d, (b, n, missing))| SubTail::Body(d, b, n, missing))
        .boxed()
}

/// `with Import, External_Name => "..."`: the external name, if given.
fn import_aspect<'t, I: TokIn<'t>>(
    expr: &Boxed<'t, 't, I, Expr, Ex<'t>>,
) -> Boxed<'t, 't, I, Option<String>, Ex<'t>> {
    kw!(With)
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
        })
        .boxed()
}

/// A package specification or body.
fn package<'t, I: TokIn<'t>>(c: &Common<'t, I>) -> Boxed<'t, 't, I, DeclKind, Ex<'t>> {
    let Common {
        stmts,
        decls,
        handler,
        ..
    } = c;
    kw!(Package)
        .ignore_then(choice((
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
                .then_ignore(kw!(Renames))
                .then(name())
                .then_ignore(semi())
                .map(|(n, renamed)| {
                    DeclKind::Renaming(Box::new(Renaming {
                        what: Renamed::Package(n),
                        renamed,
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
        )))
        .boxed()
}

/// `use P;`, `use type T;`, `use all type T;`.
fn use_decl<'t, I: TokIn<'t>>() -> Boxed<'t, 't, I, DeclKind, Ex<'t>> {
    kw!(Use)
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
        .map(DeclKind::Use)
        .boxed()
}

/// `pragma Name (Arguments);`.
fn pragma<'t, I: TokIn<'t>>(
    expr: &Boxed<'t, 't, I, Expr, Ex<'t>>,
) -> Boxed<'t, 't, I, DeclKind, Ex<'t>> {
    kw!(Pragma)
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
        })
        .boxed()
}

/// A task specification or body.
fn task<'t, I: TokIn<'t>>(c: &Common<'t, I>) -> Boxed<'t, 't, I, DeclKind, Ex<'t>> {
    let Common {
        expr,
        drange,
        decls,
        block,
        ..
    } = c;
    #[derive(Clone)]
    enum TaskItem {
        Entry(EntryDecl),
        Address(DeclKind),
        Pragma(DeclKind),
    }
    kw!(Task)
        .ignore_then(choice((
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
                .then(params(expr.clone()))
                .then(
                    kw!(Is)
                        .ignore_then(
                            choice((
                                entry_decl(expr, drange).map(TaskItem::Entry),
                                interrupt_use(expr).map(TaskItem::Address),
                                pragma(expr).map(TaskItem::Pragma),
                            ))
                            .repeated()
                            .collect::<Vec<_>>(),
                        )
                        .then_ignore(kw!(End))
                        .then_ignore(ident().or_not())
                        .or_not(),
                )
                .then_ignore(semi())
                .map(|(((is_type, name), discriminants), items)| {
                    let mut spec = TaskSpec {
                        name,
                        discriminants,
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
        )))
        .boxed()
}

/// An entry declaration of a task or protected unit.
fn entry_decl<'t, I: TokIn<'t>>(
    expr: &Boxed<'t, 't, I, Expr, Ex<'t>>,
    drange: &Boxed<'t, 't, I, DiscreteRange, Ex<'t>>,
) -> Boxed<'t, 't, I, EntryDecl, Ex<'t>> {
    // `entry E (Priority) (...)`, `entry E (1 .. 3)`: an entry family. A
    // parameter list `(X : T)` does not parse as a range (its `:`), so the
    // family is tried first.
    let family = just(Token::LParen)
        .ignore_then(drange.clone())
        .then_ignore(just(Token::RParen));
    kw!(Entry)
        .ignore_then(ident())
        .then(family.or_not())
        .then(params(expr.clone()))
        .then_ignore(semi())
        .map_with(|((name, family), params), e| EntryDecl {
            name,
            family,
            params,
            span: e.span(),
        })
        .boxed()
}

/// `for E use at A;`: an entry bound to an interrupt.
fn interrupt_use<'t, I: TokIn<'t>>(
    expr: &Boxed<'t, 't, I, Expr, Ex<'t>>,
) -> Boxed<'t, 't, I, DeclKind, Ex<'t>> {
    kw!(For)
        .ignore_then(ident())
        .then_ignore(kw!(Use))
        .then_ignore(kw!(At))
        .then(expr.clone())
        .then_ignore(semi())
        .map(|(entry, address)| DeclKind::InterruptUse { entry, address })
        .boxed()
}

/// A protected unit's specification or body.
fn protected<'t, I: TokIn<'t>>(
    c: &Common<'t, I>,
    decl: &Boxed<'t, 't, I, Decl, Ex<'t>>,
) -> Boxed<'t, 't, I, DeclKind, Ex<'t>> {
    let Common {
        expr,
        drange,
        decls,
        ..
    } = c;
    let prot_op = choice((
        entry_decl(expr, drange).map(|e| Some(ProtOp::Entry(e))),
        subprogram_spec(expr.clone())
            .then_ignore(semi())
            .map(|s| Some(ProtOp::Sub(s))),
        pragma(expr).to(None),
    ));
    kw!(Protected)
        .ignore_then(choice((
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
                .then(params(expr.clone()))
                .then_ignore(kw!(Is))
                .then(prot_op.repeated().collect::<Vec<_>>())
                .then(
                    // The private part: components, and private entries
                    // (and subprograms, read as declarations).
                    kw!(Private)
                        .ignore_then(
                            decls_end()
                                .not()
                                .rewind()
                                .ignore_then(choice((
                                    entry_decl(expr, drange).map(Ok),
                                    decl.clone().map(Err),
                                )))
                                .repeated()
                                .collect::<Vec<Result<EntryDecl, Decl>>>(),
                        )
                        .or_not(),
                )
                .then_ignore(kw!(End))
                .then_ignore(ident().or_not())
                .then_ignore(semi())
                .map_with(|((((is_type, name), discriminants), ops), private), e| {
                    let (entries, decls): (Vec<_>, Vec<_>) = private
                        .unwrap_or_default()
                        .into_iter()
                        .partition(|x| x.is_ok());
                    DeclKind::ProtectedSpec(Box::new(ProtectedSpec {
                        name,
                        discriminants,
                        is_type: is_type.is_some(),
                        ops: ops.into_iter().flatten().collect(),
                        private_entries: entries.into_iter().filter_map(|x| x.ok()).collect(),
                        private: decls.into_iter().filter_map(|x| x.err()).collect(),
                        span: e.span(),
                    }))
                }),
        )))
        .boxed()
}

/// An entry body of a protected unit.
fn entry_body<'t, I: TokIn<'t>>(c: &Common<'t, I>) -> Boxed<'t, 't, I, DeclKind, Ex<'t>> {
    let Common {
        expr,
        drange,
        decls,
        block,
        ..
    } = c;
    // `(for I in Range)`: the index of an entry family's body.
    let family = just(Token::LParen)
        .ignore_then(kw!(For))
        .ignore_then(ident())
        .then_ignore(kw!(In))
        .then(drange.clone())
        .then_ignore(just(Token::RParen));
    kw!(Entry)
        .ignore_then(ident())
        .then(family.or_not())
        .then(params(expr.clone()))
        .then_ignore(kw!(When))
        .then(expr.clone())
        .then_ignore(kw!(Is))
        .then(decls.clone())
        .then(block.clone())
        .then_ignore(ident().or_not())
        .then_ignore(semi())
        .map_with(|(((((name, family), params), barrier), decls), body), e| {
            DeclKind::EntryBody(Box::new(EntryBody {
                name,
                family,
                params,
                barrier,
                decls,
                body,
                span: e.span(),
            }))
        })
        .boxed()
}

/// A generic unit: refused, with the names of its formal types and
/// objects and of the unit itself kept (see `UnsupportedNamed`).
fn generic<'t, I: TokIn<'t>>(
    decl: &Boxed<'t, 't, I, Decl, Ex<'t>>,
) -> Boxed<'t, 't, I, DeclKind, Ex<'t>> {
    kw!(Generic)
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
        })
        .boxed()
}

/// Representation clauses other than `use at`: read whole (a record
/// representation to its `end record;`) and refused.
fn rep_clause<'t, I: TokIn<'t>>() -> Boxed<'t, 't, I, DeclKind, Ex<'t>> {
    kw!(For)
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
        .to(DeclKind::Unsupported("a representation clause"))
        .boxed()
}

/// `package body P is separate;` (and of a task or protected unit).
fn separate_body<'t, I: TokIn<'t>>() -> Boxed<'t, 't, I, DeclKind, Ex<'t>> {
    choice((kw!(Package), kw!(Task), kw!(Protected)))
        .then(kw!(Body))
        .then(ident().separated_by(just(Token::Dot)).at_least(1))
        .then(kw!(Is))
        .then(kw!(Separate))
        .then(semi())
        .to(DeclKind::Unsupported("a separate body"))
        .boxed()
}
