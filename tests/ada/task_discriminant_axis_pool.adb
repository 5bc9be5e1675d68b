--  A pool of axis controllers (RM 9.1, 3.7, 3.7.1): each task gets its own
--  axis number and gain from its discriminant constraint, positional or
--  named, or from the defaults; the discriminants are read in the task's
--  declarative part, in an accept's guard, inside an accept body, and
--  from outside as Ctl.Axis. A joint record whose discriminant constrains
--  its controller component; allocators with constraints.
with Ada.Text_IO; use Ada.Text_IO;
procedure Task_Discriminant_Axis_Pool is
   subtype Axis_Id is Integer range 1 .. 6;

   task type Controller (Axis : Axis_Id := 1; Gain : Natural := 10) is
      entry Move (Target : Integer; Reached : out Integer);
      entry Home;
      entry Stop;
   end Controller;

   task body Controller is
      Limit : constant Integer := Axis * 100;
      Position : Integer := 0;
      Homes : Natural := 0;
   begin
      loop
         select
            accept Move (Target : Integer; Reached : out Integer) do
               if Target > Limit then
                  Position := Limit;
               else
                  Position := Target;
               end if;
               Reached := Position * Gain;
            end Move;
         or
            when Axis mod 2 = 0 =>
               accept Home do
                  Homes := Homes + 1;
                  Position := 0;
                  Put_Line ("  axis" & Axis_Id'Image (Axis) & " homed");
               end Home;
         or
            accept Stop do
               Put_Line ("  axis" & Axis_Id'Image (Axis) & " stops at"
                         & Integer'Image (Position) & ", homed"
                         & Natural'Image (Homes) & " times");
            end Stop;
            exit;
         end select;
      end loop;
   end Controller;

   type Controller_Ref is access Controller;
   subtype Wrist is Controller (Axis => 5, Gain => 3);

   type Joint (N : Axis_Id) is record
      Ctl : Controller (N, 8);
      Offset : Integer := N;
   end record;

   Base : Controller;
   Shoulder : Controller (2, 7);
   Elbow : Controller (Gain => 4, Axis => 3);
   Roll : Wrist;
   Knee : Joint (4);
   Pool : array (1 .. 3) of Controller_Ref;
   R : Integer;
begin
   for I in Pool'Range loop
      Pool (I) := new Controller (Axis => I + 3, Gain => I);
   end loop;
   Put_Line ("axes:" & Axis_Id'Image (Base.Axis) & Axis_Id'Image (Shoulder.Axis)
             & Axis_Id'Image (Elbow.Axis) & Axis_Id'Image (Roll.Axis)
             & Axis_Id'Image (Knee.Ctl.Axis) & Axis_Id'Image (Pool (3).Axis));
   Put_Line ("gains:" & Natural'Image (Base.Gain) & Natural'Image (Shoulder.Gain)
             & Natural'Image (Elbow.Gain) & Natural'Image (Roll.Gain)
             & Natural'Image (Knee.Ctl.Gain) & Natural'Image (Pool (3).Gain));
   Base.Move (250, R);
   Put_Line ("base" & Integer'Image (R));
   Shoulder.Move (150, R);
   Put_Line ("shoulder" & Integer'Image (R));
   Shoulder.Home;
   Elbow.Move (-40, R);
   Put_Line ("elbow" & Integer'Image (R));
   select
      Elbow.Home;
      Put_Line ("elbow homed?");
   else
      Put_Line ("elbow has no home switch");
   end select;
   Roll.Move (900, R);
   Put_Line ("roll" & Integer'Image (R));
   Knee.Ctl.Move (333, R);
   Put_Line ("knee" & Integer'Image (R) & Integer'Image (Knee.Offset));
   Knee.Ctl.Home;
   for I in reverse Pool'Range loop
      Pool (I).Move (I * 1000, R);
      Put_Line ("pool" & Integer'Image (I) & ": axis" & Axis_Id'Image (Pool (I).Axis)
                & " reached" & Integer'Image (R));
   end loop;
   Pool (1).Home;
   Base.Stop;
   Shoulder.Stop;
   Elbow.Stop;
   Roll.Stop;
   Knee.Ctl.Stop;
   for P of Pool loop
      P.Stop;
   end loop;
end Task_Discriminant_Axis_Pool;
