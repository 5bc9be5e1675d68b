with Ada.Text_IO; use Ada.Text_IO;

procedure Recursion is
   Moves : Natural := 0;
   function Fib (N : Natural) return Natural is
   begin
      if N < 2 then
         return N;
      else
         return Fib (N - 1) + Fib (N - 2);
      end if;
   end Fib;
   function Ackermann (M, N : Natural) return Natural is
   begin
      if M = 0 then
         return N + 1;
      elsif N = 0 then
         return Ackermann (M - 1, 1);
      else
         return Ackermann (M - 1, Ackermann (M, N - 1));
      end if;
   end Ackermann;
   procedure Hanoi (N : Natural; From, To, Via : Character) is
   begin
      if N > 0 then
         Hanoi (N - 1, From, Via, To);
         Moves := Moves + 1;
         Put_Line ("move disk" & Integer'Image (N) & " from " & From & " to " & To);
         Hanoi (N - 1, Via, To, From);
      end if;
   end Hanoi;
   function Factorial (N : Natural) return Positive is
   begin
      return (if N = 0 then 1 else N * Factorial (N - 1));
   end Factorial;
   function Gcd (A, B : Natural) return Natural is
   begin
      if B = 0 then
         return A;
      end if;
      return Gcd (B, A mod B);
   end Gcd;
   function Is_Even (N : Natural) return Boolean;
   function Is_Odd (N : Natural) return Boolean is
   begin
      return N /= 0 and then Is_Even (N - 1);
   end Is_Odd;
   function Is_Even (N : Natural) return Boolean is
   begin
      return N = 0 or else Is_Odd (N - 1);
   end Is_Even;
begin
   for I in 0 .. 15 loop
      Put (Integer'Image (Fib (I)));
   end loop;
   New_Line;
   Put_Line ("Fib (25) =" & Integer'Image (Fib (25)));
   for M in 0 .. 2 loop
      for N in 0 .. 3 loop
         Put (Integer'Image (Ackermann (M, N)));
      end loop;
      New_Line;
   end loop;
   Put_Line ("Ackermann (3, 3) =" & Integer'Image (Ackermann (3, 3)));
   Hanoi (3, 'A', 'C', 'B');
   Put_Line ("moves:" & Integer'Image (Moves));
   for I in 0 .. 12 loop
      Put (Integer'Image (Factorial (I)));
   end loop;
   New_Line;
   Put_Line ("Gcd (1071, 462) =" & Integer'Image (Gcd (1071, 462)));
   Put_Line ("Is_Even (10) = " & Boolean'Image (Is_Even (10)) & ", Is_Odd (7) = " & Boolean'Image (Is_Odd (7)));
   begin
      Put_Line ("Factorial (13) =" & Integer'Image (Factorial (13)));
   exception
      when Constraint_Error =>
         Put_Line ("Factorial (13) overflows");
   end;
end Recursion;
