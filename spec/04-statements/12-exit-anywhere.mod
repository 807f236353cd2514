MODULE exit_anywhere
! @format 2
! @section 4.12
! @expect ok
! @description EXIT may stand in any statement list: the body, error handlers, traps, functions and loops.
  VAR num state;
  PROC main()
    TEST state
    CASE 0:
      state := 1;
    DEFAULT:
      TPWrite "Fatal error: illegal state";
      EXIT;
    ENDTEST
  ERROR
    EXIT;
  ENDPROC
  FUNC num f()
    WHILE TRUE DO
      EXIT;
    ENDWHILE
    RETURN 0;
  ENDFUNC
  TRAP on_event
    EXIT;
  ENDTRAP
ENDMODULE
