with Ada.Text_IO; use Ada.Text_IO;

procedure Records_Copy is
   type Vec3 is array (1 .. 3) of Integer;
   type Item is record
      Count : Integer := 0;
      Data  : Vec3 := (others => 0);
   end record;
   type Item_Array is array (1 .. 2) of Item;
   A, B : Item;
   L1, L2 : Item_Array;
   V1 : Vec3 := (1, 2, 3);
   V2 : Vec3;
   procedure Show (Label : String; I : Item) is
   begin
      Put_Line (Label & ":" & Integer'Image (I.Count) & " ("
                & Integer'Image (I.Data (1)) & Integer'Image (I.Data (2))
                & Integer'Image (I.Data (3)) & " )");
   end Show;
   procedure Modify_Copy (I : Item) is
      Local : Item := I;
   begin
      Local.Count := 999;
      Local.Data (2) := 999;
      Show ("  local", Local);
   end Modify_Copy;
begin
   A.Count := 5;
   A.Data := (10, 20, 30);
   B := A;
   B.Count := 6;
   B.Data (1) := 11;
   Show ("A", A);
   Show ("B", B);
   Modify_Copy (A);
   Show ("A after call", A);
   V2 := V1;
   V2 (3) := 33;
   Put_Line ("V1 (3) =" & Integer'Image (V1 (3)) & ", V2 (3) =" & Integer'Image (V2 (3)));
   V1 := V2;
   V2 (1) := -1;
   Put_Line ("V1 (1) =" & Integer'Image (V1 (1)) & ", V2 (1) =" & Integer'Image (V2 (1)));
   L1 (1) := A;
   L1 (2) := B;
   L2 := L1;
   L2 (1).Data (3) := 300;
   L2 (2).Count := 0;
   Show ("L1 (1)", L1 (1));
   Show ("L2 (1)", L2 (1));
   Show ("L1 (2)", L1 (2));
   Show ("L2 (2)", L2 (2));
   Put_Line ("A = B: " & Boolean'Image (A = B));
   B := A;
   Put_Line ("after B := A, A = B: " & Boolean'Image (A = B));
   Put_Line ("L1 = L2: " & Boolean'Image (L1 = L2));
   Put_Line ("V1 = V2: " & Boolean'Image (V1 = V2) & ", V1 /= V2: " & Boolean'Image (V1 /= V2));
   L1 := (others => A);
   Show ("L1 (2) after others", L1 (2));
end Records_Copy;
