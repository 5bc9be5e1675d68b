//! The virtual units checked against robots.md: error modes, reset, `ER`
//! after the motion, `WH` against the forward-kinematics test vectors, the
//! RM-501's silence and command set, `MI` counts, timing, hand jogs.

use super::arm::Counts;
use super::*;
use std::sync::{Arc, Mutex};

fn desc(robot: &str) -> RobotDescription {
    RobotDescription::builtin(robot).unwrap()
}

fn rv() -> DriveUnit {
    DriveUnit::new(desc("rv-m1"))
}

fn rm() -> DriveUnit {
    DriveUnit::new(desc("rm-501"))
}

fn ask(u: &mut DriveUnit, line: &str) -> Option<String> {
    u.handle(line).reply
}

fn er(u: &mut DriveUnit) -> String {
    ask(u, "ER").expect("ER answers")
}

/// Counts of controller degrees (40 per degree on the RV-M1).
fn at_deg(u: &mut DriveUnit, deg: [f64; 5]) {
    let c = u.arm().counts_of_deg(&deg);
    u.arm_mut().counts = c;
}

fn deg(u: &DriveUnit) -> [f64; 5] {
    u.arm().deg_of_counts(&u.arm().counts)
}

// ---- the command grammar ----

#[test]
fn decimals_are_read_as_a_unit_reads_them() {
    assert_eq!(line::decimal("+12.3"), Some(12.3));
    assert_eq!(line::decimal("-5"), Some(-5.0));
    assert_eq!(line::decimal(".5"), Some(0.5));
    assert_eq!(line::decimal("7."), Some(7.0));
    // More digits: rounded to the least increment 0.1.
    assert_eq!(line::decimal("12.34"), Some(12.3));
    assert_eq!(line::decimal("-0.04"), Some(0.0));
    assert_eq!(line::decimal("9999.9"), Some(9999.9));
    for bad in [
        "", "+", ".", "1e3", "1,0", "--1", "+-1", "1.2.3", "10000", "inf", "NaN", "0x1",
    ] {
        assert_eq!(line::decimal(bad), None, "{bad}");
    }
    assert_eq!(line::integer("+5", 0, 9), Some(5));
    for bad in ["5.0", "10", "-1", "", "5a", "1234567"] {
        assert_eq!(line::integer(bad, 0, 9), None, "{bad}");
    }
    assert_eq!(line::port_value("&HFF"), Some(0xFF));
    assert_eq!(line::port_value("-1"), Some(0xFFFF));
    assert_eq!(line::port_value("32768"), None);
    assert_eq!(line::port_value("&H10000"), None);
    assert_eq!(line::signed_tenth(-0.04), "+0.0");
    assert_eq!(line::signed_tenth(-88.26), "-88.3");
    assert_eq!(line::signed_tenth(51.0), "+51.0");
}

#[test]
fn lines_split_into_code_and_arguments() {
    let l = line::split("MJ +1.0, -2.0,3").unwrap();
    assert_eq!((l.code, l.args), ("MJ", vec!["+1.0", "-2.0", "3"]));
    let l = line::split("MJ10,0").unwrap();
    assert_eq!((l.code, l.args), ("MJ", vec!["10", "0"]));
    assert_eq!(line::split("NT").unwrap().args, Vec::<&str>::new());
    assert_eq!(line::split("mj 1,2,3,4,5"), None);
    assert_eq!(line::split("M"), None);
}

// ---- RV-M1: error modes ----

