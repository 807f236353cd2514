MODULE absent_parameter_passed_on
! @format 3
! @section 5.2
! @section 12
! @expect ok
! @description Giving an absent optional parameter as a required argument uses its value: ERR_NOTPRES at that call, before the called procedure starts.
! @exit 1
! @error ERR_NOTPRES 13:5
  PROC need(num v)
    TPWrite "wrong";
  ENDPROC
  PROC pass(\num n)
    need n;
  ENDPROC
  PROC main()
    pass;
  ENDPROC
ENDMODULE
