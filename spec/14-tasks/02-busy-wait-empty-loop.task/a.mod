MODULE busy_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @description A task waiting for another in a WHILE loop with an empty body: each round ends its turn (R-14-o), so T_B runs and sets the shared persistent that ends the loop.
! @output B 1
! @output B 2
! @output B 3
! @output A saw the flag
! @output B 4
  PERS num flag := 0;
  PROC main()
    WHILE flag = 0 DO
    ENDWHILE
    TPWrite "A saw the flag";
  ENDPROC
ENDMODULE
