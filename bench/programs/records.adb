--  A list of 100,000 parts, each with a 4-character tag built character by
--  character, made with allocators and walked with a slice comparison.
with Ada.Text_IO; use Ada.Text_IO;
procedure Records is
   type Part;
   type Part_Ptr is access Part;
   type Part is record
      Tag   : String (1 .. 4);
      Count : Integer;
      Next  : Part_Ptr;
   end record;
   Letters : constant String := "ABCDEFGHIJKLMNOPQRSTUVWXYZ";
   Head    : Part_Ptr := null;
   P       : Part_Ptr;
   T       : String (1 .. 4);
   N       : Integer;
   Matches : Integer := 0;
   Total   : Integer := 0;
begin
   for I in 1 .. 100_000 loop
      N := I;
      for K in 1 .. 4 loop
         T (K) := Letters (N mod 26 + 1);
         N := N / 26;
      end loop;
      Head := new Part'(Tag => T, Count => I mod 7, Next => Head);
   end loop;
   P := Head;
   while P /= null loop
      if P.Tag (1 .. 2) = "BA" then
         Matches := Matches + 1;
      end if;
      Total := Total + P.Count;
      P := P.Next;
   end loop;
   Put_Line (Integer'Image (Matches) & Integer'Image (Total));
end Records;
