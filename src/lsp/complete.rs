//! Completion and signature help. Both work on text that does not parse
//! where the cursor is (it is being typed): the context is read from the
//! characters before the cursor, and names from the checker's side tables
//! of what did check.

use super::analysis::Analysis;
use super::features::{self, service_doc, service_of};
use crate::check::Entity;
use crate::check::index::DefKind;
use crate::check::types::TypeId;
use crate::diag::Offsets as _;
use crate::diag::Span;
use crate::syntax::ast;
use lsp_types::{CompletionItemKind as CK, InsertTextFormat};

/// One completion candidate.
#[derive(Clone, Debug, PartialEq)]
pub struct Item {
    pub label: String,
    pub kind: CK,
    pub detail: Option<String>,
    pub doc: Option<String>,
    /// A snippet with `$1` placeholders, inserted instead of the label.
    pub snippet: Option<String>,
}

impl Item {
    fn new(label: impl Into<String>, kind: CK) -> Item {
        Item {
            label: label.into(),
            kind,
            detail: None,
            doc: None,
            snippet: None,
        }
    }

    pub fn to_lsp(&self) -> lsp_types::CompletionItem {
        lsp_types::CompletionItem {
            label: self.label.clone(),
            kind: Some(self.kind),
            detail: self.detail.clone(),
            documentation: self.doc.clone().map(|d| {
                lsp_types::Documentation::MarkupContent(lsp_types::MarkupContent {
                    kind: lsp_types::MarkupKind::Markdown,
                    value: d,
                })
            }),
            insert_text: self.snippet.clone(),
            insert_text_format: self.snippet.as_ref().map(|_| InsertTextFormat::SNIPPET),
            ..Default::default()
        }
    }
}

/// Snippets: (label, description, body).
const SNIPPETS: &[(&str, &str, &str)] = &[
    (
        "procedure ... is begin ... end",
        "procedure body",
        "procedure ${1:Name} is\nbegin\n   ${0:null;}\nend ${1:Name};",
    ),
    (
        "function ... return ... is begin ... end",
        "function body",
        "function ${1:Name} (${2:X} : ${3:Integer}) return ${4:Integer} is\nbegin\n   return ${0:X};\nend ${1:Name};",
    ),
    (
        "for ... loop",
        "counting loop",
        "for ${1:I} in ${2:1} .. ${3:10} loop\n   ${0:null;}\nend loop;",
    ),
    (
        "while ... loop",
        "while loop",
        "while ${1:Condition} loop\n   ${0:null;}\nend loop;",
    ),
    (
        "if ... then ... end if",
        "if statement",
        "if ${1:Condition} then\n   ${0:null;}\nend if;",
    ),
    (
        "exception when ... =>",
        "exception handler",
        "exception\n   when ${1:E} : ${2:OutOfReach} =>\n      ${0:Put_Line (Exception_Message (E));}",
    ),
    (
        "when others =>",
        "handler for any exception",
        "when others =>\n   ${0:null;}",
    ),
    (
        "declare ... begin ... end",
        "block",
        "declare\n   ${1:X} : ${2:Integer} := ${3:0};\nbegin\n   ${0:null;}\nend;",
    ),
];

/// What the characters before the cursor ask for.
#[derive(Debug, PartialEq)]
enum Context {
    /// After `Prefix.`: the names of the prefix (dotted, as written).
    Select(String),
    /// After `X'`.
    Attribute,
    Name,
}

