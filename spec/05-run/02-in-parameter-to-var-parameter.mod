MODULE in_parameter_to_var
! @format 3
! @section 5.2
! @expect ok
! @description An in parameter may be given to a var parameter (section 5.2's table): the alias is to the parameter's own copy, so the update changes the parameter and not the caller's variable.
! @output parameter=9
! @output caller=1
! @exit 0
  PROC set(VAR num y)
    y := 9;
  ENDPROC
  PROC mid(num x)
    set x;
    TPWrite "parameter=" \Num:=x;
  ENDPROC
  PROC main()
    VAR num v := 1;
    mid v;
    TPWrite "caller=" \Num:=v;
  ENDPROC
ENDMODULE
