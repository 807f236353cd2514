MODULE placeholder_eit
! @section 2.9
! @section 4.16
! @expect ok
! @description <EIT> stands for an ELSEIF clause.
  VAR bool b;
  PROC main()
    IF b THEN
      b := FALSE;
    <EIT>
    <EIT>
    ELSE
      b := TRUE;
    ENDIF
  ENDPROC
ENDMODULE
