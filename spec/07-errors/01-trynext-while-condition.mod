MODULE trynext_while_condition
! @format 3
! @section 4.14
! @section 7.2
! @expect ok
! @description An error inside a function called in a WHILE condition: the WHILE is the statement that caused it (section 7.2), so TRYNEXT leaves the loop and continues after ENDWHILE.
! @output body 1
! @output body 2
! @output handler
! @output after while
! @exit 0
  VAR num n;
  FUNC bool more()
    n := n + 1;
    IF n = 3 RAISE 4;
    RETURN TRUE;
  ENDFUNC
  PROC main()
    WHILE more() DO
      TPWrite "body " \Num:=n;
    ENDWHILE
    TPWrite "after while";
  ERROR
    TPWrite "handler";
    TRYNEXT;
  ENDPROC
ENDMODULE
