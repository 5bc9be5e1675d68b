with Ada.Text_IO; use Ada.Text_IO;
with Ada.Exceptions; use Ada.Exceptions;
procedure Exc_Messages is
   My_Error : exception;
   N : Integer := 0;
begin
   begin
      raise My_Error;
   exception
      when E : My_Error =>
         Put_Line (Exception_Name (E) & ": " & Exception_Message (E));
   end;
   Named : declare
      Local_Error : exception;
   begin
      raise Local_Error;
   exception
      when E : others =>
         Put_Line (Exception_Name (E));
   end Named;
   Put_Line (Integer'Image (N));
end Exc_Messages;
