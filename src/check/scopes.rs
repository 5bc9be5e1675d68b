//! Visibility: the stack of open scopes and the indexes that keep a look-up
//! to the scopes that declare a name; declaring, looking up, and the guesses
//! for a name that is not declared.

use super::*;

#[derive(Default, Debug, Clone)]
pub(super) struct Scope {
    pub(super) names: PMap<String, Vec<Entity>>,
    pub(super) uses: Vec<usize>,
    /// Packages whose operators `use type` makes directly visible (those
    /// of the package that declares the type).
    pub(super) op_uses: Vec<usize>,
    /// The name of the subprogram or block this scope belongs to (lower
    /// case), for expanded names like `Main.X`.
    pub(super) name: Option<String>,
    /// The package whose spec (false) or body (true) this scope is.
    pub(super) package: Option<(usize, bool)>,
}

/// The scopes open where the checker stands (the library level first) and
/// the indexes of their names.
#[derive(Clone)]
pub(super) struct Scopes {
    stack: Vec<Scope>,
    /// For each name, the scopes (indices into `stack`, ascending) that
    /// declare it, and the scopes that are packages': a lookup visits
    /// these only, not every scope of a deep nest (4,000 unclosed loops
    /// made each lookup walk 4,000 scopes).
    declared_in: PMap<String, Vec<u32>>,
    package_scopes: Vec<u32>,
    /// The name and constancy of each variable of the scopes (a scan of
    /// every scope's names for each assignment was quadratic).
    var_names: PMap<Var, (String, bool)>,
    /// The scopes with `use` or `use type` clauses (ascending).
    use_scopes: Vec<u32>,
    /// "not declared" reports that a later declaration may explain, by
    /// name: the report's index, the scope depth it was made at, and the
    /// number of scopes closed before it (a declaration finds its own in one
    /// look-up; see `lows` for the depth of its scopes still open).
    undeclared: HashMap<String, Vec<(usize, usize, u64)>>,
    /// Scopes closed so far, and the depths the scope stack came down to
    /// after them: (closings so far, depth), both ascending. The lowest
    /// depth reached since a report is the first entry after its count, so
    /// closing a scope does not visit every report (that was quadratic for
    /// deep nests full of undeclared names).
    closed: u64,
    lows: Vec<(u64, usize)>,
    /// Declared spelling of each name, for messages.
    spelling: PMap<String, String>,
}

impl Scopes {
    /// The library level alone.
    pub(super) fn new() -> Scopes {
        Scopes {
            stack: vec![Scope::default()],
            declared_in: PMap::new(),
            package_scopes: Vec::new(),
            var_names: PMap::new(),
            use_scopes: Vec::new(),
            undeclared: HashMap::new(),
            closed: 0,
            lows: Vec::new(),
            spelling: PMap::new(),
        }
    }

    /// The number of scopes open.
    pub(super) fn depth(&self) -> usize {
        self.stack.len()
    }

    pub(super) fn innermost(&self) -> Option<&Scope> {
        self.stack.last()
    }

    pub(super) fn innermost_mut(&mut self) -> Option<&mut Scope> {
        self.stack.last_mut()
    }

    /// The innermost open scope of the subprogram or block named `key`.
    pub(super) fn enclosing(&self, key: &str) -> Option<&Scope> {
        self.stack
            .iter()
            .rev()
            .find(|s| s.name.as_deref() == Some(key))
    }

    /// Whether the spec or body of package `p` is open.
    pub(super) fn in_package(&self, p: usize) -> bool {
        self.stack
            .iter()
            .any(|s| s.package.is_some_and(|x| x.0 == p))
    }

    pub(super) fn push(&mut self) {
        self.stack.push(Scope::default());
    }

    pub(super) fn name(&mut self, key: &str) {
        if let Some(s) = self.stack.last_mut() {
            s.name = Some(key.to_string());
        }
    }

    /// Makes the innermost scope the spec (`false`) or body of package `p`.
    pub(super) fn set_package(&mut self, p: usize, body: bool) {
        let i = self.stack.len() as u32 - 1;
        self.stack.last_mut().expect("scope").package = Some((p, body));
        if self.package_scopes.last() != Some(&i) {
            self.package_scopes.push(i);
        }
    }

    /// Notes that scope `i` has a `use` clause.
    pub(super) fn mark_uses(&mut self, i: usize) {
        let i = i as u32;
        if let Err(at) = self.use_scopes.binary_search(&i) {
            self.use_scopes.insert(at, i);
        }
    }

