with Ada.Text_IO; use Ada.Text_IO;
procedure Record_Multi is
   type Point is record
      X, Y : Integer := 0;
      Z : Integer := 5;
   end record;
   P : Point;
begin
   P.Y := 3;
   Put_Line (Integer'Image (P.X) & Integer'Image (P.Y) & Integer'Image (P.Z));
end Record_Multi;
