with Ada.Text_IO; use Ada.Text_IO;

procedure Qualified_Expressions is
   type Color is (Red, Green, Blue);
   type Signal is (Red, Yellow, Green);
   type Point is record
      X, Y : Integer;
   end record;
   type Triple is array (1 .. 3) of Integer;
   type Point_Ptr is access Point;
   subtype Small is Integer range 1 .. 10;
   function Describe (C : Color) return String is
   begin
      return "color " & Color'Image (C);
   end Describe;
   function Describe (S : Signal) return String is
   begin
      return "signal " & Signal'Image (S);
   end Describe;
   function Id (X : Integer) return Integer is
   begin
      return X;
   end Id;
   P : Point := Point'(X => 1, Y => 2);
   T : Triple := Triple'(others => 4);
   Ptr : Point_Ptr := new Point'(3, 4);
   N : Integer;
begin
   Put_Line (Describe (Color'(Red)));
   Put_Line (Describe (Signal'(Red)));
   Put_Line (Describe (Color'(Green)));
   Put_Line (Describe (Signal'(Green)));
   Put_Line (Describe (Yellow));
   Put_Line ("P =" & Integer'Image (P.X) & Integer'Image (P.Y));
   P := Point'(P.Y, P.X);
   Put_Line ("P swapped =" & Integer'Image (P.X) & Integer'Image (P.Y));
   T := Triple'(1 => 7, others => T (2) * 2);
   Put_Line ("T =" & Integer'Image (T (1)) & Integer'Image (T (2)) & Integer'Image (T (3)));
   Put_Line ("Ptr.all =" & Integer'Image (Ptr.all.X) & Integer'Image (Ptr.Y));
   Ptr := new Point'(Point'(X => -1, Y => -2));
   Put_Line ("Ptr.all =" & Integer'Image (Ptr.X) & Integer'Image (Ptr.Y));
   N := Integer'(5) * Integer'(6);
   Put_Line ("N =" & Integer'Image (N));
   Put_Line ("Small'(7) =" & Integer'Image (Small'(7)));
   Put_Line ("Float'(2.5) =" & Float'Image (Float'(2.5)));
   Put_Line ("String'(""qualified"")'Length =" & Integer'Image (String'("qualified")'Length));
   Put_Line ("Character'('z') = " & Character'('z'));
   begin
      N := Small'(Id (11));
      Put_Line ("not reached" & Integer'Image (N));
   exception
      when Constraint_Error =>
         Put_Line ("Small'(11) raised Constraint_Error");
   end;
end Qualified_Expressions;
