//! The checker's side tables for tools (the language server, later the
//! REPL): every declaration it sees ([`Def`]: name, kind, where, type) and
//! every use of a name it resolves ([`Ref`]: where -> which declaration).
//!
//! Recording is one `Vec` push per declared or resolved name. A use is
//! recorded when the checker has chosen its meaning: for a non-overloadable
//! name when it is looked up, for a subprogram or enumeration literal when
//! overload resolution has picked one. A use whose meaning could not be
//! chosen (an error) records nothing, so what checks keeps its names even
//! when the rest of the file does not.

use super::ir::{ExcId, FuncId, Var};
use super::types::TypeId;
use super::{Checker, Entity, PMap, PVec};
use crate::diag::Offsets as _;
use crate::diag::Span;

/// What a declaration declares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DefKind {
    Variable,
    Constant,
    Parameter,
    LoopVariable,
    Number,
    Type,
    Subprogram,
    EnumLiteral,
    Exception,
    Package,
    Field,
    /// An entry (or entry family) of a task or protected type: a member,
    /// named after its object (`Loader.Load`).
    Entry,
}

/// One declared name.
#[derive(Clone, Debug)]
pub struct Def {
    /// As written at the declaration.
    pub name: String,
    pub kind: DefKind,
    /// The name at its declaration.
    pub span: Span,
    /// The whole declaration (`X : T := 1;`, the type declaration, the
    /// subprogram body), for hover and document symbols.
    pub decl: Span,
    /// The type of an object, a field or an enumeration literal; the type a
    /// type declaration declares; a function's result type.
    pub ty: Option<TypeId>,
    /// The subprogram a `Subprogram` declares.
    pub func: Option<FuncId>,
    /// A renaming declaration's renamed name (`Pose.Z` of `Tip : Float
    /// renames Pose.Z;`).
    pub renames: Option<Span>,
}

/// One use of a name: its place and the index of its declaration in
/// [`Index::defs`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Ref {
    pub span: Span,
    pub def: u32,
}

/// Identity of what an entity is, to find its declaration. Variables are
/// keyed by their slot: a slot is reused by a later subprogram, and the map
/// then points at the later declaration, which is the one in scope while the
/// later subprogram is checked (a use records its declaration at once).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Key {
    Var(Var),
    Func(FuncId),
    Type(TypeId),
    Exc(ExcId),
    Package(usize),
    Lit(TypeId, i64),
    Field(TypeId, u32),
    /// Parameter `i` of a subprogram, for named associations in calls.
    Param(FuncId, u32),
}

#[derive(Clone, Debug, Default)]
pub struct Index {
    /// Uses and expression types are recorded (for tools: the language
    /// server, the REPL); off for `adair run`/`check`/`test`, where they
    /// would only cost memory (about 16 bytes per byte of source).
    pub uses: bool,
    pub defs: PVec<Def>,
    pub refs: PVec<Ref>,
    /// The type of each expression the checker checked (not errors), by
    /// its span: hover on an operator, a literal or a call shows it.
    pub types: PVec<(Span, TypeId)>,
    by_key: PMap<Key, u32>,
    /// Named numbers and `for E of` element names have no identity but
    /// their name: the latest declaration of the name.
    by_name: PMap<String, u32>,
    /// Renamings of exceptions, packages and objects: the same entity as
    /// the renamed one, told apart by the name a use spells.
    renamings: PMap<(String, Key), u32>,
}

impl Index {
    /// An index that records uses and types too.
    pub fn recording() -> Index {
        Index {
            uses: true,
            ..Index::default()
        }
    }

    /// The declaration a use at `offset` of source `file` refers to, or the
    /// declaration whose name is there.
    pub fn def_at(&self, file: u32, offset: usize) -> Option<u32> {
        let hit = |s: &Span| s.context == file && s.lo() <= offset && offset <= s.hi();
        self.refs
            .iter()
            .filter(|r| hit(&r.span))
            .min_by_key(|r| r.span.end - r.span.start)
            .map(|r| r.def)
            .or_else(|| {
                self.defs
                    .iter()
                    .position(|d| hit(&d.span))
                    .map(|i| i as u32)
            })
    }

