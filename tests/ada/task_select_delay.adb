with Ada.Text_IO; use Ada.Text_IO;

--  Selective accept with a delay alternative (a watchdog timeout), and the
--  caller's side: timed entry calls. Every timeout below happens because
--  the other side is provably busy elsewhere (main blocked on another
--  entry), never because of a race; every success happens because the call
--  is already queued (checked with 'Count) or the server has no other way
--  out than to accept it.
procedure Task_Select_Delay is
   task Watchdog is
      entry Start;
      entry Kick;
      entry Sync;
      entry Finish (Count : out Integer);
   end Watchdog;

   task body Watchdog is
      Timeouts : Integer := 0;
   begin
      accept Start;
      --  1: nobody calls Kick (main is queued on Sync): the delay wins.
      select
         accept Kick;
         Put_Line ("Watchdog: kicked (wrong)");
      or
         delay 0.05;
         Timeouts := Timeouts + 1;
         Put_Line ("Watchdog: timeout 1");
      end select;
      accept Sync;
      --  2: wait until main's Kick is queued, then the accept wins.
      while Kick'Count = 0 loop
         delay 0.001;
      end loop;
      select
         accept Kick do
            Put_Line ("Watchdog: kicked");
         end Kick;
      or
         delay 0.05;
         Timeouts := Timeouts + 1;
         Put_Line ("Watchdog: timeout 2 (wrong)");
      end select;
      --  3: a guarded delay alternative, open in round 1 (main is queued
      --  on Sync, so it times out), closed in round 2 (so the select
      --  waits for main's timed call).
      for Round in 1 .. 2 loop
         select
            accept Kick do
               Put_Line ("Watchdog: kicked in round" & Integer'Image (Round));
            end Kick;
         or
            when Round = 1 =>
               delay 0.02;
               Timeouts := Timeouts + 1;
               Put_Line ("Watchdog: round 1 timed out");
         end select;
         if Round = 1 then
            accept Sync;
         end if;
      end loop;
      accept Finish (Count : out Integer) do
         Count := Timeouts;
      end Finish;
   end Watchdog;

   N : Integer;
begin
   --  The watchdog waits at accept Start; Finish is offered only at its
   --  very end, so a timed call to Finish must time out.
   select
      Watchdog.Finish (N);
      Put_Line ("Main: finished early (wrong)");
   or
      delay 0.01;
      Put_Line ("Main: Finish timed out, as expected");
   end select;
   Watchdog.Start;
   Watchdog.Sync;          --  served after the watchdog's first timeout
   Watchdog.Kick;          --  queued, then accepted with a body
   Watchdog.Sync;          --  served after round 1 timed out
   select
      Watchdog.Kick;
      Put_Line ("Main: timed Kick accepted");
   or
      delay 30.0;
      Put_Line ("Main: timed Kick timed out (wrong)");
   end select;
   Watchdog.Finish (N);
   Put_Line ("Main: watchdog timeouts" & Integer'Image (N));
end Task_Select_Delay;
