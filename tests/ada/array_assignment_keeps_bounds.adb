--  Every array object is constrained (RM 3.3.1): an assignment slides a
--  value of the same length to the target's bounds and fails the length
--  check for another length (RM 5.2), whether the bounds came from the
--  declaration, the initial value, the actual of a formal or an allocator.
with Ada.Text_IO; use Ada.Text_IO;
procedure Array_Assignment_Keeps_Bounds is
   Src : constant String := "0123456789";
   S : String := Src (1 .. 3);
   C : String (11 .. 13) := "abc";
   B : String (1 .. 3) := "xyz";
   type Str_Ptr is access String;
   P : Str_Ptr := new String'("abc");
   procedure Shift (X : in out String) is
   begin
      X := X (X'First + 1 .. X'Last) & '.';
   end Shift;
   procedure Fill (X : out String) is
   begin
      X := "hello";
   end Fill;
begin
   S := Src (6 .. 8);
   Put_Line (S & Integer'Image (S'First) & Integer'Image (S'Last));
   S (1) := 'X';
   Put_Line (S);
   begin
      S := "wxyz";
      Put_Line ("S took 4 characters");
   exception
      when Constraint_Error => Put_Line ("S: Constraint_Error");
   end;
   Shift (C);
   Put_Line (C & Integer'Image (C'First) & Integer'Image (C'Last));
   begin
      Fill (B);
      Put_Line ("B = " & B);
   exception
      when Constraint_Error => Put_Line ("Fill: Constraint_Error, B = " & B);
   end;
   begin
      P.all := "wxyz";
      Put_Line ("P.all took 4 characters");
   exception
      when Constraint_Error => Put_Line ("P.all: Constraint_Error, " & P.all);
   end;
   P.all := "def";
   Put_Line (P.all & Integer'Image (P'First));
end Array_Assignment_Keeps_Bounds;