#[test]
fn rv_m1_error_mode_one_for_every_bad_line() {
    let bad = [
        "XY",
        "XY 1,2",
        "er",
        "MJ +1.0,+2.0,+3.0,+4.0",
        "MJ +1.0,+2.0,+3.0,+4.0,+5.0,+6.0",
        "MJ +1.0,,+3.0,+4.0,+5.0",
        "MJ +1.0,a,+3.0,+4.0,+5.0",
        "MJ 1e1,0,0,0,0",
        "MJ 10000.0,0,0,0,0",
        "NT 1",
        "WH 1",
        "SP 10",
        "SP -1",
        "SP 4.0",
        "SP 4,M",
        "PD 0,+0.0,+0.0,+0.0,+0.0,+0.0",
        "PD 630,+0.0,+0.0,+0.0,+0.0,+0.0",
        "PD 5,+0.0,+0.0,+0.0,+0.0",
        "MO 0",
        "MO 630",
        "MO 5,X",
        "HE 630",
        "MS 5,0",
        "MS 5,100",
        "MC 1,630",
        "TL 300.1",
        "TL -1.0",
        "GP 16,0,0",
        "GP 0,0,100",
        "GP 10,5",
        "TI -1",
        "TI 32768",
        "TI 1.5",
        "OD 40000",
        "OD &H10000",
        "DW +1.0,+2.0",
        "MI +400,+0,+0,+0,+0,+0",
        "PS 1",
        "HO",
    ];
    for line in bad {
        let mut u = rv();
        let before = u.arm().counts;
        assert_eq!(u.handle(line), Outcome::default(), "{line}");
        assert_eq!(er(&mut u), "1", "{line}");
        assert_eq!(u.arm().counts, before, "{line}");
    }
}

#[test]
fn rv_m1_takes_every_command_of_the_list() {
    let mut u = rv();
    let good = [
        "NT",
        "OG",
        "MJ +10.0,+5.0,+10.0,-20.0,+30.0",
        "MJ -10,-5,-10,20,-30",
        "HE 1",
        "PD 2,+200.0,+0.0,+300.0,-90.0,+0.0",
        "MO 2",
        "MO 1,C",
        "MS 2,5,O",
        "MC 1,2",
        "MC 2,1",
        "MP +250.0,+50.0,+350.0,-90.0,+0.0",
        "DW +10.0,+0.0,-10.0",
        "SP 9",
        "SP 0,H",
        "SP 5,L",
        "TL 120.5",
        "TL 0",
        "GO",
        "GC",
        "GP 10,5,20",
        "TI 3",
        "ID",
        "OD 255",
        "OD &H00F0",
        "OD -1",
        "RS",
    ];
    for line in good {
        u.handle(line);
        assert_eq!(er(&mut u), "0", "{line}");
    }
    assert!(ask(&mut u, "WH").is_some());
    assert_eq!(ask(&mut u, "DR").as_deref(), Some("&H0005A,&HFFFF"));
}

#[test]
fn rv_m1_error_mode_two_moves_nothing() {
    let mut u = rv();
    let before = u.arm().counts;
    // J2 beyond +100 deg.
    u.handle("MJ +0.0,+150.0,+0.0,+0.0,+0.0");
    assert_eq!(er(&mut u), "2");
    assert_eq!(u.arm().counts, before);
    u.handle("RS");
    // J1 exactly at its limit is fine, a tenth beyond is not.
    u.handle("MJ +150.0,+0.0,+0.0,+0.0,+0.0");
    assert_eq!(er(&mut u), "0");
    u.handle("MJ +0.1,+0.0,+0.0,+0.0,+0.0");
    assert_eq!(er(&mut u), "2");
    u.handle("RS");
    let before = u.arm().counts;
    // Far beyond the reach.
    u.handle("MP +2000.0,+0.0,+300.0,-90.0,+0.0");
    assert_eq!(er(&mut u), "2");
    u.handle("RS");
    // An undefined position.
    u.handle("MO 9");
    assert_eq!(er(&mut u), "2");
    u.handle("RS");
    // A line through the waist axis's unreachable inside: the end is
    // reachable, a point in between is not.
    u.handle("PD 3,-160.0,+0.0,+371.0,-90.0,+0.0");
    u.handle("MS 3,9");
    assert_eq!(er(&mut u), "2");
    assert_eq!(u.arm().counts, before);
}

