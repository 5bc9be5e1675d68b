with Ada.Text_IO; use Ada.Text_IO;
with Ada.Float_Text_IO; use Ada.Float_Text_IO;

procedure Frame_Matrix is
   type Frame is array (1 .. 3, 1 .. 4) of Float;
   type Matrix4 is array (1 .. 4, 1 .. 4) of Float;
   F1 : Frame := ((1.0, 0.0, 0.0, 0.0), (0.0, 1.0, 0.0, 0.0), (0.0, 0.0, 1.0, 830.6));
   A : constant Matrix4 := ((1.0, 2.0, 0.0, 1.0),
                            (0.0, 1.0, 3.0, 0.0),
                            (2.0, 0.0, 1.0, -1.0),
                            (0.0, 0.0, 0.0, 1.0));
   B : Matrix4 := (others => (others => 0.0));
   C : Matrix4;
   function Multiply (X, Y : Matrix4) return Matrix4 is
      R : Matrix4;
      Sum : Float;
   begin
      for I in X'Range (1) loop
         for J in Y'Range (2) loop
            Sum := 0.0;
            for K in X'Range (2) loop
               Sum := Sum + X (I, K) * Y (K, J);
            end loop;
            R (I, J) := Sum;
         end loop;
      end loop;
      return R;
   end Multiply;
   procedure Print (M : Matrix4) is
   begin
      for I in M'Range (1) loop
         for J in M'Range (2) loop
            Put (M (I, J), Fore => 4, Aft => 2, Exp => 0);
         end loop;
         New_Line;
      end loop;
   end Print;
begin
   for I in F1'Range (1) loop
      for J in F1'Range (2) loop
         Put (F1 (I, J), 5, 1, 0);
      end loop;
      New_Line;
   end loop;
   F1 (1, 4) := 10.0;
   F1 (2, 4) := -25.5;
   Put_Line ("F1 (1, 4) =" & Float'Image (F1 (1, 4)) & " F1 (3, 4) =" & Float'Image (F1 (3, 4)));
   Put_Line ("F1 (2, 4) =" & Float'Image (F1 (2, 4)));
   for I in 1 .. 4 loop
      B (I, I) := 2.0;
   end loop;
   B (1, 4) := 0.5;
   C := Multiply (A, B);
   Put_Line ("A * B:");
   Print (C);
   C := Multiply (C, A);
   Put_Line ("A * B * A:");
   Print (C);
   C := Multiply (A, A);
   Put_Line ("A * A:");
   Print (C);
   Put_Line ("Trace =" & Float'Image (C (1, 1) + C (2, 2) + C (3, 3) + C (4, 4)));
end Frame_Matrix;
