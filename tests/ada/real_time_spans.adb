with Ada.Text_IO; use Ada.Text_IO;
with Ada.Real_Time;
with Ada.Calendar;

--  Ada.Real_Time's Time_Span arithmetic (scaling by an Integer, the
--  truncated quotient of two spans), Duration / Integer truncated to whole
--  nanoseconds as GNAT's fixed point, and `use type` making a package's
--  operators visible without its other names.
procedure Real_Time_Spans is
   use type Ada.Real_Time.Time_Span;
   use type Ada.Calendar.Time;
   A : constant Ada.Real_Time.Time_Span := Ada.Real_Time.Milliseconds (10) / 2;
   B : constant Ada.Real_Time.Time_Span := Ada.Real_Time.To_Time_Span (0.5) * 3;
   C : constant Ada.Real_Time.Time_Span := 3 * Ada.Real_Time.Milliseconds (7);
   N : constant Integer := Ada.Real_Time.Milliseconds (100) / Ada.Real_Time.Milliseconds (40);
   M : constant Integer := Ada.Real_Time.Milliseconds (100) / Ada.Real_Time.Milliseconds (-40);
   E : constant Ada.Real_Time.Time_Span := -A + abs (A - B);
   D : constant Duration := 0.000000010;
   T0 : constant Ada.Calendar.Time := Ada.Calendar.Clock;
begin
   Put_Line (Duration'Image (Ada.Real_Time.To_Duration (A)));
   Put_Line (Duration'Image (Ada.Real_Time.To_Duration (B)));
   Put_Line (Duration'Image (Ada.Real_Time.To_Duration (C)));
   Put_Line (Integer'Image (N) & Integer'Image (M));
   Put_Line (Duration'Image (Ada.Real_Time.To_Duration (E)));
   Put_Line (Boolean'Image (A < B) & " " & Boolean'Image (B >= C));
   Put_Line (Duration'Image (Ada.Real_Time.To_Duration (Ada.Real_Time.Nanoseconds (10) / 4)));
   Put_Line (Duration'Image (D / 4) & Duration'Image (-D / 4) & Duration'Image (Duration'(0.01) / 3));
   Put_Line (Boolean'Image (T0 + 1.0 > T0) & " " & Boolean'Image (T0 - T0 = 0.0));
   Put_Line (Integer'Image (Ada.Real_Time.Milliseconds (300) / Ada.Real_Time.Milliseconds (100)));
end Real_Time_Spans;
