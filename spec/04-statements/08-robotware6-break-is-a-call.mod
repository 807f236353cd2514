MODULE robotware6_break_statement
! @section 2.4
! @section 3.6
! @section 4.8
! @format 2
! @options robotware-6
! @expect semantic-error 13:16
! @description Read as RobotWare 6 (R-2.4-rw6) there is no break statement: "Break;" inside a loop is a call of the installed instruction Break, and "break" used as a data object after that is not one.
  PROC main()
    VAR num n := 0;
    WHILE n < 3 DO
      Break;
      n := n + break;
    ENDWHILE
  ENDPROC
ENDMODULE
