MODULE present_optional
! @format 3
! @section 5.2
! @section 11
! @expect ok
! @description An optional parameter is present when the call gives its argument (section 5.2); Present tells which, and a present parameter has the argument's value.
! @output absent
! @output present 25
! @exit 0
  PROC arcweld(\num speed)
    IF Present(speed) THEN
      TPWrite "present " \Num:=speed;
    ELSE
      TPWrite "absent";
    ENDIF
  ENDPROC
  PROC main()
    arcweld;
    arcweld \speed:=25;
  ENDPROC
ENDMODULE
