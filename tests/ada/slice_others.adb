with Ada.Text_IO; use Ada.Text_IO;
procedure Slice_Others is
   type Arr is array (1 .. 6) of Integer;
   A : Arr := (others => 0);
   S : String (1 .. 3) := "abc";
   T : String := "hello";
begin
   A (2 .. 4) := (others => 9);
   for I in A'Range loop
      Put (Integer'Image (A (I)));
   end loop;
   New_Line;
   S := S (2 .. 3) & 'z';
   Put_Line (S);
   Put_Line (Integer'Image (S'First) & Integer'Image (S'Last));
   T (2 .. 3) := T (4 .. 5);
   Put_Line (T);
   declare
      U : String (5 .. 7);
   begin
      U := "xyz";
      Put_Line (U & Integer'Image (U'First));
      U := S;
      Put_Line (U);
   end;
end Slice_Others;
