MODULE test_values_in_order
! @format 3
! @section 4.20
! @expect ok
! @description The test values are evaluated in order, case by case and within a case left to right, until one equals the test expression's value: those after it are not evaluated; when none is equal, every one was, and the DEFAULT list runs.
! @output 1 2 3 4 second
! @output 1 2 3 4 5 default
! @exit 0
  VAR string seen := "";
  FUNC num v(num n)
    seen := seen + NumToStr(n, 0) + " ";
    RETURN n;
  ENDFUNC
  PROC choose(num x)
    seen := "";
    TEST x
    CASE v(1), v(2):
      TPWrite seen + "first";
    CASE v(3), v(4), v(5):
      TPWrite seen + "second";
    DEFAULT:
      TPWrite seen + "default";
    ENDTEST
  ENDPROC
  PROC main()
    choose 4;
    choose 9;
  ENDPROC
ENDMODULE
