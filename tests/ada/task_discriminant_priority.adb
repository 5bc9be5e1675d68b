--  A task's discriminant gives its priority (RM D.1: pragma Priority in the
--  task's specification may read the discriminants): conveyor drives of
--  several priorities, each reporting its id and level; 'Constrained of a
--  task object is True (RM 3.7.2).
with Ada.Text_IO; use Ada.Text_IO;
procedure Task_Discriminant_Priority is
   subtype Drive_Level is Integer range 1 .. 30;
   task type Drive (Id : Positive := 4; Level : Drive_Level := 15) is
      pragma Priority (Level);
      entry Report (N : out Positive; P : out Drive_Level);
   end Drive;

   task body Drive is
   begin
      accept Report (N : out Positive; P : out Drive_Level) do
         N := Id;
         P := Level;
      end Report;
   end Drive;

   N : Positive;
   P : Drive_Level;
begin
   Put_Line ("main");
   declare
      Low : Drive (1, 5);
      High : Drive (2, 20);
      Mid : Drive (Id => 3, Level => 10);
      Plain : Drive;
   begin
      Put_Line ("constrained: " & Boolean'Image (Low'Constrained) & " " & Boolean'Image (Plain'Constrained));
      High.Report (N, P);
      Put_Line ("high:" & Positive'Image (N) & Integer'Image (P));
      Low.Report (N, P);
      Put_Line ("low:" & Positive'Image (N) & Integer'Image (P));
      Mid.Report (N, P);
      Put_Line ("mid:" & Positive'Image (N) & Integer'Image (P));
      Plain.Report (N, P);
      Put_Line ("plain:" & Positive'Image (N) & Integer'Image (P));
   end;
end Task_Discriminant_Priority;
