MODULE loop_variable_not_in_bounds
! @format 2
! @section 4.18
! @section 2.20
! @expect semantic-error 8:21
! @description The from, to and step expressions are outside the loop variable's scope; a use of it there is refused as an unknown name.
  PROC main()
    FOR i FROM 1 TO i + 3 DO
      DebugBreak;
    ENDFOR
  ENDPROC
ENDMODULE
