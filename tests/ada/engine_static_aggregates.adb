--  An aggregate of literals with static bounds has the same value each
--  time: adair makes it once per run. Changing an object it initialised
--  must not change the next object, and a component subtype that depends
--  on a parameter is checked again at each call.
with Ada.Text_IO; use Ada.Text_IO;
procedure Engine_Static_Aggregates is
   type Mat is array (1 .. 2, 1 .. 3) of Float;
   type Row is array (1 .. 3) of Integer;

   function Fresh return Mat is
      M : Mat := (others => (others => 0.5));
   begin
      M (1, 1) := M (1, 1) + 1.0;
      return M;
   end Fresh;

   procedure Limited_To (N : Integer) is
      subtype Small is Integer range 1 .. N;
      type Smalls is array (1 .. 3) of Small;
      S : Smalls := (5, 5, 5);
   begin
      Put_Line ("limit" & Integer'Image (N) & " ok" & Integer'Image (S (2)));
   end Limited_To;

   procedure Ones (N : Integer) is
      type Row_N is array (1 .. N) of Integer;
      R : Row_N := (others => 1);
      Sum : Integer := 0;
   begin
      for I in R'Range loop
         Sum := Sum + R (I);
      end loop;
      Put_Line ("ones" & Integer'Image (N) & Integer'Image (Sum));
   end Ones;

   Total : Float := 0.0;
   R     : Row;
begin
   for I in 1 .. 3 loop
      declare
         M : Mat := Fresh;
      begin
         Total := Total + M (1, 1) + M (2, 3);
      end;
   end loop;
   Put_Line (Integer'Image (Integer (Total * 10.0)));
   for I in 1 .. 3 loop
      R := (1, 2, 3);
      R (I) := R (I) * 100;
      Put_Line (Integer'Image (R (1)) & Integer'Image (R (2)) & Integer'Image (R (3)));
   end loop;
   Ones (4);
   Ones (2);
   Ones (6);
   for N in reverse 1 .. 3 loop
      begin
         Limited_To (N * 3);
      exception
         when Constraint_Error =>
            Put_Line ("limit" & Integer'Image (N * 3) & " Constraint_Error");
      end;
   end loop;
end Engine_Static_Aggregates;
