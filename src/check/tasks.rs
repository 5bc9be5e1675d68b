//! Tasks, entries, `accept`, `select`, protected objects and address
//! clauses (tasks.md). A task type is a table entry with its entries'
//! profiles and its body (a subprogram without parameters); a protected
//! type is a record of components reached through a hidden last parameter
//! of every operation.

use super::expr::mode_text;
use super::*;

/// What kind of body [`Checker::check_body`] checks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum BodyKind {
    Subprogram,
    Task,
    /// An operation or entry of the protected type.
    Protected(u32),
}

/// The name of the hidden object parameter of protected operations.
const SELF: &str = "<protected object>";

impl Checker {
    fn new_func(
        &mut self,
        name: String,
        params: Vec<Param>,
        ret: Option<TypeId>,
        span: Span,
    ) -> FuncId {
        let id = self.funcs.len() as FuncId;
        self.funcs.push(Subprogram {
            name,
            params,
            ret,
            level: self.level + 1,
            nslots: 0,
            body: None,
            span,
        });
        self.imports.push(None);
        id
    }

    fn static_int(&mut self, e: &ast::Expr, what: &str) -> Option<i64> {
        let x = self.expr(e, Some(UNIV_INT));
        match self.static_value(&x) {
            Some(Static::Int(v)) => i64::try_from(v).ok(),
            _ => {
                if x.ty != ERROR {
                    self.err(diagnostics::not_static_integer(e.span, what));
                }
                None
            }
        }
    }

    pub(super) fn task_spec(&mut self, t: &ast::TaskSpec, span: Span, out: &mut Vec<Stmt>) {
        let k = self.tasks.len() as u32;
        let name = t.name.name.clone();
        let ty = self.types.add(&name, TypeKind::Task(k));
        let mut entries = Vec::new();
        for e in &t.entries {
            if entries
                .iter()
                .any(|x: &EntryDef| x.name.eq_ignore_ascii_case(&e.name.name))
            {
                self.err(diagnostics::entry_declared_twice(e.name.span, &e.name.name));
            }
            let params = self.params(&e.params);
            let f = self.new_func(format!("{name}.{}", e.name.name), params, None, e.name.span);
            entries.push(EntryDef {
                name: e.name.name.to_string(),
                profile: f,
                interrupt: None,
            });
        }
        for (id, addr) in &t.addresses {
            let Some(i) = entries
                .iter()
                .position(|x| x.name.eq_ignore_ascii_case(&id.name))
            else {
                self.err(diagnostics::not_an_entry_of_task(id.span, &id.name, &name));
                continue;
            };
            if !self.funcs[entries[i].profile as usize].params.is_empty() {
                self.err(diagnostics::interrupt_entry_with_parameters(
                    id.span, &id.name,
                ));
            }
            if let Some(a) = self.static_int(addr, "an address") {
                match u32::try_from(a).ok().and_then(|x| self.devices.lookup(x)) {
                    None => self.err(self.no_device(addr.span, a)),
                    Some((d, role)) if role != crate::devices::Role::Interrupt => {
                        let dname = self.devices.devices()[d].name.clone();
                        self.err(diagnostics::address_not_an_interrupt(
                            addr.span,
                            &crate::devices::ada_address(a as u32),
                            role.describe(),
                            &dname,
                        ));
                    }
                    Some(_) => entries[i].interrupt = Some(a),
                }
            }
        }
        let priority = t.priority.as_ref().map(|p| {
            let e = self.expr(p, Some(INTEGER));
            self.coerce(e, INTEGER)
        });
        self.tasks.push(TaskDef {
            name: name.to_string(),
            entries,
            body: None,
            priority,
            span,
        });
        if t.is_type {
            self.declare_checked(&t.name, Entity::Type(ty));
        } else {
            self.object(std::slice::from_ref(&t.name), false, ty, None, span, out);
        }
    }

    /// The task or protected type a body names.
    fn body_target(&mut self, id: &ast::Ident) -> Option<TypeKind> {
        self.lookup(&id.key).iter().find_map(|e| {
            let t = match e {
                Entity::Type(t) | Entity::Var { ty: t, .. } => *t,
                _ => return None,
            };
            match self.types.kind(t) {
                k @ (TypeKind::Task(_) | TypeKind::Protected(_)) => Some(k.clone()),
                _ => None,
            }
        })
    }

