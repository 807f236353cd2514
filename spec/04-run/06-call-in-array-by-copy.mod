MODULE call_in_array_by_copy
! @format 3
! @section 5.2
! @expect ok
! @description An array passed to an in parameter with {*} is copied: changing an element of the parameter does not change the argument.
! @output inside=99
! @output outside=1
! @exit 0
  PROC change(num a{*})
    a{1} := 99;
    TPWrite "inside=" \Num:=a{1};
  ENDPROC
  PROC main()
    VAR num v{2} := [1, 2];
    change v;
    TPWrite "outside=" \Num:=v{1};
  ENDPROC
ENDMODULE
