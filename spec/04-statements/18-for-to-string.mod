MODULE for_to_string
! @format 2
! @section 4.18
! @expect semantic-error 7:21
! @description The from, to and step expressions must be of type num; a string to expression is refused at it.
  PROC main()
    FOR i FROM 1 TO "5" DO
      DebugBreak;
    ENDFOR
  ENDPROC
ENDMODULE
