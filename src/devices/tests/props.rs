//! Random runs of a busy cell.

use super::*;

// ----------------------------------------------------------------- property

const BUSY_CELL: &str = r#"
[[device]]
name = "belt"
kind = "conveyor"
motor = 0o350
length = 100.0
speed = 50.0
end = [10.0, 20.0, 30.0]

[[device]]
name = "exit"
kind = "light-barrier"
on = "belt"
input = 0o352
interrupt = 0o354

[[device]]
name = "parallel"
kind = "parallel"
interrupt = 0o340
input = 0o342
output = 0o344
control = 0o346

[[event]]
at = 0.0
device = "belt"
object = { name = "a", width = 30.0 }

[[event]]
at = 0.0
device = "belt"
object = { name = "b", width = 10.0 }

[[event]]
at = 0.7
device = "belt"
object = { name = "c", width = 45.5 }

[[event]]
at = 0.7
device = "parallel"
input = 3
interrupt = true

[[event]]
at = 1.3
device = "belt"
object = { name = "d", width = 0.1 }

[[event]]
at = 2.9
device = "belt"
object = { name = "e", width = 12.0 }
"#;

/// What must hold whatever the program and the gripper do.
fn check_invariants(w: &World) {
    let mut on: Vec<(f64, bool, f64)> = w
        .objects()
        .into_iter()
        .filter_map(|o| match o.place {
            Place::OnBelt {
                position, at_end, ..
            } => Some((position, at_end, o.width)),
            _ => None,
        })
        .collect();
    on.sort_by(|a, b| b.0.total_cmp(&a.0));
    for pair in on.windows(2) {
        let gap = pair[0].0 - pair[1].0;
        let need = (pair[0].2 + pair[1].2) / 2.0;
        assert!(gap >= need - 1e-9, "overlap: {on:?}");
        assert!(!pair[1].1, "only the front object is at the end: {on:?}");
    }
    let front_at_end = on.first().is_some_and(|f| f.1);
    if let Some(f) = on.first() {
        assert!(f.0 <= 100.0);
        assert_eq!(f.1, f.0 == 100.0, "at the end exactly when there: {on:?}");
    }
    assert_eq!(w.read(0o352), Some(u16::from(front_at_end)), "the beam");
    if let Some(t) = w.next_wakeup(w.now()) {
        assert!(t >= w.now());
    }
    if let Some(o) = w.object_at([10.0, 20.0, 30.0], GRIP_TOLERANCE_MM) {
        assert_ne!(o.place, Place::Held);
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig { cases: 256, ..Default::default() })]
    #[test]
    fn random_runs_keep_the_world_consistent(
        ops in proptest::collection::vec((0u8..9, 0.0f64..1.0), 1..60)
    ) {
        let mut w = world(BUSY_CELL);
        let mut delivered = 0u64;
        for (op, x) in ops {
            let before = w.now();
            let irq = match op {
                0 => w.advance_to(before + 2.0 * x),
                1 => match w.next_wakeup(before) {
                    Some(t) => w.advance_to(t),
                    None => Vec::new(),
                },
                2 => {
                    w.write(0o350, u16::from(x > 0.3)).unwrap();
                    Vec::new()
                }
                3 => {
                    if let Some(o) = w.object_at([10.0, 20.0, 30.0], GRIP_TOLERANCE_MM) {
                        w.pick(&o.name).unwrap();
                    }
                    Vec::new()
                }
                4 => {
                    let names = ["a", "b", "c", "d", "e"];
                    let _ = w.pick(names[(x * 5.0) as usize]);
                    Vec::new()
                }
                5 => {
                    let held: Vec<String> = w
                        .objects()
                        .into_iter()
                        .filter(|o| o.place == Place::Held)
                        .map(|o| o.name)
                        .collect();
                    if let Some(n) = held.first() {
                        w.put_down(n, [10.0 + x, 20.0, 30.0]).unwrap();
                    }
                    Vec::new()
                }
                6 => {
                    w.write(0o346, u16::from(x > 0.5)).unwrap();
                    Vec::new()
                }
                7 => w.raise_interrupt(0o340).unwrap().into_iter().collect(),
                _ => {
                    w.set_input(0o342, (x * 65535.0) as u16).unwrap();
                    Vec::new()
                }
            };
            let mut last = before;
            for i in &irq {
                assert!(i.time >= last && i.time <= w.now(), "{irq:?} in {before} .. {}", w.now());
                last = i.time;
            }
            delivered += irq.len() as u64;
            check_invariants(&w);
        }
        assert_eq!(w.delivered(0o340) + w.delivered(0o354), delivered);
    }
}
