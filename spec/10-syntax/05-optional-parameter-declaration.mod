MODULE optional_parameter_declaration
! @section 5.2
! @expect ok
! @description The switch example of section 5.2 (its elided parameters completed), and optional parameters with alternatives.
  PROC glue(\switch on | switch off, pos p)
    IF Present(off ) THEN
      ! check presence of optional parameter 'off'
      p.x := 0;
    ENDIF
  ENDPROC
  PROC main()
    glue\off, pos2; ! argument use
  ENDPROC
  PROC q(\num a | num b | <ALT>, \<ALT>, \VAR num c | PERS num d | INOUT num e)
  ENDPROC
ENDMODULE
