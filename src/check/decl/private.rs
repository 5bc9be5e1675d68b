//! Private types and deferred constants (RM 7.3, 7.4) and limited types
//! (RM 7.5): the partial view a package's visible part declares, the full
//! declaration its private part gives, where each view is visible, and
//! what a limited type refuses (assignment, copies, predefined `=`).
//!
//! A private type is one `TypeId` whose `TypeInfo` holds its full view once
//! the private part has completed it. Where the full view is hidden (outside
//! the package's private part and body) the type is in `Types::hidden`, and
//! the checker's questions about its kind see `TypeKind::Private`: its
//! components, literals, aggregates and the operations of its full type are
//! refused there, while the engines, which see every full view, run it.

use super::*;
use crate::check::tables::Deferred;
use crate::check::types::PrivateView;
use crate::syntax::ast::TypeDef;

impl Checker {
    /// The package whose visible part (`false`) or private part or body
    /// (`true`) the innermost scope is.
    fn innermost_package(&self) -> Option<(usize, bool)> {
        self.scopes.innermost().and_then(|s| s.package)
    }

    /// `type T [(discriminants)] is [limited] private;` (`unknown`: the
    /// discriminant part is `(<>)`).
    pub(super) fn private_type(
        &mut self,
        name: &ast::Ident,
        limited: bool,
        discriminants: &[ast::Param],
        unknown: bool,
        span: Span,
    ) {
        let package = match self.innermost_package() {
            Some((p, false)) => Some(p),
            _ => {
                self.err(diagnostics::private_type_context(span));
                None
            }
        };
        let t = self.tables.types.add(&name.name, TypeKind::Private);
        self.tables.types.list[t as usize].private = package.map(|p| PrivateView {
            package: p as u32,
            limited,
            unknown,
        });
        if !discriminants.is_empty() {
            // Known discriminants (RM 7.3(3)): outside the package they are
            // the type's; the full declaration repeats them.
            let (fields, names) = self.discriminant_part(discriminants);
            for (i, (n, f)) in names.into_iter().zip(&fields).enumerate() {
                self.index_field(t, i as u32, n, f.ty);
            }
            self.tables.types.partial_discrs.insert(t, fields);
        }
        if let Some(p) = package {
            self.tables.packages[p].private_types.push(t);
        }
        self.declare_checked(name, Entity::Type(t));
    }

    /// Whether `prev` (what the name of a type declaration already denotes
    /// in this scope) is a private type that this declaration completes.
    pub(super) fn completes_private(&self, prev: Option<&Entity>) -> Option<TypeId> {
        match prev {
            Some(Entity::Type(old))
                if self.tables.types.private_view(*old).is_some()
                    && !self.tables.types.completed(*old) =>
            {
                Some(*old)
            }
            _ => None,
        }
    }

    /// The full declaration of private type `old`: its full view becomes the
    /// type's, under the same id.
    pub(super) fn complete_private(
        &mut self,
        old: TypeId,
        name: &ast::Ident,
        discriminants: &[ast::Param],
        def: &TypeDef,
        span: Span,
        out: &mut Vec<Stmt>,
    ) {
        let view = self.tables.types.private_view(old).expect("a private type");
        if self.innermost_package() != Some((view.package as usize, true)) {
            self.err(diagnostics::full_view_in_visible_part(
                name.span, &name.name,
            ));
        }
        let t = self.elaborating(out, |c| c.type_def(name, discriminants, def, span));
        self.install_full_view(old, t, name, discriminants, span);
        // Access types declared before the completion that now designate
        // tasks get their master here (same region).
        let before: Vec<TypeId> = (old + 1..self.tables.types.list.len() as TypeId)
            .filter(|&a| {
                matches!(self.tables.types.full_kind(a), TypeKind::Access(d) if self.tables.types.base(*d) == old)
            })
            .collect();
        for a in before {
            self.collection_master(a, span, out);
        }
    }

