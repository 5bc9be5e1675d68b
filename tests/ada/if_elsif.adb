with Ada.Text_IO; use Ada.Text_IO;

procedure If_Elsif is
   function Classify (T : Integer) return String is
   begin
      if T < 0 then
         return "freezing";
      elsif T = 0 then
         return "zero";
      elsif T <= 15 then
         return "cold";
      elsif T in 16 .. 25 then
         return "mild";
      else
         return "hot";
      end if;
   end Classify;
   procedure Grade (Score : Integer) is
   begin
      Put ("score" & Integer'Image (Score) & ": ");
      if Score >= 90 then
         Put_Line ("A");
      elsif Score >= 80 then
         Put_Line ("B");
      elsif Score >= 70 then
         Put_Line ("C");
      else
         Put_Line ("F");
      end if;
   end Grade;
   X : Integer := 0;
begin
   for T in -1 .. 1 loop
      Put_Line (Integer'Image (T * 20) & " -> " & Classify (T * 20));
   end loop;
   Put_Line ("0 -> " & Classify (0));
   Put_Line ("10 -> " & Classify (10));
   Put_Line ("25 -> " & Classify (25));
   Put_Line ("26 -> " & Classify (26));
   Grade (95);
   Grade (90);
   Grade (85);
   Grade (70);
   Grade (12);
   for I in 1 .. 6 loop
      if I mod 2 = 0 then
         X := X + I;
         if I > 3 then
            Put_Line (Integer'Image (I) & " even and big");
         else
            Put_Line (Integer'Image (I) & " even and small");
         end if;
      end if;
   end loop;
   Put_Line ("X =" & Integer'Image (X));
   if X > 100 then
      Put_Line ("unexpected");
   end if;
   if not (X > 100) then
      Put_Line ("X is at most 100");
   end if;
   if X = 12 and X /= 13 then
      Put_Line ("X is 12");
   else
      Put_Line ("X is not 12");
   end if;
end If_Elsif;
