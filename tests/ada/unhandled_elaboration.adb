with Ada.Text_IO; use Ada.Text_IO;

procedure Unhandled_Elaboration is
   subtype Level is Integer range 0 .. 9;
   function Compute (X : Integer) return Integer is
   begin
      Put_Line ("Compute" & Integer'Image (X));
      return X * 5;
   end Compute;
   procedure Run (Start : Integer) is
      L : constant Level := Compute (Start);
   begin
      Put_Line ("Run with level" & Integer'Image (L));
   exception
      when Constraint_Error =>
         Put_Line ("Run's handler does not cover its declarations");
   end Run;
begin
   Run (1);
   Run (3);
   Put_Line ("never printed");
exception
   when Program_Error =>
      Put_Line ("wrong exception");
end Unhandled_Elaboration;
