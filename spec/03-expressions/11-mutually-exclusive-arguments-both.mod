MODULE mutually_exclusive_arguments
! @format 2
! @section 3.11
! @expect semantic-error 8:20
! @description Two mutually exclusive arguments in one call; the second is refused at its backslash.
  VAR bool b;
  PROC main()
    b := check(\on \off);
  ENDPROC

  FUNC bool check(\switch on | switch off)
    RETURN Present(on);
  ENDFUNC
ENDMODULE