    /// `use P;` in the innermost scope, `p` the package.
    pub(super) fn use_package(&mut self, p: usize) {
        let s = self.stack.last_mut().expect("scope");
        if !s.uses.contains(&p) {
            s.uses.push(p);
        }
        self.mark_uses(self.stack.len() - 1);
    }

    /// `use type T;` in the innermost scope, `p` the package declaring `T`.
    pub(super) fn use_type_ops(&mut self, p: usize) {
        let s = self.stack.last_mut().expect("scope");
        if !s.op_uses.contains(&p) {
            s.op_uses.push(p);
        }
        self.mark_uses(self.stack.len() - 1);
    }

    /// Makes package `p` use-visible at the library level.
    pub(super) fn use_at_library_level(&mut self, p: usize) {
        if !self.stack[0].uses.contains(&p) {
            self.stack[0].uses.push(p);
            self.mark_uses(0);
        }
    }

    pub(super) fn pop(&mut self) {
        let i = self.stack.len() as u32 - 1;
        if let Some(s) = self.stack.pop() {
            // A package's objects are still named outside it (`P.C := 1;`
            // assigns a constant); a later object of the same slot
            // replaces the entry.
            for e in s.names.values().flatten().filter(|_| s.package.is_none()) {
                if let Entity::Var { var, .. } = e {
                    self.var_names.remove(var);
                }
            }
            for key in s.names.keys() {
                if let Some(v) = self.declared_in.get_mut(key) {
                    if v.last() == Some(&i) {
                        v.pop();
                    }
                    if v.is_empty() {
                        self.declared_in.remove(key);
                    }
                }
            }
        }
        if self.package_scopes.last() == Some(&i) {
            self.package_scopes.pop();
        }
        if self.use_scopes.last() == Some(&i) {
            self.use_scopes.pop();
        }
        let depth = self.stack.len();
        self.closed += 1;
        while self.lows.last().is_some_and(|&(_, d)| d >= depth) {
            crate::work::tick();
            self.lows.pop();
        }
        self.lows.push((self.closed, depth));
    }

    /// The depth of the scopes of a report made at `depth` after `closed`
    /// closings that are still open: the lowest the stack has come since.
    fn open_depth(&self, depth: usize, closed: u64) -> usize {
        let after = self.lows.partition_point(|&(c, _)| c <= closed);
        self.lows.get(after).map_or(depth, |&(_, d)| d.min(depth))
    }

    /// Notes that diagnostic `report` says `key` is not declared here.
    pub(super) fn note_undeclared(&mut self, key: &str, report: usize) {
        let depth = self.stack.len();
        self.undeclared
            .entry(key.to_string())
            .or_default()
            .push((report, depth, self.closed));
    }

    /// Takes the "not declared" reports of `key` made in the innermost scope
    /// (or one inside it): a declaration of `key` there now explains them.
    pub(super) fn undeclared_here(&mut self, key: &str) -> Vec<usize> {
        let depth = self.stack.len();
        let mut before = Vec::new();
        if let Some(mut uses) = self.undeclared.remove(key) {
            uses.retain(|&(i, d, c)| {
                crate::work::tick();
                let here = depth <= self.open_depth(d, c);
                if here {
                    before.push(i);
                }
                !here
            });
            if !uses.is_empty() {
                self.undeclared.insert(key.to_string(), uses);
            }
        }
        before
    }

    /// Forgets the "not declared" reports (their diagnostics are taken).
    pub(super) fn forget_reports(&mut self) {
        self.undeclared.clear();
        self.lows.clear();
    }

    /// Declares `name` in the innermost scope (and in the table of the
    /// package whose spec or body it is).
    pub(super) fn declare(&mut self, packages: &mut PVec<Package>, name: &str, e: Entity) {
        let key = name.to_lowercase();
        if !self.spelling.contains_key(&key) {
            self.spelling.insert(key.clone(), name.to_string());
        }
        let scope = self.stack.last_mut().expect("scope");
        match scope.package {
            Some((p, false)) => packages[p]
                .names
                .entry(key.clone())
                .or_default()
                .push(e.clone()),
            Some((p, true)) => packages[p]
                .private
                .entry(key.clone())
                .or_default()
                .push(e.clone()),
            None => {}
        }
        let i = self.stack.len() as u32 - 1;
        let v = self.declared_in.entry(key.clone()).or_default();
        if v.last() != Some(&i) {
            v.push(i);
        }
        if let Entity::Var { var, constant, .. } = &e {
            self.var_names.insert(*var, (key.clone(), *constant));
        }
        let scope = self.stack.last_mut().expect("scope");
        scope.names.entry(key).or_default().push(e);
    }

