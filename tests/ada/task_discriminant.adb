with Ada.Text_IO; use Ada.Text_IO;

--  RM 9.1(2), 9.1(12), 3.7: a task type may have discriminants; each
--  object gets its own values, given by a discriminant constraint (also
--  through a subtype, a record component and an allocator, RM 3.7.1),
--  and visible in the task body and as Object.Id outside it. An
--  assembly cell with one task per station, each reporting its own Id.
procedure Task_Discriminant is
   task type Station (Id : Positive; Speed : Natural) is
      entry Report (Code : out Natural);
   end Station;

   task body Station is
      Value : constant Natural := Id * 1000 + Speed;
   begin
      accept Report (Code : out Natural) do
         Put_Line ("  station" & Positive'Image (Id) & " reporting");
         Code := Value;
      end Report;
   end Station;

   subtype Welder is Station (Id => 7, Speed => 40);
   type Station_Ref is access Station;

   type Cell is record
      Feeder : Station (Id => 5, Speed => 70);
   end record;

   Loader : Station (1, 100);
   Painter : Station (2, 55);
   Spot : Welder;
   Line : Cell;
   Extra : constant Station_Ref := new Station (Id => 9, Speed => 0);
   Line_Up : array (1 .. 3) of Station_Ref;
   Code : Natural;
begin
   for I in Line_Up'Range loop
      Line_Up (I) := new Station (Id => 20 + I, Speed => I * 10);
   end loop;
   Put_Line ("Ids:" & Positive'Image (Loader.Id) & Positive'Image (Painter.Id)
             & Positive'Image (Spot.Id) & Positive'Image (Line.Feeder.Id)
             & Positive'Image (Extra.Id));
   Put_Line ("Speeds:" & Natural'Image (Loader.Speed) & Natural'Image (Painter.Speed)
             & Natural'Image (Spot.Speed) & Natural'Image (Line.Feeder.Speed)
             & Natural'Image (Extra.Speed));
   Loader.Report (Code);
   Put_Line ("Loader:" & Natural'Image (Code));
   Painter.Report (Code);
   Put_Line ("Painter:" & Natural'Image (Code));
   Spot.Report (Code);
   Put_Line ("Spot:" & Natural'Image (Code));
   Line.Feeder.Report (Code);
   Put_Line ("Feeder:" & Natural'Image (Code));
   Extra.Report (Code);
   Put_Line ("Extra:" & Natural'Image (Code));
   for I in reverse Line_Up'Range loop
      Line_Up (I).Report (Code);
      Put_Line ("Line_Up (" & Integer'Image (I) & "): Id" & Positive'Image (Line_Up (I).Id)
                & ", code" & Natural'Image (Code));
   end loop;
end Task_Discriminant;
