MODULE long_jump_from_function
! @format 3
! @section 7.2
! @expect ok
! @description A long jump out of a function evaluated inside an expression of another routine: the whole evaluation is abandoned and main's recovery point continues after the call that started it.
! @output recovery point 44
! @output after work
! @exit 0
  FUNC num value()
    RAISE 44;
  ENDFUNC
  PROC work()
    VAR num x;
    x := 2 * value();
    TPWrite "wrong: in work";
  ERROR
    TPWrite "wrong: work handler";
  ENDPROC
  PROC main()
    work;
    TPWrite "after work";
  ERROR (44)
    TPWrite "recovery point " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE
