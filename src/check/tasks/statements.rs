//! Tasking in statements and expressions: entry and protected calls,
//! `accept`, `select`, `delay`, task attributes.

use super::*;

impl Checker {
    /// A call of a protected operation from inside the protected body (by
    /// its name alone) goes to the same object.
    pub(in crate::check) fn internal_prot_call(
        &mut self,
        f: FuncId,
        mut args: Vec<Arg>,
        span: Span,
    ) -> (FuncId, Vec<Arg>) {
        let Some(&(real, k)) = self.tables.prot_real.get(&f) else {
            return (f, args);
        };
        let ctx = self
            .tasking
            .prot_ctx
            .iter()
            .rev()
            .find(|(p, _)| *p == k)
            .copied();
        match ctx {
            Some((_, Some(obj))) => {
                // A protected function only reads its object (RM 9.5.1):
                // it may not call a procedure of it.
                if Some(obj) == self.tasking.prot_function_obj
                    && self.tables.funcs[real as usize].ret.is_none()
                {
                    let name = self.tables.funcs[real as usize].name.clone();
                    self.err(diagnostics::protected_function_calls_procedure(span, &name));
                }
                let access = self.prot_access(k);
                args.push(Arg {
                    mode: ast::Mode::In,
                    value: Ex {
                        kind: ExKind::Var(obj),
                        ty: access,
                        span,
                    },
                    back_check: None,
                });
                (real, args)
            }
            _ => (f, args),
        }
    }

    /// The protected type of a prefix that names a protected object, looked
    /// at without reporting anything.
    pub(in crate::check) fn peek_protected(&mut self, q: &ast::Expr) -> Option<u32> {
        let t = match &q.kind {
            ast::ExprKind::Name(id) => match self.lookup(&id.key).first() {
                Some(Entity::Var { ty, .. }) => *ty,
                _ => return None,
            },
            ast::ExprKind::Apply(p, _) => match &p.kind {
                ast::ExprKind::Name(id) => match self.lookup(&id.key).first() {
                    Some(Entity::Var { ty, .. }) => self.tables.types.array(*ty).map(|a| a.1)?,
                    _ => return None,
                },
                _ => return None,
            },
            _ => return None,
        };
        let t = self.tables.types.designated(t).unwrap_or(t);
        match self.tables.types.kind(t) {
            TypeKind::Protected(k) => Some(*k),
            _ => None,
        }
    }

    /// A task or protected object named through an access value: the
    /// object itself (`P.E` for `P.all.E`).
    fn through_access(&self, x: Ex) -> Ex {
        match self.tables.types.designated(x.ty) {
            Some(d)
                if matches!(
                    self.tables.types.kind(d),
                    TypeKind::Task(_) | TypeKind::Protected(_)
                ) =>
            {
                let sp = x.span;
                Ex {
                    kind: ExKind::Deref(Box::new(x)),
                    ty: d,
                    span: sp,
                }
            }
            _ => x,
        }
    }

    fn obj_arg(&self, k: u32, obj: Ex) -> Arg {
        let access = self.prot_access(k);
        Arg {
            mode: ast::Mode::In,
            value: Ex { ty: access, ..obj },
            back_check: None,
        }
    }

    /// `P.F` or `P.F (args)` in an expression: a protected function.
    pub(in crate::check) fn prot_function(
        &mut self,
        k: u32,
        obj: Ex,
        id: &ast::Ident,
        args: &[ast::Arg],
        sp: Span,
    ) -> Ex {
        let obj = self.through_access(obj);
        match self.prot_subprogram(k, obj, id, args, false, sp) {
            Some((real, a)) => {
                let r = self.tables.funcs[real as usize].ret.unwrap_or(ERROR);
                self.mk(ExKind::Call(real, a.into()), r, sp)
            }
            None => self.err_ex(sp),
        }
    }

