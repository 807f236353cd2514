MODULE label_hides_module_data
! @format 2
! @section 4.4
! @expect ok
! @description A label hides a user object of the same name within its routine, and another routine still sees the module variable.
  VAR num next;
  PROC main()
    next:
    GOTO next;
  ENDPROC
  PROC other()
    next := 1;
  ENDPROC
ENDMODULE
