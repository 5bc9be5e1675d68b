with Ada.Text_IO; use Ada.Text_IO;

procedure If_Case_Expressions is
   type Shape is (Circle, Square, Triangle, Hexagon);
   function Sides (S : Shape) return Integer is
   begin
      return (case S is
                 when Circle => 0,
                 when Square => 4,
                 when Triangle => 3,
                 when Hexagon => 6);
   end Sides;
   function Sign (X : Integer) return Integer is
   begin
      return (if X > 0 then 1 elsif X < 0 then -1 else 0);
   end Sign;
   Y : Integer;
   F : Float;
begin
   for S in Shape loop
      Put_Line (Shape'Image (S) & " has" & Integer'Image (Sides (S)) & " sides");
   end loop;
   for X in -2 .. 2 loop
      Put_Line ("Sign (" & Integer'Image (X) & " ) =" & Integer'Image (Sign (X)));
   end loop;
   for I in 1 .. 6 loop
      Put_Line (Integer'Image (I) & " is " & (if I mod 2 = 0 then "even" else "odd")
                & ", " & (case I is when 1 | 2 => "low", when 3 .. 4 => "mid", when others => "high"));
   end loop;
   Y := 10 + (if Sign (-5) < 0 then 100 else 200);
   Put_Line ("Y =" & Integer'Image (Y));
   F := (if Y > 50 then 1.5 else 2.5) * 2.0;
   Put_Line ("F =" & Float'Image (F));
   Y := (case Sides (Hexagon) is when 0 .. 3 => 1, when others => 2) * 7;
   Put_Line ("Y =" & Integer'Image (Y));
   Put_Line ("Nested: " & (if Y > 10 then (if Y > 13 then "big" else "medium") else "small"));
   Put_Line ("Boolean: " & Boolean'Image ((if Y = 14 then True else False)));
   for C in Character range 'a' .. 'c' loop
      Put_Line (C & " -> " & Character'Image ((case C is when 'a' => 'A', when 'b' => 'B', when others => '?')));
   end loop;
end If_Case_Expressions;
