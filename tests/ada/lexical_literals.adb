with Ada.Text_IO; use Ada.Text_IO;

procedure Lexical_Literals is
   Hex : constant Integer := 16#FF#;
   Oct : constant Integer := 8#340#;
   Bin : constant Integer := 2#1010_0001#;
   Big : constant Integer := 1_000_000;
   Sci : constant Integer := 2E3;
   Hex_Lower : constant Integer := 16#ff_ff#;
   F1 : constant Float := 1.0E-3;
   F2 : constant Float := 1.5e2;
   F3 : constant Float := 3_141.5;
   F4 : constant Float := 16#1.8#;
   MixedCase : Integer := 1;
begin
   Put_Line ("16#FF# =" & Integer'Image (Hex));
   Put_Line ("8#340# =" & Integer'Image (Oct));
   Put_Line ("2#1010_0001# =" & Integer'Image (Bin));
   Put_Line ("1_000_000 =" & Integer'Image (Big));
   Put_Line ("2E3 =" & Integer'Image (Sci));
   Put_Line ("16#ff_ff# =" & Integer'Image (Hex_Lower));
   Put_Line ("1.0E-3 =" & Float'Image (F1));
   Put_Line ("1.5e2 =" & Float'Image (F2));
   Put_Line ("3_141.5 =" & Float'Image (F3));
   Put_Line ("16#1.8# =" & Float'Image (F4));
   MIXEDCASE := mixedcase + 1;
   Mixedcase := MixedCase * 10;
   PUT_LINE ("MixedCase =" & INTEGER'IMAGE (mixedCASE));
   put_line ("lower case keywords and names work");
   DECLARE
      Str : CONSTANT String := "Quote "" and -- not a comment";
   BEGIN
      Put_Line (Str); -- a real comment
      Put_Line ("Length" & Integer'Image (STR'Length));
   END;
   Put_Line ("Char literals: " & 'a' & ''' & '"' & ' ' & '-');
   Put_Line ("Tick after name: " & Integer'Image (Character'Pos ('''))); --'
   Put_Line ("2#1111# + 8#17# =" & Integer'Image (2#1111# + 8#17#));
end Lexical_Literals;
