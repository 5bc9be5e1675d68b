//! Statements and handled sequences.

use super::*;
use crate::syntax::ast::StmtKind as S;

impl Checker {
    pub(super) fn stmts(&mut self, ss: &[ast::Stmt]) -> Vec<Stmt> {
        let mut out = Vec::with_capacity(ss.len());
        for s in ss {
            self.stmt(s, &mut out);
        }
        // Exact size: a long program's statements are most of its memory.
        out.shrink_to_fit();
        out
    }

    /// A `begin ... exception ... end` block in its own scope. In
    /// `check_unit_consuming`, the block's statements are taken from the
    /// AST and each is dropped once it is lowered, so a long body's AST
    /// shrinks as its checked form grows.
    pub(super) fn block(&mut self, b: &ast::Block) -> Body {
        let mut stmts = Vec::new();
        let parts_here = std::mem::take(&mut self.parts_here);
        if let Some(at) = b.lazy {
            let text = self.texts.get(&at.context).cloned().unwrap_or_default();
            // The body's code, as its parts are compiled.
            let code = ir::Precompiled::new();
            let compiling = self
                .options
                .compile_parts
                .filter(|_| parts_here && !self.options.diagnostics_only);
            let diags = crate::syntax::lazy_stmts(&text, at.context, at, |n, ss| {
                if let Some(compile) = compiling {
                    let mut part = Vec::with_capacity(ss.len());
                    for s in ss {
                        self.stmt(&s, &mut part);
                    }
                    // A program with errors does not run.
                    if self.erred {
                        return;
                    }
                    let ctx = self.ctx.last().expect("a body's context");
                    let at = ir::PartAt {
                        level: self.level,
                        own: ctx.next_slot,
                        master: self.tasking.masters.last().copied().unwrap_or(false),
                    };
                    // The engine sees every full view.
                    self.tables.types.views = false;
                    let temps = compile(self.program(), at, part, &code);
                    self.tables.types.views = true;
                    self.ctx.last_mut().expect("a body's context").next_slot += temps;
                    return;
                } else if self.options.diagnostics_only {
                    // This part's checked statements go as the next are made.
                    stmts.clear();
                } else if stmts.capacity() == 0 {
                    stmts.reserve_exact(n);
                }
                for s in ss {
                    self.stmt(&s, &mut stmts);
                }
            });
            if compiling.is_some() && !self.erred {
                stmts.push(Stmt {
                    kind: StmtKind::Compiled(code),
                    span: at,
                });
            }
            if self.options.diagnostics_only {
                stmts.clear();
            }
            for d in diags {
                self.err(d);
            }
        } else if self.options.consume_ast {
            let ss = std::mem::take(&mut *b.stmts.borrow_mut());
            // About one checked statement per statement: no doubling.
            stmts.reserve_exact(ss.len());
            for s in ss {
                self.stmt(&s, &mut stmts);
            }
        } else {
            let ss = b.stmts.borrow();
            stmts.reserve_exact(ss.len());
            for s in ss.iter() {
                self.stmt(s, &mut stmts);
            }
        }
        stmts.shrink_to_fit();
        let handlers = self.handlers(&b.handlers);
        Body { stmts, handlers }
    }

    fn handlers(&mut self, hs: &[ast::Handler]) -> Vec<Handler> {
        let mut out = Vec::new();
        for h in hs {
            let mut choices = Some(Vec::new());
            for c in &h.choices {
                match c {
                    None => choices = None,
                    Some(n) => match self.denote(n, true).first() {
                        Some(Entity::Exc(e)) => {
                            if let Some(v) = &mut choices {
                                v.push(*e);
                            }
                        }
                        Some(_) => {
                            let t = crate::syntax::parser::expr_text(n);
                            self.err(diagnostics::not_an_exception(n.span, &t));
                        }
                        None => {}
                    },
                }
            }
            self.scopes.push();
            let occurrence = h.occurrence.as_ref().map(|id| {
                let var = self.new_slot();
                let e = Entity::Var {
                    var,
                    ty: OCCURRENCE,
                    constant: true,
                    value: None,
                };
                self.index_def(&id.name, id.span, &e, None);
                self.declare(&id.name, e);
                var
            });
            self.in_handler += 1;
            let stmts = self.stmts(&h.stmts);
            self.in_handler -= 1;
            self.scopes.pop();
            out.push(Handler {
                choices,
                occurrence,
                stmts,
            });
        }
        out
    }

