--  Arrays whose components are all bytes (a String's characters, Booleans,
--  small enumerations, small integers) are stored compactly by adair; a
--  component that is not a byte turns the array into general values. Every
--  operation must see the same values either way: records with strings,
--  slices on both sides of an assignment, concatenation with characters,
--  ordering, Boolean arrays, and an Integer array that starts small.
with Ada.Text_IO; use Ada.Text_IO;
procedure Engine_Compact_Arrays is
   type Colour is (Red, Green, Blue);
   type Palette is array (1 .. 4) of Colour;
   type Flags is array (1 .. 6) of Boolean;
   type Counts is array (1 .. 5) of Integer;
   type Part is record
      Tag   : String (1 .. 4);
      Count : Integer;
   end record;
   type Parts is array (1 .. 3) of Part;

   Ps    : Parts := (others => (Tag => "....", Count => 0));
   Label : String (1 .. 10) := (others => ' ');
   Name  : String := "Gripper";
   P     : Palette := (Red, Green, Blue, Red);
   F     : Flags := (True, False, True, False, False, True);
   G     : Flags;
   C     : Counts := (others => 1);
   Sum   : Integer := 0;
   High  : Character := Character'Val (200);
   S     : String (1 .. 3);
begin
   --  Records with strings, built character by character.
   for I in Ps'Range loop
      for K in 1 .. 4 loop
         Ps (I).Tag (K) := Character'Val (Character'Pos ('A') + I + K);
      end loop;
      Ps (I).Count := I * 100;
   end loop;
   for I in Ps'Range loop
      Put_Line (Ps (I).Tag & Integer'Image (Ps (I).Count)
                & " " & Ps (I).Tag (2 .. 3));
   end loop;

   --  Slices on both sides; a slice of itself, overlapping.
   Label (1 .. 7) := Name;
   Label (8 .. 10) := Name (1 .. 3);
   Put_Line ("[" & Label & "]");
   Label (2 .. 10) := Label (1 .. 9);
   Put_Line ("[" & Label & "]");
   Label (3 .. 4) := "xy";
   Put_Line ("[" & Label (1 .. 5) & "]" & Label'Length'Image);

   --  Concatenation of characters and strings, either side empty.
   Put_Line ('<' & Name & '>' & "" & "" & Name (1 .. 0) & '!');
   S := 'a' & "bc";
   Put_Line (S & Integer'Image (S'First) & Integer'Image (S'Last));

   --  A character past 127 keeps its code.
   Label (1) := High;
   Put_Line (Integer'Image (Character'Pos (Label (1)))
             & Integer'Image (Character'Pos (High)));

   --  Ordering and equality of strings.
   Put_Line (Boolean'Image (String'("abc") < "abd") & " "
             & Boolean'Image (String'("ab") < "abc") & " "
             & Boolean'Image (Name (1 .. 4) = "Grip") & " "
             & Boolean'Image (Ps (1).Tag = Ps (2).Tag));

   --  Enumerations and Booleans.
   P (2) := Blue;
   for I in P'Range loop
      Put (Colour'Image (P (I)) & " ");
   end loop;
   New_Line;
   G := not F;
   G (1 .. 2) := F (5 .. 6);
   for I in G'Range loop
      Put (Boolean'Image (G (I) and F (I)) & " ");
   end loop;
   New_Line;
   Put_Line (Boolean'Image ((F or G) = (True, True, True, True, True, True)));

   --  An Integer array that starts with small values, then holds large
   --  and negative ones, compared with one that never was small.
   C (2) := 300;
   C (3) := -7;
   C (4 .. 5) := (1_000_000, 255);
   for I in C'Range loop
      Sum := Sum + C (I);
      Put (Integer'Image (C (I)));
   end loop;
   New_Line;
   Put_Line (Integer'Image (Sum) & " "
             & Boolean'Image (C = (1, 300, -7, 1_000_000, 255)));
end Engine_Compact_Arrays;
