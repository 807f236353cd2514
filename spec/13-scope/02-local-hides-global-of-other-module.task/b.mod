MODULE cell
! @format 2
! @section 2.20
! @expect ok
! @description A LOCAL module object hides a global object of the same name declared in another module: level is a num in b.
  LOCAL VAR num level;
  PROC main()
    level := 3;
  ENDPROC
ENDMODULE
