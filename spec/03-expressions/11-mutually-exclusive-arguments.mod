MODULE mutually_exclusive_arguments
! @format 2
! @section 3.11
! @expect ok
! @description At most one of the mutually exclusive arguments on and off is given.
  VAR bool b;
  PROC main()
    b := check(\on);
    b := check(\off);
    b := check();
  ENDPROC

  FUNC bool check(\switch on | switch off)
    RETURN Present(on);
  ENDFUNC
ENDMODULE
