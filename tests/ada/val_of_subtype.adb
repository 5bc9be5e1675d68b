with Ada.Text_IO; use Ada.Text_IO;

--  S'Val is a function of S's base type (RM 3.5.5): a position outside a
--  subtype's range is no error; one outside the base type's is.
procedure Val_Of_Subtype is
   type Day is (Mon, Tue, Wed, Thu);
   subtype Mid is Day range Tue .. Wed;
   I : Integer := -1;
   D : Day := Thu;
begin
   Put_Line (Integer'Image (Natural'Val (I)));
   Put_Line (Day'Image (Mid'Val (I + 4)));
   Put_Line (Day'Image (Mid'Val (0)));
   Put_Line (Integer'Image (Positive'Val (0)));
   begin
      Put_Line (Day'Image (Mid'Val (I + 5)));
   exception
      when Constraint_Error => Put_Line ("Mid'Val (4): Constraint_Error");
   end;
   begin
      Put_Line (Day'Image (Mid'Succ (D)));
   exception
      when Constraint_Error => Put_Line ("Mid'Succ (Thu): Constraint_Error");
   end;
end Val_Of_Subtype;
