with Ada.Text_IO; use Ada.Text_IO;

procedure Membership_Tests is
   type Day is (Mon, Tue, Wed, Thu, Fri, Sat, Sun);
   subtype Weekend is Day range Sat .. Sun;
   subtype Digit is Integer range 0 .. 9;
   Lo : Integer := 3;
   Hi : constant Integer := 7;
   procedure Check (X : Integer) is
   begin
      Put_Line (Integer'Image (X) & ": in 1 .. 5 = " & Boolean'Image (X in 1 .. 5)
                & ", not in 1 .. 5 = " & Boolean'Image (X not in 1 .. 5)
                & ", in Digit = " & Boolean'Image (X in Digit)
                & ", in Lo .. Hi = " & Boolean'Image (X in Lo .. Hi)
                & ", in Natural = " & Boolean'Image (X in Natural));
   end Check;
   F : constant Float := 2.5;
   Ch : Character := 'q';
begin
   for X in -1 .. 11 loop
      Check (X);
   end loop;
   Lo := 10;
   Check (8);
   for D in Day loop
      if D in Weekend then
         Put_Line (Day'Image (D) & " weekend");
      elsif D in Mon .. Wed then
         Put_Line (Day'Image (D) & " early week");
      elsif D not in Weekend then
         Put_Line (Day'Image (D) & " late week");
      end if;
   end loop;
   Put_Line ("F in 0.0 .. 3.0 = " & Boolean'Image (F in 0.0 .. 3.0));
   Put_Line ("F in 2.6 .. 3.0 = " & Boolean'Image (F in 2.6 .. 3.0));
   Put_Line ("'q' in 'a' .. 'z' = " & Boolean'Image (Ch in 'a' .. 'z'));
   Ch := 'Q';
   Put_Line ("'Q' in 'a' .. 'z' = " & Boolean'Image (Ch in 'a' .. 'z'));
   Put_Line ("empty range: " & Boolean'Image (Lo in 5 .. 4));
   Put_Line ("combined: " & Boolean'Image (Lo in 1 .. 10 and Lo not in 5 .. 9));
end Membership_Tests;
