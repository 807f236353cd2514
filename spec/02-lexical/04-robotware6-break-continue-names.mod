MODULE robotware6_names
! @section 2.4
! @options robotware-6
! @expect ok
! @description Read as RobotWare 5 and 6 read modules (doc/rulings.md R-2.4-rw6), BREAK and CONTINUE are not reserved words: a RobotWare 6 system module names a variable continue.
  LOCAL VAR bool continue := TRUE;
  VAR num Continued := 0;
  PROC main()
    WHILE continue DO
      continue := FALSE;
    ENDWHILE
  ENDPROC
ENDMODULE
