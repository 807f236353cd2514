MODULE record_component_unknown
! @format 2
! @section 2.14
! @expect semantic-error 8:7
! @description A component name that the record type does not have is refused at that component name (pos has x, y, z).
  VAR pos p;
  PROC main()
    p.w := 1;
  ENDPROC
ENDMODULE
