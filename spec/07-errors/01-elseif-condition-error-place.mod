MODULE elseif_condition_error_place
! @format 3
! @section 4.16
! @section 7.1
! @expect ok
! @description An error in an ELSEIF condition that nothing handles is reported at the ELSEIF, which introduces the condition.
! @exit 1
! @error ERR_DIVZERO 13:5
  VAR num n := 0;
  PROC main()
    IF n = 1 THEN
      TPWrite "one";
    ELSEIF 1 / n > 0 THEN
      TPWrite "positive";
    ENDIF
  ENDPROC
ENDMODULE
