--  Private types: a gripper whose record clients never see, a force level
--  whose full view is an integer type, a jaw state whose full view is an
--  enumeration, and deferred constants completed in the private part.
with Ada.Text_IO; use Ada.Text_IO;

procedure Private_Gripper is
   package Grippers is
      type Gripper is private;
      type Force is private;
      type Jaw is private;

      Parked  : constant Gripper;
      No_Grip : constant Force;
      Firm    : constant Force;

      function Make (Width_Mm : Float) return Gripper;
      procedure Open (G : in out Gripper);
      procedure Close (G : in out Gripper; With_Force : Force);
      function Width (G : Gripper) return Float;
      function Holding (G : Gripper) return Force;
      function State (G : Gripper) return Jaw;
      function Image (J : Jaw) return String;

      function Newtons (N : Natural) return Force;
      function "+" (A, B : Force) return Force;
      function Value (F : Force) return Natural;
   private
      type Force is range 0 .. 200;
      type Jaw is (Opened, Closing, Closed);
      type Gripper is record
         Width_Mm : Float := 80.0;
         Grip     : Force := 0;
         Jaws     : Jaw := Opened;
      end record;

      Parked  : constant Gripper := (Width_Mm => 0.0, Grip => 0, Jaws => Closed);
      No_Grip : constant Force := 0;
      Firm    : constant Force := 60;
   end Grippers;

   package body Grippers is
      Opened_Width : constant Float := 80.0;

      function Make (Width_Mm : Float) return Gripper is
      begin
         return (Width_Mm => Width_Mm, Grip => No_Grip, Jaws => Opened);
      end Make;

      procedure Open (G : in out Gripper) is
      begin
         G := (Width_Mm => Opened_Width, Grip => 0, Jaws => Opened);
      end Open;

      procedure Close (G : in out Gripper; With_Force : Force) is
      begin
         G.Grip := With_Force;
         if With_Force > Firm then
            G.Width_Mm := 10.0;
         else
            G.Width_Mm := 25.0;
         end if;
         G.Jaws := (if With_Force = 0 then Closing else Closed);
      end Close;

      function Width (G : Gripper) return Float is (G.Width_Mm);
      function Holding (G : Gripper) return Force is (G.Grip);
      function State (G : Gripper) return Jaw is (G.Jaws);

      function Image (J : Jaw) return String is
      begin
         case J is
            when Opened  => return "opened";
            when Closing => return "closing";
            when Closed  => return "closed";
         end case;
      end Image;

      function Newtons (N : Natural) return Force is (Force (N));
      function "+" (A, B : Force) return Force is
      begin
         return Force (Integer'Min (Integer (Force'Last), Integer (A) + Integer (B)));
      end "+";
      function Value (F : Force) return Natural is (Natural (F));
   end Grippers;

   use Grippers;

   type Station is record
      Name : String (1 .. 5);
      Tool : Gripper;
   end record;

   Left  : Gripper;
   Right : Gripper := Make (50.0);
   Spare : constant Gripper := Parked;
   Cell  : array (1 .. 3) of Gripper;
   Stations : array (1 .. 2) of Station :=
     ((Name => "weld ", Tool => Parked), (Name => "pack ", Tool => Make (30.0)));

   procedure Show (Label : String; G : Gripper) is
   begin
      Put_Line (Label & ":" & Float'Image (Width (G)) & " mm, "
                & Integer'Image (Value (Holding (G))) & " N, " & Image (State (G)));
   end Show;
begin
   Show ("left", Left);
   Show ("right", Right);
   Show ("spare", Spare);
   Close (Left, Firm);
   Show ("left closed firm", Left);
   Close (Right, Firm + Newtons (30));
   Show ("right closed harder", Right);
   Close (Cell (2), No_Grip);
   Show ("cell 2", Cell (2));
   Put_Line ("left = right: " & Boolean'Image (Left = Right));
   Right := Left;
   Put_Line ("after copy, left = right: " & Boolean'Image (Left = Right));
   Put_Line ("spare = parked: " & Boolean'Image (Spare = Parked));
   Put_Line ("left /= parked: " & Boolean'Image (Left /= Parked));
   Cell (1) := Left;
   Cell (3) := Make (42.5);
   for I in Cell'Range loop
      Show ("cell" & Integer'Image (I), Cell (I));
   end loop;
   Open (Left);
   Show ("left opened", Left);
   Put_Line ("force sum:" & Integer'Image (Value (Firm + Firm + Firm + Firm)));
   for S of Stations loop
      Show (S.Name, S.Tool);
   end loop;
   Stations (1).Tool := Cell (3);
   Show ("weld now", Stations (1).Tool);
end Private_Gripper;
