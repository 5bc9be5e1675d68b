with Ada.Text_IO; use Ada.Text_IO;

procedure Integer_Image is
   type Int_List is array (Positive range <>) of Integer;
   Values : constant Int_List :=
     (0, 1, -1, 7, -7, 42, -42, 100, -100, 999, 1000, 65535,
      123_456, -123_456, 2_000_000_000, -2_000_000_000);
   X : Integer := 17;
   Y : constant Integer := -3;
   Z : constant Integer := 0;
begin
   Put_Line ("Integer'Image of a list:");
   for I in Values'Range loop
      Put_Line ("[" & Integer'Image (Values (I)) & "]");
   end loop;
   Put_Line ("First: [" & Integer'Image (Integer'First) & "]");
   Put_Line ("Last:  [" & Integer'Image (Integer'Last) & "]");
   Put_Line ("Positive'First:" & Positive'Image (Positive'First));
   Put_Line ("Natural'First:" & Natural'Image (Natural'First));
   Put_Line ("Natural'Last:" & Natural'Image (Natural'Last));
   Put_Line ("Object image X: [" & X'Image & "]");
   Put_Line ("Object image Y: [" & Y'Image & "]");
   Put_Line ("Object image Z: [" & Z'Image & "]");
   X := X * Y;
   Put_Line ("After X := X * Y:" & X'Image);
   Put_Line ("Expression image:" & Integer'Image (X + 100));
   Put_Line ("Length of image of 5:" & Integer'Image (Integer'Image (5)'Length));
   Put_Line ("Length of image of -5:" & Integer'Image (Integer'Image (-5)'Length));
   for I in -3 .. 3 loop
      Put (Integer'Image (I * I * I));
   end loop;
   New_Line;
   Put_Line (Integer'Image (2 ** 30) & Integer'Image (-(2 ** 30)));
end Integer_Image;
