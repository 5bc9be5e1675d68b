with Ada.Text_IO; use Ada.Text_IO;
with Ada.Exceptions; use Ada.Exceptions;

procedure Runtime_Errors is
   type Vec is array (1 .. 5) of Integer;
   V : Vec := (1, 2, 3, 4, 5);
   R : Integer := 0;
   function Id (X : Integer) return Integer is
   begin
      return X;
   end Id;
begin
   begin
      R := Id (Integer'Last) + 1;
      Put_Line ("not reached" & Integer'Image (R));
   exception
      when Constraint_Error =>
         Put_Line ("Integer'Last + 1: Constraint_Error");
   end;
   begin
      R := Id (Integer'First) - 1;
      Put_Line ("not reached" & Integer'Image (R));
   exception
      when E : Constraint_Error =>
         Put_Line ("Integer'First - 1: " & Exception_Name (E));
   end;
   begin
      R := Id (100_000) * Id (100_000);
      Put_Line ("not reached" & Integer'Image (R));
   exception
      when E : others =>
         Put_Line ("100_000 * 100_000: " & Exception_Name (E));
   end;
   begin
      R := 10 / Id (0);
      Put_Line ("not reached" & Integer'Image (R));
   exception
      when E : Constraint_Error =>
         Put_Line ("10 / 0: " & Exception_Name (E));
   end;
   begin
      R := 10 mod Id (0);
      Put_Line ("not reached" & Integer'Image (R));
   exception
      when Constraint_Error =>
         Put_Line ("10 mod 0: Constraint_Error");
   end;
   begin
      R := abs Id (Integer'First);
      Put_Line ("not reached" & Integer'Image (R));
   exception
      when Constraint_Error =>
         Put_Line ("abs Integer'First: Constraint_Error");
   end;
   begin
      R := Id (2) ** 31;
      Put_Line ("not reached" & Integer'Image (R));
   exception
      when Constraint_Error =>
         Put_Line ("2 ** 31: Constraint_Error");
   end;
   Put_Line ("2 ** 30 =" & Integer'Image (Id (2) ** 30));
   for I in 4 .. 7 loop
      begin
         V (Id (I)) := V (I - 1) * 10;
         Put_Line ("V (" & Integer'Image (I) & " ) =" & Integer'Image (V (I)));
      exception
         when Constraint_Error =>
            Put_Line ("index" & Integer'Image (I) & " out of range");
      end;
   end loop;
   begin
      R := V (Id (0));
      Put_Line ("not reached" & Integer'Image (R));
   exception
      when Constraint_Error =>
         Put_Line ("V (0): Constraint_Error");
   end;
   Put_Line ("R is still" & Integer'Image (R));
end Runtime_Errors;
