//! Names: `with` and `use` clauses, packages, what a simple or expanded
//! name denotes (`denote`, with the "not declared" report and its hints),
//! and the questions tools ask about the names visible at the top level.

use super::*;

impl Checker {
    /// Whether `key` (lower case) is undeclared or denotes a procedure or
    /// something other than functions: a REPL entry `F (X)` of functions
    /// only is an expression, never a call statement.
    pub fn may_name_a_procedure(&self, key: &str) -> bool {
        let es = self.lookup(key);
        es.is_empty()
            || es.iter().any(
                |e| !matches!(e, Entity::Func(f) if self.tables.funcs[*f as usize].ret.is_some()),
            )
    }

    /// The components of the record a name denotes (a variable of a record
    /// type, or of an access to one), for completion after `.`.
    pub fn record_fields_of(&self, name: &str) -> Vec<String> {
        let ty = match self.lookup(&name.to_lowercase()).first() {
            Some(Entity::Var { ty, .. }) => *ty,
            _ => return Vec::new(),
        };
        let ty = self.tables.types.designated(ty).unwrap_or(ty);
        if !self.components_visible_at(ty, None) {
            // Only the partial view's discriminants.
            let b = self.tables.types.base(ty);
            return self
                .tables
                .types
                .partial_discrs
                .get(&b)
                .map_or(Vec::new(), |ds| ds.iter().map(|d| d.name.clone()).collect());
        }
        self.tables
            .types
            .fields(ty)
            .map(|f| f.iter().map(|x| x.name.clone()).collect())
            .unwrap_or_default()
    }

    /// Whether the components (and the rest of the full view) of type `t`
    /// are visible at `at` (a source and an offset in it; `None`: at the
    /// top level, after what the checker has checked): not when `t` is a
    /// private type and `at` is outside its package's spec and body.
    pub fn components_visible_at(&self, t: TypeId, at: Option<(u32, usize)>) -> bool {
        let types = &self.tables.types;
        if !types.hidden.contains_key(&types.base(t)) {
            return true;
        }
        let Some((file, offset)) = at else {
            return false;
        };
        types
            .private_view(t)
            .and_then(|v| self.tables.packages.get(v.package as usize))
            .is_some_and(|p| {
                p.full_view_at.iter().any(|s| {
                    use crate::diag::Offsets as _;
                    s.context == file && s.lo() <= offset && offset <= s.hi()
                })
            })
    }

    /// The names a package declares visibly (lower case), for completion
    /// after `Pkg.`; `None` when `full` names no package.
    pub fn package_names(&self, full: &str) -> Option<Vec<String>> {
        let p = self
            .tables
            .packages
            .iter()
            .find(|p| p.name.eq_ignore_ascii_case(full))?;
        let mut v: Vec<String> = p.names.keys().cloned().collect();
        v.sort();
        Some(v)
    }

    /// What a name visible at the top level denotes (innermost first), for
    /// tools that describe a name without a recorded use.
    pub fn entities_of(&self, key: &str) -> Vec<Entity> {
        self.lookup(key)
    }

    /// Names in scope, for REPL completion.
    pub fn completion_names(&self) -> Vec<String> {
        let mut v = self.scopes.visible_names(&self.tables.packages);
        v.sort();
        v.dedup();
        v
    }

    /// The hint for a name that is not declared but is declared in a
    /// package the program did not `with` (the session checks the rest of
    /// the stdlib first when a check fails with such a name).
    pub fn with_hint(&self, name: &str) -> Option<String> {
        let pkg = self.package_declaring(&name.to_lowercase())?;
        Some(format!(
            "`{name}` is declared in `{pkg}`: add `with {pkg}; use {pkg};` at the top of the file"
        ))
    }

    /// The hint for `prefix.name` refused as "`name` is not declared in
    /// `prefix`" when a package the program did not `with` makes it legal:
    /// the child package `prefix.name` itself, or `prefix` declaring `name`
    /// (GNAT: `missing "with Ada.Numerics;"`).
    pub fn qualified_with_hint(&self, prefix: &str, name: &str) -> Option<String> {
        let full = format!("{prefix}.{name}");
        let find = |n: &str| {
            self.tables
                .packages
                .iter()
                .find(|p| p.name.eq_ignore_ascii_case(n))
        };
        let (what, pkg) = match find(&full) {
            Some(child) => ("is a package", child.name.clone()),
            None => (
                "is declared in a package",
                find(prefix)
                    .filter(|p| p.names.contains_key(&name.to_lowercase()))?
                    .name
                    .clone(),
            ),
        };
        Some(format!(
            "`{full}` {what} the program does not name: add `with {pkg};` at the top of the file"
        ))
    }

