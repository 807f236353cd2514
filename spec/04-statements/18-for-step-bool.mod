MODULE for_step_bool
! @format 2
! @section 4.18
! @expect semantic-error 7:28
! @description The step expression must be of type num; a bool is refused at it.
  PROC main()
    FOR i FROM 1 TO 5 STEP TRUE DO
      DebugBreak;
    ENDFOR
  ENDPROC
ENDMODULE