#[test]
fn rv_m1_in_an_error_mode_only_er_and_rs_are_taken() {
    let mut u = rv();
    u.handle("XY");
    let before = u.arm().counts;
    assert_eq!(u.handle("MJ +10.0,+0.0,+0.0,+0.0,+0.0"), Outcome::default());
    assert_eq!(u.arm().counts, before);
    // No answer to WH or DR either, and no other command clears the mode.
    assert_eq!(ask(&mut u, "WH"), None);
    assert_eq!(ask(&mut u, "DR"), None);
    u.handle("NT");
    assert_eq!(er(&mut u), "1");
    // A malformed RS is not RS.
    u.handle("RS 1");
    assert_eq!(er(&mut u), "1");
    assert_eq!(u.handle("RS"), Outcome::default());
    assert_eq!(er(&mut u), "0");
    let o = u.handle("MJ +10.0,+0.0,+0.0,+0.0,+0.0");
    assert!(o.busy > 0.0 && o.reply.is_none());
    assert_eq!(deg(&u)[0], 10.0);
    // Mode II too is cleared by RS only.
    u.handle("MJ +0.0,+150.0,+0.0,+0.0,+0.0");
    u.handle("MJ +1.0,+0.0,+0.0,+0.0,+0.0");
    assert_eq!(er(&mut u), "2");
    assert_eq!(deg(&u)[0], 10.0);
    u.handle("RS");
    assert_eq!(er(&mut u), "0");
}

// ---- RV-M1: WH ----

#[test]
fn wh_matches_the_forward_kinematics_test_vectors() {
    let mut u = rv();
    // Power-on: the nest, the robot file's 107 mm tool.
    assert_eq!(
        ask(&mut u, "WH").as_deref(),
        Some("+160.0,+0.0,+371.0,-90.0,+0.0")
    );
    at_deg(&mut u, [0.0; 5]);
    assert_eq!(
        ask(&mut u, "WH").as_deref(),
        Some("+0.0,+0.0,+889.0,+90.0,+0.0")
    );
    at_deg(&mut u, [0.0, 0.0, 0.0, 90.0, 0.0]);
    assert_eq!(
        ask(&mut u, "WH").as_deref(),
        Some("+179.0,+0.0,+710.0,+0.0,+0.0")
    );
    at_deg(&mut u, [90.0, 30.0, 60.0, 0.0, 0.0]);
    assert_eq!(
        ask(&mut u, "WH").as_deref(),
        Some("+0.0,+464.0,+516.5,+0.0,+0.0")
    );
    // TL moves the TCP along the tool axis; WH shows it.
    at_deg(&mut u, [0.0; 5]);
    u.handle("TL 0.0");
    assert_eq!(
        ask(&mut u, "WH").as_deref(),
        Some("+0.0,+0.0,+782.0,+90.0,+0.0")
    );
    // Negative values, r = J5.
    u.handle("TL 107.0");
    at_deg(&mut u, [-30.0, 20.0, 40.0, -10.0, -45.5]);
    let wh = ask(&mut u, "WH").unwrap();
    let v: Vec<f64> = wh.split(',').map(|s| s.parse().unwrap()).collect();
    assert!(
        wh.split(',')
            .all(|s| s.starts_with(['+', '-']) && s.split('.').nth(1).unwrap().len() == 1)
    );
    assert!(v[0] > 0.0 && v[1] < 0.0, "{wh}");
    assert_eq!(v[3], 40.0);
    assert_eq!(v[4], -45.5);
    // The RM-501's arm (it cannot be asked): its own test vector.
    let m = rm();
    let c = m.arm().counts_of_deg(&[0.0, 0.0, 90.0, 90.0, 0.0]);
    let p = m.arm().pose_of(&c, desc("rm-501").links().tool);
    assert!((p[0] - 160.0).abs() < 1e-9 && p[1].abs() < 1e-9 && (p[2] - 255.4).abs() < 1e-9);
    assert_eq!(p[3], -90.0);
}

/// The five numbers of a `WH` reply.
fn numbers(wh: &str) -> Vec<f64> {
    wh.split(',').map(|s| s.parse().unwrap()).collect()
}

