with Ada.Text_IO; use Ada.Text_IO;

procedure Block_Statements is
   X : Integer := 1;
begin
   Put_Line ("X =" & Integer'Image (X));
   declare
      X : Integer := 100;
      Y : constant Integer := X + 1;
   begin
      X := X + Y;
      Put_Line ("inner X =" & Integer'Image (X) & " Y =" & Integer'Image (Y));
      Put_Line ("outer X via name =" & Integer'Image (Block_Statements.X));
      Block_Statements.X := 5;
   end;
   Put_Line ("X =" & Integer'Image (X));
   Named :
   declare
      Z : Integer := X * 2;
   begin
      Z := Z + 1;
      Put_Line ("Named.Z =" & Integer'Image (Named.Z));
   end Named;
   begin
      X := X + 1;
      Put_Line ("block without declarations, X =" & Integer'Image (X));
   end;
   for I in 1 .. 3 loop
      declare
         Square : constant Integer := I * I;
         Text   : constant String := "square of" & Integer'Image (I);
      begin
         Put_Line (Text & " is" & Integer'Image (Square) & " (length" & Integer'Image (Text'Length) & ")");
      end;
   end loop;
   declare
      type Local_Enum is (One, Two, Three);
      Count : Integer := 0;
   begin
      for E in Local_Enum loop
         Count := Count + Local_Enum'Pos (E);
      end loop;
      Put_Line ("local enum sum:" & Integer'Image (Count) & " last " & Local_Enum'Image (Local_Enum'Last));
      declare
         Count : constant Integer := -1;
      begin
         Put_Line ("nested shadow Count =" & Integer'Image (Count));
      end;
      Put_Line ("Count again =" & Integer'Image (Count));
   end;
   declare
      N : constant Integer := X * 3;
      subtype Upto is Integer range 1 .. N;
      Total : Integer := 0;
   begin
      for I in Upto loop
         Total := Total + I;
      end loop;
      Put_Line ("sum 1 .." & Integer'Image (N) & " =" & Integer'Image (Total));
   end;
end Block_Statements;
