MODULE nearest_handler
! @format 3
! @section 7.1
! @expect ok
! @description The error goes to the nearest routine up the call chain that has an error handler; handlers further up are not involved.
! @output a handler 21
! @output back in main
! @exit 0
  PROC b()
    RAISE 21;
  ENDPROC
  PROC a()
    b;
  ERROR
    TPWrite "a handler " \Num:=ERRNO;
    RETURN;
  ENDPROC
  PROC main()
    a;
    TPWrite "back in main";
  ERROR
    TPWrite "wrong main handler";
  ENDPROC
ENDMODULE
