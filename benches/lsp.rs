//! Latency of `adair lsp`'s diagnostics after a change, on a generated
//! 2,000-line program: the server runs in a thread on an in-memory
//! connection; the time is from sending `didChange` to receiving the
//! `publishDiagnostics` of that version. Also: a burst of 50 changes sent
//! at once, to the diagnostics of the last one.
//!
//! `cargo bench --bench lsp`
#![allow(clippy::print_stdout)]

use lsp_server::{Connection, Message, Notification, Request, RequestId};
use serde_json::json;
use std::time::{Duration, Instant};

/// A program of about `lines` lines: subprograms with locals, loops,
/// record components and service calls, called from the main body.
fn program(lines: usize) -> String {
    let mut s = String::from(
        "with Ada.Text_IO; use Ada.Text_IO;\nwith AdaIR; use AdaIR;\n\nprocedure Big is\n   type Point is record\n      X : Float;\n      Y : Float;\n   end record;\n   Total : Integer := 0;\n",
    );
    let per = 14;
    // Each step is `per` lines plus a blank line and its call.
    let n = lines.saturating_sub(20) / (per + 2);
    for i in 0..n {
        s.push_str(&format!(
            "\n   procedure Step_{i} (N : Integer) is
      P : Point := (X => 1.0, Y => 2.0);
      K : Integer := {i};
   begin
      for I in 1 .. N loop
         Total := Total + I * K;
         P.X := P.X + Float (I);
         if P.X > 100.0 then
            P.Y := P.X / 2.0;
         end if;
      end loop;
      SetVelocity (RobotVelocity (50.0));
      Put_Line (Integer'Image (Total) & Float'Image (P.Y));
   end Step_{i};\n"
        ));
    }
    s.push_str("\nbegin\n   InitRobot;\n");
    for i in 0..n {
        s.push_str(&format!("   Step_{i} (3);\n"));
    }
    s.push_str("end Big;\n");
    s
}

fn uri() -> lsp_types::Uri {
    "file:///bench/big.air".parse().unwrap()
}

fn change(conn: &Connection, version: i32, text: &str) {
    let n = Notification::new(
        "textDocument/didChange".into(),
        json!({ "textDocument": { "uri": uri(), "version": version }, "contentChanges": [ { "text": text } ] }),
    );
    conn.sender.send(n.into()).unwrap();
}

/// Waits for the diagnostics of `version`; returns how many there are.
fn wait(conn: &Connection, version: i32) -> usize {
    loop {
        match conn
            .receiver
            .recv_timeout(Duration::from_secs(120))
            .unwrap()
        {
            Message::Notification(n)
                if n.method == "textDocument/publishDiagnostics"
                    && n.params["version"] == json!(version) =>
            {
                return n.params["diagnostics"].as_array().map_or(0, Vec::len);
            }
            _ => {}
        }
    }
}

fn main() {
    let text = program(2000);
    let lines = text.lines().count();
    let (server, client) = Connection::memory();
    let dir = std::env::temp_dir().join(format!("adair-lsp-bench-{}", std::process::id()));
    let dir2 = dir.clone();
    let t = std::thread::spawn(move || {
        adair::lsp::run(
            &server,
            adair::lsp::Config {
                stdlib_dir: Some(dir2),
                crash_request: false,
            },
        )
    });
    let init = Request::new(
        RequestId::from(1),
        "initialize".into(),
        json!({ "capabilities": {} }),
    );
    client.sender.send(init.into()).unwrap();
    let _ = client.receiver.recv().unwrap();
    client
        .sender
        .send(Notification::new("initialized".into(), json!({})).into())
        .unwrap();
    client
        .sender
        .send(
            Notification::new(
                "textDocument/didOpen".into(),
                json!({ "textDocument": { "uri": uri(), "languageId": "adair", "version": 1, "text": text } }),
            )
            .into(),
        )
        .unwrap();
    assert_eq!(wait(&client, 1), 0, "the generated program checks");

    // One change at a time: alternately an error and its fix.
    let broken = text.replacen("Total := Total + I * K;", "Total := Total + I * Kk;", 1);
    let mut times = Vec::new();
    for v in 2..42 {
        let t0 = Instant::now();
        change(&client, v, if v % 2 == 0 { &broken } else { &text });
        let n = wait(&client, v);
        times.push(t0.elapsed());
        assert_eq!(n, usize::from(v % 2 == 0));
    }
    times.sort();
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    println!(
        "{lines} lines: diagnostics after one change: median {:.1} ms, min {:.1} ms, max {:.1} ms ({} changes)",
        ms(times[times.len() / 2]),
        ms(times[0]),
        ms(times[times.len() - 1]),
        times.len()
    );

    // A burst of 50 changes sent at once.
    let t0 = Instant::now();
    for v in 100..150 {
        change(&client, v, if v == 149 { &text } else { &broken });
    }
    wait(&client, 149);
    println!(
        "{lines} lines: diagnostics of the last of 50 changes sent at once: {:.1} ms",
        ms(t0.elapsed())
    );
    client
        .sender
        .send(Request::new(RequestId::from(2), "shutdown".into(), json!(null)).into())
        .unwrap();
    client
        .sender
        .send(Notification::new("exit".into(), json!(null)).into())
        .unwrap();
    t.join().unwrap().unwrap();
    let _ = std::fs::remove_dir_all(&dir);
}