/// Two `WH` replies within the last digit (the unit reaches a pose in
/// whole joint counts, so a pose given to 0.1 comes back within 0.1).
fn near(a: &str, b: &str) -> bool {
    numbers(a)
        .iter()
        .zip(numbers(b))
        .all(|(x, y)| (x - y).abs() <= 0.1 + 1e-9)
}

#[test]
fn mp_and_positions_reach_what_wh_reported() {
    let mut u = rv();
    u.handle("MJ +20.0,+10.0,-30.0,-15.0,+40.0");
    assert_eq!(er(&mut u), "0");
    let there = u.arm().counts;
    let wh = ask(&mut u, "WH").unwrap();
    u.handle("NT");
    u.handle(&format!("MP {wh}"));
    assert_eq!(er(&mut u), "0");
    let got = ask(&mut u, "WH").unwrap();
    assert!(near(&got, &wh), "{got} {wh}");
    // The WH pose is rounded to 0.1: the joints come back within a few
    // counts.
    for (a, b) in u.arm().counts.iter().zip(there) {
        assert!((a - b).abs() <= 8, "{:?} {there:?}", u.arm().counts);
    }
    u.handle("NT");
    u.handle(&format!("PD 7,{wh}"));
    u.handle("MO 7");
    assert!(near(&ask(&mut u, "WH").unwrap(), &wh));
    // HE keeps the pose itself: MO comes back to the same counts.
    u.handle("MJ +1.0,+2.0,+3.0,+4.0,+5.0");
    let here = u.arm().counts;
    u.handle("HE 8");
    u.handle("NT");
    u.handle("MO 8");
    assert_eq!(u.arm().counts, here);
    // DW: 10 mm down, orientation kept.
    let a = numbers(&ask(&mut u, "WH").unwrap());
    u.handle("DW +0.0,+0.0,-10.0");
    assert_eq!(er(&mut u), "0");
    let b = numbers(&ask(&mut u, "WH").unwrap());
    let want = [a[0], a[1], a[2] - 10.0, a[3], a[4]];
    assert!(
        b.iter().zip(want).all(|(x, y)| (x - y).abs() <= 0.1 + 1e-9),
        "{a:?} {b:?}"
    );
    // The pose of tests/serial.rs's raw exchange comes back exactly.
    let mut u = rv();
    u.handle("MJ +10.0,+5.0,-10.0,-20.0,+0.0");
    let there = ask(&mut u, "WH").unwrap();
    u.handle("NT");
    u.handle(&format!("PD 7,{there}"));
    u.handle("MO 7");
    assert_eq!(ask(&mut u, "WH").unwrap(), there);
}

// ---- RV-M1: motion time ----

#[test]
fn motion_time_follows_the_speed_level() {
    let mut u = rv();
    at_deg(&mut u, [0.0, 0.0, 30.0, 0.0, 0.0]);
    // Level 9: the joint's full speed (J1 120 deg/s).
    u.handle("SP 9");
    let t = u.handle("MJ +120.0,+0.0,+0.0,+0.0,+0.0").busy;
    assert!((t - 1.0).abs() < 1e-9, "{t}");
    // The slowest joint sets the time: J2 at 72 deg/s.
    let t = u.handle("MJ -72.0,+36.0,+0.0,+0.0,+0.0").busy;
    assert!((t - 0.6).abs() < 1e-9, "{t}");
    // Power-on level 4: 4/9 of the speed; level 0 moves as level 1.
    let mut u = rv();
    let t = u.handle("MJ +40.0,+0.0,+0.0,+0.0,+0.0").busy;
    assert!((t - 40.0 / (120.0 * 4.0 / 9.0)).abs() < 1e-9, "{t}");
    u.handle("SP 0");
    let t = u.handle("MJ -12.0,+0.0,+0.0,+0.0,+0.0").busy;
    assert!((t - 0.9).abs() < 1e-9, "{t}");
    assert!((u.handle("TI 25").busy - 2.5).abs() < 1e-9);
    assert_eq!(u.handle("GO").busy, 0.3);
    assert_eq!(u.handle("GC").busy, 0.3);
    // The RM-501 is slower: 40 % (J1 48 deg/s).
    let mut m = rm();
    m.handle("SP 9");
    let t = m.handle("MI +1920,+0,+0,+0,+0,+0").busy;
    assert!((t - 1.0).abs() < 1e-9, "{t}");
}

