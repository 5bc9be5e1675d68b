with Ada.Text_IO; use Ada.Text_IO;

procedure Float_Conversions is
   type Float_List is array (Positive range <>) of Float;
   Values : constant Float_List :=
     (0.0, 0.4, 0.5, 0.6, 1.5, 2.5, 3.5, -0.4, -0.5, -1.5, -2.5, -2.6, 99.49, 99.5, -1000.5);
   I : Integer := 7;
   F : Float;
begin
   for K in Values'Range loop
      Put_Line ("Integer (" & Float'Image (Values (K)) & ") =" & Integer'Image (Integer (Values (K))));
   end loop;
   F := Float (I);
   Put_Line ("Float (7) =" & Float'Image (F));
   F := Float (I) / 2.0;
   Put_Line ("Float (7) / 2.0 =" & Float'Image (F));
   Put_Line ("Integer (7 / 2) =" & Integer'Image (I / 2));
   Put_Line ("Integer (Float (7) / 2.0) =" & Integer'Image (Integer (F)));
   I := Integer (Float (I) * 1.5);
   Put_Line ("Integer (7 * 1.5) =" & Integer'Image (I));
   Put_Line ("Float (-3) =" & Float'Image (Float (-3)));
   Put_Line ("Float (Integer'Last / 1000) =" & Float'Image (Float (Integer'Last / 1000)));
   F := 2.0 ** 3;
   Put_Line ("2.0 ** 3 =" & Float'Image (F));
   Put_Line ("2.0 ** (-2) =" & Float'Image (2.0 ** (-2)));
   Put_Line ("abs (-4.5) =" & Float'Image (abs (-4.5)));
   Put_Line ("-4.5 * 2.0 =" & Float'Image (-4.5 * 2.0));
   Put_Line ("10.0 / 4.0 =" & Float'Image (10.0 / 4.0));
   Put_Line ("Natural (3.7) =" & Natural'Image (Natural (3.7)));
   begin
      F := -0.75;
      I := Natural (F);
      Put_Line ("not reached" & Integer'Image (I));
   exception
      when Constraint_Error =>
         Put_Line ("Natural (-0.75) raised Constraint_Error");
   end;
   begin
      F := 3.0E9;
      I := Integer (F);
      Put_Line ("not reached" & Integer'Image (I));
   exception
      when Constraint_Error =>
         Put_Line ("Integer (3.0E9) raised Constraint_Error");
   end;
end Float_Conversions;
