MODULE alias_of_semi_value
! @format 2
! @section 2.15
! @section 2.16
! @expect ok
! @description An alias of a semi-value type is itself a semi-value type: read as its associated num in value context.
  ALIAS signaldi sensor;
  VAR sensor s;
  VAR num n;
  PROC main()
    IF s = 1 THEN
      n := s;
    ENDIF
  ENDPROC
ENDMODULE