// ---- RM-501 ----

#[test]
fn the_rm_501_never_answers() {
    for line in [
        "ER",
        "WH",
        "DR",
        "NT",
        "RS",
        "MI +40,+0,+0,+0,+0,+0",
        "SP 3",
        "GO",
        "GC",
        "HO",
        "OG",
        "PS 1",
        "MO 1",
        "XY",
    ] {
        let mut m = rm();
        assert_eq!(m.handle(line).reply, None, "{line}");
    }
}

#[test]
fn the_rm_501_refuses_what_it_does_not_have_until_rs() {
    for line in [
        "GP 10,5,20",
        "TL 149.6",
        "WH",
        "ER",
        "MJ +10.0,+0.0,+0.0,+0.0,+0.0",
        "MP +200.0,+0.0,+300.0,-90.0,+0.0",
        "PD 1,+0.0,+0.0,+0.0,+0.0,+0.0",
        "TI 5",
        "ID",
        "OD 1",
        "SP 4,H",
        "SP 10",
        "MI +40,+0,+0,+0,+0",
        "MI +40,+0,+0,+0,+0,+1",
        "MI +40.0,+0,+0,+0,+0,+0",
        "MI +40000,+0,+0,+0,+0,+0",
        "MO 1",
        "NT 1",
        "mi +40,+0,+0,+0,+0,+0",
    ] {
        let mut m = rm();
        m.handle(line);
        assert_ne!(m.error(), Error::None, "{line}");
        // Then every command is ignored: the arm stops while the sender
        // believes it moves.
        let before = m.arm().counts;
        assert_eq!(
            m.handle("MI +400,+0,+0,+0,+0,+0"),
            Outcome::default(),
            "{line}"
        );
        m.handle("NT");
        m.handle("GC");
        assert_eq!(m.arm().counts, before, "{line}");
        // RS recovers it.
        m.handle("RS");
        assert_eq!(m.error(), Error::None, "{line}");
        let o = m.handle("MI +400,+0,+0,+0,+0,+0");
        assert!(o.busy > 0.0, "{line}");
        assert_eq!(m.arm().counts[0], before[0] + 400, "{line}");
    }
}

#[test]
fn mi_moves_by_joint_counts() {
    let mut m = rm();
    let start = deg(&m);
    // 40 counts per degree on J1-J3, one count per 0.075 degree on J4-J5.
    m.handle("MI +400,-80,-120,-133,-1200,+0");
    assert_eq!(m.error(), Error::None);
    let d = deg(&m);
    let moved: Vec<f64> = d.iter().zip(start).map(|(a, b)| a - b).collect();
    let want = [10.0, -2.0, -3.0, -9.975, -90.0];
    for (m, w) in moved.iter().zip(want) {
        assert!((m - w).abs() < 1e-9, "{moved:?}");
    }
    // Beyond a limit (J3 0..90: nest is at 90): error, nothing moves.
    let before = m.arm().counts;
    m.handle("MI +0,+0,+200,+0,+0,+0");
    assert_eq!(m.error(), Error::Position);
    assert_eq!(m.arm().counts, before);
}

#[test]
fn rm_501_home_origin_and_positions() {
    let mut m = rm();
    let nest: Counts = m.arm().counts;
    m.handle("MI +400,+0,-400,+0,+0,+0");
    m.handle("PS 1");
    m.handle("OG");
    assert_eq!(m.arm().counts, nest, "the origin is the nest at power-on");
    m.handle("MO 1");
    let one = m.arm().counts;
    assert_eq!(one[0] - nest[0], 400);
    // HO: here is the origin; positions are counted from it.
    m.handle("MI +400,+0,+0,+0,+0,+0");
    m.handle("HO");
    let home = m.arm().counts;
    m.handle("MI -800,+0,+0,+0,+0,+0");
    m.handle("OG");
    assert_eq!(m.arm().counts, home);
    m.handle("MO 1");
    assert_eq!(m.arm().counts[0], home[0] + 400);
    assert_eq!(m.error(), Error::None);
    // NT: the nest, which is the origin again.
    m.handle("NT");
    assert_eq!(m.arm().counts, nest);
    m.handle("MO 1");
    assert_eq!(m.arm().counts, one);
    // Undefined position: the error mode.
    m.handle("MO 2");
    assert_ne!(m.error(), Error::None);
}

