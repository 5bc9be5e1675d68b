//! The device world: events, interrupts, belts, the gripper, what it shows.

use super::*;

// ------------------------------------------------------- events, interrupts

#[test]
fn events_happen_in_time_order_at_their_exact_times() {
    let mut w = world(&format!(
        r#"{PARALLEL_ONLY}
[[event]]
at = 2.0
device = "parallel"
interrupt = true

[[event]]
at = 0.5
device = "parallel"
input = 0x0001

[[event]]
at = 0.5
device = "parallel"
input = 0x0002
interrupt = true
"#
    ));
    w.write(0o346, 1).unwrap();
    assert_eq!(w.next_wakeup(0.0), Some(0.5));
    assert!(w.advance_to(0.4).is_empty());
    assert_eq!(w.read(0o342), Some(0), "nothing before its time");
    let irq = w.advance_to(0.5);
    assert_eq!(
        irq,
        [Interrupt {
            time: 0.5,
            address: 0o340,
            device: 0
        }]
    );
    assert_eq!(
        w.read(0o342),
        Some(2),
        "same time: file order, the later wins"
    );
    assert_eq!(w.next_wakeup(0.5), Some(2.0));
    let irq = w.advance_to(10.0);
    assert_eq!(irq.len(), 1);
    assert_eq!(irq[0].time, 2.0, "its own time, not the time advanced to");
    assert_eq!(w.now(), 10.0);
    assert_eq!(w.next_wakeup(10.0), None);
    assert_eq!(w.delivered(0o340), 2);
}

#[test]
fn events_at_zero_wait_for_the_first_advance() {
    let mut w = world(&format!(
        "{PARALLEL_ONLY}[[event]]\nat = 0\ndevice = \"parallel\"\ninput = 7\n"
    ));
    assert_eq!(w.read(0o342), Some(0));
    assert_eq!(w.next_wakeup(0.0), Some(0.0));
    w.advance_to(0.0);
    assert_eq!(w.read(0o342), Some(7));
    assert_eq!(w.next_wakeup(0.0), None);
}

#[test]
fn the_clock_never_goes_back() {
    let mut w = world(PARALLEL);
    w.advance_to(1.0);
    assert!(w.advance_to(0.2).is_empty());
    assert!(w.advance_to(f64::NAN).is_empty());
    assert_eq!(w.now(), 1.0);
}

#[test]
fn interrupts_while_disabled_are_dropped_and_counted() {
    let mut w = world(PARALLEL);
    assert_eq!(w.read(0o346), Some(0), "interrupts start disabled");
    assert!(
        w.advance_to(1.0).is_empty(),
        "the event's interrupt is dropped"
    );
    assert_eq!(w.read(0o342), Some(0x00FF), "but its input is set");
    assert_eq!((w.dropped(0o340), w.delivered(0o340)), (1, 0));

    w.write(0o346, 1).unwrap();
    let i = w.raise_interrupt(0o340).unwrap();
    assert_eq!(
        i,
        Some(Interrupt {
            time: 1.0,
            address: 0o340,
            device: 0
        })
    );
    assert_eq!((w.dropped(0o340), w.delivered(0o340)), (1, 1));

    // Only bit 0 enables.
    w.write(0o346, 0xFFFE).unwrap();
    assert_eq!(w.raise_interrupt(0o340).unwrap(), None);
    assert_eq!(w.raise_interrupt(0o340).unwrap(), None);
    assert_eq!((w.dropped(0o340), w.delivered(0o340)), (3, 1));
    assert_eq!(w.dropped(0o342), 0);
}

#[test]
fn registers_refuse_what_they_cannot_take() {
    let mut w = world(PARALLEL_ONLY);
    w.write(0o344, 0xBEEF).unwrap();
    assert_eq!(w.read(0o344), Some(0xBEEF), "an output reads back");
    assert!(matches!(
        w.write(0o342, 5),
        Err(DeviceError::ReadOnly { address: 0o342, .. })
    ));
    assert_eq!(w.read(0o342), Some(0), "a refused write changes nothing");
    assert!(matches!(
        w.write(0o340, 1),
        Err(DeviceError::NotARegister { .. })
    ));
    assert_eq!(w.write(0o360, 1), Err(DeviceError::NoDevice(0o360)));
    assert_eq!(w.read(0o360), None);
    assert!(matches!(
        w.raise_interrupt(0o342),
        Err(DeviceError::NotAnInterrupt { .. })
    ));
    assert!(matches!(
        w.set_input(0o344, 1),
        Err(DeviceError::NotAnInput { .. })
    ));
    assert_eq!(w.set_input(0o342, 0x1234), Ok(None));
    assert_eq!(w.read(0o342), Some(0x1234));
    assert_eq!(
        w.write(0o342, 5).unwrap_err().to_string(),
        "8#342# is the input register of `parallel`: it is set from outside, not written"
    );
}

#[test]
fn a_standalone_light_barrier_interrupts_on_the_rising_edge_only() {
    let mut w = world(
        r#"
[[device]]
name = "gate"
kind = "light-barrier"
input = 0o360
interrupt = 0o362

[[event]]
at = 1
device = "gate"
input = 1

[[event]]
at = 2
device = "gate"
input = 1

[[event]]
at = 3
device = "gate"
input = 0
"#,
    );
    let irq = w.advance_to(5.0);
    assert_eq!(
        irq,
        [Interrupt {
            time: 1.0,
            address: 0o362,
            device: 0
        }]
    );
    assert_eq!(w.read(0o360), Some(0));
    assert!(w.set_input(0o360, 1).unwrap().is_some(), "rising edge");
    assert!(w.set_input(0o360, 1).unwrap().is_none(), "already broken");
    assert!(w.set_input(0o360, 0).unwrap().is_none(), "falling edge");
    assert_eq!(
        w.set_input(0o360, 2),
        Err(DeviceError::OutOfRange {
            address: 0o360,
            value: 2,
            max: 1
        })
    );
    assert_eq!(w.delivered(0o362), 2);
    assert_eq!(w.dropped(0o362), 0, "a light barrier is always enabled");
}

// --------------------------------------------------------------------- belt

#[test]
fn an_object_reaches_the_end_when_its_centre_does() {
    let mut w = running_cell();
    assert_eq!(w.next_wakeup(0.0), Some(1.0), "the event puts box1 on");
    assert!(w.advance_to(1.0).is_empty());
    assert_eq!(on_belt(&w, "box1"), (0.0, false));
    assert_eq!(w.next_wakeup(1.0), Some(6.0), "500 mm at 100 mm/s");
    assert!(w.advance_to(5.99).is_empty());
    assert_eq!(w.read(0o352), Some(0));
    let irq = w.advance_to(6.0);
    assert_eq!(
        irq,
        [Interrupt {
            time: 6.0,
            address: 0o354,
            device: 1
        }]
    );
    assert_eq!(w.read(0o352), Some(1), "the beam is broken");
    assert_eq!(on_belt(&w, "box1"), (500.0, true));
    assert!(w.advance_to(100.0).is_empty(), "it stays at the end");
    assert_eq!(on_belt(&w, "box1"), (500.0, true));
    assert_eq!(w.next_wakeup(100.0), None);
}

#[test]
fn the_arrival_is_exact_however_the_clock_is_stepped() {
    let mut w = running_cell();
    let mut irq = Vec::new();
    let mut t = 0.0;
    while t < 7.0 {
        t += 0.1; // not exact in binary
        irq.extend(w.advance_to(t));
    }
    assert_eq!(irq.len(), 1);
    assert_eq!(irq[0].time, 6.0);
    assert_eq!(on_belt(&w, "box1"), (500.0, true));
}

#[test]
fn a_stopped_belt_keeps_its_object_and_resumes() {
    let mut w = world(CELL);
    w.advance_to(1.0);
    assert_eq!(w.next_wakeup(1.0), None, "the motor is off: nothing moves");
    w.advance_to(2.0);
    assert_eq!(on_belt(&w, "box1"), (0.0, false));
    w.write(0o350, 1).unwrap();
    assert_eq!(w.next_wakeup(2.0), Some(7.0));
    w.advance_to(4.0);
    assert_eq!(on_belt(&w, "box1"), (200.0, false));
    w.write(0o350, 0).unwrap();
    assert_eq!(w.next_wakeup(4.0), None);
    w.advance_to(9.0);
    assert_eq!(on_belt(&w, "box1"), (200.0, false), "half-way, stopped");
    // Other bits than bit 0 do not run it.
    w.write(0o350, 0xFFFE).unwrap();
    assert_eq!(w.next_wakeup(9.0), None);
    w.write(0o350, 1).unwrap();
    assert_eq!(w.read(0o350), Some(1));
    assert_eq!(w.next_wakeup(9.0), Some(12.0), "the remaining 300 mm");
    assert!(w.advance_to(11.999).is_empty());
    let irq = w.advance_to(12.0);
    assert_eq!(irq.len(), 1);
    assert_eq!(irq[0].time, 12.0);
}

