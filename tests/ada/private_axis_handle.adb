--  Private types in a robot cell: an axis handle whose full view is a
--  record, a joint register whose full view is an array, a speed whose
--  full view is a floating point type, subtypes and arrays of private
--  types, predefined "=" on them, and a limited private
--  gripper controller initialized through an out parameter.
with Ada.Text_IO; use Ada.Text_IO;

procedure Private_Axis_Handle is
   package Axes is
      type Axis_Handle is private;
      type Joint_Register is private;
      type Speed is private;
      subtype Handle is Axis_Handle;

      No_Axis : constant Axis_Handle;
      Crawl, Rapid : constant Speed;

      function Make (Joint : Positive; Limit : Float) return Axis_Handle;
      procedure Move (H : in out Axis_Handle; By : Float; At_Speed : Speed);
      function Angle (H : Axis_Handle) return Float;
      function Joint (H : Axis_Handle) return Natural;
      function Moves (H : Axis_Handle) return Natural;
      function Image (S : Speed) return String;
      function Faster (S : Speed) return Speed;

      procedure Store (R : in out Joint_Register; H : Axis_Handle);
      function Total (R : Joint_Register) return Float;
      Empty_Register : constant Joint_Register;
   private
      type Axis_Handle is record
         Joint : Natural := 0;
         Angle : Float := 0.0;
         Limit : Float := 0.0;
         Moves : Natural := 0;
      end record;
      type Joint_Register is array (1 .. 4) of Float;
      type Speed is digits 6 range 0.0 .. 100.0;

      No_Axis : constant Axis_Handle := (others => <>);
      Crawl : constant Speed := 5.0;
      Rapid : constant Speed := 80.0;
      Empty_Register : constant Joint_Register := (others => 0.0);
   end Axes;

   package body Axes is
      function Make (Joint : Positive; Limit : Float) return Axis_Handle is
      begin
         return (Joint => Joint, Angle => 0.0, Limit => Limit, Moves => 0);
      end Make;

      procedure Move (H : in out Axis_Handle; By : Float; At_Speed : Speed) is
         Step : constant Float := By * Float (At_Speed) / 100.0;
      begin
         if H = No_Axis then
            return;
         end if;
         H.Angle := Float'Min (H.Limit, Float'Max (-H.Limit, H.Angle + Step));
         H.Moves := H.Moves + 1;
      end Move;

      function Angle (H : Axis_Handle) return Float is (H.Angle);
      function Joint (H : Axis_Handle) return Natural is (H.Joint);
      function Moves (H : Axis_Handle) return Natural is (H.Moves);

      function Image (S : Speed) return String is
      begin
         if S < 10.0 then
            return "crawl";
         elsif S < 50.0 then
            return "medium";
         else
            return "rapid";
         end if;
      end Image;

      function Faster (S : Speed) return Speed is
      begin
         return Speed'Min (Speed'Last, S * 2.0);
      end Faster;

      procedure Store (R : in out Joint_Register; H : Axis_Handle) is
      begin
         if H.Joint in R'Range then
            R (H.Joint) := H.Angle;
         end if;
      end Store;

      function Total (R : Joint_Register) return Float is
         Sum : Float := 0.0;
      begin
         for A of R loop
            Sum := Sum + A;
         end loop;
         return Sum;
      end Total;
   end Axes;

   package Grippers is
      type Gripper is limited private;
      procedure Reset (G : out Gripper; Width : Float);
      procedure Grip (G : in out Gripper; Part : String);
      function Holding (G : Gripper) return String;
      function Width (G : Gripper) return Float;
   private
      type Gripper is record
         Width : Float := 0.0;
         Part  : String (1 .. 6) := (others => ' ');
         Used  : Natural := 0;
      end record;
   end Grippers;

   package body Grippers is
      procedure Reset (G : out Gripper; Width : Float) is
      begin
         G.Width := Width;
         G.Part := (others => '-');
         G.Used := 0;
      end Reset;

      procedure Grip (G : in out Gripper; Part : String) is
      begin
         G.Part := (others => ' ');
         G.Part (1 .. Part'Length) := Part;
         G.Width := G.Width / 2.0;
         G.Used := G.Used + 1;
      end Grip;

      function Holding (G : Gripper) return String is (G.Part);
      function Width (G : Gripper) return Float is (G.Width);
   end Grippers;

   use Axes, Grippers;

   type Arm is array (1 .. 3) of Handle;
   Robot : Arm := (Make (1, 90.0), Make (2, 45.0), No_Axis);
   Copy  : Arm;
   Reg   : Joint_Register := Empty_Register;
   S     : Speed := Crawl;
   Hand  : Gripper;
   Wrist : Handle := Make (5, 120.0);

   procedure Show (H : Handle) is
   begin
      Put_Line ("joint" & Natural'Image (Joint (H)) & " at"
                & Integer'Image (Integer (Angle (H))) & " after"
                & Natural'Image (Moves (H)) & " moves");
   end Show;
begin
   for I in Robot'Range loop
      Move (Robot (I), 60.0, S);
      S := Faster (S);
      Put_Line ("speed now " & Image (S));
   end loop;
   for I in 1 .. 4 loop
      Move (Robot (2), 100.0, Rapid);
   end loop;
   for H of Robot loop
      Show (H);
      Store (Reg, H);
   end loop;
   Put_Line ("register total" & Integer'Image (Integer (Total (Reg))));
   Put_Line ("register empty: " & Boolean'Image (Reg = Empty_Register));
   Copy := Robot;
   Put_Line ("copy equal: " & Boolean'Image (Copy = Robot));
   Move (Copy (1), -30.0, Rapid);
   Put_Line ("after move, equal: " & Boolean'Image (Copy = Robot));
   Put_Line ("third is no axis: " & Boolean'Image (Robot (3) = No_Axis));
   Put_Line ("crawl /= rapid: " & Boolean'Image (Crawl /= Rapid));
   Move (Wrist, 50.0, Rapid);
   Show (Wrist);
   Reset (Hand, 80.0);
   Put_Line ("holding [" & Holding (Hand) & "] width"
             & Integer'Image (Integer (Width (Hand))));
   Grip (Hand, "bolt");
   Put_Line ("holding [" & Holding (Hand) & "] width"
             & Integer'Image (Integer (Width (Hand))));
end Private_Axis_Handle;
