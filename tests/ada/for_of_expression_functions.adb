with Ada.Text_IO; use Ada.Text_IO;
procedure For_Of_Expression_Functions is
   type Arr is array (1 .. 4) of Integer;
   type Grid is array (1 .. 2, 1 .. 3) of Integer;
   A : Arr := (1, 2, 3, 4);
   G : Grid := ((1, 2, 3), (4, 5, 6));
   C : constant Arr := (10, 20, 30, 40);
   S : String := "abc";
   Sum : Integer := 0;
   function Sq (X : Integer) return Integer is (X * X);
   function Sgn (X : Integer) return Integer is
     (if X > 0 then 1 elsif X < 0 then -1 else 0);
   function Kind (X : Integer) return String is
     (case X mod 3 is when 0 => "zero", when 1 => "one", when others => "two");
   function Make return Arr is ((5, 6, 7, 8));
begin
   for E of A loop
      E := Sq (E);
   end loop;
   for E of A loop
      Put (Integer'Image (E));
   end loop;
   New_Line;
   for E of reverse A loop
      Put (Integer'Image (E) & Integer'Image (Sgn (E - 5)));
   end loop;
   New_Line;
   for E of G loop
      Put (Integer'Image (E));
      E := E * 10;
   end loop;
   New_Line;
   for E of reverse G loop
      Put (Integer'Image (E));
   end loop;
   New_Line;
   for E of C loop
      Sum := Sum + E;
   end loop;
   Put_Line (Integer'Image (Sum));
   for Ch of S loop
      Ch := Character'Succ (Ch);
   end loop;
   Put_Line (S);
   for E of Make loop
      Put (" " & Kind (E));
      exit when E = 7;
   end loop;
   New_Line;
   for E of A (2 .. 3) loop
      E := 0;
   end loop;
   for E of A loop
      Put (Integer'Image (E));
   end loop;
   New_Line;
end For_Of_Expression_Functions;