    /// A constant of the innermost scope that no name denotes (what a
    /// renaming evaluated once, RM 8.5.1(6)): known as a constant, so that
    /// an assignment through the renaming is refused.
    pub(super) fn declare_hidden(&mut self, var: Var, ty: TypeId) {
        const KEY: &str = " renamed";
        self.var_names.insert(var, (KEY.to_string(), true));
        let e = Entity::Var {
            var,
            ty,
            constant: true,
            value: None,
        };
        let scope = self.stack.last_mut().expect("scope");
        scope.names.entry(KEY.to_string()).or_default().push(e);
    }

    /// Declares a library-level package (`key` lower case) in the
    /// outermost scope.
    pub(super) fn declare_library_package(&mut self, key: String, p: usize) {
        let v = self.declared_in.entry(key.clone()).or_default();
        if v.first() != Some(&0) {
            v.insert(0, 0);
        }
        self.stack[0]
            .names
            .entry(key)
            .or_default()
            .push(Entity::Package(p));
    }

    /// Replaces the latest meaning of `key` in the innermost scope (and in
    /// its package's table): an object that an address clause maps.
    pub(super) fn redeclare(&mut self, packages: &mut PVec<Package>, key: &str, e: Entity) {
        if let Entity::Var { var, constant, .. } = &e {
            self.var_names.insert(*var, (key.to_string(), *constant));
        }
        let scope = self.stack.last_mut().expect("scope");
        if let Some(last) = scope.names.get_mut(key).and_then(|v| v.last_mut()) {
            *last = e.clone();
        }
        if let Some((p, private)) = scope.package {
            let table = if private {
                &mut packages[p].private
            } else {
                &mut packages[p].names
            };
            if let Some(last) = table.get_mut(key).and_then(|v| v.last_mut()) {
                *last = e;
            }
        }
    }

    /// All entities a simple name denotes here (innermost first; overloadable
    /// names collect from all levels).
    pub(super) fn lookup(&self, packages: &PVec<Package>, key: &str) -> Vec<Entity> {
        let mut found: Vec<Entity> = Vec::new();
        // The scopes that declare `key` or are a package's, innermost
        // first (the others add nothing).
        let declaring: &[u32] = self.declared_in.get(key).map_or(&[], |v| &v[..]);
        let (mut d, mut p) = (declaring.len(), self.package_scopes.len());
        let candidates = std::iter::from_fn(|| {
            let a = d.checked_sub(1).map(|k| declaring[k]);
            let b = p.checked_sub(1).map(|k| self.package_scopes[k]);
            let next = a.max(b)?;
            if a == Some(next) {
                d -= 1;
            }
            if b == Some(next) {
                p -= 1;
            }
            Some(&self.stack[next as usize])
        });
        for s in candidates {
            crate::work::tick();
            if let Some(es) = s.names.get(key) {
                let overloadable = es
                    .iter()
                    .all(|e| matches!(e, Entity::Func(_) | Entity::EnumLit(..)));
                if !overloadable {
                    if found.is_empty() {
                        return vec![es.last().cloned().expect("nonempty")];
                    }
                    break;
                }
                for e in es.iter().rev() {
                    found.push(e.clone());
                }
            }
            if let Some((p, is_body)) = s.package {
                let pk = &packages[p];
                let spec = (is_body || !s.names.contains_key(key))
                    .then(|| pk.names.get(key))
                    .flatten();
                // A package body sees its spec's private part too.
                let private = is_body.then(|| pk.private.get(key)).flatten();
                for es in [spec, private].into_iter().flatten() {
                    let overloadable = es
                        .iter()
                        .all(|e| matches!(e, Entity::Func(_) | Entity::EnumLit(..)));
                    if !overloadable && found.is_empty() {
                        return vec![es.last().cloned().expect("nonempty")];
                    }
                    found.extend(es.iter().rev().cloned());
                }
            }
        }
        if !found.is_empty() {
            return found;
        }
        // Use-visible declarations of packages (and, for an operator, of
        // the packages of `use type` clauses).
        let op = key.starts_with('"');
        for s in self
            .use_scopes
            .iter()
            .rev()
            .map(|&i| &self.stack[i as usize])
        {
            crate::work::tick();
            let op_uses = if op { &s.op_uses[..] } else { &[] };
            for &p in s
                .uses
                .iter()
                .chain(op_uses.iter().filter(|p| !s.uses.contains(p)))
            {
                if let Some(es) = packages[p].names.get(key) {
                    found.extend(es.iter().cloned());
                }
            }
        }
        // Non-overloadable use-visible names conflict: keep the first.
        if found.len() > 1
            && found
                .iter()
                .any(|e| !matches!(e, Entity::Func(_) | Entity::EnumLit(..)))
        {
            found.truncate(1);
        }
        found
    }

