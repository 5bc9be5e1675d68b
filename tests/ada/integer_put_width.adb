with Ada.Text_IO; use Ada.Text_IO;
with Ada.Integer_Text_IO; use Ada.Integer_Text_IO;

procedure Integer_Put_Width is
   N : Integer := 1;
begin
   Put ("["); Put (42); Put_Line ("]");
   Put ("["); Put (-42); Put_Line ("]");
   Put ("["); Put (0); Put_Line ("]");
   Put ("["); Put (Integer'First); Put_Line ("]");
   Put ("["); Put (Integer'Last); Put_Line ("]");
   for W in 0 .. 6 loop
      Put ("W=" & Integer'Image (W) & " [");
      Put (123, Width => W);
      Put ("] [");
      Put (-123, W);
      Put ("] [");
      Put (Item => 0, Width => W);
      Put_Line ("]");
   end loop;
   Put ("["); Put (7, 1); Put_Line ("]");
   Put ("["); Put (-7, 1); Put_Line ("]");
   Put ("["); Put (Width => 8, Item => 2_000_000_000); Put_Line ("]");
   Put ("["); Put (-2_000_000_000, 15); Put_Line ("]");
   Put_Line ("Table:");
   for I in 1 .. 5 loop
      N := N * 7;
      Put (I, 3);
      Put (N, 8);
      Put (-N, 8);
      New_Line;
   end loop;
   Ada.Integer_Text_IO.Put (99, 4);
   Ada.Text_IO.New_Line;
end Integer_Put_Width;
