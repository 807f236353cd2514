MODULE for_from_dnum
! @format 2
! @section 4.18
! @expect semantic-error 8:16
! @description The from expression must be of type num; a dnum variable is refused at it.
  VAR dnum start;
  PROC main()
    FOR i FROM start TO 5 DO
      DebugBreak;
    ENDFOR
  ENDPROC
ENDMODULE
