//! The path memory: a path holds at most `PosNo'Last` positions and all
//! paths together at most `MAX_TOTAL_POSITIONS`; past either, the memory
//! refuses and nothing changes. The positions' list against a plain vector
//! under random inserts and deletes; a path file with too many positions.
//! (`PathMemOverflow` raised in a program: tests/services/path_memory.rs.)

use crate::services::paths::{Frame, MAX_POSITIONS, MAX_TOTAL_POSITIONS, PathMem, Positions};
use proptest::prelude::*;

fn frame(x: f64) -> Frame {
    [
        [1.0, 0.0, 0.0, x],
        [0.0, 1.0, 0.0, 0.0],
        [0.0, 0.0, 1.0, 0.0],
    ]
}

proptest! {
    #[test]
    fn positions_behave_like_a_vector(
        ops in proptest::collection::vec((0u8..3, 0usize..3000), 1..4000)
    ) {
        let mut model: Vec<Frame> = Vec::new();
        let mut p = Positions::default();
        for (k, (op, at)) in ops.into_iter().enumerate() {
            match op {
                // Inserts twice as often as deletes, so blocks split.
                0 | 1 => {
                    let i = at.min(model.len());
                    model.insert(i, frame(k as f64));
                    p.insert(at, frame(k as f64));
                }
                _ if !model.is_empty() => {
                    let i = at % model.len();
                    prop_assert_eq!(model.remove(i), p.remove(i));
                }
                _ => {}
            }
            prop_assert_eq!(p.len(), model.len());
        }
        prop_assert!(p.iter().eq(model.iter()));
        for (i, f) in model.iter().enumerate() {
            prop_assert_eq!(p.get(i), Some(f));
        }
        prop_assert_eq!(p.get(model.len()), None);
    }
}

#[test]
fn the_memory_refuses_past_either_limit_and_changes_nothing() {
    let mut m = PathMem::default();
    m.create(1);
    for i in 0..MAX_POSITIONS {
        assert_eq!(m.insert(1, 0, frame(i as f64)), Ok(0));
    }
    let e = m.insert(1, 0, frame(-1.0)).unwrap_err();
    assert!(e.contains("is full: it holds 65000 positions"), "{e}");
    assert_eq!(m.get(&1).unwrap().len(), MAX_POSITIONS);
    assert_eq!(
        m.get(&1).unwrap().get(0),
        Some(&frame((MAX_POSITIONS - 1) as f64))
    );
    // The other paths fill the rest of the memory.
    let mut p = 2;
    while m.total() < MAX_TOTAL_POSITIONS {
        let len = m.get(&p).map_or(0, Positions::len);
        if len == MAX_POSITIONS {
            p += 1;
        }
        m.insert(p, usize::MAX, frame(0.0)).unwrap();
    }
    m.create(p + 1);
    let e = m.insert(p + 1, 0, frame(0.0)).unwrap_err();
    assert!(e.contains("over all paths"), "{e}");
    assert_eq!(m.total(), MAX_TOTAL_POSITIONS);
    assert_eq!(m.get(&(p + 1)).unwrap().len(), 0);
    let e = m.load(vec![(p + 2, vec![frame(0.0)])]).unwrap_err();
    assert!(e.contains("over all paths"), "{e}");
    assert!(!m.contains_key(&(p + 2)));
    // Deleting makes room again.
    m.delete(1, 0);
    assert_eq!(m.total(), MAX_TOTAL_POSITIONS - 1);
    assert_eq!(m.insert(p + 1, 0, frame(0.0)), Ok(0));
    m.remove(&(p + 1));
    assert_eq!(m.total(), MAX_TOTAL_POSITIONS - 1);
}

#[test]
fn a_path_file_with_more_than_pos_no_last_positions_is_a_data_error() {
    let pos = " 1 0 0 0 0 1 0 0 0 0 1 0";
    let mut text = String::from("adair-paths 1\npath 1\n");
    for k in 1..=MAX_POSITIONS + 1 {
        text.push_str(&format!("pos {k}{pos}\n"));
    }
    text.push_str("end\n");
    let (line, msg) = crate::services::paths::parse(&text).unwrap_err();
    assert_eq!(line, MAX_POSITIONS + 3);
    assert!(
        msg.contains("position 65001 is outside PosNo 1 .. 65000"),
        "{msg}"
    );
}
