--  `Choice => <>` in an array aggregate: the component's default (RM 4.3.3(23.1)).
with Ada.Text_IO; use Ada.Text_IO;
procedure Array_Aggregate_Box is
   type Vec is array (1 .. 3) of Integer;
   V : Vec := (1 => 5, others => <>);
   type Inner is record
      A : Integer := 7;
      B : Integer := 8;
   end record;
   type Arr is array (1 .. 2) of Inner;
   X : Arr := (others => <>);
   Y : Arr := (1 => (A => 1, B => <>), 2 => <>);
begin
   Put_Line (Integer'Image (V (1)));
   Put_Line (Integer'Image (X (1).A) & Integer'Image (X (2).B));
   Put_Line (Integer'Image (Y (1).A) & Integer'Image (Y (1).B) & Integer'Image (Y (2).A));
end Array_Aggregate_Box;