    /// The first (predefined, then user) package that declares `key`
    /// visibly: the usual cause of an undeclared `Put_Line` is a missing `with`.
    fn package_declaring(&self, key: &str) -> Option<String> {
        self.tables
            .packages
            .iter()
            .find(|p| p.names.contains_key(key))
            .map(|p| p.name.clone())
    }

    /// `T.E` in task T's own body, E not declared there: not an expanded
    /// name but T's entry E (T the task object, declared outside its body).
    pub(super) fn own_task_entry(&self, task: &ast::Ident, sel: &ast::Ident) -> bool {
        let Some(scope) = self.scopes.enclosing(&task.key) else {
            return false;
        };
        !scope.names.contains_key(&*sel.key)
            && self.lookup(&task.key).iter().any(|e| {
                matches!(e, Entity::Var { ty, .. }
                    if matches!(self.tables.types.kind(*ty), types::TypeKind::Task(_)))
            })
    }

    pub(super) fn funcs_named(&self, key: &str, _after: usize) -> Option<FuncId> {
        self.lookup(key).iter().find_map(|e| match e {
            Entity::Func(f) if self.tables.funcs[*f as usize].params.is_empty() => Some(*f),
            _ => None,
        })
    }

    /// `with P;`: the package must exist (standard or stdlib units are loaded
    /// by the driver before the user's file).
    pub(super) fn with_clause(&mut self, n: &ast::Expr) {
        if self.package_of(n, false).is_none() {
            let text = crate::syntax::parser::expr_text(n);
            self.missing_units.push(text.to_lowercase());
            self.err(diagnostics::no_library_unit(n.span, &text));
        }
    }

    pub(super) fn use_clause(&mut self, names: &[ast::Expr]) {
        for n in names {
            // A unit whose `with` already failed is not reported again.
            let text = crate::syntax::parser::expr_text(n).to_lowercase();
            if self.missing_units.contains(&text) {
                continue;
            }
            match self.package_of(n, true) {
                Some(p) => self.scopes.use_package(p),
                None => {
                    // `use type T;`: the operators of the package that
                    // declares T become directly visible.
                    let es = self.denote(n, false);
                    match es.first() {
                        Some(Entity::Type(t)) => {
                            let t = *t;
                            let declaring = self.tables.packages.iter().position(|p| {
                                p.names.values().any(|es| {
                                    es.iter().any(|e| matches!(e, Entity::Type(x) if *x == t))
                                })
                            });
                            if let Some(p) = declaring {
                                self.scopes.use_type_ops(p);
                            }
                        }
                        Some(_) => {
                            let text = crate::syntax::parser::expr_text(n);
                            self.err(diagnostics::not_a_package(n.span, &text));
                        }
                        None => {}
                    }
                }
            }
        }
    }

    fn package_of(&mut self, n: &ast::Expr, report: bool) -> Option<usize> {
        match self.denote(n, report).first() {
            Some(Entity::Package(p)) => Some(*p),
            _ => None,
        }
    }