    /// Declares task or protected type `t`, or makes it the full view of
    /// the private type its name declared in the visible part.
    pub(in crate::check) fn declare_type_or_full_view(
        &mut self,
        name: &ast::Ident,
        t: TypeId,
        discriminants: &[ast::Param],
        span: Span,
    ) {
        let prev = self
            .scopes
            .innermost()
            .and_then(|s| s.names.get(&*name.key))
            .and_then(|es| es.last().cloned());
        match self.completes_private(prev.as_ref()) {
            Some(old) => {
                let view = self.tables.types.private_view(old).expect("a private type");
                if self.innermost_package() != Some((view.package as usize, true)) {
                    self.err(diagnostics::full_view_in_visible_part(
                        name.span, &name.name,
                    ));
                }
                self.install_full_view(old, t, name, discriminants, span);
            }
            None => self.declare_checked(name, Entity::Type(t)),
        }
    }

    /// Makes type `t` (just declared by the full declaration `name`, with
    /// `discriminants`, at `span`) the full view of private type `old`.
    pub(in crate::check) fn install_full_view(
        &mut self,
        old: TypeId,
        t: TypeId,
        name: &ast::Ident,
        discriminants: &[ast::Param],
        span: Span,
    ) {
        let view = self.tables.types.private_view(old).expect("a private type");
        if !view.limited && t != ERROR && self.limited_part(t).is_some() {
            self.err(diagnostics::limited_completion_of_nonlimited(
                name.span, &name.name,
            ));
        }
        let known = self.tables.types.partial_discrs.contains_key(&old);
        if known && t != ERROR {
            self.conform_discriminants(old, t, name, discriminants, span);
        }
        // RM 7.3(13): a partial view without discriminants promises
        // objects that need no constraint, so the full type is definite.
        // Unknown discriminants (`(<>)`) promise nothing.
        let types = &self.tables.types;
        let indefinite = types.array(t).is_some_and(|a| a.2.is_none())
            || (!types.discriminants(t).is_empty()
                && !types.discriminant_defaults(t)
                && types.discriminant_constraint(t).is_none());
        if t != ERROR && indefinite && !known && !view.unknown {
            self.err(diagnostics::indefinite_full_view(name.span, &name.name));
        }
        if let Some(&at) = self.early_discriminant_reads.get(&old)
            && matches!(
                self.tables.types.full_kind(t),
                TypeKind::Task(_) | TypeKind::Protected(_)
            )
        {
            self.err(diagnostics::unsupported(
                at,
                "reading a discriminant of a private type completed by a task or protected type before its full declaration",
            ));
        }
        // The discriminants of a task or protected full view, by its type.
        if let Some(ds) = self.tables.types.conc_discrs.remove(&t) {
            self.tables.types.conc_discrs.insert(old, ds);
        }
        let prev = self.tables.types.get(old).clone();
        let mut info = self.tables.types.get(t).clone();
        info.base = old;
        info.name = prev.name;
        info.full_name = prev.full_name;
        info.private = prev.private;
        if let Some((l, h)) = &mut info.range {
            l.ty = old;
            h.ty = old;
        }
        self.tables.types.list[old as usize] = info;
        self.retarget_enum_lits(t, old);
        self.retarget_package_lits(view.package as usize, t, old);
        let fields = self.tables.types.fields(old).map_or(0, |f| f.len());
        if known {
            // The partial view's discriminants are the declarations its
            // full declaration's repeat (go to definition, rename).
            let n = self.tables.types.partial_discrs[&old].len();
            for (i, id) in discriminants
                .iter()
                .flat_map(|p| &p.names)
                .enumerate()
                .take(n)
            {
                self.index_field_ref(id.span, old, i as u32);
            }
            self.index
                .retarget_fields_from(t, old, n as u32, fields as u32);
        } else {
            self.index.retarget_fields(t, old, fields as u32);
        }
        // The full declaration's name names the type its partial view
        // declared (go to definition, references, rename).
        self.index_ref(name.span, &name.key, &Entity::Type(old));
    }

