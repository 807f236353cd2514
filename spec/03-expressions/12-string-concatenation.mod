MODULE string_concatenation
! @format 2
! @section 3.12
! @expect ok
! @description Row + string, string -> string.
  VAR string first := "John";
  VAR string r;
  PROC main()
    r := first + " " + "Smith";
  ENDPROC
ENDMODULE
