with Ada.Text_IO; use Ada.Text_IO;
--  An allocator inside an aggregate puts its task under the master of its
--  access type too: the inner block does not wait for it.
procedure Task_Access_Master_Aggregate is
   task type W;
   task body W is begin delay 0.2; Put_Line ("W done"); end W;
   type A is access W;
   type R is record P : A; N : Integer; end record;
   task type V;
   task body V is begin delay 0.1; Put_Line ("V done"); end V;
   X : R;
begin
   declare
      Y : V;
   begin
      X := (P => new W, N => 2);
   end;
   Put_Line ("block left");
end Task_Access_Master_Aggregate;
