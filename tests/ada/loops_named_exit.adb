with Ada.Text_IO; use Ada.Text_IO;

procedure Loops_Named_Exit is
   type Grid is array (1 .. 4, 1 .. 5) of Integer;
   G : Grid;
   Found_I, Found_J : Integer := 0;
   Total : Integer := 0;
begin
   for I in G'Range (1) loop
      for J in G'Range (2) loop
         G (I, J) := I * J;
      end loop;
   end loop;
   Search :
   for I in G'Range (1) loop
      for J in G'Range (2) loop
         if G (I, J) = 12 then
            Found_I := I;
            Found_J := J;
            exit Search;
         end if;
      end loop;
   end loop Search;
   Put_Line ("12 found at" & Integer'Image (Found_I) & "," & Integer'Image (Found_J));
   Outer :
   for I in 1 .. 10 loop
      Inner :
      for J in 1 .. 10 loop
         exit Inner when J > I;
         exit Outer when I * J > 20;
         Total := Total + I * J;
      end loop Inner;
      Put_Line ("row" & Integer'Image (I) & " total" & Integer'Image (Total));
   end loop Outer;
   Put_Line ("final total" & Integer'Image (Total));
   Total := 0;
   Counting :
   while Total < 100 loop
      Total := Total + 7;
      exit Counting when Total mod 5 = 0;
   end loop Counting;
   Put_Line ("first multiple of 35:" & Integer'Image (Total));
   Total := 0;
   Forever :
   loop
      Total := Total + 1;
      Skip :
      for K in 1 .. 3 loop
         exit Skip when K = 2;
         Put (Integer'Image (Total * 10 + K));
      end loop Skip;
      exit Forever when Total = 3;
   end loop Forever;
   New_Line;
   Put_Line ("Total =" & Integer'Image (Total));
end Loops_Named_Exit;