    /// The type of the smallest checked expression around `offset`.
    pub fn type_at(&self, file: u32, offset: usize) -> Option<(Span, TypeId)> {
        self.types
            .iter()
            .filter(|(s, _)| s.context == file && s.lo() <= offset && offset < s.hi())
            .min_by_key(|(s, _)| s.end - s.start)
            .copied()
    }

    /// Every place that names declaration `def` (uses, without duplicates,
    /// in source order).
    pub fn uses_of(&self, def: u32) -> Vec<Span> {
        let mut v: Vec<Span> = self
            .refs
            .iter()
            .filter(|r| r.def == def)
            .map(|r| r.span)
            .collect();
        v.sort_by_key(|s| (s.context, s.start, s.end));
        v.dedup();
        v
    }

    /// The declaration of a subprogram.
    pub fn def_of_func(&self, f: FuncId) -> Option<&Def> {
        self.by_key
            .get(&Key::Func(f))
            .and_then(|i| self.defs.get(*i as usize))
    }

    /// The declaration of a type.
    pub fn def_of_type(&self, t: TypeId) -> Option<&Def> {
        self.by_key
            .get(&Key::Type(t))
            .and_then(|i| self.defs.get(*i as usize))
    }

    /// Where component (or discriminant) `i` of type `t` is declared.
    pub fn def_of_field(&self, t: TypeId, i: u32) -> Option<&Def> {
        self.by_key
            .get(&Key::Field(t, i))
            .and_then(|i| self.defs.get(*i as usize))
    }

    /// Components `from .. n` of record type `from_ty`, declared by the full
    /// declaration of private type `to`, are `to`'s (its partial view
    /// declared the discriminants before them).
    pub(super) fn retarget_fields_from(&mut self, from_ty: TypeId, to: TypeId, from: u32, n: u32) {
        for i in from..n {
            if let Some(&d) = self.by_key.get(&Key::Field(from_ty, i)) {
                self.by_key.insert(Key::Field(to, i), d);
            }
        }
    }

    /// The components of record type `from`, declared by the full
    /// declaration of private type `to`, are `to`'s.
    pub(super) fn retarget_fields(&mut self, from: TypeId, to: TypeId, n: u32) {
        for i in 0..n {
            if let Some(&d) = self.by_key.get(&Key::Field(from, i)) {
                self.by_key.insert(Key::Field(to, i), d);
            }
        }
    }
}

fn key_of(e: &Entity) -> Option<Key> {
    Some(match e {
        Entity::Var { var, .. } => Key::Var(*var),
        Entity::Func(f) => Key::Func(*f),
        Entity::Type(t) => Key::Type(*t),
        Entity::Exc(x) => Key::Exc(*x),
        Entity::Package(p) => Key::Package(*p),
        Entity::EnumLit(t, p) => Key::Lit(*t, *p),
        Entity::Number(_) | Entity::Alias(_) => return None,
    })
}

impl Checker {
    /// Records the declaration of `name` at `span` as entity `e`.
    pub(super) fn index_def(&mut self, name: &str, span: Span, e: &Entity, kind: Option<DefKind>) {
        let (k, ty, func) = match e {
            Entity::Var {
                ty, constant: c, ..
            } => (
                if *c {
                    DefKind::Constant
                } else {
                    DefKind::Variable
                },
                Some(*ty),
                None,
            ),
            Entity::Number(_) => (DefKind::Number, None, None),
            Entity::Type(t) => (DefKind::Type, Some(*t), None),
            Entity::Func(f) => (
                DefKind::Subprogram,
                self.tables.funcs.get(*f as usize).and_then(|s| s.ret),
                Some(*f),
            ),
            Entity::EnumLit(t, _) => (DefKind::EnumLiteral, Some(*t), None),
            Entity::Exc(_) => (DefKind::Exception, None, None),
            Entity::Package(_) => (DefKind::Package, None, None),
            Entity::Alias(x) => (DefKind::LoopVariable, Some(x.ty), None),
        };
        let i = self.index.defs.len() as u32;
        self.index.defs.push(Def {
            name: name.to_string(),
            kind: kind.unwrap_or(k),
            span,
            decl: self.cur_decl.unwrap_or(span),
            ty,
            func,
            renames: None,
        });
        match key_of(e) {
            Some(key) => {
                self.index.by_key.insert(key, i);
            }
            None => {
                self.index.by_name.insert(name.to_lowercase(), i);
            }
        }
    }