    /// A call of protected subprogram `id` of object `obj` (of protected
    /// type `k`) from outside: the subprogram and the arguments, the object
    /// last.
    fn prot_subprogram(
        &mut self,
        k: u32,
        obj: Ex,
        id: &ast::Ident,
        args: &[ast::Arg],
        procedure: bool,
        sp: Span,
    ) -> Option<(FuncId, Vec<Arg>)> {
        let fs: Vec<FuncId> = self.tables.prot_members[k as usize]
            .iter()
            .filter(|m| *m.name == *id.key)
            .map(|m| m.profile)
            .collect();
        if fs.is_empty() {
            self.err(diagnostics::not_a_protected_operation(
                id.span,
                &id.name,
                procedure,
                &self.tables.prots[k as usize].name,
            ));
            return None;
        }
        if fs.iter().all(|f| self.private_outside(k, *f)) {
            let pname = self.tables.prots[k as usize].name.clone();
            self.err(diagnostics::private_protected_operation(
                id.span, &id.name, &pname,
            ));
            return None;
        }
        // Not an internal call, even inside a protected body.
        let outer = std::mem::take(&mut self.tasking.prot_ctx);
        let r = self.call(&fs, args, None, procedure, sp, &id.name);
        self.tasking.prot_ctx = outer;
        let (f, mut a) = r?;
        let real = self.tables.prot_real.get(&f)?.0;
        self.index_ref(id.span, &id.key, &Entity::Func(f));
        a.push(self.obj_arg(k, obj));
        let flags = self.constrained_flag_args(real, &a);
        a.extend(flags);
        Some((real, a))
    }

    /// Whether `profile`, an operation of protected type `k`, is private
    /// and the statement being checked is outside `k`'s body.
    fn private_outside(&self, k: u32, profile: FuncId) -> bool {
        self.tables.prot_private.contains(&profile)
            && !self.tasking.prot_ctx.iter().any(|(p, _)| *p == k)
    }

    /// A task value: a task object, or an access to one.
    pub(in crate::check) fn task_value(&mut self, e: &ast::Expr) -> Option<Ex> {
        let x = self.expr(e, None);
        let x = self.through_access(x);
        match self.tables.types.kind(x.ty) {
            TypeKind::Task(_) => Some(x),
            TypeKind::Error => None,
            _ => {
                self.err(diagnostics::task_expected(
                    e.span,
                    self.tables.types.name(x.ty),
                ));
                None
            }
        }
    }

    /// `T.E (args)` or `P.Op (args)` as a statement: an entry call or a
    /// protected procedure. `None`: not a call on a task or protected object.
    pub(in crate::check) fn concurrent_call(
        &mut self,
        prefix: &ast::Expr,
        args: &[ast::Arg],
        span: Span,
    ) -> Option<Option<StmtKind>> {
        // `T.E (I) (args)`: a member of an entry family.
        let (prefix, index) = match &prefix.kind {
            ast::ExprKind::Apply(p, ia) if matches!(p.kind, ast::ExprKind::Select(..)) => {
                (&**p, Some(ia.as_slice()))
            }
            _ => (prefix, None),
        };
        let ast::ExprKind::Select(q, id) = &prefix.kind else {
            return None;
        };
        let own = matches!(&q.kind, ast::ExprKind::Name(n) if self.own_task_entry(n, id));
        if !own && self.expanded_prefix(q) {
            return None;
        }
        let is_conc = |this: &mut Self, t: TypeId| {
            let t = this.tables.types.designated(t).unwrap_or(t);
            matches!(
                this.tables.types.kind(t),
                TypeKind::Task(_) | TypeKind::Protected(_)
            )
        };
        let peek = match &q.kind {
            ast::ExprKind::Name(n) => match self.lookup(&n.key).first() {
                Some(Entity::Var { ty, .. }) => Some(*ty),
                _ => None,
            },
            _ => None,
        };
        if let Some(t) = peek
            && !is_conc(self, t)
        {
            return None;
        }
        let obj = self.expr(q, None);
        if !is_conc(self, obj.ty) {
            return None;
        }
        Some(self.entry_or_procedure(obj, id, index, args, span))
    }