    fn cond(&mut self, e: &ast::Expr) -> Ex {
        let c = self.expr(e, Some(BOOLEAN));
        if c.ty != ERROR && self.tables.types.base(c.ty) != BOOLEAN {
            self.err(diagnostics::condition_not_boolean(
                e.span,
                (!self.tables.types.is_universal(c.ty)).then(|| self.tables.types.name(c.ty)),
            ));
            return c;
        }
        self.coerce(c, BOOLEAN)
    }

    pub(super) fn stmt(&mut self, s: &ast::Stmt, out: &mut Vec<Stmt>) {
        crate::work::tick();
        let sp = s.span;
        if self.tasking.masters.is_empty() && !matches!(s.kind, S::Decl(_) | S::Null | S::Error) {
            self.activate_library_tasks(out, sp);
        }
        let kind = match &s.kind {
            S::Null | S::Error => return,
            S::Decl(d) => {
                self.decl(d, out);
                return;
            }
            S::Assign(target, value) => {
                // Assigning a variable is not reading it.
                let before = self.target_var(target).map(|v| (v, self.was_read(v)));
                let t = self.expr(target, None);
                if let Some((v, false)) = before {
                    self.set_read(v, false);
                }
                self.check_variable(&t, target.span, "the target of an assignment");
                self.limited_assignment(t.ty, target.span);
                let ty = t.ty;
                // An aggregate assigned to a slice takes the slice's bounds
                // (`A (2 .. 4) := (others => 9);`).
                let vty = match (&t.kind, &value.kind) {
                    (ExKind::Slice(_, lh), ast::ExprKind::Aggregate(_)) => {
                        let [l, h] = &**lh;
                        match self.tables.types.array(ty).map(|(i, e, _)| (i.to_vec(), e)) {
                            Some((index, elem)) => {
                                let name = self.tables.types.name(ty).to_string();
                                let st = self.tables.types.add_subtype(&name, ty);
                                self.tables.types.list[st as usize].kind = TypeKind::Array {
                                    index,
                                    elem,
                                    bounds: Some(vec![(l.clone(), h.clone())]),
                                };
                                st
                            }
                            None => ty,
                        }
                    }
                    _ => ty,
                };
                if let Some(d) = self.procedure_assigned(target.span, value) {
                    self.err(d);
                    StmtKind::Null
                } else {
                    let v = self.expr(value, Some(vty));
                    let v = self.coerce(v, vty);
                    let v = self.keep_discriminants(&t, v);
                    StmtKind::Assign(t, v)
                }
            }
            S::Call(e) => match self.call_stmt(e) {
                Some(k) => k,
                None => return,
            },
            S::If { arms, els } => {
                let mut out_arms = Vec::with_capacity(arms.len());
                for (c, body) in arms {
                    let c = self.cond(c);
                    let b = self.scoped_stmts(body);
                    out_arms.push((c, b));
                }
                let e = els
                    .as_ref()
                    .map(|b| self.scoped_stmts(b))
                    .unwrap_or_default();
                StmtKind::If(out_arms, e)
            }
            S::Case { subject, arms } => {
                let subj = self.expr(subject, None);
                let st = if self.tables.types.is_universal(subj.ty) {
                    INTEGER
                } else {
                    subj.ty
                };
                let subj = self.coerce(subj, st);
                let lists: Vec<&[ast::Choice]> =
                    arms.iter().map(|a| a.choices.as_slice()).collect();
                let (ranges, others_at) = self.case_choices(st, &lists, subject.span);
                let mut outa = Vec::new();
                let mut others = None;
                for (i, a) in arms.iter().enumerate() {
                    let b = self.scoped_stmts(&a.body);
                    if Some(i) == others_at {
                        others = Some(b);
                    } else {
                        outa.push((ranges[i].clone(), b));
                    }
                }
                StmtKind::Case(subj, outa, others)
            }
            S::Loop {
                label,
                scheme,
                body,
                end_label,
            } => {
                if let (Some(l), Some(e)) = (label, end_label)
                    && l.key != e.key
                {
                    self.err(diagnostics::end_loop_mismatch(e.span, &e.name, &l.name));
                }
                if let (None, Some(e)) = (label, end_label) {
                    self.err(diagnostics::end_loop_unnamed(e.span, &e.name));
                }
                let id = self.new_loop();
                self.loops
                    .push((label.as_ref().map(|l| l.key.to_string()), id));
                let k = match &**scheme {
                    ast::LoopScheme::Plain => {
                        let body = self.scoped_stmts(body);
                        StmtKind::Loop { id, body }
                    }
                    ast::LoopScheme::While(c) => {
                        let cond = self.cond(c);
                        let body = self.scoped_stmts(body);
                        StmtKind::While { id, cond, body }
                    }
                    ast::LoopScheme::For {
                        var,
                        reverse,
                        range,
                    } => {
                        let (lo, hi, t) = self.discrete_range(range, None);
                        let t = if self.tables.types.is_universal(t) {
                            INTEGER
                        } else {
                            t
                        };
                        let (lo, hi) = (self.coerce_base(lo, t), self.coerce_base(hi, t));
                        // With static bounds the loop parameter has a static
                        // subtype (a `case` on it needs no `others`).
                        let t = match (self.static_value(&lo), self.static_value(&hi)) {
                            (Some(Static::Int(l)), Some(Static::Int(h)))
                                if self.tables.types.is_discrete(t) =>
                            {
                                let name = self.tables.types.name(t).to_string();
                                let st = self.tables.types.add_subtype(&name, t);
                                let info = &mut self.tables.types.list[st as usize];
                                info.range = Some((lo.clone(), hi.clone()));
                                info.static_range = Some((l, h));
                                st
                            }
                            _ => t,
                        };
                        self.scopes.push();
                        let v = self.new_slot();
                        let e = Entity::Var {
                            var: v,
                            ty: t,
                            constant: true,
                            value: None,
                        };
                        self.index_def(&var.name, var.span, &e, Some(index::DefKind::LoopVariable));
                        self.declare(&var.name, e);
                        let body = self.stmts(body);
                        self.scopes.pop();
                        StmtKind::For(Box::new(ForLoop {
                            id,
                            var: v,
                            lo,
                            hi,
                            reverse: *reverse,
                            body,
                        }))
                    }
                    ast::LoopScheme::ForOf {
                        var,
                        reverse,
                        array,
                    } => self.for_of(id, var, *reverse, array, body),
                };
                self.loops.pop();
                k
            }
            S::Exit { label, cond } => {
                let id = match label {
                    None => self.loops.last().map(|l| l.1),
                    Some(l) => {
                        let f = self
                            .loops
                            .iter()
                            .rev()
                            .find(|x| x.0.as_deref() == Some(l.key.as_ref()))
                            .map(|x| x.1);
                        if f.is_none() {
                            self.err(diagnostics::no_loop_named(l.span, &l.name));
                            return;
                        }
                        f
                    }
                };
                let Some(id) = id else {
                    self.err(diagnostics::exit_outside_loop(sp));
                    return;
                };
                let c = cond.as_ref().map(|c| self.cond(c));
                StmtKind::Exit(id, c)
            }
            S::Return(v) => {
                let ctx = self.ctx.last_mut().expect("ctx");
                ctx.saw_return = true;
                let ret = ctx.ret;
                let is_sub = ctx.func.is_some();
                match (v, ret) {
                    (Some(v), Some(t)) => {
                        let e = self.expr(v, Some(t));
                        let e = self.coerce(e, t);
                        self.limited_return(&e, t);
                        StmtKind::Return(Some(e))
                    }
                    (None, None) if is_sub => StmtKind::Return(None),
                    (None, None) => {
                        self.err(diagnostics::return_outside_subprogram(sp));
                        return;
                    }
                    (Some(v), None) => {
                        self.err(diagnostics::procedure_returns_value(v.span));
                        return;
                    }
                    (None, Some(t)) => {
                        self.err(diagnostics::function_returns_nothing(
                            sp,
                            self.tables.types.name(t),
                        ));
                        return;
                    }
                }
            }
            S::Block { label, decls, body } => {
                self.scopes.push();
                if let Some(l) = label {
                    self.scopes.name(&l.key);
                    // An exception declared in a named block is
                    // `UNIT.BLOCK.NAME` (as GNAT's Exception_Name).
                    self.unit_path.push(l.name.to_string());
                }
                let mut elab = Vec::new();
                self.tasking.masters.push(false);
                self.decls_completed(decls, &mut elab);
                let inner = self.block(body);
                let creates = self.tasking.masters.pop().unwrap_or(false);
                if label.is_some() {
                    self.unit_path.pop();
                }
                self.scopes.pop();
                if creates {
                    let stmts = self.master_region(elab, inner, sp, true, false);
                    StmtKind::Block(Box::new(Body {
                        stmts,
                        handlers: Vec::new(),
                    }))
                } else if elab.is_empty() {
                    StmtKind::Block(Box::new(inner))
                } else {
                    elab.push(Stmt {
                        kind: StmtKind::Block(Box::new(inner)),
                        span: sp,
                    });
                    StmtKind::Block(Box::new(Body {
                        stmts: elab,
                        handlers: Vec::new(),
                    }))
                }
            }
            S::Raise { name, message } => {
                let msg = message.as_ref().map(|m| {
                    let e = self.expr(m, Some(STRING));
                    self.coerce(e, STRING)
                });
                match name {
                    None => {
                        if self.in_handler == 0 {
                            self.err(diagnostics::reraise_outside_handler(sp));
                            return;
                        }
                        StmtKind::Reraise
                    }
                    Some(n) => match self.denote(n, true).first() {
                        Some(Entity::Exc(e)) => StmtKind::Raise(*e, msg),
                        Some(_) => {
                            let t = crate::syntax::parser::expr_text(n);
                            self.err(diagnostics::not_an_exception(n.span, &t));
                            return;
                        }
                        None => return,
                    },
                }
            }
            S::Delay(until, d) => {
                let d = self.delay_amount(*until, d);
                StmtKind::Delay(*until, d)
            }
            S::Abort(ts) => {
                let ts = ts.iter().filter_map(|t| self.task_value(t)).collect();
                StmtKind::Abort(ts)
            }
            S::Accept {
                entry,
                index,
                params,
                body,
            } => match self.accept(entry, index.as_deref(), params, body.as_deref(), sp) {
                Some(a) => StmtKind::Accept(Box::new(a)),
                None => return,
            },
            S::Requeue { target, abort } => match self.requeue(target, *abort, sp) {
                Some(r) => StmtKind::Requeue(Box::new(r)),
                None => return,
            },
            S::Select(alts) => match self.select(alts, sp) {
                Some(k) => k,
                None => return,
            },
        };
        out.push(Stmt { kind, span: sp });
    }

