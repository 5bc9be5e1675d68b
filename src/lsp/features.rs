//! Hover, definition, references, rename and document symbols: pure
//! functions of an [`Analysis`] and a byte offset, read from the checker's
//! side tables (`check::index`) and the service table.

use super::analysis::{Analysis, LineIndex};
use crate::check::Entity;
use crate::check::index::{Def, DefKind};
use crate::diag::Offsets as _;
use crate::diag::Span;
use crate::services::table::{self, Service};
use crate::syntax::ast;

/// The identifier around `offset` (its byte range), if any.
pub fn word_at(text: &str, offset: usize) -> Option<(usize, usize)> {
    let is_id = |c: char| c.is_alphanumeric() || c == '_';
    let offset = offset.min(text.len());
    if !text.is_char_boundary(offset) {
        return None;
    }
    let start = text[..offset]
        .char_indices()
        .rev()
        .take_while(|(_, c)| is_id(*c))
        .last()
        .map_or(offset, |(i, _)| i);
    let end = text[offset..]
        .char_indices()
        .find(|(_, c)| !is_id(*c))
        .map_or(text.len(), |(i, _)| offset + i);
    (start < end).then_some((start, end))
}

/// The declaration the name at `offset` refers to (or declares).
pub fn def_at(a: &Analysis, offset: usize) -> Option<(u32, &Def)> {
    let i = a.checker.index.def_at(a.file, offset)?;
    a.checker.index.defs.get(i as usize).map(|d| (i, d))
}

/// The Ada type name of a type id.
fn tname(a: &Analysis, t: crate::check::types::TypeId) -> String {
    a.checker.tables.types.name(t).to_string()
}

/// The comment lines right above the line where `at` is, without `--`.
fn comment_above(text: &str, at: usize) -> String {
    let at = at.min(text.len());
    let line_start = text[..at].rfind('\n').map_or(0, |i| i + 1);
    let mut lines: Vec<&str> = Vec::new();
    for l in text[..line_start].lines().rev() {
        let t = l.trim();
        match t.strip_prefix("--") {
            Some(c) => lines.push(c.trim()),
            None => break,
        }
    }
    lines.reverse();
    lines.join("\n")
}

/// The service a subprogram is bound to, if it is one.
pub fn service_of(a: &Analysis, f: u32) -> Option<&'static Service> {
    let import = a.checker.tables.imports.get(f as usize)?.as_deref()?;
    table::by_import(import)
}

/// A service's documentation: the table's doc text (the function form of a
/// `Value...` service shares the procedure's), command code and the
/// exceptions its doc names.
pub fn service_doc(svc: &Service) -> String {
    let doc = if svc.doc.is_empty() {
        table::SERVICES
            .iter()
            .find(|s| s.name.eq_ignore_ascii_case(svc.name) && !s.doc.is_empty())
            .map_or("", |s| s.doc)
    } else {
        svc.doc
    };
    let mut s = String::new();
    if svc.code > 0 {
        s.push_str(&format!("AdaIR service, command code {}\n\n", svc.code));
    } else if svc.group != table::Group::Library {
        s.push_str("AdaIR service (simulator)\n\n");
    }
    s.push_str(doc);
    let raises = exceptions_in(doc);
    if !raises.is_empty() {
        s.push_str(&format!("\n\nRaises: {}", raises.join(", ")));
    }
    s
}

/// The exception names (of the services' exception table) a doc text
/// mentions, as spelled there.
fn exceptions_in(doc: &str) -> Vec<String> {
    let names: Vec<String> = crate::services::Exc::ALL
        .iter()
        .map(|e| {
            let full = e.full_name();
            full.rsplit('.').next().unwrap_or(full).to_string()
        })
        .collect();
    let mut out: Vec<String> = Vec::new();
    for w in doc.split(|c: char| !(c.is_alphanumeric() || c == '_')) {
        if names.iter().any(|n| n.eq_ignore_ascii_case(w)) && !out.iter().any(|o| o == w) {
            out.push(w.to_string());
        }
    }
    out
}