    fn entry_or_procedure(
        &mut self,
        obj: Ex,
        id: &ast::Ident,
        index: Option<&[ast::Arg]>,
        args: &[ast::Arg],
        span: Span,
    ) -> Option<StmtKind> {
        let obj = self.through_access(obj);
        match self.tables.types.kind(obj.ty).clone() {
            TypeKind::Task(k) => {
                let def = &self.tables.tasks[k as usize];
                let Some(i) = def
                    .entries
                    .iter()
                    .position(|e| e.name.eq_ignore_ascii_case(&id.name))
                else {
                    let names: Vec<String> = def.entries.iter().map(|e| e.name.clone()).collect();
                    let mut d = diagnostics::not_an_entry_of_task(id.span, &id.name, &def.name);
                    if !names.is_empty() {
                        d = d.with_hint(format!("its entries: {}", names.join(", ")));
                    }
                    self.err(d);
                    return None;
                };
                let profile = def.entries[i].profile;
                let family = def.entries[i].family;
                let name = format!("{}.{}", def.name, id.name);
                let takes = !self.tables.funcs[profile as usize].params.is_empty();
                let (index, args) = self.member_call(takes, family, &name, index, args, span)?;
                let (_, a) = self.call(&[profile], args, None, true, span, &name)?;
                self.index_ref(id.span, &id.key, &Entity::Func(profile));
                Some(StmtKind::EntryCall(Box::new(EntryCall {
                    target: CallTarget::Task {
                        task: obj,
                        ttype: k,
                        entry: i as u32,
                    },
                    args: a,
                    index,
                })))
            }
            TypeKind::Protected(k) => {
                if let Some(i) = self.tables.prots[k as usize]
                    .entries
                    .iter()
                    .position(|e| e.name.eq_ignore_ascii_case(&id.name))
                {
                    let profile = self.tables.prots[k as usize].entries[i].profile;
                    let family = self.tables.prots[k as usize].entries[i].family;
                    let name = format!("{}.{}", self.tables.prots[k as usize].name, id.name);
                    if self.private_outside(k, profile) {
                        let pname = self.tables.prots[k as usize].name.clone();
                        self.err(diagnostics::private_protected_operation(
                            id.span, &id.name, &pname,
                        ));
                        return None;
                    }
                    let takes = !self.tables.funcs[profile as usize].params.is_empty();
                    let (index, args) =
                        self.member_call(takes, family, &name, index, args, span)?;
                    let (_, mut a) = self.call(&[profile], args, None, true, span, &name)?;
                    self.index_ref(id.span, &id.key, &Entity::Func(profile));
                    a.extend(index.clone().map(|value| Arg {
                        mode: ast::Mode::In,
                        value,
                        back_check: None,
                    }));
                    a.push(self.obj_arg(k, obj));
                    return Some(StmtKind::EntryCall(Box::new(EntryCall {
                        target: CallTarget::Prot {
                            prot: k,
                            entry: i as u32,
                        },
                        args: a,
                        index,
                    })));
                }
                if let Some(ia) = index {
                    let text = format!("{} ({})", id.name, self.args_text(ia));
                    self.err(diagnostics::not_a_procedure_or_entry(span, &text));
                    return None;
                }
                let (real, a) = self.prot_subprogram(k, obj, id, args, true, span)?;
                Some(StmtKind::ProtCall(real, a.into()))
            }
            _ => None,
        }
    }