    fn scoped_stmts(&mut self, ss: &[ast::Stmt]) -> Vec<Stmt> {
        self.scopes.push();
        let r = self.stmts(ss);
        self.scopes.pop();
        r
    }

    pub(super) fn call_stmt(&mut self, e: &ast::Expr) -> Option<StmtKind> {
        let (prefix, args): (&ast::Expr, &[ast::Arg]) = match &e.kind {
            ast::ExprKind::Apply(p, a) => (p, a),
            _ => (e, &[]),
        };
        if let Some(r) = self.concurrent_call(prefix, args, e.span) {
            return r;
        }
        let es = match &prefix.kind {
            ast::ExprKind::Name(_) | ast::ExprKind::Select(..) => self.denote(prefix, true),
            _ => Vec::new(),
        };
        // `V.F;` with V an object: a component, nothing to call (the
        // denotation reports only unknown names and package members).
        if es.is_empty()
            && let ast::ExprKind::Select(q, _) = &prefix.kind
            && self
                .denote(q, false)
                .first()
                .is_some_and(|x| !matches!(x, Entity::Package(_)))
        {
            let t = crate::syntax::parser::expr_text(prefix);
            self.err(diagnostics::not_a_procedure_or_entry(e.span, &t));
            for a in args {
                self.expr(&a.value, None);
            }
            return None;
        }
        let fs: Vec<FuncId> = es
            .iter()
            .filter_map(|x| {
                if let Entity::Func(f) = x {
                    Some(*f)
                } else {
                    None
                }
            })
            .collect();
        if fs.is_empty() {
            if !es.is_empty() {
                let t = crate::syntax::parser::expr_text(prefix);
                self.err(diagnostics::not_a_procedure(e.span, &t));
            } else if !matches!(
                prefix.kind,
                ast::ExprKind::Name(_) | ast::ExprKind::Select(..)
            ) {
                self.err(diagnostics::not_a_statement(e.span));
            }
            for a in args {
                self.expr(&a.value, None);
            }
            return None;
        }
        let name = crate::syntax::parser::expr_text(prefix);
        let (f, a) = self.call(&fs, args, None, true, e.span, &name)?;
        if let Some(id) = last_ident(prefix) {
            self.index_ref(id.span, &id.key, &Entity::Func(f));
        }
        Some(StmtKind::Call(self.tables.callee(f), a.into()))
    }
}

