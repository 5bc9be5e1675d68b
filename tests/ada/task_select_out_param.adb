with Ada.Text_IO; use Ada.Text_IO;

--  RM 9.5.2(24), 6.4.1(17): an out parameter of an accept statement is
--  copied back to the caller when the accept body ends, also when the
--  accept is an alternative of a selective accept (RM 9.7.1) that has a
--  terminate alternative. A counting server in a conveyor cell: parts are
--  reported with one entry and the count is read back with another.
procedure Task_Select_Out_Param is
   task Counter is
      entry Part (Weight : in Positive);
      entry Lines (N : out Natural);
      entry Heaviest (W : in out Natural);
   end Counter;

   task body Counter is
      Count : Natural := 0;
      Max : Natural := 0;
   begin
      loop
         select
            accept Part (Weight : in Positive) do
               Count := Count + 1;
               if Weight > Max then
                  Max := Weight;
               end if;
            end Part;
         or
            accept Lines (N : out Natural) do
               N := Count;
            end Lines;
         or
            when Count > 0 =>
               accept Heaviest (W : in out Natural) do
                  if Max > W then
                     W := Max;
                  end if;
               end Heaviest;
         or
            terminate;
         end select;
      end loop;
   end Counter;

   N : Natural := 0;
   W : Natural := 4;
begin
   Counter.Lines (N);
   Put_Line ("lines before:" & Natural'Image (N));
   for Weight in 1 .. 7 loop
      Counter.Part (Weight * 3 mod 10 + 1);
   end loop;
   Counter.Lines (N);
   Put_Line ("lines after:" & Natural'Image (N));
   Counter.Heaviest (W);
   Put_Line ("heaviest:" & Natural'Image (W));
   W := 50;
   Counter.Heaviest (W);
   Put_Line ("heaviest, starting from 50:" & Natural'Image (W));
end Task_Select_Out_Param;
