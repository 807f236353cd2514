MODULE recursion_own_instances
! @format 3
! @section 2.21
! @expect ok
! @description In a chain of recursive calls every instance of the routine gets its own memory for the same routine variable (section 2.21): each level still sees its own value after the deeper calls return.
! @output level 1
! @output level 2
! @output level 3
! @exit 0
  PROC down(num depth)
    VAR num mine;
    mine := depth;
    IF depth > 1 down depth - 1;
    TPWrite "level " \Num:=mine;
  ENDPROC
  PROC main()
    down 3;
  ENDPROC
ENDMODULE
