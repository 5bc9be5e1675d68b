with Ada.Text_IO; use Ada.Text_IO;

--  A task type, an array of its objects and a single object of it:
--  each worker gets its number by an entry and computes a square; main
--  collects the results in index order, so the output does not depend on
--  which worker finishes first.
procedure Task_Types_Array is
   task type Worker is
      entry Start (Id : Integer);
      entry Result (Value : out Integer);
   end Worker;

   task body Worker is
      My_Id : Integer := 0;
      Sum : Integer := 0;
   begin
      accept Start (Id : Integer) do
         My_Id := Id;
      end Start;
      for I in 1 .. My_Id loop
         Sum := Sum + I * I;
      end loop;
      accept Result (Value : out Integer) do
         Value := Sum;
      end Result;
   end Worker;

   type Worker_Array is array (1 .. 5) of Worker;
   Crew : Worker_Array;

   Helper : Worker;
   Helper_Number : constant Integer := 7;
   R : Integer;
   Total : Integer := 0;
begin
   for I in Crew'Range loop
      Crew (I).Start (I * 10);
   end loop;
   Helper.Start (Helper_Number);
   for I in reverse Crew'Range loop
      Crew (I).Result (R);
      Put_Line ("worker" & Integer'Image (I) & ":" & Integer'Image (R));
      Total := Total + R;
   end loop;
   Helper.Result (R);
   Put_Line ("helper" & Integer'Image (Helper_Number) & ":" & Integer'Image (R));
   Put_Line ("total" & Integer'Image (Total + R));
   for I in Crew'Range loop
      while not Crew (I)'Terminated loop
         delay 0.001;
      end loop;
   end loop;
   Put_Line ("all workers terminated");
end Task_Types_Array;