// ---- the station: timing, faults, hand jogs ----

/// A log written into memory.
#[derive(Clone, Default)]
struct Shared(Arc<Mutex<Vec<u8>>>);

impl Write for Shared {
    fn write(&mut self, b: &[u8]) -> std::io::Result<usize> {
        self.0.lock().unwrap().extend_from_slice(b);
        Ok(b.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// A line that delivers the script at once and records what is sent.
struct Script {
    input: VecDeque<Vec<u8>>,
    sent: Vec<(Instant, String)>,
}

impl Link for Script {
    fn receive(&mut self, timeout: Duration) -> Received {
        match self.input.pop_front() {
            Some(b) => Received::Bytes(b),
            None => {
                std::thread::sleep(timeout);
                Received::Nothing
            }
        }
    }
    fn send(&mut self, bytes: &[u8]) -> bool {
        self.sent
            .push((Instant::now(), String::from_utf8_lossy(bytes).to_string()));
        true
    }
}

struct Run {
    start: Instant,
    sent: Vec<(Instant, String)>,
    log: String,
    unit: DriveUnit,
}

/// Feeds `lines` (CR-terminated, all at once) to a station and runs it
/// until the last line has been executed.
fn run_station(unit: DriveUnit, mut faults: Faults, lines: &[&str]) -> Run {
    faults.hangup_after = Some(lines.len() as u64);
    let shared = Shared::default();
    let log = Log::new(Some(Box::new(shared.clone())));
    let mut station = Station::new(unit, faults, log).unwrap();
    let text: String = lines.iter().map(|l| format!("{l}\r")).collect();
    let mut link = Script {
        input: VecDeque::from([text.into_bytes()]),
        sent: Vec::new(),
    };
    let start = Instant::now();
    station.run(&mut link);
    let log = String::from_utf8(shared.0.lock().unwrap().clone()).unwrap();
    Run {
        start,
        sent: link.sent,
        log,
        unit: station.unit,
    }
}

fn replies(r: &Run) -> Vec<&str> {
    r.sent.iter().map(|(_, s)| s.as_str()).collect()
}

#[test]
fn er_is_answered_when_the_motion_has_ended() {
    // SP 9, 24 degrees of J1 at 120 deg/s: 0.2 s, at time scale 1.
    let r = run_station(
        rv(),
        Faults::default(),
        &["SP 9", "MJ +24.0,+0.0,+0.0,+0.0,+0.0", "ER", "TI 2", "WH"],
    );
    assert_eq!(replies(&r), ["0\r\n", "+146.2,+65.1,+371.0,-90.0,+0.0\r\n"]);
    let er_at = r.sent[0].0 - r.start;
    assert!(er_at >= Duration::from_millis(200), "{er_at:?}");
    // The dwell too: WH waits for TI's 0.2 s.
    let wh_at = r.sent[1].0 - r.sent[0].0;
    assert!(wh_at >= Duration::from_millis(200), "{wh_at:?}");
}

#[test]
fn the_time_scale_shortens_the_wait() {
    let faults = Faults {
        time_scale: 0.01,
        ..Faults::default()
    };
    // 300 degrees at level 4: 5.6 s unscaled.
    let r = run_station(
        rv(),
        faults,
        &[
            "MJ +150.0,+0.0,+0.0,+0.0,+0.0",
            "MJ -150.0,+0.0,+0.0,+0.0,+0.0",
            "ER",
        ],
    );
    assert_eq!(replies(&r), ["0\r\n"]);
    let at = r.sent[0].0 - r.start;
    assert!(at >= Duration::from_millis(56), "{at:?}");
}

#[test]
fn faults_are_checked() {
    for bad in [f64::NAN, f64::INFINITY, -1.0, 0.0] {
        let f = Faults {
            time_scale: bad,
            ..Faults::default()
        };
        assert!(f.check().is_err(), "{bad}");
        let f = Faults {
            slow: bad,
            ..Faults::default()
        };
        assert_eq!(f.check().is_err(), bad != 0.0, "{bad}");
    }
    assert!(Faults::default().check().is_ok());
    // A huge but finite scale saturates instead of panicking.
    let now = Instant::now();
    assert!(after(now, 1e300) > now);
    assert!(after(now, f64::MAX * 10.0) >= now);
    assert_eq!(
        parse_jog_after("3:+10.0,0,-5.5,0,0"),
        Ok((3, [10.0, 0.0, -5.5, 0.0, 0.0]))
    );
    for bad in [
        "3",
        "x:1,2,3,4,5",
        "3:1,2,3,4",
        "3:1,2,3,4,inf",
        "3:1,2,3,4,a",
    ] {
        assert!(parse_jog_after(bad).is_err(), "{bad}");
    }
}

#[test]
fn refuse_silence_and_corruption() {
    let faults = Faults {
        refuse: Some((2, 2)),
        corrupt: Some(4),
        silent_after: Some(5),
        time_scale: 0.01,
        ..Faults::default()
    };
    let r = run_station(
        rv(),
        faults,
        &["ER", "MJ +10.0,+0.0,+0.0,+0.0,+0.0", "ER", "ER", "RS", "ER"],
    );
    assert_eq!(replies(&r), ["0\r\n", "2\r\n", "#?\r\n"]);
    // The refused motion did not move the arm.
    assert_eq!(deg(&r.unit)[0], 0.0);
}

#[test]
fn the_log_has_each_byte_each_way_with_its_time() {
    let r = run_station(rv(), Faults::default(), &["ER", "XY"]);
    let lines: Vec<&str> = r.log.lines().collect();
    assert_eq!(lines.len(), 3, "{}", r.log);
    assert!(lines[0].ends_with(" < ER\\rXY\\r"), "{}", lines[0]);
    assert!(lines[1].ends_with(" > 0\\r\\n"), "{}", lines[1]);
    assert!(lines[2].ends_with(" x hang up"), "{}", lines[2]);
    // `{:10.4}` seconds: ten columns, four decimals.
    let time = &lines[1][..10];
    assert!(
        time.starts_with("    0.0") && time.trim().parse::<f64>().is_ok(),
        "{time}"
    );
}

#[test]
fn a_hand_jog_after_a_command_moves_the_arm_when_it_stands() {
    let faults = Faults {
        jog_after: vec![
            (2, [90.0, 0.0, 0.0, 0.0, 0.0]),
            (2, [0.0, 0.0, 50.0, 0.0, 0.0]),
        ],
        time_scale: 0.01,
        ..Faults::default()
    };
    let r = run_station(
        rv(),
        faults,
        &["WH", "MJ +0.0,+0.0,-10.0,+0.0,+0.0", "WH", "ER"],
    );
    // J1 +90; J3 from 80 by +50 stops at its 110 limit: +30.
    assert_eq!(
        replies(&r),
        [
            "+160.0,+0.0,+371.0,-90.0,+0.0\r\n",
            "+0.0,+89.1,+327.1,-110.0,+0.0\r\n",
            "0\r\n"
        ]
    );
    assert_eq!(deg(&r.unit), [90.0, 0.0, 110.0, 90.0, 0.0]);
    let jogs: Vec<&str> = r.log.lines().filter(|l| l.contains(" j ")).collect();
    assert_eq!(jogs.len(), 2);
    assert!(
        jogs[0].ends_with(" j +90.0,+0.0,+0.0,+0.0,+0.0"),
        "{}",
        jogs[0]
    );
    assert!(
        jogs[1].ends_with(" j +0.0,+0.0,+30.0,+0.0,+0.0"),
        "{}",
        jogs[1]
    );
    // Logged after the motion's line was received, before the next reply.
    let jog = r.log.find(" j +90.0").unwrap();
    assert!(r.log.find(" > +").unwrap() < jog && jog < r.log.rfind(" > +").unwrap());
}

#[test]
fn the_control_file_jogs_the_arm() {
    let path = std::env::temp_dir().join(format!("adair-simctl-control-{}", std::process::id()));
    std::fs::write(&path, "jog +10.0,+0.0,-10.0,+0.0,+5.0\nwiggle\njog 1,2\n").unwrap();
    let faults = Faults {
        control: Some(path.clone()),
        ..Faults::default()
    };
    let r = run_station(rm(), faults, &["HO"]);
    let _ = std::fs::remove_file(&path);
    // RM-501: J5 moves in 0.075 degree counts: 5.0 is 66.67 counts -> 67.
    let d = deg(&r.unit);
    assert!(
        (d[0] - 10.0).abs() < 1e-9 && (d[2] - 80.0).abs() < 1e-9,
        "{d:?}"
    );
    assert!((d[4] - 5.025).abs() < 1e-9, "{d:?}");
    assert!(
        r.log.contains(" j +10.0,+0.0,-10.0,+0.0,+5.025"),
        "{}",
        r.log
    );
    assert!(r.log.contains(" ? wiggle"), "{}", r.log);
    assert!(r.log.contains(" ? jog 1,2"), "{}", r.log);
}

#[test]
fn a_control_fifo_is_read_whenever_a_writer_comes() {
    let path = std::env::temp_dir().join(format!("adair-simctl-fifo-{}", std::process::id()));
    let _ = std::fs::remove_file(&path);
    nix::unistd::mkfifo(&path, nix::sys::stat::Mode::S_IRWXU).unwrap();
    // Opens at once although nobody writes yet.
    let mut c = Control::open(&path).unwrap();
    assert!(c.poll().is_empty());
    for n in 1..=2 {
        let mut w = std::fs::OpenOptions::new().write(true).open(&path).unwrap();
        write!(w, "jog {n},0,").unwrap();
        w.flush().unwrap();
        assert!(c.poll().is_empty(), "half a line waits");
        writeln!(w, "0,0,0").unwrap();
        drop(w);
        assert_eq!(c.poll(), [format!("jog {n},0,0,0,0")]);
        assert!(c.poll().is_empty());
    }
    let _ = std::fs::remove_file(&path);
}

#[test]
fn the_old_drivers_rm_501_lines_leave_the_hand_open() {
    // What the driver sent before it learnt the RM-501's command set
    // (tests/serial/rm_501_motions.log at e8d1e6c): `GP` puts the unit in
    // its error mode, and the `GC` after it is ignored without a sign.
    let sent = [
        "ER",
        "RS",
        "NT",
        "SP 5",
        "MI +0,+0,-3600,-1200,+0,+0",
        "GO",
        "MI +1200,+800,+1600,-133,+667,+0",
        "MI -220,+132,+44,+103,-269,+0",
        "SP 7",
        "MI +480,-240,+360,-53,+440,+0",
        "MI -480,+240,-360,+53,-440,+0",
        "GP 3,3,3",
        "GC",
    ];
    let mut m = rm();
    for (i, line) in sent.iter().enumerate() {
        m.handle(line);
        let refused = *line == "ER" || i >= 11;
        assert_eq!(m.error() != Error::None, refused, "{line}");
    }
    let DriveUnit::Rm501(u) = &m else {
        unreachable!()
    };
    assert!(u.hand_open);
    // Without the GP the hand closes.
    let mut m = rm();
    for line in sent.iter().filter(|l| !l.starts_with("GP")) {
        m.handle(line);
    }
    let DriveUnit::Rm501(u) = &m else {
        unreachable!()
    };
    assert!(!u.hand_open);
}
