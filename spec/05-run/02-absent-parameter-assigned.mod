MODULE absent_parameter_assigned
! @format 3
! @section 5.2
! @section 12
! @expect ok
! @description The value of an absent optional parameter cannot be set either (section 5.2): assigning to it raises ERR_NOTPRES.
! @exit 1
! @error ERR_NOTPRES 10:5
  PROC set(\VAR num n)
    n := 1;
  ENDPROC
  PROC main()
    set;
  ENDPROC
ENDMODULE
