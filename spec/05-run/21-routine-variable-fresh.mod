MODULE routine_variable_fresh
! @format 3
! @section 2.21
! @section 2.22
! @expect ok
! @description Routine variables are volatile (section 2.21): every call gets a new instance, initialised again from its declaration, so the increment of one call is not seen by the next.
! @output 6
! @output 6
! @exit 0
  PROC count()
    VAR num n := 5;
    n := n + 1;
    TPWrite "" \Num:=n;
  ENDPROC
  PROC main()
    count;
    count;
  ENDPROC
ENDMODULE
