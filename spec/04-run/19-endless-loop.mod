MODULE endless_loop
! @format 3
! @section 4.19
! @section 1.4
! @expect ok
! @description A loop that never ends is stopped by the step limit: exit 3.
! @max-steps 100000
! @output start
! @exit 3
  VAR num n;
  PROC main()
    TPWrite "start";
    WHILE TRUE DO
      n := n + 1;
    ENDWHILE
  ENDPROC
ENDMODULE