    /// RM 7.3(13), 6.3.1(17): the full declaration of a private type
    /// whose partial view has known discriminants repeats them, fully
    /// conformant: the same names, subtypes and defaults (the same
    /// lexical elements, spaces aside), in order. The report is GNAT's:
    /// at the first discriminant that differs.
    fn conform_discriminants(
        &mut self,
        old: TypeId,
        t: TypeId,
        name: &ast::Ident,
        discriminants: &[ast::Param],
        span: Span,
    ) {
        let partial = self.tables.types.partial_discrs[&old].clone();
        let at = self
            .index
            .def_of_field(old, 0)
            .map_or(name.span, |d| d.span);
        if discriminants.is_empty() {
            self.err(diagnostics::full_view_missing_discriminants(
                Span {
                    end: span.start + 4,
                    ..span
                },
                &name.name,
                at,
            ));
            return;
        }
        let full = self.tables.types.discriminants(t).to_vec();
        let written: Vec<(&ast::Ident, Option<&ast::Expr>)> = discriminants
            .iter()
            .flat_map(|p| p.names.iter().map(move |n| (n, p.default.as_ref())))
            .collect();
        let text = |c: &Self, s: Span| -> String {
            c.snippet(s)
                .chars()
                .filter(|ch| !ch.is_whitespace())
                .flat_map(char::to_lowercase)
                .collect()
        };
        for (i, (id, default)) in written.iter().enumerate() {
            let Some(p) = partial.get(i) else {
                self.err(diagnostics::discriminants_not_conformant(
                    id.span,
                    &name.name,
                    "too many discriminants",
                    at,
                ));
                return;
            };
            let what = if full.get(i).is_none_or(|f| f.ty != p.ty) {
                format!("the subtype of `{}` does not match", id.name)
            } else if *p.key != *id.key {
                format!("name `{}` does not match `{}`", id.name, p.name)
            } else if default.map(|d| text(self, d.span))
                != p.default.as_ref().map(|d| text(self, d.span))
            {
                format!("the default expression for `{}` does not match", id.name)
            } else {
                continue;
            };
            let partial_at = self
                .index
                .def_of_field(old, i as u32)
                .map_or(at, |d| d.span);
            self.err(diagnostics::discriminants_not_conformant(
                id.span, &name.name, &what, partial_at,
            ));
            return;
        }
        if written.len() < partial.len() {
            self.err(diagnostics::discriminants_not_conformant(
                name.span,
                &name.name,
                "too few discriminants",
                at,
            ));
        }
    }

    /// The literals of a full view, in its package's table of private
    /// names: those of the type first declared.
    fn retarget_package_lits(&mut self, pk: usize, from: TypeId, to: TypeId) {
        let table = &mut self.tables.packages[pk].private;
        let keys: Vec<String> = table
            .iter()
            .filter(|(_, es)| {
                es.iter()
                    .any(|e| matches!(e, Entity::EnumLit(t, _) if *t == from))
            })
            .map(|(k, _)| k.clone())
            .collect();
        for k in keys {
            if let Some(es) = table.get_mut(&k) {
                for e in es.iter_mut() {
                    if let Entity::EnumLit(t, _) = e
                        && *t == from
                    {
                        *t = to;
                    }
                }
            }
        }
    }

    /// `C : constant T;` in a package's visible part: a deferred constant,
    /// which the private part completes. False (nothing declared) anywhere
    /// else.
    pub(super) fn deferred_constant(&mut self, names: &[ast::Ident], t: TypeId) -> bool {
        let Some((pk, false)) = self.innermost_package() else {
            return false;
        };
        for n in names {
            let var = self.new_slot();
            self.declare_checked(
                n,
                Entity::Var {
                    var,
                    ty: t,
                    constant: true,
                    value: None,
                },
            );
            self.tables.packages[pk].deferred.push(Deferred {
                key: n.key.to_string(),
                name: n.name.to_string(),
                var,
                ty: t,
                span: n.span,
                completed: false,
            });
        }
        true
    }

