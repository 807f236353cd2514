MODULE propagation_up_call_chain
! @format 3
! @section 7.1
! @expect ok
! @description An error in a routine without error handler is raised again at the routine's call, and so on up the call chain until a routine with a handler (section 7.1, older manual section 8.1; doc/rulings.md): main handles an error raised two calls down.
! @output main handler 21
! @output after a
! @exit 0
  PROC b()
    RAISE 21;
    TPWrite "wrong b";
  ENDPROC
  PROC a()
    b;
    TPWrite "wrong a";
  ENDPROC
  PROC main()
    a;
    TPWrite "after a";
  ERROR
    TPWrite "main handler " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE
