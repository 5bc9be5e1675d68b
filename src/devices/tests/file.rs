//! The device file: the spec's examples, addresses, every refusal.

use super::*;

// ------------------------------------------------------------------ file

#[test]
fn the_spec_parallel_example_parses() {
    let d = parse(PARALLEL);
    assert_eq!(d.source(), "test.toml");
    assert_eq!(d.devices().len(), 1);
    assert_eq!(d.devices()[0].name, "parallel");
    assert_eq!(
        d.devices()[0].kind,
        DeviceKind::Parallel {
            interrupt: 0o340,
            input: 0o342,
            output: 0o344,
            control: 0o346
        }
    );
    assert_eq!(
        d.events(),
        &[Event {
            at: 0.5,
            device: 0,
            input: Some(0x00FF),
            object: None,
            interrupt: true,
            line: 9,
        }]
    );
    // The example is the default set, plus its event.
    let default = Devices::default_set();
    assert_eq!(d.devices()[0].kind, default.devices()[0].kind);
    assert_eq!(d.devices()[0].name, default.devices()[0].name);
}

#[test]
fn the_spec_cell_example_parses() {
    let d = parse(CELL);
    let names: Vec<&str> = d.devices().iter().map(|d| d.name.as_str()).collect();
    assert_eq!(names, ["belt", "exit"]);
    assert_eq!(
        d.devices()[0].kind,
        DeviceKind::Conveyor {
            motor: 0o350,
            length: 500.0,
            speed: 100.0,
            end: [250.0, 250.0, 30.0]
        }
    );
    assert_eq!(
        d.devices()[1].kind,
        DeviceKind::LightBarrier {
            on: Some(0),
            input: 0o352,
            interrupt: Some(0o354)
        }
    );
    assert_eq!(d.devices()[1].line, 9);
    let e = &d.events()[0];
    assert_eq!((e.at, e.device, e.line), (1.0, 0, 16));
    assert_eq!(
        e.object,
        Some(ObjectSpec {
            name: "box1".into(),
            width: 30.0
        })
    );
    assert_eq!(d.lookup(0o354), Some((1, Role::Interrupt)));
    assert_eq!(d.lookup(0o352), Some((1, Role::Input)));
    assert_eq!(d.lookup(0o350), Some((0, Role::Motor)));
    assert_eq!(d.lookup(0o340), None, "the file replaces the default set");
}

#[test]
fn addresses_may_be_octal_hex_binary_or_decimal() {
    let d = parse(
        r#"
[[device]]
name = "p"
kind = "parallel"
interrupt = 0o340
input = 0xE2
output = 228
control = 0b11100110
"#,
    );
    assert_eq!(
        d.addresses().collect::<Vec<_>>(),
        [
            (0o340, 0, Role::Interrupt),
            (0o342, 0, Role::Input),
            (0o344, 0, Role::Output),
            (0o346, 0, Role::Control),
        ]
    );
}

#[test]
fn the_default_set_is_the_appendix_c_port() {
    let d = Devices::default_set();
    assert_eq!(d.source(), "the default device set");
    assert!(d.events().is_empty());
    assert_eq!(d.lookup(0o340), Some((0, Role::Interrupt)));
    assert_eq!(d.lookup(0o342), Some((0, Role::Input)));
    assert_eq!(d.lookup(0o344), Some((0, Role::Output)));
    assert_eq!(d.lookup(0o346), Some((0, Role::Control)));
    assert_eq!(d.addresses().count(), 4);
    assert!(d.is_interrupt(0o340) && !d.is_interrupt(0o346));
    let w = World::new(d);
    assert!(w.is_interrupt(0o340));
    assert!(!w.is_interrupt(0o342));
    assert_eq!(w.read(0o340), None, "an interrupt is not a register");
    for a in [0o342, 0o344, 0o346] {
        assert_eq!(w.read(a), Some(0));
    }
    assert_eq!(w.next_wakeup(0.0), None);
}

/// Each bad file is one error at the line and column of the problem.
#[test]
fn a_bad_file_is_one_error_at_its_line() {
    let conveyor = "[[device]]\nname = \"belt\"\nkind = \"conveyor\"\nmotor = 0o350\n";
    let belt = format!("{conveyor}length = 500.0\nspeed = 100.0\nend = [1, 2, 3]\n");
    let cases: Vec<(String, &str, &str)> = vec![
        (
            "[[device]]\nname = \"x\"\nkind = \"stepper\"\n".into(),
            "3:8",
            "unknown kind `stepper` for device `x`; the kinds are parallel, light-barrier, conveyor",
        ),
        (
            format!("{conveyor}length = 500.0\nend = [1, 2, 3]\n"),
            "1:1",
            "device `belt` has no `speed`",
        ),
        (
            format!(
                "{PARALLEL_ONLY}\n[[device]]\nname = \"q\"\nkind = \"light-barrier\"\ninput = 0o344\n"
            ),
            "13:9",
            "address 8#344# (0o344) is used twice: it is already the output of `parallel` (line 7)",
        ),
        (
            format!(
                "{PARALLEL_ONLY}\n[[event]]\nat = 1.0\ndevice = \"paralel\"\ninterrupt = true\n"
            ),
            "12:10",
            "the event names an unknown device `paralel`; the devices are parallel",
        ),
        (
            "[[device]]\nname = \"exit\"\nkind = \"light-barrier\"\non = \"belt\"\ninput = 1\n"
                .into(),
            "4:6",
            "light barrier `exit` is `on` a belt that is not there: no device is named `belt`; `on` names a conveyor",
        ),
        (
            format!(
                "{PARALLEL_ONLY}[[device]]\nname = \"exit\"\nkind = \"light-barrier\"\non = \"parallel\"\ninput = 1\n"
            ),
            "12:6",
            "`parallel` is a parallel",
        ),
        (
            format!(
                "{belt}[[event]]\nat = -1.0\ndevice = \"belt\"\nobject = {{ name = \"b\", width = 3 }}\n"
            ),
            "9:6",
            "`at` = -1.0: must be a time in seconds from 0 to Duration'Last",
        ),
        (
            format!(
                "{belt}[[event]]\nat = nan\ndevice = \"belt\"\nobject = {{ name = \"b\", width = 3 }}\n"
            ),
            "9:6",
            "`at` = NaN: must be a time in seconds from 0 to Duration'Last",
        ),
        (
            format!(
                "{belt}[[event]]\nat = 1e10\ndevice = \"belt\"\nobject = {{ name = \"b\", width = 3 }}\n"
            ),
            "9:6",
            "`at` = 10000000000.0: must be a time in seconds from 0 to Duration'Last (9223372036.854775807)",
        ),
        (
            format!("{conveyor}length = -500.0\nspeed = 100.0\nend = [1, 2, 3]\n"),
            "5:10",
            "`length` = -500.0: must be a length in mm > 0",
        ),
        (
            format!("{conveyor}length = 500.0\nspeed = 0\nend = [1, 2, 3]\n"),
            "6:9",
            "`speed` = 0.0: must be a speed in mm/s > 0",
        ),
        (
            format!("{conveyor}length = 500.0\nspeed = inf\nend = [1, 2, 3]\n"),
            "6:9",
            "`speed` = inf: must be a speed in mm/s > 0",
        ),
        (
            format!("{conveyor}length = 500.0\nspeed = 1\nend = [1, 2]\n"),
            "7:7",
            "`end` must be a position [x, y, z] of three finite numbers (mm)",
        ),
        (
            format!(
                "{belt}[[event]]\nat = 1\ndevice = \"belt\"\nobject = {{ name = \"b\", width = nan }}\n"
            ),
            "11:32",
            "`width` = NaN: must be a width in mm > 0",
        ),
        (
            format!("{belt}[[event]]\nat = 1\ndevice = \"belt\"\nobject = {{ name = \"b\" }}\n"),
            "11:10",
            "the `object` has no `width`",
        ),
        (
            format!(
                "{belt}[[event]]\nat = 1\ndevice = \"belt\"\nobject = {{ name = \"b\", width = 1 }}\n[[event]]\nat = 2\ndevice = \"belt\"\nobject = {{ name = \"b\", width = 1 }}\n"
            ),
            "15:19",
            "an object named `b` is already put on a belt at line 11",
        ),
        (
            format!("{belt}[[event]]\nat = 1\ndevice = \"belt\"\ninput = 1\n"),
            "11:9",
            "an event on conveyor `belt` cannot have `input`: a conveyor has no input register",
        ),
        (
            format!("{PARALLEL_ONLY}[[event]]\nat = 1\ndevice = \"parallel\"\ninput = 0x10000\n"),
            "12:9",
            "`input` = 65536: must be from 0 to 65535 (0xFFFF)",
        ),
        (
            format!("{PARALLEL_ONLY}[[event]]\nat = 1\ndevice = \"parallel\"\n"),
            "9:1",
            "this `[[event]]` does nothing: give it `input`, `interrupt = true` or `object`",
        ),
        (
            format!(
                "{PARALLEL_ONLY}[[event]]\nat = 1\ndevice = \"parallel\"\nobject = {{ name = \"b\", width = 1 }}\n"
            ),
            "12:10",
            "an event on parallel `parallel` cannot have `object`: objects are put on conveyors",
        ),
        (
            format!("{PARALLEL_ONLY}speed = 3\n"),
            "9:9",
            "a parallel device has no `speed`; its fields are name, kind, interrupt, input, output, control",
        ),
        (
            format!("{PARALLEL_ONLY}[[device]]\nname = \"parallel\"\n"),
            "10:8",
            "a device named `parallel` is already defined at line 2",
        ),
        (
            "[[device]]\nname = \"p\"\nkind = \"parallel\"\ninterrupt = \"8#340#\"\n".into(),
            "4:13",
            "`interrupt` must be an integer address; for Ada's `8#340#` write `0o340` (got the string \"8#340#\")",
        ),
        (
            "[[device]]\nname = \"p\"\nkind = \"parallel\"\ninterrupt = -8\n".into(),
            "4:13",
            "`interrupt` = -8: an address is from 0 to 4294967295 (0o37777777777)",
        ),
        (
            "[[device]]\nname = \"p\"\nkind = \"parallel\"\ninterupt = 8\n".into(),
            "4:1",
            "unknown field `interupt`",
        ),
        (
            "[[device]]\nname = \"p\"\nkind = \"parallel\"\ninterrupt = = 8\n".into(),
            "4:13",
            "extra `=`",
        ),
        (
            "# devices\n[device]\nname = \"p\"\n".into(),
            "2:1",
            "each device is a table `[[device]]` (double brackets), not `[device]`",
        ),
        (
            format!("{PARALLEL_ONLY}[event]\nat = 1\n"),
            "9:1",
            "each event is a table `[[event]]` (double brackets), not `[event]`",
        ),
        (
            "[[devices]]\nname = \"p\"\n".into(),
            "1:3",
            "unknown field `devices`, expected `device` or `event`",
        ),
    ];
    for (text, at, message) in cases {
        let e = match Devices::from_toml(&text, "bad.toml") {
            Ok(_) => panic!("accepted:\n{text}"),
            Err(e) => e,
        };
        let shown = e.to_string();
        let head = format!("bad.toml:{at}: error: ");
        assert!(
            shown.starts_with(&head) && shown.contains(message),
            "for\n{text}\nexpected `{head}...{message}...`\n     got `{shown}`"
        );
        assert!(!shown.contains('\n'), "one line: {shown}");
    }
}