    /// `C : constant T := V;` in a package's private part, `C` a deferred
    /// constant of its visible part: gives it its value. False when no name
    /// of the declaration is one (an ordinary constant).
    pub(super) fn complete_deferred(
        &mut self,
        names: &[ast::Ident],
        t: TypeId,
        init: &ast::Expr,
        span: Span,
        out: &mut Vec<Stmt>,
    ) -> bool {
        let Some((pk, true)) = self.innermost_package() else {
            return false;
        };
        let found: Vec<Option<usize>> = names
            .iter()
            .map(|n| {
                self.tables.packages[pk]
                    .deferred
                    .iter()
                    .position(|d| *d.key == *n.key && !d.completed)
                    // Declared in this very scope: the spec's, not a body's.
                    .filter(|_| {
                        self.scopes
                            .innermost()
                            .is_some_and(|s| s.names.contains_key(&*n.key))
                    })
            })
            .collect();
        if found.iter().all(Option::is_none) {
            return false;
        }
        let ex = self.expr(init, Some(t));
        let init_ex = self.coerce(ex, t);
        self.limited_init(&init_ex, t);
        let value = self
            .static_value(&init_ex)
            .filter(|_| self.tables.types.is_scalar(t))
            .map(|v| self.machine_value(v, t));
        for (n, f) in names.iter().zip(found) {
            let Some(i) = f else {
                let var = self.new_slot();
                out.push(Stmt {
                    kind: StmtKind::Init(var, init_ex.clone()),
                    span,
                });
                self.declare_checked(
                    n,
                    Entity::Var {
                        var,
                        ty: t,
                        constant: true,
                        value: value.clone(),
                    },
                );
                continue;
            };
            let d = self.tables.packages[pk].deferred[i].clone();
            self.tables.packages[pk].deferred[i].completed = true;
            if self.tables.types.base(d.ty) != self.tables.types.base(t) && t != ERROR {
                let declared = self.tname(d.ty);
                self.err(diagnostics::deferred_type_mismatch(
                    n.span, &d.name, &declared, d.span,
                ));
            }
            out.push(Stmt {
                kind: StmtKind::Init(d.var, init_ex.clone()),
                span,
            });
            let e = Entity::Var {
                var: d.var,
                ty: d.ty,
                constant: true,
                value: value.clone(),
            };
            self.index_ref(n.span, &n.key, &e);
            self.declare(&n.name, e);
        }
        true
    }

    /// The end of a package spec: what its visible part promised and its
    /// private part did not complete, and the full views it declared are
    /// hidden from here on (until its body).
    pub(super) fn end_of_package_spec(&mut self, pk: usize) {
        let pname = self.tables.packages[pk].name.clone();
        let mut missing = Vec::new();
        for d in &self.tables.packages[pk].deferred {
            if !d.completed {
                missing.push(diagnostics::deferred_constant_not_completed(
                    d.span, &d.name, &pname,
                ));
            }
        }
        for t in self.private_types_of(pk) {
            if !self.tables.types.completed(t) {
                let name = self.tables.types.name(t).to_string();
                let at = self
                    .index
                    .def_of_type(t)
                    .map_or(crate::diag::span(0, 0, 0), |d| d.span);
                missing.push(diagnostics::private_type_not_completed(at, &name, &pname));
            }
        }
        for d in missing {
            self.err(d);
        }
        self.flag_pending_formals();
        self.full_views(pk, false);
    }

    /// The private types of package `pk` (and the types derived from them).
    fn private_types_of(&self, pk: usize) -> Vec<TypeId> {
        self.tables.packages[pk].private_types.clone()
    }

    /// Shows (inside package `pk`'s body) or hides (after its spec and
    /// body) the full views of its private types.
    pub(super) fn full_views(&mut self, pk: usize, visible: bool) {
        for t in self.private_types_of(pk) {
            if visible {
                self.tables.types.hidden.remove(&t);
            } else {
                self.tables.types.hidden.insert(t, ());
            }
        }
    }

    /// A type derived from a private type whose full view is hidden here:
    /// hidden too.
    pub(super) fn derived_from_private(&mut self, parent: TypeId, t: TypeId) {
        if self.tables.types.is_hidden(parent) {
            self.tables.types.hidden.insert(t, ());
            // Its discriminants are the parent's (RM 3.4(11)), partial and
            // full.
            let pb = self.tables.types.base(parent);
            if let Some(ds) = self.tables.types.partial_discrs.get(&pb).cloned() {
                self.tables.types.partial_discrs.insert(t, ds);
            }
            if let Some(ds) = self.tables.types.conc_discrs.get(&pb).cloned() {
                self.tables.types.conc_discrs.insert(t, ds);
            }
            if let Some(v) = self.tables.types.private_view(parent) {
                self.tables.packages[v.package as usize]
                    .private_types
                    .push(t);
            }
        }
    }

