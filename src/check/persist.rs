//! Persistent (structurally shared) tables for the checker.
//!
//! The REPL copies its checker before every entry, to roll a refused entry
//! back; with plain `Vec`s and `HashMap`s that copy grew with everything
//! declared so far, and a session of n entries took n² time (issue 35).
//! These tables share their unchanged parts between copies: a copy costs
//! about as much whatever the tables hold, and a change copies one path of
//! a tree of wide nodes.

use imbl::shared_ptr::RcK;
use std::ops::{Deref, DerefMut};

/// A persistent map (`imbl`'s hash array mapped trie).
pub type PMap<K, V> = imbl::GenericHashMap<K, V, std::hash::RandomState, RcK>;

/// A persistent list (`imbl`'s RRB vector), with the few `Vec` methods
/// the checker uses under their `Vec` names.
#[derive(Clone, Debug)]
pub struct PVec<T: Clone>(imbl::GenericVector<T, RcK>);

impl<T: Clone> Default for PVec<T> {
    fn default() -> Self {
        PVec(imbl::GenericVector::new())
    }
}

impl<T: Clone> PVec<T> {
    pub fn new() -> Self {
        Self::default()
    }
    pub fn push(&mut self, v: T) {
        self.0.push_back(v);
    }
    pub fn last(&self) -> Option<&T> {
        self.0.back()
    }
    pub fn last_mut(&mut self) -> Option<&mut T> {
        self.0.back_mut()
    }
    pub fn pop(&mut self) -> Option<T> {
        self.0.pop_back()
    }
}

impl<T: Clone> Deref for PVec<T> {
    type Target = imbl::GenericVector<T, RcK>;
    fn deref(&self) -> &Self::Target {
        &self.0
    }
}

impl<T: Clone> DerefMut for PVec<T> {
    fn deref_mut(&mut self) -> &mut Self::Target {
        &mut self.0
    }
}

impl<T: Clone> FromIterator<T> for PVec<T> {
    fn from_iter<I: IntoIterator<Item = T>>(iter: I) -> Self {
        PVec(iter.into_iter().collect())
    }
}

impl<'a, T: Clone> IntoIterator for &'a PVec<T> {
    type Item = &'a T;
    type IntoIter = imbl::vector::Iter<'a, T, RcK>;
    fn into_iter(self) -> Self::IntoIter {
        self.0.iter()
    }
}
