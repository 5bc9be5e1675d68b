//! A rendezvous allocates nothing that grows with the number of
//! rendezvous: a switch between threads reuses its lists of frames
//! (`Codes::spare_frames`, `spare_saved`), an `accept` waits on queues
//! held inline, an entry call reuses its thread's list of slots. (Each of
//! them allocated once per switch; 10,000 rendezvous made 60,000 blocks.)
//!
//! The work is counted as the bytes the runs allocate (the process's
//! allocator counts them in the tests' build), not timed. This file holds
//! one test, so that no other test allocates while it counts.

use adair::golden::SharedBuf;
use adair::interp::memory::ALLOC;
use adair::session::{Outcome, Session};

/// The bytes a run of `n` rendezvous allocates (its output is checked).
fn rendezvous_bytes(n: usize) -> usize {
    let src = format!(
        "with Ada.Text_IO; use Ada.Text_IO;
procedure Ping is
   task Server is
      entry Add (X : in out Integer);
   end Server;
   task body Server is
   begin
      for I in 1 .. {n} loop
         accept Add (X : in out Integer) do
            X := X + 1;
         end Add;
      end loop;
   end Server;
   V : Integer := 0;
begin
   for I in 1 .. {n} loop
      Server.Add (V);
   end loop;
   Put_Line (Integer'Image (V));
end Ping;
"
    );
    let out = SharedBuf::default();
    let mut s = Session::new(Box::new(out.clone()));
    let before = ALLOC.total_allocated();
    let outcome = s.run_source("ping.adb", &src);
    let bytes = ALLOC.total_allocated() - before;
    assert!(matches!(outcome, Outcome::Ok), "{:?}", outcome.exit_code());
    assert_eq!(out.take().trim(), n.to_string());
    bytes
}

#[test]
fn a_rendezvous_allocates_nothing_per_rendezvous() {
    let (small, large) = (rendezvous_bytes(1_000), rendezvous_bytes(5_000));
    let per = large.saturating_sub(small) as f64 / 4_000.0;
    assert!(
        per < 4.0,
        "{per:.1} bytes allocated per rendezvous ({small} bytes for 1,000, {large} for 5,000)"
    );
}
