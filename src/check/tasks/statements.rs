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
            .filter(|(n, ..)| **n == *id.key)
            .map(|(_, p, _, _)| *p)
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
        // Not an internal call, even inside a protected body.
        let outer = std::mem::take(&mut self.tasking.prot_ctx);
        let r = self.call(&fs, args, None, procedure, sp, &id.name);
        self.tasking.prot_ctx = outer;
        let (f, mut a) = r?;
        let real = self.tables.prot_real.get(&f)?.0;
        self.index_ref(id.span, &id.key, &Entity::Func(f));
        a.push(self.obj_arg(k, obj));
        Some((real, a))
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
        Some(self.entry_or_procedure(obj, id, args, span))
    }

    fn entry_or_procedure(
        &mut self,
        obj: Ex,
        id: &ast::Ident,
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
                let name = format!("{}.{}", def.name, id.name);
                let (_, a) = self.call(&[profile], args, None, true, span, &name)?;
                Some(StmtKind::EntryCall(Box::new(EntryCall {
                    target: CallTarget::Task {
                        task: obj,
                        ttype: k,
                        entry: i as u32,
                    },
                    args: a,
                })))
            }
            TypeKind::Protected(k) => {
                if let Some(i) = self.tables.prots[k as usize]
                    .entries
                    .iter()
                    .position(|e| e.name.eq_ignore_ascii_case(&id.name))
                {
                    let profile = self.tables.prots[k as usize].entries[i].profile;
                    let name = format!("{}.{}", self.tables.prots[k as usize].name, id.name);
                    let (_, mut a) = self.call(&[profile], args, None, true, span, &name)?;
                    a.push(self.obj_arg(k, obj));
                    return Some(StmtKind::EntryCall(Box::new(EntryCall {
                        target: CallTarget::Prot {
                            prot: k,
                            entry: i as u32,
                        },
                        args: a,
                    })));
                }
                let (real, a) = self.prot_subprogram(k, obj, id, args, true, span)?;
                Some(StmtKind::ProtCall(real, a.into()))
            }
            _ => None,
        }
    }

    /// `accept E (...) [do ... end E];` in the body of the task declaring E.
    pub(in crate::check) fn accept(
        &mut self,
        entry: &ast::Ident,
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
        if let Some(&(_, _, outer)) = self
            .tasking
            .accepting
            .iter()
            .find(|(t, e, _)| *t == k && *e == i as u32)
        {
            self.err(diagnostics::nested_accept(sp, &entry.name, outer));
            return None;
        }
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
            slots.push((var, p.mode));
        }
        self.tasking.accepting.push((k, i as u32, sp));
        let body = body.map(|b| self.block(b));
        self.tasking.accepting.pop();
        self.scopes.pop();
        Some(Accept {
            entry: i as u32,
            params: slots,
            body,
        })
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
                        params,
                        body,
                    } = &acc.kind
                    else {
                        continue;
                    };
                    let Some(x) = self.accept(entry, params, body.as_deref(), acc.span) else {
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
            let ast::ExprKind::Name(id) = &p.kind else {
                return None;
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
                return Some(self.mk(
                    ExKind::Attr(AttrOp::ProtCount(i as u32), Box::new(vec![o])),
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
                return Some(self.mk(
                    ExKind::Attr(AttrOp::Count(i as u32), Box::default()),
                    INTEGER,
                    sp,
                ));
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
