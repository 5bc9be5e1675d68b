--  A tag buffer: the station code is a slice of the tag, renamed; writes
--  go through the renamed slice and through a slice of a slice.
with Ada.Text_IO; use Ada.Text_IO;
procedure Renaming_Slice_Paths is
   Tag     : String (1 .. 10) := "CELL-A-001";
   Station : String renames Tag (6 .. 8);
begin
   Station (7) := 'B';
   Put_Line (Tag);
   Tag (6 .. 8) (8) := '+';
   Put_Line (Tag);
   Tag (1 .. 9) (2 .. 3) := "OO";
   Put_Line (Tag & " " & Station);
   begin
      Tag (6 .. 8) (9) := 'X';
   exception
      when Constraint_Error => Put_Line ("index outside the slice");
   end;
   begin
      Station (5) := 'X';
   exception
      when Constraint_Error => Put_Line ("index outside the renamed slice");
   end;
   begin
      Tag (1 .. 4) (3 .. 5) := "abc";
   exception
      when Constraint_Error => Put_Line ("slice outside the slice");
   end;
   Put_Line (Tag);
end Renaming_Slice_Paths;
