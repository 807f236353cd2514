MODULE call_same_variable_twice
! @format 3
! @section 5.2
! @expect ok
! @description The same variable given to two var parameters: both are aliases of it, so an update through one is seen through the other at once.
! @output b=5
! @exit 0
  PROC both(VAR num a, VAR num b)
    a := 5;
    TPWrite "b=" \Num:=b;
  ENDPROC
  PROC main()
    VAR num v := 1;
    both v, v;
  ENDPROC
ENDMODULE