fn code_block(s: &str) -> String {
    format!("```ada\n{}\n```", s.trim_end())
}

/// A comment after the declaration on its last line (`--  radians`).
fn comment_beside(text: &str, end: usize) -> Option<&str> {
    let rest = text.get(end.min(text.len())..)?;
    let line = rest.split('\n').next().unwrap_or("");
    line.trim().strip_prefix("--").map(str::trim)
}

/// The first lines of a declaration's text (see
/// [`crate::check::index::declaration_text`]).
fn decl_text(a: &Analysis, s: Span) -> String {
    crate::check::index::declaration_text(a.sources.text(s.context), s)
}

/// Hover text (markdown) and the range it is about.
pub fn hover(a: &Analysis, offset: usize) -> Option<(String, Span)> {
    if let Some((_, d)) = def_at(a, offset) {
        let at = a
            .checker
            .index
            .refs
            .iter()
            .filter(|r| r.span.context == a.file && r.span.lo() <= offset && offset <= r.span.hi())
            .map(|r| r.span)
            .min_by_key(|s| s.end - s.start)
            .unwrap_or(d.span);
        return Some((describe_def(a, d), at));
    }
    // An expression that is not a name: its type.
    if let Some((span, t)) = a.checker.index.type_at(a.file, offset) {
        let text = a.span_text(span);
        let shown = if text.len() <= 60 && !text.contains('\n') {
            format!("{text} : {}", tname(a, t))
        } else {
            format!("expression : {}", tname(a, t))
        };
        return Some((code_block(&shown), span));
    }
    // Not resolved (the text around it does not check): a service or a
    // name visible at the top level, by its spelling.
    let (s, e) = word_at(&a.text, offset)?;
    let word = &a.text[s..e];
    let span = crate::diag::span(a.file, s, e);
    if let Some(svc) = table::SERVICES
        .iter()
        .find(|x| x.name.eq_ignore_ascii_case(word))
    {
        let decl = svc.declaration();
        let decl = decl.split(" with Import").next().unwrap_or(&decl);
        return Some((
            format!("{}\n\n{}", code_block(decl), service_doc(svc)),
            span,
        ));
    }
    let es = a.checker.entities_of(&word.to_lowercase());
    let e = es.first()?;
    if let Some(d) = a.checker.def_named(&word.to_lowercase(), e) {
        return Some((describe_def(a, d), span));
    }
    let text = match e {
        Entity::Type(t) => format!("type {} (predefined)", tname(a, *t)),
        Entity::Var { ty, .. } => format!("{word} : {}", tname(a, *ty)),
        Entity::EnumLit(t, _) => format!("{word} : {} (predefined)", tname(a, *t)),
        Entity::Exc(_) => format!("{word} : exception (predefined)"),
        _ => return None,
    };
    Some((code_block(&text), span))
}