    pub(super) fn task_body(&mut self, b: &ast::TaskBody, span: Span) {
        let Some(TypeKind::Task(k)) = self.body_target(&b.name) else {
            self.err(diagnostics::task_body_without_spec(
                b.name.span,
                &b.name.name,
            ));
            return;
        };
        if self.tasks[k as usize].body.is_some() {
            self.err(diagnostics::task_body_twice(b.name.span, &b.name.name));
            return;
        }
        let f = self.new_func(b.name.name.to_string(), Vec::new(), None, span);
        self.tasks[k as usize].body = Some(f);
        self.task_ctx.push(k);
        self.check_body(
            f,
            &b.name.key,
            &b.name.name,
            &[],
            &b.decls,
            &b.body,
            BodyKind::Task,
        );
        self.task_ctx.pop();
    }

    pub(super) fn protected_spec(&mut self, p: &ast::ProtectedSpec, out: &mut Vec<Stmt>) {
        let k = self.prots.len() as u32;
        let name = p.name.name.clone();
        // The components: a record with the object's number first.
        let mut fields = vec![types::Field {
            name: "<number>".into(),
            key: "<number>".into(),
            ty: INTEGER,
            default: None,
        }];
        for d in &p.private {
            match &d.kind {
                ast::DeclKind::Object {
                    names,
                    ty,
                    init,
                    constant: false,
                    anon: None,
                } => {
                    let t = self.subtype_ind(ty);
                    let default = init.as_ref().map(|e| {
                        let x = self.expr(e, Some(t));
                        self.coerce(x, t)
                    });
                    for n in names {
                        fields.push(types::Field {
                            name: n.name.to_string(),
                            key: n.key.to_string(),
                            ty: t,
                            default: default.clone(),
                        });
                    }
                }
                ast::DeclKind::Pragma { .. } => {}
                _ => self.err(diagnostics::unsupported_in_protected_private(d.span)),
            }
        }
        let rec = self
            .types
            .add(&format!("{name} components"), TypeKind::Record(fields));
        let access = self
            .types
            .add(&format!("{name} object"), TypeKind::Access(rec));
        let ty = self.types.add(&name, TypeKind::Protected(k));
        let self_param = |ty| Param {
            name: SELF.into(),
            mode: ast::Mode::In,
            ty,
            default: None,
        };
        let mut members = Vec::new();
        let mut entries = Vec::new();
        for op in &p.ops {
            match op {
                ast::ProtOp::Sub(spec) => {
                    let params = self.params(&spec.params);
                    let ret = spec.ret.as_ref().map(|r| self.type_mark(r));
                    let display = spec.name.display();
                    let profile =
                        self.new_func(format!("{name}.{display}"), params.clone(), ret, spec.span);
                    let mut real_params = params;
                    real_params.push(self_param(access));
                    let real =
                        self.new_func(format!("{name}.{display}"), real_params, ret, spec.span);
                    self.prot_real.insert(profile, (real, k));
                    members.push((spec.name.key(), profile, real, ret.is_some()));
                }
                ast::ProtOp::Entry(e) => {
                    let params = self.params(&e.params);
                    let profile =
                        self.new_func(format!("{name}.{}", e.name.name), params, None, e.span);
                    entries.push(ProtEntry {
                        name: e.name.name.to_string(),
                        profile,
                        barrier: None,
                        body: None,
                    });
                }
            }
        }
        self.prot_members.resize(k as usize + 1, Vec::new());
        self.prot_members[k as usize] = members;
        self.prots.push(ProtDef {
            name: name.to_string(),
            rec,
            access,
            entries,
            span: p.span,
        });
        if p.is_type {
            self.declare_checked(&p.name, Entity::Type(ty));
        } else {
            self.object(std::slice::from_ref(&p.name), false, ty, None, p.span, out);
        }
    }

    /// The access type of a protected type's object parameter.
    fn prot_access(&self, k: u32) -> TypeId {
        self.prots[k as usize].access
    }

