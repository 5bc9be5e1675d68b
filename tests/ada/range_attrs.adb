with Ada.Text_IO; use Ada.Text_IO;
procedure Range_Attrs is
   type Grid is array (1 .. 3, 0 .. 4) of Integer;
   type Mat is array (Positive range <>, Positive range <>) of Integer;
   G : Grid := (others => (others => 1));
   M : Mat := ((1, 2, 3), (4, 5, 6));
   V : array (2 .. 5) of Integer := (others => 0);
   X : Integer := 3;
begin
   if X in V'Range then
      Put_Line ("in range");
   end if;
   if 7 not in V'Range then
      Put_Line ("7 not in range");
   end if;
   Put_Line (Integer'Image (G'First (2)) & Integer'Image (G'Last (2)));
   Put_Line (Integer'Image (G'Length (1)) & Integer'Image (G'Length (2)));
   for I in G'Range (1) loop
      for J in G'Range (2) loop
         G (I, J) := I * 10 + J;
      end loop;
   end loop;
   Put_Line (Integer'Image (G (3, 4)));
   Put_Line (Integer'Image (M'First (1)) & Integer'Image (M'Last (1))
             & Integer'Image (M'First (2)) & Integer'Image (M'Last (2)));
   for I in M'Range (1) loop
      for J in M'Range (2) loop
         Put (Integer'Image (M (I, J)));
      end loop;
      New_Line;
   end loop;
end Range_Attrs;