/// What hover says about a declaration.
pub fn describe_def(a: &Analysis, d: &Def) -> String {
    let src = a.sources.text(d.span.context);
    let mut doc = comment_above(src, d.decl.lo());
    if let Some(c) = comment_beside(src, d.decl.hi()) {
        if !doc.is_empty() {
            doc.push('\n');
        }
        doc.push_str(c);
    }
    // (A renamed exception's doc is the exception's.)
    let exception = match d.renames {
        Some(r) => a.span_text(r).rsplit('.').next().unwrap_or("").trim(),
        None => &d.name,
    };
    if d.kind == DefKind::Exception
        && let Some(e) = crate::services::exception_doc(exception)
    {
        doc = e;
    }
    let ty = d.ty.map(|t| tname(a, t)).unwrap_or_default();
    let mut s = match d.kind {
        // A renaming: its declaration says what it renames.
        _ if d.renames.is_some() => code_block(&decl_text(a, d.decl)),
        DefKind::Subprogram => {
            let f = d.func.unwrap_or(u32::MAX);
            let sig = if (f as usize) < a.checker.tables.funcs.len() {
                a.checker.signature(f)
            } else {
                d.name.clone()
            };
            let mut s = code_block(&sig);
            if let Some(svc) = service_of(a, f) {
                s.push_str("\n\n");
                s.push_str(&service_doc(svc));
                return s;
            }
            s
        }
        DefKind::Variable => code_block(&format!("{} : {ty}", d.name)),
        DefKind::Constant => code_block(&format!("{} : constant {ty}", d.name)),
        DefKind::Parameter => code_block(&format!("{} : {ty}  -- parameter", d.name)),
        DefKind::LoopVariable => code_block(&format!("{} : {ty}  -- loop variable", d.name)),
        DefKind::Field => code_block(&format!("{} : {ty}  -- record component", d.name)),
        DefKind::EnumLiteral => code_block(&format!("{} : {ty}  -- enumeration literal", d.name)),
        DefKind::Type | DefKind::Number | DefKind::Entry => code_block(&decl_text(a, d.decl)),
        DefKind::Exception => code_block(&format!("{} : exception", d.name)),
        DefKind::Package => code_block(&format!("package {}", d.name)),
    };
    // An object's type, when it is declared in a source: its definition.
    if matches!(
        d.kind,
        DefKind::Variable | DefKind::Constant | DefKind::Parameter | DefKind::Field
    ) && let Some(td) = d.ty.and_then(|t| a.checker.index.def_of_type(t))
    {
        s.push_str("\n\n");
        s.push_str(&code_block(&decl_text(a, td.decl)));
    }
    if !doc.is_empty() {
        s.push_str("\n\n");
        s.push_str(&doc);
    }
    if d.span.context != a.file {
        s.push_str(&format!(
            "\n\n*declared in {}*",
            a.sources.name(d.span.context)
        ));
    }
    s
}

/// The declaration of the name at `offset`.
pub fn definition(a: &Analysis, offset: usize) -> Option<Span> {
    def_at(a, offset).map(|(_, d)| d.span)
}

/// Every place that names the declaration of the name at `offset`.
pub fn references(a: &Analysis, offset: usize, with_decl: bool) -> Vec<Span> {
    let Some((i, d)) = def_at(a, offset) else {
        return Vec::new();
    };
    let mut v = a.checker.index.uses_of(i);
    if with_decl {
        v.push(d.span);
    }
    v.sort_by_key(|s| (s.context, s.start));
    v.dedup();
    v
}

/// Why a rename cannot be done, or the spans to replace.
pub fn rename(a: &Analysis, offset: usize, new_name: &str) -> Result<Vec<Span>, String> {
    let Some((i, d)) = def_at(a, offset) else {
        return Err("no name that adair knows is here".into());
    };
    if d.span.context != a.file {
        return Err(format!(
            "`{}` is declared in {}, not in this file",
            d.name,
            a.sources.name(d.span.context)
        ));
    }
    if !is_identifier(new_name) {
        return Err(format!("`{new_name}` is not an Ada identifier"));
    }
    // A use that does not check is not in the side tables: renaming now
    // could leave it behind.
    if a.diags.iter().any(|d| !d.is_warning()) || a.crashed.is_some() {
        return Err(
            "the file has errors: fix them first, so that every use of the name is known".into(),
        );
    }
    let mut v = a.checker.index.uses_of(i);
    v.push(d.span);
    v.retain(|s| s.context == a.file);
    v.sort_by_key(|s| s.start);
    v.dedup();
    Ok(v)
}

/// An Ada identifier that is not a reserved word.
pub fn is_identifier(s: &str) -> bool {
    let mut cs = s.chars();
    cs.next().is_some_and(char::is_alphabetic)
        && s.chars().all(|c| c.is_alphanumeric() || c == '_')
        && !s.contains("__")
        && !s.ends_with('_')
        && !crate::syntax::token::Kw::ALL
            .iter()
            .any(|(w, _)| w.eq_ignore_ascii_case(s))
}

