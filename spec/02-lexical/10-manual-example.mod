MODULE manual_example
! @section 2.10
! @expect ok
! @description The example of section 2.10, inside a procedure.
  VAR num length;
  PROC main()
    ! Increase length
    length := length + 5;
    IF length < 1000 OR length > 14000 THEN
      ! Out of bounds
      EXIT;
    ENDIF
  ENDPROC
ENDMODULE
