with Ada.Text_IO; use Ada.Text_IO;

--  The dependent expressions of an `if` or `case` expression have its
--  type, not the subtype of the first one (RM 4.5.7): a value outside
--  that subtype is no error until it goes to a constrained place.
procedure If_Expression_Branch_Subtype is
   subtype Small is Integer range 1 .. 10;
   K : Small := 1;
   B : Boolean := True;
   I : Integer;
   S : Small;
begin
   for J in 1 .. 2 loop
      Put_Line (Boolean'Image ((if B then -J else 0) < 0));
   end loop;
   Put_Line (Boolean'Image ((if B then -K else 0) < 0));
   Put_Line (Boolean'Image ((case K is when 1 => K - 5, when others => K) < 0));
   I := (if B then K * 100 else K);
   Put_Line (Integer'Image (I));
   begin
      S := (if B then K * 100 else K);
      Put_Line (Integer'Image (S));
   exception
      when Constraint_Error => Put_Line ("range check at the assignment");
   end;
end If_Expression_Branch_Subtype;
