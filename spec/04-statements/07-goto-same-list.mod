MODULE goto_same_list
! @format 2
! @section 4.7
! @section 4.4
! @expect ok
! @description GOTO to a label of the same statement list, backward and forward (section 4.7's next:).
  VAR num i;
  PROC main()
    next:
    i := i + 1;
    IF i < 10 GOTO next;
    GOTO done;
    i := 0;
    done:
  ENDPROC
ENDMODULE
