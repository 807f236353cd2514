MODULE component_name_missing
! @section 3.6
! @expect syntax-error 8:12
! @description '.' must be followed by a component name.
  VAR pos p;
  VAR num x;
  PROC main()
    x := p.;
  ENDPROC
ENDMODULE