    /// The limited type that makes `t` limited here (`t` itself, or the
    /// type of one of its components), if it is: a task or protected type,
    /// a limited private type where its full view is hidden, a record or
    /// array with a limited component (RM 7.5).
    pub(in crate::check) fn limited_part(&self, t: TypeId) -> Option<TypeId> {
        let types = &self.tables.types;
        match types.kind(t) {
            TypeKind::Task(_) | TypeKind::Protected(_) => Some(t),
            TypeKind::Private => types.private_view(t).filter(|v| v.limited).map(|_| t),
            TypeKind::Array { elem, .. } => self.limited_part(*elem),
            TypeKind::Record(fs) => fs.iter().find_map(|f| self.limited_part(f.ty)),
            _ => None,
        }
    }

    /// Why `t` is limited, when one of its components makes it so.
    fn limited_hint(&self, t: TypeId) -> Option<String> {
        let part = self.limited_part(t)?;
        if self.tables.types.base(part) == self.tables.types.base(t) {
            return None;
        }
        Some(format!(
            "`{}` has a component of the limited type `{}`",
            self.tname(t),
            self.tname(part)
        ))
    }

    /// An assignment to an object of type `t`.
    pub(in crate::check) fn limited_assignment(&mut self, t: TypeId, span: Span) {
        if t != ERROR && self.limited_part(t).is_some() {
            let d = diagnostics::limited_assignment(span, &self.tname(t));
            let d = diagnostics::limited_because(d, self.limited_hint(t));
            self.err(d);
        }
    }

    /// The initial value of an object of type `t`: for a limited type, an
    /// aggregate or a function call (built in place), never a copy.
    pub(in crate::check) fn limited_init(&mut self, init: &Ex, t: TypeId) {
        if t != ERROR && self.limited_part(t).is_some() && !built_in_place(init) {
            let d = diagnostics::limited_copy(init.span, &self.tname(t));
            let d = diagnostics::limited_because(d, self.limited_hint(t));
            self.err(d);
        }
    }

    /// The value of `return` in a function whose result type `t` is limited.
    pub(in crate::check) fn limited_return(&mut self, value: &Ex, t: TypeId) {
        if t != ERROR && self.limited_part(t).is_some() && !built_in_place(value) {
            let d = diagnostics::limited_return(value.span, &self.tname(t));
            let d = diagnostics::limited_because(d, self.limited_hint(t));
            self.err(d);
        }
    }

    /// Predefined `=` or `/=` on values of type `t`.
    pub(in crate::check) fn limited_equality(&mut self, t: TypeId, op: &str, span: Span) -> bool {
        if t != ERROR && self.limited_part(t).is_some() {
            let d = diagnostics::limited_equality(span, op, &self.tname(t));
            let d = diagnostics::limited_because(d, self.limited_hint(t));
            self.err(d);
            return true;
        }
        false
    }

    /// The package that declares the private type `t`, for messages.
    pub(in crate::check) fn private_package(&self, t: TypeId) -> String {
        self.tables
            .types
            .private_view(t)
            .and_then(|v| self.tables.packages.get(v.package as usize))
            .map_or_else(String::new, |p| p.name.clone())
    }
}

/// Whether a value is built where it is used (RM 7.5(2.1)): an aggregate
/// or a function call, also as the choices of a conditional expression.
fn built_in_place(e: &Ex) -> bool {
    match &e.kind {
        ExKind::Call(..) | ExKind::ArrayAgg(_) | ExKind::RecordAgg(_) | ExKind::Error => true,
        ExKind::RangeCheck(x, _) | ExKind::ArrayConvert(x, _) => built_in_place(x),
        ExKind::If(arms, els) => arms.iter().all(|(_, v)| built_in_place(v)) && built_in_place(els),
        ExKind::Case(c) => {
            c.1.iter().all(|(_, v)| built_in_place(v)) && c.2.as_ref().is_none_or(built_in_place)
        }
        _ => e.ty == ERROR,
    }
}
