--  A string literal of an array type whose index subtype does not start at 1
--  starts at that subtype's first (RM 4.2(11)).
with Ada.Text_IO; use Ada.Text_IO;
procedure String_Literal_Lower_Bound is
   subtype Idx is Integer range 10 .. 20;
   type Str is array (Idx range <>) of Character;
   type S3 is array (Integer range <>) of Character;
   X : Str := "ab";
   E : Str := "";
   Y : S3 := "cd";
   procedure Show (V : Str) is
   begin
      Put_Line (Integer'Image (V'First) & Integer'Image (V'Last));
   end Show;
begin
   Put_Line (Integer'Image (X'First) & Integer'Image (X'Last) & " " & Character'Image (X (11)));
   Put_Line (Integer'Image (E'First) & Integer'Image (E'Last));
   Put_Line (Integer'Image (Y'First));
   Show ("xyz");
   Show ("");
   Show (X & "q");
end String_Literal_Lower_Bound;
