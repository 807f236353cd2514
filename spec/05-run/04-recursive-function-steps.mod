MODULE recursive_function_steps
! @format 3
! @section 4.17
! @section 4.10
! @section 3.12
! @section 2.13
! @section 5.4
! @expect ok
! @description Recursive functions of two statements, a compact IF returning the parameter or a literal and then RETURN of a sum, difference or product of two operands neither of them a num literal: the left operand is evaluated before the right (§3.1), each operation is rounded to single precision (ten additions of 0.1 give 1.0000001, more than 1), and a product beyond the range of num is ERR_OVERFLOW in the RETURN statement.
! @output fact(10)=3628800
! @output diff(4)=2
! @output order=121
! @output tenths(10) > 1=TRUE
! @output sq: ERR_OVERFLOW
! @exit 0
  VAR num order := 0;
  FUNC num fact(num n)
    IF n <= 1 RETURN 1;
    RETURN n * fact(n - 1);
  ENDFUNC
  FUNC num diff(num n)
    IF n < 1 RETURN n;
    RETURN n - diff(n - 1);
  ENDFUNC
  FUNC num mark(num d)
    order := order * 10 + d;
    RETURN d;
  ENDFUNC
  FUNC num pair(num n)
    IF n > 0 RETURN n;
    RETURN mark(1) + mark(2) - 0 * pair(1);
  ENDFUNC
  FUNC num tenths(num n)
    IF n <= 0 RETURN 0;
    RETURN 0.1 + tenths(n - 1);
  ENDFUNC
  FUNC num sq(num x)
    IF x < 2E38 RETURN x;
    RETURN x * sq(x / 2);
  ENDFUNC
  PROC main()
    VAR num r;
    TPWrite "fact(10)=" \Num:=fact(10);
    TPWrite "diff(4)=" \Num:=diff(4);
    r := pair(0) + mark(1);
    TPWrite "order=" \Num:=order;
    TPWrite "tenths(10) > 1=" \Bool:=tenths(10) > 1;
    r := sq(3E38);
    TPWrite "sq: no error";
  ERROR
    IF ERRNO = ERR_OVERFLOW TPWrite "sq: ERR_OVERFLOW";
    RETURN;
  ENDPROC
ENDMODULE