#[test]
fn an_arrival_is_exactly_at_the_end_even_when_the_division_rounds() {
    // 333 mm at 100 mm/s from t = 1.1: 100 * ((1.1 + 3.33) - 1.1) is
    // 332.99999999999994 in binary; the object must still stop at 333.
    let mut w = world(
        r#"
[[device]]
name = "belt"
kind = "conveyor"
motor = 1
length = 333
speed = 100
end = [0, 0, 0]

[[event]]
at = 1.1
device = "belt"
object = { name = "b", width = 10 }
"#,
    );
    w.write(1, 1).unwrap();
    w.advance_to(1.1);
    let t = w.next_wakeup(1.1).unwrap();
    w.advance_to(t);
    assert_eq!(on_belt(&w, "b"), (333.0, true));
    w.advance_to(t + 1.0);
    assert_eq!(on_belt(&w, "b"), (333.0, true));
}

#[test]
fn something_overdue_wakes_at_once() {
    let w = world(PARALLEL);
    assert_eq!(w.next_wakeup(0.0), Some(0.5));
    assert_eq!(w.next_wakeup(0.7), Some(0.7), "due before 0.7: wake at 0.7");
}

#[test]
fn a_light_barrier_on_a_belt_follows_the_objects() {
    let mut w = world(CELL);
    assert_eq!(
        w.set_input(0o352, 1),
        Err(DeviceError::FollowsBelt {
            address: 0o352,
            barrier: "exit".into(),
            belt: "belt".into()
        })
    );
    assert_eq!(w.read(0o352), Some(0));
    let e = Devices::from_toml(
        &format!("{CELL}\n[[event]]\nat = 2\ndevice = \"exit\"\ninput = 1\n"),
        "cell.toml",
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        "cell.toml:24:9: error: an event on light-barrier `exit` cannot have `input`: \
         its beam follows the objects on `belt`"
    );
}

#[test]
fn the_beam_interrupts_once_and_the_next_object_queues_behind() {
    // box1 (30 mm) at 1.0, box2 (20 mm) and box3 (10 mm) at 1.0 too: each
    // waits behind the one before it, centre to centre at the half widths.
    let mut w = world(&format!("{CELL}{TWO_BOXES}"));
    w.write(0o350, 1).unwrap();
    w.advance_to(1.0);
    assert_eq!(on_belt(&w, "box2").0, -25.0);
    assert_eq!(on_belt(&w, "box3").0, -40.0);
    let irq = w.advance_to(60.0);
    assert_eq!(irq.len(), 1, "one rising edge: {irq:?}");
    assert_eq!(irq[0].time, 6.0);
    assert_eq!(on_belt(&w, "box1"), (500.0, true));
    assert_eq!(on_belt(&w, "box2"), (475.0, false));
    assert_eq!(on_belt(&w, "box3"), (460.0, false));
    assert_eq!(w.next_wakeup(60.0), None, "the end is taken");

    // Picking box1 clears the beam; box2 moves up its 25 mm.
    w.pick("box1").unwrap();
    assert_eq!(w.read(0o352), Some(0));
    assert_eq!(w.next_wakeup(60.0), Some(60.25));
    let irq = w.advance_to(61.0);
    assert_eq!(irq.len(), 1);
    assert_eq!(irq[0].time, 60.25);
    assert_eq!(on_belt(&w, "box2"), (500.0, true));
    assert_eq!(on_belt(&w, "box3"), (485.0, false));
    assert_eq!(w.read(0o352), Some(1));
    assert_eq!(w.delivered(0o354), 2);
}

#[test]
fn an_arrival_comes_before_an_event_of_the_same_instant() {
    let mut w = world(&format!(
        "{CELL}{}[[event]]\nat = 6.0\ndevice = \"parallel\"\ninterrupt = true\n",
        PARALLEL_ONLY
    ));
    w.write(0o350, 1).unwrap();
    w.write(0o346, 1).unwrap();
    let irq = w.advance_to(6.0);
    let order: Vec<(f64, Address)> = irq.iter().map(|i| (i.time, i.address)).collect();
    assert_eq!(order, [(6.0, 0o354), (6.0, 0o340)]);
}

// ------------------------------------------------------------------ gripper

