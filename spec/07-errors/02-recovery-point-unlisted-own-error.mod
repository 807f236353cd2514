MODULE recovery_point_unlisted
! @format 3
! @section 7.2
! @section 7.1
! @expect ok
! @description The list of a recovery point restricts only the long-jump search: the ERROR (56) clause is still the routine's error handler for an error of its own body that the list does not name (doc/rulings.md R-7.2-a).
! @output handler divzero=TRUE
! @output after
! @exit 0
  PROC main()
    VAR num d;
    VAR num x;
    x := 1 / d;
    TPWrite "after";
  ERROR (56)
    TPWrite "handler divzero=" \Bool:=ERRNO = ERR_DIVZERO;
    TRYNEXT;
  ENDPROC
ENDMODULE
