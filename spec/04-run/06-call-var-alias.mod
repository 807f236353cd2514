MODULE call_var_alias
! @format 3
! @section 5.2
! @expect ok
! @description A var parameter is an alias of its argument (section 5.2): an update through the parameter is at once an update of the argument, visible through the argument's own name before the procedure returns.
! @output during=5
! @output after=5
! @exit 0
  VAR num g := 1;
  PROC change(VAR num a)
    a := 5;
    TPWrite "during=" \Num:=g;
  ENDPROC
  PROC main()
    change g;
    TPWrite "after=" \Num:=g;
  ENDPROC
ENDMODULE
