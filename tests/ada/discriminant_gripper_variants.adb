--  A gripper record with a variant per tool kind (RM 3.8.1): `when A |
--  B`, ranges and `others`, a nested variant part, defaults, constrained
--  objects (positional and named), an array of mutable grippers filled by
--  an aggregate, components of the wrong variant read and written
--  (Constraint_Error), a whole-record assignment that changes the kind,
--  equality of variant records.
with Ada.Text_IO; use Ada.Text_IO;
procedure Discriminant_Gripper_Variants is
   type Tool_Kind is (Jaws, Vacuum, Magnet, Welder, Camera);
   type Gripper (Kind : Tool_Kind := Jaws) is record
      Id : Natural := 0;
      case Kind is
         when Jaws =>
            Opening : Float := 0.05;
            Force : Natural := 20;
         when Vacuum | Magnet =>
            Pressure : Float := 0.8;
            case Kind is
               when Magnet => Current : Natural := 3;
               when others => null;
            end case;
         when Welder .. Camera =>
            null;
      end case;
   end record;
   procedure Show (G : Gripper) is
   begin
      Put (Tool_Kind'Image (G.Kind) & Natural'Image (G.Id));
      case G.Kind is
         when Jaws => Put (Float'Image (G.Opening) & Natural'Image (G.Force));
         when Vacuum => Put (Float'Image (G.Pressure));
         when Magnet => Put (Float'Image (G.Pressure) & Natural'Image (G.Current));
         when others => null;
      end case;
      New_Line;
   end Show;
   G : Gripper;
   V : Gripper (Vacuum);
   M : Gripper (Kind => Magnet);
   W : Gripper := (Kind => Welder, Id => 7);
   type Tool_Rack is array (1 .. 3) of Gripper;
   Rack : Tool_Rack := ((Jaws, 1, 0.02, 10), (Kind => Magnet, Id => 2, Pressure => 0.5, Current => 4), others => <>);
begin
   Show (G);
   Show (V);
   Show (M);
   Show (W);
   for R of Rack loop
      Show (R);
   end loop;
   G.Opening := 0.08;
   V.Pressure := 0.95;
   M.Current := M.Current + 1;
   Show (G);
   Show (V);
   Show (M);
   begin
      Put_Line (Float'Image (V.Opening));
   exception
      when Constraint_Error => Put_Line ("no opening on a vacuum gripper");
   end;
   begin
      W.Pressure := 1.0;
   exception
      when Constraint_Error => Put_Line ("no pressure on a welder");
   end;
   begin
      Put_Line (Natural'Image (Rack (1).Current));
   exception
      when Constraint_Error => Put_Line ("no current on jaws");
   end;
   G := (Kind => Vacuum, Id => 4, Pressure => 0.6);
   Show (G);
   Put_Line (Boolean'Image (G = V) & Boolean'Image (G = (Vacuum, 4, 0.6)));
   Rack (3) := G;
   Show (Rack (3));
   begin
      V := (Kind => Jaws, Id => 1, Opening => 0.0, Force => 1);
   exception
      when Constraint_Error => Put_Line ("V stays a vacuum gripper");
   end;
end Discriminant_Gripper_Variants;
