--  The constructs the compiled engine now runs itself: abs, unary minus of
--  reals, float-to-integer conversion, .all, not and and/or/xor of Boolean
--  arrays, array conversions, 'First/'Last of a dynamic subtype, membership
--  tests with several ranges (bounds with side effects), raise with and
--  without a message, and raise; in a handler.
with Ada.Text_IO; use Ada.Text_IO;
with Ada.Exceptions;
procedure Engine_Unary_Raise is
   type Axis is (X, Y, Z, Roll, Pitch, Yaw);
   type Mask is array (Axis) of Boolean;
   type Offsets is array (Positive range <>) of Integer;
   subtype Three is Offsets (1 .. 3);
   type Pose is record
      Joint : Integer;
      Angle : Float;
   end record;
   type Pose_Ref is access Pose;

   Gripper_Jam : exception;
   Calls : Natural := 0;

   function Limit (N : Integer) return Integer is
   begin
      Calls := Calls + 1;
      return N;
   end Limit;

   function Reason (Code : Integer) return String is
   begin
      return "jam at station" & Integer'Image (Code);
   end Reason;

   procedure Check_Station (Code : Integer) is
   begin
      if Code > 3 then
         raise Gripper_Jam with Reason (Code);
      elsif Code < 0 then
         raise Constraint_Error;
      end if;
   end Check_Station;

   procedure Guarded (Code : Integer) is
   begin
      Check_Station (Code);
      Put_Line ("station" & Integer'Image (Code) & " ok");
   exception
      when Gripper_Jam =>
         Put_Line ("guard saw the jam, passing it on");
         raise;
   end Guarded;

   Error_Sum : Integer := 0;
   Drift : Float := 0.0;
   Steps : Integer := 0;
   P : Pose_Ref := new Pose'(Joint => 4, Angle => -1.25);
   Q : Pose_Ref;
   Copy : Pose;
   Enabled : Mask := (X | Y | Z => True, others => False);
   Locked : constant Mask := (Roll => True, Z => True, others => False);
   Free : Mask;
   Hi : Integer := 5;
   Big : Float := 4.0;
   Low : Integer := Integer'First;
begin
   --  abs, unary minus and rounding in a loop
   for I in -5 .. 5 loop
      Error_Sum := Error_Sum + abs (I * 3 - 4);
      Drift := Drift + abs (Float (I) * 0.5 - 0.75);
      Steps := Steps + Integer (Float (I) * 0.5);
   end loop;
   Put_Line ("error sum" & Integer'Image (Error_Sum));
   Put_Line ("steps" & Integer'Image (Steps));
   Put_Line ("drift" & Integer'Image (Integer (Drift * 100.0)));
   Put_Line ("neg" & Integer'Image (Integer (-Drift)));
   Put_Line ("round 2.5 =" & Integer'Image (Integer (2.5))
             & ", -2.5 =" & Integer'Image (Integer (-2.5)));
   begin
      Steps := Integer (Float (Integer'Last) * Big);
      Put_Line ("no overflow?");
   exception
      when Constraint_Error => Put_Line ("float to integer overflow caught");
   end;
   begin
      Steps := abs (Low);
      Put_Line ("no overflow?");
   exception
      when Constraint_Error => Put_Line ("abs overflow caught");
   end;

   --  .all
   Copy := P.all;
   P.all.Joint := 9;
   Put_Line ("copy joint" & Integer'Image (Copy.Joint)
             & ", now" & Integer'Image (P.all.Joint));
   begin
      Copy := Q.all;
      Put_Line ("no access check?");
   exception
      when Constraint_Error => Put_Line ("null .all caught");
   end;

   --  Boolean arrays
   Free := Enabled and not Locked;
   for A in Axis loop
      if Free (A) then
         Put (Axis'Image (A) & " ");
      end if;
   end loop;
   New_Line;
   Free := (Enabled or Locked) xor Mask'(others => True);
   for A in Axis loop
      if Free (A) then
         Put (Axis'Image (A) & " ");
      end if;
   end loop;
   New_Line;

   --  array conversion
   declare
      Raw : Offsets (5 .. 7) := (10, 20, 30);
      T : Three;
   begin
      T := Three (Raw);
      Put_Line ("converted first" & Integer'Image (T'First)
                & " sum" & Integer'Image (T (1) + T (2) + T (3)));
   end;

   --  'First and 'Last of a dynamic subtype, membership tests
   declare
      subtype Window is Integer range Hi - 3 .. Hi + 3;
      Inside : Natural := 0;
   begin
      Put_Line ("window" & Integer'Image (Window'First) & " .."
                & Integer'Image (Window'Last));
      for I in -2 .. 12 loop
         if I in Window'First .. Window'First + 1 | Limit (7) .. Limit (Hi + 3) then
            Inside := Inside + 1;
         end if;
         if I not in 0 .. 9 then
            Put (Integer'Image (I));
         end if;
      end loop;
      New_Line;
      Put_Line ("inside" & Integer'Image (Inside) & ", limit calls"
                & Integer'Image (Calls));
   end;

   --  raise, with and without a message, and raise;
   for Code in -1 .. 5 loop
      begin
         Guarded (Code);
      exception
         when E : Gripper_Jam =>
            Put_Line ("jam handled: " & Ada.Exceptions.Exception_Message (E));
         when Constraint_Error =>
            Put_Line ("negative code" & Integer'Image (Code));
      end;
   end loop;
   Guarded (7);
end Engine_Unary_Raise;