    pub(super) fn visible_names(&self, packages: &PVec<Package>) -> Vec<String> {
        let mut v: Vec<String> = Vec::new();
        for s in &self.stack {
            // (Hidden names begin with a space: no identifier does.)
            v.extend(s.names.keys().filter(|k| !k.starts_with(' ')).cloned());
            for &p in &s.uses {
                v.extend(packages[p].names.keys().cloned());
            }
        }
        v
    }

    /// A visible name close to `key`, as declared, for "did you mean".
    pub(super) fn suggest(&self, packages: &PVec<Package>, key: &str) -> Option<String> {
        let mut best: Option<(usize, String)> = None;
        for n in self.visible_names(packages) {
            let d = edit_distance(key, &n);
            if key.len() > 2
                && d <= 1.max(key.len() / 3)
                && d > 0
                && best.as_ref().is_none_or(|b| d < b.0)
            {
                best = Some((d, n));
            }
        }
        if best.is_none() && key.len() >= 4 {
            // A name cut short (`Error` for `ErrorCode`): the shortest
            // visible name it begins.
            for n in self.visible_names(packages) {
                if n.len() > key.len()
                    && n.len() <= 2 * key.len()
                    && n.starts_with(key)
                    && best
                        .as_ref()
                        .is_none_or(|b| (n.len(), &n) < (b.1.len(), &b.1))
                {
                    best = Some((0, n));
                }
            }
        }
        best.map(|b| self.spelled(&b.1))
    }

    /// A name as it was declared (keys are lower case).
    pub(super) fn spelled(&self, key: &str) -> String {
        self.spelling
            .get(key)
            .cloned()
            .unwrap_or_else(|| key.to_string())
    }

    /// The name and constancy of a variable of the open scopes.
    pub(super) fn var(&self, v: Var) -> Option<(String, bool)> {
        self.var_names.get(&v).cloned()
    }
}

impl Checker {
    pub(super) fn declare(&mut self, name: &str, e: Entity) {
        self.scopes.declare(&mut self.tables.packages, name, e);
    }

    /// Replaces the latest meaning of `key` in the innermost scope (and in
    /// its package's table): an object that an address clause maps.
    pub(super) fn redeclare(&mut self, key: &str, e: Entity) {
        self.scopes.redeclare(&mut self.tables.packages, key, e);
    }

    /// Declares a name, reporting a clash with a non-overloadable name of the
    /// same declarative region.
    pub(super) fn declare_checked(&mut self, id: &ast::Ident, e: Entity) {
        self.index_def(&id.name, id.span, &e, None);
        self.declare_checked_unindexed(id, e);
    }

    /// [`Self::declare_checked`] for a declaration the caller records in
    /// the index itself (a renaming).
    pub(super) fn declare_checked_unindexed(&mut self, id: &ast::Ident, e: Entity) {
        let overloadable = matches!(e, Entity::Func(_) | Entity::EnumLit(..));
        if let Some(prev) = self.scopes.innermost().and_then(|s| s.names.get(&*id.key)) {
            let clash = prev
                .iter()
                .any(|p| !(overloadable && matches!(p, Entity::Func(_) | Entity::EnumLit(..))));
            if clash
                && !matches!(prev.last(), Some(Entity::Type(t)) if matches!(self.tables.types.kind(*t), TypeKind::Incomplete))
            {
                self.err(diagnostics::declared_twice(id.span, &id.name));
            }
        }
        // A name reported "not declared" earlier in this scope (or one
        // inside it): it was used before its declaration.
        let is_func = matches!(e, Entity::Func(_));
        let before = self.scopes.undeclared_here(&id.key);
        for i in before {
            if let Some(d) = self.diags.get_mut(i) {
                *d = diagnostics::used_before_declaration(d.span, &id.name, id.span, is_func);
            }
        }
        self.declare(&id.name, e);
    }

    /// All entities a simple name denotes here (innermost first; overloadable
    /// names collect from all levels).
    pub(super) fn lookup(&self, key: &str) -> Vec<Entity> {
        self.scopes.lookup(&self.tables.packages, key)
    }

    /// A name as it was declared (keys are lower case).
    pub fn spelled(&self, key: &str) -> String {
        self.scopes.spelled(key)
    }
}

pub fn edit_distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().collect();
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for i in 1..=a.len() {
        let mut cur = vec![i; b.len() + 1];
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            cur[j] = (prev[j] + 1).min(cur[j - 1] + 1).min(prev[j - 1] + cost);
        }
        prev = cur;
    }
    prev[b.len()]
}
