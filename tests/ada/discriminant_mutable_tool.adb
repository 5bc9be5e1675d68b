--  A tool changer: the arm's mounted tool is a mutable record (its
--  discriminant has a default, RM 3.7(28)) whose kind changes with each
--  whole-record assignment; the rack's slots are constrained, by their
--  subtype or by their initial value, and keep their kind (RM 5.2(10):
--  Constraint_Error). 'Constrained (RM 3.7.2) of objects, components,
--  formals (as constrained as their actuals) and allocated objects.
with Ada.Text_IO; use Ada.Text_IO;
procedure Discriminant_Mutable_Tool is
   type Tool_Kind is (None, Gripper, Drill, Camera);
   type Tool (Kind : Tool_Kind := None) is record
      Serial : Natural := 0;
      case Kind is
         when None => null;
         when Gripper => Jaw_Width : Float := 0.04;
         when Drill => Speed : Natural := 3000;
         when Camera => Exposure : Float := 0.01;
      end case;
   end record;
   subtype Drill_Tool is Tool (Drill);
   type Tool_Ref is access Tool;
   type Arm is record
      Mounted : Tool;
      Spare : Drill_Tool;
   end record;
   type Slot_Array is array (1 .. 3) of Tool;

   procedure Show (Label : String; T : Tool) is
   begin
      Put (Label & ": " & Tool_Kind'Image (T.Kind) & Natural'Image (T.Serial));
      case T.Kind is
         when Gripper => Put (Float'Image (T.Jaw_Width));
         when Drill => Put (Natural'Image (T.Speed));
         when Camera => Put (Float'Image (T.Exposure));
         when None => null;
      end case;
      New_Line;
   end Show;

   function Make (K : Tool_Kind; Serial : Natural) return Tool is
   begin
      case K is
         when None => return (Kind => None, Serial => Serial);
         when Gripper => return (Gripper, Serial, 0.05);
         when Drill => return (Kind => Drill, Serial => Serial, Speed => 1200);
         when Camera => return (Kind => Camera, Serial => Serial, Exposure => 0.02);
      end case;
   end Make;

   --  Mounts a new tool in T: legal only if T may change its kind.
   procedure Mount (T : in out Tool; K : Tool_Kind; Serial : Natural) is
   begin
      Put_Line ("mount " & Tool_Kind'Image (K) & " constrained: "
                & Boolean'Image (T'Constrained));
      T := Make (K, Serial);
   exception
      when Constraint_Error =>
         Put_Line ("  the slot keeps its " & Tool_Kind'Image (T.Kind));
   end Mount;

   procedure Reset (T : out Tool) is
   begin
      T := (Kind => None, Serial => 0);
   end Reset;

   Current : Tool;
   Fixed : Drill_Tool;
   Probe : Tool (Camera);
   Kept : constant Tool := Make (Gripper, 11);
   Robot : Arm;
   Rack : Slot_Array := (Make (Gripper, 1), Make (Drill, 2), others => <>);
   Heap : Tool_Ref := new Tool'(Make (Camera, 40));
begin
   Show ("current", Current);
   Put_Line ("constrained:" & Boolean'Image (Current'Constrained)
             & Boolean'Image (Fixed'Constrained) & Boolean'Image (Probe'Constrained)
             & Boolean'Image (Kept'Constrained) & Boolean'Image (Robot.Mounted'Constrained)
             & Boolean'Image (Robot.Spare'Constrained) & Boolean'Image (Rack (1)'Constrained)
             & Boolean'Image (Heap.all'Constrained));
   Current := Make (Gripper, 7);
   Show ("current", Current);
   Current := Make (Drill, 8);
   Show ("current", Current);
   Mount (Current, Camera, 9);
   Show ("current", Current);
   Mount (Fixed, Camera, 10);
   Show ("fixed", Fixed);
   Mount (Fixed, Drill, 12);
   Show ("fixed", Fixed);
   Mount (Robot.Mounted, Gripper, 13);
   Show ("mounted", Robot.Mounted);
   Mount (Robot.Spare, Gripper, 14);
   Show ("spare", Robot.Spare);
   for I in Rack'Range loop
      Mount (Rack (I), Camera, 20 + I);
      Show ("rack", Rack (I));
   end loop;
   Mount (Heap.all, Drill, 30);
   Show ("heap", Heap.all);
   begin
      Heap.all := Make (Gripper, 31);
   exception
      when Constraint_Error => Put_Line ("the heap tool keeps its kind");
   end;
   begin
      Probe := Current;
      Show ("probe", Probe);
      Probe := Make (Drill, 32);
   exception
      when Constraint_Error => Put_Line ("the probe stays a camera");
   end;
   Reset (Current);
   Show ("current", Current);
   begin
      Reset (Probe);
   exception
      when Constraint_Error => Put_Line ("the probe cannot be reset");
   end;
   Put_Line (Boolean'Image (Current = (Kind => None, Serial => 0))
             & Boolean'Image (Rack (1) = Rack (2)) & Boolean'Image (Kept = Make (Gripper, 11)));
end Discriminant_Mutable_Tool;
