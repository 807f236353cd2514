MODULE recursive_function_guards
! @format 3
! @section 4.17
! @section 4.10
! @section 3.12
! @section 2.13
! @section 5.4
! @expect ok
! @description Recursive functions whose first statement is a compact IF comparing the parameter with a num literal (each comparison operator) and returning, and whose recursive call passes the parameter plus or minus a literal: each call gets a copy of its argument, each operation is rounded to single precision (the steps of 0.1 reach 1 after ten additions, 1.0000001, not after eleven as in double precision), and an overflowing argument is ERR_OVERFLOW in the calling statement.
! @output fib(10)=55
! @output sumto(10)=55
! @output sumdown(6)=315
! @output countup(3)=10
! @output atleast(2)=5
! @output up(0) >= 1=TRUE
! @output up(0) < 1.05=TRUE
! @output steps=10
! @output tozero(4)=100
! @output nz(5)=5
! @output down(2.5)=-0.5
! @output grow: ERR_OVERFLOW
! @exit 0
  VAR num steps := 0;
  FUNC num fib(num n)
    IF n < 2 RETURN n;
    RETURN fib(n - 1) + fib(n - 2);
  ENDFUNC
  FUNC num sumto(num n)
    IF n <= 0 RETURN 0;
    RETURN n + sumto(n - 1);
  ENDFUNC
  FUNC num sumdown(num n)
    IF n <= 3 RETURN n * 100;
    RETURN n + sumdown(n - 1);
  ENDFUNC
  FUNC num atleast(num n)
    IF n >= 5 RETURN n;
    RETURN atleast(n + 1);
  ENDFUNC
  FUNC num countup(num n)
    IF n > 9 RETURN n;
    RETURN countup(n + 1);
  ENDFUNC
  FUNC num up(num x)
    IF x >= 1 RETURN x;
    steps := steps + 1;
    RETURN up(x + 0.1);
  ENDFUNC
  FUNC num tozero(num n)
    IF n = 0 RETURN 100;
    RETURN tozero(n - 1);
  ENDFUNC
  FUNC num nz(num n)
    IF n <> 0 RETURN nz(n - 1) + 1;
    RETURN 0;
  ENDFUNC
  FUNC num down(num x)
    IF x < 0 RETURN x;
    RETURN down(x - 1);
  ENDFUNC
  FUNC num grow(num x)
    IF x < 0 RETURN x;
    RETURN grow(x + 3E38);
  ENDFUNC
  PROC main()
    VAR num r;
    TPWrite "fib(10)=" \Num:=fib(10);
    TPWrite "sumto(10)=" \Num:=sumto(10);
    TPWrite "sumdown(6)=" \Num:=sumdown(6);
    TPWrite "countup(3)=" \Num:=countup(3);
    TPWrite "atleast(2)=" \Num:=atleast(2);
    r := up(0);
    TPWrite "up(0) >= 1=" \Bool:=r >= 1;
    TPWrite "up(0) < 1.05=" \Bool:=r < 1.05;
    TPWrite "steps=" \Num:=steps;
    TPWrite "tozero(4)=" \Num:=tozero(4);
    TPWrite "nz(5)=" \Num:=nz(5);
    TPWrite "down(2.5)=" \Num:=down(2.5);
    r := grow(0);
    TPWrite "grow: no error";
  ERROR
    IF ERRNO = ERR_OVERFLOW TPWrite "grow: ERR_OVERFLOW";
    RETURN;
  ENDPROC
ENDMODULE