#[test]
fn an_unreadable_file_names_the_file() {
    let e = Devices::load(std::path::Path::new("/no/such/devices.toml")).unwrap_err();
    assert_eq!(e.at, None);
    assert!(
        e.to_string()
            .starts_with("/no/such/devices.toml: error: cannot read the device file"),
        "{e}"
    );
}

proptest::proptest! {
    /// A mangled device file is an error with a place, never a panic.
    #[test]
    fn mangled_files_never_panic(
        cuts in proptest::collection::vec((0usize..2000, 0usize..6, "[\\[\\]=\"a-z0-9_. \n{},-]{0,4}"), 1..6)
    ) {
        let mut text = format!("{CELL}{PARALLEL_ONLY}{TWO_BOXES}");
        for (at, len, insert) in cuts {
            let mut at = at % (text.len() + 1);
            while !text.is_char_boundary(at) {
                at -= 1;
            }
            let mut end = (at + len).min(text.len());
            while !text.is_char_boundary(end) {
                end -= 1;
            }
            text.replace_range(at..end, &insert);
        }
        if let Err(e) = Devices::from_toml(&text, "m.toml") {
            let (line, col) = e.at.expect("a place");
            assert!(line >= 1 && line <= text.lines().count() + 1 && col >= 1, "{e}");
            assert!(!e.to_string().contains('\n'), "{e}");
        }
    }
}

/// Every event knows its line, in a file of many (lines are found by a
/// binary search now; `bench/linear.sh` times 10,000 to 40,000 events).
#[test]
fn each_of_many_events_knows_its_line() {
    let n = 3000;
    let mut text = String::from(PARALLEL_ONLY);
    let first = text.lines().count() + 1;
    for i in 0..n {
        text.push_str(&format!(
            "[[event]]\nat = {i}.0\ndevice = \"parallel\"\ninterrupt = true\n"
        ));
    }
    let d = Devices::from_toml(&text, "many.toml").expect("parses");
    let lines: Vec<usize> = d.events().iter().map(|e| e.line).collect();
    let want: Vec<usize> = (0..n).map(|i| first + 4 * i).collect();
    assert_eq!(lines, want);
}
