--  Duration is GNAT's 64-bit count of nanoseconds.
with Ada.Text_IO; use Ada.Text_IO;
procedure Duration_Range is
   D : Duration := 0.1;
begin
   Put_Line (Duration'Image (Duration'Last));
   Put_Line (Duration'Image (Duration'First));
   Put_Line (Duration'Image (D));
   Put_Line (Duration'Image (D * 3));
   Put_Line (Duration'Image (-1.5));
end Duration_Range;
