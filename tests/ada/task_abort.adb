with Ada.Text_IO; use Ada.Text_IO;

--  abort: 'Callable is False at once, 'Terminated becomes True when the
--  task has finished dying (polled, as it may take a moment in GNAT). A
--  caller queued on an aborted task's entry gets Tasking_Error.
procedure Task_Abort is
   protected Flag is
      procedure Set;
      entry Wait_Set;
      procedure Note (Text : String);
      function Noted return String;
   private
      Is_Set : Boolean := False;
      Last : String (1 .. 20) := (others => ' ');
   end Flag;

   protected body Flag is
      procedure Set is
      begin
         Is_Set := True;
      end Set;
      entry Wait_Set when Is_Set is
      begin
         null;
      end Wait_Set;
      procedure Note (Text : String) is
      begin
         Last := (others => ' ');
         Last (1 .. Text'Length) := Text;
      end Note;
      function Noted return String is
      begin
         return Last;
      end Noted;
   end Flag;

   task Sleeper is
      entry Never;
   end Sleeper;
   task body Sleeper is
   begin
      accept Never;
      Put_Line ("Sleeper: not reached (wrong)");
   end Sleeper;

   task Spinner;
   task body Spinner is
   begin
      loop
         delay 0.001;
      end loop;
   end Spinner;

   task Victim is
      entry Service;
      entry Other;
   end Victim;
   task body Victim is
   begin
      while Service'Count = 0 loop
         delay 0.001;
      end loop;
      Flag.Set;                    --  a caller is queued on Service now
      accept Other;
   end Victim;

   task Caller;
   task body Caller is
   begin
      Victim.Service;
      Flag.Note ("served (wrong)");
   exception
      when Tasking_Error =>
         Flag.Note ("Tasking_Error");
   end Caller;

   task Quick;
   task body Quick is
   begin
      null;
   end Quick;

begin
   Put_Line ("Sleeper callable: " & Boolean'Image (Sleeper'Callable));
   abort Sleeper;
   Put_Line ("after abort, Sleeper callable: " & Boolean'Image (Sleeper'Callable));
   while not Sleeper'Terminated loop
      delay 0.001;
   end loop;
   Put_Line ("Sleeper terminated: " & Boolean'Image (Sleeper'Terminated));

   abort Spinner, Quick;            --  Quick may well be done already
   Put_Line ("Spinner callable: " & Boolean'Image (Spinner'Callable)
             & ", Quick callable: " & Boolean'Image (Quick'Callable));
   while not (Spinner'Terminated and Quick'Terminated) loop
      delay 0.001;
   end loop;
   Put_Line ("Spinner and Quick terminated");

   Flag.Wait_Set;
   abort Victim;
   while not Caller'Terminated loop
      delay 0.001;
   end loop;
   Put_Line ("Caller saw: " & Flag.Noted);
   abort Victim;                    --  aborting it again does nothing
   while not Victim'Terminated loop  --  GNAT may still be ending it
      delay 0.001;
   end loop;
   Put_Line ("Victim terminated: " & Boolean'Image (Victim'Terminated));
end Task_Abort;
