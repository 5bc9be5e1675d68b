with Ada.Text_IO; use Ada.Text_IO;

--  Out and in out parameters of a robot cell's helpers, copied back into
--  every kind of actual: a variable, a record component, an array element,
--  a slice, a component through an access value, an element of an array in
--  a record; and the check of a copied-back value against the actual's
--  subtype (RM 6.4.1(17)). Also a native's out parameters (Get_Line).
procedure Engine_Out_Parameters is
   subtype Percent is Integer range 0 .. 100;
   type Joint_Array is array (1 .. 4) of Integer;
   type Gripper is record
      Name  : String (1 .. 4);
      Force : Integer;
      Joints : Joint_Array;
   end record;
   type Gripper_Ref is access Gripper;

   procedure Bump (X : in out Integer; By : Integer) is
   begin
      X := X + By;
   end Bump;

   procedure Label (S : out String; Id : Integer) is
   begin
      for I in S'Range loop
         S (I) := Character'Val (Character'Pos ('A') + (Id + I) mod 26);
      end loop;
   end Label;

   procedure Split (V : Integer; Hi, Lo : out Integer) is
   begin
      Hi := V / 10;
      Lo := V mod 10;
   end Split;

   function Take (X : in out Integer) return Integer is
      Old : constant Integer := X;
   begin
      X := 0;
      return Old;
   end Take;

   G : Gripper := ("GR01", 5, (others => 0));
   R : Gripper_Ref := new Gripper'(G);
   J : Joint_Array := (1, 2, 3, 4);
   Level : Percent := 90;
   Count : Integer := 7;
   Buffer : String (1 .. 8) := (others => '.');
begin
   Bump (G.Force, 3);
   Bump (J (2), 40);
   Bump (R.Force, 100);
   Bump (R.Joints (4), -9);
   Label (G.Name (3 .. 4), 1);
   Label (Buffer (2 .. 5), 3);
   Split (J (2), J (3), J (4));
   Put_Line (G.Name & Integer'Image (G.Force) & " " & Buffer);
   Put_Line (Integer'Image (J (1)) & Integer'Image (J (2)) & Integer'Image (J (3))
             & Integer'Image (J (4)));
   Put_Line (R.Name & Integer'Image (R.Force) & Integer'Image (R.Joints (4)));
   Put_Line ("took" & Integer'Image (Take (Count)) & ", left" & Integer'Image (Count));
   begin
      Bump (Level, 20);
      Put_Line ("level" & Integer'Image (Level));
   exception
      when Constraint_Error =>
         Put_Line ("level kept" & Integer'Image (Level));
   end;
   declare
      Line : String (1 .. 20);
      Last : Natural;
   begin
      Get_Line (Line, Last);
      Put_Line ("read [" & Line (1 .. Last) & "]");
   exception
      when End_Error => Put_Line ("no input");
   end;
end Engine_Out_Parameters;