impl Checker {
    /// `for E of [reverse] A loop ... end loop;`: one `for` loop per
    /// dimension over `A'Range (N)` (row-major, as GNAT), with `E` standing
    /// for `A (I1, ..., In)`. An array that is not a name (a function
    /// result, an aggregate) is evaluated once into a hidden constant first.
    fn for_of(
        &mut self,
        id: u32,
        var: &ast::Ident,
        reverse: bool,
        array: &ast::Expr,
        body: &[ast::Stmt],
    ) -> StmtKind {
        let arr = self.expr(array, None);
        let Some(index) = self.tables.types.array(arr.ty).map(|(i, _, _)| i.to_vec()) else {
            if arr.ty != ERROR {
                self.err(diagnostics::for_of_needs_array(
                    array.span,
                    &self.tname(arr.ty),
                ));
            }
            let body = self.scoped_stmts(body);
            return StmtKind::Loop { id, body };
        };
        let elem = self
            .tables
            .types
            .array(arr.ty)
            .map(|(_, e, _)| e)
            .unwrap_or(ERROR);
        self.scopes.push();
        let mut before = Vec::new();
        let base = if is_name(&arr) {
            arr
        } else {
            let tmp = self.new_slot();
            self.declare(
                " for-of array",
                Entity::Var {
                    var: tmp,
                    ty: arr.ty,
                    constant: true,
                    value: None,
                },
            );
            let (ty, span) = (arr.ty, arr.span);
            before.push(Stmt {
                kind: StmtKind::Assign(self.mk(ExKind::Var(tmp), ty, span), arr),
                span,
            });
            self.mk(ExKind::Var(tmp), ty, span)
        };
        let vars: Vec<Var> = index.iter().map(|_| self.new_slot()).collect();
        let subscripts = vars
            .iter()
            .zip(&index)
            .map(|(v, t)| self.mk(ExKind::Var(*v), *t, var.span))
            .collect();
        // A slice `P (L .. H)`: its components are those of `P` from L to H.
        let (base, slice) = match base.kind {
            ExKind::Slice(p, lh) => {
                let [l, h] = *lh;
                (*p, Some((l, h)))
            }
            _ => (base, None),
        };
        let element = self.mk(
            ExKind::Index(Box::new(base.clone()), Box::new(subscripts)),
            elem,
            var.span,
        );
        let e = Entity::Alias(Box::new(element));
        self.index_def(&var.name, var.span, &e, None);
        self.declare(&var.name, e);
        let mut stmts = self.stmts(body);
        self.scopes.pop();
        // Innermost dimension first: the last index varies fastest.
        for (d, v) in vars.iter().enumerate().rev() {
            let dim = d as u8 + 1;
            let it = index[d];
            let (lo, hi) = match &slice {
                Some((l, h)) => (l.clone(), h.clone()),
                None => (
                    self.mk(
                        ExKind::Attr(AttrOp::ArrFirst(dim), Box::new(vec![base.clone()])),
                        it,
                        array.span,
                    ),
                    self.mk(
                        ExKind::Attr(AttrOp::ArrLast(dim), Box::new(vec![base.clone()])),
                        it,
                        array.span,
                    ),
                ),
            };
            let loop_id = if d == 0 { id } else { self.new_loop() };
            stmts = vec![Stmt {
                kind: StmtKind::For(Box::new(ForLoop {
                    id: loop_id,
                    var: *v,
                    lo,
                    hi,
                    reverse,
                    body: stmts,
                })),
                span: array.span,
            }];
        }
        if before.is_empty() {
            return stmts.pop().map(|s| s.kind).unwrap_or(StmtKind::Null);
        }
        before.extend(stmts);
        StmtKind::Block(Box::new(Body {
            stmts: before,
            handlers: Vec::new(),
        }))
    }
}