/// One symbol of the outline.
#[derive(Clone, Debug, PartialEq)]
pub struct Symbol {
    pub name: String,
    pub detail: Option<String>,
    pub kind: lsp_types::SymbolKind,
    /// The whole declaration.
    pub span: Span,
    /// The name.
    pub name_span: Span,
    pub children: Vec<Symbol>,
}

/// The outline of a document, from its syntax tree as far as it parses.
pub fn symbols(a: &Analysis) -> Vec<Symbol> {
    let Some(unit) = &a.unit else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for item in &unit.items {
        match item {
            ast::TopItem::Decl(d) => decl_symbols(a, d, &mut out),
            ast::TopItem::Stmt(s) => stmt_symbols(a, s, &mut out),
            _ => {}
        }
    }
    out
}

fn stmt_symbols(a: &Analysis, s: &ast::Stmt, out: &mut Vec<Symbol>) {
    if let ast::StmtKind::Decl(d) = &s.kind {
        decl_symbols(a, d, out);
    }
}

fn decl_symbols(a: &Analysis, d: &ast::Decl, out: &mut Vec<Symbol>) {
    use lsp_types::SymbolKind as K;
    let mark = |ind: &ast::SubtypeInd| a.span_text(ind.span).to_string();
    let mut leaf = |name: &ast::Ident, kind: K, detail: Option<String>| {
        out.push(Symbol {
            name: name.name.to_string(),
            detail,
            kind,
            span: d.span,
            name_span: name.span,
            children: Vec::new(),
        })
    };
    match &d.kind {
        ast::DeclKind::Object {
            names,
            constant,
            ty,
            ..
        } => {
            for n in names {
                let kind = if *constant { K::CONSTANT } else { K::VARIABLE };
                leaf(n, kind, Some(mark(ty)));
            }
        }
        ast::DeclKind::Number { names, .. } => {
            for n in names {
                leaf(n, K::CONSTANT, None);
            }
        }
        ast::DeclKind::Type {
            name,
            discriminants,
            def,
            ..
        } => {
            let (kind, children) = match def {
                ast::TypeDef::Record(list) => (
                    K::STRUCT,
                    discriminant_symbols(a, discriminants)
                        .chain(components(list).into_iter().flat_map(|c| {
                            c.names.iter().map(move |n| Symbol {
                                name: n.name.to_string(),
                                detail: Some(a.span_text(c.ty.span).to_string()),
                                kind: K::FIELD,
                                span: c.span,
                                name_span: n.span,
                                children: Vec::new(),
                            })
                        }))
                        .collect(),
                ),
                ast::TypeDef::Enum(lits) => (
                    K::ENUM,
                    lits.iter()
                        .filter_map(|l| match l {
                            ast::EnumLit::Ident(i) => Some(Symbol {
                                name: i.name.to_string(),
                                detail: None,
                                kind: K::ENUM_MEMBER,
                                span: i.span,
                                name_span: i.span,
                                children: Vec::new(),
                            }),
                            ast::EnumLit::Char(..) => None,
                        })
                        .collect(),
                ),
                _ => (K::CLASS, Vec::new()),
            };
            let detail = match def {
                ast::TypeDef::Private { limited: true } => "limited private type",
                ast::TypeDef::Private { limited: false } => "private type",
                _ => "type",
            };
            out.push(Symbol {
                name: name.name.to_string(),
                detail: Some(detail.into()),
                kind,
                span: d.span,
                name_span: name.span,
                children,
            });
        }
        ast::DeclKind::Subtype { name, ind } => leaf(name, K::CLASS, Some(mark(ind))),
        ast::DeclKind::Exception { names } => {
            for n in names {
                leaf(n, K::EVENT, Some("exception".into()));
            }
        }
        ast::DeclKind::SubprogramDecl { spec, .. } => {
            out.push(subprogram_symbol(a, spec, d.span, Vec::new()));
        }
        ast::DeclKind::SubprogramBody(b) => {
            let mut children = Vec::new();
            for x in &b.decls {
                decl_symbols(a, x, &mut children);
            }
            for s in b.body.stmts.borrow().iter() {
                stmt_symbols(a, s, &mut children);
            }
            out.push(subprogram_symbol(a, &b.spec, d.span, children));
        }
        ast::DeclKind::PackageSpec(p) => {
            let mut children = Vec::new();
            for x in p.decls.iter().chain(&p.private) {
                decl_symbols(a, x, &mut children);
            }
            out.push(package_symbol(a, &p.name, d.span, children, "package"));
        }
        ast::DeclKind::PackageBody(p) => {
            let mut children = Vec::new();
            for x in &p.decls {
                decl_symbols(a, x, &mut children);
            }
            out.push(package_symbol(a, &p.name, d.span, children, "package body"));
        }
        ast::DeclKind::Renaming(r) => {
            let renames = format!("renames {}", a.span_text(r.renamed.span));
            match &r.what {
                ast::Renamed::Object { name, ty } => {
                    let detail = format!("{} {renames}", a.span_text(ty.span));
                    leaf(name, K::VARIABLE, Some(detail));
                }
                ast::Renamed::Exception(name) => leaf(name, K::EVENT, Some(renames)),
                ast::Renamed::Package(name) => leaf(name, K::MODULE, Some(renames)),
                ast::Renamed::Subprogram(spec) => {
                    let mut sym = subprogram_symbol(a, spec, d.span, Vec::new());
                    sym.detail = Some(renames);
                    out.push(sym);
                }
            }
        }
        // A task or protected object (or type) and its entries, subprograms
        // and private components; their bodies with what they declare.
        ast::DeclKind::TaskSpec(t) => {
            let children = t.entries.iter().map(|e| entry_symbol(a, e)).collect();
            let (kind, detail) = if t.is_type {
                (K::CLASS, "task type")
            } else {
                (K::OBJECT, "task")
            };
            out.push(unit_symbol(&t.name, d.span, children, kind, detail));
        }
        ast::DeclKind::ProtectedSpec(p) => {
            let mut children = Vec::new();
            for op in &p.ops {
                match op {
                    ast::ProtOp::Sub(spec) => {
                        children.push(subprogram_symbol(a, spec, spec.span, Vec::new()));
                    }
                    ast::ProtOp::Entry(e) => children.push(entry_symbol(a, e)),
                }
            }
            children.extend(p.private_entries.iter().map(|e| entry_symbol(a, e)));
            for x in &p.private {
                decl_symbols(a, x, &mut children);
            }
            let (kind, detail) = if p.is_type {
                (K::CLASS, "protected type")
            } else {
                (K::OBJECT, "protected")
            };
            out.push(unit_symbol(&p.name, d.span, children, kind, detail));
        }
        ast::DeclKind::TaskBody(t) => {
            let mut children = Vec::new();
            for x in &t.decls {
                decl_symbols(a, x, &mut children);
            }
            out.push(unit_symbol(
                &t.name,
                d.span,
                children,
                K::CLASS,
                "task body",
            ));
        }
        ast::DeclKind::ProtectedBody(p) => {
            let mut children = Vec::new();
            for x in &p.decls {
                decl_symbols(a, x, &mut children);
            }
            out.push(unit_symbol(
                &p.name,
                d.span,
                children,
                K::CLASS,
                "protected body",
            ));
        }
        ast::DeclKind::EntryBody(e) => {
            let mut children = Vec::new();
            for x in &e.decls {
                decl_symbols(a, x, &mut children);
            }
            let detail = match &e.family {
                Some((i, r)) => format!("entry body (for {} in {})", i.name, range_text(a, r)),
                None => "entry body".into(),
            };
            out.push(Symbol {
                name: e.name.name.to_string(),
                detail: Some(detail),
                kind: K::METHOD,
                span: d.span,
                name_span: e.name.span,
                children,
            });
        }
        _ => {}
    }
}