#[test]
fn picking_from_the_end_clears_the_beam_at_that_moment() {
    let mut w = running_cell();
    w.advance_to(8.0);
    assert_eq!(w.read(0o352), Some(1));
    let found = w
        .object_at([250.0, 250.0, 30.0], GRIP_TOLERANCE_MM)
        .expect("at the end");
    assert_eq!(found.name, "box1");
    assert_eq!(found.centre, Some([250.0, 250.0, 30.0]));
    let was = w.pick("box1").unwrap();
    assert!(matches!(was.place, Place::OnBelt { at_end: true, .. }));
    assert_eq!(was.width, 30.0);
    assert_eq!(
        w.read(0o352),
        Some(0),
        "cleared when the jaws close, not later"
    );
    assert_eq!(position(&w, "box1"), Place::Held);
    assert_eq!(w.object_at([250.0, 250.0, 30.0], 5.0), None);
    assert_eq!(w.pick("box1"), Err(DeviceError::AlreadyHeld("box1".into())));
    assert!(
        w.advance_to(20.0).is_empty(),
        "a falling edge does not interrupt"
    );

    w.put_down("box1", [100.0, -50.0, 10.0]).unwrap();
    assert_eq!(position(&w, "box1"), Place::At([100.0, -50.0, 10.0]));
    assert_eq!(w.read(0o352), Some(0), "put down off the belt");
    assert_eq!(
        w.object_at([103.0, -46.0, 10.0], 5.0).map(|o| o.name),
        Some("box1".into())
    );
    assert_eq!(
        w.put_down("box1", [0.0; 3]),
        Err(DeviceError::NotHeld("box1".into()))
    );
    assert_eq!(
        w.pick("box9"),
        Err(DeviceError::UnknownObject("box9".into()))
    );
    w.pick("box1").unwrap();
}

#[test]
fn the_gripper_reaches_5_mm_and_only_objects_at_rest() {
    let mut w = running_cell();
    w.advance_to(3.0);
    assert_eq!(
        w.object_at([250.0, 250.0, 30.0], 1000.0),
        None,
        "on the way: not where the gripper can reach it"
    );
    w.advance_to(6.0);
    assert!(
        w.object_at([255.0, 250.0, 30.0], GRIP_TOLERANCE_MM)
            .is_some()
    );
    assert!(
        w.object_at([255.01, 250.0, 30.0], GRIP_TOLERANCE_MM)
            .is_none()
    );
    assert!(
        w.object_at([250.0, 250.0, 35.5], GRIP_TOLERANCE_MM)
            .is_none()
    );
}

// ------------------------------------------------------------------ display

#[test]
fn describe_shows_registers_objects_and_counts() {
    let mut w = world(&format!("{CELL}{PARALLEL_ONLY}"));
    w.write(0o350, 1).unwrap();
    w.raise_interrupt(0o340).unwrap();
    w.advance_to(3.0);
    let s = w.to_string();
    assert_eq!(
        s,
        "devices of test.toml at t = 3.000 s
belt (conveyor, 500 mm at 100 mm/s, end at (250.0, 250.0, 30.0) mm)
  8#350#   motor      16#0001# (running)
  box1 (30 mm) at 200.0 mm
exit (light barrier at the end of belt)
  8#354#   interrupt  always enabled, rising edge; 0 delivered, 0 dropped
  8#352#   input      0 (beam clear)
parallel (parallel)
  8#340#   interrupt  disabled; 0 delivered, 1 dropped
  8#342#   input      16#0000#
  8#344#   output     16#0000#
  8#346#   control    16#0000# (interrupts disabled)
"
    );
    assert_eq!(
        w.trace_line(),
        "[t=    3.000 s] devices: belt motor=16#0001# box1@200.0; exit beam=0; \
         parallel in=16#0000# out=16#0000# ctl=16#0000# dropped=1"
    );
    w.advance_to(6.0);
    w.pick("box1").unwrap();
    assert!(w.to_string().contains("box1 (30 mm) in the gripper\n"));
    assert!(w.trace_line().ends_with("; box1 held"));
}

#[test]
fn the_log_tells_what_happened_in_order() {
    let mut w = running_cell();
    w.set_logging(true);
    w.advance_to(6.0);
    w.pick("box1").unwrap();
    let lines: Vec<String> = w.take_log().iter().map(|h| h.to_string()).collect();
    assert_eq!(
        lines,
        [
            "[t=    1.000 s] devices: belt: box1 put on the start",
            "[t=    6.000 s] devices: belt: box1 reaches the end",
            "[t=    6.000 s] devices: exit: beam broken",
            "[t=    6.000 s] devices: exit: interrupt 8#354# delivered",
            "[t=    6.000 s] devices: exit: beam clear",
            "[t=    6.000 s] devices: gripper: box1 picked",
        ]
    );
    assert!(w.take_log().is_empty(), "taken");
}
