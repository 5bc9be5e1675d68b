with Ada.Text_IO; use Ada.Text_IO;

--  A cell controller hands out parts to robots by priority: the entry
--  family Request (Priority) keeps one queue per priority. Urgent requests
--  go first, then normal ones, then low ones (guards on the members'
--  'Count), and at the end of the shift a loop over the family index
--  drains what is left. A robot that finds the controller busy makes a
--  conditional call, another a timed call, on a single member.
procedure Task_Entry_Family_Priority is
   type Priority is (Urgent, Normal, Low);
   subtype Part_Id is Integer range 1 .. 99;

   task Controller is
      entry Request (Priority) (Part : in Part_Id; Ticket : out Positive);
      entry Drain;
   end Controller;

   task body Controller is
      Next : Positive := 1;

      procedure Hand_Out (P : Priority; Part : Part_Id; Ticket : out Positive) is
      begin
         Ticket := Next;
         Put_Line (Priority'Image (P) & " part" & Part_Id'Image (Part)
                   & " gets ticket" & Positive'Image (Next));
         Next := Next + 1;
      end Hand_Out;
   begin
      delay 0.5;  --  every robot has queued by now
      Put_Line ("queued:" & Natural'Image (Request (Urgent)'Count)
                & Natural'Image (Request (Normal)'Count)
                & Natural'Image (Request (Low)'Count));
      for Round in 1 .. 3 loop
         select
            accept Request (Urgent) (Part : in Part_Id; Ticket : out Positive) do
               Hand_Out (Urgent, Part, Ticket);
            end Request;
         or
            when Request (Urgent)'Count = 0 =>
               accept Request (Normal) (Part : in Part_Id; Ticket : out Positive) do
                  Hand_Out (Normal, Part, Ticket);
               end Request;
         or
            when Request (Urgent)'Count = 0 and Request (Normal)'Count = 0 =>
               accept Request (Low) (Part : in Part_Id; Ticket : out Positive) do
                  Hand_Out (Low, Part, Ticket);
               end Request;
         end select;
      end loop;
      accept Drain;
      for P in reverse Priority loop
         while Request (P)'Count > 0 loop
            accept Request (P) (Part : in Part_Id; Ticket : out Positive) do
               Hand_Out (P, Part, Ticket);
            end Request;
         end loop;
      end loop;
      Put_Line ("controller done");
   end Controller;

   task type Robot is
      entry Start (Level : Priority; Part : Part_Id);
      entry Report (Got : out Natural);
   end Robot;

   task body Robot is
      L : Priority;
      P : Part_Id;
      T : Positive;
   begin
      accept Start (Level : Priority; Part : Part_Id) do
         L := Level;
         P := Part;
      end Start;
      Controller.Request (L) (P, T);
      accept Report (Got : out Natural) do
         Got := T;
      end Report;
   end Robot;

   Robots : array (1 .. 6) of Robot;
   Levels : constant array (1 .. 6) of Priority :=
     (Low, Normal, Urgent, Low, Urgent, Normal);
   Got : Natural;
   T : Positive;
begin
   for I in Robots'Range loop
      Robots (I).Start (Levels (I), 10 * I);
      delay 0.01;
   end loop;
   select
      Controller.Request (Urgent) (77, T);
      Put_Line ("conditional call served");
   else
      Put_Line ("conditional call: controller busy");
   end select;
   select
      Controller.Request (Normal) (88, T);
      Put_Line ("timed call served");
   or
      delay 0.1;
      Put_Line ("timed call: gave up");
   end select;
   delay 1.0;
   Controller.Drain;
   for I in Robots'Range loop
      Robots (I).Report (Got);
      Put_Line ("robot" & Integer'Image (I) & " " & Priority'Image (Levels (I))
                & " ticket" & Natural'Image (Got));
   end loop;
end Task_Entry_Family_Priority;