fn is_id(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// The context at `offset`, skipping the identifier being typed.
fn context(text: &str, offset: usize) -> Context {
    let before = text.get(..offset.min(text.len())).unwrap_or("");
    let head = before.trim_end_matches(is_id);
    if let Some(rest) = head.strip_suffix('\'') {
        // `'a'` is a character literal; `X'` and `)'` begin an attribute.
        let word_start = rest.trim_end_matches(is_id);
        let after_name = rest.len() > word_start.len() && !word_start.ends_with('\'');
        if rest.ends_with(')') || after_name {
            return Context::Attribute;
        }
    }
    if let Some(rest) = head.strip_suffix('.') {
        if rest.ends_with('.') {
            return Context::Name; // `1 ..`
        }
        // The dotted name before the dot.
        let start = rest
            .char_indices()
            .rev()
            .take_while(|(_, c)| is_id(*c) || *c == '.')
            .last()
            .map_or(rest.len(), |(i, _)| i);
        let prefix = &rest[start..];
        if !prefix.is_empty() && prefix.starts_with(|c: char| c.is_alphabetic()) {
            return Context::Select(prefix.to_string());
        }
    }
    Context::Name
}

/// The completion candidates at `offset`.
pub fn completion(a: &Analysis, offset: usize) -> Vec<Item> {
    match context(&a.text, offset) {
        Context::Attribute => crate::check::index::ATTRIBUTES
            .iter()
            .map(|n| Item::new(*n, CK::PROPERTY))
            .collect(),
        Context::Select(prefix) => select_items(a, offset, &prefix),
        Context::Name => name_items(a, offset),
    }
}

/// The spans of the syntax tree in which a declaration is local: subprogram
/// bodies, blocks, loops and handlers.
fn regions(unit: &ast::CompilationUnit) -> Vec<Span> {
    fn stmts(ss: &[ast::Stmt], out: &mut Vec<Span>) {
        for s in ss {
            match &s.kind {
                ast::StmtKind::Block { decls, body, .. } => {
                    out.push(s.span);
                    decl_list(decls, out);
                    block(body, out);
                }
                ast::StmtKind::Loop { body, .. } => {
                    out.push(s.span);
                    stmts(body, out);
                }
                ast::StmtKind::If { arms, els } => {
                    for (_, b) in arms {
                        stmts(b, out);
                    }
                    if let Some(b) = els {
                        stmts(b, out);
                    }
                }
                ast::StmtKind::Case { arms, .. } => {
                    for arm in arms {
                        stmts(&arm.body, out);
                    }
                }
                ast::StmtKind::Decl(d) => decl_list(std::slice::from_ref(d), out),
                _ => {}
            }
        }
    }
    fn block(b: &ast::Block, out: &mut Vec<Span>) {
        stmts(&b.stmts.borrow(), out);
        for h in &b.handlers {
            out.push(h.span);
            stmts(&h.stmts, out);
        }
    }
    fn decl_list(ds: &[ast::Decl], out: &mut Vec<Span>) {
        for d in ds {
            match &d.kind {
                ast::DeclKind::SubprogramBody(b) => {
                    out.push(d.span);
                    decl_list(&b.decls, out);
                    block(&b.body, out);
                }
                ast::DeclKind::PackageBody(p) => {
                    out.push(d.span);
                    decl_list(&p.decls, out);
                    if let Some(b) = &p.init {
                        block(b, out);
                    }
                }
                ast::DeclKind::PackageSpec(p) => {
                    out.push(d.span);
                    decl_list(&p.decls, out);
                    decl_list(&p.private, out);
                }
                _ => {}
            }
        }
    }
    let mut out = Vec::new();
    for item in &unit.items {
        match item {
            ast::TopItem::Decl(d) => decl_list(std::slice::from_ref(d), &mut out),
            ast::TopItem::Stmt(s) => stmts(std::slice::from_ref(s), &mut out),
            _ => {}
        }
    }
    out
}

/// The declarations of this document visible at `offset` (innermost last):
/// those declared before it whose enclosing region holds it.
pub fn visible_defs(a: &Analysis, offset: usize) -> Vec<u32> {
    let regions = a.unit.as_ref().map(regions).unwrap_or_default();
    let inside = |r: &Span, s: usize, e: usize| r.lo() <= s && e <= r.hi();
    let mut v = Vec::new();
    for (i, d) in a.checker.index.defs.iter().enumerate() {
        // Components and entries are named through their record or object.
        if d.span.context != a.file
            || matches!(d.kind, DefKind::Field | DefKind::Entry)
            || d.span.lo() > offset
        {
            continue;
        }
        // A subprogram or package is declared in the region around its own.
        let own = matches!(d.kind, DefKind::Subprogram | DefKind::Package);
        let owner = regions
            .iter()
            .filter(|r| inside(r, d.span.lo(), d.span.hi()) && !(own && r.start == d.decl.start))
            .min_by_key(|r| r.end - r.start);
        // A parameter is visible in its body only (not after a spec).
        if d.kind == DefKind::Parameter && owner.is_none_or(|r| r.start != d.decl.start) {
            continue;
        }
        if owner.is_none_or(|r| inside(r, offset, offset)) {
            v.push(i as u32);
        }
    }
    v
}

fn kind_of(k: DefKind) -> CK {
    match k {
        DefKind::Variable | DefKind::Parameter | DefKind::LoopVariable => CK::VARIABLE,
        DefKind::Constant | DefKind::Number => CK::CONSTANT,
        DefKind::Type => CK::CLASS,
        DefKind::Subprogram => CK::FUNCTION,
        DefKind::EnumLiteral => CK::ENUM_MEMBER,
        DefKind::Exception => CK::EVENT,
        DefKind::Package => CK::MODULE,
        DefKind::Field => CK::FIELD,
        DefKind::Entry => CK::METHOD,
    }
}

fn entity_kind(e: &Entity) -> CK {
    match e {
        Entity::Var { constant: true, .. } | Entity::Number(_) => CK::CONSTANT,
        Entity::Var { .. } | Entity::Alias(_) => CK::VARIABLE,
        Entity::Type(_) => CK::CLASS,
        Entity::Func(_) => CK::FUNCTION,
        Entity::EnumLit(..) => CK::ENUM_MEMBER,
        Entity::Exc(_) => CK::EVENT,
        Entity::Package(_) => CK::MODULE,
    }
}

fn name_items(a: &Analysis, offset: usize) -> Vec<Item> {
    let mut out: Vec<Item> = Vec::new();
    let mut seen = std::collections::HashSet::new();
    let mut push = |out: &mut Vec<Item>, it: Item| {
        if seen.insert(it.label.to_lowercase()) {
            out.push(it);
        }
    };
    // Local names first (innermost wins).
    for i in visible_defs(a, offset).into_iter().rev() {
        let d = &a.checker.index.defs[i as usize];
        let mut it = Item::new(d.name.clone(), kind_of(d.kind));
        it.detail = match (d.kind, d.func) {
            (DefKind::Subprogram, Some(f)) => Some(a.checker.signature(f)),
            _ => d.ty.map(|t| a.checker.tables.types.name(t).to_string()),
        };
        push(&mut out, it);
    }
    // The services, with their documentation from the table.
    for svc in crate::services::table::SERVICES {
        let mut it = Item::new(svc.name, CK::FUNCTION);
        let decl = svc.declaration();
        it.detail = Some(
            decl.split(" with Import")
                .next()
                .unwrap_or(&decl)
                .to_string(),
        );
        it.doc = Some(service_doc(svc));
        push(&mut out, it);
    }
    // Names visible at the top level: the document's and the used packages'.
    for key in a.checker.completion_names() {
        if key.starts_with(['\'', '"', ' ']) {
            continue;
        }
        let es = a.checker.entities_of(&key);
        let Some(e) = es.first() else { continue };
        let mut it = Item::new(a.checker.spelled(&key), entity_kind(e));
        it.detail = match e {
            Entity::Func(f) => Some(a.checker.signature(*f)),
            Entity::Var { ty, .. } | Entity::EnumLit(ty, _) => {
                Some(a.checker.tables.types.name(*ty).to_string())
            }
            _ => None,
        };
        push(&mut out, it);
    }
    for (w, _) in crate::syntax::token::Kw::ALL {
        push(&mut out, Item::new(*w, CK::KEYWORD));
    }
    for (label, what, body) in SNIPPETS {
        let mut it = Item::new(*label, CK::SNIPPET);
        it.detail = Some(what.to_string());
        it.snippet = Some(body.to_string());
        out.push(it);
    }
    out
}

/// The type of the object a simple name denotes at `offset`.
fn object_type(a: &Analysis, offset: usize, name: &str) -> Option<TypeId> {
    for i in visible_defs(a, offset).into_iter().rev() {
        let d = &a.checker.index.defs[i as usize];
        if d.name.eq_ignore_ascii_case(name) {
            return match d.kind {
                DefKind::Variable
                | DefKind::Constant
                | DefKind::Parameter
                | DefKind::LoopVariable => d.ty,
                _ => None,
            };
        }
    }
    match a.checker.entities_of(&name.to_lowercase()).first() {
        Some(Entity::Var { ty, .. }) => Some(*ty),
        Some(Entity::Alias(x)) => Some(x.ty),
        _ => None,
    }
}

/// The package a package renaming visible at `offset` renames (as
/// written after `renames`), followed through renamings of renamings.
fn renamed_package(a: &Analysis, offset: usize, prefix: &str) -> Option<String> {
    let defs = visible_defs(a, offset);
    let mut name = prefix.to_string();
    let mut found = None;
    for _ in 0..8 {
        let renames = defs.iter().rev().find_map(|&i| {
            let d = &a.checker.index.defs[i as usize];
            (d.kind == DefKind::Package && d.name.eq_ignore_ascii_case(&name))
                .then_some(d.renames)
                .flatten()
        });
        let Some(r) = renames else { break };
        name = a.span_text(r).to_string();
        found = Some(name.clone());
    }
    found
}

fn select_items(a: &Analysis, offset: usize, prefix: &str) -> Vec<Item> {
    let c = &a.checker;
    let package = renamed_package(a, offset, prefix);
    if let Some(names) = c.package_names(package.as_deref().unwrap_or(prefix)) {
        return names
            .iter()
            .filter(|k| !k.starts_with(['\'', '"']))
            .map(|k| {
                let kind = c.entities_of(k).first().map_or(CK::VALUE, entity_kind);
                let mut it = Item::new(c.spelled(k), kind);
                if let Some(svc) = crate::services::table::SERVICES
                    .iter()
                    .find(|s| s.name.eq_ignore_ascii_case(k))
                {
                    it.kind = CK::FUNCTION;
                    it.doc = Some(service_doc(svc));
                }
                it
            })
            .collect();
    }
    // A record object, then its components down the dotted name.
    let mut parts = prefix.split('.');
    let Some(first) = parts.next() else {
        return Vec::new();
    };
    let Some(mut ty) = object_type(a, offset, first) else {
        return Vec::new();
    };
    // A private type's components are not offered outside its package.
    let here = Some((a.file, offset));
    for p in parts {
        let t = c.tables.types.designated(ty).unwrap_or(ty);
        let Some(f) = c
            .tables
            .types
            .fields(t)
            .filter(|_| c.components_visible_at(t, here))
            .and_then(|fs| fs.iter().find(|f| f.key == p.to_lowercase()))
        else {
            return Vec::new();
        };
        ty = f.ty;
    }
    let t = c.tables.types.designated(ty).unwrap_or(ty);
    // A task's entries; a protected object's entries and subprograms.
    let ops = c.operations_of(t);
    if !ops.is_empty() {
        return ops
            .into_iter()
            .map(|(name, f, entry)| {
                let mut it = Item::new(name, if entry { CK::METHOD } else { CK::FUNCTION });
                it.detail = c.index.def_of_func(f).map(|d| {
                    crate::check::index::declaration_text(a.sources.text(d.decl.context), d.decl)
                });
                it
            })
            .collect();
    }
    // Outside its package, a private type's partial view shows only its
    // discriminants.
    let fields = if c.components_visible_at(t, here) {
        c.tables.types.fields(t)
    } else {
        let b = c.tables.types.base(t);
        c.tables.types.partial_discrs.get(&b).map(|v| v.as_slice())
    };
    fields
        .map(|fs| {
            fs.iter()
                .map(|f| {
                    let mut it = Item::new(f.name.clone(), CK::FIELD);
                    it.detail = Some(c.tables.types.name(f.ty).to_string());
                    it
                })
                .collect()
        })
        .unwrap_or_default()
}

/// One candidate: its label, each parameter's range in the label (UTF-16
/// code units) and its documentation.
#[derive(Clone, Debug, PartialEq)]
pub struct Signature {
    pub label: String,
    pub params: Vec<(usize, usize)>,
    pub doc: Option<String>,
}

/// Signature help: the candidate signatures (label and each parameter's
/// range in it), which is active, and the active parameter.
#[derive(Clone, Debug, PartialEq)]
pub struct Signatures {
    pub list: Vec<Signature>,
    pub active: usize,
    pub param: usize,
}

/// The call around `offset`: the name before the open parenthesis, the
/// argument index and the name of a named association being written.
fn open_call(text: &str, offset: usize) -> Option<(String, usize, usize, Option<String>)> {
    let before = text.get(..offset.min(text.len()))?;
    // From the start of the statement: strings and comments are skipped.
    let mut stack: Vec<(usize, usize)> = Vec::new(); // (paren offset, commas)
    let mut in_str = false;
    let mut chars = before.char_indices().peekable();
    while let Some((i, ch)) = chars.next() {
        if in_str {
            if ch == '"' {
                in_str = false;
            }
            continue;
        }
        match ch {
            '"' => in_str = true,
            '-' if chars.peek().is_some_and(|(_, c)| *c == '-') => {
                for (_, c) in chars.by_ref() {
                    if c == '\n' {
                        break;
                    }
                }
            }
            '\'' => {
                // A character literal `'x'`: skip it whole.
                let mut look = chars.clone();
                if let (Some(_), Some((_, '\''))) = (look.next(), look.next()) {
                    chars.next();
                    chars.next();
                }
            }
            '(' => stack.push((i, 0)),
            ')' => {
                stack.pop();
            }
            ',' => {
                if let Some(top) = stack.last_mut() {
                    top.1 += 1;
                }
            }
            ';' => stack.clear(),
            _ => {}
        }
    }
    let &(paren, commas) = stack.last()?;
    let head = before[..paren].trim_end();
    let start = head
        .char_indices()
        .rev()
        .take_while(|(_, c)| is_id(*c) || *c == '.')
        .last()
        .map_or(head.len(), |(i, _)| i);
    let name = head[start..].rsplit('.').next()?.to_string();
    if name.is_empty() {
        return None;
    }
    // `Name => ` in the argument being written.
    let arg = before[paren + 1..].rsplit(',').next().unwrap_or("");
    let named = arg
        .split_once("=>")
        .map(|(n, _)| n.trim().to_string())
        .filter(|n| features::is_identifier(n));
    Some((name, start, commas, named))
}

pub fn signature_help(a: &Analysis, offset: usize) -> Option<Signatures> {
    let (name, name_at, commas, named) = open_call(&a.text, offset)?;
    let c = &a.checker;
    // The subprogram the checker chose there, else every one so named.
    let resolved = features::def_at(a, name_at)
        .and_then(|(_, d)| d.func)
        .filter(|f| c.tables.funcs[*f as usize].name.eq_ignore_ascii_case(&name));
    let mut funcs: Vec<u32> = match resolved {
        Some(f) => vec![f],
        None => (0..c.tables.funcs.len() as u32)
            .filter(|f| c.tables.funcs[*f as usize].name.eq_ignore_ascii_case(&name))
            .collect(),
    };
    funcs.dedup_by_key(|f| c.signature(*f));
    if funcs.is_empty() {
        return None;
    }
    let mut list = Vec::new();
    let mut active = None;
    let mut param = commas;
    for (k, f) in funcs.iter().enumerate() {
        let sub = &c.tables.funcs[*f as usize];
        let mut label = format!("{} ", sub.name);
        let mut ranges = Vec::new();
        if !sub.params.is_empty() {
            label.push('(');
            for (i, p) in sub.params.iter().enumerate() {
                if i > 0 {
                    label.push_str("; ");
                }
                let mode = match p.mode {
                    ast::Mode::In => "",
                    ast::Mode::Out => "out ",
                    ast::Mode::InOut => "in out ",
                };
                let start = label.encode_utf16().count();
                label.push_str(&format!("{} : {mode}{}", p.name, c.tables.types.name(p.ty)));
                if p.default.is_some() {
                    label.push_str(" := ...");
                }
                ranges.push((start, label.encode_utf16().count()));
            }
            label.push(')');
        }
        if let Some(r) = sub.ret {
            label.push_str(&format!(" return {}", c.tables.types.name(r)));
        }
        let label = label.trim_end().to_string();
        let doc = service_of(a, *f).map(service_doc);
        let fits = match &named {
            Some(n) => sub
                .params
                .iter()
                .position(|p| p.name.eq_ignore_ascii_case(n)),
            None => (commas < sub.params.len()).then_some(commas),
        };
        if active.is_none()
            && let Some(p) = fits
        {
            active = Some(k);
            param = p;
        }
        list.push(Signature {
            label,
            params: ranges,
            doc,
        });
    }
    Some(Signatures {
        list,
        active: active.unwrap_or(0),
        param,
    })
}
