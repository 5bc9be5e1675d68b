--  Subprogram renamings in a cell controller: a motion procedure under a
--  shorter name with its own parameter names and defaults, operators on a
--  vector record renamed from named functions and back, predefined
--  operators and attributes renamed as functions, a renaming-as-body, and
--  an enumeration literal renamed as a function.
with Ada.Text_IO; use Ada.Text_IO;
procedure Renaming_Subprograms is
   type Vec is record
      X, Y, Z : Integer;
   end record;

   function Add (L, R : Vec) return Vec is
   begin
      return (L.X + R.X, L.Y + R.Y, L.Z + R.Z);
   end Add;

   function Scale (V : Vec; K : Integer) return Vec is
   begin
      return (V.X * K, V.Y * K, V.Z * K);
   end Scale;

   function "+" (L, R : Vec) return Vec renames Add;
   function "*" (V : Vec; K : Integer) return Vec renames Scale;
   function Sum (A, B : Vec) return Vec renames "+";       --  renames the renaming

   function Image (V : Vec) return String is
   begin
      return "(" & Integer'Image (V.X) & "," & Integer'Image (V.Y) & ","
        & Integer'Image (V.Z) & " )";
   end Image;

   subtype Speed is Integer range 1 .. 100;
   Moves : Natural := 0;

   procedure Move_To (Target : Vec; Velocity : Speed := 50) is
   begin
      Moves := Moves + 1;
      Put_Line ("move to " & Image (Target) & " at" & Integer'Image (Velocity));
   end Move_To;

   --  The renaming's own parameter names and default; Move_To's subtype
   --  Speed still bounds Rate (RM 8.5.4(7)).
   procedure Go (Goal : Vec; Rate : Integer := 20) renames Move_To;

   procedure Count_Up (N : in out Natural) is
   begin
      N := N + 1;
   end Count_Up;
   procedure Bump (Counter : in out Natural) renames Count_Up;

   --  Predefined operators and attributes, renamed.
   function Plus (L, R : Integer) return Integer renames "+";
   function Minus (L, R : Integer) return Integer renames "-";
   function Negate (X : Integer) return Integer renames "-";
   function Same (L, R : Vec) return Boolean renames "=";
   function Img (N : Integer) return String renames Integer'Image;
   function Next (N : Integer) return Integer renames Integer'Succ;

   type Gripper_State is (Open, Closed, Jammed);
   function Default_State return Gripper_State renames Open;

   --  A renaming-as-body completes an earlier declaration.
   function Double (V : Vec) return Vec;
   function Twice (V : Vec) return Vec is
   begin
      return V + V;
   end Twice;
   function Double (V : Vec) return Vec renames Twice;

   Home   : constant Vec := (0, 0, 300);
   Offset : constant Vec := (10, -5, 20);
   P      : Vec := Home;
   Parts  : Natural := 0;
   Limit  : Integer := 150;
   Big    : Integer := Integer'Last;
begin
   P := P + Offset;
   Put_Line ("p " & Image (P));
   P := Sum (P, Offset * 2);
   Put_Line ("p " & Image (P));
   Put_Line ("double " & Image (Double (Offset)));
   Go (P);
   Go (Goal => Home, Rate => 80);
   begin
      Go (Rate => Limit, Goal => Offset);
   exception
      when Constraint_Error => Put_Line ("rate" & Integer'Image (Limit) & " refused");
   end;
   Move_To (Home);
   Put_Line ("moves" & Natural'Image (Moves));
   Bump (Parts);
   Bump (Counter => Parts);
   Put_Line ("parts" & Natural'Image (Parts));
   Put_Line ("plus" & Integer'Image (Plus (40, 2)) & " minus"
             & Integer'Image (Minus (L => 40, R => 2))
             & " negate" & Integer'Image (Negate (7)));
   Put_Line ("same " & Boolean'Image (Same (P, P)) & " "
             & Boolean'Image (Same (P, Home)));
   Put_Line ("img" & Img (12) & " next" & Integer'Image (Next (12)));
   Put_Line ("state " & Gripper_State'Image (Default_State));
   begin
      Put_Line (Integer'Image (Plus (Big, 1)));
   exception
      when Constraint_Error => Put_Line ("overflow in Plus");
   end;
end Renaming_Subprograms;
