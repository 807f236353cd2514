MODULE assignment
! @format 3
! @section 4.5
! @expect ok
! @description An assignment replaces the current value of the target with the value of the expression (section 4.5); the right-hand side reads the old value.
! @output count=1
! @output count=2
! @exit 0
  VAR num count;
  PROC main()
    count := count + 1;
    TPWrite "count=" \Num:=count;
    count := count + 1;
    TPWrite "count=" \Num:=count;
  ENDPROC
ENDMODULE
