--  Enumeration types with character literals ('B' and 'b' are different
--  literals), beside Character's own.
with Ada.Text_IO; use Ada.Text_IO;
procedure Char_Enum_Literals is
   type Grade is ('A', 'B', 'C', 'b');
   G : Grade := 'B';
   H : Grade := 'b';
   C : Character := 'B';
begin
   Put_Line (Grade'Image (G) & Grade'Image (H) & Integer'Image (Grade'Pos (H)));
   G := Grade'Succ (G);
   Put_Line (Grade'Image (G));
   Put_Line (Character'Image (C));
   for X in Grade loop
      Put (Grade'Image (X));
   end loop;
   New_Line;
end Char_Enum_Literals;
