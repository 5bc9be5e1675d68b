with Ada.Text_IO; use Ada.Text_IO;
with Ada.Integer_Text_IO; use Ada.Integer_Text_IO;
with Ada.Float_Text_IO; use Ada.Float_Text_IO;
with Ada.Exceptions; use Ada.Exceptions;
procedure Text_Io_Field_Limits is
begin
   Put (42, Width => 255);
   New_Line;
   Put (3.25, Fore => 1, Aft => 20, Exp => 0);
   New_Line;
   begin
      Put (42, Width => Integer'Last);
   exception
      when E : others => Put_Line ("W: " & Exception_Name (E) & " " & Exception_Message (E));
   end;
   begin
      Put (1.5, Fore => Integer'Last, Aft => 2, Exp => 0);
   exception
      when E : others => Put_Line ("F: " & Exception_Name (E) & " " & Exception_Message (E));
   end;
   begin
      Put (1.5, Fore => 2, Aft => Integer'Last, Exp => 0);
   exception
      when E : others => Put_Line ("A: " & Exception_Name (E) & " " & Exception_Message (E));
   end;
end Text_Io_Field_Limits;
