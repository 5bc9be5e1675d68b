//! The value stack: the slots of every frame, one after the other.
//!
//! A call pushes its frame's slots and a return takes them off, hundreds of
//! thousands of times a second in a recursive program. A `Vec<Value>` made
//! that cost a drop of every slot (a call through the drop glue per value)
//! and a fill of every new one. Here the slots above the top stay allocated:
//! taking a frame off drops only the values that own memory (arrays,
//! records, accesses, occurrences) and leaves scalars where they are, and
//! a new frame clears its slots to `Undef` in a loop that knows it writes
//! over scalars only.
//!
//! Invariant: a slot at or above `len` holds `Undef`, an `Int` or a `Real`
//! (written over without the drop glue, see [`overwrite`]).

use super::value::{Value, overwrite};

#[derive(Default, Debug)]
pub struct Stack {
    data: Vec<Value>,
    len: usize,
}

/// Whether a value owns nothing that must be dropped.
#[inline(always)]
fn scalar(v: &Value) -> bool {
    matches!(v, Value::Undef | Value::Int(_) | Value::Real(_))
}

impl Stack {
    #[inline(always)]
    pub fn len(&self) -> usize {
        self.len
    }

    /// Takes the slots from `n` up off the stack.
    #[inline]
    pub fn truncate(&mut self, n: usize) {
        if n >= self.len {
            return;
        }
        for v in &mut self.data[n..self.len] {
            if !scalar(v) {
                *v = Value::Undef;
            }
        }
        self.len = n;
    }

    /// [`Self::truncate`] of slots that hold scalars only (a frame whose
    /// code puts nothing else there, see `vm::Code::scalar`): nothing to
    /// drop, nothing to look at.
    #[inline(always)]
    pub fn truncate_scalars(&mut self, n: usize) {
        debug_assert!(
            self.data[n.min(self.len)..self.len].iter().all(scalar),
            "a frame freed as scalars holds a value that owns memory"
        );
        self.len = self.len.min(n);
    }

    /// Grows the stack to `n` slots, the new ones `Undef`.
    #[inline]
    pub fn grow_to(&mut self, n: usize) {
        self.grow_to_clearing(n, n);
    }

    /// Grows the stack to `n` slots, of which those below `clear` are
    /// `Undef` and the others whatever scalar they held (a frame's
    /// temporaries, which its code writes before it reads them).
    #[inline]
    pub fn grow_to_clearing(&mut self, clear: usize, n: usize) {
        if n <= self.len {
            return;
        }
        let reuse = clear.min(self.data.len()).max(self.len);
        for v in &mut self.data[self.len..reuse] {
            // A scalar (the invariant): nothing to drop, so a plain store.
            // (Were the invariant broken, a value would leak, no more.)
            debug_assert!(scalar(v));
            std::mem::forget(std::mem::replace(v, Value::Undef));
        }
        if n > self.data.len() {
            self.data.resize(n, Value::Undef);
        }
        self.len = n;
    }

    /// Opens a frame of `size` slots on top whose first slot is the
    /// integer `n` (a call's one argument), slots `1 .. own` `Undef` and
    /// the others (temporaries) whatever scalar they held: what
    /// [`Self::push_int`] then [`Self::grow_to_clearing`] make, in one
    /// pass over the frame.
    #[inline(always)]
    pub fn open_frame_int(&mut self, n: i64, own: usize, size: usize) {
        // (The argument is one of the frame's own slots.)
        debug_assert!(own >= 1 && size >= own);
        let base = self.len;
        let top = base + size;
        if top > self.data.len() {
            self.data.resize(top, Value::Undef);
        }
        let frame = &mut self.data[base..top];
        // Slots at or above the top hold scalars (the invariant): nothing
        // to drop, so plain stores.
        std::mem::forget(std::mem::replace(&mut frame[0], Value::Int(n)));
        if own > 1 {
            for v in &mut frame[1..own.min(size)] {
                debug_assert!(scalar(v));
                std::mem::forget(std::mem::replace(v, Value::Undef));
            }
        }
        self.len = top;
    }

    #[inline]
    pub fn push(&mut self, x: Value) {
        if self.len < self.data.len() {
            overwrite(&mut self.data[self.len], x);
        } else {
            self.data.push(x);
        }
        self.len += 1;
    }

    /// `push` of an integer, stored in place (a `Value` built first and
    /// copied went through memory, a store-forwarding stall per argument).
    #[inline]
    pub fn push_int(&mut self, n: i64) {
        if self.len < self.data.len() {
            match &mut self.data[self.len] {
                Value::Int(y) => *y = n,
                // A scalar (the invariant): nothing to drop.
                s => std::mem::forget(std::mem::replace(s, Value::Int(n))),
            }
        } else {
            self.data.push(Value::Int(n));
        }
        self.len += 1;
    }

    pub fn get(&self, i: usize) -> Option<&Value> {
        self.data[..self.len].get(i)
    }

    /// The live slots.
    pub fn as_slice(&self) -> &[Value] {
        &self.data[..self.len]
    }

    pub fn as_mut_slice(&mut self) -> &mut [Value] {
        &mut self.data[..self.len]
    }

    /// The live slots as a vector.
    pub fn into_vec(mut self) -> Vec<Value> {
        self.data.truncate(self.len);
        self.data
    }
}

impl From<Vec<Value>> for Stack {
    fn from(data: Vec<Value>) -> Stack {
        Stack {
            len: data.len(),
            data,
        }
    }
}

impl std::ops::Index<usize> for Stack {
    type Output = Value;
    #[inline(always)]
    fn index(&self, i: usize) -> &Value {
        debug_assert!(i < self.len, "slot {i} above the stack's top {}", self.len);
        &self.data[i]
    }
}

impl std::ops::IndexMut<usize> for Stack {
    #[inline(always)]
    fn index_mut(&mut self, i: usize) -> &mut Value {
        debug_assert!(i < self.len, "slot {i} above the stack's top {}", self.len);
        &mut self.data[i]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_frame_taken_off_drops_what_it_owns_and_a_new_one_is_undef() {
        let shared = super::super::value::Array::string("ab");
        let mut s = Stack::default();
        s.grow_to(1);
        s.push(Value::Arr(shared.clone()));
        s.push(Value::Int(7));
        s.push(Value::Real(1.5));
        assert_eq!(shared.ref_count(), 2);
        s.truncate(1);
        assert_eq!(s.len(), 1);
        // The array went with its frame.
        assert_eq!(shared.ref_count(), 1);
        s.grow_to(4);
        assert!(s.as_slice().iter().all(|v| matches!(v, Value::Undef)));
        assert_eq!(s.get(4), None);
        s.push(Value::Int(3));
        assert_eq!(s.len(), 5);
        assert_eq!(s[4], Value::Int(3));
        // Over slots above the top, then past the end of the storage.
        s.truncate(1);
        s.push_int(9);
        assert_eq!(s[1], Value::Int(9));
        s.truncate(0);
        for k in 0..7 {
            s.push_int(k);
        }
        assert_eq!(s.as_slice(), (0..7).map(Value::Int).collect::<Vec<_>>());
        // A frame of two own slots and two temporaries: the own ones are
        // cleared, the temporaries keep the scalars they held.
        s.truncate(1);
        s.grow_to_clearing(3, 5);
        assert_eq!(s.len(), 5);
        assert_eq!(
            s.as_slice(),
            [
                Value::Int(0),
                Value::Undef,
                Value::Undef,
                Value::Int(3),
                Value::Int(4)
            ]
        );
    }
}