/// An entry of a task or protected declaration: a family says its range.
fn entry_symbol(a: &Analysis, e: &ast::EntryDecl) -> Symbol {
    let detail = match &e.family {
        Some(r) => format!("entry family ({})", range_text(a, r)),
        None => "entry".into(),
    };
    Symbol {
        name: e.name.name.to_string(),
        detail: Some(detail),
        kind: lsp_types::SymbolKind::EVENT,
        span: e.span,
        name_span: e.name.span,
        children: Vec::new(),
    }
}

/// A discrete range as written.
fn range_text(a: &Analysis, r: &ast::DiscreteRange) -> String {
    let span = match r {
        ast::DiscreteRange::Range(l, h) => {
            crate::diag::span(l.span.context, l.span.lo(), h.span.hi())
        }
        ast::DiscreteRange::Subtype(ind) => ind.span,
        ast::DiscreteRange::Attr(e) => e.span,
    };
    a.span_text(span).to_string()
}

/// A task or protected declaration or body.
fn unit_symbol(
    name: &ast::Ident,
    span: Span,
    children: Vec<Symbol>,
    kind: lsp_types::SymbolKind,
    what: &str,
) -> Symbol {
    Symbol {
        name: name.name.to_string(),
        detail: Some(what.into()),
        kind,
        span,
        name_span: name.span,
        children,
    }
}

