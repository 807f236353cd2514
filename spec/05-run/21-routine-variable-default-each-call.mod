MODULE routine_variable_default
! @format 3
! @section 2.21
! @section 2.22
! @expect ok
! @description A routine variable without initial value receives the initial value of its type (0 for num, section 2.22) at every call, not the value left by the previous call (reading: the table of section 2.22 applies to routine variables too).
! @output 1 x
! @output 1 x
! @exit 0
  PROC count()
    VAR num n;
    VAR string s;
    n := n + 1;
    s := s + "x";
    TPWrite NumToStr(n, 0) + " " + s;
  ENDPROC
  PROC main()
    count;
    count;
  ENDPROC
ENDMODULE
