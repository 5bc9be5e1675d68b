with Ada.Text_IO; use Ada.Text_IO;
with Ada.Float_Text_IO; use Ada.Float_Text_IO;

procedure Unconstrained_Arrays is
   type Float_Vector is array (Positive range <>) of Float;
   V3 : constant Float_Vector := (1.0, 2.0, 3.0);
   V5 : Float_Vector (1 .. 5) := (0.5, -1.5, 2.25, 4.0, -0.25);
   W  : Float_Vector (3 .. 6) := (others => 1.5);

   function Sum (V : Float_Vector) return Float is
      S : Float := 0.0;
   begin
      for I in V'Range loop
         S := S + V (I);
      end loop;
      return S;
   end Sum;

   function Max_Index (V : Float_Vector) return Integer is
      Best : Integer := V'First;
   begin
      for I in V'First + 1 .. V'Last loop
         if V (I) > V (Best) then
            Best := I;
         end if;
      end loop;
      return Best;
   end Max_Index;

   procedure Scale (V : in out Float_Vector; Factor : Float) is
   begin
      for I in V'Range loop
         V (I) := V (I) * Factor;
      end loop;
   end Scale;

   procedure Describe (Label : String; V : Float_Vector) is
   begin
      Put (Label & " [" & Integer'Image (V'First) & " .." & Integer'Image (V'Last)
           & " ] len" & Integer'Image (V'Length) & ":");
      for I in V'Range loop
         Put (V (I), 3, 2, 0);
      end loop;
      Put (" sum ");
      Put (Sum (V), 1, 3, 0);
      New_Line;
   end Describe;
begin
   Describe ("V3", V3);
   Describe ("V5", V5);
   Describe ("W", W);
   Put_Line ("Max index V5:" & Integer'Image (Max_Index (V5)));
   Put_Line ("Max index V3:" & Integer'Image (Max_Index (V3)));
   Scale (V5, 2.0);
   Describe ("V5*2", V5);
   Scale (W, -1.0);
   W (4) := 10.0;
   Describe ("W", W);
   Put_Line ("Max index W:" & Integer'Image (Max_Index (W)));
   Describe ("literal", (7.5, 8.5));
   Describe ("single", (1 => 42.0));
   declare
      Empty : Float_Vector (1 .. 0);
   begin
      Describe ("empty", Empty);
   end;
   declare
      Dyn : Float_Vector (1 .. V3'Length * 2) := (others => 0.25);
   begin
      Dyn (Dyn'Last) := Sum (V3);
      Describe ("dyn", Dyn);
   end;
end Unconstrained_Arrays;