    /// The index and the parameters of a call of entry `name` (`family`:
    /// its range, if a family): `E (I) (args)`; `E (I)` for a family
    /// without parameters (its one list is the index, as GNAT reads it).
    fn member_call<'a>(
        &mut self,
        takes_params: bool,
        family: Option<Family>,
        name: &str,
        index: Option<&'a [ast::Arg]>,
        args: &'a [ast::Arg],
        span: Span,
    ) -> Option<(Option<Ex>, &'a [ast::Arg])> {
        match (family, index) {
            (None, None) => Some((None, args)),
            (None, Some(_)) => {
                self.err(diagnostics::not_a_family(
                    span,
                    name,
                    &format!("`{name} (...)` with its parameters only"),
                ));
                None
            }
            (Some(f), Some(ia)) => Some((Some(self.family_index(f, name, ia, span)?), args)),
            // One list for a family without parameters: its index.
            (Some(f), None) if !args.is_empty() && !takes_params => {
                Some((Some(self.family_index(f, name, args, span)?), &[]))
            }
            (Some(f), None) => {
                let example = format!("`{name} ({}) (...)`", self.family_first_text(f));
                self.err(diagnostics::family_needs_index(
                    span, name, "a call", &example,
                ));
                None
            }
        }
    }

    /// The index of a member of family `f` of entry `name`: one value of
    /// its subtype, checked against its range.
    fn family_index(&mut self, f: Family, name: &str, args: &[ast::Arg], span: Span) -> Option<Ex> {
        let [
            ast::Arg {
                name: None, value, ..
            },
        ] = args
        else {
            let example = format!("`{name} ({}) (...)`", self.family_first_text(f));
            self.err(diagnostics::family_needs_index(
                args.first().map_or(span, |a| a.span),
                name,
                "the first parenthesis",
                &example,
            ));
            for a in args {
                self.expr(&a.value, None);
            }
            return None;
        };
        let e = self.expr(value, Some(f.ty));
        Some(self.coerce(e, f.ty))
    }

    /// The first member of a family as written (for hints).
    fn family_first_text(&self, f: Family) -> String {
        match self.tables.types.enum_lits(f.ty) {
            Some(l) => l
                .get(f.lo as usize)
                .map(|x| self.spelled(&x.to_lowercase()))
                .unwrap_or_default(),
            None => f.lo.to_string(),
        }
    }

    fn args_text(&self, args: &[ast::Arg]) -> String {
        args.iter()
            .map(|a| crate::syntax::parser::expr_text(&a.value))
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// `accept E (...) [do ... end E];` in the body of the task declaring E.
    pub(in crate::check) fn accept(
        &mut self,
        entry: &ast::Ident,
        index: Option<&ast::Expr>,
        params: &[ast::Param],
        body: Option<&ast::Block>,
        sp: Span,
    ) -> Option<Accept> {
        let here = self
            .ctx
            .last()
            .and_then(|c| c.func)
            .map(|f| format!("procedure {}", self.tables.funcs[f as usize].name))
            .unwrap_or_else(|| "the main program".into());
        let Some(&k) = self.tasking.task_ctx.last() else {
            self.err(diagnostics::misplaced_accept(sp, &here));
            return None;
        };
        if self.ctx.last().and_then(|c| c.func) != self.tables.tasks[k as usize].body {
            self.err(diagnostics::misplaced_accept(sp, &here));
            return None;
        }
        let def = self.tables.tasks[k as usize].clone();
        let Some(i) = def
            .entries
            .iter()
            .position(|e| e.name.eq_ignore_ascii_case(&entry.name))
        else {
            let names: Vec<&str> = def.entries.iter().map(|e| e.name.as_str()).collect();
            self.err(diagnostics::no_such_entry(
                entry.span,
                &entry.name,
                &def.name,
                &names,
            ));
            return None;
        };
        if let Some(outer) = self
            .tasking
            .accepting
            .iter()
            .find(|a| a.task == k && a.entry == i as u32)
        {
            self.err(diagnostics::nested_accept(sp, &entry.name, outer.at));
            return None;
        }
        let index = match (def.entries[i].family, index) {
            (None, None) => None,
            // Checked against the family's range when the accept (an
            // open alternative of a select) runs, RM 9.7.1(15).
            (Some(f), Some(x)) => {
                let e = self.expr(x, Some(f.ty));
                Some(self.coerce_base(e, f.ty))
            }
            (Some(f), None) => {
                let example = format!(
                    "`accept {} ({}) ...`",
                    entry.name,
                    self.family_first_text(f)
                );
                self.err(diagnostics::family_needs_index(
                    entry.span,
                    &entry.name,
                    "an accept statement",
                    &example,
                ));
                return None;
            }
            (None, Some(x)) => {
                self.err(diagnostics::not_a_family(
                    x.span,
                    &entry.name,
                    &format!("`accept {} ...` without an index", entry.name),
                ));
                return None;
            }
        };
        self.index_ref(
            entry.span,
            &entry.name.to_lowercase(),
            &Entity::Func(def.entries[i].profile),
        );
        let profile = self.tables.funcs[def.entries[i].profile as usize].clone();
        let ps = self.params(params);
        if !self.same_profile(&profile, &ps, None) {
            let want: Vec<String> = profile
                .params
                .iter()
                .map(|p| {
                    format!(
                        "{} : {}{}",
                        p.name,
                        mode_text(p.mode),
                        self.tables.types.name(p.ty)
                    )
                })
                .collect();
            let decl = self.declared_at(def.entries[i].profile);
            self.err(diagnostics::accept_params_differ(
                sp,
                &entry.name,
                &decl,
                ps.len(),
                &want,
            ));
            return None;
        }
        self.scopes.push();
        let mut slots = Vec::new();
        let written = params.iter().flat_map(|p| p.names.iter());
        for (p, id) in profile.params.iter().zip(written) {
            let var = self.new_slot();
            let e = Entity::Var {
                var,
                ty: p.ty,
                constant: p.mode == ast::Mode::In,
                value: None,
            };
            self.index_def(&id.name, id.span, &e, None);
            self.declare(&id.name, e);
            if self.needs_constrained_flag(p.mode, p.ty) {
                self.constrained_flags.insert(var, None);
            }
            slots.push((var, p.mode));
        }
        self.tasking.accepting.push(Accepting {
            task: k,
            entry: i as u32,
            at: sp,
            slots: slots.clone(),
        });
        let body = body.map(|b| self.block(b));
        self.tasking.accepting.pop();
        self.scopes.pop();
        for (v, _) in &slots {
            self.constrained_flags.remove(v);
        }
        Some(Accept {
            entry: i as u32,
            index,
            params: slots,
            body,
        })
    }

    /// `requeue E [with abort];`: directly in an accept statement or a
    /// protected entry body (not in a subprogram inside one), to an entry
    /// whose parameters are those of the call being served, or none.
    pub(in crate::check) fn requeue(
        &mut self,
        target: &ast::Expr,
        abort: bool,
        sp: Span,
    ) -> Option<Requeue> {
        let here = self.ctx.last().and_then(|c| c.func);
        let accept = self
            .tasking
            .accepting
            .last()
            .filter(|a| here.is_some() && here == self.tables.tasks[a.task as usize].body)
            .cloned();
        let body = self
            .tasking
            .entry_bodies
            .last()
            .filter(|(b, ..)| here == Some(*b))
            .copied();
        // The entry whose call is served, and where.
        let (served, own_task, own_prot) = match (&accept, body) {
            (Some(a), _) => (
                self.tables.tasks[a.task as usize].entries[a.entry as usize].profile,
                Some(a.task),
                None,
            ),
            (None, Some((_, k, i))) => (
                self.tables.prots[k as usize].entries[i as usize].profile,
                None,
                Some(k),
            ),
            (None, None) => {
                let what = self.here_text();
                self.err(diagnostics::misplaced_requeue(sp, &what));
                return None;
            }
        };
        // `E (I)`: a member of a family.
        let (name, index) = match &target.kind {
            ast::ExprKind::Apply(p, ia) => (&**p, Some(ia.as_slice())),
            _ => (target, None),
        };
        let not_entry = |this: &mut Self| {
            let text = crate::syntax::parser::expr_text(name);
            this.err(diagnostics::requeue_not_an_entry(name.span, &text));
        };
        let (to, profile, family, id) = match &name.kind {
            ast::ExprKind::Name(id) => {
                let own = |entries: Vec<(String, FuncId, Option<Family>)>| {
                    entries
                        .into_iter()
                        .enumerate()
                        .find(|(_, (n, ..))| n.eq_ignore_ascii_case(&id.name))
                };
                if let Some(k) = own_task
                    && let Some((i, (_, f, fam))) = own(self.tables.tasks[k as usize]
                        .entries
                        .iter()
                        .map(|e| (e.name.clone(), e.profile, e.family))
                        .collect())
                {
                    let to = RequeueTarget::Task {
                        task: None,
                        ttype: k,
                        entry: i as u32,
                    };
                    (to, f, fam, id)
                } else if let Some(k) = own_prot
                    && let Some((i, (_, f, fam))) = own(self.tables.prots[k as usize]
                        .entries
                        .iter()
                        .map(|e| (e.name.clone(), e.profile, e.family))
                        .collect())
                    && let Some(&(_, Some(obj))) = self.tasking.prot_ctx.last()
                {
                    let obj = Ex {
                        kind: ExKind::Var(obj),
                        ty: self.prot_access(k),
                        span: name.span,
                    };
                    let to = RequeueTarget::Prot {
                        obj,
                        prot: k,
                        entry: i as u32,
                        internal: true,
                    };
                    (to, f, fam, id)
                } else {
                    // Looked up for its own message (not declared, ...).
                    if !self.lookup(&id.key).is_empty() {
                        not_entry(self);
                    } else {
                        self.expr(name, None);
                    }
                    return None;
                }
            }
            ast::ExprKind::Select(q, id) => {
                let obj = self.expr(q, None);
                let obj = self.through_access(obj);
                match self.tables.types.kind(obj.ty).clone() {
                    TypeKind::Task(k) => {
                        let Some(i) = self.tables.tasks[k as usize]
                            .entries
                            .iter()
                            .position(|e| e.name.eq_ignore_ascii_case(&id.name))
                        else {
                            let tname = self.tables.tasks[k as usize].name.clone();
                            self.err(diagnostics::not_an_entry_of_task(id.span, &id.name, &tname));
                            return None;
                        };
                        let e = &self.tables.tasks[k as usize].entries[i];
                        let (f, fam) = (e.profile, e.family);
                        let to = RequeueTarget::Task {
                            task: Some(obj),
                            ttype: k,
                            entry: i as u32,
                        };
                        (to, f, fam, id)
                    }
                    TypeKind::Protected(k) => {
                        let Some(i) = self.tables.prots[k as usize]
                            .entries
                            .iter()
                            .position(|e| e.name.eq_ignore_ascii_case(&id.name))
                        else {
                            not_entry(self);
                            return None;
                        };
                        let e = &self.tables.prots[k as usize].entries[i];
                        let (f, fam) = (e.profile, e.family);
                        if self.private_outside(k, f) {
                            let pname = self.tables.prots[k as usize].name.clone();
                            self.err(diagnostics::private_protected_operation(
                                id.span, &id.name, &pname,
                            ));
                            return None;
                        }
                        let obj = Ex {
                            ty: self.prot_access(k),
                            ..obj
                        };
                        let to = RequeueTarget::Prot {
                            obj,
                            prot: k,
                            entry: i as u32,
                            internal: false,
                        };
                        (to, f, fam, id)
                    }
                    TypeKind::Error => return None,
                    _ => {
                        not_entry(self);
                        return None;
                    }
                }
            }
            _ => {
                not_entry(self);
                return None;
            }
        };
        self.index_ref(id.span, &id.key, &Entity::Func(profile));
        let ename = crate::syntax::parser::expr_text(name);
        let index = match (family, index) {
            (None, None) => None,
            (Some(f), Some(ia)) => Some(self.family_index(f, &ename, ia, sp)?),
            (Some(f), None) => {
                let example = format!("`requeue {ename} ({});`", self.family_first_text(f));
                self.err(diagnostics::family_needs_index(
                    name.span,
                    &ename,
                    "a requeue statement",
                    &example,
                ));
                return None;
            }
            (None, Some(_)) => {
                self.err(diagnostics::not_a_family(
                    target.span,
                    &ename,
                    &format!("`requeue {ename};`"),
                ));
                return None;
            }
        };
        let want = self.tables.funcs[served as usize].clone();
        let got = self.tables.funcs[profile as usize].clone();
        let params = !got.params.is_empty();
        let conform = want.params.len() == got.params.len()
            && want
                .params
                .iter()
                .zip(&got.params)
                .all(|(a, b)| a.mode == b.mode && self.statically_match(a.ty, b.ty));
        if params && !conform {
            let text = |this: &Self, f: &Subprogram| {
                f.params
                    .iter()
                    .map(|p| {
                        format!(
                            "{} : {}{}",
                            p.name,
                            mode_text(p.mode),
                            this.tables.types.name(p.ty)
                        )
                    })
                    .collect::<Vec<_>>()
                    .join("; ")
            };
            let served_name = want
                .name
                .rsplit('.')
                .next()
                .unwrap_or(&want.name)
                .to_string();
            let (tp, sp_) = (text(self, &got), text(self, &want));
            let tp = if tp.is_empty() { "none".into() } else { tp };
            let sp_ = if sp_.is_empty() { "none".into() } else { sp_ };
            self.err(diagnostics::requeue_profile_differs(
                name.span,
                &ename,
                &served_name,
                &tp,
                &sp_,
            ));
            return None;
        }
        Some(Requeue {
            target: to,
            index,
            abort,
            params,
            accept: accept.map(|a| a.slots),
        })
    }

    /// Whether two subtypes statically match (the same subtype, or the
    /// same type with the same static constraint).
    fn statically_match(&self, a: TypeId, b: TypeId) -> bool {
        let t = &self.tables.types;
        a == b
            || (t.base(a) == t.base(b)
                && t.get(a).static_range == t.get(b).static_range
                && t.get(a).static_frange == t.get(b).static_frange
                && t.get(a).range.is_some() == t.get(a).static_range.is_some()
                && t.get(b).range.is_some() == t.get(b).static_range.is_some()
                && !t.is_array(a))
    }

    /// Where the statement being checked stands, for messages.
    fn here_text(&self) -> String {
        match self.ctx.last().and_then(|c| c.func) {
            Some(f) => {
                let sub = &self.tables.funcs[f as usize];
                if self.tables.tasks.iter().any(|t| t.body == Some(f)) {
                    format!("the body of task {}", sub.name)
                } else if sub.ret.is_some() {
                    format!("function {}", sub.name)
                } else {
                    format!("procedure {}", sub.name)
                }
            }
            None => "the main program".into(),
        }
    }

    pub(in crate::check) fn delay_amount(&mut self, until: bool, d: &ast::Expr) -> Ex {
        if until {
            let e = self.expr(d, None);
            if e.ty != ERROR && !matches!(self.tables.types.kind(e.ty), TypeKind::Time) {
                self.err(diagnostics::delay_until_needs_time(
                    d.span,
                    self.tables.types.name(e.ty),
                ));
            }
            e
        } else {
            let e = self.expr(d, Some(DURATION));
            self.coerce(e, DURATION)
        }
    }

    fn guard(&mut self, g: &Option<ast::Expr>) -> Option<Ex> {
        g.as_ref().map(|g| {
            let e = self.expr(g, Some(BOOLEAN));
            self.coerce(e, BOOLEAN)
        })
    }

    pub(in crate::check) fn select(
        &mut self,
        alts: &[ast::SelectAlt],
        sp: Span,
    ) -> Option<StmtKind> {
        use ast::SelectKind as K;
        // A timed or conditional entry call.
        if let Some(K::Call(call, then)) = alts.first().map(|a| &a.kind) {
            let call_stmt = self.call_stmt(call)?;
            let StmtKind::EntryCall(ec) = call_stmt else {
                self.err(diagnostics::timed_call_not_entry(call.span));
                return None;
            };
            let then = self.scoped(then);
            let (delay, other) = match alts.get(1).map(|a| &a.kind) {
                Some(K::Delay(until, d, s)) if alts.len() == 2 && alts[1].guard.is_none() => {
                    (Some((*until, self.delay_amount(*until, d))), self.scoped(s))
                }
                Some(K::Else(s)) if alts.len() == 2 => (None, self.scoped(s)),
                _ => {
                    self.err(diagnostics::entry_call_select_alternatives(sp));
                    return None;
                }
            };
            return Some(StmtKind::TimedCall(Box::new(TimedCall {
                call: *ec,
                then,
                delay,
                other,
            })));
        }
        let mut out = Select {
            alts: Vec::new(),
            delay: None,
            terminate: None,
            els: None,
        };
        for a in alts {
            match &a.kind {
                K::Accept(acc, then) => {
                    let guard = self.guard(&a.guard);
                    let ast::StmtKind::Accept {
                        entry,
                        index,
                        params,
                        body,
                    } = &acc.kind
                    else {
                        continue;
                    };
                    let Some(x) =
                        self.accept(entry, index.as_deref(), params, body.as_deref(), acc.span)
                    else {
                        continue;
                    };
                    let then = self.scoped(then);
                    out.alts.push((guard, x, then));
                }
                K::Delay(until, d, then) => {
                    let guard = self.guard(&a.guard);
                    if out.delay.is_some() || out.terminate.is_some() {
                        self.err(diagnostics::select_one_delay_or_terminate(a.span));
                        continue;
                    }
                    let d = self.delay_amount(*until, d);
                    let then = self.scoped(then);
                    out.delay = Some((guard, *until, d, then));
                }
                K::Terminate => {
                    let guard = self.guard(&a.guard);
                    if out.delay.is_some() || out.terminate.is_some() {
                        self.err(diagnostics::select_terminate_and_delay(a.span));
                        continue;
                    }
                    out.terminate = Some(guard);
                }
                K::Else(s) => {
                    if out.delay.is_some() || out.terminate.is_some() {
                        self.err(diagnostics::select_else_with_delay(a.span));
                    }
                    out.els = Some(self.scoped(s));
                }
                K::Call(c, _) => {
                    self.err(diagnostics::entry_call_not_first(c.span));
                }
            }
        }
        if out.alts.is_empty() {
            self.err(diagnostics::select_without_accept(sp));
            return None;
        }
        Some(StmtKind::Select(Box::new(out)))
    }

    fn scoped(&mut self, ss: &[ast::Stmt]) -> Vec<Stmt> {
        self.scopes.push();
        let r = self.stmts(ss);
        self.scopes.pop();
        r
    }

    /// `E'Count`, `T'Callable`, `T'Terminated`.
    pub(in crate::check) fn task_attribute(
        &mut self,
        p: &ast::Expr,
        key: &str,
        sp: Span,
    ) -> Option<Ex> {
        if key == "count" {
            // `E'Count`, `E (I)'Count` of a member of a family.
            let (id, index) = match &p.kind {
                ast::ExprKind::Name(id) => (id, None),
                ast::ExprKind::Apply(q, ia) => match &q.kind {
                    ast::ExprKind::Name(id) => (id, Some(ia.as_slice())),
                    _ => return None,
                },
                _ => return None,
            };
            if let Some(&(k, obj)) = self.tasking.prot_ctx.last()
                && let Some(i) = self.tables.prots[k as usize]
                    .entries
                    .iter()
                    .position(|e| e.name.eq_ignore_ascii_case(&id.name))
            {
                let obj = obj?;
                let access = self.prot_access(k);
                let o = Ex {
                    kind: ExKind::Var(obj),
                    ty: access,
                    span: sp,
                };
                let family = self.tables.prots[k as usize].entries[i].family;
                let mut args = vec![o];
                match self.count_index(family, &id.name, index, sp) {
                    Ok(x) => args.extend(x),
                    Err(()) => return Some(self.err_ex(sp)),
                }
                return Some(self.mk(
                    ExKind::Attr(AttrOp::ProtCount(i as u32), Box::new(args)),
                    INTEGER,
                    sp,
                ));
            }
            if let Some(&k) = self.tasking.task_ctx.last()
                && let Some(i) = self.tables.tasks[k as usize]
                    .entries
                    .iter()
                    .position(|e| e.name.eq_ignore_ascii_case(&id.name))
            {
                let family = self.tables.tasks[k as usize].entries[i].family;
                let Ok(args) = self.count_index(family, &id.name, index, sp) else {
                    return Some(self.err_ex(sp));
                };
                return Some(self.mk(
                    ExKind::Attr(
                        AttrOp::Count(i as u32),
                        Box::new(args.into_iter().collect()),
                    ),
                    INTEGER,
                    sp,
                ));
            }
            if index.is_some() {
                return None;
            }
            self.err(diagnostics::count_needs_entry(id.span, &id.name));
            return Some(self.err_ex(sp));
        }
        let t = self.task_value(p)?;
        let op = if key == "callable" {
            AttrOp::Callable
        } else {
            AttrOp::Terminated
        };
        Some(self.mk(ExKind::Attr(op, Box::new(vec![t])), BOOLEAN, sp))
    }

    /// The index of `E (I)'Count` when E is a family (Err: reported, when
    /// it is missing or E is not a family).
    fn count_index(
        &mut self,
        family: Option<Family>,
        name: &str,
        index: Option<&[ast::Arg]>,
        sp: Span,
    ) -> Result<Option<Ex>, ()> {
        match (family, index) {
            (None, None) => Ok(None),
            (Some(f), Some(ia)) => self.family_index(f, name, ia, sp).map(Some).ok_or(()),
            (Some(f), None) => {
                let example = format!("`{name} ({})'Count`", self.family_first_text(f));
                self.err(diagnostics::family_needs_index(
                    sp, name, "'Count", &example,
                ));
                Err(())
            }
            (None, Some(_)) => {
                self.err(diagnostics::not_a_family(
                    sp,
                    name,
                    &format!("`{name}'Count`"),
                ));
                Err(())
            }
        }
    }

    /// ` (declared at L:C)` for a subprogram or entry profile.
    fn declared_at(&self, f: FuncId) -> String {
        let sp = self.tables.funcs[f as usize].span;
        match self.texts.get(&sp.context) {
            Some(t) => {
                let before = &t[..sp.lo().min(t.len())];
                let line = before.matches('\n').count() + 1;
                let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
                format!(" (declared at {line}:{col})")
            }
            None => String::new(),
        }
    }
}
