with Ada.Text_IO; use Ada.Text_IO;
with Ada.Exceptions; use Ada.Exceptions;
with Ada.IO_Exceptions;
procedure Explicit_Raise is
begin
   begin
      raise Constraint_Error;
   exception
      when E : others => Put_Line ("[" & Exception_Message (E) & "]");
   end;
   begin
      raise Program_Error;
   exception
      when E : others => Put_Line ("[" & Exception_Message (E) & "]");
   end;
   begin
      raise Constraint_Error with "mine";
   exception
      when E : others => Put_Line ("[" & Exception_Message (E) & "]");
   end;
   begin
      raise Ada.IO_Exceptions.Data_Error;
   exception
      when E : others => Put_Line ("[" & Exception_Message (E) & "]");
   end;
   raise Storage_Error;
end Explicit_Raise;
