with Ada.Text_IO; use Ada.Text_IO;
with Ada.Integer_Text_IO; use Ada.Integer_Text_IO;

procedure Final_Newline is
   --  GNAT's Text_IO terminates an unfinished last line when the
   --  program ends, so the output ends with a line terminator even
   --  though the last call is a Put without New_Line.
   Total : Integer := 0;
begin
   Put_Line ("Numbers on one line:");
   for I in 1 .. 10 loop
      Total := Total + I;
      Put (I, Width => 3);
   end loop;
   New_Line;
   Put ("Total:");
   Put (Total, 5);
   New_Line;
   Put ("Running:");
   Total := 0;
   for I in 1 .. 5 loop
      Total := Total + I * I;
      Put (Integer'Image (Total));
      Put (',');
   end loop;
   New_Line;
   Put ("last line without terminator:");
   Put (Total);
end Final_Newline;
