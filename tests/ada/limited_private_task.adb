--  A limited private type whose full view is a task type: clients of the
--  package hold conveyor drivers as opaque handles and drive them through
--  the package's procedures, which call the task's entries.
with Ada.Text_IO; use Ada.Text_IO;

procedure Limited_Private_Task is
   package Conveyors is
      type Driver is limited private;
      procedure Start (D : in out Driver; Speed : Positive);
      procedure Stop (D : in out Driver; Moved : out Natural);
   private
      task type Driver is
         entry Start (Speed : Positive);
         entry Stop (Moved : out Natural);
      end Driver;
   end Conveyors;

   package body Conveyors is
      task body Driver is
         Rate  : Positive := 1;
         Total : Natural := 0;
      begin
         accept Start (Speed : Positive) do
            Rate := Speed;
         end Start;
         Total := Rate * 10;
         accept Stop (Moved : out Natural) do
            Moved := Total;
         end Stop;
      end Driver;

      procedure Start (D : in out Driver; Speed : Positive) is
      begin
         D.Start (Speed);
      end Start;

      procedure Stop (D : in out Driver; Moved : out Natural) is
      begin
         D.Stop (Moved);
      end Stop;
   end Conveyors;

   use Conveyors;

   type Belt_Line is record
      Infeed, Outfeed : Driver;
   end record;

   Line : Belt_Line;
   Single : Driver;
   Moved : Natural;
begin
   Start (Line.Infeed, 3);
   Start (Line.Outfeed, 5);
   Start (Single, 7);
   Stop (Line.Infeed, Moved);
   Put_Line ("infeed moved" & Natural'Image (Moved));
   Stop (Line.Outfeed, Moved);
   Put_Line ("outfeed moved" & Natural'Image (Moved));
   Stop (Single, Moved);
   Put_Line ("single moved" & Natural'Image (Moved));
end Limited_Private_Task;
