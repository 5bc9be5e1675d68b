with Ada.Text_IO; use Ada.Text_IO;
with Ada.Float_Text_IO; use Ada.Float_Text_IO;

procedure Float_Put_Formats is
   type Float_List is array (Positive range <>) of Float;
   Values : constant Float_List :=
     (0.0, 1.0, -1.0, 3.14159, -3.14159, 830.6, 0.015625, -0.5, 12345.0, 1.0E-5);
   procedure Show (X : Float; Fore, Aft, Exp : Natural) is
   begin
      Put ("[");
      Put (X, Fore, Aft, Exp);
      Put ("]");
   end Show;
begin
   for I in Values'Range loop
      Put ("[");
      Put (Values (I));
      Put ("]");
      Show (Values (I), 1, 0, 0);
      Show (Values (I), 3, 2, 0);
      Show (Values (I), 0, 3, 2);
      Show (Values (I), 1, 1, 4);
      Show (Values (I), 6, 4, 3);
      Show (Values (I), 2, 0, 1);
      New_Line;
   end loop;
   Put (2.5, Fore => 5, Aft => 2, Exp => 0); New_Line;
   Put (Item => -2.5, Fore => 1, Aft => 3, Exp => 0); New_Line;
   Put (100.0, Exp => 0); New_Line;
   Put (100.0, Aft => 1); New_Line;
   Put (100.0, Fore => 8); New_Line;
   Put (0.125, 1, 6, 0); New_Line;
   Put (-0.125, 0, 1, 0); New_Line;
   Put (1.0E10, 1, 1, 0); New_Line;
   Put (1.0E-10, 1, 3, 4); New_Line;
   Put (123.456, 1, 2, 2); New_Line;
   Put (5.0E-3, 2, 0, 3); New_Line;
end Float_Put_Formats;
