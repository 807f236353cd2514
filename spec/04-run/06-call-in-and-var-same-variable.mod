MODULE call_in_and_var_same
! @format 3
! @section 5.2
! @expect ok
! @description The same variable given to an in parameter and a var parameter: the in parameter holds a copy taken at the call, so an update through the var parameter does not change it.
! @output copy=1
! @output shared=5
! @exit 0
  PROC mix(num copy, VAR num shared)
    shared := 5;
    TPWrite "copy=" \Num:=copy;
    TPWrite "shared=" \Num:=shared;
  ENDPROC
  PROC main()
    VAR num v := 1;
    mix v, v;
  ENDPROC
ENDMODULE
