with Ada.Text_IO; use Ada.Text_IO;

procedure Aggregate_Integer_First is
   type Int_Vec is array (Integer range <>) of Integer;
   type Nat_Vec is array (Natural range <>) of Integer;
   type Pos_Vec is array (Positive range <>) of Integer;
   type Color is (Red, Green, Blue, White);
   type Color_Vec is array (Color range <>) of Integer;
   A : constant Int_Vec := (10, 20, 30);
   N : constant Nat_Vec := (4, 5, 6, 7);
   P : constant Pos_Vec := (8, 9);
   C : constant Color_Vec := (1, 2, 3);
   S : constant String := "abc";
   B : constant Int_Vec := (-1 => 100, 0 => 200, 1 => 300);

   procedure Show (V : Int_Vec) is
   begin
      Put ("First =" & Integer'Image (V'First) & " Last =" & Integer'Image (V'Last)
           & " Length =" & Integer'Image (V'Length) & " :");
      for I in V'Range loop
         Put (Integer'Image (V (I)));
      end loop;
      New_Line;
   end Show;
begin
   Show (A);
   Put_Line ("A (Integer'First) =" & Integer'Image (A (Integer'First)));
   Put_Line ("A (Integer'First + 2) =" & Integer'Image (A (Integer'First + 2)));
   Show (B);
   Show ((5 => 1, 6 => 2));
   Put_Line ("N'First =" & Integer'Image (N'First) & " N'Last =" & Integer'Image (N'Last));
   Put_Line ("P'First =" & Integer'Image (P'First) & " P'Last =" & Integer'Image (P'Last));
   Put_Line ("C'First = " & Color'Image (C'First) & " C'Last = " & Color'Image (C'Last));
   Put_Line ("S'First =" & Integer'Image (S'First) & " S'Last =" & Integer'Image (S'Last));
   for K in C'Range loop
      Put_Line (Color'Image (K) & " =>" & Integer'Image (C (K)));
   end loop;
   declare
      D : Int_Vec (-3 .. 0) := (others => 9);
   begin
      D (-3) := 1;
      Show (D);
   end;
end Aggregate_Integer_First;
