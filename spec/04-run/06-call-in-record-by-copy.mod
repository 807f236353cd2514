MODULE call_in_record_by_copy
! @format 3
! @section 5.2
! @expect ok
! @description A record passed to an in parameter is copied: changing a component of the parameter does not change the argument.
! @output inside=50
! @output outside=1
! @exit 0
  PROC change(pos p)
    p.x := 50;
    TPWrite "inside=" \Num:=p.x;
  ENDPROC
  PROC main()
    VAR pos v := [1, 2, 3];
    change v;
    TPWrite "outside=" \Num:=v.x;
  ENDPROC
ENDMODULE
