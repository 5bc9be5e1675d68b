with Ada.Text_IO; use Ada.Text_IO;

procedure Aggregates_Nested is
   type Row is array (1 .. 4) of Integer;
   type Table is array (1 .. 3) of Row;
   type Matrix is array (1 .. 3, 1 .. 3) of Integer;
   type Pair is record
      Left, Right : Integer;
   end record;
   type Pair_List is array (1 .. 4) of Pair;
   type Box is record
      Corner : Pair;
      Size   : Row;
   end record;
   T : Table := ((1, 2, 3, 4), (others => 0), (1 => 9, 4 => 6, others => -1));
   M : constant Matrix := (1 => (1, 0, 0), 2 => (1 => 0, others => 2), 3 => (3 => 1, others => 0));
   P : constant Pair_List := (1 => (1, 2), 2 | 3 => (Left => 5, Right => 6), others => (0, 0));
   B : constant Box := (Corner => (Right => 7, Left => 8), Size => (2 .. 3 => 5, others => 1));
   R : Row := (2 .. 3 => 7, others => 0);
begin
   for I in T'Range loop
      for J in Row'Range loop
         Put (Integer'Image (T (I) (J)));
      end loop;
      New_Line;
   end loop;
   for I in 1 .. 3 loop
      for J in 1 .. 3 loop
         Put (Integer'Image (M (I, J)));
      end loop;
      New_Line;
   end loop;
   for I in P'Range loop
      Put_Line ("P" & Integer'Image (I) & " =" & Integer'Image (P (I).Left) & Integer'Image (P (I).Right));
   end loop;
   Put_Line ("B.Corner =" & Integer'Image (B.Corner.Left) & Integer'Image (B.Corner.Right));
   for J in B.Size'Range loop
      Put (Integer'Image (B.Size (J)));
   end loop;
   New_Line;
   for J in R'Range loop
      Put (Integer'Image (R (J)));
   end loop;
   New_Line;
   T (2) := R;
   T (3) (2) := 100;
   R := (1 | 3 => 4, 2 | 4 => 8);
   for I in T'Range loop
      for J in Row'Range loop
         Put (Integer'Image (T (I) (J)));
      end loop;
      New_Line;
   end loop;
   Put_Line ("R sum =" & Integer'Image (R (1) + R (2) + R (3) + R (4)));
end Aggregates_Nested;
