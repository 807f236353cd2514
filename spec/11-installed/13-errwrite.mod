MODULE errwrite_use
! @format 3
! @section 13
! @expect ok
! @description ErrWrite writes to the event log, not to the program's output (which holds the lines of TPWrite only), and execution continues.
! @output after
! @exit 0
  PROC main()
    ErrWrite "Header", "Reason";
    ErrWrite \W, "Warning header", "Reason" \RL2:="second line";
    TPWrite "after";
  ENDPROC
ENDMODULE