    /// Finds the entities a name (identifier or selected name) denotes.
    pub(super) fn denote(&mut self, n: &ast::Expr, report: bool) -> Vec<Entity> {
        crate::work::tick();
        match &n.kind {
            ast::ExprKind::Name(id) => {
                let es = self.lookup(&id.key);
                if report {
                    self.index_use(id, &es);
                }
                if es.is_empty() && report && !self.unsupported_names.contains(&*id.key) {
                    let mut d = diagnostics::not_declared(id.span, &id.name);
                    if let Some(pkg) = self.package_declaring(&id.key) {
                        d = d.with_hint(format!(
                            "`{}` is declared in `{pkg}`: add `with {pkg}; use {pkg};` at the top of the file",
                            id.name
                        ));
                    } else if let Some(h) = diagnostics::from_other_robot_languages(&id.key) {
                        d = d.with_hint(h);
                    } else if let Some(s) = self.scopes.suggest(&self.tables.packages, &id.key) {
                        d = d.with_guess(format!("did you mean `{s}`?"));
                    }
                    let n = self.diags.len();
                    self.err(d);
                    if self.diags.len() > n {
                        self.scopes.note_undeclared(&id.key, n);
                    }
                }
                es
            }
            ast::ExprKind::Select(p, id) => {
                if let ast::ExprKind::Name(pn) = &p.kind
                    && let Some(scope) = self.scopes.enclosing(&pn.key)
                    && !self.own_task_entry(pn, id)
                {
                    let es = scope.names.get(&*id.key).cloned().unwrap_or_default();
                    if report {
                        self.index_use(id, &es);
                    }
                    if es.is_empty() && report {
                        self.err(diagnostics::not_declared_in(id.span, &id.name, &pn.name));
                    }
                    return es;
                }
                let pes = self.denote(p, report);
                match pes.first() {
                    Some(Entity::Package(pk)) => {
                        let pk = *pk;
                        let mut es = self.tables.packages[pk]
                            .names
                            .get(&*id.key)
                            .cloned()
                            .unwrap_or_default();
                        // Inside the package itself, its private names are visible too.
                        if es.is_empty() && self.scopes.in_package(pk) {
                            es = self.tables.packages[pk]
                                .private
                                .get(&*id.key)
                                .cloned()
                                .unwrap_or_default();
                        }
                        if report {
                            self.index_use(id, &es);
                        }
                        if es.is_empty() && report {
                            let pname = self.tables.packages[pk].name.clone();
                            let mut d = diagnostics::not_declared_in(id.span, &id.name, &pname);
                            let cands: Vec<String> =
                                self.tables.packages[pk].names.keys().cloned().collect();
                            if let Some(best) = cands
                                .iter()
                                .filter(|c| edit_distance(&id.key, c) <= 2)
                                .min_by_key(|c| edit_distance(&id.key, c))
                            {
                                d = d.with_guess(format!(
                                    "did you mean `{pname}.{}`?",
                                    self.spelled(best)
                                ));
                            }
                            self.err(d);
                        }
                        es
                    }
                    _ => Vec::new(),
                }
            }
            _ => Vec::new(),
        }
    }

    /// Records the use of a name whose meaning is settled: one entity, or a
    /// non-overloadable one (overloads are recorded when resolved).
    fn index_use(&mut self, id: &ast::Ident, es: &[Entity]) {
        if let Some(e) = es.first()
            && (es.len() == 1 || !matches!(e, Entity::Func(_) | Entity::EnumLit(..)))
        {
            let e = e.clone();
            self.index_ref(id.span, &id.key, &e);
        }
    }

    /// Creates a package (and its parents, for `Ada.Text_IO`), returning its index.
    pub(super) fn package(&mut self, full: &str) -> usize {
        if let Some(i) = self
            .tables
            .packages
            .iter()
            .position(|p| p.name.eq_ignore_ascii_case(full))
        {
            return i;
        }
        let idx = self.tables.packages.len();
        self.tables.packages.push(Package {
            name: full.to_string(),
            names: PMap::new(),
            private: PMap::new(),
            deferred: Vec::new(),
            private_types: Vec::new(),
            full_view_at: Vec::new(),
        });
        match full.rsplit_once('.') {
            Some((parent, last)) => {
                let p = self.package(parent);
                self.tables.packages[p]
                    .names
                    .entry(last.to_lowercase())
                    .or_default()
                    .push(Entity::Package(idx));
            }
            None => {
                // Library-level packages are visible in the outermost scope.
                self.scopes
                    .declare_library_package(full.to_lowercase(), idx);
            }
        }
        idx
    }

    /// Makes a package's declarations directly visible at the top level
    /// (script mode: Ada.Text_IO and friends without `with`/`use`).
    pub fn use_everywhere(&mut self, full: &str) {
        if let Some(i) = self
            .tables
            .packages
            .iter()
            .position(|p| p.name.eq_ignore_ascii_case(full))
        {
            self.scopes.use_at_library_level(i);
        }
    }

    /// Makes an existing entity visible in a package under another name
    /// (Ada's IO exceptions through `AdaIR` and `Ada.Text_IO`).
    pub fn export(&mut self, package: &str, name: &str, from_package: &str) {
        let (Some(to), Some(from)) = (
            self.tables
                .packages
                .iter()
                .position(|p| p.name.eq_ignore_ascii_case(package)),
            self.tables
                .packages
                .iter()
                .position(|p| p.name.eq_ignore_ascii_case(from_package)),
        ) else {
            return;
        };
        let key = name.to_lowercase();
        if let Some(es) = self.tables.packages[from].names.get(&key).cloned() {
            self.tables.packages[to].names.insert(key, es);
        }
    }
}
