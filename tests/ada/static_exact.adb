with Ada.Text_IO; use Ada.Text_IO;
procedure Static_Exact is
   Big : constant := Integer'Last + 1 - 1;
   A : constant := 0.1;
   B : constant := 0.2;
   C : constant := 0.3;
   Third : constant := 1.0 / 3.0;
   N : Integer := Integer'Last + 1 - 1;
begin
   Put_Line (Integer'Image (Big));
   Put_Line (Integer'Image (N));
   if A + B = C then
      Put_Line ("0.1 + 0.2 = 0.3 for named numbers");
   else
      Put_Line ("inexact");
   end if;
   if Third * 3.0 = 1.0 then
      Put_Line ("exact third");
   end if;
   Put_Line (Integer'Image (2 ** 40 / 2 ** 38));
end Static_Exact;
