with Ada.Text_IO;    use Ada.Text_IO;
with Ada.Exceptions; use Ada.Exceptions;

procedure Exception_Information is
   Gripper_Jam : exception;
begin
   begin
      raise Gripper_Jam with "jaws stuck at 12 mm";
   exception
      when E : Gripper_Jam =>
         Put (Ada.Exceptions.Exception_Information (E));
         Put_Line (Exception_Name (E) & " / " & Exception_Message (E));
   end;
   begin
      raise Program_Error with "no body";
   exception
      when E : others =>
         Put_Line (Exception_Name (E) & ": " & Exception_Message (E));
   end;
end Exception_Information;