    pub(super) fn protected_body(&mut self, b: &ast::ProtectedBody) {
        let Some(TypeKind::Protected(k)) = self.body_target(&b.name) else {
            self.err(diagnostics::protected_body_without_spec(
                b.name.span,
                &b.name.name,
            ));
            return;
        };
        self.prot_bodied.push(k);
        self.prot_ctx.push((k, None));
        self.push_scope();
        // The operations are visible inside the body by their names.
        let members = self.prot_members[k as usize].clone();
        for (key, profile, _, _) in &members {
            self.declare(key, Entity::Func(*profile));
        }
        for d in &b.decls {
            match &d.kind {
                ast::DeclKind::SubprogramBody(sb) => self.prot_op_body(k, sb),
                ast::DeclKind::EntryBody(eb) => self.entry_body_of(k, eb),
                ast::DeclKind::Pragma { .. } => {}
                _ => self.err(diagnostics::unsupported_in_protected_body(d.span)),
            }
        }
        self.pop_scope();
        self.prot_ctx.pop();
        for (key, profile, real, _) in &members {
            if self.funcs[*real as usize].body.is_none() {
                let what = self.spelled(key);
                self.err(diagnostics::protected_body_lacks(
                    b.span,
                    &b.name.name,
                    &what,
                ));
                let _ = profile;
            }
        }
        for e in self.prots[k as usize].entries.clone() {
            if e.body.is_none() {
                self.err(diagnostics::protected_body_lacks_entry(
                    b.span,
                    &b.name.name,
                    &e.name,
                ));
            }
        }
    }

    fn prot_op_body(&mut self, k: u32, b: &ast::SubprogramBody) {
        let key = b.spec.name.key();
        let params = self.params(&b.spec.params);
        let ret = b.spec.ret.as_ref().map(|r| self.type_mark(r));
        let found = self.prot_members[k as usize]
            .iter()
            .find(|(n, p, _, _)| {
                *n == key && self.same_profile(&self.funcs[*p as usize], &params, ret)
            })
            .map(|(_, _, r, _)| *r);
        let Some(real) = found else {
            self.err(diagnostics::not_in_protected_with_profile(
                b.spec.span,
                &b.spec.name.display(),
                &self.prots[k as usize].name,
            ));
            return;
        };
        if self.funcs[real as usize].body.is_some() {
            self.err(diagnostics::body_twice(b.spec.span, &b.spec.name.display()));
            return;
        }
        let written: Vec<&ast::Ident> = b.spec.params.iter().flat_map(|p| p.names.iter()).collect();
        let saw = self.check_body(
            real,
            &key,
            &b.spec.name.display(),
            &written,
            &b.decls,
            &b.body,
            BodyKind::Protected(k),
        );
        if ret.is_some() && !saw {
            self.err(diagnostics::protected_function_without_return(
                b.spec.span,
                &b.spec.name.display(),
            ));
        }
    }

    pub(super) fn entry_body(&mut self, b: &ast::EntryBody) {
        match self.prot_ctx.last() {
            Some((k, _)) => {
                let k = *k;
                self.entry_body_of(k, b)
            }
            None => self.err(diagnostics::entry_body_outside_protected(b.span)),
        }
    }

