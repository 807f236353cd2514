MODULE robotware6_break_instruction
! @format 3
! @section 2.4
! @section 4.6
! @options robotware-6
! @expect ok
! @description RobotWare 6's instruction Break (R-2.4-rw6) stops the program at once, inside a loop too: the loop does not go on and nothing after it runs.
! @output before 1
  PROC main()
    VAR num n := 0;
    WHILE n < 3 DO
      Incr n;
      TPWrite "before " \Num:=n;
      Break;
      TPWrite "after";
    ENDWHILE
    TPWrite "after the loop";
  ENDPROC
ENDMODULE