    /// Records the declaration of an entry (its whole declaration at
    /// `decl`), whose calls, `accept`s and `requeue`s refer to `profile`.
    pub(super) fn index_entry(&mut self, id: &crate::syntax::ast::Ident, decl: Span, f: FuncId) {
        let n = self.index.defs.len() as u32;
        self.index.defs.push(Def {
            name: id.name.to_string(),
            kind: DefKind::Entry,
            span: id.span,
            decl,
            ty: None,
            func: Some(f),
            renames: None,
        });
        self.index.by_key.insert(Key::Func(f), n);
    }

    /// Records a record component's declaration.
    pub(super) fn index_field(
        &mut self,
        rec: TypeId,
        i: u32,
        id: &crate::syntax::ast::Ident,
        ty: TypeId,
    ) {
        let n = self.index.defs.len() as u32;
        self.index.defs.push(Def {
            name: id.name.to_string(),
            kind: DefKind::Field,
            span: id.span,
            decl: id.span,
            ty: Some(ty),
            func: None,
            renames: None,
        });
        self.index.by_key.insert(Key::Field(rec, i), n);
    }

    /// Records parameter `i` of subprogram `f` as written in its spec.
    pub(super) fn index_param(
        &mut self,
        f: FuncId,
        i: u32,
        id: &crate::syntax::ast::Ident,
        ty: TypeId,
    ) {
        let n = self.index.defs.len() as u32;
        self.index.defs.push(Def {
            name: id.name.to_string(),
            kind: DefKind::Parameter,
            span: id.span,
            decl: self.cur_decl.unwrap_or(id.span),
            ty: Some(ty),
            func: None,
            renames: None,
        });
        self.index.by_key.insert(Key::Param(f, i), n);
    }

    /// Records parameter `i` of `f` as the body declares it (entity `e`):
    /// the spec's declaration when the body is its own spec, else a
    /// declaration of its own that named associations then refer to.
    pub(super) fn index_body_param(
        &mut self,
        f: FuncId,
        i: u32,
        id: &crate::syntax::ast::Ident,
        e: &Entity,
    ) {
        let spec = self.index.by_key.get(&Key::Param(f, i)).copied();
        match (spec, key_of(e)) {
            (Some(d), Some(k)) if self.index.defs[d as usize].span == id.span => {
                self.index.by_key.insert(k, d);
            }
            _ => {
                let n = self.index.defs.len() as u32;
                self.index_def(&id.name, id.span, e, Some(DefKind::Parameter));
                self.index.by_key.insert(Key::Param(f, i), n);
            }
        }
    }

    /// Records a named association `Name => ...` of a call of `f`.
    pub(super) fn index_named_arg(&mut self, f: FuncId, id: &crate::syntax::ast::Ident) {
        let Some(i) = self.tables.funcs.get(f as usize).and_then(|s| {
            s.params
                .iter()
                .position(|p| p.name.eq_ignore_ascii_case(&id.name))
        }) else {
            return;
        };
        if let Some(&def) = self.index.by_key.get(&Key::Param(f, i as u32))
            && self.index.uses
        {
            self.index.refs.push(Ref { span: id.span, def });
        }
    }

