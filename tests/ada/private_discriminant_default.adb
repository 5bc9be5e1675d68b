--  A tool slot of a gripper: a private type whose partial view gives its
--  discriminant (the jaw width) a default. An object declared without a
--  constraint is mutable: assigning a slot of another width changes its
--  width; a constrained one keeps its width, and an `in out` formal is
--  as constrained as its actual ('Constrained says which).
with Ada.Text_IO; use Ada.Text_IO;

procedure Private_Discriminant_Default is
   package Tools is
      type Tool_Slot (Width : Positive := 40) is private;
      Default_Width : constant Positive := 40;

      function Make (Width : Positive; Name : String) return Tool_Slot;
      function Name (S : Tool_Slot) return String;
      function Grips (S : Tool_Slot) return Natural;
      procedure Grip (S : in out Tool_Slot);
   private
      type Tool_Slot (Width : Positive := 40) is record
         Label : String (1 .. 6) := "empty ";
         Used  : Natural := 0;
      end record;
   end Tools;

   package body Tools is
      function Make (Width : Positive; Name : String) return Tool_Slot is
         S : Tool_Slot (Width);
      begin
         S.Label := (others => ' ');
         S.Label (1 .. Name'Length) := Name;
         return S;
      end Make;

      function Name (S : Tool_Slot) return String is (S.Label);
      function Grips (S : Tool_Slot) return Natural is (S.Used);

      procedure Grip (S : in out Tool_Slot) is
      begin
         S.Used := S.Used + 1;
      end Grip;
   end Tools;

   use Tools;

   Slot  : Tool_Slot;
   Fixed : Tool_Slot (25);
   Rack  : array (1 .. 3) of Tool_Slot;

   procedure Show (Tag : String; S : Tool_Slot) is
   begin
      Put_Line (Tag & ": width" & Positive'Image (S.Width) & " [" & Name (S)
                & "] grips" & Natural'Image (Grips (S)));
   end Show;

   --  Puts a wide suction cup in the slot: only a slot whose width may
   --  change takes it.
   procedure Retool (S : in out Tool_Slot) is
   begin
      Put_Line ("retool, constrained: " & Boolean'Image (S'Constrained));
      S := Make (90, "suckr");
      Grip (S);
   exception
      when Constraint_Error =>
         Put_Line ("retool: Constraint_Error, width stays"
                   & Positive'Image (S.Width));
   end Retool;
begin
   Show ("slot", Slot);
   Put_Line ("slot constrained: " & Boolean'Image (Slot'Constrained)
             & ", fixed constrained: " & Boolean'Image (Fixed'Constrained));
   Put_Line ("default width" & Positive'Image (Default_Width));
   Slot := Make (60, "jaws");
   Grip (Slot);
   Show ("slot", Slot);
   Fixed := Make (25, "pins");
   Show ("fixed", Fixed);
   begin
      Fixed := Make (30, "wide");
   exception
      when Constraint_Error =>
         Put_Line ("width 30 into fixed: Constraint_Error");
   end;
   Retool (Slot);
   Show ("slot", Slot);
   Retool (Fixed);
   Show ("fixed", Fixed);
   Rack (2) := Make (15, "tweez");
   Retool (Rack (3));
   for I in Rack'Range loop
      Show ("rack" & Integer'Image (I), Rack (I));
   end loop;
   declare
      Held : Tool_Slot := Rack (2);
   begin
      Held := Rack (3);
      Show ("held", Held);
   end;
end Private_Discriminant_Default;
