MODULE asin_out_of_domain
! @format 3
! @section 13
! @section 7.1
! @expect ok
! @description The argument of ASin must be in [-1, 1] (installed-facts.md section 1, CONFIRMED): ASin(2) is an execution error, which the routine's error handler receives (its name is not given by the sources, so the case does not test it).
! @output error
! @output after
! @exit 0
  PROC main()
    VAR num v := 2;
    VAR num a;
    a := ASin(v);
    TPWrite "after";
  ERROR
    TPWrite "error";
    TRYNEXT;
  ENDPROC
ENDMODULE
