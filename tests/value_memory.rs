//! The bytes a run-time value takes, counted by the crate's allocator
//! (`interp::memory::in_use`). This file is its own test binary, with one
//! test, so no other test allocates while it measures.

use adair::interp::memory::in_use;
use adair::interp::{Array, Obj, Value};

/// The measures one after the other (one test: see above).
#[test]
fn values_take_what_they_should() {
    a_list_node_takes_64_bytes();
    a_copied_array_is_one_allocation();
}

/// A list node (`type Node is record V : Integer; Next : Ptr; end
/// record`, made by `new`) is an object and its record, each behind a
/// reference count without a weak count: the record 40 bytes for two
/// components (std's `Rc` took 48, a 64-byte block of the system allocator
/// instead of 48) and the object 24 (std's `Rc<RefCell<Value>>` took 40, a
/// 48-byte block instead of 32).
fn a_list_node_takes_64_bytes() {
    const N: usize = 10_000;
    let mut head = Value::Ptr(None);
    let before = in_use();
    for i in 0..N {
        head = Value::Ptr(Some(Obj::new(Value::record(smallvec::smallvec![
            Value::Int(i as i64),
            head,
        ]))));
    }
    let per_node = (in_use() - before) / N;
    drop(head);
    assert_eq!(per_node, 64, "bytes per list node");
}

/// An array value is a pointer to one block holding its reference count,
/// bounds and components; copying it on write is that one allocation: a
/// `String (1 .. 4)` 48 bytes (it was a 72-byte `Rc` box), a 40-character
/// one 80 (it was 72 and a second allocation of 40), three integers 64
/// (it was 72 and 24).
fn a_copied_array_is_one_allocation() {
    assert_eq!(std::mem::size_of::<Array>(), 8, "an array value's size");
    const N: usize = 1_000;
    let long = "x".repeat(40);
    let ints = [Value::Int(1000), Value::Int(-1), Value::Int(7)];
    let cases: [(&str, Array, usize); 3] = [
        ("String (1 .. 4)", Array::string("ABCD"), 48),
        ("String (1 .. 40)", Array::string(&long), 80),
        ("three integers", Array::from_vals(ints.to_vec()), 64),
    ];
    for (what, original, bytes) in cases {
        let mut copies = Vec::with_capacity(N);
        let before = in_use();
        for _ in 0..N {
            let mut c = original.clone();
            c.set(0, Value::Int(65));
            copies.push(c);
        }
        let per_copy = (in_use() - before) / N;
        assert!(copies.iter().all(|c| !c.same_block(&original)));
        drop(copies);
        assert_eq!(per_copy, bytes, "bytes per copy of a {what}");
    }
}
