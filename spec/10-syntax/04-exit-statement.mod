MODULE exit_statement
! @section 4.12
! @expect ok
! @description The example of section 4.12, its elided CASE body completed.
  CONST num ready := 1;
  VAR num state;
  VAR iodev console;
  PROC main()
    TEST state
      CASE ready:
        state := 0;
      DEFAULT:
      ! illegal/unknown state - abort
        write console, "Fatal error: illegal state";
        EXIT;
    ENDTEST
  ENDPROC
ENDMODULE
