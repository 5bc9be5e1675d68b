with Ada.Text_IO; use Ada.Text_IO;

procedure Exception_Declare_Block is
   subtype Small is Integer range 1 .. 10;
   Limit_Hit : exception;
   Total : Integer := 0;
   function Id (X : Integer) return Integer is
   begin
      return X;
   end Id;
begin
   for I in 8 .. 12 loop
      declare
         S : constant Small := Id (I);
         Doubled : Integer := S * 2;
      begin
         Doubled := Doubled + 1;
         Total := Total + Doubled;
         Put_Line ("I =" & Integer'Image (I) & " Doubled =" & Integer'Image (Doubled));
      exception
         when Constraint_Error =>
            Put_Line ("never: handler of the block does not see its own declarations failing");
      end;
   end loop;
exception
   when Constraint_Error =>
      Put_Line ("caught in main handler, Total =" & Integer'Image (Total));
      declare
         Count : Integer := 0;
      begin
         loop
            Count := Count + 1;
            declare
               Local : constant Integer := Count * Count;
            begin
               if Local > 20 then
                  raise Limit_Hit;
               end if;
               Put_Line ("Local =" & Integer'Image (Local));
            end;
         end loop;
      exception
         when Limit_Hit =>
            Put_Line ("Limit hit at Count =" & Integer'Image (Count));
      end;
      declare
         Outer : Integer := 1;
      begin
         declare
            Inner : Small := 5;
         begin
            Inner := Id (Inner * 3);
            Outer := Inner;
         exception
            when Constraint_Error =>
               Outer := -1;
               Put_Line ("inner block handled its own statement failure");
         end;
         Put_Line ("Outer =" & Integer'Image (Outer));
      end;
end Exception_Declare_Block;
