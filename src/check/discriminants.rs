//! What the checker knows of an object with discriminants at run time:
//! whether it is constrained (RM 3.7.2 `'Constrained`), and the checks an
//! assignment to it needs (RM 5.2(10)). A record whose discriminants have
//! defaults, declared without a constraint, is mutable: an assignment of
//! the whole record may change them. Any other object of a type with
//! discriminants is constrained, by its subtype or by its initial value;
//! an `out` or `in out` formal of a mutable type is as constrained as its
//! actual, which the caller says in a hidden `in` argument after the
//! others (a slot of the callee after its parameters).
//!
//! Whether an object's discriminants can change is a property of its
//! type's full view, outside the package too: a private type's partial
//! view without discriminants or with unknown ones (`(<>)`) may hide a
//! record whose discriminants have defaults (RM 3.7(28)). So these
//! questions look at the full view; a subprogram declared before the
//! full view of one of its formals' types gets its flags at the end of
//! the package spec, when the full view is known.

use super::*;

impl Checker {
    /// Whether a formal of this mode and type gets a hidden flag saying
    /// whether its actual is constrained.
    pub(super) fn needs_constrained_flag(&self, mode: ast::Mode, t: TypeId) -> bool {
        mode != ast::Mode::In
            && self.tables.types.full_discriminant_defaults(t)
            && self.tables.types.discriminant_constraint(t).is_none()
    }

    /// Whether an object of subtype `t` needs a discriminant constraint
    /// or an initial value: its discriminants have no defaults (RM 3.7(26)),
    /// or they are unknown (`type T (<>) is private;`, RM 3.3(23)).
    pub(super) fn needs_discriminants(&self, t: TypeId) -> bool {
        let types = &self.tables.types;
        (!types.discriminants(t).is_empty()
            && !types.discriminant_defaults(t)
            && types.discriminant_constraint(t).is_none())
            || types.unknown_discriminants(t)
    }

    /// Gives `f`'s mutable formals their hidden flags, if it has any; when
    /// one of its formals is of a private type not completed yet, at the
    /// end of the package spec ([`Checker::flag_pending_formals`]).
    pub(super) fn flag_formals(&mut self, f: FuncId) {
        let types = &self.tables.types;
        if self.tables.funcs[f as usize].params.iter().any(|p| {
            p.mode != ast::Mode::In && types.private_view(p.ty).is_some() && !types.completed(p.ty)
        }) {
            self.pending_flags.push(f);
            return;
        }
        if self.tables.funcs[f as usize]
            .params
            .iter()
            .any(|p| self.needs_constrained_flag(p.mode, p.ty))
        {
            self.flagged_funcs.insert(f);
        }
    }

    /// The subprograms waiting for the full views of their formals'
    /// types that have them now (at the end of a package spec): their
    /// flags. One called before (an expression function of the visible
    /// part) has none: its formals count as constrained.
    pub(super) fn flag_pending_formals(&mut self) {
        let pending = std::mem::take(&mut self.pending_flags);
        for f in pending {
            let types = &self.tables.types;
            if self.tables.funcs[f as usize]
                .params
                .iter()
                .any(|p| types.private_view(p.ty).is_some() && !types.completed(p.ty))
            {
                self.pending_flags.push(f);
            } else {
                self.flag_formals(f);
            }
        }
    }

    /// The formals of `f` that have a hidden flag, in order.
    pub(super) fn flagged_formals(&self, f: FuncId) -> Vec<usize> {
        if !self.flagged_funcs.contains(&f) {
            return Vec::new();
        }
        let params = &self.tables.funcs[f as usize].params;
        (0..params.len())
            .filter(|&j| self.needs_constrained_flag(params[j].mode, params[j].ty))
            .collect()
    }

