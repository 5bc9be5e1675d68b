with Ada.Text_IO; use Ada.Text_IO;

procedure Array_Attributes is
   type Vec is array (1 .. 5) of Integer;
   type Shifted is array (-2 .. 2) of Integer;
   type Grid is array (1 .. 3, 0 .. 4) of Integer;
   type Color is (Red, Green, Blue);
   type Per_Color is array (Color) of Float;
   V : Vec := (others => 0);
   S : constant Shifted := (10, 20, 30, 40, 50);
   G : Grid := (others => (others => 0));
   P : constant Per_Color := (Red => 1.0, Green => 0.5, Blue => 0.25);
begin
   Put_Line ("V'First =" & Integer'Image (V'First) & " V'Last =" & Integer'Image (V'Last)
             & " V'Length =" & Integer'Image (V'Length));
   Put_Line ("S'First =" & Integer'Image (S'First) & " S'Last =" & Integer'Image (S'Last)
             & " S'Length =" & Integer'Image (S'Length));
   Put_Line ("Vec'Length =" & Integer'Image (Vec'Length));
   for I in V'Range loop
      V (I) := I * I;
   end loop;
   for I in reverse V'Range loop
      Put (Integer'Image (V (I)));
   end loop;
   New_Line;
   for I in S'Range loop
      Put_Line ("S (" & Integer'Image (I) & ") =" & Integer'Image (S (I)));
   end loop;
   Put_Line ("G'First (1) =" & Integer'Image (G'First (1)) & " G'Last (1) =" & Integer'Image (G'Last (1)));
   Put_Line ("G'First (2) =" & Integer'Image (G'First (2)) & " G'Last (2) =" & Integer'Image (G'Last (2)));
   Put_Line ("G'Length (1) =" & Integer'Image (G'Length (1)) & " G'Length (2) =" & Integer'Image (G'Length (2)));
   Put_Line ("G'Length =" & Integer'Image (G'Length) & " G'First =" & Integer'Image (G'First));
   for I in G'Range (1) loop
      for J in G'Range (2) loop
         G (I, J) := I * 10 + J;
         Put (Integer'Image (G (I, J)));
      end loop;
      New_Line;
   end loop;
   Put_Line ("Grid'Last (2) =" & Integer'Image (Grid'Last (2)));
   Put_Line ("P'First = " & Color'Image (P'First) & " P'Last = " & Color'Image (P'Last));
   Put_Line ("P'Length =" & Integer'Image (P'Length));
   for C in P'Range loop
      Put_Line (Color'Image (C) & " ->" & Float'Image (P (C)));
   end loop;
   Put_Line ("String length:" & Integer'Image (String'("hello")'Length));
end Array_Attributes;
