with Ada.Text_IO; use Ada.Text_IO;

procedure Case_Statements is
   type Day is (Mon, Tue, Wed, Thu, Fri, Sat, Sun);
   subtype Small is Integer range 0 .. 20;
   procedure Describe (N : Integer) is
   begin
      Put (Integer'Image (N) & ": ");
      case N is
         when Integer'First .. -1 =>
            Put_Line ("negative");
         when 0 =>
            Put_Line ("zero");
         when 1 | 3 | 5 | 7 | 9 =>
            Put_Line ("small odd");
         when 2 | 4 | 6 | 8 =>
            Put_Line ("small even");
         when 10 .. 19 | 100 =>
            Put_Line ("teen or hundred");
         when others =>
            Put_Line ("other");
      end case;
   end Describe;
   function Kind (D : Day) return String is
   begin
      case D is
         when Mon .. Fri =>
            return "workday";
         when Sat | Sun =>
            return "weekend";
      end case;
   end Kind;
   S : Small := 0;
   C : Character;
begin
   for N in -2 .. 12 loop
      Describe (N);
   end loop;
   Describe (100);
   Describe (101);
   for D in Day loop
      Put_Line (Day'Image (D) & " is a " & Kind (D));
   end loop;
   for I in 1 .. 4 loop
      S := I * 5;
      case S is
         when 0 .. 9 => Put_Line ("S" & Integer'Image (S) & " single digit");
         when 10 | 20 => Put_Line ("S" & Integer'Image (S) & " round");
         when others => Put_Line ("S" & Integer'Image (S) & " other");
      end case;
   end loop;
   for I in 1 .. 5 loop
      C := Character'Val (Character'Pos ('a') + I * 5);
      case C is
         when 'a' | 'e' | 'i' | 'o' | 'u' => Put_Line (C & " vowel");
         when 'b' .. 'd' | 'f' .. 'h' => Put_Line (C & " early consonant");
         when others => Put_Line (C & " late letter");
      end case;
   end loop;
   case Day'Value ("sat") is
      when Sat =>
         Put_Line ("parsed Saturday");
         case Kind (Sat)'Length is
            when 7 => Put_Line ("seven letters");
            when others => Put_Line ("other length");
         end case;
      when others =>
         null;
   end case;
end Case_Statements;
