MODULE compact_if_retry
! @format 3
! @section 4.17
! @section 7.1
! @expect ok
! @description The simple statement of a compact IF is part of it: an error in it makes the compact IF the statement that caused the error, so RETRY evaluates the condition again (doc/semantics.md, compact-if).
! @output handled
! @output done
! @exit 0
  VAR bool busy := TRUE;
  PROC main()
    IF busy RAISE 50;
    TPWrite "done";
  ERROR
    TPWrite "handled";
    busy := FALSE;
    RETRY;
  ENDPROC
ENDMODULE