    /// The hidden arguments of a call of `f`: for each flagged formal,
    /// whether its actual is constrained.
    pub(super) fn constrained_flag_args(&mut self, f: FuncId, args: &[Arg]) -> Vec<Arg> {
        // Called before its flags were decided: it has none.
        let callee = self.tables.callee(f);
        self.pending_flags.retain(|&g| g != callee);
        self.flagged_formals(callee)
            .into_iter()
            .filter_map(|j| args.get(j))
            .map(|a| Arg {
                mode: ast::Mode::In,
                value: self
                    .constrained_ex(&a.value)
                    .unwrap_or_else(|| self.mk(ExKind::Int(1), BOOLEAN, a.value.span)),
                back_check: None,
            })
            .collect()
    }

    /// `X'Constrained` of an object of a type with discriminants: a
    /// Boolean, static unless `X` is a flagged formal. None for a value
    /// whose discriminants cannot change (a result, a constant): True.
    pub(super) fn constrained_ex(&self, e: &Ex) -> Option<Ex> {
        let types = &self.tables.types;
        let yes = |v: bool| Some(self.mk(ExKind::Int(v as i64), BOOLEAN, e.span));
        if types.full_discriminants(e.ty).is_empty()
            || types.discriminant_constraint(e.ty).is_some()
            || !types.full_discriminant_defaults(e.ty)
            || matches!(
                types.full_kind(e.ty),
                TypeKind::Task(_) | TypeKind::Protected(_)
            )
        {
            // A task or a protected object is limited: constrained.
            return yes(true);
        }
        match &e.kind {
            ExKind::Var(v) => {
                match self.constrained_flags.get(v) {
                    Some(Some(flag)) => return Some(self.mk(ExKind::Var(*flag), BOOLEAN, e.span)),
                    Some(None) => return yes(true),
                    None => {}
                }
                match self.scopes.var(*v) {
                    Some((_, constant)) => yes(constant),
                    None => yes(true),
                }
            }
            // A component or an element of an unconstrained subtype with
            // defaults is mutable (RM 3.7(28)), unless it is part of a
            // constant; an object made by an allocator is constrained by
            // its initial value (RM 4.8(6)).
            ExKind::Field(p, _) | ExKind::Index(p, _) => yes(self.part_of_constant(p)),
            _ => yes(true),
        }
    }

    /// Whether the object `e` names a part of is a constant (or a value).
    fn part_of_constant(&self, e: &Ex) -> bool {
        match &e.kind {
            ExKind::Var(v) => match self.scopes.var(*v) {
                Some((_, constant)) => constant,
                None => true,
            },
            ExKind::Field(p, _) | ExKind::Index(p, _) | ExKind::Variant(p, _) => {
                self.part_of_constant(p)
            }
            // A heap object is a variable (access-to-constant types are
            // not in the subset).
            ExKind::Deref(_) => false,
            _ => true,
        }
    }

    /// The value of an assignment to `target`: when the target is an
    /// object constrained by its initial value or by its actual (not by its
    /// subtype, which `coerce` checks already), the value's discriminants
    /// must be the object's (RM 5.2(10): "discriminant check failed").
    pub(super) fn keep_discriminants(&mut self, target: &Ex, value: Ex) -> Ex {
        let types = &self.tables.types;
        if types.full_discriminants(target.ty).is_empty()
            || types.discriminant_constraint(target.ty).is_some()
            || value.ty == ERROR
            || target.ty == ERROR
        {
            return value;
        }
        let when = if types.full_discriminant_defaults(target.ty) {
            match &target.kind {
                ExKind::Var(v) => match self.constrained_flags.get(v) {
                    Some(Some(flag)) => self.mk(ExKind::Var(*flag), BOOLEAN, target.span),
                    Some(None) => self.mk(ExKind::Int(1), BOOLEAN, target.span),
                    None => return value,
                },
                ExKind::Deref(_) => self.mk(ExKind::Int(1), BOOLEAN, target.span),
                _ => return value,
            }
        } else {
            self.mk(ExKind::Int(1), BOOLEAN, target.span)
        };
        let (ty, span) = (value.ty, value.span);
        self.mk(
            ExKind::KeepDiscriminants(Box::new([value, target.clone(), when])),
            ty,
            span,
        )
    }
}
