with Ada.Text_IO; use Ada.Text_IO;
with Ada.Float_Text_IO; use Ada.Float_Text_IO;

procedure Float_Put_Rounding is
   procedure Line (Label : String; X : Float; Aft : Natural; Exp : Natural := 0) is
   begin
      Put (Label & " -> ");
      Put (X, Fore => 1, Aft => Aft, Exp => Exp);
      New_Line;
   end Line;
begin
   Line ("7.25 aft 1", 7.25, 1);
   Line ("-7.25 aft 1", -7.25, 1);
   Line ("7.75 aft 1", 7.75, 1);
   Line ("0.5 aft 0", 0.5, 0);
   Line ("1.5 aft 0", 1.5, 0);
   Line ("2.5 aft 0", 2.5, 0);
   Line ("-2.5 aft 0", -2.5, 0);
   Line ("0.125 aft 2", 0.125, 2);
   Line ("0.375 aft 2", 0.375, 2);
   Line ("-0.375 aft 2", -0.375, 2);
   Line ("9.96875 aft 2", 9.96875, 2);
   Line ("99.5 aft 0", 99.5, 0);
   Line ("999.9375 aft 1", 999.9375, 1);
   Line ("1234.125 exp", 1234.125, 5, 3);
   Line ("1234.375 exp", 1234.375, 5, 3);
   Line ("2.5 aft 0 exp", 2.5, 0, 2);
   Line ("9.5 aft 0 exp", 9.5, 0, 2);
   Line ("-9.75 aft 1 exp", -9.75, 1, 3);
   Line ("0.00001 aft 4", 0.00001, 4);
   Line ("-0.00001 aft 4", -0.00001, 4);
   Line ("-0.00001 aft 0", -0.00001, 0);
   Line ("-0.04 aft 1", -0.04, 1);
   Line ("-0.06 aft 1", -0.06, 1);
   Line ("0.0 aft 3", 0.0, 3);
   Put (-0.00001, 1, 4, 0); New_Line;
   Put (-0.00001, 6, 2, 0); New_Line;
   Put (0.96875, 1, 1, 0); New_Line;
   Put (0.96875, 1, 1, 2); New_Line;
end Float_Put_Rounding;
