with Ada.Text_IO; use Ada.Text_IO;
procedure Case_Static_Loop is
   subtype Small is Integer range 1 .. 4;
   C : Character;
begin
   for I in Small loop
      case I is
         when 1 => Put_Line ("one");
         when 2 | 3 => Put_Line ("two or three");
         when 4 => Put_Line ("four");
      end case;
   end loop;
   for I in 1 .. 3 loop
      case I is
         when 1 .. 2 => Put_Line ("low");
         when others => Put_Line ("high");
      end case;
   end loop;
   for I in 1 .. 3 loop
      case I is
         when 1 => Put_Line ("I = 1");
         when 2 => Put_Line ("I = 2");
         when 3 => Put_Line ("I = 3");
      end case;
   end loop;
   declare
      S : Small := 2;
      type Color is (Red, Green, Blue);
      subtype Warm is Color range Red .. Green;
      W : Warm := Green;
   begin
      case S is
         when 1 .. 2 => Put_Line ("S low");
         when 3 .. 4 => Put_Line ("S high");
      end case;
      case W is
         when Red => Put_Line ("red");
         when Green => Put_Line ("green");
      end case;
      for K in Warm loop
         case K is
            when Red => Put_Line ("K red");
            when Green => Put_Line ("K green");
         end case;
      end loop;
   end;
   C := Character'Val (65);
   case C is
      when Character'Val (65) => Put_Line ("A by Val");
      when 'B' => Put_Line ("B");
      when others => Put_Line ("other");
   end case;
end Case_Static_Loop;
