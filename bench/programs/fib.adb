with Ada.Text_IO; use Ada.Text_IO;
procedure Fib is
   function F (N : Integer) return Integer is
   begin
      if N < 2 then
         return N;
      end if;
      return F (N - 1) + F (N - 2);
   end F;
begin
   Put_Line (Integer'Image (F (27)));
end Fib;
