with Ada.Text_IO; use Ada.Text_IO;

procedure Character_Attrs is
   C : Character := 'A';
   Word : constant String := "Ada Lovelace 1815";
   Upper, Lower, Digit, Other : Natural := 0;
   function To_Upper (Ch : Character) return Character is
   begin
      if Ch in 'a' .. 'z' then
         return Character'Val (Character'Pos (Ch) - Character'Pos ('a') + Character'Pos ('A'));
      else
         return Ch;
      end if;
   end To_Upper;
   Result : String (Word'Range);
begin
   Put_Line ("Pos (A) =" & Integer'Image (Character'Pos ('A')));
   Put_Line ("Pos (a) =" & Integer'Image (Character'Pos ('a')));
   Put_Line ("Pos (0) =" & Integer'Image (Character'Pos ('0')));
   Put_Line ("Pos (space) =" & Integer'Image (Character'Pos (' ')));
   Put_Line ("Val (66) = " & Character'Val (66));
   Put_Line ("Image (C) = " & Character'Image (C));
   Put_Line ("C'Image = " & C'Image);
   Put_Line ("Image ('''') = " & Character'Image ('''));
   Put_Line ("Image (' ') = " & Character'Image (' '));
   C := Character'Succ (C);
   Put_Line ("Succ = " & C);
   C := Character'Pred ('z');
   Put_Line ("Pred (z) = " & C);
   Put_Line ("First pos =" & Integer'Image (Character'Pos (Character'First)));
   Put_Line ("Last pos =" & Integer'Image (Character'Pos (Character'Last)));
   for I in 0 .. 9 loop
      Put (Character'Val (Character'Pos ('0') + I));
   end loop;
   New_Line;
   for Ch in Character range 'a' .. 'j' loop
      Put (Ch);
      Put (' ');
   end loop;
   New_Line;
   for I in Word'Range loop
      case Word (I) is
         when 'A' .. 'Z' => Upper := Upper + 1;
         when 'a' .. 'z' => Lower := Lower + 1;
         when '0' .. '9' => Digit := Digit + 1;
         when others => Other := Other + 1;
      end case;
      Result (I) := To_Upper (Word (I));
   end loop;
   Put_Line (Result);
   Put_Line ("upper" & Integer'Image (Upper) & " lower" & Integer'Image (Lower)
             & " digit" & Integer'Image (Digit) & " other" & Integer'Image (Other));
   Put_Line ("C < 'z': " & Boolean'Image (C < 'z') & ", C < 'Z': " & Boolean'Image (C < 'Z')
             & ", C = Character'('y'): " & Boolean'Image (C = Character'('y')));
   Put_Line ("Value = " & Character'Image (Character'Value ("'x'")));
end Character_Attrs;
