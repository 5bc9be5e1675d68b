with Ada.Text_IO; use Ada.Text_IO;

--  Tasks created by allocators: each is activated by its `new`, runs
--  independently of the declaring block, and is reached through the access
--  value. 'Callable and 'Terminated through the access value.
procedure Task_Access_New is
   task type Counter is
      entry Add (N : Integer);
      entry Total (T : out Integer);
      entry Quit;
   end Counter;

   type Counter_Ref is access Counter;

   task body Counter is
      Sum : Integer := 0;
   begin
      loop
         select
            accept Add (N : Integer) do
               Sum := Sum + N;
            end Add;
         or
            accept Total (T : out Integer) do
               T := Sum;
            end Total;
         or
            accept Quit;
            exit;
         end select;
      end loop;
   end Counter;

   A, B : Counter_Ref;
   T : Integer;
   Pool : array (1 .. 3) of Counter_Ref;
begin
   A := new Counter;
   B := new Counter;
   for I in 1 .. 10 loop
      A.Add (I);
      B.all.Add (I * I);
   end loop;
   A.Total (T);
   Put_Line ("A total" & Integer'Image (T));
   B.Total (T);
   Put_Line ("B total" & Integer'Image (T));
   Put_Line ("A callable: " & Boolean'Image (A'Callable));
   A.Quit;
   while not A'Terminated loop
      delay 0.001;
   end loop;
   Put_Line ("A terminated: " & Boolean'Image (A.all'Terminated));
   Put_Line ("A callable: " & Boolean'Image (A'Callable));
   Put_Line ("B terminated: " & Boolean'Image (B'Terminated));
   for I in Pool'Range loop
      Pool (I) := new Counter;
      Pool (I).Add (I * 1000);
   end loop;
   for I in Pool'Range loop
      Pool (I).Total (T);
      Put_Line ("pool" & Integer'Image (I) & ":" & Integer'Image (T));
      Pool (I).Quit;
   end loop;
   B.Quit;
   Put_Line ("done");
end Task_Access_New;