    fn entry_body_of(&mut self, k: u32, b: &ast::EntryBody) {
        let Some(i) = self.prots[k as usize]
            .entries
            .iter()
            .position(|e| e.name.eq_ignore_ascii_case(&b.name.name))
        else {
            self.err(diagnostics::not_an_entry_of_protected(
                b.name.span,
                &b.name.name,
                &self.prots[k as usize].name,
            ));
            return;
        };
        let entry = self.prots[k as usize].entries[i].clone();
        if entry.body.is_some() {
            self.err(diagnostics::entry_body_twice(b.name.span, &b.name.name));
            return;
        }
        let params = self.params(&b.params);
        let profile = self.funcs[entry.profile as usize].clone();
        if !self.same_profile(&profile, &params, None) {
            self.err(diagnostics::entry_body_params_differ(
                b.name.span,
                &b.name.name,
            ));
        }
        let access = self.prot_access(k);
        let pname = self.prots[k as usize].name.clone();
        // The barrier: a function of the object alone.
        let barrier = self.new_func(
            format!("{pname}.{} barrier", b.name.name),
            vec![Param {
                name: SELF.into(),
                mode: ast::Mode::In,
                ty: access,
                default: None,
            }],
            Some(BOOLEAN),
            b.barrier.span,
        );
        let ret_stmt = ast::Block {
            stmts: vec![ast::Stmt {
                kind: ast::StmtKind::Return(Some(Box::new(b.barrier.clone()))),
                span: b.barrier.span,
            }]
            .into(),
            handlers: Vec::new(),
            span: b.barrier.span,
            lazy: None,
        };
        self.check_body(
            barrier,
            "<barrier>",
            &b.name.name,
            &[],
            &[],
            &ret_stmt,
            BodyKind::Protected(k),
        );
        let mut real_params = profile.params.clone();
        real_params.push(Param {
            name: SELF.into(),
            mode: ast::Mode::In,
            ty: access,
            default: None,
        });
        let body = self.new_func(
            format!("{pname}.{}", b.name.name),
            real_params,
            None,
            b.span,
        );
        let written: Vec<&ast::Ident> = b.params.iter().flat_map(|p| p.names.iter()).collect();
        self.check_body(
            body,
            &b.name.key,
            &b.name.name,
            &written,
            &b.decls,
            &b.body,
            BodyKind::Protected(k),
        );
        let e = &mut self.prots[k as usize].entries[i];
        e.barrier = Some(barrier);
        e.body = Some(body);
    }

    /// Inside a protected operation: the components by name, as components
    /// of the object parameter.
    pub(super) fn declare_components(&mut self, k: u32, obj: Option<Var>) {
        let Some(obj) = obj else { return };
        let rec = self.prots[k as usize].rec;
        let access = self.prot_access(k);
        let sp = self.prots[k as usize].span;
        let fields = self
            .types
            .fields(rec)
            .map(|f| f.to_vec())
            .unwrap_or_default();
        for (i, f) in fields.iter().enumerate().skip(1) {
            let p = Ex {
                kind: ExKind::Var(obj),
                ty: access,
                span: sp,
            };
            let d = Ex {
                kind: ExKind::Deref(Box::new(p)),
                ty: rec,
                span: sp,
            };
            let x = Ex {
                kind: ExKind::Field(Box::new(d), i as u32),
                ty: f.ty,
                span: sp,
            };
            self.declare(&f.name, Entity::Alias(Box::new(x)));
        }
    }

