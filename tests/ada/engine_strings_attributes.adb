--  Strings, slices and attributes as robot programs use them, each in a
--  loop so that the compiled engine runs them many times: a string
--  literal assigned and then changed in place must not change the
--  literal (each iteration starts from "abc"); concatenation of strings
--  and characters; slices on both sides of an assignment, overlapping;
--  'Image, 'Pos, 'Val, 'Succ, 'Pred, 'Min, 'Max, 'Value, 'First, 'Last,
--  'Length of a slice; a slice whose bound is a function call.
with Ada.Text_IO; use Ada.Text_IO;
procedure Engine_Strings_Attributes is
   type Axis is (Base, Shoulder, Elbow, Pitch, Roll);
   S : String (1 .. 3);
   Line : String (1 .. 10) := "0123456789";
   Count : Natural := 0;
   function Mid return Positive is
   begin
      Count := Count + 1;
      return 5;
   end Mid;
   Tag : String (1 .. 4);
   Sum : Integer := 0;
begin
   for I in 1 .. 3 loop
      S := "abc";
      S (I) := 'X';
      Put_Line (S & " " & "abc");
   end loop;
   for A in Axis loop
      Put_Line (Axis'Image (A) & Integer'Image (Axis'Pos (A))
                & " next " & Axis'Image (Axis'Val ((Axis'Pos (A) + 1) mod 5)));
   end loop;
   Put_Line (Axis'Image (Axis'Succ (Base)) & " " & Axis'Image (Axis'Pred (Roll)));
   for K in 1 .. 4 loop
      Tag (K) := Character'Val (Character'Pos ('A') + K * 3 mod 26);
   end loop;
   Put_Line ("tag " & Tag & " " & Tag (2 .. 3) & Tag (4) & 'Z');
   Line (3 .. 6) := Line (1 .. 4);
   Put_Line (Line);
   Line (1 .. 4) := Line (2 .. 5);
   Put_Line (Line);
   --  (Operands of "&" are evaluated in an order Ada leaves open: the
   --  calls' count is printed on its own line.)
   Put_Line (Line (Mid .. 7)
             & Integer'Image (Line (Mid .. 9)'Length)
             & Integer'Image (Line (Mid .. 9)'First));
   Put_Line ("calls" & Integer'Image (Count));
   for I in 1 .. 5 loop
      Sum := Sum + Integer'Max (I, 3) - Integer'Min (I, 2)
        + Integer'Value (Integer'Image (I * 7));
   end loop;
   Put_Line ("sum" & Integer'Image (Sum));
   Put_Line ("empty [" & Line (5 .. 4) & "]" & Integer'Image (Line (5 .. 4)'Length));
   begin
      Put_Line (Line (8 .. 11));
   exception
      when Constraint_Error => Put_Line ("slice past the end: CONSTRAINT_ERROR");
   end;
end Engine_Strings_Attributes;
