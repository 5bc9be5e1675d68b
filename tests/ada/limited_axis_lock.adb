--  Limited private types: an axis lock handle that clients cannot copy or
--  compare with the predefined "=", built in place by a function, compared
--  with the package's own "=", held in records and arrays (which are then
--  limited too), and passed as parameters.
with Ada.Text_IO; use Ada.Text_IO;

procedure Limited_Axis_Lock is
   package Axes is
      type Axis_Lock is limited private;

      function Lock_For (Axis : Positive) return Axis_Lock;
      procedure Take (L : in out Axis_Lock; Owner : Character);
      procedure Release (L : in out Axis_Lock);
      function Held (L : Axis_Lock) return Boolean;
      function Owner (L : Axis_Lock) return Character;
      function Axis (L : Axis_Lock) return Natural;
      function "=" (A, B : Axis_Lock) return Boolean;
      procedure Hand_Over (From, To : in out Axis_Lock);
      Takes : Natural := 0;
   private
      type Axis_Lock is record
         Axis  : Natural := 0;
         Held  : Boolean := False;
         Owner : Character := '-';
      end record;
   end Axes;

   package body Axes is
      function Lock_For (Axis : Positive) return Axis_Lock is
      begin
         return (Axis => Axis, Held => False, Owner => '-');
      end Lock_For;

      procedure Take (L : in out Axis_Lock; Owner : Character) is
      begin
         if not L.Held then
            L.Held := True;
            L.Owner := Owner;
            Takes := Takes + 1;
         end if;
      end Take;

      procedure Release (L : in out Axis_Lock) is
         Free : Axis_Lock;
      begin
         Free.Axis := L.Axis;
         --  Inside the package the full view is a plain record: copied.
         L := Free;
      end Release;

      function Held (L : Axis_Lock) return Boolean is (L.Held);
      function Owner (L : Axis_Lock) return Character is (L.Owner);
      function Axis (L : Axis_Lock) return Natural is (L.Axis);

      function "=" (A, B : Axis_Lock) return Boolean is
      begin
         return A.Axis = B.Axis;
      end "=";

      procedure Hand_Over (From, To : in out Axis_Lock) is
      begin
         if From.Held then
            To.Held := True;
            To.Owner := From.Owner;
            From.Held := False;
            From.Owner := '-';
         end if;
      end Hand_Over;
   end Axes;

   use Axes;

   --  A record with a limited component is limited.
   type Arm_Locks is record
      Shoulder : Axis_Lock;
      Elbow    : Axis_Lock;
      Name     : String (1 .. 3) := "arm";
   end record;

   Base  : Axis_Lock := Lock_For (1);
   Wrist : Axis_Lock := Lock_For (5);
   Spare : Axis_Lock;
   Arm   : Arm_Locks;
   Bank  : array (1 .. 3) of Axis_Lock;

   procedure Show (Label : String; L : Axis_Lock) is
   begin
      Put_Line (Label & ": axis" & Natural'Image (Axis (L)) & ", held "
                & Boolean'Image (Held (L)) & ", owner " & Owner (L));
   end Show;
begin
   Show ("base", Base);
   Show ("spare", Spare);
   Take (Base, 'A');
   Take (Base, 'B');
   Show ("base taken", Base);
   Put_Line ("base = wrist: " & Boolean'Image (Base = Wrist));
   Put_Line ("base = lock 1: " & Boolean'Image (Base = Lock_For (1)));
   Put_Line ("spare /= wrist: " & Boolean'Image (Spare /= Wrist));
   Hand_Over (Base, Wrist);
   Show ("base after hand-over", Base);
   Show ("wrist after hand-over", Wrist);
   Take (Arm.Shoulder, 'C');
   Show (Arm.Name & " shoulder", Arm.Shoulder);
   Show (Arm.Name & " elbow", Arm.Elbow);
   for I in Bank'Range loop
      Take (Bank (I), Character'Val (Character'Pos ('0') + I));
   end loop;
   Release (Bank (2));
   for I in Bank'Range loop
      Show ("bank" & Integer'Image (I), Bank (I));
   end loop;
   Release (Wrist);
   Show ("wrist released", Wrist);
   declare
      Tool : Axis_Lock := Lock_For (6);
   begin
      Take (Tool, 'T');
      Show ("tool", Tool);
   end;
   Put_Line ("takes:" & Natural'Image (Takes));
end Limited_Axis_Lock;
