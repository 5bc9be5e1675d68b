with Ada.Text_IO; use Ada.Text_IO;

procedure Float_Image is
   type Float_List is array (Positive range <>) of Float;
   Values : constant Float_List :=
     (0.0, 1.0, -1.0, 0.5, -0.5, 0.1, -0.1, 2.5, 10.0, 100.0,
      830.6, -830.6, 1234.125, 1234.375, 99999.5, 123456.0,
      1.0E10, 1.0E-10, -1.0E-10, 3.0E20, 1.5E-5, 0.001, 7.0E-3,
      999999.0, 0.25, 0.125, 0.0625, 1024.0, 4.0E6, -65536.0);
   F : Float := 2.0;
   G : Float := -0.75;
begin
   for I in Values'Range loop
      Put_Line (Integer'Image (I) & ": [" & Float'Image (Values (I)) & "]");
   end loop;
   Put_Line ("F'Image:" & F'Image);
   Put_Line ("G'Image:" & G'Image);
   F := F * 1.5;
   Put_Line ("F * 1.5:" & Float'Image (F));
   G := G / 4.0;
   Put_Line ("G / 4.0:" & Float'Image (G));
   Put_Line ("Negative zero:" & Float'Image (-F * 0.0));
   Put_Line ("1/3:" & Float'Image (1.0 / 3.0));
   Put_Line ("2/3:" & Float'Image (2.0 / 3.0));
   Put_Line ("Sum:" & Float'Image (0.5 + 0.25 + 0.125));
   Put_Line ("Length of image:" & Integer'Image (Float'Image (1.0)'Length));
   Put_Line ("Length of negative image:" & Integer'Image (Float'Image (-1.0)'Length));
end Float_Image;
