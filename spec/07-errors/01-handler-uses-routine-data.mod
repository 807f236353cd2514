MODULE handler_uses_routine_data
! @format 3
! @section 7.1
! @expect ok
! @description The error handler is part of the routine: the routine's data and parameters are in its scope (section 7.1), with the values they had when the error occurred.
! @output count=3 limit=2
! @exit 0
  PROC work(num limit)
    VAR num count;
    WHILE TRUE DO
      count := count + 1;
      IF count > limit RAISE 9;
    ENDWHILE
  ERROR
    TPWrite "count=" + NumToStr(count, 0) + " limit=" + NumToStr(limit, 0);
    RETURN;
  ENDPROC
  PROC main()
    work 2;
  ENDPROC
ENDMODULE
