MODULE while_false_at_start
! @format 3
! @section 4.19
! @expect ok
! @description The condition is evaluated before the first iteration too: when it is false at once the body never runs.
! @output check
! @output after
! @exit 0
  FUNC bool check()
    TPWrite "check";
    RETURN FALSE;
  ENDFUNC
  PROC main()
    WHILE check() DO
      TPWrite "wrong";
    ENDWHILE
    TPWrite "after";
  ENDPROC
ENDMODULE
