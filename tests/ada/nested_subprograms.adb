with Ada.Text_IO; use Ada.Text_IO;

procedure Nested_Subprograms is
   Total : Integer := 0;

   procedure Outer (N : Integer) is
      Local : Integer := N * 10;

      procedure Add (V : Integer) is
      begin
         Local := Local + V;
         Total := Total + V;
      end Add;

      function Scaled (F : Integer) return Integer is
         function Inner_Helper return Integer is
         begin
            return Local * F;
         end Inner_Helper;
      begin
         return Inner_Helper + N;
      end Scaled;
   begin
      Add (1);
      Add (2);
      Put_Line ("Outer" & Integer'Image (N) & ": Local =" & Integer'Image (Local)
                & " Scaled (2) =" & Integer'Image (Scaled (2)));
   end Outer;

   function Counter_Sum (Limit : Integer) return Integer is
      Acc : Integer := 0;
      procedure Step (I : Integer) is
      begin
         if I > Limit then
            return;
         end if;
         Acc := Acc + I;
         Step (I + 1);
      end Step;
   begin
      Step (1);
      return Acc;
   end Counter_Sum;

   procedure Shadow is
      Total : Integer := -1;
   begin
      Total := Total * 2;
      Put_Line ("shadowed Total =" & Integer'Image (Total)
                & ", outer Total =" & Integer'Image (Nested_Subprograms.Total));
   end Shadow;
begin
   Outer (1);
   Outer (5);
   Put_Line ("Total =" & Integer'Image (Total));
   Put_Line ("Counter_Sum (10) =" & Integer'Image (Counter_Sum (10)));
   Put_Line ("Counter_Sum (0) =" & Integer'Image (Counter_Sum (0)));
   Shadow;
   Put_Line ("Total =" & Integer'Image (Total));
end Nested_Subprograms;
