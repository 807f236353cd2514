MODULE call_in_by_copy
! @format 3
! @section 5.2
! @section 4.6
! @expect ok
! @description An in parameter starts with the value of its argument and is then an ordinary routine variable (section 5.2): assigning to it leaves the caller's variable unchanged.
! @output inside=10
! @output outside=1
! @exit 0
  PROC change(num a)
    a := 10;
    TPWrite "inside=" \Num:=a;
  ENDPROC
  PROC main()
    VAR num v := 1;
    change v;
    TPWrite "outside=" \Num:=v;
  ENDPROC
ENDMODULE
