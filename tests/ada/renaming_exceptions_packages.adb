--  A gripper package under a short name, its exception under another
--  name: raised by either name, caught by either, and reported by the
--  name it was declared with.
with Ada.Text_IO;
with Ada.Exceptions; use Ada.Exceptions;
procedure Renaming_Exceptions_Packages is
   package IO renames Ada.Text_IO;

   package Grippers is
      Gripper_Jam : exception;
      Max_Force : constant Integer := 40;
      Force : Integer := 0;
      procedure Close (With_Force : Integer);
      function Holding return Boolean;
   end Grippers;

   package body Grippers is
      procedure Close (With_Force : Integer) is
      begin
         if With_Force > Max_Force then
            raise Gripper_Jam with "force" & Integer'Image (With_Force);
         end if;
         Force := With_Force;
      end Close;

      function Holding return Boolean is
      begin
         return Force > 0;
      end Holding;
   end Grippers;

   package G renames Grippers;
   Jam : exception renames G.Gripper_Jam;
   Too_Far : exception renames Constraint_Error;

   procedure Try (F : Integer) is
   begin
      G.Close (F);
      IO.Put_Line ("closed at" & Integer'Image (G.Force));
   exception
      when Jam =>
         IO.Put_Line ("jam caught as Jam");
         raise;
   end Try;

   Reach : constant array (1 .. 3) of Integer := (100, 200, 300);
   K : Integer := 4;
begin
   Try (20);
   IO.Put_Line ("holding " & Boolean'Image (G.Holding));
   begin
      Try (55);
   exception
      when E : Grippers.Gripper_Jam =>
         IO.Put_Line ("caught as Gripper_Jam: " & Exception_Name (E)
                      & " / " & Exception_Message (E));
   end;
   begin
      raise Jam;
   exception
      when G.Gripper_Jam => IO.Put_Line ("Jam raised, Gripper_Jam caught");
   end;
   begin
      IO.Put_Line (Integer'Image (Reach (K)));
   exception
      when E : Too_Far => IO.Put_Line ("too far: " & Exception_Name (E));
   end;
   declare
      use G;
   begin
      Close (Max_Force);
      IO.Put_Line ("use G: force" & Integer'Image (Force));
   end;
   raise Jam with "left unhandled";
end Renaming_Exceptions_Packages;
