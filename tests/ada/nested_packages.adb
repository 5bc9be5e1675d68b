with Ada.Text_IO; use Ada.Text_IO;

procedure Nested_Packages is
   package Geometry is
      type Point is record
         X, Y : Integer;
      end record;
      Origin : constant Point := (0, 0);
      function Manhattan (A, B : Point) return Integer;
      procedure Print (P : Point);
      Bad_Point : exception;
   end Geometry;

   package body Geometry is
      function Manhattan (A, B : Point) return Integer is
      begin
         return abs (A.X - B.X) + abs (A.Y - B.Y);
      end Manhattan;
      procedure Print (P : Point) is
      begin
         if P.X < -1000 then
            raise Bad_Point with "x too small";
         end if;
         Put_Line ("(" & Integer'Image (P.X) & "," & Integer'Image (P.Y) & " )");
      end Print;
   end Geometry;

   package Counters is
      Count : Integer := 0;
      procedure Tick;
      function Value return Integer;
   end Counters;

   package body Counters is
      Step : constant Integer := 5;
      procedure Tick is
      begin
         Count := Count + Step;
      end Tick;
      function Value return Integer is
      begin
         return Count;
      end Value;
   end Counters;

   use Geometry;
   P : Point := (3, -4);
begin
   Print (P);
   Geometry.Print (Origin);
   Put_Line ("distance:" & Integer'Image (Manhattan (P, Geometry.Origin)));
   P := (X => -2000, Y => 1);
   begin
      Print (P);
   exception
      when Bad_Point =>
         Put_Line ("Geometry.Bad_Point caught");
   end;
   begin
      Geometry.Print (P);
   exception
      when Geometry.Bad_Point =>
         Put_Line ("caught again");
         raise Geometry.Bad_Point with "and again";
   end;
exception
   when Geometry.Bad_Point =>
      for I in 1 .. 3 loop
         Counters.Tick;
      end loop;
      Put_Line ("Counters.Value =" & Integer'Image (Counters.Value));
      Counters.Count := 1;
      Counters.Tick;
      Put_Line ("Counters.Count =" & Integer'Image (Counters.Count));
end Nested_Packages;