/// Whether an array expression names an object (so that writing to its
/// components through the loop's element name changes it).
fn is_name(e: &Ex) -> bool {
    match &e.kind {
        ExKind::Var(_) | ExKind::Deref(_) => true,
        ExKind::Index(p, _) | ExKind::Field(p, _) | ExKind::Variant(p, _) | ExKind::Slice(p, _) => {
            is_name(p)
        }
        _ => false,
    }
}

impl Checker {
    /// The variable a plain-name assignment target denotes.
    fn target_var(&self, target: &ast::Expr) -> Option<Var> {
        let ast::ExprKind::Name(n) = &target.kind else {
            return None;
        };
        match self.lookup(&n.key).first() {
            Some(Entity::Var { var, .. }) => Some(*var),
            _ => None,
        }
    }
}

/// The identifier a name ends with (`P` of `P` and of `Pkg.P`).
pub(super) fn last_ident(e: &ast::Expr) -> Option<&ast::Ident> {
    match &e.kind {
        ast::ExprKind::Name(id) | ast::ExprKind::Select(_, id) => Some(id),
        _ => None,
    }
}

impl Checker {
    /// `F := ValuePosition (1, N);`: a procedure that gives its result in
    /// its last, `out` parameter, called as a function. The diagnostic
    /// shows the call as it is written (`ValuePosition (1, N, F);`).
    fn procedure_assigned(&mut self, target: Span, value: &ast::Expr) -> Option<Diagnostic> {
        let (callee, args) = match &value.kind {
            ast::ExprKind::Apply(p, args) => (p, args.len()),
            _ => return None,
        };
        let ast::ExprKind::Name(id) = &callee.kind else {
            return None;
        };
        let es = self.lookup(&id.key);
        let mut out_last = None;
        for e in &es {
            let Entity::Func(f) = e else { return None };
            let sp = &self.tables.funcs[*f as usize];
            if sp.ret.is_some() {
                return None;
            }
            if sp.params.len() == args + 1
                && matches!(
                    sp.params.last().map(|p| p.mode),
                    Some(ast::Mode::Out | ast::Mode::InOut)
                )
            {
                out_last = Some(*f);
            }
        }
        let f = out_last?;
        let call = self.snippet(value.span);
        let written = format!(
            "{}, {});",
            call.trim_end().strip_suffix(')')?.trim_end(),
            self.snippet(target)
        );
        Some(diagnostics::procedure_result_in_out_param(
            value.span,
            &id.name,
            &self.tables.funcs[f as usize].params.last()?.name,
            &written,
            &self.signature(f),
        ))
    }
}
