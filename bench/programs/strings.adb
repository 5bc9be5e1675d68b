--  Strings as robot programs use them: labels made with Integer'Image and
--  "&", read back character by character and compared by slices.
with Ada.Text_IO; use Ada.Text_IO;
procedure Strings is
   Sum   : Integer := 0;
   Count : Integer := 0;
begin
   for I in 1 .. 200_000 loop
      declare
         S : constant String :=
           "P" & Integer'Image (I) & ":" & Integer'Image (I mod 97);
      begin
         for K in S'Range loop
            Sum := Sum + Character'Pos (S (K));
         end loop;
         if S (S'Last - 1 .. S'Last) = " 1" then
            Count := Count + 1;
         end if;
      end;
   end loop;
   Put_Line (Integer'Image (Count) & Integer'Image (Sum));
end Strings;
