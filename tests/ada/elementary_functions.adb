with Ada.Text_IO; use Ada.Text_IO;
with Ada.Float_Text_IO; use Ada.Float_Text_IO;
with Ada.Numerics; use Ada.Numerics;
with Ada.Numerics.Elementary_Functions; use Ada.Numerics.Elementary_Functions;

procedure Elementary_Functions is
   procedure Show (Label : String; X : Float) is
   begin
      Put (Label & " = ");
      Put (X, Fore => 1, Aft => 5, Exp => 0);
      New_Line;
   end Show;
   X : Float := 0.0;
begin
   Show ("Pi", Pi);
   Show ("Pi / 2", Ada.Numerics.Pi / 2.0);
   Show ("e", Ada.Numerics.e);
   Show ("Sqrt (2)", Sqrt (2.0));
   Show ("Sqrt (16)", Sqrt (16.0));
   Show ("Sqrt (0.25)", Sqrt (0.25));
   Show ("Sin (0)", Sin (0.0));
   Show ("Sin (Pi / 6)", Sin (Pi / 6.0));
   Show ("Sin (1)", Sin (1.0));
   Show ("Cos (0)", Cos (0.0));
   Show ("Cos (Pi / 3)", Cos (Pi / 3.0));
   Show ("Cos (2)", Cos (2.0));
   Show ("Tan (Pi / 4)", Tan (Pi / 4.0));
   Show ("Tan (0.5)", Tan (0.5));
   Show ("Arcsin (0.5)", Arcsin (0.5));
   Show ("Arcsin (1)", Arcsin (1.0));
   Show ("Arccos (0)", Arccos (0.0));
   Show ("Arccos (-1)", Arccos (-1.0));
   Show ("Arctan (1)", Arctan (1.0));
   Show ("Arctan (-2)", Arctan (-2.0));
   Show ("Arctan (1, 1)", Arctan (1.0, 1.0));
   Show ("Arctan (1, -1)", Arctan (1.0, -1.0));
   Show ("Arctan (-1, -1)", Arctan (-1.0, -1.0));
   Show ("Arctan (Y => 2, X => 0)", Arctan (Y => 2.0, X => 0.0));
   Show ("Arctan (0, -1)", Arctan (0.0, -1.0));
   Show ("Exp (0)", Exp (0.0));
   Show ("Exp (1)", Exp (1.0));
   Show ("Exp (-2)", Exp (-2.0));
   Show ("Log (1)", Log (1.0));
   Show ("Log (10)", Log (10.0));
   Show ("Log (e)", Log (e));
   Show ("2.0 ** 0.5", 2.0 ** 0.5);
   Show ("9.0 ** 1.5", 9.0 ** 1.5);
   Show ("10.0 ** (-1.0)", 10.0 ** (-1.0));
   Show ("2.0 ** 3 (integer)", 2.0 ** 3);
   Show ("Sin**2 + Cos**2", Sin (0.7) ** 2 + Cos (0.7) ** 2);
   for I in 0 .. 4 loop
      X := Float (I) * 0.5;
      Put ("angle");
      Put (X, 2, 4, 0);
      Put (" sin");
      Put (Sin (X), 2, 4, 0);
      Put (" cos");
      Put (Cos (X), 2, 4, 0);
      New_Line;
   end loop;
   Put (Sqrt (830.6), 1, 3, 2);
   New_Line;
   Put (Exp (10.0), 1, 4, 3);
   New_Line;
   begin
      X := Sqrt (-1.0);
      Put_Line ("not reached");
   exception
      when Ada.Numerics.Argument_Error =>
         Put_Line ("Sqrt (-1.0) raised Argument_Error");
   end;
end Elementary_Functions;
