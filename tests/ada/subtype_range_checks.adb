with Ada.Text_IO; use Ada.Text_IO;

procedure Subtype_Range_Checks is
   subtype Percent is Integer range 0 .. 100;
   subtype Small is Integer range -5 .. 5;
   subtype Unit_Float is Float range 0.0 .. 1.0;
   type Day is (Mon, Tue, Wed, Thu, Fri, Sat, Sun);
   subtype Weekend is Day range Sat .. Sun;
   P : Percent := 50;
   S : Small := 0;
   U : Unit_Float := 0.5;
   W : Weekend := Sat;
   function Id (X : Integer) return Integer is
   begin
      return X;
   end Id;
   procedure Set_Percent (Value : Integer) is
   begin
      P := Value;
      Put_Line ("P set to" & Integer'Image (P));
   exception
      when Constraint_Error =>
         Put_Line ("Set_Percent (" & Integer'Image (Value) & " ) raised Constraint_Error, P stays" & Integer'Image (P));
   end Set_Percent;
   function Half (X : Small) return Integer is
   begin
      return X / 2;
   end Half;
begin
   Set_Percent (75);
   Set_Percent (101);
   Set_Percent (-1);
   Set_Percent (100);
   for I in 1 .. 8 loop
      begin
         S := Id (I);
         Put_Line ("S =" & Integer'Image (S));
      exception
         when Constraint_Error =>
            Put_Line ("S := " & Integer'Image (I) & " failed");
      end;
   end loop;
   begin
      Put_Line ("Half (4) =" & Integer'Image (Half (Id (4))));
      Put_Line ("Half (9) =" & Integer'Image (Half (Id (9))));
   exception
      when Constraint_Error =>
         Put_Line ("Half (9): parameter out of range");
   end;
   begin
      U := Float (Id (1)) / 4.0;
      Put_Line ("U =" & Float'Image (U));
      U := Float (Id (3)) / 2.0;
      Put_Line ("not reached");
   exception
      when Constraint_Error =>
         Put_Line ("U := 1.5 raised Constraint_Error, U =" & Float'Image (U));
   end;
   begin
      W := Day'Val (Id (6));
      Put_Line ("W = " & Day'Image (W));
      W := Day'Val (Id (4));
      Put_Line ("not reached");
   exception
      when Constraint_Error =>
         Put_Line ("W := Fri raised Constraint_Error, W = " & Day'Image (W));
   end;
   begin
      P := Id (30) + Id (80);
      Put_Line ("not reached");
   exception
      when Constraint_Error =>
         Put_Line ("30 + 80 does not fit Percent");
   end;
   Put_Line ("Percent'First =" & Integer'Image (Percent'First) & " Percent'Last =" & Integer'Image (Percent'Last));
   for I in Small loop
      Put (Integer'Image (I));
   end loop;
   New_Line;
end Subtype_Range_Checks;
