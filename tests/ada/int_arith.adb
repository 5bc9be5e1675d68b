with Ada.Text_IO; use Ada.Text_IO;

procedure Int_Arith is
   procedure Show (A, B : Integer) is
   begin
      Put_Line (Integer'Image (A) & "," & Integer'Image (B) & ":  /" & Integer'Image (A / B)
                & "  mod" & Integer'Image (A mod B) & "  rem" & Integer'Image (A rem B));
   end Show;
   X : constant Integer := 7;
   Y : Integer := 3;
begin
   Show (7, 3);
   Show (-7, 3);
   Show (7, -3);
   Show (-7, -3);
   Show (6, 3);
   Show (-6, 3);
   Show (0, 5);
   Show (1, 10);
   Show (-1, 10);
   Show (13, -4);
   Put_Line ("-7 mod 3 =" & Integer'Image (-7 mod 3));
   Put_Line ("(-7) mod 3 =" & Integer'Image ((-7) mod 3));
   Put_Line ("-X mod Y =" & Integer'Image (-X mod Y));
   Put_Line ("-7 rem 3 =" & Integer'Image (-7 rem 3));
   Put_Line ("-2 ** 2 =" & Integer'Image (-2 ** 2));
   Put_Line ("(-2) ** 2 =" & Integer'Image ((-2) ** 2));
   Put_Line ("(-2) ** 3 =" & Integer'Image ((-2) ** 3));
   Put_Line ("2 ** 10 =" & Integer'Image (2 ** 10));
   Put_Line ("3 ** 0 =" & Integer'Image (3 ** 0));
   Put_Line ("10 ** 9 =" & Integer'Image (10 ** 9));
   Put_Line ("abs -5 =" & Integer'Image (abs (-5)));
   Put_Line ("abs X - 10 =" & Integer'Image (abs (X - 10)));
   Put_Line ("-abs (Y + 1) =" & Integer'Image (-abs (Y + 1)));
   Put_Line ("2 + 3 * 4 =" & Integer'Image (2 + 3 * 4));
   Put_Line ("(2 + 3) * 4 =" & Integer'Image ((2 + 3) * 4));
   Put_Line ("20 / 3 * 3 =" & Integer'Image (20 / 3 * 3));
   Put_Line ("20 - 3 - 4 =" & Integer'Image (20 - 3 - 4));
   Put_Line ("100 / 10 / 5 =" & Integer'Image (100 / 10 / 5));
   Put_Line ("-9 / 2 =" & Integer'Image (-9 / 2));
   Put_Line ("9 / -2 =" & Integer'Image (9 / (-2)));
   Put_Line ("+5 - -3 =" & Integer'Image (+5 - (-3)));
   Y := Y ** 2 * 2 ** 3;
   Put_Line ("Y ** 2 * 2 ** 3 =" & Integer'Image (Y));
   Y := X mod 4 * 3 + X rem 2;
   Put_Line ("X mod 4 * 3 + X rem 2 =" & Integer'Image (Y));
end Int_Arith;