/// A record's discriminants, as fields of its outline.
fn discriminant_symbols<'a>(
    a: &'a Analysis,
    discriminants: &'a [ast::Param],
) -> impl Iterator<Item = Symbol> + 'a {
    discriminants.iter().flat_map(move |p| {
        p.names.iter().map(move |n| Symbol {
            name: n.name.to_string(),
            detail: Some(format!("discriminant : {}", a.span_text(p.ty.span))),
            kind: lsp_types::SymbolKind::FIELD,
            span: p.span,
            name_span: n.span,
            children: Vec::new(),
        })
    })
}

/// Every component of a record, those of its variants included, in order.
fn components(list: &ast::ComponentList) -> Vec<&ast::Component> {
    let mut out: Vec<&ast::Component> = list.components.iter().collect();
    if let Some(v) = &list.variants {
        for arm in &v.arms {
            out.extend(components(&arm.body));
        }
    }
    out
}

fn subprogram_symbol(
    a: &Analysis,
    spec: &ast::SubprogramSpec,
    span: Span,
    children: Vec<Symbol>,
) -> Symbol {
    let kind = if spec.ret.is_some() {
        lsp_types::SymbolKind::FUNCTION
    } else {
        lsp_types::SymbolKind::METHOD
    };
    let detail = a
        .span_text(spec.span)
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ");
    Symbol {
        name: spec.name.display(),
        detail: Some(detail),
        kind,
        span,
        name_span: spec.name.span(),
        children,
    }
}

fn package_symbol(
    a: &Analysis,
    name: &ast::Expr,
    span: Span,
    children: Vec<Symbol>,
    what: &str,
) -> Symbol {
    Symbol {
        name: a.span_text(name.span).to_string(),
        detail: Some(what.into()),
        kind: lsp_types::SymbolKind::PACKAGE,
        span,
        name_span: name.span,
        children,
    }
}

/// Converts a symbol tree to the protocol's type.
#[allow(deprecated)] // `DocumentSymbol::deprecated` must still be given.
pub fn to_document_symbol(text: &str, lines: &LineIndex, s: &Symbol) -> lsp_types::DocumentSymbol {
    let range = lines.range(text, s.span);
    let mut sel = lines.range(text, s.name_span);
    // The selection must lie inside the range.
    if sel.start < range.start || sel.end > range.end {
        sel = range;
    }
    lsp_types::DocumentSymbol {
        name: if s.name.is_empty() {
            "?".into()
        } else {
            s.name.clone()
        },
        detail: s.detail.clone(),
        kind: s.kind,
        tags: None,
        deprecated: None,
        range,
        selection_range: sel,
        children: Some(
            s.children
                .iter()
                .map(|c| to_document_symbol(text, lines, c))
                .collect(),
        ),
    }
}
