with Ada.Text_IO; use Ada.Text_IO;
with Ada.Calendar;
with Ada.Real_Time;

--  RM 9.6(7), D.8(19-23): Duration is a fixed point type (GNAT: Small is
--  1 ns) and Time and Time_Span are exact counts too, so their sums,
--  differences and comparisons are exact: no rounding error builds up, as
--  it would in floating point. Measured times vary from run to run and
--  are not printed, only relations that hold for any real timing: a delay
--  lasts at least as long as asked, measured from the end of the previous
--  measurement.
procedure Time_Exact_Arithmetic is
   D : constant Duration := 0.1;
   Cycle : Duration := 0.03;   --  a variable: not folded at compile time
   Sum : Duration := 0.0;
begin
   --  Duration: exact decimal fractions.
   Put_Line ("0.03 - 0.02 = 0.01: " & Boolean'Image (Duration'(0.03) - 0.02 = 0.01));
   Put_Line ("Cycle - 0.02 = 0.01: " & Boolean'Image (Cycle - 0.02 = 0.01));
   Cycle := Cycle - 0.02;
   Put_Line ("Cycle reduced by 0.02 >= 0.01: " & Boolean'Image (Cycle >= 0.01));
   Put_Line ("0.1 * 3 = 0.3: " & Boolean'Image (D * 3 = 0.3));
   for I in 1 .. 10 loop
      Sum := Sum + D;
   end loop;
   Put_Line ("ten times 0.1 = 1.0: " & Boolean'Image (Sum = 1.0));
   Put_Line ("0.7 - 0.4 - 0.3 =" & Duration'Image (Duration'(0.7) - 0.4 - 0.3));

   declare
      use Ada.Real_Time;
      Start : constant Time := Clock;
      Span : Time_Span;
      Step : Time_Span := Time_Span_Zero;
   begin
      Put_Line ("30 ms - 20 ms = 0.01: "
                & Boolean'Image (To_Duration (Milliseconds (30) - Milliseconds (20)) = 0.01));
      Put_Line ("To_Time_Span (0.1) * 3 = 300 ms: "
                & Boolean'Image (To_Time_Span (0.1) * 3 = Milliseconds (300)));
      for I in 1 .. 1000 loop
         Step := Step + Microseconds (1);
      end loop;
      Put_Line ("1000 us = 1 ms: " & Boolean'Image (Step = Milliseconds (1)));
      Put_Line ("Start + 10 ms + 20 ms - Start = 30 ms: "
                & Boolean'Image (Start + Milliseconds (10) + Milliseconds (20) - Start
                                 = Milliseconds (30)));
      delay 0.02;
      Span := Clock - Start;
      Put_Line ("first delay took at least 20 ms: "
                & Boolean'Image (Span >= Milliseconds (20)));
      delay 0.01;
      Put_Line ("second delay took at least 10 ms: "
                & Boolean'Image (Clock - Start - Span >= Milliseconds (10)));
   end;

   declare
      use Ada.Calendar;
      Start : constant Time := Clock;
      Span : Duration;
   begin
      Put_Line ("Start + 0.1 + 0.2 = Start + 0.3: "
                & Boolean'Image (Start + 0.1 + 0.2 = Start + 0.3));
      Put_Line ("(Start + 0.3) - (Start + 0.1) = 0.2: "
                & Boolean'Image ((Start + 0.3) - (Start + 0.1) = 0.2));
      delay 0.02;
      Span := Clock - Start;
      delay 0.01;
      Put_Line ("calendar: second delay took at least 0.01: "
                & Boolean'Image (Clock - Start - Span >= 0.01));
   end;
end Time_Exact_Arithmetic;
