with Ada.Text_IO; use Ada.Text_IO;
procedure Matrix is
   type Mat is array (1 .. 4, 1 .. 4) of Float;
   function Mul (A, B : Mat) return Mat is
      C : Mat := (others => (others => 0.0));
   begin
      for I in 1 .. 4 loop
         for J in 1 .. 4 loop
            for K in 1 .. 4 loop
               C (I, J) := C (I, J) + A (I, K) * B (K, J);
            end loop;
         end loop;
      end loop;
      return C;
   end Mul;
   R : Mat := ((1.0, 0.0, 0.0, 0.0), (0.0, 1.0, 0.0, 0.0), (0.0, 0.0, 1.0, 0.0), (0.0, 0.0, 0.0, 1.0));
   T : constant Mat := ((0.0, -1.0, 0.0, 1.0), (1.0, 0.0, 0.0, 2.0), (0.0, 0.0, 1.0, 3.0), (0.0, 0.0, 0.0, 1.0));
begin
   for N in 1 .. 200_000 loop
      R := Mul (R, T);
   end loop;
   Put_Line (Float'Image (R (1, 4)) & Float'Image (R (2, 4)) & Float'Image (R (3, 4)));
end Matrix;
