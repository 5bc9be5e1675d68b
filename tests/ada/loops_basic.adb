with Ada.Text_IO; use Ada.Text_IO;

procedure Loops_Basic is
   N : Integer := 1;
   Sum : Integer := 0;
   Count : Natural := 0;
   Lo : constant Integer := 3;
   Hi : Integer := 1;
begin
   for I in 1 .. 5 loop
      Put (Integer'Image (I));
   end loop;
   New_Line;
   for I in reverse 1 .. 5 loop
      Put (Integer'Image (I));
   end loop;
   New_Line;
   for I in -2 .. 2 loop
      Sum := Sum + I * I;
   end loop;
   Put_Line ("sum of squares:" & Integer'Image (Sum));
   for I in Lo .. Hi loop
      Put_Line ("never: empty range");
   end loop;
   for I in reverse Lo .. Hi loop
      Put_Line ("never: empty reverse range");
   end loop;
   Hi := 6;
   for I in Lo .. Hi loop
      Hi := 0;
      Put (Integer'Image (I));
   end loop;
   New_Line;
   Put_Line ("Hi changed inside loop:" & Integer'Image (Hi));
   while N < 1000 loop
      N := N * 3;
      Count := Count + 1;
   end loop;
   Put_Line ("N =" & Integer'Image (N) & " after" & Integer'Image (Count) & " steps");
   while N > 5000 loop
      Put_Line ("never");
   end loop;
   N := 27;
   Count := 0;
   loop
      exit when N = 1;
      if N mod 2 = 0 then
         N := N / 2;
      else
         N := 3 * N + 1;
      end if;
      Count := Count + 1;
   end loop;
   Put_Line ("Collatz steps for 27:" & Integer'Image (Count));
   Count := 0;
   loop
      Count := Count + 1;
      if Count = 4 then
         exit;
      end if;
   end loop;
   Put_Line ("Count =" & Integer'Image (Count));
   for I in 1 .. 3 loop
      for J in reverse I .. 3 loop
         Put (Integer'Image (I * 10 + J));
      end loop;
      New_Line;
   end loop;
   for C in Character range 'x' .. 'z' loop
      Put (C);
   end loop;
   New_Line;
end Loops_Basic;
