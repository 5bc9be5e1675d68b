with Ada.Text_IO; use Ada.Text_IO;
procedure Sole_Arg_Ifexpr is
   X : Integer := 5;
   function Twice (N : Integer) return Integer is
   begin
      return 2 * N;
   end Twice;
begin
   Put_Line (if X > 3 then "big" else "small");
   Put_Line (Integer'Image (Twice (if X > 3 then 10 else 20)));
   Put_Line (case X is when 5 => "five", when others => "other");
   Put_Line (Integer'Image (Twice (case X is when 1 => 1, when others => 7)));
end Sole_Arg_Ifexpr;
