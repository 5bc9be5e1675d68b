with Ada.Text_IO; use Ada.Text_IO;
with Ada.Calendar;
with Ada.Real_Time;

--  delay and delay until with Ada.Calendar and Ada.Real_Time. Only what
--  Ada guarantees is printed: a delay lasts at least as long as asked,
--  a periodic task never wakes early, the arithmetic is exact. Measured
--  times themselves vary from run to run in GNAT and are not printed.
procedure Task_Clocks is

   procedure Calendar_Part is
      use Ada.Calendar;
      Start : constant Time := Clock;
      Later : Time;
      D : Duration;
   begin
      delay 0.05;
      D := Clock - Start;
      Put_Line ("calendar: delay 0.05 took at least 0.05: " & Boolean'Image (D >= 0.05));
      Later := Start + 0.1;
      delay until Later;
      Put_Line ("calendar: woke at or after Later: " & Boolean'Image (Clock >= Later));
      Put_Line ("calendar: Later - Start =" & Duration'Image (Later - Start));
      Put_Line ("calendar: Later - 0.1 = Start: " & Boolean'Image (Later - 0.1 = Start));
      Put_Line ("calendar: Start < Later: " & Boolean'Image (Start < Later)
                & ", Start > Later: " & Boolean'Image (Start > Later)
                & ", Start <= Start: " & Boolean'Image (Start <= Start));
      delay until Start;   --  in the past: returns at once
      delay -1.0;          --  negative: no wait
      delay 0.0;
      Put_Line ("calendar: past and negative delays return");
   end Calendar_Part;

   procedure Real_Time_Part is
      use Ada.Real_Time;
      Start : constant Time := Clock;
      Period : constant Time_Span := Milliseconds (20);
      Next : Time := Start;
      Span : Time_Span;
   begin
      Put_Line ("real time: 250 ms =" & Duration'Image (To_Duration (Milliseconds (250))));
      Put_Line ("real time: period + period =" & Duration'Image (To_Duration (Period + Period)));
      Put_Line ("real time: 20 ms - 50 ms =" & Duration'Image (To_Duration (Period - Milliseconds (50))));
      Put_Line ("real time: 20 ms < 50 ms: " & Boolean'Image (Period < Milliseconds (50))
                & ", 20 ms >= 20 ms: " & Boolean'Image (Period >= Milliseconds (20)));
      for I in 1 .. 3 loop
         Next := Next + Period;
         delay until Next;
      end loop;
      Span := Clock - Start;
      Put_Line ("real time: three periods took at least 60 ms: "
                & Boolean'Image (Span >= Milliseconds (60)));
      Put_Line ("real time: Next - Start =" & Duration'Image (To_Duration (Next - Start)));
      Put_Line ("real time: Next - Period > Start: " & Boolean'Image (Next - Period > Start));
   end Real_Time_Part;

   --  A periodic task on Ada.Real_Time: every tick is at or after its
   --  release time, and the ticks are counted.
   task Ticker is
      entry Result (Ticks : out Integer; Never_Early : out Boolean);
   end Ticker;

   task body Ticker is
      use Ada.Real_Time;
      Next : Time := Clock;
      Count : Integer := 0;
      Ok : Boolean := True;
   begin
      for I in 1 .. 5 loop
         Next := Next + Milliseconds (10);
         delay until Next;
         if Clock < Next then
            Ok := False;
         end if;
         Count := Count + 1;
      end loop;
      accept Result (Ticks : out Integer; Never_Early : out Boolean) do
         Ticks := Count;
         Never_Early := Ok;
      end Result;
   end Ticker;

   N : Integer;
   B : Boolean;
begin
   Calendar_Part;
   Real_Time_Part;
   Ticker.Result (N, B);
   Put_Line ("ticker: ticks" & Integer'Image (N) & ", never early: " & Boolean'Image (B));
end Task_Clocks;
