//! The bytes a run-time value takes, counted by the crate's allocator
//! (`interp::memory::in_use`). This file is its own test binary, with one
//! test, so no other test allocates while it measures.

use adair::interp::memory::in_use;
use adair::interp::{Obj, Value};

/// A list node (`type Node is record V : Integer; Next : Ptr; end
/// record`, made by `new`) is an object and its record, each behind a
/// reference count without a weak count: the record 40 bytes for two
/// components (std's `Rc` took 48, a 64-byte block of the system allocator
/// instead of 48) and the object 24 (std's `Rc<RefCell<Value>>` took 40, a
/// 48-byte block instead of 32).
#[test]
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