    /// Records a renaming declaration of `name` at `span` (its renamed name
    /// at `renamed`): an entity that may be the renamed one's, so a use is
    /// its own when it spells `name`.
    pub(super) fn index_renaming(
        &mut self,
        name: &str,
        span: Span,
        e: &Entity,
        kind: Option<DefKind>,
        renamed: Span,
    ) {
        let i = self.index.defs.len() as u32;
        let key = key_of(e);
        let own = key.and_then(|k| self.index.by_key.get(&k).copied());
        self.index_def(name, span, e, kind);
        if let Some(d) = self.index.defs.get_mut(i as usize) {
            d.renames = Some(renamed);
        }
        if let Some(key) = key {
            // The renamed entity's own declaration stays its key's.
            match own {
                Some(own) => self.index.by_key.insert(key, own),
                None => self.index.by_key.remove(&key),
            };
            self.index.renamings.insert((name.to_lowercase(), key), i);
        }
    }

    /// Records that the name at `span` (spelled `key` in lower case) means `e`.
    pub(super) fn index_ref(&mut self, span: Span, key: &str, e: &Entity) {
        if let Some(def) = self.def_index(key, e)
            && self.index.uses
        {
            self.index.refs.push(Ref { span, def });
        }
    }

    /// Records a use of record component `i` of `rec` at `span`.
    pub(super) fn index_field_ref(&mut self, span: Span, rec: TypeId, i: u32) {
        let k = Key::Field(rec, i);
        let def = self.index.by_key.get(&k).or_else(|| {
            self.index
                .by_key
                .get(&Key::Field(self.tables.types.base(rec), i))
        });
        if let Some(&def) = def
            && self.index.uses
        {
            self.index.refs.push(Ref { span, def });
        }
    }

    /// The declaration a name spelled `key` (lower case) that means `e`
    /// refers to: a renaming's own when `key` is the renaming's name (`Gone
    /// : exception renames Constraint_Error;`), else the entity's (as
    /// [`Checker::index_ref`] records a use).
    pub fn def_named(&self, key: &str, e: &Entity) -> Option<&Def> {
        self.def_index(key, e)
            .and_then(|i| self.index.defs.get(i as usize))
    }

    /// The index in [`Index::defs`] of what [`Checker::def_named`] finds.
    fn def_index(&self, key: &str, e: &Entity) -> Option<u32> {
        match key_of(e) {
            Some(k) => self
                .index
                .renamings
                .get(&(key.to_string(), k))
                .or_else(|| self.index.by_key.get(&k)),
            // An object renaming, a named number: by its name.
            None => self.index.by_name.get(key),
        }
        .copied()
    }

    /// The declaration recorded for an entity (not for named numbers).
    pub fn def_of(&self, e: &Entity) -> Option<&Def> {
        key_of(e)
            .and_then(|k| self.index.by_key.get(&k))
            .and_then(|i| self.index.defs.get(*i as usize))
    }
}

/// The attributes the checker knows, as they are spelled in the manual (for
/// completion after `'`).
pub const ATTRIBUTES: &[&str] = &[
    "Ceiling",
    "Constrained",
    "Digits",
    "First",
    "Floor",
    "Image",
    "Last",
    "Length",
    "Max",
    "Min",
    "Pos",
    "Pred",
    "Range",
    "Rounding",
    "Succ",
    "Truncation",
    "Val",
    "Value",
];

/// The first lines (at most 15) of the declaration at `decl` in `src`, its
/// continuation lines unindented by the indentation of its first: what
/// hover and the REPL's `:help` show of a declaration.
pub fn declaration_text(src: &str, decl: Span) -> String {
    const MAX: usize = 15;
    let start = decl.lo().min(src.len());
    let indent = src[..start]
        .rsplit('\n')
        .next()
        .map_or(0, |l| l.len() - l.trim_start().len());
    let t = src.get(decl.range()).unwrap_or("");
    let lines: Vec<&str> = t
        .lines()
        .enumerate()
        .map(|(i, l)| {
            let ws = l.len() - l.trim_start().len();
            if i == 0 { l } else { &l[ws.min(indent)..] }
        })
        .collect();
    let mut out = lines[..lines.len().min(MAX)].join("\n");
    if lines.len() > MAX {
        out.push_str("\n...");
    }
    out
}
