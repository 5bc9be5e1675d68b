--  A formal `in out` of a mutable record type (its discriminant has a
--  default) is as constrained as its actual (RM 3.7.2, 6.4.1): through a
--  renaming of the procedure, a function with an `in out` parameter, and
--  a procedure of a protected tool crib, called from outside and from
--  inside the protected body.
with Ada.Text_IO; use Ada.Text_IO;
procedure Discriminant_Formals is
   type Tool_Kind is (Empty, Gripper, Welder);
   type Tool (Kind : Tool_Kind := Empty) is record
      Serial : Natural := 0;
      case Kind is
         when Empty => null;
         when Gripper => Force : Natural := 40;
         when Welder => Current : Natural := 120;
      end case;
   end record;

   procedure Swap_In (T : in out Tool; K : Tool_Kind) is
   begin
      Put_Line ("swap to " & Tool_Kind'Image (K) & ", constrained "
                & Boolean'Image (T'Constrained));
      case K is
         when Empty => T := (Kind => Empty, Serial => T.Serial);
         when Gripper => T := (Kind => Gripper, Serial => T.Serial + 1, Force => 55);
         when Welder => T := (Kind => Welder, Serial => T.Serial + 1, Current => 90);
      end case;
   end Swap_In;
   procedure Change_Tool (T : in out Tool; K : Tool_Kind) renames Swap_In;

   function Wear_Out (T : in out Tool) return Natural is
   begin
      T := (Kind => Empty, Serial => T.Serial);
      return T.Serial;
   end Wear_Out;

   protected Crib is
      procedure Issue (T : in out Tool);
      procedure Issue_Twice (T : in out Tool);
      function Issued return Natural;
   private
      Count : Natural := 0;
   end Crib;

   protected body Crib is
      procedure Issue (T : in out Tool) is
      begin
         Put_Line ("crib issues, constrained " & Boolean'Image (T'Constrained));
         Count := Count + 1;
         T := (Kind => Welder, Serial => 100 + Count, Current => 150);
      end Issue;
      procedure Issue_Twice (T : in out Tool) is
      begin
         Issue (T);
         Issue (T);
      end Issue_Twice;
      function Issued return Natural is
      begin
         return Count;
      end Issued;
   end Crib;

   procedure Show (Label : String; T : Tool) is
   begin
      Put (Label & ": " & Tool_Kind'Image (T.Kind) & Natural'Image (T.Serial));
      case T.Kind is
         when Empty => null;
         when Gripper => Put (Natural'Image (T.Force));
         when Welder => Put (Natural'Image (T.Current));
      end case;
      New_Line;
   end Show;

   Arm : Tool;
   Station : Tool (Gripper);
begin
   Change_Tool (Arm, Gripper);
   Show ("arm", Arm);
   begin
      Change_Tool (Station, Welder);
   exception
      when Constraint_Error => Put_Line ("the station keeps its gripper");
   end;
   Show ("station", Station);
   Put_Line ("worn" & Natural'Image (Wear_Out (Arm)));
   Show ("arm", Arm);
   begin
      Put_Line ("worn" & Natural'Image (Wear_Out (Station)));
   exception
      when Constraint_Error => Put_Line ("a gripper station cannot be emptied");
   end;
   Crib.Issue (Arm);
   Show ("arm", Arm);
   begin
      Crib.Issue (Station);
   exception
      when Constraint_Error => Put_Line ("no welder for the station");
   end;
   Arm := (Kind => Empty, Serial => 7);
   Crib.Issue_Twice (Arm);
   Show ("arm", Arm);
   begin
      Crib.Issue_Twice (Station);
   exception
      when Constraint_Error => Put_Line ("still no welder for the station");
   end;
   Put_Line ("issued" & Natural'Image (Crib.Issued));
end Discriminant_Formals;