    /// A call of a protected operation from inside the protected body (by
    /// its name alone) goes to the same object.
    pub(super) fn internal_prot_call(
        &mut self,
        f: FuncId,
        mut args: Vec<Arg>,
        span: Span,
    ) -> (FuncId, Vec<Arg>) {
        let Some(&(real, k)) = self.prot_real.get(&f) else {
            return (f, args);
        };
        let ctx = self.prot_ctx.iter().rev().find(|(p, _)| *p == k).copied();
        match ctx {
            Some((_, Some(obj))) => {
                // A protected function only reads its object (RM 9.5.1):
                // it may not call a procedure of it.
                if Some(obj) == self.prot_function_obj && self.funcs[real as usize].ret.is_none() {
                    let name = self.funcs[real as usize].name.clone();
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
    pub(super) fn peek_protected(&mut self, q: &ast::Expr) -> Option<u32> {
        let t = match &q.kind {
            ast::ExprKind::Name(id) => match self.lookup(&id.key).first() {
                Some(Entity::Var { ty, .. }) => *ty,
                _ => return None,
            },
            ast::ExprKind::Apply(p, _) => match &p.kind {
                ast::ExprKind::Name(id) => match self.lookup(&id.key).first() {
                    Some(Entity::Var { ty, .. }) => self.types.array(*ty).map(|a| a.1)?,
                    _ => return None,
                },
                _ => return None,
            },
            _ => return None,
        };
        let t = self.types.designated(t).unwrap_or(t);
        match self.types.kind(t) {
            TypeKind::Protected(k) => Some(*k),
            _ => None,
        }
    }

    /// A task or protected object named through an access value: the
    /// object itself (`P.E` for `P.all.E`).
    fn through_access(&self, x: Ex) -> Ex {
        match self.types.designated(x.ty) {
            Some(d)
                if matches!(
                    self.types.kind(d),
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
    pub(super) fn prot_function(
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
                let r = self.funcs[real as usize].ret.unwrap_or(ERROR);
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
        let fs: Vec<FuncId> = self.prot_members[k as usize]
            .iter()
            .filter(|(n, ..)| **n == *id.key)
            .map(|(_, p, _, _)| *p)
            .collect();
        if fs.is_empty() {
            self.err(diagnostics::not_a_protected_operation(
                id.span,
                &id.name,
                procedure,
                &self.prots[k as usize].name,
            ));
            return None;
        }
        // Not an internal call, even inside a protected body.
        let outer = std::mem::take(&mut self.prot_ctx);
        let r = self.call(&fs, args, None, procedure, sp, &id.name);
        self.prot_ctx = outer;
        let (f, mut a) = r?;
        let real = self.prot_real.get(&f)?.0;
        self.index_ref(id.span, &id.key, &Entity::Func(f));
        a.push(self.obj_arg(k, obj));
        Some((real, a))
    }

    /// A task value: a task object, or an access to one.
    pub(super) fn task_value(&mut self, e: &ast::Expr) -> Option<Ex> {
        let x = self.expr(e, None);
        let x = self.through_access(x);
        match self.types.kind(x.ty) {
            TypeKind::Task(_) => Some(x),
            TypeKind::Error => None,
            _ => {
                self.err(diagnostics::task_expected(e.span, self.types.name(x.ty)));
                None
            }
        }
    }

    /// `T.E (args)` or `P.Op (args)` as a statement: an entry call or a
    /// protected procedure. `None`: not a call on a task or protected object.
    pub(super) fn concurrent_call(
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
            let t = this.types.designated(t).unwrap_or(t);
            matches!(
                this.types.kind(t),
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
        match self.types.kind(obj.ty).clone() {
            TypeKind::Task(k) => {
                let def = &self.tasks[k as usize];
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
                if let Some(i) = self.prots[k as usize]
                    .entries
                    .iter()
                    .position(|e| e.name.eq_ignore_ascii_case(&id.name))
                {
                    let profile = self.prots[k as usize].entries[i].profile;
                    let name = format!("{}.{}", self.prots[k as usize].name, id.name);
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
    pub(super) fn accept(
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
            .map(|f| format!("procedure {}", self.funcs[f as usize].name))
            .unwrap_or_else(|| "the main program".into());
        let Some(&k) = self.task_ctx.last() else {
            self.err(diagnostics::misplaced_accept(sp, &here));
            return None;
        };
        if self.ctx.last().and_then(|c| c.func) != self.tasks[k as usize].body {
            self.err(diagnostics::misplaced_accept(sp, &here));
            return None;
        }
        let def = self.tasks[k as usize].clone();
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
            .accepting
            .iter()
            .find(|(t, e, _)| *t == k && *e == i as u32)
        {
            self.err(diagnostics::nested_accept(sp, &entry.name, outer));
            return None;
        }
        let profile = self.funcs[def.entries[i].profile as usize].clone();
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
                        self.types.name(p.ty)
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
        self.push_scope();
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
        self.accepting.push((k, i as u32, sp));
        let body = body.map(|b| self.block(b));
        self.accepting.pop();
        self.pop_scope();
        Some(Accept {
            entry: i as u32,
            params: slots,
            body,
        })
    }

    pub(super) fn delay_amount(&mut self, until: bool, d: &ast::Expr) -> Ex {
        if until {
            let e = self.expr(d, None);
            if e.ty != ERROR && !matches!(self.types.kind(e.ty), TypeKind::Time) {
                self.err(diagnostics::delay_until_needs_time(
                    d.span,
                    self.types.name(e.ty),
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

    pub(super) fn select(&mut self, alts: &[ast::SelectAlt], sp: Span) -> Option<StmtKind> {
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
        self.push_scope();
        let r = self.stmts(ss);
        self.pop_scope();
        r
    }

    /// `E'Count`, `T'Callable`, `T'Terminated`.
    pub(super) fn task_attribute(&mut self, p: &ast::Expr, key: &str, sp: Span) -> Option<Ex> {
        if key == "count" {
            let ast::ExprKind::Name(id) = &p.kind else {
                return None;
            };
            if let Some(&(k, obj)) = self.prot_ctx.last()
                && let Some(i) = self.prots[k as usize]
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
            if let Some(&k) = self.task_ctx.last()
                && let Some(i) = self.tasks[k as usize]
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

    /// `for X use at Addr;` outside a task spec: `X` becomes a device
    /// register.
    pub(super) fn address_clause(&mut self, name: &ast::Ident, address: &ast::Expr, span: Span) {
        let Some(addr) = self.static_int(address, "an address") else {
            return;
        };
        let here = crate::devices::ada_address(addr as u32);
        let Some((dev, role)) = u32::try_from(addr)
            .ok()
            .and_then(|a| self.devices.lookup(a))
        else {
            self.err(self.no_device(address.span, addr));
            return;
        };
        let dname = self.devices.devices()[dev].name.clone();
        if role == crate::devices::Role::Interrupt {
            self.err(diagnostics::object_at_interrupt(
                address.span,
                &here,
                &dname,
            ));
            return;
        }
        let Some(Entity::Var { ty, var, .. }) = self
            .scopes
            .last()
            .and_then(|s| s.names.get(&*name.key))
            .and_then(|es| es.last().cloned())
        else {
            self.err(diagnostics::address_clause_not_object(
                name.span, &name.name,
            ));
            return;
        };
        // Bits 0 .. 15 of the register, as the handbook's `t_16_bit`.
        let bits = self.types.array(ty).is_some_and(|(ix, elem, bounds)| {
            let b = bounds.and_then(|b| b.first()).cloned();
            ix.len() == 1 && self.types.base(elem) == BOOLEAN && b.is_some_and(|(lo, hi)| {
                matches!(
                    (self.static_value(&lo), self.static_value(&hi)),
                    (Some(Static::Int(l)), Some(Static::Int(h))) if l == 0.into() && h == 15.into()
                )
            })
        });
        if !self.types.is_integer(ty) && !bits {
            self.err(diagnostics::register_type(span, &name.name));
            return;
        }
        // The device reads and writes it: no "never read" warning.
        for frame in &mut self.unread {
            frame.remove(&var);
        }
        let reg = Entity::Alias(Box::new(Ex {
            kind: ExKind::Register(addr as u32),
            ty,
            span: name.span,
        }));
        self.redeclare(&name.key, reg);
    }

    /// "no device at ADDR" naming the device file and its addresses.
    fn no_device(&self, sp: Span, addr: i64) -> Diagnostic {
        // Written whole (an address beyond 32 bits is not cut).
        let here = if addr >= 0 {
            format!("8#{addr:o}#")
        } else {
            addr.to_string()
        };
        let known: Vec<String> = self
            .devices
            .addresses()
            .map(|(a, d, r)| {
                format!(
                    "{} ({} of `{}`)",
                    crate::devices::ada_address(a),
                    r.describe(),
                    self.devices.devices()[d].name
                )
            })
            .collect();
        let mut d = diagnostics::no_device_at(sp, &here, self.devices.source());
        let default = *self.devices == crate::devices::Devices::default_set();
        d = if known.is_empty() {
            d.with_hint("the device file declares no devices: give one with `--devices FILE.toml`")
        } else if default {
            d.with_hint(format!(
                "the addresses there: {}; a program for other devices runs with their file: `adair run --devices FILE.toml ...`",
                known.join(", ")
            ))
        } else {
            d.with_hint(format!("the addresses there: {}", known.join(", ")))
        };
        d
    }

    pub(super) fn pragma(&mut self, _name: &ast::Ident, _span: Span) {}

    /// ` (declared at L:C)` for a subprogram or entry profile.
    fn declared_at(&self, f: FuncId) -> String {
        let sp = self.funcs[f as usize].span;
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
