//! Tasks and protected objects: their declarations and bodies (tasks.md);
//! entry calls, `accept` and `select` are in `statements.rs`, address
//! clauses in `devices.rs`. A task type is a table entry with its entries'
//! profiles and its body (a subprogram without parameters); a protected
//! type is a record of components reached through a hidden last parameter
//! of every operation.

use super::expr::mode_text;
use super::*;

mod devices;
mod statements;

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

/// The first queue of the entry after one whose first queue and family
/// are `prev` (the first entry's: 0).
fn next_queue(prev: Option<(u32, Option<Family>)>) -> u32 {
    prev.map_or(0, |(first, f)| {
        first.saturating_add(f.map_or(1, |f| f.len()))
    })
}

impl Checker {
    fn new_func(
        &mut self,
        name: String,
        params: Vec<Param>,
        ret: Option<TypeId>,
        span: Span,
    ) -> FuncId {
        let id = self.tables.funcs.len() as FuncId;
        self.tables.funcs.push(Subprogram {
            name,
            params,
            ret,
            level: self.level + 1,
            nslots: 0,
            body: None,
            span,
        });
        self.tables.imports.push(None);
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

    /// The index range of entry family `entry`: a discrete subtype with
    /// static bounds (a range `1 .. 4` is one of its type).
    fn entry_family(&mut self, r: &ast::DiscreteRange, entry: &ast::Ident) -> Option<Family> {
        let (lo, hi, t) = self.discrete_range(r, None);
        if t == ERROR || !self.tables.types.is_discrete(t) {
            return None;
        }
        let span = match r {
            ast::DiscreteRange::Range(a, b) => Span {
                end: b.span.end,
                ..a.span
            },
            ast::DiscreteRange::Subtype(ind) => ind.span,
            ast::DiscreteRange::Attr(e) => e.span,
        };
        let bounds = match (self.static_value(&lo), self.static_value(&hi)) {
            (Some(Static::Int(a)), Some(Static::Int(b))) => {
                i64::try_from(a).ok().zip(i64::try_from(b).ok())
            }
            _ => None,
        };
        let Some((a, b)) = bounds else {
            self.err(diagnostics::family_range_not_static(span, &entry.name));
            return None;
        };
        if a < 0 {
            self.err(diagnostics::family_low_bound_negative(span, &entry.name, a));
            return None;
        }
        // The subtype an index is checked against.
        let ty = match r {
            ast::DiscreteRange::Subtype(_) => t,
            _ => {
                let name = self.tables.types.name(t).to_string();
                let st = self.tables.types.add_subtype(&name, t);
                self.set_range(st, lo, hi);
                st
            }
        };
        Some(Family { ty, lo: a, hi: b })
    }

    pub(super) fn task_spec(&mut self, t: &ast::TaskSpec, span: Span, out: &mut Vec<Stmt>) {
        let k = self.tables.tasks.len() as u32;
        let name = t.name.name.clone();
        let ty = self.tables.types.add(&name, TypeKind::Task(k));
        let discriminants = self.conc_discriminants(ty, &t.discriminants, t.is_type, "task", &name);
        let mut entries = Vec::new();
        for e in &t.entries {
            if entries
                .iter()
                .any(|x: &EntryDef| x.name.eq_ignore_ascii_case(&e.name.name))
            {
                self.err(diagnostics::entry_declared_twice(e.name.span, &e.name.name));
            }
            let family = e
                .family
                .as_ref()
                .and_then(|r| self.entry_family(r, &e.name));
            let params = self.params(&e.params);
            let f = self.new_func(format!("{name}.{}", e.name.name), params, None, e.name.span);
            self.index_entry(&e.name, e.span, f);
            let first = next_queue(entries.last().map(|x: &EntryDef| (x.first, x.family)));
            entries.push(EntryDef {
                name: e.name.name.to_string(),
                profile: f,
                interrupt: None,
                family,
                first,
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
            if entries[i].family.is_some() {
                self.err(diagnostics::interrupt_entry_family(id.span, &id.name));
                continue;
            }
            if !self.tables.funcs[entries[i].profile as usize]
                .params
                .is_empty()
            {
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
        // The priority may read the discriminants (RM D.1(17)).
        self.scopes.push();
        for (i, d) in discriminants.iter().enumerate() {
            let x = Ex {
                kind: ExKind::Discriminant(i as u32),
                ty: d.ty,
                span: t.name.span,
            };
            self.declare(&d.name, Entity::Alias(Box::new(x)));
        }
        let priority = t.priority.as_ref().map(|p| {
            let e = self.expr(p, Some(INTEGER));
            self.coerce(e, INTEGER)
        });
        self.scopes.pop();
        self.tables.tasks.push(TaskDef {
            name: name.to_string(),
            discriminants,
            entries,
            body: None,
            priority,
            span,
        });
        if t.is_type {
            self.declare_type_or_full_view(&t.name, ty, &t.discriminants, span);
        } else {
            // A single task: its anonymous type is recorded too, so hover on
            // the object shows the declaration.
            self.index_def(&t.name.name, t.name.span, &Entity::Type(ty), None);
            self.object(std::slice::from_ref(&t.name), false, ty, None, span, out);
        }
    }

    /// The discriminant part of the task or protected type `ty` (RM 9.1,
    /// 9.4): none on a single task or protected object.
    fn conc_discriminants(
        &mut self,
        ty: TypeId,
        ps: &[ast::Param],
        is_type: bool,
        unit: &str,
        name: &str,
    ) -> Vec<types::Field> {
        let Some(first) = ps.first() else {
            return Vec::new();
        };
        if !is_type {
            self.err(diagnostics::single_unit_discriminants(
                first.span, unit, name,
            ));
            return Vec::new();
        }
        let (fields, names) = self.discriminant_part(ps);
        for (i, (n, f)) in names.into_iter().zip(&fields).enumerate() {
            self.index_field(ty, i as u32, n, f.ty);
        }
        self.tables.types.conc_discrs.insert(ty, fields.clone());
        fields
    }

    /// The task or protected type a body names.
    fn body_target(&mut self, id: &ast::Ident) -> Option<TypeKind> {
        self.lookup(&id.key).iter().find_map(|e| {
            let t = match e {
                Entity::Type(t) | Entity::Var { ty: t, .. } => *t,
                _ => return None,
            };
            match self.tables.types.kind(t) {
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
        if self.tables.tasks[k as usize].body.is_some() {
            self.err(diagnostics::task_body_twice(b.name.span, &b.name.name));
            return;
        }
        // The discriminants: the body's parameters (RM 9.1(12)).
        let params = self.tables.tasks[k as usize]
            .discriminants
            .iter()
            .map(|d| Param {
                name: d.name.clone(),
                mode: ast::Mode::In,
                ty: d.ty,
                default: None,
            })
            .collect();
        let f = self.new_func(b.name.name.to_string(), params, None, span);
        self.tables.tasks[k as usize].body = Some(f);
        self.tasking.task_ctx.push(k);
        self.check_body(
            f,
            &b.name.key,
            &b.name.name,
            &[],
            &b.decls,
            &b.body,
            BodyKind::Task,
        );
        self.tasking.task_ctx.pop();
    }

    pub(super) fn protected_spec(&mut self, p: &ast::ProtectedSpec, out: &mut Vec<Stmt>) {
        let k = self.tables.prots.len() as u32;
        let name = p.name.name.clone();
        let ty = self.tables.types.add(&name, TypeKind::Protected(k));
        // The components: a record with the object's number first, then
        // the discriminants (the record's discriminants, the number
        // included), then the private part's components.
        let mut fields = vec![types::Field {
            discriminant: true,
            ..types::Field::plain("<number>", "<number>", INTEGER, None)
        }];
        let discriminants =
            self.conc_discriminants(ty, &p.discriminants, p.is_type, "protected object", &name);
        fields.extend(discriminants.iter().cloned());
        // In the private part a discriminant stands for the value being
        // built (a bound: `Items : Part_Array (1 .. Size)`).
        self.scopes.push();
        for (i, f) in fields.iter().enumerate().skip(1) {
            let x = Ex {
                kind: ExKind::Discriminant(i as u32),
                ty: f.ty,
                span: p.name.span,
            };
            self.declare(&f.name, Entity::Alias(Box::new(x)));
        }
        let outer = std::mem::replace(&mut self.in_discriminated, !discriminants.is_empty());
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
                    let dependent = self.in_discriminated && self.reads_discriminant(t);
                    if dependent {
                        self.check_discriminants_alone(t, ty.span);
                    }
                    let default = init.as_ref().map(|e| {
                        let x = self.expr(e, Some(t));
                        self.coerce(x, t)
                    });
                    let ft = if dependent {
                        self.tables.types.base(t)
                    } else {
                        t
                    };
                    for n in names {
                        fields.push(types::Field {
                            dependent: dependent.then_some(t),
                            ..types::Field::plain(&n.name, &n.key, ft, default.clone())
                        });
                    }
                }
                ast::DeclKind::Pragma { .. }
                | ast::DeclKind::SubprogramDecl { import: None, .. } => {}
                _ => self.err(diagnostics::unsupported_in_protected_private(d.span)),
            }
        }
        self.in_discriminated = outer;
        self.scopes.pop();
        let rec = self
            .tables
            .types
            .add(&format!("{name} components"), TypeKind::Record(fields));
        let access = self
            .tables
            .types
            .add(&format!("{name} object"), TypeKind::Access(rec));
        let self_param = |ty| Param {
            name: SELF.into(),
            mode: ast::Mode::In,
            ty,
            default: None,
        };
        let mut members = Vec::new();
        let mut entries = Vec::new();
        // The visible operations, then the private part's (called from
        // the body only).
        let private_subs: Vec<ast::ProtOp> = p
            .private
            .iter()
            .filter_map(|d| match &d.kind {
                ast::DeclKind::SubprogramDecl { spec, import: None } => {
                    Some(ast::ProtOp::Sub(spec.clone()))
                }
                _ => None,
            })
            .chain(p.private_entries.iter().cloned().map(ast::ProtOp::Entry))
            .collect();
        let all = p
            .ops
            .iter()
            .map(|o| (o, false))
            .chain(private_subs.iter().map(|o| (o, true)));
        for (op, private) in all {
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
                    self.flag_formals(real);
                    self.tables.prot_real.insert(profile, (real, k));
                    if private {
                        self.tables.prot_private.insert(profile);
                    }
                    members.push(ProtMember {
                        name: spec.name.key(),
                        profile,
                        real,
                    });
                }
                ast::ProtOp::Entry(e) => {
                    let family = e
                        .family
                        .as_ref()
                        .and_then(|r| self.entry_family(r, &e.name));
                    let params = self.params(&e.params);
                    let profile =
                        self.new_func(format!("{name}.{}", e.name.name), params, None, e.span);
                    self.index_entry(&e.name, e.span, profile);
                    let first = next_queue(entries.last().map(|x: &ProtEntry| (x.first, x.family)));
                    if private {
                        self.tables.prot_private.insert(profile);
                    }
                    entries.push(ProtEntry {
                        name: e.name.name.to_string(),
                        profile,
                        barrier: None,
                        body: None,
                        family,
                        first,
                    });
                }
            }
        }
        self.tables.prot_members.resize(k as usize + 1, Vec::new());
        self.tables.prot_members[k as usize] = members;
        self.tables.prots.push(ProtDef {
            name: name.to_string(),
            rec,
            access,
            entries,
            span: p.span,
        });
        if p.is_type {
            self.declare_type_or_full_view(&p.name, ty, &p.discriminants, p.span);
        } else {
            // As for a single task.
            self.index_def(&p.name.name, p.name.span, &Entity::Type(ty), None);
            self.object(std::slice::from_ref(&p.name), false, ty, None, p.span, out);
        }
    }

    /// The access type of a protected type's object parameter.
    fn prot_access(&self, k: u32) -> TypeId {
        self.tables.prots[k as usize].access
    }

    pub(super) fn protected_body(&mut self, b: &ast::ProtectedBody) {
        let Some(TypeKind::Protected(k)) = self.body_target(&b.name) else {
            self.err(diagnostics::protected_body_without_spec(
                b.name.span,
                &b.name.name,
            ));
            return;
        };
        self.tables.prot_bodied.push(k);
        self.tasking.prot_ctx.push((k, None));
        self.scopes.push();
        // The operations are visible inside the body by their names.
        let members = self.tables.prot_members[k as usize].clone();
        for m in &members {
            self.declare(&m.name, Entity::Func(m.profile));
        }
        for d in &b.decls {
            match &d.kind {
                ast::DeclKind::SubprogramBody(sb) => self.prot_op_body(k, sb),
                ast::DeclKind::EntryBody(eb) => self.entry_body_of(k, eb),
                ast::DeclKind::Pragma { .. } => {}
                _ => self.err(diagnostics::unsupported_in_protected_body(d.span)),
            }
        }
        self.scopes.pop();
        self.tasking.prot_ctx.pop();
        for m in &members {
            if self.tables.funcs[m.real as usize].body.is_none() {
                let what = self.spelled(&m.name);
                self.err(diagnostics::protected_body_lacks(
                    b.span,
                    &b.name.name,
                    &what,
                ));
            }
        }
        for e in self.tables.prots[k as usize].entries.clone() {
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
        let found = self.tables.prot_members[k as usize]
            .iter()
            .find(|m| {
                m.name == key
                    && self.same_profile(&self.tables.funcs[m.profile as usize], &params, ret)
            })
            .map(|m| m.real);
        let Some(real) = found else {
            self.err(diagnostics::not_in_protected_with_profile(
                b.spec.span,
                &b.spec.name.display(),
                &self.tables.prots[k as usize].name,
            ));
            return;
        };
        if self.tables.funcs[real as usize].body.is_some() {
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
        match self.tasking.prot_ctx.last() {
            Some((k, _)) => {
                let k = *k;
                self.entry_body_of(k, b)
            }
            None => self.err(diagnostics::entry_body_outside_protected(b.span)),
        }
    }

    fn entry_body_of(&mut self, k: u32, b: &ast::EntryBody) {
        let Some(i) = self.tables.prots[k as usize]
            .entries
            .iter()
            .position(|e| e.name.eq_ignore_ascii_case(&b.name.name))
        else {
            self.err(diagnostics::not_an_entry_of_protected(
                b.name.span,
                &b.name.name,
                &self.tables.prots[k as usize].name,
            ));
            return;
        };
        let entry = self.tables.prots[k as usize].entries[i].clone();
        if entry.body.is_some() {
            self.err(diagnostics::entry_body_twice(b.name.span, &b.name.name));
            return;
        }
        let params = self.params(&b.params);
        let profile = self.tables.funcs[entry.profile as usize].clone();
        if !self.same_profile(&profile, &params, None) {
            self.err(diagnostics::entry_body_params_differ(
                b.name.span,
                &b.name.name,
            ));
        }
        let access = self.prot_access(k);
        let pname = self.tables.prots[k as usize].name.clone();
        // A family's index: a parameter of the barrier and the body, before
        // the object.
        let index = self.family_body_index(b, entry.family);
        let index_param = |id: &ast::Ident, ty| Param {
            name: id.name.to_string(),
            mode: ast::Mode::In,
            ty,
            default: None,
        };
        let self_param = Param {
            name: SELF.into(),
            mode: ast::Mode::In,
            ty: access,
            default: None,
        };
        let mut barrier_params: Vec<Param> =
            index.iter().map(|(id, t)| index_param(id, *t)).collect();
        barrier_params.push(self_param.clone());
        // The barrier: a function of the object alone (and of the index).
        let barrier = self.new_func(
            format!("{pname}.{} barrier", b.name.name),
            barrier_params,
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
        let index_name: Vec<&ast::Ident> = index.iter().map(|(id, _)| *id).collect();
        self.check_body(
            barrier,
            "<barrier>",
            &b.name.name,
            &index_name,
            &[],
            &ret_stmt,
            BodyKind::Protected(k),
        );
        let mut real_params = profile.params.clone();
        real_params.extend(index.iter().map(|(id, t)| index_param(id, *t)));
        real_params.push(self_param);
        let body = self.new_func(
            format!("{pname}.{}", b.name.name),
            real_params,
            None,
            b.span,
        );
        let written: Vec<&ast::Ident> = b
            .params
            .iter()
            .flat_map(|p| p.names.iter())
            .chain(index_name.iter().copied())
            .collect();
        self.tasking.entry_bodies.push((body, k, i as u32));
        self.check_body(
            body,
            &b.name.key,
            &b.name.name,
            &written,
            &b.decls,
            &b.body,
            BodyKind::Protected(k),
        );
        self.tasking.entry_bodies.pop();
        let e = &mut self.tables.prots[k as usize].entries[i];
        e.barrier = Some(barrier);
        e.body = Some(body);
    }

    /// The index of an entry body (`for I in Range`) and its subtype, when
    /// the entry is a family (`family`); reported when it does not match
    /// the declaration.
    fn family_body_index<'b>(
        &mut self,
        b: &'b ast::EntryBody,
        family: Option<Family>,
    ) -> Option<(&'b ast::Ident, TypeId)> {
        match (&b.family, family) {
            (None, None) => None,
            (Some((id, r)), Some(f)) => {
                let (lo, hi, t) = self.discrete_range(r, None);
                let same = t == ERROR
                    || (self.tables.types.base(t) == self.tables.types.base(f.ty)
                        && self.static_value(&lo) == Some(Static::Int(f.lo.into()))
                        && self.static_value(&hi) == Some(Static::Int(f.hi.into())));
                if !same {
                    let declared = self.family_text(f);
                    self.err(diagnostics::family_body_differs(
                        id.span,
                        &b.name.name,
                        &declared,
                    ));
                }
                Some((id, f.ty))
            }
            (None, Some(f)) => {
                let declared = self.family_text(f);
                self.err(diagnostics::family_needs_index(
                    b.name.span,
                    &b.name.name,
                    "its body",
                    &format!(
                        "`entry {} (for I in {declared}) ... when ... is`",
                        b.name.name
                    ),
                ));
                None
            }
            (Some((id, _)), None) => {
                self.err(diagnostics::not_a_family(
                    id.span,
                    &b.name.name,
                    &format!(
                        "`entry {} ... when ... is` without `(for ...)`",
                        b.name.name
                    ),
                ));
                None
            }
        }
    }

    /// A family's range as the user would write it: its subtype's name, or
    /// its bounds.
    pub(super) fn family_text(&self, f: Family) -> String {
        let name = self.tables.types.name(f.ty);
        let image = |v: i64| match self.tables.types.enum_lits(f.ty) {
            Some(l) => l
                .get(v as usize)
                .map_or_else(|| v.to_string(), |l| l.to_string()),
            None => v.to_string(),
        };
        let base = self.tables.types.base(f.ty);
        let whole = self.tables.types.discrete_bounds(base) == Some((f.lo.into(), f.hi.into()));
        match () {
            _ if whole || name != self.tables.types.name(base) => name.to_string(),
            _ if self.tables.types.enum_lits(f.ty).is_some() => {
                format!("{name} range {} .. {}", image(f.lo), image(f.hi))
            }
            _ => format!("{} .. {}", f.lo, f.hi),
        }
    }

    /// Inside a protected operation: the components by name, as components
    /// of the object parameter.
    pub(super) fn declare_components(&mut self, k: u32, obj: Option<Var>) {
        let Some(obj) = obj else { return };
        let rec = self.tables.prots[k as usize].rec;
        let access = self.prot_access(k);
        let sp = self.tables.prots[k as usize].span;
        let fields = self
            .tables
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
}

impl Checker {
    /// The operations a task or protected object of type `t` offers to
    /// callers (not those of a private part): each one's name as declared,
    /// its profile, and whether it is an entry. Empty for other types.
    pub fn operations_of(&self, t: TypeId) -> Vec<(String, FuncId, bool)> {
        let t = self.tables.types.base(t);
        let spelled = |f: FuncId| {
            let n = &self.tables.funcs[f as usize].name;
            n.rsplit('.').next().unwrap_or(n).to_string()
        };
        match *self.tables.types.kind(t) {
            TypeKind::Task(k) => self.tables.tasks[k as usize]
                .entries
                .iter()
                .map(|e| (e.name.clone(), e.profile, true))
                .collect(),
            TypeKind::Protected(k) => {
                let p = &self.tables.prots[k as usize];
                let subs = self
                    .tables
                    .prot_members
                    .get(k as usize)
                    .into_iter()
                    .flatten();
                p.entries
                    .iter()
                    .map(|e| (e.name.clone(), e.profile, true))
                    .chain(subs.map(|m| (spelled(m.profile), m.profile, false)))
                    .filter(|(_, f, _)| !self.tables.prot_private.contains(f))
                    .collect()
            }
            _ => Vec::new(),
        }
    }
}
